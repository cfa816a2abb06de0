// MBF (mbf_oblique.hpp) against Kharaz, Gorham & Salman's (2001) measured rebounds of alumina on
// glass (data/kharaz2001, two independent digitisations). Kharaz et al. report that their
// measurements agree closely with Maw et al.'s theory; this checks that ours does, in the
// small-angle regime where the tangential compliance matters (theta <= 31.5 deg), and
// that the contact point's velocity reverses where and as much as measured.
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "corlab/restitution/mbf_oblique.hpp"

namespace corlab::restitution {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct Point {
  std::string source;
  std::string quantity;
  double angle = 0.0;  // [deg]
  double value = 0.0;
};

std::vector<Point> measured() {
  std::ifstream file(std::string(CORLAB_DATA_DIR) + "/kharaz2001/measured_points.csv");
  std::vector<Point> points;
  std::string line;
  std::getline(file, line);
  while (std::getline(file, line)) {
    std::stringstream row(line);
    Point p;
    std::string angle;
    std::string value;
    std::getline(row, p.source, ',');
    std::getline(row, p.quantity, ',');
    std::getline(row, angle, ',');
    std::getline(row, value, ',');
    p.angle = std::stod(angle);
    p.value = std::stod(value);
    points.push_back(p);
  }
  return points;
}

MbfRebound kharaz(double angle_deg) {
  return mbf_rebound(restitution::kharaz2001_impact(angle_deg));
}

// The contact point's rebound angle atan(u' / v_n') [deg].
double contact_point_angle(const MbfRebound& r, double angle_deg) {
  const double v_n = 3.9 * std::cos(angle_deg * kDeg);
  return std::atan2(r.contact_slip_velocity, r.normal_restitution * v_n) / kDeg;
}

// Measured: +0.77 deg at 2.1 and 3.9 deg (the contact point still moves forward: for this chi =
// 1.50 the sticking contact's tangential oscillation ends past a full period), -1.06 deg at 9.7,
// -8.53 deg at 20.3 (the deepest reversal), -2.55 deg at 30.2. MBF gives the same signs, and the
// deepest reversal within 1 deg of the measured value.
TEST(MbfKharaz, TheContactPointReversesAsMeasured) {
  int compared = 0;
  for (const Point& p : measured()) {
    if (p.quantity != "rebound_angle_contact_point" || p.angle > 31.0) continue;
    const double theory = contact_point_angle(kharaz(p.angle), p.angle);
    EXPECT_EQ(std::signbit(theory), std::signbit(p.value)) << p.angle;
    if (p.angle > 15.0 && p.angle < 25.0) {
      EXPECT_NEAR(theory, p.value, 1.0) << p.angle;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 1);
  // The theory's deepest reversal lies between the measured 9.7 and 30.2 degrees.
  double deepest = 0.0;
  double at = 0.0;
  for (double angle = 5.0; angle <= 30.0; angle += 0.5) {
    const double a = contact_point_angle(kharaz(angle), angle);
    if (a < deepest) {
      deepest = a;
      at = angle;
    }
  }
  EXPECT_GT(at, 15.0);
  EXPECT_LT(at, 25.0);
  EXPECT_NEAR(deepest, -9.1, 0.2);  // -9.108 deg at 22.0 deg (200 and 400 annuli alike)
}

// e_t and omega up to 31.5 deg. The readings differ by about 0.005 in e_t and 6 rad/s in omega;
// e_t changes by 0.015 per degree near 10 deg, so a 2-degree difference in the angle read off
// the figure is 0.03. Bounds: 0.04 in e_t and 30 rad/s in omega (measured residuals, both
// sources: e_t -0.036 ... +0.006, omega -24 ... +17 rad/s; docs/theory/oblique_theory.md).
TEST(MbfKharaz, TangentialRestitutionAndSpinUpToThirtyDegrees) {
  int compared = 0;
  for (const Point& p : measured()) {
    if (p.angle > 31.5) continue;
    const MbfRebound r = kharaz(p.angle);
    if (p.quantity == "e_t") {
      EXPECT_NEAR(r.tangential_restitution, p.value, 0.04) << p.source << " " << p.angle;
      ++compared;
    } else if (p.quantity == "omega") {
      EXPECT_NEAR(r.spin, p.value, 30.0) << p.source << " " << p.angle;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 18);
}

}  // namespace
}  // namespace corlab::restitution
