// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file j2_plasticity.hpp
/// Isotropic hypoelastic material with J2 (von Mises) plasticity and linear isotropic hardening,
/// integrated with the radial return of Wilkins (1964) / Simo & Hughes (1998, Computational
/// Inelasticity, Box 3.1): sigma_y(eps_p) = sigma_y0 + H eps_p. H = 0 is perfectly plastic (Ma
/// et al. 2023 eq. 1); no yield stress is purely elastic. Equivalent stress sqrt(3 J2),
/// J2 = 1/2 s:s. One material point for every geometry: the axisymmetric element passes an
/// AxisymTensor, the 3-D hexahedron a SymTensor3.

#include <algorithm>
#include <cmath>
#include <limits>

#include "corlab/fem/kernels/axisym_tensor.hpp"
#include "corlab/fem/kernels/sym_tensor3.hpp"

namespace corlab::fem {

struct J2Plasticity {
  /// Yield stress of a purely elastic material [Pa].
  static constexpr double kNoYield = std::numeric_limits<double>::max();
  /// Floor of the equivalent stress in the return's division [Pa].
  static constexpr double kTiny = 1e-300;

  double shear_modulus = 0.0;  ///< G [Pa]
  double bulk_modulus = 0.0;   ///< K [Pa]
  /// sigma_y0 [Pa]; kNoYield (the largest double) = elastic: it is never reached and keeps the
  /// plastic work (sigma_y x 0) finite, so the return stays branch-free.
  double yield_stress = kNoYield;
  double hardening_modulus = 0.0;  ///< H = d sigma_y / d eps_p [Pa]

  /// Internal variables of one material point.
  struct State {
    double eps_p = 0.0;  ///< equivalent plastic strain [-]
  };

  /// What one update did.
  struct Increment {
    double d_eps_p = 0.0;  ///< equivalent plastic strain increment [-]
    double plastic_work =
        0.0;  ///< plastic dissipation per unit volume, trapezoid in sigma_y [J/m^3]
  };

  /// From Young's modulus E [Pa], Poisson's ratio nu [-], the yield stress sigma_y0 [Pa]
  /// (kNoYield: elastic) and the hardening modulus H [Pa].
  static J2Plasticity from(double youngs_modulus,
                           double poisson_ratio,
                           double yield_stress = kNoYield,
                           double hardening_modulus = 0.0) {
    J2Plasticity j;
    j.shear_modulus = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
    j.bulk_modulus = youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio));
    j.yield_stress = yield_stress;
    j.hardening_modulus = hardening_modulus;
    return j;
  }

  /// Current yield stress [Pa].
  double flow_stress(const State& state) const {
    return yield_stress + hardening_modulus * state.eps_p;
  }

  /// Adds the elastic trial increment C : d_eps to `stress` and returns it to the yield surface.
  /// d_eps is the strain increment [-] (tensor shear components). Tensor is AxisymTensor or
  /// SymTensor3: the return is written once over their primitives (deviator,
  /// deviatoric_equivalent, with_deviator, add_isotropic, trace).
  template <class Tensor>
  Increment update(Tensor& stress, State& state, const Tensor& d_eps) const {
    const double two_g = 2.0 * shear_modulus;
    const double lam = bulk_modulus - two_g / 3.0;
    add_isotropic(stress, d_eps, two_g, lam);
    const double p = trace(stress) * (1.0 / 3.0);
    const Tensor s = deviator(stress, p);
    const double q = deviatoric_equivalent(s);
    const double sy = flow_stress(state);
    // Branch-free (vectorisable) radial return: d_eps_p = <q - sigma_y>_+ / (3G + H), deviator
    // scaled by 1 - 3G d_eps_p / q (= 1 when elastic).
    const double inv_stiffness = 1.0 / (3.0 * shear_modulus + hardening_modulus);  // hoisted
    const double dep = std::max(q - sy, 0.0) * inv_stiffness;
    const double scale = 1.0 - 3.0 * shear_modulus * dep / std::max(q, kTiny);
    stress = with_deviator(p, scale, s);
    state.eps_p += dep;
    Increment inc;
    inc.d_eps_p = dep;
    inc.plastic_work = (sy + 0.5 * hardening_modulus * dep) * dep;
    return inc;
  }

  /// Elastic strain energy density of a stress: s:s/(4G) + p^2/(2K) [J/m^3].
  template <class Tensor>
  double strain_energy_density(const Tensor& stress) const {
    const double p = trace(stress) * (1.0 / 3.0);
    const Tensor s = deviator(stress, p);
    return contract(s, s) / (4.0 * shear_modulus) + p * p / (2.0 * bulk_modulus);
  }
};

}  // namespace corlab::fem
