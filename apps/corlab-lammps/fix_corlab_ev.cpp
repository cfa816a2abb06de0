// SPDX-License-Identifier: BSD-3-Clause
#include "fix_corlab_ev.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <utility>

#include "atom.h"
#include "corlab/dem/ev_damping.hpp"
#include "error.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

namespace corlab::lammps {

using corlab::dem::HysteresisLaw;
using corlab::dem::UniformTable;

FixCorlabEv::FixCorlabEv(LAMMPS_NS::LAMMPS* instance, int narg, char** arg)
    : Fix(instance, narg, arg) {
  ntypes_ = atom->ntypes;
  if (atom->radius_flag == 0 || atom->tag_enable == 0) {
    fail("needs atom_style sphere with atom IDs");
  }
  if (narg < 7 || std::strcmp(arg[3], "speeds") != 0) fail("expected `speeds V_MIN V_MAX N`");
  v_min_ = number(narg, arg, 4, "V_MIN");
  v_max_ = number(narg, arg, 5, "V_MAX");
  const double rows = number(narg, arg, 6, "N");
  if (!(rows >= 2.0 && rows <= 1e6) || rows != std::floor(rows)) {
    fail("N = " + std::string(arg[6]) + " must be an integer >= 2");
  }
  const int n = static_cast<int>(rows);
  const auto size = static_cast<std::size_t>(ntypes_) + 1;
  pair_row_.assign(size * size, -1);
  pair_estar_.assign(size * size, 0.0);
  const auto type_of = [&](int index) {
    const double t = number(narg, arg, index, "type");
    if (!(t >= 1.0 && t <= ntypes_) || t != std::floor(t)) {
      fail("type " + std::string(arg[index]) + " is not an atom type (1.." +
           std::to_string(ntypes_) + ")");
    }
    return static_cast<std::size_t>(t);
  };
  std::vector<double> e;
  for (int i = 7; i < narg;) {
    const std::string key = arg[i];
    if (key == "pair") {
      const std::size_t a = type_of(i + 1);
      const std::size_t b = type_of(i + 2);
      const double estar = number(narg, arg, i + 3, "E*");
      i = parse_table(narg, arg, i + 4, n, e);
      pair_row_[a * size + b] = pair_row_[b * size + a] = static_cast<int>(tables_.size() - 1);
      pair_estar_[a * size + b] = pair_estar_[b * size + a] = estar;
    } else if (key == "wall") {
      WallRows w{{}, std::vector<int>(size, -1), std::vector<double>(size, 0.0)};
      const std::string shape = i + 1 < narg ? arg[i + 1] : "";
      if (shape == "plane") {
        for (int k = 0; k < 3; ++k) {
          w.wall.point[static_cast<std::size_t>(k)] = number(narg, arg, i + 2 + k, "plane point");
          w.wall.normal[static_cast<std::size_t>(k)] = number(narg, arg, i + 5 + k, "plane normal");
        }
        const auto& nv = w.wall.normal;
        const double norm = std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        if (!(norm > 0.0)) fail("a plane's normal must not be zero");
        for (double& c : w.wall.normal) c /= norm;
        i += 8;
      } else if (shape == "cylinder") {
        w.wall.shape = corlab::dem::WallShape::cylinder;
        const double axis = number(narg, arg, i + 2, "cylinder axis");
        if (axis != 0.0 && axis != 1.0 && axis != 2.0) fail("a cylinder's axis must be 0, 1 or 2");
        w.wall.axis = static_cast<int>(axis);
        w.wall.centre = {number(narg, arg, i + 3, "C1"), number(narg, arg, i + 4, "C2")};
        w.wall.radius = number(narg, arg, i + 5, "R");
        w.wall.lo = number(narg, arg, i + 6, "LO");
        w.wall.hi = number(narg, arg, i + 7, "HI");
        if (!(w.wall.radius > 0.0) || !(w.wall.hi > w.wall.lo))
          fail("a cylinder needs R > 0, HI > LO");
        i += 8;
      } else {
        fail("wall shape `" + shape + "` is not plane or cylinder");
      }
      walls_.push_back(std::move(w));
    } else if (key == "type") {
      if (walls_.empty()) fail("`type` must follow a `wall`");
      const std::size_t t = type_of(i + 1);
      walls_.back().estar[t] = number(narg, arg, i + 2, "E*");
      i = parse_table(narg, arg, i + 3, n, e);
      walls_.back().row[t] = static_cast<int>(tables_.size() - 1);
    } else {
      fail("unknown keyword `" + key + "` (pair, wall, type)");
    }
  }
}

LAMMPS_NS::Fix* FixCorlabEv::create(LAMMPS_NS::LAMMPS* instance, int narg, char** arg) {
  return new FixCorlabEv(instance, narg, arg);
}

void FixCorlabEv::fail(const std::string& message) {
  error->all(FLERR, std::string("fix corlab/ev: ") + message);
}

double FixCorlabEv::number(int narg, char** arg, int index, const char* what) {
  if (index >= narg) fail(std::string("missing ") + what);
  char* end = nullptr;
  const double x = std::strtod(arg[index], &end);
  if (end == arg[index] || *end != '\0' || !std::isfinite(x)) {
    fail(std::string(what) + " = `" + arg[index] + "` is not a finite number");
  }
  return x;
}

int FixCorlabEv::parse_table(int narg, char** arg, int index, int n, std::vector<double>& row) {
  row.clear();
  for (int k = 0; k < n; ++k) row.push_back(number(narg, arg, index + k, "e"));
  try {
    tables_.push_back(corlab::dem::chi_table(v_min_, v_max_, row));
  } catch (const std::exception& ex) {
    fail(ex.what());
  }
  return index + n;
}

int FixCorlabEv::setmask() { return LAMMPS_NS::FixConst::PRE_REVERSE; }

void FixCorlabEv::init() {
  if (atom->ntypes != ntypes_) fail("the number of atom types changed since the fix was defined");
  LAMMPS_NS::Pair* granular = force->pair_match("granular", 1);
  if (granular == nullptr || granular != force->pair) {
    fail("needs pair_style granular (not within hybrid)");
  }
  if (std::strncmp(update->integrate_style, "respa", 5) == 0)
    fail("run_style respa is not supported");
}

void FixCorlabEv::setup_pre_reverse(int eflag, int vflag) { pre_reverse(eflag, vflag); }

void FixCorlabEv::pre_reverse(int /*eflag*/, int /*vflag*/) {
  const LAMMPS_NS::NeighList* list = force->pair->list;
  if (list == nullptr) fail("pair_style granular has no neighbour list");
  // Atoms are reordered and exchanged only when the lists are rebuilt.
  const bool rebuilt = neighbor->ncalls != ncalls_ || list != list_;
  ncalls_ = neighbor->ncalls;
  list_ = list;
  add_pair_forces(rebuilt);
  add_wall_forces(rebuilt);
}

void FixCorlabEv::Slots::rebuild(std::size_t n) {
  carried_.clear();
  for (std::size_t k = 0; k < active_.size(); ++k) {
    if (active_[k] != 0) carried_.emplace(slots_[k].key, slots_[k]);
  }
  active_.assign(n, 0);
  slots_.resize(n);
}

template <class Onset>
double FixCorlabEv::Slots::damping(
    std::size_t k, std::uint64_t key, double overlap, double rate, const Onset& onset) {
  if (active_[k] == 0) {
    const auto old = carried_.find(key);  // empty but at a rebuild
    if (old != carried_.end()) {
      slots_[k] = old->second;
    } else {
      const HysteresisLaw law = onset();
      slots_[k] = {law, law.damping_coefficient(), key};
    }
    active_[k] = 1;
  }
  const Slot& s = slots_[k];
  return s.law.damping(overlap, rate, s.coefficient);
}

void FixCorlabEv::add_pair_forces(bool rebuilt) {
  const LAMMPS_NS::NeighList* list = force->pair->list;
  if (rebuilt) {
    pair_offset_.resize(static_cast<std::size_t>(list->inum));
    std::size_t total = 0;
    for (int ii = 0; ii < list->inum; ++ii) {
      pair_offset_[static_cast<std::size_t>(ii)] = total;
      total += static_cast<std::size_t>(list->numneigh[list->ilist[ii]]);
    }
    pair_slots_.rebuild(total);
  }
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  const double* radius = atom->radius;
  const LAMMPS_NS::tagint* tag = atom->tag;
  const int* type = atom->type;
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  const bool newton = force->newton_pair != 0;
  const auto size = static_cast<std::size_t>(ntypes_) + 1;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    if ((mask[i] & groupbit) == 0) continue;
    const int* jlist = list->firstneigh[i];
    const std::size_t first = pair_offset_[static_cast<std::size_t>(ii)];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      const std::size_t cell =
          static_cast<std::size_t>(type[i]) * size + static_cast<std::size_t>(type[j]);
      const int row = pair_row_[cell];
      if (row < 0 || (mask[j] & groupbit) == 0) continue;
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double radsum = radius[i] + radius[j];
      const std::size_t k = first + static_cast<std::size_t>(jj);
      if (rsq >= radsum * radsum || rsq == 0.0) {
        pair_slots_.release(k);
        continue;
      }
      const double dist = std::sqrt(rsq);
      const double inv = 1.0 / dist;
      const double n[3] = {d[0] * inv, d[1] * inv, d[2] * inv};
      const double rate =
          (v[i][0] - v[j][0]) * n[0] + (v[i][1] - v[j][1]) * n[1] + (v[i][2] - v[j][2]) * n[2];
      const auto lo = static_cast<std::uint64_t>(std::min(tag[i], tag[j]));
      const auto hi = static_cast<std::uint64_t>(std::max(tag[i], tag[j]));
      // [N], pushes j away from i
      const double force_n = pair_slots_.damping(k, (lo << 32U) | hi, radsum - dist, rate, [&] {
        return corlab::dem::onset_law(tables_[static_cast<std::size_t>(row)], rate,
                                      pair_estar_[cell], radius[i] * radius[j] / radsum);
      });
      for (int a = 0; a < 3; ++a) {
        f[i][a] -= force_n * n[a];
        if (newton || j < nlocal) f[j][a] += force_n * n[a];
      }
    }
  }
  if (rebuilt) pair_slots_.settle();
}

