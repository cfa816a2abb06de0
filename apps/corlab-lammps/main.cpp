// corlab-lammps: Debian's LAMMPS (liblammps0, 20220106) run as a library with corlab's fix style
// corlab/ev registered, for the lammps_compiled.in of `corlab dem`. Takes LAMMPS's own command
// line: `corlab-lammps -in in.file` (or `mpirun -np N corlab-lammps -in in.file`), as `lmp` does.
// SPDX-License-Identifier: BSD-3-Clause
#include <mpi.h>

#include "fix_corlab_ev.hpp"
#include "input.h"
#include "lammps.h"
#include "modify.h"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  {
    // Registered as LAMMPS's PLUGIN package registers a fix style (plugin.cpp), which Debian's
    // build leaves out: the creator goes into Modify's fix map before the input is read.
    LAMMPS_NS::LAMMPS lammps(argc, argv, MPI_COMM_WORLD);
    (*lammps.modify->fix_map)["corlab/ev"] = &corlab::lammps::FixCorlabEv::create;
    lammps.input->file();
  }
  MPI_Finalize();
  return 0;
}
