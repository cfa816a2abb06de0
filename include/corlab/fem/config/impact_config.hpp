// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file impact_config.hpp
/// Everything that defines one impact simulation. Defaults reproduce Ma et al. 2023, Table 1, at
/// 5 m/s: steel sphere R = 35 mm (E = 210 GPa, nu = 0.3, rho = 7850) on a 70 mm x 70 mm steel
/// substrate with sigma_y = 500 MPa, gap 0.1 mm, smallest element 0.25 mm at the contact.
///
/// Text keys (TOML tables / `--set key=value`), all SI: the table in config_keys.hpp (key, unit,
/// range, default, doc); `corlab simulate --help` prints it.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/core/units.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::fem {

struct SphereConfig {
  double radius = 35e-3;  ///< R [m]
  Material material{.name = "steel_ma2023 (elastic sphere)",
                    .youngs_modulus = 210e9,
                    .poisson_ratio = 0.3,
                    .density = 7850.0,
                    .yield_stress = std::nullopt,
                    .hardening_modulus = 0.0,
                    .source = "Ma et al. 2023, Table 1"};  ///< elastic unless yield_stress is set
};

/// What the sphere hits (docs/theory/solver.md, section 7).
enum class SubstrateShape : std::uint8_t {
  kFlat,    ///< the elastic-plastic substrate block, fixed at its base (Ma et al. 2023)
  kRigid,   ///< a rigid frictionless flat at z = 0: no substrate body
  kSphere,  ///< a second sphere of radius substrate.radius, free and at rest (head-on impact)
};

/// "flat", "rigid" or "sphere".
std::string_view to_string(SubstrateShape shape);

/// The flat substrate's far faces (its sides and base; docs/theory/solver.md, "Far boundary").
enum class SubstrateBoundary : std::uint8_t {
  kFixed,      ///< the base held, the sides free (Ma et al. 2023): waves reflect
  kAbsorbing,  ///< Lysmer-Kuhlemeyer dashpots on the sides and base (absorbing_boundary.hpp)
  /// The dashpots and, beside each, the viscous-spring boundary's spring (absorbing_boundary.hpp)
  kViscousSpring,
};

/// "fixed", "absorbing" or "viscous_spring".
std::string_view to_string(SubstrateBoundary boundary);

struct SubstrateConfig {
  SubstrateShape shape = SubstrateShape::kFlat;
  /// The far faces of the flat (substrate.shape = flat only).
  SubstrateBoundary boundary = SubstrateBoundary::kFixed;
  double radius = 70e-3;  ///< radial extent [m] (paper: L = 2R); the radius R2 of a sphere
  double depth = 70e-3;   ///< depth [m]; the bottom face is fixed unless `boundary` absorbs
  Material material{.name = "steel_ma2023",
                    .youngs_modulus = 210e9,
                    .poisson_ratio = 0.3,
                    .density = 7850.0,
                    .yield_stress = 500e6,
                    .hardening_modulus = 0.0,
                    .source = "Ma et al. 2023, Table 1"};  ///< J2 if yield_stress is set
};

/// A plane angle, kept in radians. Its config key is written in degrees: converted where the
/// key is read and written (config_keys.cpp), nowhere else.
struct PlaneAngle {
  double radians = 0.0;  ///< [rad]

  /// The angle of `deg` degrees.
  static constexpr PlaneAngle degrees(double deg) { return {deg * units::kDegree}; }
  /// In degrees, rounded to 15 significant digits, so that a value read in degrees is written
  /// back as it was typed (30 deg, not 30.000000000000004) [deg].
  double in_degrees() const;
};

struct ImpactConditions {
  double velocity = 5.0;  ///< impact speed v > 0 [m/s], sphere moving towards the substrate
  double gap = 0.1e-3;    ///< initial gap [m]; crossed exactly (free flight), no steps spent
  /// Impacts of the pair on the same spot [-]: after each rebound the bodies are sent back at
  /// the same approach speed, carrying their residual stress, plastic strain, shape and
  /// vibration (solver.md section 8).
  int repeats = 1;
  /// Angle of the impact velocity from the contact normal, in [0, 90) deg: the normal speed is
  /// velocity cos(angle). Only the 3-D model (solver.model = 3d) takes one above 0.
  PlaneAngle angle;
};

