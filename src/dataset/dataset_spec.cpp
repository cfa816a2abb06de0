// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/dataset_spec.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <sstream>

#include "corlab/core/error.hpp"
#include "corlab/core/escaped_text.hpp"
#include "corlab/core/number.hpp"
#include "corlab/dataset/sobol_sequence.hpp"

namespace corlab::dataset {
namespace {

// `v` as a TOML basic string: "..." with quotes, backslashes and control characters escaped.
std::string toml_string(const std::string& v) {
  std::ostringstream out;
  const toml::value<std::string> node(v);
  out << toml::toml_formatter{node, toml::format_flags::allow_unicode_strings};
  return out.str();
}

std::string toml_value(const std::string& v) { return parse_double(v) ? v : toml_string(v); }

void append_settings(std::string& out, const study::Settings& settings) {
  for (const auto& [key, value] : settings) {
    out += fmt::format("{} = {}\n", toml_string(key), toml_value(value));
  }
}

// The header's line on a pair box's extra coordinates (empty for the flat box).
std::string pair_box_comment(const ImpactBox& box) {
  if (!is_pair_box(box)) return "";
  return fmt::format(
      ",\n# rho_sphere/rho_substrate in [{}, {}], a flat substrate for {} of the points and\n"
      "# R1/R2 in [{}, {}] for the rest",
      box.density_ratio.min, box.density_ratio.max, box.flat_fraction, box.radius_ratio.min,
      box.radius_ratio.max);
}

}  // namespace

DatasetDesign pair_design() {
  return DatasetDesign{.name = "fe_restitution_pairs", .points = 2048, .box = pair_box()};
}

void validate_design_points(std::size_t points, std::string_view field) {
  if (points < 1 || points > study::kMaxRunsLimit) {
    throw_invalid(
        field, static_cast<double>(points),
        fmt::format("in [1, {}] (the most runs a sweep spec may hold)", study::kMaxRunsLimit));
  }
}

std::vector<DesignPoint> design_points(const DatasetDesign& design) {
  validate_design_points(design.points, "points");
  const auto u = sobol_points(box_dimension(design.box), design.points);
  std::vector<DesignPoint> points;
  points.reserve(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    DesignPoint p{.index = i, .u = u[i], .point = box_point(design.box, u[i]), .settings = {}};
    p.settings = point_settings(design.box, p.point);
    points.push_back(std::move(p));
  }
  return points;
}

study::Settings dataset_base_settings(const ImpactBox& box) {
  study::Settings base{
      {"substrate.E", fmt::format("{}", box.substrate_modulus)},
      {"substrate.rho", fmt::format("{}", box.density)},
  };
  // A pair box sets each case's sphere.rho.
  if (!is_pair_box(box)) base.emplace_back("sphere.rho", fmt::format("{}", box.density));
  base.insert(base.end(), {
                              {"mesh.h_min", "0.00025"},
                              {"mesh.contact_elements", "12"},
                          });
  // Just above first yield at k2 = 1e-3 the contact is ~0.1 mm wide and lasts ~20 ms: ~3e7 steps
  // of 0.7 ns before mass scaling (docs/theory/dataset.md). A pair box's light, stiff spheres
  // (E ratio 20, density ratio 0.1: waves 14 times faster) need up to ten times more.
  base.emplace_back("solver.max_steps", is_pair_box(box) ? "1000000000" : "100000000");
  return base;
}

std::string dataset_spec_toml(const DatasetDesign& design, std::string_view command) {
  const ImpactBox& box = design.box;
  std::string out = fmt::format(
      "# corlab FE restitution dataset: design (docs/theory/dataset.md). Written by\n"
      "#   {}\n"
      "# Do not edit: a test checks that the command writes this file. One [[cases]] per Sobol\n"
      "# point of the box k2 in [{}, {}], v/v_y in [{}, min({} m/s, damage number {})],\n"
      "# E_sphere/E_substrate in [{}, {}], sphere elastic or sigma_y ratio in [{}, {}],\n"
      "# nu in [{}, {}], H/E in [{}, {}]{}.\n"
      "[study]\nname = {}\ndescription = \"FE restitution dataset: {} Sobol points of the "
      "dimensionless box\"\nmax_runs = {}\n\n[base]\n",
      escaped_text(command), box.k2.min, box.k2.max, box.velocity_ratio_min, box.velocity_max,
      box.damage_number_max, box.modulus_ratio.min, box.modulus_ratio.max,
      box.sphere_yield_ratio.min, box.sphere_yield_ratio.max, box.nu.min, box.nu.max,
      box.hardening_ratio.min, box.hardening_ratio.max, pair_box_comment(box),
      toml_string(design.name), design.points, std::max<std::size_t>(design.points, 1));
  append_settings(out, dataset_base_settings(box));
  for (const DesignPoint& p : design_points(design)) {
    out += fmt::format("\n[[cases]]  # design point {}\n", p.index);
    append_settings(out, p.settings);
  }
  return out;
}

}  // namespace corlab::dataset
