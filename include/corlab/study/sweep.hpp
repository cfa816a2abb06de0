// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file sweep.hpp
/// Runs every case of a sweep with the impact solver, one run per core, appending each finished
/// case to <out>/results.csv at once (written and fsync'ed by one writer) and resuming where a
/// previous run left off. Under `mpirun -n N` (N > 1) the cases are distributed over the ranks
/// instead: rank 0 hands out case indices on request, runs cases itself and writes every row.

#include <atomic>
#include <filesystem>
#include <functional>
#include <string_view>
#include <vector>

#include "corlab/fem/solver/impact_result.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace corlab::study {

/// Runs one case. Must be callable from several threads at once. A run that sees
/// control.cancel turn true throws (it is then not recorded: it is rerun on resume).
using CaseRunner =
    std::function<fem::ImpactResult(const fem::ImpactConfig&, const fem::SimulationControl&)>;

struct SweepOptions {
  /// Cases run at the same time per process (threads); 0 = all cores (under MPI: 1 per rank).
  int jobs = 0;
  bool progress = true;  ///< progress bar on stderr (rank 0 only)
  CaseRunner runner;     ///< empty = fem::simulate (the production path)
  /// When it turns true: no new case starts, running ones are cancelled, finished rows are kept.
  const std::atomic<bool>* cancel = nullptr;
  /// Run the pending cases in the spec's order instead of longest first: for a space-filling
  /// design (Sobol) finished over several sessions, whose every prefix is balanced.
  bool spec_order = false;
  /// Only these cases (indices in the spec's order, 0-based; a repeated index runs once); empty =
  /// all. The summary's total counts them only. To rerun some rows of a study (a dataset subset).
  std::vector<std::size_t> only;
};

/// Parses a case selection: comma-separated indices and inclusive ranges ("0-99,512,1000-1023")
/// of a spec with `runs` cases, in the order written (repeats kept: SweepOptions::only drops them).
/// Throws InputError naming `field` for a bad token or an index out of range.
std::vector<std::size_t> parse_case_selection(std::string_view text,
                                              std::size_t runs,
                                              std::string_view field);

struct SweepSummary {
  int total = 0;             ///< cases in the spec
  int already_done = 0;      ///< finished in an earlier run (found in results.csv), skipped
  int ran = 0;               ///< finished in this run (ok, not_separated or failed)
  int failed = 0;            ///< of `ran`: threw (status failed)
  int not_separated = 0;     ///< of `ran`: t_max reached before rebound (status not_separated)
  double wall_s = 0;         ///< wall-clock time of this run [s]
  bool interrupted = false;  ///< cancelled before every case finished
  int rank = 0;              ///< MPI rank of this process (0 without MPI)
  int ranks = 1;             ///< MPI ranks that took part (1 without MPI)
  int workers = 0;           ///< cases run at the same time, over all ranks
  /// Cases still to run (total - already_done - ran).
  int remaining() const { return total - already_done - ran; }
};

/// Runs the sweep into `out_dir` (created if needed): results.csv (see results_table.hpp) and
/// spec.toml (a copy of the spec). Cases whose id already has a row with status ok or
/// not_separated are skipped (the solver is deterministic: rerunning them gives the same row);
/// rows of failed cases are dropped and those cases rerun. A failed case does not stop the
/// sweep. Throws InputError for a bad spec or an unusable out_dir before anything runs.
/// Started by mpirun with more than one rank (and built with MPI), it runs distributed; every
/// rank must call it with the same spec, and every rank gets the same summary (rank aside).
SweepSummary run_sweep(const SweepSpec& spec,
                       const std::filesystem::path& out_dir,
                       const SweepOptions& options);

/// Number of MPI ranks this process was started with by mpirun/srun (environment:
/// OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_SIZE), 1 if none. Does not touch MPI.
int launched_world_size();

/// The MPI rank from the same environment (0 if none). Does not touch MPI.
int launched_world_rank();

/// True when this build can run sweeps over MPI (CORLAB_WITH_MPI).
bool mpi_available();

}  // namespace corlab::study
