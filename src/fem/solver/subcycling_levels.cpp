// Element subcycling's level assignment (docs/theory/solver.md section 11): each element's level
// from its stable step, the neighbour and interface rules, and the level-sorted ranges.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/subcycling_levels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "corlab/fem/kernels/subcycling_level.hpp"

namespace corlab::fem::solver {
namespace {

/// Stable step of element e at the start positions (as for dt_critical, mass scaling included)
/// [s].
double initial_element_step(const ImpactModel& m, int e) {
  return m.elements.step_scale[e] * physical_element_step(m, e);
}

/// Level of each node: the smallest level of its elements.
std::vector<int> node_levels(const ImpactModel& m, const std::vector<int>& element_level) {
  std::vector<int> level(m.n_nodes, kMaxSubcyclingLevels);
  for (int e = 0; e < m.n_elements; ++e) {
    for (int n : m.elements.nodes(e)) level[n] = std::min(level[n], element_level[e]);
  }
  return level;
}

/// Whether each node may carry an element one level above its own (kInterfaceStepRatio): every
/// element of the node's level at it has its own step (`own`) >= kInterfaceStepRatio x 2^L x
/// dt_critical.
std::vector<char> may_carry_slower(const ImpactModel& m,
                                   const std::vector<int>& level,
                                   const std::vector<int>& node_level,
                                   const std::vector<double>& own) {
  std::vector<char> ok(m.n_nodes, 1);
  for (int e = 0; e < m.n_elements; ++e) {
    const double ratio = own[e] / std::ldexp(m.dt_critical, level[e]);
    for (int n : m.elements.nodes(e)) {
      if (level[e] == node_level[n] && ratio < kInterfaceStepRatio) ok[n] = 0;
    }
  }
  return ok;
}

/// Level of each element: subcycling_level of its own stable step against dt_critical; 0 for an
/// element touching a contact node; then lowered until it is at most one above the smallest level
/// at its nodes (neighbours differ by at most one level), and to a node's level where that node
/// may not carry a slower element (may_carry_slower).
std::vector<int> element_levels(const ImpactModel& m, int max_level) {
  std::vector<char> contact(m.n_nodes, 0);
  for (int i : m.slaves) contact[i] = 1;
  for (int i : m.masters) contact[i] = 1;
  std::vector<int> level(m.n_elements, 0);
  std::vector<double> own(m.n_elements);
  for (int e = 0; e < m.n_elements; ++e) {
    own[e] = initial_element_step(m, e);
    int l = subcycling_level(m.dt_critical, own[e], max_level);
    for (int n : m.elements.nodes(e)) l = contact[n] != 0 ? 0 : l;
    level[e] = l;
  }
  for (bool changed = true; changed;) {
    changed = false;
    const std::vector<int> nl = node_levels(m, level);
    const std::vector<char> ok = may_carry_slower(m, level, nl, own);
    for (int e = 0; e < m.n_elements; ++e) {
      int lim = level[e];
      for (int n : m.elements.nodes(e)) lim = std::min(lim, nl[n] + (ok[n] != 0 ? 1 : 0));
      changed = changed || lim != level[e];
      level[e] = lim;
    }
  }
  return level;
}

/// SubcyclingLevels::interface_nodes from the element and node levels (elements at a node differ
/// from it by at most one level).
void set_interface_nodes(const ElementConstants& elements, SubcyclingLevels& lv) {
  std::vector<char> slow(lv.node.size(), 0);
  for (int e = 0; e < elements.size(); ++e) {
    for (int n : elements.nodes(e))
      slow[n] = static_cast<char>(slow[n] || lv.element[e] > lv.node[n]);
  }
  for (auto& nodes : lv.interface_nodes) nodes.clear();
  for (std::size_t n = 0; n < slow.size(); ++n) {
    if (slow[n] != 0) lv.interface_nodes[lv.node[n]].push_back(static_cast<int>(n));
  }
}

/// Elements of each body sorted by level (stable), the level ranges, and the nodes by level.
/// node_level: each node's level (the smallest level of its elements).
void sort_by_level(ImpactModel& m, const std::vector<int>& level, std::vector<int> node_level) {
  SubcyclingLevels& lv = m.levels;
  std::vector<int> order(m.n_elements);
  for (int e = 0; e < m.n_elements; ++e) order[e] = e;
  const auto by_level = [&](int a, int b) { return level[a] < level[b]; };
  std::stable_sort(order.begin(), order.begin() + m.n_sphere_elements, by_level);
  std::stable_sort(order.begin() + m.n_sphere_elements, order.end(), by_level);
  ElementConstants sorted;
  lv.element.assign(m.n_elements, 0);
  for (int k = 0; k < m.n_elements; ++k) {
    sorted.push_back(m.elements.nodes(order[k]), m.elements.mesh_index[order[k]]);
    sorted.step_scale[k] = m.elements.step_scale[order[k]];
    lv.element[k] = level[order[k]];
  }
  m.elements = std::move(sorted);
  for (int l = 0; l <= kMaxSubcyclingLevels; ++l) {
    const auto below = [&](int x) { return x <= l; };
    const auto mid = lv.element.begin() + m.n_sphere_elements;
    lv.sphere_end[l] = static_cast<int>(std::count_if(lv.element.begin(), mid, below));
    lv.substrate_end[l] =
        m.n_sphere_elements + static_cast<int>(std::count_if(mid, lv.element.end(), below));
  }
  lv.node = std::move(node_level);
  lv.node_scale.resize(m.n_nodes);
  for (int i = 0; i < m.n_nodes; ++i) lv.node_scale[i] = std::ldexp(1.0, lv.node[i]);
  lv.node_order.resize(m.n_nodes);
  for (int i = 0; i < m.n_nodes; ++i) lv.node_order[i] = i;
  std::stable_sort(lv.node_order.begin(), lv.node_order.end(),
                   [&](int a, int b) { return lv.node[a] < lv.node[b]; });
  for (int l = 0; l <= kMaxSubcyclingLevels; ++l) {
    lv.node_end[l] = static_cast<int>(
        std::count_if(lv.node.begin(), lv.node.end(), [&](int x) { return x <= l; }));
  }
  set_interface_nodes(m.elements, lv);
}

}  // namespace

void set_levels(const SolverConfig& sc, ImpactModel& m) {
  m.levels = SubcyclingLevels{};
  const int max_level = std::clamp(sc.subcycling_levels, 0, kMaxSubcyclingLevels);
  if (max_level == 0) return;
  // Nodes step at the smallest level of their elements, so that every element's nodes are in
  // sync when it updates (docs/theory/solver.md section 11).
  const std::vector<int> level = element_levels(m, max_level);
  const std::vector<int> nl = node_levels(m, level);
  const int used = *std::max_element(level.begin(), level.end());
  double updates = 0.0;
  for (int l : level) updates += std::ldexp(1.0, -l);
  if (used == 0 || updates > kMaxUpdateFraction * m.n_elements) return;
  sort_by_level(m, level, nl);
  m.levels.max_level = used;
}

}  // namespace corlab::fem::solver
