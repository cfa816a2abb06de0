// The axisymmetric impact run: model -> state -> the one time loop (time_loop.hpp) until the
// stop rule, the run status and the result. Model, state and step: src/fem/solver/; stop rule:
// separation_rule.hpp; theory: docs/theory/solver.md.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/explicit_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "corlab/fem/output/field_snapshot.hpp"
#include "corlab/fem/solver/run_quality.hpp"
#include "corlab/fem/solver/separation_rule.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "fem/solver/impact_model.hpp"
#include "fem/solver/impact_state.hpp"
#include "fem/solver/impact_step.hpp"
#include "fem/solver/run_bookkeeping.hpp"
#include "fem/solver/time_loop.hpp"

namespace corlab::fem {
namespace {

using solver::ContactKind;
using solver::ImpactModel;
using solver::ImpactState;
using solver::RunBookkeeping;
using solver::TimeLoop;

FieldSnapshot snapshot(const ImpactModel& m, const Mesh& mesh, const ImpactState& s, double t) {
  FieldSnapshot f;
  f.time = t;
  f.mesh = mesh;
  f.mesh.r = s.r;
  f.mesh.z = s.z;
  f.displacement_r.resize(m.n_nodes);
  f.displacement_z.resize(m.n_nodes);
  for (int i = 0; i < m.n_nodes; ++i) {
    f.displacement_r[i] = s.r[i] - mesh.r[i];
    f.displacement_z[i] = s.z[i] - mesh.z[i];
  }
  f.velocity_r = s.vr;
  f.velocity_z = s.vz;
  f.von_mises.assign(m.n_elements, 0.0);
  f.pressure.assign(m.n_elements, 0.0);
  f.plastic_strain.assign(m.n_elements, 0.0);
  const auto& es = s.elements;
  for (int e = 0; e < m.n_elements; ++e) {
    const AxisymTensor st{es.srr[e], es.szz[e], es.stt[e], es.srz[e]};
    const int k = m.elements.mesh_index[e];
    f.von_mises[k] = von_mises(st);
    f.pressure[k] = -trace(st) / 3.0;
    f.plastic_strain[k] = es.eps_p[e];
  }
  return f;
}

/// Largest von Mises stress over the substrate's elements now [Pa].
double substrate_von_mises_max(const ImpactModel& m, const ImpactState& s) {
  const auto& es = s.elements;
  double vm = 0.0;
  for (int e = m.n_sphere_elements; e < m.n_elements; ++e) {
    vm = std::max(vm, von_mises(AxisymTensor{es.srr[e], es.szz[e], es.stt[e], es.srz[e]}));
  }
  return vm;
}

/// The axisymmetric model's own fields of the result: the crater, the substrate's stress.
void finish_axisymmetric(const ImpactModel& m,
                         const ImpactState& s,
                         double z_axis_surface,
                         ImpactResult& res) {
  // The target's surface on the axis sunk relative to the target's c.o.m. (a flat's is at rest).
  res.crater_depth =
      m.contact == ContactKind::kSegments
          ? (z_axis_surface - s.z[m.masters[0]]) - (m.z_com_target_start - s.target_com_z)
          : 0.0;
  res.substrate_von_mises_max = substrate_von_mises_max(m, s);
  if (res.status == RunStatus::kSeparated) res.suspect = suspect_reason(res);
}

/// What the in-run mass scaling did (impact_step_mass.hpp), into the result.
void in_run_scaling_fields(const ImpactModel& m, const ImpactState& s, ImpactResult& res) {
  const solver::InRunScaling& sc = s.scaling;
  if (!sc.on()) return;
  res.in_run_added_mass_fraction = sc.added_mass / m.scaling.sphere_mass_physical;
  res.in_run_scaled_elements = static_cast<int>(sc.scaled.size());
  res.in_run_steps_saved = sc.steps_unscaled - static_cast<double>(s.step);
  res.energy_mass_scaling = s.energy.mass_scaling;
}

}  // namespace

ImpactResult run_impact(const ImpactConfig& config,
                        const Mesh& mesh,
                        const SimulationControl& control) {
  const auto wall_start = std::chrono::steady_clock::now();
  const ImpactModel m = solver::make_impact_model(config, mesh);
  ImpactState s = solver::make_initial_state(m);
  solver::init_in_run_scaling(config.solver, m, s);
  // The substrate surface on the axis (the rigid flat: z = 0), for the crater depth.
  const double z_axis_surface = m.contact == ContactKind::kSegments ? s.z[m.masters[0]] : 0.0;
  ImpactResult res;
  res.elements = m.n_elements;
  res.nodes = m.n_nodes;
  res.time_step = m.dt_initial;
  res.mass_scaling = m.scaling.factor * m.scaling.step_floor_scale;
  res.added_mass_fraction = m.scaling.added_mass / m.scaling.sphere_mass_physical;
  res.simd = std::string(to_string(m.simd));
  res.h_contact = solver::contact_element_size(m);
  res.energy_initial = m.energy_initial;

  TimeLoop<ImpactModel, ImpactState> loop(config, control, m, s, res.history, [&](double t) {
    if (control.on_fields) control.on_fields(t, snapshot(m, mesh, s, t));
  });
  RunStatus status = loop.run();
  const RunBookkeeping& book = loop.bookkeeping();
  solver::finish_run(m, s, loop, status, res);
  finish_axisymmetric(m, s, z_axis_surface, res);
  if (res.separated) res.e_impacts = {res.e};
  for (int k = 2; k <= config.impact.repeats && status == RunStatus::kSeparated; ++k) {
    loop.relaunch();
    status = loop.run();
    if (status == RunStatus::kSeparated) {
      res.e_impacts.push_back(solver::relative_velocity(s) / m.velocity);
    } else {
      // The run's status is its last impact's; the first impact's fields stay as they were.
      res.status = status;
      res.separated = false;
      res.status_detail =
          fmt::format("impact {}: {}", k,
                      solver::status_detail(status, m, s, loop.last_forces(), loop.time_limit()));
    }
  }
  if (config.impact.repeats > 1) {  // the run's totals over every impact
    res.energy_balance_error = book.balance_max();
    res.steps = s.step;
    res.element_updates = s.element_updates;
    res.end_time = s.t;
  }
  in_run_scaling_fields(m, s, res);
  solver::close_run(s, wall_start, control, res);
  return res;
}

}  // namespace corlab::fem
