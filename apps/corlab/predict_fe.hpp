// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file predict_fe.hpp
/// `corlab predict --model fe|auto` (study/fe_curve.hpp, dataset/auto_restitution.hpp): its
/// options, kept apart from the closed-form models' code in cmd_predict.cpp.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "corlab/materials/material.hpp"

namespace corlab::cli {

/// The options only `--model fe|auto` reads.
struct FeOptions {
  std::string shape;  ///< flat | sphere | rigid; empty: sphere for a radius ratio > 0, else flat
  int jobs = 0;       ///< speeds run at once (0: one per core)
  bool no_cache = false;   ///< compute every speed, store nothing
  bool quiet = false;      ///< no progress line
  double tolerance = 0.0;  ///< > 0: fe at fewer speeds, interpolated to this error [-]
};

/// Whether `model` is answered here: "fe" or "auto".
bool is_fe_model(const std::string& model);

/// Adds --shape, --jobs, --no-cache and --quiet to `predict`.
void add_fe_options(CLI::App& sub, FeOptions& options);

/// InputError when an FE-only option is given with a closed-form model.
void require_no_fe_options(const FeOptions& options, double radius_ratio);

/// What one `predict --model fe|auto` computes and prints.
struct FePredictRequest {
  std::string model;  ///< fe | auto
  std::string sphere_spec;
  std::string substrate_spec;
  Material sphere;
  Material substrate;
  std::vector<double> velocities;  ///< [m/s]
  double radius_ratio = 0.0;       ///< R1/R2 [-]
  std::string format;              ///< csv | json
  FeOptions options;
};

/// Runs it and prints the rows; exit 0 when every speed has an e, 4 when some has none (its row
/// says why), 128 + signal when interrupted.
int run_predict_fe(const FePredictRequest& request);

}  // namespace corlab::cli