void FixCorlabEv::add_wall_forces(bool rebuilt) {
  const auto nlocal = static_cast<std::size_t>(atom->nlocal);
  if (rebuilt || wall_slots_.size() != nlocal * walls_.size()) {
    wall_slots_.rebuild(nlocal * walls_.size());
    rebuilt = true;
  }
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  const double* radius = atom->radius;
  const int* type = atom->type;
  const int* mask = atom->mask;
  // Wall by wall (slot w * nlocal + i): most atoms touch no wall, and a plane's test is one dot
  // product.
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const WallRows& wall = walls_[w];
    const bool plane = wall.wall.shape == corlab::dem::WallShape::plane;
    for (std::size_t i = 0; i < nlocal; ++i) {
      const std::size_t k = w * nlocal + i;
      const std::array<double, 3> xi{x[i][0], x[i][1], x[i][2]};
      if (plane && !(radius[i] > corlab::dem::plane_gap(wall.wall, xi))) {
        wall_slots_.release(k);
        continue;
      }
      const int row = wall.row[static_cast<std::size_t>(type[i])];
      const auto contact = corlab::dem::wall_contact(wall.wall, xi, radius[i]);
      if (!contact || row < 0 || (mask[i] & groupbit) == 0) {
        wall_slots_.release(k);
        continue;
      }
      const auto& n = contact->normal;
      const double rate = -(v[i][0] * n[0] + v[i][1] * n[1] + v[i][2] * n[2]);
      const auto key = static_cast<std::uint64_t>(atom->tag[i]) * walls_.size() + w;
      const double force_n = wall_slots_.damping(k, key, contact->overlap, rate, [&] {
        return corlab::dem::onset_law(tables_[static_cast<std::size_t>(row)], rate,
                                      wall.estar[static_cast<std::size_t>(type[i])], radius[i]);
      });
      for (std::size_t a = 0; a < 3; ++a) f[i][a] += force_n * n[a];
    }
  }
  if (rebuilt) wall_slots_.settle();
}

}  // namespace corlab::lammps
