// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file fix_corlab_ev.hpp
/// LAMMPS fix style corlab/ev (registered by corlab-lammps): corlab's e(v) damping
/// (corlab/dem/ev_damping.hpp) added in C++ to an elastic Hertz `pair_style granular` and to the
/// walls named in its arguments, as the Python hook of lammps.in adds it. Written by `corlab dem`
/// into lammps_compiled.in:
///   fix ID GROUP corlab/ev speeds V_MIN V_MAX N
///       pair I J E* e_1 .. e_N ...                       (type pair I-J, E* [Pa], e at N speeds)
///       wall plane PX PY PZ NX NY NZ                     (a point [m], the normal to the
///       particles) wall cylinder AXIS C1 C2 R LO HI                 (AXIS 0|1|2, [m]; particles
///       inside) type T E* e_1 .. e_N ...                         (the last wall's contact with
///       type T)
/// The speeds are V_MIN + k (V_MAX - V_MIN)/(N - 1) [m/s]. A contact's v_in is its normal approach
/// speed at its first step, kept per contact (atom IDs) on its MPI rank. Forces are added in
/// pre_reverse: onto ghost atoms too when newton_pair is on (LAMMPS sums them into their owners),
/// as pair_style granular adds its own. Not counted in the virial (pressure).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "corlab/dem/contact_laws.hpp"
#include "corlab/dem/dem_walls.hpp"
#include "corlab/dem/uniform_table.hpp"
#include "fix.h"

namespace corlab::lammps {

class FixCorlabEv : public LAMMPS_NS::Fix {
 public:
  FixCorlabEv(LAMMPS_NS::LAMMPS* instance, int narg, char** arg);
  /// The creator LAMMPS's Modify::fix_map holds for "corlab/ev".
  static LAMMPS_NS::Fix* create(LAMMPS_NS::LAMMPS* instance, int narg, char** arg);

  int setmask() override;
  void init() override;
  void setup_pre_reverse(int eflag, int vflag) override;
  void pre_reverse(int eflag, int vflag) override;

 private:
  /// One wall: its geometry and, per atom type, the row in tables_ (-1: undamped) and E* [Pa].
  struct WallRows {
    corlab::dem::Wall wall;
    std::vector<int> row;
    std::vector<double> estar;
  };
  using Memory = std::unordered_map<std::uint64_t, corlab::dem::HysteresisLaw>;

  [[noreturn]] void fail(const std::string& message);
  double number(int narg, char** arg, int index, const char* what);
  int parse_table(int narg, char** arg, int index, int n, std::vector<double>& row);
  void add_pair_forces();
  void add_wall_forces();
  // The contact's law: kept from its first step (in `before`) or taken now.
  static const corlab::dem::HysteresisLaw& law_of(Memory& now,
                                                  const Memory& before,
                                                  std::uint64_t key,
                                                  const corlab::dem::UniformTable& chi,
                                                  double rate,
                                                  double estar,
                                                  double radius);

  double v_min_ = 0.0;
  double v_max_ = 0.0;
  int ntypes_ = 0;
  std::vector<corlab::dem::UniformTable> tables_;
  std::vector<int> pair_row_;       // [(ntypes + 1) * ti + tj] -> tables_ index or -1
  std::vector<double> pair_estar_;  // E* [Pa] of each type pair
  std::vector<WallRows> walls_;
  Memory pairs_now_, pairs_before_, walls_now_, walls_before_;
};

}  // namespace corlab::lammps
