// The elastic oblique-impact theory of Maw, Barber & Fawcett (mbf_oblique.hpp) as a table: for
// Kharaz, Gorham & Salman's (2001) alumina sphere on soda-lime glass (R = 2.5 mm, 3.9 m/s,
// mu = 0.092) the rebound against the normalised incidence psi1, or its discretisation study.
//
// Sample runs:
//   build/bin/example_mbf_oblique_table                 # psi1 -> psi2, e_t, omega, angle
//   build/bin/example_mbf_oblique_table convergence     # psi2 against annuli and time steps
//   build/bin/example_mbf_oblique_table scan 1.5034     # psi2(psi1) on a fine grid for a chi
//   build/bin/example_mbf_oblique_table kharaz data/kharaz2001/measured_points.csv
//                                                       # against Kharaz et al.'s measurements
//   build/bin/example_mbf_oblique_table angles 2 4 40   # e_t, omega, angle at those angles (CSV)
//   build/bin/example_mbf_oblique_table chi             # the no-slip limit and psi2(1.2) vs chi
//   build/bin/example_mbf_oblique_table steel           # the FE comparison's cases (steel, mu 0.3)
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "corlab/restitution/mbf_oblique.hpp"

namespace {

using corlab::restitution::MbfDiscretisation;
using corlab::restitution::MbfImpact;

constexpr double kDegreesPerRadian = 57.295779513082320877;

// Kharaz et al.'s alumina on glass (mbf_oblique.hpp).
MbfImpact kharaz(double angle_deg) { return corlab::restitution::kharaz2001_impact(angle_deg); }

void table() {
  const MbfImpact base = kharaz(10.0);
  const double kappa = corlab::restitution::mbf_stiffness_ratio(
      base.sphere_modulus, base.sphere_poisson, base.flat_modulus, base.flat_poisson);
  const double chi = corlab::restitution::mbf_chi(kappa, base.gyration);
  fmt::print("# alumina on glass: kappa = {:.5f}, chi = {:.5f}, 4 chi - 1 = {:.4f}\n", kappa, chi,
             4.0 * chi - 1.0);
  fmt::print("{:>6} {:>8} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>4} {}\n", "psi1", "theta", "psi2",
             "e_t", "e_t_rigid", "omega", "omega_rig", "angle", "rev", "regime");
  for (double psi1 :
       {0.1, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0, 8.0}) {
    const double theta = std::atan(psi1 * base.friction / kappa) * kDegreesPerRadian;
    const auto r =
        corlab::restitution::mbf_rebound(kharaz(theta), {.annuli = 400, .time_steps = 20000});
    // Rigid body, sticking contact leaves rolling (beta = 0) where Coulomb does not bind.
    const double tan_t = std::tan(theta / kDegreesPerRadian);
    const double slide = 1.0 - 2.0 * base.friction / tan_t;
    const double e_t_rigid = std::max(slide, 1.0 - base.gyration / (1.0 + base.gyration));
    const double v_t = base.velocity * std::sin(theta / kDegreesPerRadian);
    const double omega_rigid = (1.0 - e_t_rigid) * v_t / (base.gyration * base.radius);
    fmt::print("{:6.2f} {:8.4f} {:9.5f} {:9.5f} {:9.5f} {:9.2f} {:9.2f} {:9.4f} {:4d} {}\n", psi1,
               theta, r.psi2, r.tangential_restitution, e_t_rigid, r.spin, omega_rigid,
               r.rebound_angle, r.force_reversals,
               r.gross_sliding ? "gross sliding" : "micro-slip");
  }
}

void convergence() {
  const double chi = 1.5;
  fmt::print("# chi = {}: psi2 against the discretisation\n", chi);
  fmt::print("{:>6} {:>7} {:>7} {:>13} {:>13}\n", "psi1", "annuli", "steps", "psi2", "e_n - 1");
  for (double psi1 : {0.5, 1.5, 3.0, 4.5}) {
    for (int level = 0; level < 5; ++level) {
      const int annuli = 50 << level;
      const int steps = 2500 << level;
      const auto n = corlab::restitution::mbf_normalised(
          chi, psi1, MbfDiscretisation{.annuli = annuli, .time_steps = steps});
      fmt::print("{:6.2f} {:7d} {:7d} {:13.8f} {:13.3e}\n", psi1, annuli, steps, n.psi2,
                 n.normal_restitution - 1.0);
    }
  }
}

void scan(double chi) {
  fmt::print("# chi = {}: psi1 psi2 force_reversals gross_sliding\n", chi);
  double best_psi1 = 0.0;
  double best_psi2 = std::numeric_limits<double>::infinity();
  double zero = std::numeric_limits<double>::quiet_NaN();
  double previous = 0.0;
  for (int i = 1; i <= 400; ++i) {
    const double psi1 = 0.02 * i;
    const auto n =
        corlab::restitution::mbf_normalised(chi, psi1, {.annuli = 400, .time_steps = 20000});
    if (n.psi2 < best_psi2) {
      best_psi2 = n.psi2;
      best_psi1 = psi1;
    }
    if (std::isnan(zero) && i > 1 && previous < 0.0 && n.psi2 >= 0.0) {
      zero = psi1 - 0.02 * n.psi2 / (n.psi2 - previous);
    }
    previous = n.psi2;
    if (i % 10 == 0) {
      fmt::print("{:6.2f} {:10.5f} {:3d} {}\n", psi1, n.psi2, n.force_reversals,
                 n.gross_sliding ? 1 : 0);
    }
  }
  fmt::print("# minimum psi2 = {:.5f} at psi1 = {:.2f} (grid 0.02); psi2 = 0 at psi1 = {:.4f}\n",
             best_psi2, best_psi1, zero);
}

// Bisection for the chi in [lo, hi] where f changes sign.
template <typename F>
double sign_change(F f, double lo, double hi) {
  const double f_lo = f(lo);
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f_lo * f(mid) <= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// The small-psi1 limit (no slip: psi2/psi1) and psi2 at psi1 = 1.2 (MBF 1976's Fig. 4) against
// chi, and the reversals of the tangential force at psi1 = 0.3.
void chi_dependence() {
  const MbfDiscretisation fine{.annuli = 400, .time_steps = 20000};
  const MbfDiscretisation no_slip{.annuli = 400, .time_steps = 20000, .coulomb = false};
  auto ratio = [&](double chi) {
    return corlab::restitution::mbf_normalised(chi, 1.0, no_slip).contact_point_ratio;
  };
  auto psi2_at = [&](double chi) {
    return corlab::restitution::mbf_normalised(chi, 1.2, fine).psi2;
  };
  fmt::print("{:>5} {:>16} {:>12} {:>14}\n", "chi", "no-slip psi2/psi1", "psi2(1.2)",
             "reversals(0.3)");
  for (int i = 1; i <= 12; ++i) {
    const double chi = 0.25 * i;
    fmt::print("{:5.2f} {:+16.4f} {:+12.4f} {:14d}\n", chi, ratio(chi), psi2_at(chi),
               corlab::restitution::mbf_normalised(chi, 0.3, fine).force_reversals);
  }
  fmt::print("# no-slip ratio = 0 at chi = {:.4f}; psi2(1.2) = 0 at chi = {:.4f}\n",
             sign_change(ratio, 1.0, 1.5), sign_change(psi2_at, 1.0, 2.0));
}

// The cases of verification_mbf_hex_impact_test: elastic steel (210 GPa, 0.3, 7850 kg/m^3,
// R = 35 mm) on the like-material flat, mu = 0.3, v_n = 10 m/s, at psi1 = 0.5 to 6.
void steel_cases() {
  const double kappa = corlab::restitution::mbf_stiffness_ratio(210e9, 0.3, 210e9, 0.3);
  for (double psi1 : {0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0}) {
    const double theta = std::atan(psi1 * 0.3 / kappa);
    const auto r = corlab::restitution::mbf_rebound({.radius = 35e-3,
                                                     .density = 7850.0,
                                                     .sphere_modulus = 210e9,
                                                     .sphere_poisson = 0.3,
                                                     .flat_modulus = 210e9,
                                                     .flat_poisson = 0.3,
                                                     .velocity = 10.0 / std::cos(theta),
                                                     .angle = theta * kDegreesPerRadian,
                                                     .friction = 0.3},
                                                    {.annuli = 400, .time_steps = 20000});
    fmt::print(
        "psi1 {:.2f} theta {:.4f} v {:.4f} chi {:.5f} psi2 {:.5f} e_t {:.5f} omega {:.4f} "
        "angle {:.4f} t_c {:.4e}\n",
        psi1, theta * kDegreesPerRadian, 10.0 / std::cos(theta), r.chi, r.psi2,
        r.tangential_restitution, r.spin, r.rebound_angle, r.contact_time);
  }
}

// Every measured point of data/kharaz2001 (source, quantity, angle, value, unit) beside MBF.
void kharaz_points(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(file, line);  // header
  fmt::print("{:>27} {:>28} {:>8} {:>10} {:>10} {:>9}\n", "source", "quantity", "angle", "measured",
             "MBF", "MBF-meas");
  while (std::getline(file, line)) {
    std::stringstream row(line);
    std::string source, quantity, angle, value;
    std::getline(row, source, ',');
    std::getline(row, quantity, ',');
    std::getline(row, angle, ',');
    std::getline(row, value, ',');
    const double theta = std::stod(angle);
    const auto r =
        corlab::restitution::mbf_rebound(kharaz(theta), {.annuli = 400, .time_steps = 20000});
    const double v_n = 3.9 * std::cos(theta / kDegreesPerRadian);
    double mbf = r.tangential_restitution;
    if (quantity == "omega") mbf = r.spin;
    if (quantity == "rebound_angle_com") mbf = r.rebound_angle;
    if (quantity == "rebound_angle_contact_point") {
      mbf = std::atan2(r.contact_slip_velocity, r.normal_restitution * v_n) * kDegreesPerRadian;
    }
    fmt::print("{:>27} {:>28} {:8.3f} {:10.4f} {:10.4f} {:9.4f}\n", source, quantity, theta,
               std::stod(value), mbf, mbf - std::stod(value));
  }
  double deepest = 0.0;
  double at = 0.0;
  for (double theta = 5.0; theta <= 30.0; theta += 0.5) {
    const auto r = corlab::restitution::mbf_rebound(kharaz(theta));
    const double v_n = 3.9 * std::cos(theta / kDegreesPerRadian);
    const double a =
        std::atan2(r.contact_slip_velocity, r.normal_restitution * v_n) * kDegreesPerRadian;
    if (a < deepest) {
      deepest = a;
      at = theta;
    }
  }
  fmt::print("# MBF's deepest contact-point angle: {:.4f} deg at {:.1f} deg (0.5-deg grid)\n",
             deepest, at);
}

// MBF for Kharaz's case at the given angles [deg], as CSV (angle, e_t, omega [rad/s], c.o.m.
// rebound angle [deg]): the theory column of scripts/kharaz_fe_table.py.
void kharaz_angles(int count, char** angles) {
  fmt::print("impact_angle_deg,e_t,omega,rebound_angle_com\n");
  for (int i = 0; i < count; ++i) {
    const double theta = std::strtod(angles[i], nullptr);
    const auto r =
        corlab::restitution::mbf_rebound(kharaz(theta), {.annuli = 400, .time_steps = 20000});
    fmt::print("{},{:.6f},{:.4f},{:.4f}\n", theta, r.tangential_restitution, r.spin,
               r.rebound_angle);
  }
}
}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "table";
    if (mode == "table") {
      table();
    } else if (mode == "convergence") {
      convergence();
    } else if (mode == "steel") {
      steel_cases();
    } else if (mode == "chi") {
      chi_dependence();
    } else if (mode == "kharaz" && argc > 2) {
      kharaz_points(argv[2]);
    } else if (mode == "angles" && argc > 2) {
      kharaz_angles(argc - 2, argv + 2);
    } else if (mode == "scan" && argc > 2) {
      scan(std::strtod(argv[2], nullptr));
    } else {
      fmt::print(stderr,
                 "usage: example_mbf_oblique_table [table | convergence | scan CHI | kharaz CSV | "
                 "angles DEG... | chi | steel]\n");
      return 2;
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}\n", e.what());
    return 1;
  }
  return 0;
}
