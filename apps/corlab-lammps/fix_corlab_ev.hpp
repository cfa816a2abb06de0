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
/// speed at its first step, kept per contact on its MPI rank: in a slot per neighbour-list entry
/// (and per local atom and wall), carried by atom IDs to the new slots when LAMMPS rebuilds its
/// neighbour list, so that no step but a rebuild looks anything up. Forces are added in
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
  /// Per-contact memory laid out like the neighbour list (or local atoms x walls), indexed
  /// directly between rebuilds; at a rebuild the touching contacts carry over by key.
  class Slots {
   public:
    /// New layout of n slots; the contacts touching before move to `carried_`.
    void rebuild(std::size_t n);
    /// The damping [N] of the contact in slot k, touching now at `overlap` [m] and `rate`
    /// [m/s]: its law kept, carried over a rebuild, or onset() (a contact's first step).
    template <class Onset>
    double damping(
        std::size_t k, std::uint64_t key, double overlap, double rate, const Onset& onset);
    /// Slot k does not touch: its next touch starts a new contact.
    void release(std::size_t k) { active_[k] = 0; }
    /// After the first step of a layout: what did not carry over is gone.
    void settle() { carried_.clear(); }
    std::size_t size() const { return active_.size(); }

   private:
    struct Slot {
      corlab::dem::HysteresisLaw law;
      double coefficient = 0.0;  // law.damping_coefficient()
      std::uint64_t key = 0;
    };
    std::vector<std::uint8_t> active_;  // apart from the laws: every step reads each flag
    std::vector<Slot> slots_;
    std::unordered_map<std::uint64_t, Slot> carried_;
  };

  [[noreturn]] void fail(const std::string& message);
  double number(int narg, char** arg, int index, const char* what);
  int parse_table(int narg, char** arg, int index, int n, std::vector<double>& row);
  void add_pair_forces(bool rebuilt);
  void add_wall_forces(bool rebuilt);

  double v_min_ = 0.0;
  double v_max_ = 0.0;
  int ntypes_ = 0;
  std::vector<corlab::dem::UniformTable> tables_;
  std::vector<int> pair_row_;       // [(ntypes + 1) * ti + tj] -> tables_ index or -1
  std::vector<double> pair_estar_;  // E* [Pa] of each type pair
  std::vector<WallRows> walls_;
  Slots pair_slots_;
  Slots wall_slots_;
  std::vector<std::size_t> pair_offset_;  // first slot of each ilist entry
  const void* list_ = nullptr;            // the neighbour list the slots follow
  LAMMPS_NS::bigint ncalls_ = -1;         // its builds so far (Neighbor::ncalls)
};

}  // namespace corlab::lammps
