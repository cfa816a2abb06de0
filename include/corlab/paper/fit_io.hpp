// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file fit_io.hpp
/// Glue between results tables, the fitters and JSON: samples from a results.csv, JSON forms of
/// the fit results (used by fit.json, `corlab fit` and the Python bindings).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "corlab/fit/fit_expression.hpp"
#include "corlab/fit/linear_regression.hpp"
#include "corlab/paper/fit_paper.hpp"
#include "corlab/study/results_table.hpp"

namespace corlab::study {

/// Group label of a (rho, E*, sigma_y) triple, e.g. "rho7850_E115.4GPa_sy500MPa".
std::string group_label(double sphere_rho, double E_star, double sigma_y);

/// Why a fit leaves out row `row`, or "" when the row is usable: its status is not "ok", or
/// (unless `include_suspect`) its `suspect` column names a quality problem (run_quality.hpp).
std::string row_exclusion(const ResultsTable& table, std::size_t row, bool include_suspect);

/// The usable rows (row_exclusion() empty) as restitution samples (columns e, velocity,
/// sphere_rho, E_star, sigma_y); case_id = group_label() so that one paper "case" collects all its
/// velocities, row_id = the row's case_id. Rows that are not usable or have no yield stress
/// (elastic substrate) are left out and, if `excluded` is given, appended to it with the reason.
/// Throws InputError if a needed column is missing.
std::vector<RestitutionSample> restitution_samples(const ResultsTable& table,
                                                   std::vector<ExcludedRow>* excluded = nullptr,
                                                   bool include_suspect = false);

/// The case_id of a row ("row N", 1-based, in a table without a case_id column).
std::string row_name(const ResultsTable& table, std::size_t row);

/// The rows a user form (`corlab fit --form`) leaves out before its --where filter: not usable
/// (row_exclusion()), or a non-finite `response`; each with the reason.
std::vector<ExcludedRow> form_exclusions(const ResultsTable& table,
                                         const std::string& response,
                                         bool include_suspect = false);

/// The usable rows of `table` (row_exclusion() empty), in their order.
ResultsTable usable_rows(const ResultsTable& table, bool include_suspect = false);

/// The numeric columns of a table (for fit_expression()); text columns are left out.
DataColumns numeric_columns(const ResultsTable& table);

nlohmann::json to_json(const std::vector<ExcludedRow>& rows);  ///< [{case_id, reason}]
nlohmann::json to_json(const GoodnessOfFit& g);
nlohmann::json to_json(const Coefficient& c);
nlohmann::json to_json(const LinearFit& fit);
nlohmann::json to_json(const NonlinearFit& fit);
nlohmann::json to_json(const RestitutionLawFit& fit);
nlohmann::json to_json(const YieldVelocityFit& fit);

/// Forms (i)-(ii) on a results.csv and, when the table holds >= 3 E* values and >= 2 yield
/// stresses, forms (iii)-(iv) on the per-case crossing velocities. Returns
/// {"restitution_law": ..., "yield_velocity": ... | null, "rows", "rows_excluded", "excluded":
/// [{case_id, reason}] (every row not used by form (i)), "read_notes": the table's notes()}.
nlohmann::json fit_paper_forms(const ResultsTable& table, const PaperFitOptions& options = {});

}  // namespace corlab::study
