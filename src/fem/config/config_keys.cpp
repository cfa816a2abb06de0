// The table of ImpactConfig keys (config_keys.hpp): unit, range, doc and accessor of each key, and
// the parsing, range checks and help text that come from it.
#include "corlab/fem/config/config_keys.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <type_traits>
#include <variant>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/text.hpp"
#include "corlab/materials/material_database.hpp"
#include "fem/config/choice_keys.hpp"

namespace corlab::fem {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Where a key's value lives in ImpactConfig; the alternative fixes how its text is read.
using Accessor = std::variant<double* (*)(ImpactConfig&),
                              long long* (*)(ImpactConfig&),
                              int* (*)(ImpactConfig&),
                              std::optional<double>* (*)(ImpactConfig&),
                              std::vector<double>* (*)(ImpactConfig&),
                              Material* (*)(ImpactConfig&),
                              std::filesystem::path* (*)(ImpactConfig&),
                              SubstrateShape* (*)(ImpactConfig&),
                              SolverModel* (*)(ImpactConfig&)>;

constexpr KeyKind kKindOf[] = {KeyKind::number,       KeyKind::integer,     KeyKind::integer,
                               KeyKind::yield_stress, KeyKind::number_list, KeyKind::material,
                               KeyKind::path,         KeyKind::choice,      KeyKind::choice};

struct KeyEntry {
  ConfigKeyInfo info;
  Accessor access;
};

KeyEntry entry(std::string_view key,
               std::string_view unit,
               std::optional<KeyRange> range,
               std::string_view doc,
               Accessor access,
               std::string_view echo_in = {}) {
  return {{key, kKindOf[access.index()], unit, range, doc, echo_in}, access};
}

KeyRange closed(double lo, double hi, std::string_view why = {}) {
  return {lo, hi, false, false, why};
}
KeyRange open_closed(double lo, double hi, std::string_view why = {}) {
  return {lo, hi, true, false, why};
}
KeyRange open(double lo, double hi, std::string_view why = {}) { return {lo, hi, true, true, why}; }
KeyRange closed_open(double lo, double hi, std::string_view why = {}) {
  return {lo, hi, false, true, why};
}

template <bool kSphere>
Material& body(ImpactConfig& c) {
  if constexpr (kSphere) {
    return c.sphere.material;
  } else {
    return c.substrate.material;
  }
}

// The six material keys of one body; `k` are their names in the order material, E, nu, rho,
// sigma_y, hardening. summary.json echoes the properties inside the material's object.
template <bool kSphere>
void add_material_keys(std::vector<KeyEntry>& t, const std::array<std::string_view, 6>& k) {
  t.push_back(entry(
      k[0], "", std::nullopt,
      "database name and/or E=..,nu=..,rho=..[,sy=..][,H=..] (applied first)",
      +[](ImpactConfig& c) { return &body<kSphere>(c); }));
  t.push_back(entry(
      k[1], "[Pa]", closed(1e4, 1e13, "from gels to 10 x diamond"), "Young's modulus E",
      +[](ImpactConfig& c) { return &body<kSphere>(c).youngs_modulus; }, k[0]));
  t.push_back(entry(
      k[2], "[-]", open(-1.0, 0.5, "isotropic elasticity"), "Poisson's ratio nu",
      +[](ImpactConfig& c) { return &body<kSphere>(c).poisson_ratio; }, k[0]));
  t.push_back(entry(
      k[3], "[kg/m^3]", closed(1.0, 1e5, "from foams to 4 x osmium"), "density rho",
      +[](ImpactConfig& c) { return &body<kSphere>(c).density; }, k[0]));
  t.push_back(entry(
      k[4], "[Pa]", open(0.0, kInf),
      "yield stress, `none` = elastic (yield strain sigma_y/E in [1e-5, 0.1))",
      +[](ImpactConfig& c) { return &body<kSphere>(c).yield_stress; }, k[0]));
  t.push_back(entry(
      k[5], "[Pa]", closed(0.0, kInf), "linear isotropic hardening modulus H (< E)",
      +[](ImpactConfig& c) { return &body<kSphere>(c).hardening_modulus; }, k[0]));
}

void add_geometry_and_mesh_keys(std::vector<KeyEntry>& t) {
  t.push_back(entry(
      "impact.velocity", "[m/s]",
      open_closed(0.0, 1000.0, "no equation of state for hypervelocity impact"),
      "impact speed towards the substrate", +[](ImpactConfig& c) { return &c.impact.velocity; }));
  t.push_back(entry(
      "impact.gap", "[m]", closed(0.0, 1.0),
      "initial gap, crossed in exact free flight (also <= sphere.radius)",
      +[](ImpactConfig& c) { return &c.impact.gap; }));
  t.push_back(entry(
      "impact.repeats", "[-]", closed(1.0, 100.0, "each impact costs a single run"),
      "impacts of the pair on the same spot (> 1: repeated impacts carrying residual stress, "
      "plastic strain and shape; e of each in e_impacts)",
      +[](ImpactConfig& c) { return &c.impact.repeats; }));
  t.push_back(entry(
      "impact.angle", "[deg]", closed_open(0.0, 90.0, "from the contact normal; 90 never touches"),
      "angle of the impact velocity from the contact normal (> 0: the 3-D model; the normal "
      "speed is impact.velocity cos(angle))",
      +[](ImpactConfig& c) { return &c.impact.angle; }));
  t.push_back(entry(
      "contact.friction", "[-]", closed(0.0, 10.0), "Coulomb friction coefficient mu (3-D model)",
      +[](ImpactConfig& c) { return &c.contact.friction; }));
  t.push_back(entry(
      "mesh.h_min", "[m]", open_closed(0.0, 1.0), "element size at the contact",
      +[](ImpactConfig& c) { return &c.mesh.h_min; }));
  t.push_back(entry(
      "mesh.contact_elements", "[-]", closed(0.0, 1000.0),
      "h <= predicted contact radius / this (0 = off)",
      +[](ImpactConfig& c) { return &c.mesh.contact_elements; }));
  t.push_back(entry(
      "mesh.refine_factor", "[-]", closed(1.0, 10.0),
      "refined zone radius = this x predicted contact radius",
      +[](ImpactConfig& c) { return &c.mesh.refine_factor; }));
  t.push_back(entry(
      "mesh.refine_depth", "[-]", closed(0.25, 10.0),
      "refined zone depth below the contact = this x predicted contact radius",
      +[](ImpactConfig& c) { return &c.mesh.refine_depth; }));
  t.push_back(entry(
      "mesh.growth", "[-]", closed(1.0, MeshConfig::kMaxGrowth),
      "size ratio of neighbouring elements outside the zone",
      +[](ImpactConfig& c) { return &c.mesh.growth; }));
  t.push_back(entry(
      "mesh.h_max", "[m]", open_closed(0.0, 1.0), "largest element size (also >= mesh.h_min)",
      +[](ImpactConfig& c) { return &c.mesh.h_max; }));
  t.push_back(entry(
      "mesh.transitions", "[-]", closed(0.0, 1.0, "0 = off, 1 = on"),
      "3:1 transitions in the tensor-grid substrate and the sphere's ring and skin (fewer "
      "elements)",
      +[](ImpactConfig& c) { return &c.mesh.transitions; }));
  t.push_back(entry(
      "mesh.file", "", std::nullopt,
      "Gmsh .msh file instead of the built-in mesh (geometry keys then unused)",
      +[](ImpactConfig& c) { return &c.mesh.file; }));
}

void add_solver_and_output_keys(std::vector<KeyEntry>& t) {
  t.push_back(entry(
      "solver.model", "", std::nullopt,
      "axisymmetric (normal impacts) | 3d (the 3-D half model: hexahedra, friction, oblique "
      "impacts; chosen whenever impact.angle > 0)",
      +[](ImpactConfig& c) { return &c.solver.model; }));
  t.push_back(entry(
      "solver.safety_factor", "[-]",
      open_closed(0.0, 1.0, "and <= 1/sqrt(1 + solver.penalty_scale)"),
      "dt = this x stable step estimate",
      +[](ImpactConfig& c) { return &c.solver.safety_factor; }));
  t.push_back(entry(
      "solver.hourglass", "[-]",
      closed(0.0, 0.15, "LS-DYNA: stiffness hourglass above 0.15 may be unstable"),
      "Flanagan-Belytschko stiffness hourglass coefficient (axisymmetric quads)",
      +[](ImpactConfig& c) { return &c.solver.hourglass; }));
  t.push_back(entry(
      "solver.hourglass_3d", "[-]",
      closed(0.0, 0.15, "LS-DYNA: stiffness hourglass above 0.15 may be unstable"),
      "the same for the 3-D model's hexahedra",
      +[](ImpactConfig& c) { return &c.solver.hourglass_3d; }));
  t.push_back(entry(
      "solver.bulk_viscosity_linear", "[-]",
      closed(0.0, 0.12, "2 x the ABAQUS/Explicit and LS-DYNA default 0.06"),
      "linear bulk viscosity b1",
      +[](ImpactConfig& c) { return &c.solver.bulk_viscosity_linear; }));
  t.push_back(entry(
      "solver.bulk_viscosity_quadratic", "[-]",
      closed(0.0, 2.0, "ABAQUS/Explicit default 1.2, LS-DYNA 1.5"), "quadratic bulk viscosity b2",
      +[](ImpactConfig& c) { return &c.solver.bulk_viscosity_quadratic; }));
  t.push_back(entry(
      "solver.penalty_scale", "[-]",
      closed(0.1, 0.5, "softer lets the bodies interpenetrate, stiffer is unstable"),
      "contact penalty k = this x m_eff (2 / dt_crit)^2",
      +[](ImpactConfig& c) { return &c.solver.penalty_scale; }));
  t.push_back(entry(
      "solver.t_max", "[s]", closed(0.0, 10.0),
      "hard stop (0 = 20 Hertz contact times after contact; else > gap/velocity)",
      +[](ImpactConfig& c) { return &c.solver.t_max; }));
  t.push_back(entry(
      "solver.max_steps", "[-]", closed(1.0, 1e12),
      "refuse a run estimated to need more time steps (raise it to run anyway)",
      +[](ImpactConfig& c) { return &c.solver.max_steps; }));
  t.push_back(entry(
      "solver.subcycling_levels", "[-]", closed(0.0, 6.0, "2^6 = 64 base steps per major cycle"),
      "element subcycling: elements step at up to 2^this x the base step (0 = off)",
      +[](ImpactConfig& c) { return &c.solver.subcycling_levels; }));
  t.push_back(entry(
      "solver.mass_scaling_max", "[-]",
      closed(1.0, 64.0, "dt x 64 = density x 4096 at the contact"),
      "mass scaling: the base step may grow up to this factor times the step floor (the "
      "contact's h-squares' step; 1 = off, floor included)",
      +[](ImpactConfig& c) { return &c.solver.mass_scaling_max; }));
  t.push_back(entry(
      "solver.mass_scaling_inertia", "[-]", closed(0.0, 1e-2, "quasi-static contact zone"),
      "mass scaling: bound on the added inertia (F^2 - 1) rho v^2 / p_ref",
      +[](ImpactConfig& c) { return &c.solver.mass_scaling_inertia; }));
  t.push_back(entry(
      "output.times", "[s]", closed(0.0, 10.0), "times at which to write VTU fields (a list)",
      +[](ImpactConfig& c) { return &c.output.field_times; }));
  t.push_back(entry(
      "output.history_every", "[-]", closed(1.0, 1e9), "write a history row every N steps",
      +[](ImpactConfig& c) { return &c.output.history_every; }));
}

std::vector<KeyEntry> build_table() {
  std::vector<KeyEntry> t;
  t.push_back(entry(
      "sphere.radius", "[m]", closed(1e-6, 1.0), "sphere radius R",
      +[](ImpactConfig& c) { return &c.sphere.radius; }));
  add_material_keys<true>(t, {"sphere.material", "sphere.E", "sphere.nu", "sphere.rho",
                              "sphere.sigma_y", "sphere.hardening"});
  t.push_back(entry(
      "substrate.shape", "", std::nullopt,
      "what the sphere hits: flat (the elastic-plastic substrate below) | rigid (a rigid "
      "frictionless flat; the substrate keys are then unused) | sphere (a second sphere at rest, "
      "radius substrate.radius, of substrate.material)",
      +[](ImpactConfig& c) { return &c.substrate.shape; }));
  t.push_back(entry(
      "substrate.radius", "[m]", closed(1e-6, 10.0),
      "radial extent (also >= 2 predicted contact radii); for substrate.shape = sphere its "
      "radius R2",
      +[](ImpactConfig& c) { return &c.substrate.radius; }));
  t.push_back(entry(
      "substrate.depth", "[m]", closed(1e-6, 10.0),
      "depth, bottom face fixed (also >= 2 predicted contact radii)",
      +[](ImpactConfig& c) { return &c.substrate.depth; }));
  add_material_keys<false>(t, {"substrate.material", "substrate.E", "substrate.nu", "substrate.rho",
                               "substrate.sigma_y", "substrate.hardening"});
  add_geometry_and_mesh_keys(t);
  add_solver_and_output_keys(t);
  return t;
}

const std::vector<KeyEntry>& key_table() {
  static const std::vector<KeyEntry> table = build_table();
  return table;
}

const KeyEntry* find_entry(std::string_view key) {
  const auto& t = key_table();
  const auto it =
      std::find_if(t.begin(), t.end(), [key](const KeyEntry& e) { return e.info.key == key; });
  return it == t.end() ? nullptr : &*it;
}

long long parse_integer_value(std::string_view key, std::string_view text) {
  text = trim(text);
  const std::optional<long long> value = parse_integer(text);
  if (!value) throw_invalid(key, text, "an integer");
  return *value;
}

std::vector<double> parse_list(std::string_view key, std::string_view text) {
  std::vector<double> out;
  text = trim(text);
  if (!text.empty() && text.front() == '[' && text.back() == ']') {
    text = trim(text.substr(1, text.size() - 2));
  }
  if (text.empty()) return out;
  while (true) {
    const auto comma = text.find(',');
    out.push_back(parse_finite(key, text.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return out;
}

// `none` clears the yield stress; an empty value is an error (an unset shell variable must not
// silently turn plasticity off).
std::optional<double> parse_yield(std::string_view key, std::string_view text) {
  const auto t = trim(text);
  if (t == "none") return std::nullopt;
  if (t.empty()) throw_invalid(key, t, "a finite number, or `none` for an elastic body");
  return parse_finite(key, t);
}

// Reads `text` into the value `e` gives access to.
void set_value(const KeyEntry& e, ImpactConfig& c, std::string_view text) {
  const std::string_view key = e.info.key;
  std::visit(
      [&](auto get) {
        auto* target = get(c);
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, double>) {
          *target = parse_finite(key, text);
        } else if constexpr (std::is_same_v<T, long long>) {
          *target = parse_integer_value(key, text);
        } else if constexpr (std::is_same_v<T, int>) {
          const long long v = parse_integer_value(key, text);
          if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
            throw_invalid(key, text, "an integer that fits 32 bits");
          }
          *target = static_cast<int>(v);
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          *target = parse_yield(key, text);
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          *target = parse_list(key, text);
        } else if constexpr (std::is_same_v<T, Material>) {
          const std::string body(key.substr(0, key.find('.')));
          try {
            *target = parse_material_spec(trim(text), body);
          } catch (const InputError& err) {
            // An error about the whole spec (unknown name, incomplete) names the key itself.
            if (err.field() != body) throw;
            throw InputError(std::string(key), err.value(), err.constraint(), true);
          }
        } else if constexpr (config_choices::kIsChoice<T>) {
          *target = config_choices::parse_choice<T>(key, text);
        } else {
          *target = std::string(trim(text));
        }
      },
      e.access);
}

// The numeric values of a key (none for text keys and an unset yield stress).
std::vector<double> numbers_of(const KeyEntry& e, ImpactConfig& c) {
  return std::visit(
      [&](auto get) -> std::vector<double> {
        const auto* v = get(c);
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(v)>>;
        if constexpr (std::is_arithmetic_v<T>) {
          return {static_cast<double>(*v)};
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          return *v ? std::vector<double>{**v} : std::vector<double>{};
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          return *v;
        } else {
          return {};
        }
      },
      e.access);
}

std::string text_of(const KeyEntry& e, ImpactConfig& c) {
  return std::visit(
      [&](auto get) -> std::string {
        const auto* v = get(c);
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(v)>>;
        if constexpr (std::is_arithmetic_v<T>) {
          return fmt::format("{}", *v);
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          return *v ? fmt::format("{}", **v) : std::string("none");
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          return fmt::format("[{}]", fmt::join(*v, ", "));
        } else if constexpr (std::is_same_v<T, Material>) {
          return v->name;
        } else if constexpr (config_choices::kIsChoice<T>) {
          return std::string(to_string(*v));
        } else {
          return v->string();
        }
      },
      e.access);
}

nlohmann::json material_json(const Material& m) {
  return {{"name", m.name},
          {"E", m.youngs_modulus},
          {"nu", m.poisson_ratio},
          {"rho", m.density},
          {"sigma_y", m.yield_stress ? nlohmann::json(*m.yield_stress) : nlohmann::json(nullptr)},
          {"hardening", m.hardening_modulus},
          {"source", m.source}};
}

nlohmann::json json_of(const KeyEntry& e, ImpactConfig& c) {
  return std::visit(
      [&](auto get) -> nlohmann::json {
        const auto* v = get(c);
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(v)>>;
        if constexpr (std::is_same_v<T, std::optional<double>>) {
          return *v ? nlohmann::json(**v) : nlohmann::json(nullptr);
        } else if constexpr (std::is_same_v<T, Material>) {
          return material_json(*v);
        } else if constexpr (std::is_same_v<T, std::filesystem::path>) {
          return v->string();
        } else if constexpr (config_choices::kIsChoice<T>) {
          return std::string(to_string(*v));
        } else {
          return *v;
        }
      },
      e.access);
}

}  // namespace

bool KeyRange::contains(double value) const {
  if (!std::isfinite(value)) return false;
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return above && below;
}

std::string KeyRange::text(std::string_view unit) const {
  std::string out = std::isinf(hi) ? fmt::format("{} {}", lo_open ? ">" : ">=", lo)
                                   : fmt::format("in {}{}, {}{}", lo_open ? '(' : '[', lo, hi,
                                                 hi_open ? ')' : ']');
  if (!unit.empty()) out += fmt::format(" {}", unit);
  if (!why.empty()) out += fmt::format(" ({})", why);
  return out;
}

const std::vector<ConfigKeyInfo>& config_keys() {
  static const std::vector<ConfigKeyInfo> infos = [] {
    std::vector<ConfigKeyInfo> out;
    for (const auto& e : key_table()) out.push_back(e.info);
    return out;
  }();
  return infos;
}

const ConfigKeyInfo* find_config_key(std::string_view key) {
  const KeyEntry* e = find_entry(key);
  return e == nullptr ? nullptr : &e->info;
}

std::string config_value_text(const ImpactConfig& config, std::string_view key) {
  const KeyEntry* e = find_entry(key);
  if (e == nullptr) return {};
  ImpactConfig copy = config;
  return text_of(*e, copy);
}

nlohmann::json config_value_json(const ImpactConfig& config, std::string_view key) {
  const KeyEntry* e = find_entry(key);
  if (e == nullptr) return nullptr;
  ImpactConfig copy = config;
  return json_of(*e, copy);
}

std::vector<std::string> config_echo_path(const ConfigKeyInfo& info) {
  std::vector<std::string> path;
  std::string_view rest = info.echo_in.empty() ? info.key : info.echo_in;
  for (auto dot = rest.find('.'); dot != std::string_view::npos; dot = rest.find('.')) {
    path.emplace_back(rest.substr(0, dot));
    rest.remove_prefix(dot + 1);
  }
  path.emplace_back(rest);
  if (!info.echo_in.empty()) path.emplace_back(info.key.substr(info.key.rfind('.') + 1));
  return path;
}

void set_config_key(ImpactConfig& config, std::string_view key, std::string_view value) {
  key = trim(key);
  const KeyEntry* e = find_entry(key);
  if (e == nullptr) {
    throw_invalid("config key", key, fmt::format("one of {}", fmt::join(config_key_names(), ", ")));
  }
  set_value(*e, config, value);
}

void validate_key_ranges(const ImpactConfig& config) {
  ImpactConfig copy = config;  // the accessors take a mutable config; nothing is written
  for (const auto& e : key_table()) {
    if (!e.info.range) continue;
    for (const double v : numbers_of(e, copy)) {
      if (!e.info.range->contains(v)) throw_invalid(e.info.key, v, e.info.range->text(e.info.unit));
    }
  }
}

std::string config_keys_help() {
  const ImpactConfig defaults;
  std::string out = "Config keys (--set key=value, TOML [table] key = value; SI units):\n";
  for (const auto& e : key_table()) {
    const std::string range = e.info.range ? e.info.range->text(e.info.unit) : std::string("text");
    const std::string value = config_value_text(defaults, e.info.key);
    out += fmt::format("  {:<32} {} (default {})\n      {}\n", e.info.key, e.info.doc,
                       value.empty() ? "none" : value, range);
  }
  return out;
}

std::vector<std::string> config_key_names() {
  std::vector<std::string> names;
  for (const auto& e : key_table()) names.emplace_back(e.info.key);
  return names;
}

}  // namespace corlab::fem
