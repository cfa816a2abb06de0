// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/study/sweep.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>

#include "corlab/core/atomic_file.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/number.hpp"
#include "corlab/fem/solver/run_cost.hpp"
#include "sweep_internal.hpp"

namespace corlab::study {
namespace {

int env_int(const char* name) {
  const char* text = std::getenv(name);
  if (text == nullptr) return -1;
  const std::optional<long long> value = parse_integer(text);
  return value && *value > 0 && *value <= std::numeric_limits<int>::max() ? static_cast<int>(*value)
                                                                          : -1;
}

using Clock = std::chrono::steady_clock;

}  // namespace

int launched_world_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const int size = env_int(name); size > 0) return size;
  }
  return 1;
}

int launched_world_rank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}) {
    if (const int rank = env_int(name); rank >= 0) return rank;
  }
  return 0;
}

bool mpi_available() {
#ifdef CORLAB_WITH_MPI
  return true;
#else
  return false;
#endif
}

namespace detail {

Outcome execute_case(const std::vector<SweepCase>& cases,
                     std::size_t index,
                     const std::vector<std::string>& swept_keys,
                     const CaseRunner& runner,
                     const std::atomic<bool>* cancel,
                     std::atomic<int>* spare) {
  const SweepCase& run = cases.at(index);
  std::vector<std::string> swept_values;
  for (const auto& key : swept_keys) {
    const auto it = std::find_if(run.settings.begin(), run.settings.end(),
                                 [&key](const Setting& s) { return s.first == key; });
    swept_values.push_back(it == run.settings.end() ? std::string() : it->second);
  }
  Outcome outcome;
  outcome.index = index;
  fem::SimulationControl control;
  control.cancel = cancel;
  control.spare_threads = spare;
  control.config_validated = true;  // SweepSpec::expand() validated every run's config
  const auto start = Clock::now();
  auto elapsed = [&start] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  std::vector<std::string> row;
  try {
    const fem::ImpactResult result = runner(run.config, control);
    outcome.wall_s = elapsed();
    if (result.status == fem::RunStatus::kCancelled) {
      outcome.status = kInterrupted;
      return outcome;
    }
    row = result_row(run.id, swept_values, run.config, &result, "", outcome.wall_s);
  } catch (const std::exception& err) {
    outcome.wall_s = elapsed();
    if (cancel != nullptr && cancel->load()) {
      outcome.status = kInterrupted;
      return outcome;
    }
    row = result_row(run.id, swept_values, run.config, nullptr, err.what(), outcome.wall_s);
  } catch (...) {
    outcome.wall_s = elapsed();
    row =
        result_row(run.id, swept_values, run.config, nullptr, "unknown exception", outcome.wall_s);
  }
  outcome.status = row.at(1);
  outcome.line = csv_line(row);
  return outcome;
}

std::string serialize(const Outcome& outcome) {
  return fmt::format("{}\t{}\t{}\t{}", outcome.index, outcome.status, format_number(outcome.wall_s),
                     outcome.line);
}

Outcome deserialize(std::string_view message) {
  Outcome outcome;
  std::string_view fields[3];
  for (auto& field : fields) {
    const auto tab = message.find('\t');
    if (tab == std::string_view::npos) throw std::runtime_error("malformed sweep message");
    field = message.substr(0, tab);
    message.remove_prefix(tab + 1);
  }
  const std::optional<long long> index = parse_integer(fields[0]);
  const std::optional<double> wall_s = parse_double(fields[2]);
  if (!index || *index < 0 || !wall_s) throw std::runtime_error("malformed sweep message");
  outcome.index = static_cast<std::size_t>(*index);
  outcome.status = std::string(fields[1]);
  outcome.wall_s = *wall_s;
  outcome.line = std::string(message);
  return outcome;
}

std::optional<std::size_t> CaseQueue::next() {
  const std::lock_guard lock(mutex_);
  if ((cancel_ != nullptr && cancel_->load()) || next_ >= pending_.size()) {
    ++spare_;  // the worker that asked stops
    return std::nullopt;
  }
  return pending_[next_++];
}

Plan make_plan(const SweepSpec& spec, const SweepOptions& options) {
  Plan plan;
  plan.cases = spec.expand();
  plan.swept_keys = spec.swept_keys();
  plan.header = results_header(plan.swept_keys);
  for (const std::size_t i : options.only) {
    if (i >= plan.cases.size()) {
      throw_invalid("case index", static_cast<double>(i),
                    fmt::format("< {} (the spec's runs)", plan.cases.size()));
    }
  }
  if (options.only.empty()) {
    plan.selected.resize(plan.cases.size());
    std::iota(plan.selected.begin(), plan.selected.end(), std::size_t{0});
  } else {
    // A case named twice runs once, in the place of its first mention.
    std::set<std::size_t> seen;
    for (const std::size_t i : options.only) {
      if (seen.insert(i).second) plan.selected.push_back(i);
    }
  }
  return plan;
}

void ensure_directory(const std::filesystem::path& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir)) {
    throw InputError(
        fmt::format("invalid --out = '{}': must be a directory that can be created ({})",
                    out_dir.string(), ec ? ec.message() : "not a directory"));
  }
}

