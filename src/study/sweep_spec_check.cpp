// Validation of a sweep spec: each setting where it was written, then every run whole
// (sweep_spec_detail.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/hash.hpp"
#include "corlab/fem/config/config_keys.hpp"
#include "study/sweep_spec_detail.hpp"

namespace corlab::study {
namespace {

/// The place of `key` in one run: its grid value, else its case's, else [base]'s; empty if the run
/// does not set it.
std::string place_of(const SweepSpec& spec,
                     const SpecPlaces& places,
                     std::size_t case_index,
                     const Settings& point,
                     std::string_view key) {
  for (const auto& [k, v] : point) {
    if (k != key) continue;
    for (const auto& [grid_key, values] : spec.grid) {
      if (grid_key != key) continue;
      const auto i =
          static_cast<std::size_t>(std::find(values.begin(), values.end(), v) - values.begin());
      return fmt::format("grid.{}[{}]", quoted_key(key), i);
    }
  }
  if (!spec.cases.empty()) {
    const Settings& c = spec.cases[case_index];
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i].first == key) return places.cases[case_index][i];
    }
  }
  for (std::size_t i = 0; i < spec.base.size(); ++i) {
    if (spec.base[i].first == key) return places.base[i];
  }
  return {};
}

/// The keys whose values make a run's resolved configuration: every key a spec sets, a material
/// key as its body's five properties (the material's name is not physics), the solver model as
/// the one that runs (uses_3d_model). Two runs with the same values of these run the same case.
std::vector<std::string> identity_keys(const SweepSpec& spec) {
  std::set<std::string> keys;
  auto add = [&keys](const std::string& key) {
    if (key == "solver.model") return;  // the effective model is added on its own
    if (is_material_key(key)) {
      const std::string body = key.substr(0, key.size() - std::string_view(".material").size());
      for (const char* p : {".E", ".nu", ".rho", ".sigma_y", ".hardening"}) keys.insert(body + p);
      return;
    }
    keys.insert(key);
  };
  for (const auto& [k, v] : spec.base) add(k);
  for (const auto& c : spec.cases) {
    for (const auto& [k, v] : c) add(k);
  }
  for (const auto& [k, values] : spec.grid) add(k);
  return {keys.begin(), keys.end()};
}

/// The resolved configuration as text over `keys` (identity_keys).
std::string identity_of(const fem::ImpactConfig& config, const std::vector<std::string>& keys) {
  std::string text = fem::uses_3d_model(config) ? "3d" : "axisymmetric";
  for (const auto& key : keys) {
    text += '\n';
    text += key;
    text += '=';
    text += fem::config_value_text(config, key);
  }
  return text;
}

/// One run of a spec: its case's index and settings, its index and its grid point.
struct RunRef {
  std::size_t case_index;
  std::size_t index;
  const Settings& case_settings;
  const Settings& point;
};

/// Throws `err`, a run's fem::validate error, at the place of the setting it is about: the run's
/// case or grid value its field names (a property's error may come from its body's material
/// key), else its one case or grid value; a run of several such values is named with them, so
/// that the combination shows. An error of [base] alone names [base].
[[noreturn]] void fail_run(const SweepSpec& spec,
                           const SpecPlaces& places,
                           const SpecError& error,
                           const RunRef& run,
                           const InputError& err) {
  Settings varying = run.case_settings;
  for (const auto& [k, v] : run.point) set_or_replace(varying, k, v);
  if (varying.empty()) {
    for (std::size_t i = 0; i < spec.base.size(); ++i) {
      const auto& [key, value] = spec.base[i];
      if (err.field() == key || key == err.field() + ".material")
        error.rethrow_at(places.base[i], key, value, err);
    }
    error.fail("[base]", err.what());
  }
  const Setting* culprit = varying.size() == 1 ? &varying.front() : nullptr;
  for (const auto& s : varying) {
    if (!err.field().empty() && (s.first == err.field() || s.first == err.field() + ".material"))
      culprit = &s;
  }
  if (culprit == nullptr) {
    error.fail(fmt::format("run {} ({})", run.index, settings_summary(varying)), err.what());
  }
  const std::string where = place_of(spec, places, run.case_index, run.point, culprit->first);
  if (varying.size() == 1) error.rethrow_at(where, culprit->first, culprit->second, err);
  error.fail(fmt::format("run {} ({})", run.index, settings_summary(varying)),
             fmt::format("{}: {}", where, err.what()));
}

}  // namespace

