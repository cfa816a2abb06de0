// Verification of the explicit solver on the case of Ma et al. (2023), Table 1, 5 m/s: energy
// balance, energy loss vs hysteresis area (paper: 12.61 J vs 12.63 J), hourglass energy (paper:
// 0.0693 %), mesh convergence and scale invariance. One 5 m/s run is shared by the checks.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/simulate.hpp"

namespace corlab::fem {
namespace {

class PaperCase : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!result_) result_ = std::make_unique<ImpactResult>(simulate(ImpactConfig{}));
    const ImpactResult& r = *result_;
    std::printf(
        "paper case 5 m/s: e = %.5f, e_energy = %.5f, loss = %.4f J, hysteresis = %.4f J, "
        "plastic = %.4f J, hourglass = %.3e J (%.4f %%), balance = %.2e, F_max = %.5g N, "
        "delta_max = %.5g m, t_c = %.5g s, elements = %d, steps = %lld\n",
        r.e, r.e_energy, r.energy_sphere_loss, r.hysteresis_area, r.energy_dissipated_plastic,
        r.energy_hourglass, 100.0 * r.energy_hourglass / r.energy_initial, r.energy_balance_error,
        r.F_max, r.delta_max, r.t_contact, r.elements, r.steps);
  }
  static const ImpactResult& result() { return *result_; }
  static inline std::unique_ptr<ImpactResult> result_;
};

constexpr double kPaperLoss = 12.61;  // [J], Ma et al. 2023, section 1.2

TEST_F(PaperCase, SeparatesWithThePaperRestitution) {
  EXPECT_TRUE(result().separated);
  // Paper energies imply e = sqrt(1 - 12.61/17.62) = 0.533 (models.md section 1.4).
  // Measured e = 0.534869, +0.0019 (2026-11-27, AMD EPYC AVX-512); bound 0.003 (was 0.02):
  // inside the run's own GCI (0.0035), and a 1 % shift of e either way (+0.0072 / -0.0035) fails.
  EXPECT_NEAR(result().e, 0.533, 0.003);
}

TEST_F(PaperCase, EnergyBalanceHoldsThroughout) {
  // Measured 3.16e-6, the same as the largest of the 1142 history rows (2026-11-27, AMD EPYC
  // AVX-512); bound 1e-5 (was 5e-3): 3x margin, a 10x worse balance fails.
  EXPECT_LT(result().energy_balance_error, 1e-5);
  for (double err : result().history.energy_balance_error) ASSERT_LT(std::abs(err), 1e-5);
}

TEST_F(PaperCase, EnergyLossMatchesHysteresisArea) {
  const ImpactResult& r = result();
  // Measured (2026-11-27, AMD EPYC AVX-512): loss 12.5722 J, hysteresis 12.5749 J, -0.022 %
  // apart (the sphere's vibration energy: e_energy vs e); bound 0.1 % (was 1 %): 4.6x margin.
  EXPECT_NEAR(r.energy_sphere_loss, r.hysteresis_area, 0.001 * r.hysteresis_area);
  // Against the paper's 12.61 J: -0.30 % and -0.28 %; bound 0.5 % (was 5 %), about the run's GCI
  // in energy (0.5 %): a 1 % rise of e (-1.1 %) fails, a 1 % fall (+0.50 %) is the e test's.
  EXPECT_NEAR(r.energy_sphere_loss, kPaperLoss, 0.005 * kPaperLoss);
  EXPECT_NEAR(r.hysteresis_area, kPaperLoss, 0.005 * kPaperLoss);
}

TEST_F(PaperCase, PenaltyPenetrationIsSmall) {
  // The penalty at 0.1 of its stability limit: penetration about 1 % of the indentation or less.
  std::printf("penetration_max = %.3g m = %.3g %% of delta_max\n", result().penetration_max,
              100.0 * result().penetration_max / result().delta_max);
  // Measured 0.349 % of delta_max (2026-11-27, AMD EPYC AVX-512). Bounds 0.1 % (was > 0: a
  // penalty 3.5x stiffer than sized fails) and 1 % (was 2 %): 2.9x margin.
  EXPECT_GT(result().penetration_max, 0.001 * result().delta_max);
  EXPECT_LT(result().penetration_max, 0.01 * result().delta_max);
}

