// corlab's model (corlab2026): exactly 1 at first yield and continuous there, within (0, 1],
// non-increasing in v over random inputs in and beyond the dataset's box, Johnson's v^(-1/4) at
// high speed for perfect plasticity, registered, and the shipped coefficients those of
// data/fe_restitution/model_fit.json.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/corlab2026.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "corlab/restitution/first_yield.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::restitution {
namespace {

Material body(double e, double nu, std::optional<double> sy, double h_ratio) {
  return Material{.name = "t",
                  .youngs_modulus = e,
                  .poisson_ratio = nu,
                  .density = 7850.0,
                  .yield_stress = sy,
                  .hardening_modulus = h_ratio * e,
                  .source = ""};
}

// A random pair in a box wider than the dataset's (extrapolation must keep the guarantees).
struct RandomPair {
  Material sphere, substrate;
};
RandomPair random_pair(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double e_sub = 210e9, e_sph = e_sub * std::exp(std::log(0.1) + u(rng) * std::log(100.0));
  const double sy = 2e9 * std::exp(std::log(1e-3) + u(rng) * std::log(30.0)) * 0.5;
  const std::optional<double> sy_sph =
      u(rng) < 0.5 ? std::nullopt : std::optional<double>(sy * (0.2 + 10.0 * u(rng)));
  const double h = 0.2 * u(rng);
  return {body(e_sph, 0.1 + 0.39 * u(rng), sy_sph, h), body(e_sub, 0.1 + 0.39 * u(rng), sy, h)};
}

TEST(Corlab2026, OneAtFirstYieldAndContinuousThere) {
  std::mt19937_64 rng(7);
  const Corlab2026Coefficients k = corlab2026_fitted();
  for (int i = 0; i < 200; ++i) {
    const RandomPair p = random_pair(rng);
    const Corlab2026 m{.pair = corlab2026_pair(p.sphere, p.substrate), .coefficients = k};
    const double vy = m.yield_velocity();
    EXPECT_DOUBLE_EQ(vy, first_yield(p.sphere, p.substrate).velocity);
    EXPECT_EQ(m.cor(vy), 1.0);
    EXPECT_EQ(m.cor(0.5 * vy), 1.0);
    EXPECT_LT(m.cor(vy * (1.0 + 1e-3)), 1.0);
    EXPECT_GT(m.cor(vy * (1.0 + 1e-9)), 1.0 - 1e-6);
  }
}

TEST(Corlab2026, WithinBoundsAndNonIncreasingInVelocity) {
  std::mt19937_64 rng(11);
  const Corlab2026Coefficients k = corlab2026_fitted();
  for (int i = 0; i < 300; ++i) {
    const RandomPair p = random_pair(rng);
    const Corlab2026 m{.pair = corlab2026_pair(p.sphere, p.substrate), .coefficients = k};
    double previous = 1.0;
    for (double x = 1.0; x < 1e6; x *= 1.05) {
      const double e = m.cor(x * m.yield_velocity());
      ASSERT_GT(e, 0.0) << "pair " << i << " x " << x;
      ASSERT_LE(e, previous * (1.0 + 1e-12)) << "pair " << i << " x " << x;
      previous = e;
    }
  }
}

TEST(Corlab2026, JohnsonsQuarterPowerForPerfectPlasticityAndShallowCraters) {
  // Elastic sphere, no hardening, D_y -> 0 (the crater factor off): e ~ x^(-1/4) for x >> 1,
  // whatever share of the compliance the yielding body has.
  const Corlab2026Coefficients k = corlab2026_fitted();
  for (const double share : {0.1, 0.5, 0.9}) {
    Corlab2026Inputs in{.compliance_share = share};
    auto e_at = [&](double x) {
      in.velocity_ratio = x;
      return corlab2026_restitution(in, k);
    };
    const double slope = std::log(e_at(2e8) / e_at(1e8)) / std::log(2.0);
    EXPECT_NEAR(slope, -0.25, 1e-3) << "compliance share " << share;
  }
}

TEST(Corlab2026, TheBodyThatTakesMoreOfTheDeformationLosesMore) {
  // Same x, D_y and hardening, an elastic sphere: a yielding substrate with a larger share of the
  // compliance (a stiffer sphere) rebounds less, if the fitted stretch is positive (it is:
  // model_fit.json).
  const Corlab2026Coefficients k = corlab2026_fitted();
  ASSERT_GT(k.compliance_first, 0.0);
  Corlab2026Inputs stiff_sphere{
      .velocity_ratio = 30.0, .compliance_share = 0.2, .other_is_sphere = true};
  Corlab2026Inputs soft_sphere = stiff_sphere;
  soft_sphere.compliance_share = 0.8;
  EXPECT_LT(corlab2026_restitution(stiff_sphere, k), corlab2026_restitution(soft_sphere, k));
}

TEST(Corlab2026, AFlattenedSphereStaysContinuousAndMonotoneForAnyFirstYieldContact) {
  // A sphere that yields first gets Jackson & Green's falling hardness; even with an absurd
  // first-yield contact radius (its cap would fall below the first-yield pressure) e is 1 at
  // first yield and non-increasing.
  const Corlab2026Coefficients k = corlab2026_fitted();
  for (const double a_y : {1e-3, 0.05, 0.5, 5.0}) {
    Corlab2026Inputs in{.contact_radius_at_yield = a_y};
    in.velocity_ratio = 1.0 + 1e-9;
    EXPECT_GT(corlab2026_restitution(in, k), 1.0 - 1e-6) << "a_y/R " << a_y;
    double previous = 1.0;
    for (double x = 1.0; x < 1e6; x *= 1.1) {
      in.velocity_ratio = x;
      const double e = corlab2026_restitution(in, k);
      ASSERT_LE(e, previous * (1.0 + 1e-12)) << "a_y/R " << a_y << " x " << x;
      previous = e;
    }
  }
}

TEST(Corlab2026, RegisteredWithItsStatusAndTheShippedCoefficients) {
  const ModelInfo& info = model_info("corlab2026");
  EXPECT_EQ(info.status, Status::kVerifiedDataset);
  EXPECT_NE(info.citation.find("docs/theory/corlab_model.md"), std::string::npos);
  const Material sphere = body(210e9, 0.3, std::nullopt, 0.0);
  const Material substrate = body(210e9, 0.3, 500e6, 0.0);
  const Model m = make_model("corlab2026", sphere, substrate);
  const Corlab2026 direct{.pair = corlab2026_pair(sphere, substrate),
                          .coefficients = corlab2026_fitted()};
  for (const double v : {0.01, 0.1, 1.0, 5.0, 50.0}) EXPECT_EQ(m.cor(v), direct.cor(v));

  std::ifstream in(CORLAB_SOURCE_DIR "/data/fe_restitution/model_fit.json");
  ASSERT_TRUE(in) << "data/fe_restitution/model_fit.json missing";
  const auto json = nlohmann::json::parse(in)["coefficients"];
  const Corlab2026Coefficients k = corlab2026_fitted();
  ASSERT_EQ(json.size(), kCorlab2026Coefficients.size());
  // Bit for bit: the build's path (CMake's JSON reader, its 17-digit text, the compiler's
  // parse) against an independent reader of the same file.
  for (const auto& [name, member] : kCorlab2026Coefficients) {
    EXPECT_EQ(k.*member, json.at(std::string(name)).get<double>()) << name;
  }
}

}  // namespace
}  // namespace corlab::restitution
