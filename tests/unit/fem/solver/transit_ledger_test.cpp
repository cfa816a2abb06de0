// The subcycling's energy-in-transit ledger (fem/solver/transit_ledger.hpp) on a system whose
// energy is known exactly: two masses on three linear springs, stepped by the solver's
// asynchronous scheme (node 0 and the wall spring at the base step, node 1 and its two springs at
// twice it). With linear springs the trapezoid the elements book is the exact potential energy,
// so kinetic (product form) + potential energy - the ledger must equal the initial energy to
// round-off at every major-cycle boundary; without the ledger it is off by O(dt^2).
#include "fem/solver/transit_ledger.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "fem/solver/impact_model.hpp"
#include "fem/solver/impact_step.hpp"

namespace corlab::fem::solver {
namespace {

struct Chain {
  static constexpr double kMass = 1.0;                     // [kg], both nodes
  static constexpr double kWall0 = 3.0;                    // wall - node 0 spring, level 0 [N/m]
  static constexpr double kCoupling = 1.0;                 // node 0 - node 1 spring, level 1 [N/m]
  static constexpr double kWall1 = 0.5;                    // node 1 - wall spring, level 1 [N/m]
  std::array<double, 2> r{}, z{}, vr{}, vz{}, fr{}, fz{};  // z is the chain's direction
  std::array<int, 2> level{0, 1};

  [[nodiscard]] double potential() const {
    return 0.5 * (kWall0 * z[0] * z[0] + kCoupling * (z[1] - z[0]) * (z[1] - z[0]) +
                  kWall1 * z[1] * z[1]);
  }
};

// The energy error of the stepped chain, relative to its initial energy, at every major-cycle
// boundary over `steps` base steps of dt [s]: the largest with the ledger (first) and without.
std::array<double, 2> largest_errors(double dt, int steps) {
  SubcyclingLevels lv;
  lv.max_level = 1;
  lv.interface_nodes[0] = {0};  // node 0 (level 0) carries the level-1 coupling spring
  Chain c;
  c.vz = {1.0, -0.5};  // [m/s], springs unstretched: no force at the start, as in an impact run
  const double e0 = 0.5 * Chain::kMass * (c.vz[0] * c.vz[0] + c.vz[1] * c.vz[1]);
  TransitLedger ledger;
  ledger.reset(lv, c.vr.data(), c.vz.data());
  std::array<double, 2> worst{0.0, 0.0};
  for (long long k = 0; k < steps; ++k) {
    const int due = sync_level(k, lv.max_level);
    double ke = 0.0;
    for (int n = 0; n < 2; ++n) {
      if (c.level[n] > due) continue;
      const double v_new = c.vz[n] + dt * c.fz[n] / Chain::kMass;
      ke += 0.5 * Chain::kMass * c.vz[n] * v_new;
      c.vz[n] = v_new;
      c.z[n] += std::ldexp(dt, c.level[n]) * v_new;
      c.fz[n] = 0.0;
    }
    if (due == lv.max_level) {
      // Kinetic energy of the boundary (both nodes due), potential at its positions (before the
      // drift just done: undo it).
      const std::array<double, 2> z_now = c.z;
      for (int n = 0; n < 2; ++n) c.z[n] -= std::ldexp(dt, c.level[n]) * c.vz[n];
      const double booked = ke + c.potential();
      c.z = z_now;
      worst[0] = std::max(worst[0], std::abs(booked - ledger.energy - e0) / e0);
      worst[1] = std::max(worst[1], std::abs(booked - e0) / e0);
    }
    for (int l = 0; l < due; ++l) ledger.open_windows(lv, l, c.vr.data(), c.vz.data());
    // Elements due at k + 1: the wall spring of node 0 every step, node 1's springs every second
    // one (impulse 2 dt g: scattered as 2 g).
    c.fz[0] += -Chain::kWall0 * c.z[0];
    if (sync_level(k + 1, lv.max_level) == 1) {
      ledger.before_slow_pass(lv, 0, c.fr.data(), c.fz.data());
      const double coupling = Chain::kCoupling * (c.z[1] - c.z[0]);
      c.fz[0] += 2.0 * coupling;
      c.fz[1] += 2.0 * (-coupling - Chain::kWall1 * c.z[1]);
      ledger.after_slow_pass(lv, 0, dt, c.fr.data(), c.fz.data(), c.vr.data(), c.vz.data());
    }
  }
  return worst;
}

TEST(TransitLedger, WindowTransitFormula) {
  // 1/2 h (v2 - v1) (g_end - g_start)
  EXPECT_DOUBLE_EQ(window_transit(0.1, 1.0, 3.0, 5.0, 2.0), 0.5 * 0.1 * 2.0 * -3.0);
  EXPECT_EQ(window_transit(0.1, 1.0, 1.0, 5.0, 2.0), 0.0);  // no kick inside the window
  EXPECT_EQ(window_transit(0.1, 1.0, 3.0, 2.0, 2.0), 0.0);  // a constant slow force
}

TEST(TransitLedger, ClosesTheBalanceOfASubcycledChainToRoundOff) {
  const auto [with_ledger, without] = largest_errors(0.05, 20000);
  EXPECT_LT(with_ledger, 1e-12);
  // Without it the error is the transit, O(dt^2): not round-off.
  EXPECT_GT(without, 1e-4);
  // Halving the step quarters the transit (the ledger's terms are second order in dt).
  const auto [with_half, without_half] = largest_errors(0.025, 40000);
  EXPECT_LT(with_half, 1e-12);
  EXPECT_NEAR(without / without_half, 4.0, 0.5);
}

}  // namespace
}  // namespace corlab::fem::solver
