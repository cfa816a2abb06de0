// Verification of the 3-D model's error bars on e_n, e_t and omega (discretisation_error.hpp,
// error_bars.md "The 3-D model"), in two parts:
// - the four stored seeded samples (data/error_bar_coverage/3d_seed<SEED>/runs.csv, made by
//   scripts/error_bar_coverage_3d.py; 20261129-31 with 0.9.0's contact, 20261132 with the
//   friction at the contact points that followed it): the estimators re-applied to each
//   case's stored companions (the script's --score-only), per quantity the cases whose h / sqrt 2
//   value lies inside the bar and the median relative bar over the median relative
//   |x(h / sqrt 2) - x(h)|, held at what they measured, for corlab's bars and for issue 39's
//   candidate scatter_3d on e_t and omega. Issue 39 asks >= 23 of 24 inside at a width <= 3:
//   neither meets both on every sample (error_bars.md says why).
// - two of the first sample's cases, one elastic and one elastic-plastic, each run with its error
//   estimate and again at h / sqrt 2: the estimate end to end. Each finer value must lie inside
//   its bar (as measured: 6 of 6), and the median of the six bars, relative to each value, must
//   be at most issue 39's 3 x the median relative change: 2.61 x with the friction at the contact
//   points (3.05e-2 against 1.17e-2; 0.9.0's contact: 2.60 x, 4.71e-2 against 1.81e-2; about
//   3.2 x with scatter_3d on e_t and omega). A median over six values of two cases: the samples
//   above score 24 cases per quantity.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/error_bar.hpp"
#include "support/coverage_tally.hpp"

