// Fits of one-parameter laws to a target e(v), tables and their interpolation error.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dem/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/dem/contact_ode.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/dem/uniform_table.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::dem {
namespace {

TEST(DemCalibration, ViscoelasticFitRecoversItsOwnDamping) {
  const double k = hertz_stiffness(120e9, 0.004);
  const double m = 2e-3;
  const double c_true = 3.0e4;
  const RestitutionCurve own = [&](double v) {
    const ViscoelasticHertzLaw law{k, c_true};
    const ForceLaw f = [&law](double d, double r, const ContactHistory&) {
      return law.force(d, r);
    };
    return simulate_impact(f, m, v).restitution;
  };
  const auto speeds = log_speeds(0.1, 10.0, 5);
  const auto fit = fit_viscoelastic_damping(k, m, speeds, own);
  EXPECT_NEAR(fit.parameter / c_true, 1.0, 1e-5);
  EXPECT_LT(fit.max_abs_error, 1e-7);
  EXPECT_LT(fit.fitted.back(), fit.fitted.front());  // e falls with v
}

TEST(DemCalibration, ThorntonFitRecoversTheModelPressure) {
  const auto& db = MaterialDatabase::builtin();
  const auto model =
      restitution::make_model("thornton1997", db.get("alumina_ma2023"), db.get("aluminium_ma2023"));
  const auto& kernel = std::get<restitution::Thornton1997>(model.kernel());
  const double radius = 0.005;
  const double mass = 4.0 / 3.0 * units::kPi * std::pow(radius, 3) * kernel.pair.sphere_density;
  const auto speeds = log_speeds(0.5, 5.0, 4);
  const auto fit = fit_thornton_pressure(kernel.pair.effective_modulus, radius, mass, speeds,
                                         [&](double v) { return model.cor(v); });
  EXPECT_NEAR(fit.parameter / kernel.limiting_pressure(), 1.0, 1e-4);
  EXPECT_LT(fit.max_abs_error, 1e-6);
}

TEST(DemCalibration, TabulatedCurveInterpolatesAndRejectsBadTables) {
  const auto curve = tabulated_curve({1.0, 2.0, 4.0}, {0.9, 0.8, 0.6});
  EXPECT_DOUBLE_EQ(curve(1.5), 0.85);
  EXPECT_DOUBLE_EQ(curve(0.1), 0.9);
  EXPECT_DOUBLE_EQ(curve(9.0), 0.6);
  EXPECT_THROW(tabulated_curve({1.0, 1.0}, {0.9, 0.8}), InputError);
  EXPECT_THROW(tabulated_curve({1.0, 2.0}, {0.9, 1.8}), InputError);
  EXPECT_THROW(tabulated_curve({1.0}, {0.9}), InputError);
}

// The chi(e) table of the docs: 4096 points on [0.05, 0.99]; its stated error bound is 1.2e-4
// (relative to chi, the worst case is at e = 0.05 where chi'' is largest).
TEST(DemCalibration, ChiTableInterpolationErrorIsAsStated) {
  const auto table = tabulate([](double e) { return exact_chi(e); }, 0.05, 0.99, 4096);
  const double err = max_interpolation_error(table, [](double e) { return exact_chi(e); });
  EXPECT_LT(err, 1.2e-4);
  std::printf("chi table max interpolation error: %.3g\n", err);
  EXPECT_GT(err, 0.0);
  EXPECT_DOUBLE_EQ(table(0.0), table.values().front());  // clamped below the range
  EXPECT_DOUBLE_EQ(table(2.0), table.values().back());
}

}  // namespace
}  // namespace corlab::dem
