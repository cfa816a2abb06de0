// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file lammps_hook.hpp
/// The two e(v) hooks of the LAMMPS fragments: the Python one of lammps.in (fix python/invoke)
/// and the compiled one of lammps_compiled.in (fix corlab/ev of corlab-lammps). Both add
/// corlab/dem/ev_damping.hpp's damping with the same 64-row table (detail::kHookTableRows).
#include <string>
#include <vector>

#include "corlab/dem/dem_export.hpp"

namespace corlab::dem::detail {

/// The pair of particle type `t` with wall material `m` (nullptr: none, e.g. no wall material).
const PairCalibration* wall_pair(const std::vector<PairCalibration>& pairs, int t, int m);

/// lammps.in's hook: `python corlab_ev_force here """..."""` and its fix python/invoke.
std::string lammps_python_hook(const ExportSpec& spec, const std::vector<PairCalibration>& pairs);

/// lammps_compiled.in's `fix corlab_ev all corlab/ev speeds ... pair ... wall ... type ...`:
/// e at the table speeds for each e(v) pair of types and each wall's contact with each type.
std::string lammps_compiled_fix(const ExportSpec& spec, const std::vector<PairCalibration>& pairs);

}  // namespace corlab::dem::detail
