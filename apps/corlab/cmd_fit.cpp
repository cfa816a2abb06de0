// `corlab fit RESULTS.csv`: fit model forms to a results table (results.csv of a sweep, or any
// CSV with a header).
//
// Sample runs:
//   corlab fit out/report/table2/results.csv                     # Ma et al. 2023 forms (i)-(ii)
//   corlab fit out/report/table2/results.csv --json              # same, as JSON
//   corlab fit results.csv --form "e ~ a + s*ln(k1) + b*ln(k2)" --param a=1,s=0.05,b=0.2
//       --where "e < 0.999"                    # (one line) any user form, nonlinear LS
// Exit status: 0 fitted, 1 the iteration did not converge, 2 bad input.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/fit/fit_expression.hpp"
#include "corlab/paper/fit_io.hpp"
#include "corlab/paper/fit_paper.hpp"
#include "corlab/study/results_table.hpp"

namespace corlab::cli {
namespace {

struct FitArgs {
  std::string results;
  std::string form;
  std::vector<std::string> params;
  std::string where;
  double confidence = 0.95;
  double plastic_tolerance = 1e-3;
  bool json = false;
  bool include_suspect = false;
};

std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "-"; }

void print_coefficient(const study::Coefficient& c) {
  fmt::print("{:<34} {:>12} {:>11} [{:>11}, {:>11}] {:>9}  {}\n", c.name, num(c.value),
             num(c.standard_error), num(c.ci_lower), num(c.ci_upper), num(c.paper), c.unit);
}

void print_goodness(const char* what, const study::GoodnessOfFit& g) {
  if (!std::isfinite(g.r_squared)) {
    fmt::print("{:<34} not fitted (too few cases)\n", what);
    return;
  }
  fmt::print("{:<34} R^2 = {:.5f}  max rel. error = {:.2f} %  RMS rel. error = {:.2f} %\n", what,
             g.r_squared, 100 * g.max_relative_error, 100 * g.rms_relative_error);
}

/// Every row a fit left out, with the reason (never dropped silently).
void print_excluded(const std::vector<study::ExcludedRow>& rows) {
  if (rows.empty()) return;
  fmt::print("excluded rows ({}):\n", rows.size());
  for (const auto& r : rows) fmt::print("  {}: {}\n", r.case_id, r.reason);
}

int fit_paper(const FitArgs& args, const study::ResultsTable& table) {
  study::PaperFitOptions options;
  options.confidence = args.confidence;
  options.plastic_tolerance = args.plastic_tolerance;
  options.include_suspect = args.include_suspect;
  if (args.json) {
    fmt::print("{}\n", study::fit_paper_forms(table, options).dump(2));
    return 0;
  }
  std::vector<study::ExcludedRow> excluded;
  const auto samples = study::restitution_samples(table, &excluded, args.include_suspect);
  const study::RestitutionLawFit law = study::fit_restitution_law(samples, options);
  excluded.insert(excluded.end(), law.excluded.begin(), law.excluded.end());
  fmt::print(
      "Ma et al. 2023 forms on {} ({} rows: {} plastic points used, {} excluded, listed "
      "below)\n",
      args.results, table.size(), law.points_used, excluded.size());
  fmt::print("{:<34} {:>12} {:>11} {:>27} {:>9}\n", "coefficient", "value", "std. err.",
             fmt::format("{:g} % confidence interval", 100 * args.confidence), "paper");
  print_coefficient(law.slope);
  print_coefficient(law.alpha);
  print_coefficient(law.beta);
  for (const auto& c : law.cases) {
    study::Coefficient a = c.a;
    a.name = "a[" + c.case_id + "]";
    print_coefficient(a);
  }
  print_goodness("(i)  e = a_i + s ln k1:", law.form_i);
  print_goodness("(ii) a = alpha + beta ln k2:", law.form_ii);
  print_goodness("eq. 12 (plastic points):", law.combined);
  print_excluded(excluded);
  return 0;
}

int fit_form(const FitArgs& args, const study::ResultsTable& table) {
  study::NonlinearFitOptions options;
  options.confidence = args.confidence;
  options.where = args.where;
  const auto params = study::parse_parameter_starts(args.params);
  // only the rows that finished cleanly (status ok, not suspect unless --include-suspect)
  const study::ResultsTable rows = study::usable_rows(table, args.include_suspect);
  const study::NonlinearFit fit =
      study::fit_expression(args.form, params, study::numeric_columns(rows), options);
  const auto excluded =
      study::form_exclusions(table, study::split_formula(args.form).first, args.include_suspect);
  const auto by_where = table.size() - excluded.size() - static_cast<std::size_t>(fit.observations);
  if (args.json) {
    nlohmann::json out = study::to_json(fit);
    out.erase("left_out");  // row numbers of the usable subset: "excluded" names them by case
    out["rows"] = table.size();
    out["excluded"] = study::to_json(excluded);
    out["excluded_by_where"] = by_where;
    fmt::print("{}\n", out.dump(2));
    return fit.converged ? 0 : 1;
  }
  fmt::print("{} ~ {}   ({} rows used of {}; {} left out by --where; {} iterations, {})\n",
             fit.response, fit.model, fit.observations, table.size(), by_where, fit.iterations,
             fit.message);
  fmt::print("{:<26} {:>12} {:>11} {:>27}\n", "parameter", "value", "std. err.",
             fmt::format("{:g} % confidence interval", 100 * args.confidence));
  for (std::size_t j = 0; j < fit.names.size(); ++j) {
    fmt::print("{:<26} {:>12} {:>11} [{:>11}, {:>11}]\n", fit.names[j], num(fit.coefficients[j]),
               num(fit.standard_errors[j]), num(fit.ci_lower[j]), num(fit.ci_upper[j]));
  }
  print_goodness("goodness of fit:", fit.goodness);
  print_excluded(excluded);
  return fit.converged ? 0 : 1;
}

const CommandRegistration kRegistration{Command{
    "fit", "Fit model forms to a results table: Ma et al. 2023 forms, or any user form (--form)",
    [](CLI::App& sub) -> std::function<int()> {
      auto args = std::make_shared<FitArgs>();
      sub.add_option("results", args->results, "results.csv of a sweep (or any CSV with header)")
          ->required();
      sub.add_option("--form", args->form,
                     "user form 'response ~ model' over the columns, e.g. "
                     "\"e ~ a + s*ln(k1) + b*ln(k2)\" (default: the paper's forms)");
      sub.add_option("--param", args->params, "parameter start values, e.g. a=1,s=0.05");
      sub.add_option("--where", args->where, "row filter for --form, e.g. \"e < 0.999\"");
      sub.add_option("--confidence", args->confidence, "confidence level of the intervals");
      sub.add_option("--plastic-tolerance", args->plastic_tolerance,
                     "paper forms: use points with e < 1 - tol");
      sub.add_flag("--json", args->json, "print JSON instead of a table");
      sub.add_flag("--include-suspect", args->include_suspect,
                   "also fit runs flagged suspect (left out by default, listed as excluded)");
      return [args] {
        const study::ResultsTable table = study::read_results(args->results);
        for (const auto& note : table.notes()) fmt::print(stderr, "corlab: warning: {}\n", note);
        if (args->form.empty()) {
          if (!args->params.empty() || !args->where.empty()) {
            throw_invalid("--param/--where", "given", "used with --form only");
          }
          return fit_paper(*args, table);
        }
        if (args->params.empty()) throw_invalid("--param", "", "given with --form");
        return fit_form(*args, table);
      };
    },
    50}};

}  // namespace
}  // namespace corlab::cli
