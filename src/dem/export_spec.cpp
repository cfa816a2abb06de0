// The user's side of a DEM export: labelled materials, --pair and --pair-table, and the checks of
// the whole spec (labels, radii, targets, the pairs named).
// SPDX-License-Identifier: BSD-3-Clause
#include "dem/detail/export_spec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"
#include "corlab/dem/tangential.hpp"
#include "corlab/materials/material_database.hpp"

namespace corlab::dem {
namespace {

constexpr std::string_view kLabelChars =
    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.+";

bool is_label(std::string_view s) {
  return !s.empty() && s.find_first_not_of(kLabelChars) == std::string_view::npos;
}

// A label of digits only reads as a type id in --pair (1/2=E names types 1 and 2).
bool is_type_id(std::string_view s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
}

// The keys of an inline material spec: "E=..." is a material, not a label "E".
bool is_material_key(std::string_view s) {
  return s == "E" || s == "nu" || s == "rho" || s == "sy" || s == "sigma_y" || s == "H";
}

// A label as written: labels go into LAMMPS comments, YADE strings and file names.
std::string clean_label(std::string name) {
  for (char& c : name) {
    if (kLabelChars.find(c) == std::string_view::npos) c = '_';
  }
  return name;
}

}  // namespace

LabelledMaterial parse_labelled_material(std::string_view text, std::string_view field) {
  LabelledMaterial out;
  const auto eq = text.find('=');
  const std::string_view head = trim(text.substr(0, eq == std::string_view::npos ? 0 : eq));
  if (eq != std::string_view::npos && head.find(',') == std::string_view::npos &&
      !is_material_key(head)) {
    if (!is_label(head)) {
      throw_invalid(std::string(field) + " label", head,
                    "letters, digits, _ . + (LABEL=MATERIAL, e.g. glass=E=63e9,nu=0.22,rho=2500)");
    }
    out.label = std::string(head);
    out.label_given = true;
    out.material = parse_material_spec(text.substr(eq + 1), field);
    return out;
  }
  out.material = parse_material_spec(text, field);
  if (out.material.name != "inline") out.label = clean_label(out.material.name);
  return out;
}

PairRestitution parse_pair_restitution(std::string_view text) {
  constexpr std::string_view kSyntax = "A/B=E with type labels or ids (or wall) and e in (0, 1]";
  const auto slash = text.find('/');
  const auto eq = text.rfind('=');
  if (slash == std::string_view::npos || eq == std::string_view::npos || eq < slash) {
    throw_invalid("pair", text, kSyntax);
  }
  PairRestitution p;
  p.first = std::string(trim(text.substr(0, slash)));
  p.second = std::string(trim(text.substr(slash + 1, eq - slash - 1)));
  if (p.first.empty() || p.second.empty()) throw_invalid("pair", text, kSyntax);
  p.restitution = parse_finite("pair " + p.first + "/" + p.second, text.substr(eq + 1));
  if (!(p.restitution > 0.0 && p.restitution <= 1.0)) {
    throw_invalid("pair " + p.first + "/" + p.second, p.restitution, "in (0, 1] (1: elastic)");
  }
  return p;
}

PairValue parse_pair_value(std::string_view text, std::string_view field) {
  const std::string syntax =
      fmt::format("A/B=X with type labels or ids (or a wall's label) and a {} >= 0", field);
  const auto slash = text.find('/');
  const auto eq = text.rfind('=');
  if (slash == std::string_view::npos || eq == std::string_view::npos || eq < slash) {
    throw_invalid(field, text, syntax);
  }
  PairValue p;
  p.first = std::string(trim(text.substr(0, slash)));
  p.second = std::string(trim(text.substr(slash + 1, eq - slash - 1)));
  if (p.first.empty() || p.second.empty()) throw_invalid(field, text, syntax);
  p.value = parse_finite(fmt::format("{} {}/{}", field, p.first, p.second), text.substr(eq + 1));
  if (p.value < 0.0) {
    throw_invalid(fmt::format("{} {}/{}", field, p.first, p.second), p.value, ">= 0");
  }
  return p;
}

PairTable parse_pair_table(std::string_view text) {
  constexpr std::string_view kSyntax =
      "A/B=FILE with type labels or ids (or wall) and an FE results.csv (columns velocity, e)";
  const auto slash = text.find('/');
  const auto eq = text.find('=');
  if (slash == std::string_view::npos || eq == std::string_view::npos || eq < slash) {
    throw_invalid("pair-table", text, kSyntax);
  }
  PairTable t;
  t.first = std::string(trim(text.substr(0, slash)));
  t.second = std::string(trim(text.substr(slash + 1, eq - slash - 1)));
  t.source = std::string(trim(text.substr(eq + 1)));
  if (t.first.empty() || t.second.empty() || t.source.empty()) {
    throw_invalid("pair-table", text, kSyntax);
  }
  return t;
}

std::string type_label(const ExportSpec& spec, int id) {
  const ParticleType& t = spec.types[static_cast<std::size_t>(id - 1)];
  if (!t.label.empty()) return t.label;
  if (t.material.name != "inline") return clean_label(t.material.name);
  return fmt::format("type{}", id);
}

std::string wall_label(const ExportSpec& spec) {
  if (!spec.wall_label.empty()) return spec.wall_label;
  if (spec.wall && spec.wall->name != "inline") return clean_label(spec.wall->name);
  return "wall";
}

std::string wall_label(const ExportSpec& spec, int k) {
  if (k == 0) return wall_label(spec);
  const LabelledMaterial& m = spec.extra_walls[static_cast<std::size_t>(k - 1)];
  return m.label.empty() ? fmt::format("wall{}", k + 1) : m.label;
}

void validate_table_points(int points) {
  if (points < 2 || points > kMaxTablePoints) {
    throw_invalid("table-points", points,
                  fmt::format("in [2, {}] (rows per pair of the e(v) tables)", kMaxTablePoints));
  }
}

namespace detail {
namespace {

// The type id (0 = wall) a pair override (`field`: pair or pair-table) names, by label or id.
int resolve_type(const ExportSpec& spec,
                 const std::string& name,
                 std::string_view field,
                 const std::string& text) {
  const int n = static_cast<int>(spec.types.size());
  const int walls = static_cast<int>(spec.extra_walls.size());
  for (int k = 1; k <= walls; ++k) {  // a further wall material: by its label only
    if (name == wall_label(spec, k)) return -k;
  }
  if (name == "wall" && walls > 0) {
    throw_invalid(field, text, "a wall named by its label (the export has several wall materials)");
  }
  const bool wall = name == "wall" || (spec.wall && name == wall_label(spec));
  for (int i = 1; i <= n; ++i) {
    if (name != type_label(spec, i) && name != std::to_string(i)) continue;
    if (wall) {  // a type and the wall of one database material: both named after it
      throw_invalid(field, text,
                    fmt::format("a pair whose names are unambiguous ({} names type {} and the "
                                "wall: say {} or wall)",
                                name, i, i));
    }
    return i;
  }
  if (wall) {
    if (!spec.wall) throw_invalid(field, text, "a pair of existing types (no --wall given)");
    return 0;
  }
  std::string known;
  for (int i = 1; i <= n; ++i) known += type_label(spec, i) + ", ";
  for (int k = 1; k <= walls; ++k) known += wall_label(spec, k) + ", ";
  throw_invalid(field, text,
                fmt::format("two of [{}wall] (labels or type ids) and ={}", known,
                            field == "pair"         ? "E"
                            : field == "pair-table" ? "FILE"
                                                    : "MU"));
}

// The pair (lower id first, 0 = wall) that `first`/`second` name: at least one particle type,
// with --wall-only a type-wall pair.
std::pair<int, int> named_pair(const ExportSpec& spec,
                               const std::string& first,
                               const std::string& second,
                               std::string_view field) {
  const std::string text = first + "/" + second;
  const int a = resolve_type(spec, first, field, text);
  const int b = resolve_type(spec, second, field, text);
  if (a <= 0 && b <= 0) {
    throw_invalid(field, text, "a pair with a particle type (the wall has no wall/wall contact)");
  }
  if (spec.wall_only && a > 0 && b > 0) {
    throw_invalid(field, text, "a type-wall pair (the export is --wall-only)");
  }
  return {std::min(a, b), std::max(a, b)};
}

// Labels: unique over the types and the wall, the types' not 'wall', none a bare type id.
void validate_labels(const ExportSpec& spec) {
  constexpr std::string_view kRule =
      "unique among the types and the wall, not 'wall' and not a number (--pair 1/2=E names types "
      "by id; LABEL=MATERIAL)";
  constexpr std::string_view kChars = "letters, digits, _ . + (LABEL=MATERIAL)";
  std::vector<std::string> labels;
  for (int i = 1; i <= static_cast<int>(spec.types.size()); ++i) {
    const std::string label = type_label(spec, i);
    if (!is_label(label)) throw_invalid("type label", label, kChars);
    if (std::find(labels.begin(), labels.end(), label) != labels.end() || label == "wall" ||
        is_type_id(label)) {
      throw_invalid("type label", label, kRule);
    }
    labels.push_back(label);
  }
  if (!spec.wall) return;
  for (int k = 1; k <= static_cast<int>(spec.extra_walls.size()); ++k) {
    const std::string wall = wall_label(spec, k);
    if (!is_label(wall)) throw_invalid("wall label", wall, kChars);
    if (std::find(labels.begin(), labels.end(), wall) != labels.end() || wall == "wall" ||
        wall == wall_label(spec) || is_type_id(wall)) {
      throw_invalid("wall label", wall, kRule);
    }
    labels.push_back(wall);
  }
  const std::string wall = wall_label(spec);
  if (!is_label(wall)) throw_invalid("wall label", wall, kChars);
  // A wall of a type's database material shares its name (--pair says `wall` or the type id); a
  // label the user gives is another matter: refused.
  const bool given = !spec.wall_label.empty();
  if ((given && std::find(labels.begin(), labels.end(), wall) != labels.end()) ||
      is_type_id(wall)) {
    throw_invalid("wall label", wall, kRule);
  }
}

// Each pair a --pair or --pair-table names exists and is named once.
void validate_pair_targets(const ExportSpec& spec) {
  std::vector<std::pair<int, int>> named;
  const auto add = [&](const std::string& first, const std::string& second, std::string_view field,
                       const std::string& text) {
    const auto key = named_pair(spec, first, second, field);
    if (std::find(named.begin(), named.end(), key) != named.end()) {
      throw_invalid(
          field, text,
          field == "friction"
              ? "a pair that no other --friction A/B=MU names (one mu per pair)"
              : "a pair that no other --pair or --pair-table names (one target per pair)");
    }
    named.push_back(key);
  };
  for (const auto& p : spec.pair_restitution) {
    add(p.first, p.second, "pair", fmt::format("{}/{}={}", p.first, p.second, p.restitution));
  }
  for (const auto& t : spec.pair_tables) {
    add(t.first, t.second, "pair-table", t.first + "/" + t.second + "=" + t.source);
  }
  named.clear();  // a pair's mu is another quantity than its e
  for (const auto& p : spec.pair_friction) {
    add(p.first, p.second, "friction", fmt::format("{}/{}={}", p.first, p.second, p.value));
  }
}

// Whether `first`/`second` (labels or ids) name the pair (i, j) (j = 0: the wall).
bool names_pair(const ExportSpec& spec,
                const std::string& first,
                const std::string& second,
                int i,
                int j,
                std::string_view field = "pair") {
  const auto key = named_pair(spec, first, second, field);
  return key == std::pair{std::min(i, j), std::max(i, j)};
}

}  // namespace

void validate_export_spec(const ExportSpec& spec) {
  if (spec.types.empty()) throw_invalid("types", 0.0, "at least one particle type");
  for (int i = 1; i <= static_cast<int>(spec.types.size()); ++i) {
    const ParticleType& t = spec.types[static_cast<std::size_t>(i - 1)];
    if (!(t.radius >= kMinRadius && t.radius <= kMaxRadius)) {
      throw_invalid(fmt::format("type {} ({}) radius", i, type_label(spec, i)), t.radius,
                    fmt::format("in [{}, {}] [m]", kMinRadius, kMaxRadius));
    }
    validate(t.material, "type material");
  }
  if (spec.wall) validate(*spec.wall, "wall");
  if (spec.wall_only && !spec.wall) throw_invalid("wall_only", 1.0, "used with a wall");
  const int targets = static_cast<int>(spec.restitution.has_value()) +
                      static_cast<int>(!spec.model.empty()) +
                      static_cast<int>(spec.table.has_value());
  const bool own_targets = !spec.pair_restitution.empty() || !spec.pair_tables.empty();
  if (targets > 1 || (targets == 0 && !own_targets)) {
    throw_invalid("target", static_cast<double>(targets),
                  "exactly one of --restitution, --model, --table (none: --pair or --pair-table "
                  "for every pair)");
  }
  if (spec.restitution) require_open_range("restitution", *spec.restitution, 0.0, 1.0);
  validate_friction(spec.friction);
  for (const auto& p : spec.pair_friction) validate_friction(p.value);
  if (!std::isfinite(spec.rolling) || spec.rolling < 0.0) {
    throw_invalid("rolling", spec.rolling, ">= 0 (rolling resistance mu_r; 0: none)");
  }
  validate_walls(spec);
  require_positive("v_min", spec.v_min, "[m/s]");
  if (!(spec.v_max > spec.v_min)) throw_invalid("v_max", spec.v_max, "> v_min");
  if (spec.fit_points < 2 || spec.fit_points > 200)
    throw_invalid("fit_points", spec.fit_points, "in [2, 200]");
  validate_labels(spec);
  validate_pair_targets(spec);
}

std::optional<double> pair_override(const ExportSpec& spec, int i, int j) {
  for (const auto& p : spec.pair_restitution) {
    if (names_pair(spec, p.first, p.second, i, j)) return p.restitution;
  }
  return std::nullopt;
}

std::optional<double> pair_friction(const ExportSpec& spec, int i, int j) {
  for (const auto& p : spec.pair_friction) {
    if (names_pair(spec, p.first, p.second, i, j, "friction")) return p.value;
  }
  return std::nullopt;
}

int named_wall(const ExportSpec& spec, const std::string& first, const std::string& second) {
  std::string text = first;
  text += "/";
  text += second;
  for (const std::string* name : {&first, &second}) {
    const int id = resolve_type(spec, *name, "pair", text);
    if (id <= 0) return -id;
  }
  return -1;
}

const PairTable* pair_table(const ExportSpec& spec, int i, int j) {
  for (const auto& t : spec.pair_tables) {
    if (names_pair(spec, t.first, t.second, i, j)) return &t;
  }
  return nullptr;
}

}  // namespace detail
}  // namespace corlab::dem