void prepare_output(const SweepSpec& spec,
                    const std::filesystem::path& out_dir,
                    const SweepOptions& options,
                    Plan& plan) {
  ensure_directory(out_dir);
  check_same_study(spec, out_dir);
  try {
    write_file_atomically(out_dir / "spec.toml", spec.to_toml());
  } catch (const std::runtime_error& err) {
    throw InputError(
        fmt::format("invalid --out = '{}': must be writable ({})", out_dir.string(), err.what()));
  }
  // Finished rows (the solver is deterministic: a run that ended without a clean rebound ends
  // the same way again); failed rows (exceptions) are retried.
  std::vector<std::string> keep{std::string(kStatusOk)};
  for (const auto status : {fem::RunStatus::kNotSeparated, fem::RunStatus::kStepCollapsed,
                            fem::RunStatus::kElementInverted, fem::RunStatus::kNonFinite,
                            fem::RunStatus::kStepBudgetExceeded}) {
    keep.emplace_back(fem::to_string(status));
  }
  const ExistingResults existing = prepare_resume(out_dir / "results.csv", plan.header, keep);
  check_no_duplicate_rows(out_dir / "results.csv", existing);
  if (existing.dropped_partial_line) {
    fmt::print(stderr,
               "corlab: {}: dropped a cut last line (a kill during a write); its case "
               "runs again\n",
               (out_dir / "results.csv").string());
  }
  if (existing.duplicates_dropped > 0) {
    fmt::print(stderr, "corlab: {}: dropped {} repeated row(s) of cases already recorded\n",
               (out_dir / "results.csv").string(), existing.duplicates_dropped);
  }
  plan.pending.clear();
  plan.already_done = 0;
  for (const std::size_t i : plan.selected) {
    if (existing.status.count(plan.cases[i].id) != 0) {
      ++plan.already_done;
    } else {
      plan.pending.push_back(i);
    }
  }
  if (!options.spec_order) longest_first(plan);
}

void longest_first(Plan& plan) {
  std::vector<double> cost(plan.cases.size(), 0.0);
  for (const std::size_t i : plan.pending) {
    try {
      cost[i] = fem::estimate_run_cost(plan.cases[i].config).element_steps();
    } catch (const std::exception&) {
      cost[i] = 0.0;  // an invalid case fails at once when it runs: last
    }
  }
  std::stable_sort(plan.pending.begin(), plan.pending.end(),
                   [&cost](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
}

DirectoryLock::DirectoryLock(const std::filesystem::path& out_dir) {
  const auto file = out_dir / ".sweep.lock";
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InputError(fmt::format("invalid --out = '{}': must be writable ({})", out_dir.string(),
                                 std::strerror(errno)));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw InputError(fmt::format(
        "invalid --out = '{}': must not be in use by another running sweep", out_dir.string()));
  }
}

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

Recorder::Recorder(const std::filesystem::path& csv, const Plan& plan, int workers, bool progress)
    : appender_(csv, plan.header),
      total_(static_cast<int>(plan.selected.size())),
      already_done_(plan.already_done),
      workers_(workers) {
  if (progress) {
    progress_ = std::make_unique<ProgressBar>(stderr, total_, workers_);
    progress_->update(already_done_, 0, -1.0, true);
  }
}

void Recorder::record(const Outcome& outcome) {
  if (outcome.status == kInterrupted) {
    ++interrupted_;
    return;
  }
  appender_.append_line(outcome.line);
  ++ran_;
  wall_sum_ += outcome.wall_s;
  if (outcome.status == kStatusFailed) ++failed_;
  if (outcome.status == kStatusNotSeparated) ++not_separated_;
  if (progress_) progress_->update(already_done_ + ran_, failed_, wall_sum_ / ran_);
}

void Recorder::tick() {
  if (progress_) progress_->tick();
}

void Recorder::finish() {
  if (progress_) progress_->finish();
}

SweepSummary Recorder::summary(double wall_s, bool cancelled) const {
  SweepSummary s;
  s.total = total_;
  s.already_done = already_done_;
  s.ran = ran_;
  s.failed = failed_;
  s.not_separated = not_separated_;
  s.wall_s = wall_s;
  s.workers = workers_;
  s.interrupted = (cancelled || interrupted_ > 0) && s.remaining() > 0;
  return s;
}

}  // namespace detail

