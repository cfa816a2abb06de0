// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file simulate.hpp
/// Entry point of the explicit axisymmetric impact solver. Reentrant: no globals, so a study may
/// run one simulation per thread.

#include <atomic>
#include <functional>

#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/mesh/mesh.hpp"
#include "corlab/fem/output/field_snapshot.hpp"
#include "corlab/fem/solver/impact_result.hpp"

namespace corlab::fem {

struct SimulationControl {
  /// Polled every few hundred steps; when it turns true the run stops with status kCancelled.
  const std::atomic<bool>* cancel = nullptr;
  /// Called now and then with the fraction done (estimate, 0..1).
  std::function<void(double)> progress;
  /// Stop at maximum compression (the sphere's c.o.m. velocity turns from approach to rebound),
  /// with status kMaxCompression: yield-onset probes need only the loading half.
  bool stop_at_max_compression = false;
  /// The caller needs e only (the error bar's companion runs): the run ends at the first short
  /// window after the last contact (SeparationRule::e_only) instead of watching the sphere ring
  /// for a few wave transits; e is the same unless the sphere touches again in between, the
  /// energies and e_energy are then those of the shorter run.
  bool e_only = false;
  /// Threads of the caller's pool that have no work left (a sweep's tail), or null: a run with
  /// companions (simulate_with_error_estimate) takes one while it is > 0 to run them alongside,
  /// and gives it back when they are done.
  std::atomic<int>* spare_threads = nullptr;
  /// Called at each requested field time (output.times) with the current mesh and fields (for
  /// VTU output): on_fields by the axisymmetric model, on_hex_fields by the 3-D one.
  std::function<void(double time, const FieldSnapshot&)> on_fields;
  std::function<void(double time, const HexFieldSnapshot&)> on_hex_fields;
  /// The caller already ran validate() on this very config (the CLI before it creates the output
  /// directory, a sweep spec for each of its runs), so simulate() does not check it again:
  /// a config is validated once, where it enters.
  bool config_validated = false;
};

/// Runs one impact (validates the config first unless control.config_validated; throws
/// InputError when it is invalid).
ImpactResult simulate(const ImpactConfig& config, const SimulationControl& control = {});

}  // namespace corlab::fem