TEST_F(PaperCase, HourglassEnergyIsSmall) {
  // Measured 0.0532 % of E0 (2026-11-27, AMD EPYC AVX-512; paper 0.0693 %). Bound 0.1 % kept,
  // not tightened: the README's criterion and 1.9x the measured value already.
  EXPECT_LT(result().energy_hourglass, 0.001 * result().energy_initial);
}

TEST_F(PaperCase, MeshConvergence) {
  // h_min = 1.0, 0.5, 0.35, 0.25 (the shared run) and 0.2 mm; the a/12 bound is off so that
  // h_min is the contact element size. Criterion: e changes by < 1 % between the two finest.
  // (Measured: 0.5549, 0.5367, 0.5421, 0.5349, 0.5363: the coarse meshes scatter by about
  // 1 %, 0.25 -> 0.2 mm changes e by 0.26 %.)
  auto run = [](double h) {
    ImpactConfig c;
    c.mesh.h_min = h;
    c.mesh.contact_elements = 0.0;
    const ImpactResult r = simulate(c);
    // Measured exactly h at all four (2026-11-27); bound 1e-9 h (was 1e-3 h): round-off only.
    EXPECT_NEAR(r.h_contact, h, 1e-9 * h);
    EXPECT_TRUE(r.separated);
    std::printf("h_min = %.2f mm: e = %.5f (elements %d, steps %lld)\n", h * 1e3, r.e, r.elements,
                r.steps);
    return r.e;
  };
  for (const double h : {1.0e-3, 0.5e-3, 0.35e-3}) run(h);
  ASSERT_NEAR(result().h_contact, 0.25e-3, 1e-9 * 0.25e-3);  // measured exact; was 1e-7 m
  std::printf("h_min = 0.25 mm: e = %.5f\n", result().e);
  const double e_finest = run(0.2e-3);
  // Measured 0.26 % (2026-11-27, AMD EPYC AVX-512); bound 0.5 % (was 1 %): 1.9x margin, since
  // mesh changes move the coarser meshes' e by ~1 %; the GCI bracket below is the finer check.
  EXPECT_LT(std::abs(e_finest - result().e), 0.005 * e_finest);
  // The error estimate (discretisation_error.hpp, what `corlab reproduce` runs): the 0.25 mm
  // run's bar contains the 0.2 mm and the 0.18 mm values (the two-grid GCI it replaced did not
  // contain the 0.18 mm one: issue 28).
  const ImpactResult estimate = simulate_with_error_estimate(ImpactConfig{});
  ASSERT_EQ(estimate.e, result().e);
  const double e_018 = run(0.18e-3);
  std::printf("e = %.5f +/- %.5f; e(0.2 mm) = %.5f, e(0.18 mm) = %.5f\n", estimate.e,
              estimate.e_error, e_finest, e_018);
  EXPECT_LE(std::abs(e_finest - result().e), estimate.e_error);
  EXPECT_LE(std::abs(e_018 - result().e), estimate.e_error);
}

TEST_F(PaperCase, ScaleInvariance) {
  // Every length / 14 (R = 2.5 mm): a rate-independent, gravity-free impact gives the same e.
  const double s = 1.0 / 14.0;
  ImpactConfig c;
  c.sphere.radius *= s;
  c.substrate.radius *= s;
  c.substrate.depth *= s;
  c.impact.gap *= s;
  c.mesh.h_min *= s;
  c.mesh.h_max *= s;
  const ImpactResult r = simulate(c);
  std::printf("R = 2.5 mm: e = %.6f vs %.6f at R = 35 mm\n", r.e, result().e);
  // Measured -7.1e-13 relative (2026-11-27, AMD EPYC AVX-512): exact but for round-off; bound
  // 1e-9 (was 0.5 %), 100x the AVX2 vs AVX-512 spread (1e-11) as in DatasetInvariance.
  EXPECT_NEAR(r.e, result().e, 1e-9 * result().e);
}

}  // namespace
}  // namespace corlab::fem
