// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_box.hpp
/// The dimensionless input box of corlab's FE restitution datasets (docs/theory/dataset.md) and
/// its map to impact configurations. An elastic or elastic-plastic sphere (radius R1 = 35 mm,
/// the paper's) hits an elastic-plastic flat substrate or a free elastic-plastic second sphere
/// at rest; both bodies have linear hardening H = h E when they yield. The inputs are the design
/// coordinates (Sobol dimension in this order):
///
///   k2 = sigma_y,substrate / E*              log-uniform          (Ma et al. 2023 eq. 6)
///   v / v_y                                  log-uniform from just above first yield (v_y of
///                                            the pair, first_yield.hpp) to the smaller of
///                                            velocity_max and the damage-number bound
///   E_sphere / E_substrate                   log-uniform
///   sigma_y,sphere / sigma_y,substrate       elastic sphere for the first elastic_sphere_fraction
///                                            of the coordinate, log-uniform above
///   nu_substrate, h = H/E, nu_sphere         uniform
///   rho_sphere / rho_substrate               log-uniform          (pair boxes only)
///   R1 / R2                                  a flat (R1/R2 = 0) for the first flat_fraction of
///                                            the coordinate, uniform above (pair boxes only)
///
/// The flat box of the first dataset (ImpactBox{}) has equal densities and flats only and uses
/// the first seven coordinates; a pair box (pair_box()) uses all nine. "Substrate" is body 2:
/// the flat or the second sphere. The dimensional base (E_substrate, rho_substrate, R1 and the
/// flat's size) is fixed; by dimensional analysis e depends on the dimensionless inputs only
/// (tests/verification/dataset_invariance_test.cpp).

#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace corlab::dataset {

/// A closed interval [min, max].
struct Range {
  double min = 0.0;
  double max = 0.0;
};

/// The box and the dimensional base it is mapped onto. Defaults: the ranges of issue 10.
struct ImpactBox {
  Range k2{1e-3, 1.5e-2};           ///< sigma_y,substrate / E* [-]
  double velocity_ratio_min = 1.1;  ///< smallest v / v_y [-]
  double velocity_max = 100.0;      ///< largest impact speed [m/s]
  /// Largest Johnson damage number rho v^2 / sigma_y,substrate [-]: 0.26 is the paper's own
  /// extreme (Table 2: 70 m/s, rho = 15700 kg/m^3, sigma_y = 300 MPa); beyond it the crater is
  /// deeper than R/4 and the axisymmetric mesh tangles.
  double damage_number_max = 0.26;
  Range modulus_ratio{0.2, 5.0};         ///< E_sphere / E_substrate [-]
  Range sphere_yield_ratio{0.5, 5.0};    ///< sigma_y,sphere / sigma_y,substrate when it yields [-]
  double elastic_sphere_fraction = 0.5;  ///< share of the design with an elastic sphere [-]
  Range nu{0.2, 0.45};                   ///< Poisson's ratio of either body [-]
  Range hardening_ratio{0.0, 0.05};      ///< H / E of each yielding body [-]
  double substrate_modulus = 210e9;      ///< E_substrate [Pa]
  double density = 7850.0;               ///< rho_substrate (and rho_sphere at ratio 1) [kg/m^3]
  Range density_ratio{1.0, 1.0};         ///< rho_sphere / rho_substrate [-]
  double flat_fraction = 1.0;            ///< share of the design on a flat (R1/R2 = 0) [-]
  Range radius_ratio{0.1, 1.0};          ///< R1 / R2 when body 2 is a sphere [-]
};

/// The box of particle-particle and particle-wall impacts (issue 26): E ratio 0.05-20, density
/// ratio 0.1-10, a flat for a quarter of the design and R1/R2 in [0.1, 1] for the rest.
ImpactBox pair_box();

/// Design coordinates of the flat box.
inline constexpr int kBoxDimension = 7;
/// Design coordinates of a pair box (density and radius ratios added).
inline constexpr int kPairBoxDimension = 9;

/// Whether a box varies the density or radius ratio (a pair box).
bool is_pair_box(const ImpactBox& box);

/// kPairBoxDimension for a pair box, else kBoxDimension.
int box_dimension(const ImpactBox& box);

/// One point of the box.
struct DimensionlessImpact {
  double k2 = 0.0;                           ///< sigma_y,substrate / E* [-]
  double velocity_ratio = 0.0;               ///< v / v_y [-]
  double modulus_ratio = 0.0;                ///< E_sphere / E_substrate [-]
  std::optional<double> sphere_yield_ratio;  ///< sigma_y ratio; empty = elastic sphere [-]
  double nu_substrate = 0.0;                 ///< [-]
  double hardening_ratio = 0.0;              ///< H / E [-]
  double nu_sphere = 0.0;                    ///< [-]
  double density_ratio = 1.0;                ///< rho_sphere / rho_substrate [-]
  double radius_ratio = 0.0;                 ///< R1 / R2; 0 = a flat substrate [-]
};

/// The point at design coordinates u in [0, 1)^box_dimension(box) (order of the file comment).
/// The velocity ratio's upper end depends on the other inputs (speed and damage-number bounds).
DimensionlessImpact box_point(const ImpactBox& box, std::span<const double> u);

/// The two materials of a point (E_substrate and rho_substrate from the box) [SI].
struct PointMaterials {
  Material sphere;
  Material substrate;
};
PointMaterials point_materials(const ImpactBox& box, const DimensionlessImpact& p);

/// Impact speed of a point [m/s].
double point_velocity(const ImpactBox& box, const DimensionlessImpact& p);

/// The sweep settings of a point, as shortest round-trip text: sphere.E, sphere.nu,
/// sphere.sigma_y (`none` for an elastic sphere), sphere.hardening, substrate.nu,
/// substrate.sigma_y, substrate.hardening, impact.velocity; for a pair box also sphere.rho,
/// substrate.shape and, on a sphere, substrate.radius (R2).
study::Settings point_settings(const ImpactBox& box, const DimensionlessImpact& p);

/// The dimensionless inputs of any impact configuration (the inverse of the map above, for any
/// run: dataset, Table 2 or user study) [-].
struct DimensionlessInputs {
  double k1 = 0.0;                    ///< E* / (rho* v^2); rho* = rho_sphere on a flat
  double k2 = 0.0;                    ///< sigma_y,substrate / E* (nan: elastic substrate)
  double velocity_ratio = 0.0;        ///< v / v_y (nan: neither body yields)
  double first_yield_velocity = 0.0;  ///< v_y [m/s]
  bool sphere_yields_first = false;
  double modulus_ratio = 0.0;       ///< E_sphere / E_substrate
  double sphere_yield_ratio = 0.0;  ///< sigma_y,sphere / sigma_y,substrate (inf: elastic sphere)
  double nu_sphere = 0.0;
  double nu_substrate = 0.0;
  double hardening_ratio_sphere = 0.0;     ///< H / E of the sphere
  double hardening_ratio_substrate = 0.0;  ///< H / E of the substrate
  double density_ratio = 0.0;              ///< rho_sphere / rho_substrate
  double damage_number = 0.0;              ///< rho* v^2 / sigma_y,substrate (Johnson 1972)
  double radius_ratio = 0.0;               ///< R1 / R2 (0: a flat, fixed or rigid)
  double effective_density = 0.0;          ///< rho* = 3 m* / (4 pi R*^3) [kg/m^3]
};
DimensionlessInputs dimensionless_inputs(const fem::ImpactConfig& config);

}  // namespace corlab::dataset