namespace corlab::fem {
namespace {

/// One case of the script's sample: its BASE settings with the drawn angle [deg], speed [m/s],
/// friction [-] and the flat's yield stress ("none": elastic).
ImpactConfig sample_case(double angle, double velocity, double friction, const char* sigma_y) {
  ImpactConfig c;
  apply_settings(
      c,
      {"solver.model=3d", "sphere.radius=2.5e-3", "substrate.radius=2.5e-3",
       "substrate.depth=2.5e-3", "mesh.contact_elements=4", "mesh.h_min=1.25e-4", "mesh.h_max=1e-3",
       "mesh.growth=1.6", "impact.angle=" + std::to_string(angle),
       "impact.velocity=" + std::to_string(velocity),
       "contact.friction=" + std::to_string(friction), std::string("substrate.sigma_y=") + sigma_y},
      "test");
  return c;
}

constexpr std::array<const char*, 3> kQuantities{"e_n", "e_t", "omega"};

/// A stored sample's runs: (case, ratio rounded to 1e-6) -> the row's fields by column name.
using Runs = std::map<std::pair<std::string, long>, std::map<std::string, std::string>>;

Runs read_runs(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  EXPECT_TRUE(in) << csv;
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  for (std::stringstream s(line); std::getline(s, line, ',');) header.push_back(line);
  Runs runs;
  while (std::getline(in, line)) {
    std::map<std::string, std::string> row;
    std::stringstream s(line);
    for (const std::string& name : header) std::getline(s, row[name], ',');
    runs[{row["case"], std::lround(std::stod(row["ratio"]) * 1e6)}] = row;
  }
  return runs;
}

/// The sample's per-quantity tallies with the estimators given, relative to |x(h)| (as the
/// script's score()).
std::array<test::CoverageTally, 3> score_sample(const Runs& runs,
                                                const std::array<std::string_view, 3>& estimators) {
  std::array<test::CoverageTally, 3> tally;
  const auto separated = [&](const std::string& c,
                             double q) -> const std::map<std::string, std::string>* {
    const auto it = runs.find({c, std::lround(q * 1e6)});
    return it != runs.end() && it->second.at("status") == "separated" ? &it->second : nullptr;
  };
  for (const auto& [key, row] : runs) {
    if (key.second != 1000000) continue;  // one pass per case, at its own mesh
    const auto* reference = separated(key.first, 1.0 / std::sqrt(2.0));
    if (separated(key.first, 1.0) == nullptr || reference == nullptr) continue;
    for (std::size_t k = 0; k < kQuantities.size(); ++k) {
      std::vector<double> x{std::stod(row.at(kQuantities[k]))};
      std::vector<double> ratios{1.0};
      for (const double q : kErrorBarRatios3d) {
        const auto* r = separated(key.first, q);  // the companions corlab keeps
        if (r == nullptr ||
            std::stod(r->at("a_over_h")) < kMinCompanionContactElements * (1 - 1e-9))
          continue;
        x.push_back(std::stod(r->at(kQuantities[k])));
        ratios.push_back(q);
      }
      const double bar = error_bar(estimators[k], x, ratios);
      const double change = std::abs(std::stod(reference->at(kQuantities[k])) - x[0]);
      tally[k].add(bar / std::abs(x[0]), change / std::abs(x[0]));
    }
  }
  return tally;
}

TEST(ErrorBarCoverage3d, StoredSamplesPerQuantity) {
  // Per sample, estimators (e_n, e_t, omega) and quantity: the fewest cases inside and the widest
  // median bar / median change, as measured (0.01 above the width measured).
  struct Bound {
    int inside;
    double width;
  };
  struct Check {
    const char* sample;
    std::array<std::string_view, 3> estimators;
    std::array<Bound, 3> bounds;
  };
  constexpr std::array<std::string_view, 3> kCorlab{kErrorBar3dNormal, kErrorBar3dTangential,
                                                    kErrorBar3dTangential};
  constexpr std::array<std::string_view, 3> kCandidate{kErrorBar3dNormal, "scatter_3d",
                                                       "scatter_3d"};
  const std::array<Check, 8> checks{{
      {"3d_seed20261129", kCorlab, {{{23, 5.47}, {21, 1.86}, {23, 2.18}}}},
      {"3d_seed20261130", kCorlab, {{{23, 21.38}, {22, 3.24}, {24, 3.16}}}},
      {"3d_seed20261131", kCorlab, {{{22, 6.46}, {24, 4.02}, {23, 3.31}}}},
      {"3d_seed20261132", kCorlab, {{{24, 4.27}, {21, 8.85}, {23, 4.0}}}},
      {"3d_seed20261129", kCandidate, {{{23, 5.47}, {23, 2.26}, {23, 2.65}}}},
      {"3d_seed20261130", kCandidate, {{{23, 21.38}, {24, 3.94}, {24, 4.45}}}},
      {"3d_seed20261131", kCandidate, {{{22, 6.46}, {24, 4.98}, {23, 4.63}}}},
      {"3d_seed20261132", kCandidate, {{{24, 4.27}, {23, 10.76}, {23, 5.26}}}},
  }};
  for (const Check& check : checks) {
    const auto tally = score_sample(read_runs(std::filesystem::path(CORLAB_SOURCE_DIR) / "data" /
                                              "error_bar_coverage" / check.sample / "runs.csv"),
                                    check.estimators);
    for (std::size_t k = 0; k < kQuantities.size(); ++k) {
      const double width = test::median(tally[k].bars) / test::median(tally[k].changes);
      std::printf("%s %s by %s: %d of %zu inside, width %.2f\n", check.sample, kQuantities[k],
                  std::string(check.estimators[k]).c_str(), tally[k].inside, tally[k].bars.size(),
                  width);
      EXPECT_EQ(tally[k].bars.size(), 24U) << check.sample << " " << kQuantities[k];
      EXPECT_GE(tally[k].inside, check.bounds[k].inside) << check.sample << " " << kQuantities[k];
      EXPECT_LE(width, check.bounds[k].width) << check.sample << " " << kQuantities[k];
    }
  }
}

TEST(ErrorBarCoverage3d, TwoCasesOfTheSeededSample) {
  struct Case {
    double angle, velocity, friction;
    const char* sigma_y;
  };
  const std::array<Case, 2> cases{{{3.83, 5.911, 0.147, "none"}, {6.14, 1.422, 0.255, "850e6"}}};
  test::CoverageTally tally;  // relative to each value: omega is 28-96 rad/s, e_n near 1
  for (const Case& k : cases) {
    const ImpactConfig c = sample_case(k.angle, k.velocity, k.friction, k.sigma_y);
    const ImpactResult r = simulate_with_error_estimate(c);
    SimulationControl e_only;  // as the companions: ends one short window after the contact
    e_only.e_only = true;
    const ImpactResult finer = simulate(coarsened(c, 1.0 / std::sqrt(2.0)), e_only);
    ASSERT_TRUE(r.separated && finer.separated) << r.status_detail << finer.status_detail;
    const std::array<std::array<double, 3>, 3> rows{{{r.e_n, r.e_error, finer.e_n},
                                                     {r.e_t, r.e_t_error, finer.e_t},
                                                     {r.omega, r.omega_error, finer.omega}}};
    for (const auto& [x, bar, fine] : rows) {
      ASSERT_TRUE(std::isfinite(bar)) << r.e_error_reason;
      const double scale = std::abs(x);
      const char* verdict = tally.add(bar / scale, std::abs(fine - x) / scale);
      std::printf("%5.2f deg, %6.3f m/s: %.5g +/- %.3g, finer %.5g (%s)\n", k.angle, k.velocity, x,
                  bar, fine, verdict);
    }
  }
  tally.print();
  EXPECT_EQ(tally.inside, 6);
  EXPECT_LE(test::median(tally.bars), 3.0 * test::median(tally.changes));
}

}  // namespace
}  // namespace corlab::fem