void validate_spec(const SweepSpec& spec, const SpecError& error, const SpecPlaces& places) {
  // 1. Each setting alone: its syntax and its key's range. Limits that join keys (friction needs
  // an angle, h_max >= h_min) are checked per run below, where all of a run's keys are known.
  auto check_one = [&](const std::string& where, const std::string& key, const std::string& value) {
    fem::ImpactConfig config;
    try {
      fem::apply_setting(config, key, value);
      fem::validate_key_ranges(config);
    } catch (const InputError& err) {
      error.rethrow_at(where, key, value, err);
    }
  };
  for (std::size_t i = 0; i < spec.base.size(); ++i) {
    check_one(places.base[i], spec.base[i].first, spec.base[i].second);
  }
  for (std::size_t c = 0; c < spec.cases.size(); ++c) {
    for (std::size_t i = 0; i < spec.cases[c].size(); ++i) {
      check_one(places.cases[c][i], spec.cases[c][i].first, spec.cases[c][i].second);
    }
  }
  for (const auto& [key, values] : spec.grid) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      check_one(fmt::format("grid.{}[{}]", quoted_key(key), i), key, values[i]);
    }
  }
  // 2. Every run (base, case and grid point together), and no two identical runs.
  std::map<std::string, std::size_t> seen;
  // Resolved configurations by their hash (a million runs' texts would take hundreds of MB); a
  // match is confirmed on the texts.
  std::unordered_multimap<std::uint64_t, std::size_t> resolved;
  const std::vector<std::string> keys = identity_keys(spec);
  const auto points = grid_points(spec);
  const auto case_of = [&spec](std::size_t c) {
    return spec.cases.empty() ? Settings{} : spec.cases[c];
  };
  const auto identity_of_run = [&](std::size_t run) {
    fem::ImpactConfig config;
    apply_settings(config, merged(spec, case_of(run / points.size()), points[run % points.size()]));
    return identity_of(config, keys);
  };
  const std::size_t n_cases = spec.cases.empty() ? 1 : spec.cases.size();
  std::size_t index = 0;
  for (std::size_t c = 0; c < n_cases; ++c) {
    const Settings case_settings = case_of(c);
    for (const auto& point : points) {
      const Settings settings = merged(spec, case_settings, point);
      fem::ImpactConfig config;
      try {
        apply_settings(config, settings);
        fem::validate(config);
      } catch (const InputError& err) {
        fail_run(spec, places, error, {c, index, case_settings, point}, err);
      }
      const std::string id = case_id(settings);
      if (const auto [it, inserted] = seen.emplace(id, index); !inserted) {
        error.fail("", fmt::format("runs {} and {} have identical settings ({})", it->second, index,
                                   settings_summary(settings)));
      }
      const std::string identity = identity_of(config, keys);
      const std::uint64_t hash = fnv1a64(identity);
      const auto [first, last] = resolved.equal_range(hash);
      for (auto it = first; it != last; ++it) {
        if (identity_of_run(it->second) != identity) continue;
        const std::size_t earlier = it->second;
        error.fail("", fmt::format("runs {} ({}) and {} ({}) resolve to the same configuration "
                                   "(values written differently, one case run twice); keep one",
                                   earlier,
                                   settings_summary(merged(spec, case_of(earlier / points.size()),
                                                           points[earlier % points.size()])),
                                   index, settings_summary(settings)));
      }
      resolved.emplace(hash, index);
      ++index;
    }
  }
}

}  // namespace corlab::study
