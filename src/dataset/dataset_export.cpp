// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/dataset_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/output_directory.hpp"
#include "corlab/dataset/impact_box.hpp"
#include "corlab/fem/output/impact_output.hpp"
#include "corlab/fem/solver/result_fields.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace corlab::dataset {
namespace {

using fem::FieldKind;
using fem::FieldValue;
using nlohmann::json;

/// What an input column is computed from: the run's config and its dimensionless inputs.
struct RunInputs {
  const fem::ImpactConfig& config;
  const DimensionlessInputs& d;
};

/// A column computed from a run's inputs.
struct InputColumn {
  std::string_view name;
  std::string_view unit;
  FieldKind kind;
  std::string_view description;
  FieldValue (*value)(const RunInputs&);
};

FieldValue yield_or_inf(const Material& m) {
  return m.yield_stress ? *m.yield_stress : std::numeric_limits<double>::infinity();
}

// The dataset's input columns (one place: dataset.csv, columns.json and the datasheet's list).
const std::array<InputColumn, 29> kInputColumns{{
    {"k1", "-", FieldKind::real,
     "E* / (rho* v^2) (Ma et al. 2023 eq. 5; rho* = rho_sphere on a flat)",
     [](const RunInputs& in) -> FieldValue { return in.d.k1; }},
    {"k2", "-", FieldKind::real, "sigma_y,substrate / E* (Ma et al. 2023 eq. 6)",
     [](const RunInputs& in) -> FieldValue { return in.d.k2; }},
    {"velocity_ratio", "-", FieldKind::real, "v / v_y, v_y the pair's first-yield speed",
     [](const RunInputs& in) -> FieldValue { return in.d.velocity_ratio; }},
    {"first_yield_velocity", "m/s", FieldKind::real,
     "v_y: Hertz p0 = C(nu) sigma_y in the weaker body (restitution/first_yield.hpp)",
     [](const RunInputs& in) -> FieldValue { return in.d.first_yield_velocity; }},
    {"sphere_yields_first", "-", FieldKind::boolean, "the sphere reaches first yield first",
     [](const RunInputs& in) -> FieldValue { return in.d.sphere_yields_first; }},
    {"modulus_ratio", "-", FieldKind::real, "E_sphere / E_substrate",
     [](const RunInputs& in) -> FieldValue { return in.d.modulus_ratio; }},
    {"sphere_yield_ratio", "-", FieldKind::real,
     "sigma_y,sphere / sigma_y,substrate (inf: elastic sphere)",
     [](const RunInputs& in) -> FieldValue { return in.d.sphere_yield_ratio; }},
    {"nu_sphere", "-", FieldKind::real, "Poisson's ratio of the sphere",
     [](const RunInputs& in) -> FieldValue { return in.d.nu_sphere; }},
    {"nu_substrate", "-", FieldKind::real, "Poisson's ratio of the substrate",
     [](const RunInputs& in) -> FieldValue { return in.d.nu_substrate; }},
    {"hardening_ratio_sphere", "-", FieldKind::real, "H / E of the sphere (0 if elastic)",
     [](const RunInputs& in) -> FieldValue { return in.d.hardening_ratio_sphere; }},
    {"hardening_ratio_substrate", "-", FieldKind::real, "H / E of the substrate",
     [](const RunInputs& in) -> FieldValue { return in.d.hardening_ratio_substrate; }},
    {"density_ratio", "-", FieldKind::real, "rho_sphere / rho_substrate",
     [](const RunInputs& in) -> FieldValue { return in.d.density_ratio; }},
    {"damage_number", "-", FieldKind::real, "Johnson's damage number rho* v^2 / sigma_y,substrate",
     [](const RunInputs& in) -> FieldValue { return in.d.damage_number; }},
    // The dimensional inputs, every one (a row is self-contained without configs.jsonl).
    {"sphere_E", "Pa", FieldKind::real, "Young's modulus of the sphere",
     [](const RunInputs& in) -> FieldValue { return in.config.sphere.material.youngs_modulus; }},
    {"sphere_nu", "-", FieldKind::real, "Poisson's ratio of the sphere",
     [](const RunInputs& in) -> FieldValue { return in.config.sphere.material.poisson_ratio; }},
    {"sphere_rho", "kg/m^3", FieldKind::real, "density of the sphere",
     [](const RunInputs& in) -> FieldValue { return in.config.sphere.material.density; }},
    {"sphere_sigma_y", "Pa", FieldKind::real, "yield stress of the sphere (inf: elastic)",
     [](const RunInputs& in) -> FieldValue { return yield_or_inf(in.config.sphere.material); }},
    {"sphere_H", "Pa", FieldKind::real, "linear hardening modulus of the sphere",
     [](const RunInputs& in) -> FieldValue { return in.config.sphere.material.hardening_modulus; }},
    {"substrate_E", "Pa", FieldKind::real, "Young's modulus of the substrate",
     [](const RunInputs& in) -> FieldValue { return in.config.substrate.material.youngs_modulus; }},
    {"substrate_nu", "-", FieldKind::real, "Poisson's ratio of the substrate",
     [](const RunInputs& in) -> FieldValue { return in.config.substrate.material.poisson_ratio; }},
    {"substrate_rho", "kg/m^3", FieldKind::real, "density of the substrate",
     [](const RunInputs& in) -> FieldValue { return in.config.substrate.material.density; }},
    {"substrate_sigma_y", "Pa", FieldKind::real, "yield stress of the substrate",
     [](const RunInputs& in) -> FieldValue { return yield_or_inf(in.config.substrate.material); }},
    {"substrate_H", "Pa", FieldKind::real, "linear hardening modulus of the substrate",
     [](const RunInputs& in) -> FieldValue {
       return in.config.substrate.material.hardening_modulus;
     }},
    {"sphere_radius", "m", FieldKind::real, "sphere radius R",
     [](const RunInputs& in) -> FieldValue { return in.config.sphere.radius; }},
    {"substrate_shape", "-", FieldKind::text,
     "what the sphere hits: flat (the substrate block), sphere (a free second sphere), rigid",
     [](const RunInputs& in) -> FieldValue {
       return std::string(fem::to_string(in.config.substrate.shape));
     }},
    {"substrate_radius", "m", FieldKind::real,
     "the second sphere's radius R2 (substrate.shape = sphere), else the flat's radial extent",
     [](const RunInputs& in) -> FieldValue { return in.config.substrate.radius; }},
    {"radius_ratio", "-", FieldKind::real, "R1 / R2 (0: a flat)",
     [](const RunInputs& in) -> FieldValue { return in.d.radius_ratio; }},
    {"effective_density", "kg/m^3", FieldKind::real,
     "rho* = 3 m* / (4 pi R*^3), the density in k1, v_y and the damage number (rho_sphere on a "
     "flat)",
     [](const RunInputs& in) -> FieldValue { return in.d.effective_density; }},
    {"velocity", "m/s", FieldKind::real, "impact speed v",
     [](const RunInputs& in) -> FieldValue { return in.config.impact.velocity; }},
}};

// Result columns that repeat an input column under another name.
constexpr std::array<std::string_view, 1> kRepeatedInputs{"sigma_y"};

json column(std::string_view name, std::string_view unit, FieldKind kind, std::string_view doc) {
  return json{{"name", name}, {"unit", unit}, {"kind", fem::to_string(kind)}, {"description", doc}};
}

/// columns.json entries of the columns before the inputs, of the inputs, of the swept keys.
json leading_columns() {
  json out = json::array();
  out.push_back(column("design_index", "-", FieldKind::integer,
                       "index of the Sobol point (studies/dataset/fe_restitution.toml)"));
  out.push_back(column("case_id", "-", FieldKind::text, "the sweep's case id (hash of settings)"));
  out.push_back(column("status", "-", FieldKind::text,
                       "ok (a clean rebound), a run status or failed (docs/user/sweeps.md)"));
  out.push_back(column("included", "-", FieldKind::boolean, "in the fitting set"));
  out.push_back(column("exclusion_reason", "-", FieldKind::text,
                       "why not (empty if included): status, no e, energy balance > 0.5 %, "
                       "hourglass energy, penetration"));
  for (const auto& c : kInputColumns) out.push_back(column(c.name, c.unit, c.kind, c.description));
  return out;
}

json result_column(const std::string& name) {
  if (const fem::ResultField* f = fem::find_result_field(name)) {
    return column(name, f->unit, f->kind, f->description);
  }
  return column(name, "-", FieldKind::text, "one-line message of a failed run");  // `error`
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw_invalid("dataset output", file.string(), "a writable file");
  out << text;
}

/// The first words of a reason (numbers cut), to count reasons of one kind together.
std::string reason_kind(const std::string& reason) {
  const auto cut = reason.find_first_of("0123456789");
  std::string kind = reason.substr(0, cut);
  while (!kind.empty() && (kind.back() == ' ' || kind.back() == '=')) kind.pop_back();
  return kind;
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

std::string exclusion_reason(const study::ResultsTable& results,
                             std::size_t row,
                             const InclusionLimits& limits) {
  const std::string& status = results.cell(row, "status");
  if (status != study::kStatusOk) return fmt::format("status {}", status);
  const auto e = parse_double(results.cell(row, "e"));
  if (!e || !std::isfinite(*e) || *e <= 0.0 || *e > 1.0) {
    return fmt::format("e = {} not in (0, 1]", results.cell(row, "e"));
  }
  const auto balance = parse_double(results.cell(row, "energy_balance_error"));
  if (!balance || !(*balance <= limits.energy_balance)) {
    return fmt::format("energy balance error {} > {}", results.cell(row, "energy_balance_error"),
                       limits.energy_balance);
  }
  return results.cell(row, "suspect");
}

namespace {

/// Row of each case id in the results; InputError for a case the spec does not have.
std::map<std::string, std::size_t> rows_by_case(const study::ResultsTable& results,
                                                const std::vector<study::SweepCase>& runs,
                                                const std::filesystem::path& spec_file) {
  std::set<std::string> ids;
  for (const auto& run : runs) ids.insert(run.id);
  std::map<std::string, std::size_t> row_of;
  for (std::size_t r = 0; r < results.size(); ++r) {
    const std::string& id = results.cell(r, "case_id");
    if (ids.count(id) == 0) {
      throw_invalid("case_id", id,
                    fmt::format("a case of {} (results of another spec?)", spec_file.string()));
    }
    row_of[id] = r;
  }
  return row_of;
}

/// The dataset's columns: leading, inputs, then the results.csv columns that are results (not
/// case_id, status, the swept settings or a repeated input), which are copied as written.
struct ExportColumns {
  json described;                   ///< columns.json
  std::vector<std::string> copied;  ///< result columns copied from results.csv
};

ExportColumns export_columns(const study::ResultsTable& results,
                             const std::vector<std::string>& swept) {
  ExportColumns out{leading_columns(), {}};
  for (const auto& name : results.columns()) {
    const bool is_input =
        std::any_of(kInputColumns.begin(), kInputColumns.end(),
                    [&name](const InputColumn& c) { return c.name == name; }) ||
        std::find(kRepeatedInputs.begin(), kRepeatedInputs.end(), name) != kRepeatedInputs.end();
    const bool is_key = std::find(swept.begin(), swept.end(), name) != swept.end();
    if (name == "case_id" || name == "status" || is_input || is_key) continue;
    out.copied.push_back(name);
    out.described.push_back(result_column(name));
  }
  return out;
}

/// Counts row r in the summary; an included row adds its e_error / e to rel_errors.
void count_row(const study::ResultsTable& results,
               std::size_t r,
               const std::string& reason,
               ExportSummary& summary,
               std::vector<double>& rel_errors) {
  ++summary.rows;
  summary.cpu_s += parse_double(results.cell(r, "wall_s")).value_or(0.0);
  summary.builds.insert(results.has_column("corlab_build") ? results.cell(r, "corlab_build")
                                                           : "unknown (before corlab_build)");
  if (!reason.empty()) {
    ++summary.excluded[reason_kind(reason)];
    return;
  }
  ++summary.included;
  const double e = *parse_double(results.cell(r, "e"));
  const auto err = parse_double(results.cell(r, "e_error"));
  if (err && std::isfinite(*err)) rel_errors.push_back(*err / e);
}

void write_summary(const std::filesystem::path& file,
                   const ExportSummary& summary,
                   const InclusionLimits& limits) {
  const json s{{"design_points", summary.design_points},
               {"rows", summary.rows},
               {"included", summary.included},
               {"excluded", summary.excluded},
               {"cpu_s", summary.cpu_s},
               {"e_error_relative_max", summary.e_error_max},
               {"e_error_relative_median", summary.e_error_median},
               {"builds", summary.builds},
               {"energy_balance_limit", limits.energy_balance}};
  write_text(file, s.dump(2) + "\n");
}

}  // namespace

ExportSummary export_dataset(const std::filesystem::path& sweep_dir,
                             const std::filesystem::path& out_dir,
                             const InclusionLimits& limits) {
  const study::SweepSpec spec = study::load_sweep_spec(sweep_dir / "spec.toml");
  const std::vector<study::SweepCase> runs = spec.expand();
  const study::ResultsTable results = study::read_results(sweep_dir / "results.csv");
  const auto row_of = rows_by_case(results, runs, sweep_dir / "spec.toml");
  const ExportColumns columns = export_columns(results, spec.swept_keys());
  std::vector<std::string> header;
  for (const auto& c : columns.described) header.push_back(c["name"].get<std::string>());

  ensure_output_directory(out_dir, "--out");
  ExportSummary summary;
  summary.design_points = runs.size();
  std::string csv = study::csv_line(header) + "\n";
  std::string configs;
  std::vector<double> rel_errors;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto it = row_of.find(runs[i].id);
    if (it == row_of.end()) continue;
    const std::size_t r = it->second;
    const std::string reason = exclusion_reason(results, r, limits);
    std::vector<std::string> fields{std::to_string(i), runs[i].id, results.cell(r, "status"),
                                    reason.empty() ? "true" : "false", reason};
    const DimensionlessInputs d = dimensionless_inputs(runs[i].config);
    for (const auto& c : kInputColumns) {
      fields.push_back(fem::field_text(c.value(RunInputs{runs[i].config, d})));
    }
    for (const auto& name : columns.copied) fields.push_back(results.cell(r, name));
    csv += study::csv_line(fields) + "\n";
    configs += json{{"case_id", runs[i].id},
                    {"design_index", i},
                    {"config", fem::config_to_json(runs[i].config)}}
                   .dump() +
               "\n";
    count_row(results, r, reason, summary, rel_errors);
  }
  summary.e_error_max =
      rel_errors.empty() ? std::nan("") : *std::max_element(rel_errors.begin(), rel_errors.end());
  summary.e_error_median = median(rel_errors);
  write_text(out_dir / "dataset.csv", csv);
  write_text(out_dir / "columns.json", columns.described.dump(2) + "\n");
  write_text(out_dir / "configs.jsonl", configs);
  write_summary(out_dir / "summary.json", summary, limits);
  return summary;
}

}  // namespace corlab::dataset
