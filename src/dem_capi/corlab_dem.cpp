// The C API (include/corlab/corlab_dem.h) over corlab::dem; built as the shared library
// libcorlab_dem. No exception crosses the C boundary.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/corlab_dem.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/dem/calibration.hpp"
#include "corlab/dem/contact_laws.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/dem/uniform_table.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/restitution/registry.hpp"
#include "corlab/version.hpp"

struct corlab_dem_pair {
  corlab::dem::UniformTable restitution;  // e(v)
  corlab::dem::UniformTable chi;          // chi(e) on [0.02, 1]
  double stiffness = 0.0;                 // K [N/m^1.5]
};

namespace {

constexpr int kTablePoints = 1024;

void write_error(char* err, size_t err_len, const std::string& message) {
  if (err == nullptr || err_len == 0) return;
  const size_t n = std::min(err_len - 1, message.size());
  std::memcpy(err, message.data(), n);
  err[n] = '\0';
}

corlab_dem_pair* make_pair(const corlab::dem::RestitutionCurve& curve,
                           double v_min,
                           double v_max,
                           double stiffness) {
  auto* pair = new corlab_dem_pair;
  pair->restitution = corlab::dem::tabulate(curve, v_min, v_max, kTablePoints);
  pair->chi = corlab::dem::tabulate([](double e) { return corlab::dem::exact_chi(e); }, 0.02, 1.0,
                                    4 * kTablePoints);
  pair->stiffness = stiffness;
  return pair;
}

// The library may run where the source tree is not: data_directory() then takes the copy
// installed next to it (<prefix>/share/corlab, installed_data_directory()).
const corlab::MaterialDatabase& material_database() { return corlab::MaterialDatabase::builtin(); }

template <class F>
corlab_dem_pair* guarded(char* err, size_t err_len, const F& make) {
  try {
    return make();
  } catch (const std::exception& e) {
    write_error(err, err_len, e.what());
  } catch (...) {
    write_error(err, err_len, "corlab_dem: unknown error");
  }
  return nullptr;
}

}  // namespace

extern "C" {

const char* corlab_dem_version(void) { return corlab::kVersion.data(); }

corlab_dem_pair* corlab_dem_pair_from_materials(const char* sphere,
                                                const char* substrate,
                                                const char* model,
                                                double radius,
                                                double v_min,
                                                double v_max,
                                                char* err,
                                                size_t err_len) {
  return guarded(err, err_len, [&] {
    if (sphere == nullptr || substrate == nullptr || model == nullptr) {
      throw corlab::InputError("invalid sphere/substrate/model = NULL: must be a name");
    }
    corlab::require_positive("radius", radius, "[m]");
    corlab::require_positive("v_min", v_min, "[m/s]");
    if (!(v_max > v_min)) corlab::throw_invalid("v_max", v_max, "> v_min");
    const auto& db = material_database();
    const auto cor = corlab::restitution::make_model(model, db.get(sphere), db.get(substrate));
    const auto pair =
        corlab::restitution::make_impact_pair(db.get(sphere), db.get(substrate), model);
    return make_pair([&cor](double v) { return cor.cor(v); }, v_min, v_max,
                     corlab::dem::hertz_stiffness(pair.effective_modulus, radius));
  });
}

corlab_dem_pair* corlab_dem_pair_from_table(const double* velocities,
                                            const double* restitution,
                                            size_t n,
                                            double effective_modulus,
                                            double effective_radius,
                                            char* err,
                                            size_t err_len) {
  return guarded(err, err_len, [&] {
    if (velocities == nullptr || restitution == nullptr) {
      throw corlab::InputError("invalid table = NULL: must point to n values");
    }
    corlab::require_positive("effective_modulus", effective_modulus, "[Pa]");
    corlab::require_positive("effective_radius", effective_radius, "[m]");
    std::vector<double> v(velocities, velocities + n);
    std::vector<double> e(restitution, restitution + n);
    const auto curve = corlab::dem::tabulated_curve(v, e);
    return make_pair(curve, v.front(), v.back(),
                     corlab::dem::hertz_stiffness(effective_modulus, effective_radius));
  });
}

double corlab_dem_restitution(const corlab_dem_pair* pair, double velocity) {
  return pair->restitution(velocity);
}

double corlab_dem_chi(const corlab_dem_pair* pair, double velocity) {
  return pair->chi(pair->restitution(velocity));
}

double corlab_dem_stiffness(const corlab_dem_pair* pair) { return pair->stiffness; }

double corlab_dem_force(const corlab_dem_pair* pair,
                        double overlap,
                        double overlap_rate,
                        corlab_dem_state* state) {
  if (!(overlap > 0.0)) return 0.0;
  if (state->impact_velocity <= 0.0) state->impact_velocity = std::max(overlap_rate, 1e-12);
  state->max_overlap = std::max(state->max_overlap, overlap);
  const double v_in = state->impact_velocity;
  const corlab::dem::HysteresisLaw law{
      .stiffness = pair->stiffness, .chi = corlab_dem_chi(pair, v_in), .impact_velocity = v_in};
  return law.force(overlap, overlap_rate);
}

void corlab_dem_pair_free(corlab_dem_pair* pair) { delete pair; }

}  // extern "C"