/// How the 3-D model's contact enforces Coulomb friction's stick (docs/theory/solver3d.md,
/// "Contact and friction"; coulomb_friction.hpp).
enum class FrictionEnforcement : std::uint8_t {
  /// Predictor-corrector (Taylor & Flanagan 1989): the force that stops the relative tangential
  /// motion over the step, capped at mu f_n; no tangential compliance.
  kKinematic,
  /// A tangential penalty spring (k_t = the normal penalty) with a Coulomb return map: stick
  /// needs a small relative displacement, in series with the bodies' own compliance.
  kPenalty,
};

/// "kinematic" or "penalty".
std::string_view to_string(FrictionEnforcement enforcement);

/// The contact law beyond the normal penalty.
struct ContactConfig {
  double friction = 0.0;  ///< Coulomb coefficient mu >= 0 (3-D model only) [-]
  /// How stick is enforced (3-D model only).
  FrictionEnforcement enforcement = FrictionEnforcement::kKinematic;
};

struct MeshConfig {
  double h_min = 0.25e-3;  ///< element size at the contact [m] (paper: 0.25 mm)
  /// Upper bound on h at the contact as a fraction of the predicted contact radius:
  /// h <= a_max / contact_elements, so slow impacts stay resolved. 0 disables the bound.
  double contact_elements = 12.0;
  double refine_factor =
      1.5;  ///< refined zone radius = refine_factor x predicted contact radius [-]
  /// Refined zone depth below the contact = refine_depth x predicted contact radius [-]. The
  /// elastic stresses peak at 0.48 a below the contact (Johnson 1985, fig. 4.6); deeper, the
  /// graded mesh changes e by < 0.1 % (docs/theory/mesh.md, "Depth of the refined zone").
  double refine_depth = 0.5;
  static constexpr double kMaxGrowth = 2.0;  ///< largest accepted `growth` [-]
  double growth = 1.15;  ///< size ratio of neighbouring elements outside the zone [-]
  double h_max = 5e-3;   ///< largest element size [m]
  /// 1 = 3:1 transitions in the tensor-grid substrate and the sphere's bottom ring and skin (the
  /// default), 0 = plain grids [-]
  double transitions = 1.0;
  std::filesystem::path file;  ///< Gmsh .msh file; empty = built-in generator
};

/// Which solver runs the impact.
enum class SolverModel : std::uint8_t {
  kAxisymmetric,  ///< the axisymmetric solver (normal impacts; the default)
  kThreeD,        ///< the 3-D half model (docs/theory/solver3d.md): oblique impacts, friction
};

/// "axisymmetric" or "3d".
std::string_view to_string(SolverModel model);

struct SolverConfig {
  /// The model (uses_3d_model); impact.angle above 0 needs the 3-D one.
  SolverModel model = SolverModel::kAxisymmetric;
  double safety_factor = 0.8;  ///< dt = safety_factor x stable step estimate [-]
  double hourglass = 0.05;     ///< stiffness hourglass coefficient (Flanagan-Belytschko) [-]
  /// The same for the 3-D model's hexahedra [-]: 0.05 lets a contact sliding over the deformable
  /// flat pump energy into the flat's hourglass modes (docs/theory/solver3d.md).
  double hourglass_3d = 0.15;
  double bulk_viscosity_linear = 0.06;    ///< b1 [-] (ABAQUS/Explicit default)
  double bulk_viscosity_quadratic = 1.2;  ///< b2 [-] (ABAQUS/Explicit default)
  /// Contact penalty k = penalty_scale x m_eff (2 / dt_crit)^2, dt_crit = the initial stable step
  /// estimate (independent of safety_factor) [-]
  double penalty_scale = 0.28;
  double t_max = 0.0;  ///< hard stop [s]; 0 = 20 x the Hertz contact time
  /// Step budget [-]: validate() refuses a run whose estimated step count (estimate_run()) is
  /// larger; the solver stops a run that reaches it (status step_budget_exceeded).
  long long max_steps = 20'000'000;
  /// Work caps [-]: validate() refuses, before meshing, a run whose a-priori element count, or
  /// element count x expected steps, is larger (estimate_run(); docs/user/errors.md).
  long long max_elements = 2'000'000;
  double max_element_steps = 1e12;
  /// Multi-time-step integration (element subcycling, docs/theory/solver.md section 11): elements
  /// step at 2^L x the base step, L <= this (0 = every element at the base step) [-].
  int subcycling_levels = 4;
  /// Mass scaling to a target step (docs/theory/solver.md section 12): the elements below the
  /// step floor (the contact's h-squares' stable step) reach it, then those below F x the floor
  /// get their density raised until they reach that; F is the largest power of two <= this whose
  /// added inertia stays within mass_scaling_inertia (1 = off, floor included) [-].
  double mass_scaling_max = 8.0;
  /// Bound on the inertia that mass scaling adds, (F^2 - 1) rho v^2 / p_ref, rho the larger
  /// density, v the impact speed, p_ref the smaller of the Hertz p0 and the yield stresses [-].
  double mass_scaling_inertia = 1e-4;
  /// In-run selective mass scaling (docs/theory/solver.md section 12, "In the run"): an element of
  /// the substrate whose stable step falls below this fraction of the run's first step gets its
  /// density raised, during the run, until its step is back above it (0 = off) [-].
  double in_run_step_floor = 0.0;
  /// Bound on the mass the in-run scaling adds, a fraction of the sphere's mass [-]: with a floor
  /// of 0.35, e moved by <= 0.2 of its error bar on the paper's dearest run (solver.md 12).
  double in_run_added_mass = 5e-4;
};

