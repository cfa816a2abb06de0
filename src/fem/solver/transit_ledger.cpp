// The subcycling's energy in transit (see transit_ledger.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/transit_ledger.hpp"

#include <cmath>
#include <cstddef>

namespace corlab::fem::solver {
namespace {

/// r_out[k] = r[nodes[k]], z_out[k] = z[nodes[k]]: a nodal pair at the interface nodes.
void gather(const std::vector<int>& nodes,
            const double* r,
            const double* z,
            std::vector<double>& r_out,
            std::vector<double>& z_out) {
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    r_out[k] = r[nodes[k]];
    z_out[k] = z[nodes[k]];
  }
}

}  // namespace

void TransitLedger::reset(const SubcyclingLevels& lv, const double* vr, const double* vz) {
  energy = 0.0;
  for (int l = 0; l < kMaxSubcyclingLevels; ++l) {
    const std::size_t n = lv.interface_nodes[l].size();
    TransitLevel& t = levels[l];
    for (auto* v : {&t.g_r, &t.g_z, &t.f_r, &t.f_z, &t.v_r, &t.v_z}) v->assign(n, 0.0);
    open_windows(lv, l, vr, vz);
  }
}

void TransitLedger::before_slow_pass(const SubcyclingLevels& lv,
                                     int level,
                                     const double* fr,
                                     const double* fz) {
  gather(lv.interface_nodes[level], fr, fz, levels[level].f_r, levels[level].f_z);
}

void TransitLedger::after_slow_pass(const SubcyclingLevels& lv,
                                    int level,
                                    double h,
                                    const double* fr,
                                    const double* fz,
                                    const double* vr,
                                    const double* vz) {
  const std::vector<int>& nodes = lv.interface_nodes[level];
  TransitLevel& t = levels[level];
  // The slow pass scattered 2^{level+1} g: its impulse in base-step units.
  const double unscale = std::ldexp(1.0, -(level + 1));
  double sum = 0.0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const int n = nodes[k];
    const double g_r = (fr[n] - t.f_r[k]) * unscale;
    const double g_z = (fz[n] - t.f_z[k]) * unscale;
    sum += window_transit(h, t.v_r[k], vr[n], t.g_r[k], g_r) +
           window_transit(h, t.v_z[k], vz[n], t.g_z[k], g_z);
    t.g_r[k] = g_r;
    t.g_z[k] = g_z;
  }
  energy += sum;
}

void TransitLedger::open_windows(const SubcyclingLevels& lv,
                                 int level,
                                 const double* vr,
                                 const double* vz) {
  gather(lv.interface_nodes[level], vr, vz, levels[level].v_r, levels[level].v_z);
}

}  // namespace corlab::fem::solver
