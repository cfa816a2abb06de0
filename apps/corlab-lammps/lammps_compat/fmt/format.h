// SPDX-License-Identifier: BSD-3-Clause
// Debian 12's liblammps-dev headers (20220106) include "fmt/format.h" from the fmt 7 that LAMMPS
// bundles (fmt::v7_lmp, not shipped) and name fmt::make_args_checked, which Debian's fmt 9 no
// longer has: every LAMMPS header then fails with "'make_args_checked' is not a member of 'fmt'".
// This shim, first on corlab-lammps's include path, takes fmt 9 and declares the name. Only the
// std::string overloads of Error::all and utils::logmesg may be called: the formatting templates
// would pass fmt 9 types to a library built with fmt 7, so instantiating one stops the build.
#pragma once
#include_next <fmt/format.h>

namespace fmt {
template <typename... Args, typename S>
format_args make_args_checked(const S&, const Args&...) {
  static_assert(sizeof...(Args) != sizeof...(Args),
                "corlab-lammps: call LAMMPS's Error/logmesg with one std::string");
  return {};
}
}  // namespace fmt