SweepSummary run_sweep(const SweepSpec& spec,
                       const std::filesystem::path& out_dir,
                       const SweepOptions& options) {
  const CaseRunner runner =
      options.runner
          ? options.runner
          : CaseRunner([](const fem::ImpactConfig& config, const fem::SimulationControl& control) {
              return fem::simulate(config, control);
            });
  std::atomic<bool> never{false};
  const std::atomic<bool>* cancel = options.cancel != nullptr ? options.cancel : &never;
  if (options.jobs < 0) throw_invalid("jobs", options.jobs, ">= 0 (0 = all cores)");

  if (const int world = launched_world_size(); world > 1) {
#ifdef CORLAB_WITH_MPI
    return detail::run_sweep_mpi(spec, out_dir, options, runner, cancel);
#else
    throw InputError(
        fmt::format("invalid launch = mpirun with {} ranks: must be a corlab built with MPI "
                    "(CORLAB_WITH_MPI); run without mpirun for a local sweep",
                    world));
#endif
  }

  const auto start = Clock::now();
  detail::Plan plan = detail::make_plan(spec, options);
  detail::ensure_directory(out_dir);
  const detail::DirectoryLock lock(out_dir);
  detail::prepare_output(spec, out_dir, options, plan);
  const int jobs =
      std::max(1, std::min(worker_count(options.jobs), static_cast<int>(plan.pending.size())));
  detail::Recorder recorder(out_dir / "results.csv", plan, jobs, options.progress);
  detail::CaseQueue queue(plan.pending, cancel);
  {
    detail::WorkerPool pool(
        plan.pending.empty() ? 0 : jobs, [&queue] { return queue.next(); },
        [&](std::size_t index) {
          return detail::execute_case(plan.cases, index, plan.swept_keys, runner, cancel,
                                      queue.spare());
        });
    while (true) {
      const bool stopped = pool.stopped();  // read before taking: no outcome can be missed
      for (const auto& outcome : pool.take(std::chrono::milliseconds(200))) {
        recorder.record(outcome);
      }
      recorder.tick();
      if (stopped) break;
    }
    pool.join();
  }
  recorder.finish();
  return recorder.summary(std::chrono::duration<double>(Clock::now() - start).count(),
                          cancel->load());
}

std::vector<std::size_t> parse_case_selection(std::string_view text,
                                              std::size_t runs,
                                              std::string_view field) {
  std::vector<std::size_t> out;
  const std::string constraint = fmt::format(
      "comma-separated case indices or ranges a-b, each in [0, {}] (the spec's runs)", runs - 1);
  auto index = [&](std::string_view token) {
    const auto v = parse_double(token);
    if (!v || *v < 0.0 || *v != std::floor(*v) || *v >= static_cast<double>(runs)) {
      throw_invalid(field, text, constraint);
    }
    return static_cast<std::size_t>(*v);
  };
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string_view token = text.substr(begin, end - begin);
    const std::size_t dash = token.find('-');
    const std::size_t lo = index(token.substr(0, dash));
    const std::size_t hi = dash == std::string_view::npos ? lo : index(token.substr(dash + 1));
    if (hi < lo) throw_invalid(field, text, constraint);
    for (std::size_t i = lo; i <= hi; ++i) out.push_back(i);
    begin = end + 1;
  }
  return out;
}

}  // namespace corlab::study
