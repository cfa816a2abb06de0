// SPDX-License-Identifier: BSD-3-Clause
#include "dem/detail/export_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "corlab/dem/contact_laws.hpp"
#include "corlab/dem/tangential.hpp"
#include "corlab/version.hpp"
#include "dem/detail/script_text.hpp"

namespace corlab::dem::detail {

std::string export_header(const ExportSpec& spec, std::string_view code) {
  std::string out =
      fmt::format("# corlab {} dem export for {} (SI units). Particle types:\n", kVersion, code);
  for (std::size_t i = 0; i < spec.types.size(); ++i) {
    const auto id = static_cast<int>(i) + 1;
    out += fmt::format("#   type {} = {}: {}, radius {:.6g} m\n", id, type_label(spec, id),
                       script_text(spec.types[i].material.name), spec.types[i].radius);
  }
  if (spec.wall) {
    out += fmt::format("#   wall = {}: {} (rigid, flat)\n", wall_label(spec),
                       script_text(spec.wall->name));
  }
  return out;
}

bool has_friction(const ExportSpec& spec) {
  return spec.friction > 0.0 || std::any_of(spec.pair_friction.begin(), spec.pair_friction.end(),
                                            [](const auto& p) { return p.value > 0.0; });
}

std::string friction_words(const ExportSpec& spec) {
  std::string out = fmt::format("{:.6g}", spec.friction);
  for (const auto& p : spec.pair_friction) {
    out += fmt::format("; {}/{} {:.6g}", script_text(p.first), script_text(p.second), p.value);
  }
  return out;
}

double rolling_stiffness(double e_star, double r_star, double m_star, double g_star, double v_max) {
  const double k = hertz_stiffness(e_star, r_star);
  const double delta = std::pow(1.25 * m_star * v_max * v_max / k, 0.4);
  return mindlin_coefficient(g_star) * std::sqrt(r_star * delta);
}

std::string fit_comment(const CurveFit& fit) {
  return fmt::format("fit over {:.4g}..{:.4g} m/s ({} speeds): rms {:.2e}, max |de| {:.2e}",
                     fit.velocities.front(), fit.velocities.back(), fit.velocities.size(),
                     fit.rms_error, fit.max_abs_error);
}

std::vector<double> table_speeds(const ExportSpec& spec, int points) {
  validate_table_points(points);
  std::vector<double> v(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) {
    v[static_cast<std::size_t>(i)] = spec.v_min + (spec.v_max - spec.v_min) * i / (points - 1);
  }
  return v;
}

double recommended_step(const std::vector<PairCalibration>& pairs,
                        const std::function<CodeLaw(const PairCalibration&)>& law_of) {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& p : pairs) {
    dt = std::min(dt, p.contact_time_fast / step_rule(law_of(p)).steps_per_contact);
  }
  return dt;
}

std::string time_step_comment(const ExportSpec& spec,
                              const std::vector<PairCalibration>& pairs,
                              const std::function<CodeLaw(const PairCalibration&)>& law_of,
                              std::string_view comment) {
  std::string out = fmt::format(
      "{0} Time step. Hertz contact time of each pair at v_max = {1:.4g} m/s and v_min = {2:.4g} "
      "m/s:\n",
      comment, spec.v_max, spec.v_min);
  for (const auto& p : pairs) {
    const StepRule& rule = step_rule(law_of(p));
    out += fmt::format("{}   {}: {:.3e} s / {:.3e} s; {}: contact time / {}\n", comment, p.name(),
                       p.contact_time_fast, p.contact_time_slow, rule.name, rule.steps_per_contact);
  }
  out += fmt::format(
      "{0} Recommended step {1:.3e} s (the shortest of those): at it, and at twice it, this\n"
      "{0} code's e stays within {2:.0e} of its law's (measured in drop tests, wherever in a step\n"
      "{0} a contact starts: scripts/dem_time_step.py); a larger step delivers another e.\n",
      comment, recommended_step(pairs, law_of), kTimeStepError);
  return out;
}

}  // namespace corlab::dem::detail

#include <cmath>

#include "corlab/dem/hysteresis_chi.hpp"

namespace corlab::dem::detail {

double hook_table_error(const ExportSpec& spec, const PairCalibration& pair, bool chi_table) {
  const auto v = table_speeds(spec, kHookTableRows);
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < v.size(); ++k) {
    const double mid = 0.5 * (v[k] + v[k + 1]);
    const double e0 = pair.curve(v[k]);
    const double e1 = pair.curve(v[k + 1]);
    const double e =
        chi_table ? exact_restitution(0.5 * (exact_chi(e0) + exact_chi(e1))) : 0.5 * (e0 + e1);
    worst = std::max(worst, std::abs(e - pair.curve(mid)));
  }
  return worst;
}

}  // namespace corlab::dem::detail
