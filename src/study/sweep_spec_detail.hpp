// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file sweep_spec_detail.hpp
/// The settings arithmetic of a sweep spec and its validation, shared by sweep_spec.cpp (parsing,
/// expansion) and sweep_spec_check.cpp (validation). Private to src/study.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/study/sweep_spec.hpp"
#include "spec_error.hpp"

namespace corlab::study {

/// `key` in double quotes, as a spec's places show it.
std::string quoted_key(std::string_view key);

/// Sets `key` to `value`, replacing an earlier value of the same key in place.
void set_or_replace(Settings& settings, const std::string& key, const std::string& value);

/// Whether `key` is a `<body>.material` key.
bool is_material_key(std::string_view key);

/// The settings in the order they are applied: the material keys first (stable).
Settings application_order(Settings settings);

/// The grid points in order, the last key varying fastest.
std::vector<Settings> grid_points(const SweepSpec& spec);

/// One run's settings: base, then its case, then its grid point, in application order.
Settings merged(const SweepSpec& spec, const Settings& case_settings, const Settings& point);

/// "k1=v1, k2=v2", for messages.
std::string settings_summary(const Settings& settings);

/// Where each setting of a spec was written ("base.\"key\"", "cases[0].\"key\"").
struct SpecPlaces {
  std::vector<std::string> base;
  std::vector<std::vector<std::string>> cases;
};

/// Validates every setting where it was written (its own syntax and range), then every run as
/// `corlab simulate` would, all of its keys together; refuses two runs with identical settings
/// or identical resolved configurations. Throws a located InputError on the first problem.
void validate_spec(const SweepSpec& spec, const SpecError& error, const SpecPlaces& places);

}  // namespace corlab::study