struct OutputConfig {
  std::vector<double> field_times;  ///< times [s] at which to write VTU fields (empty = none)
  int history_every = 10;           ///< write a history row every N steps
};

struct ImpactConfig {
  SphereConfig sphere;
  SubstrateConfig substrate;
  ImpactConditions impact;
  ContactConfig contact;
  MeshConfig mesh;
  SolverConfig solver;
  OutputConfig output;
};

/// Whether the sphere hits the rigid flat (no substrate body).
inline bool rigid_target(const ImpactConfig& config) {
  return config.substrate.shape == SubstrateShape::kRigid;
}

/// Whether the 3-D model runs: solver.model alone chooses (an oblique impact with the
/// axisymmetric model is refused by validate()).
inline bool uses_3d_model(const ImpactConfig& config) {
  return config.solver.model == SolverModel::kThreeD;
}

/// Whether the sphere hits a second, free sphere.
inline bool sphere_target(const ImpactConfig& config) {
  return config.substrate.shape == SubstrateShape::kSphere;
}

/// Normal approach speed v cos(impact.angle) [m/s].
double normal_velocity(const ImpactConfig& config);

/// Time from the release at impact.gap to the first contact, gap / normal speed [s]: the origin
/// of output.times and of the run's end_time is the release, in both models.
double contact_start_time(const ImpactConfig& config);

/// E* of the contact [Pa]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, the second term 0 for the
/// rigid flat.
double contact_effective_modulus(const ImpactConfig& config);

/// The yield stress [Pa] that bounds the contact pressure in the a-priori estimates
/// (contact_estimate.hpp): the substrate's for the flat, the sphere's for the rigid flat, the
/// smaller of the two spheres'; empty if no such body yields.
std::optional<double> contact_yield_stress(const ImpactConfig& config);

/// Throws InputError naming the first invalid field (e.g. "invalid impact.velocity = 0: ...").
/// Checks each key's range (config_keys.hpp), then the limits that join keys (config_limits.hpp:
/// gap, substrate size, contact radius, stability, estimated step count).
void validate(const ImpactConfig& config);

/// Sets one key (see file comment) from text; throws InputError for an unknown key or bad value.
void apply_setting(ImpactConfig& config, std::string_view key, std::string_view value);

/// Applies key=value settings in one go: the `*.material` keys first (so an explicit property such
/// as `sphere.rho` overrides the preset it modifies), then the others in order. A key given twice
/// is an error (ambiguous), as is an item without '='. `origin` names the source in messages
/// (e.g. "--set").
void apply_settings(ImpactConfig& config,
                    const std::vector<std::string>& key_value_items,
                    std::string_view origin);

/// Reads a TOML file of the keys above over the defaults; throws InputError for a malformed file,
/// an unknown key or a value that is not of the key's type. Ranges are checked by validate() once
/// the overrides (--set) are applied: simulate() does it.
ImpactConfig load_impact_config(const std::filesystem::path& file);

}  // namespace corlab::fem
