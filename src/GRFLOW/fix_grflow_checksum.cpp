// clang-format off
/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */
// clang-format on

/* ----------------------------------------------------------------------
   Contributing authors: GRFLOW developers

   A checksum file FILE.cksum (grflow_checksum.h: the format of POSIX
   cksum) for every restart file FILE the restart command writes, made
   once the file is complete: on the next step, or at the end of the run
   when the file was written on its last step.  A file that a kill cut
   short has no checksum file; one damaged later no longer matches its
   checksum.  A resume can so tell a usable restart file from a damaged
   one without reading it.
------------------------------------------------------------------------- */

#include "fix_grflow_checksum.h"

#include "grflow_checksum.h"

#include "atom_masks.h"
#include "comm.h"
#include "error.h"
#include "output.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixGRFLOWChecksum::FixGRFLOWChecksum(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  if (narg > 3)
    error->all(FLERR, "Illegal fix grflow/checksum command: unexpected argument '{}'", arg[3]);
  nevery = 1;
  // it reads no atom data: with the KOKKOS package nothing is copied to
  // the host for it on every step
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
  // a restart write before this fix existed is not its business
  done = output->last_restart;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWChecksum::setmask()
{
  return END_OF_STEP | POST_RUN;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWChecksum::init()
{
  if (!output->restart_flag) {
    if (comm->me == 0)
      error->warning(FLERR, "Fix grflow/checksum {}: no restart command, no restart file to check",
                     id);
    return;
  }
  if ((output->restart_flag_single && strchr(output->restart1, '%')) ||
      (output->restart_flag_double && strchr(output->restart2a, '%')))
    error->all(FLERR,
               "Fix grflow/checksum {}: restart files written by several processors ('%' in the "
               "restart file name) are not supported",
               id);
  if ((output->restart_flag_single && output->restart_every_single == 0) ||
      (output->restart_flag_double && output->restart_every_double == 0))
    error->all(FLERR,
               "Fix grflow/checksum {}: restart files at steps set by a variable are not supported",
               id);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWChecksum::end_of_step()
{
  check();
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWChecksum::post_run()
{
  check();
}

/* ----------------------------------------------------------------------
   the restart command wrote on step last_restart (Output::write(), after
   every fix of that step): the files of that step are complete now
------------------------------------------------------------------------- */

void FixGRFLOWChecksum::check()
{
  const bigint step = output->last_restart;
  if (step < 0 || step == done || !output->restart_flag) return;
  done = step;

  std::string message;
  if (comm->me == 0) {
    if (output->restart_flag_single && step % output->restart_every_single == 0)
      message = GRFLOW::write_checksum_file(GRFLOW::restart_file_of_step(output->restart1, step));
    // the pair of files the restart command alternates between: the one
    // just written is the one before the toggle
    if (message.empty() && output->restart_flag_double && step % output->restart_every_double == 0)
      message = GRFLOW::write_checksum_file(output->restart_toggle ? output->restart2a
                                                                   : output->restart2b);
  }
  int failed = message.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, world);
  // error->all() prints rank 0's message, the one that knows what failed
  if (failed) error->all(FLERR, "Fix grflow/checksum {}: {}", id, message);
}
