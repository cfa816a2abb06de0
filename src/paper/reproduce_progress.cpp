// `corlab reproduce`, the progress of the whole reproduction: every run's cost estimated before
// anything runs (fem::estimate_run_cost), so that one line shows the fraction of the whole done
// and the time left at the rate measured so far (study::WorkProgress).
// SPDX-License-Identifier: BSD-3-Clause
#include <exception>
#include <set>
#include <string>

#include "corlab/core/thread_pool.hpp"
#include "corlab/fem/config/config_keys.hpp"
#include "corlab/fem/solver/discretisation_error.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "corlab/materials/material.hpp"
#include "corlab/paper/yield_velocity.hpp"
#include "corlab/study/results_table.hpp"
#include "reproduce_internal.hpp"

namespace corlab::study::reproduce_detail {

namespace fs = std::filesystem;

namespace {

/// Estimated element-steps of one run; 0 for an invalid config (it fails at once when it runs).
double element_steps(const fem::ImpactConfig& config) {
  try {
    return fem::estimate_run_cost(config).element_steps();
  } catch (const std::exception&) {
    return 0.0;
  }
}

/// The case ids of results.csv whose rows a resumed sweep keeps (every status but failed).
std::set<std::string> finished_sweep_cases(const fs::path& file) {
  std::set<std::string> out;
  if (!fs::exists(file)) return out;
  try {
    const ResultsTable t = read_results(file);
    if (t.size() == 0) return out;
    const auto& ids = t.text("case_id");
    const auto& status = t.text("status");
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (status[i] != kStatusFailed) out.insert(ids[i]);
    }
  } catch (const std::exception&) {
    out.clear();  // the sweep itself reports what is wrong with the file
  }
  return out;
}

}  // namespace

double companion_cost_factor() {
  double sum = 0.0;
  for (const double ratio : fem::kErrorBarRatios) sum += 1.0 / (ratio * ratio * ratio);
  return sum;
}

double case_cost(const fem::ImpactConfig& config, bool error_estimate) {
  const double cost = element_steps(config);
  const bool companions = error_estimate && config.mesh.file.empty();
  return companions ? cost * (1.0 + companion_cost_factor()) : cost;
}

double onset_case_cost(const fem::ImpactConfig& config) {
  fem::ImpactConfig probe = config;
  const auto& substrate = probe.substrate.material;
  try {
    if (substrate.yield_stress) {
      probe.impact.velocity = hertz_yield_onset_velocity(
          probe.sphere.material.density, effective_modulus(probe.sphere.material, substrate),
          *substrate.yield_stress);
    }
  } catch (const std::exception&) {
    return 0.0;
  }
  return kOnsetRunsPerCase * kLoadingHalfFraction * element_steps(probe);
}

std::string swept_key(const fem::ImpactConfig& config, const std::vector<std::string>& keys) {
  std::string key;
  for (const auto& k : keys) {
    try {
      key += fem::config_value_text(config, k);
    } catch (const std::exception&) {
      key += '?';  // not a config key: the other keys tell the cases apart
    }
    key += '\x1f';
  }
  return key;
}

StudyCost study_cost(const std::string& name,
                     const SweepSpec& spec,
                     const fs::path& dir,
                     const ReproduceOptions& opt) {
  StudyCost out;
  out.cases = spec.expand();
  const std::size_t n = out.cases.size();
  out.cost.assign(n, 0.0);
  out.done.assign(n, false);
  const bool history = is_history_study(name);
  const std::set<std::string> finished = history || name == kOnsetStudy
                                             ? std::set<std::string>{}
                                             : finished_sweep_cases(dir / "results.csv");
  for (std::size_t i = 0; i < n; ++i) {
    const SweepCase& c = out.cases[i];
    out.done[i] =
        history ? fs::exists(dir / "runs" / c.id / "summary.json") : finished.count(c.id) != 0;
  }
  // One mesh per case (about 10 ms each): on every worker.
  parallel_for(n, worker_count(opt.jobs), [&](std::size_t i) {
    const fem::ImpactConfig& config = out.cases[i].config;
    out.cost[i] = name == kOnsetStudy ? onset_case_cost(config)
                                      : case_cost(config, !history && opt.error_estimate);
  });
  return out;
}

double StudyCost::total() const {
  double sum = 0.0;
  for (const double c : cost) sum += c;
  return sum;
}

double StudyCost::skipped() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < cost.size(); ++i) sum += done[i] ? cost[i] : 0.0;
  return sum;
}

}  // namespace corlab::study::reproduce_detail
