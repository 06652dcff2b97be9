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

/* ----------------------------------------------------------------------
   Contributing authors: GRFLOW developers

   A drag on the velocities (and spins) of a group: fix langevin with
   zero temperature, without its random numbers, and with a KOKKOS
   variant that has the spin term (fix langevin/kk has no omega).  The
   formulas are GRFLOW::Drag's (grflow_drag.h); this class loops.
------------------------------------------------------------------------- */

#include "fix_grflow_drag.h"

#include "grflow_drag.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "respa.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixGRFLOWDrag::FixGRFLOWDrag(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), t_damp(0.0), spin(0), ilevel_respa(0)
{
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix grflow/drag", error);
  t_damp = utils::numeric(FLERR, arg[3], false, lmp);
  if (!(t_damp > 0.0))
    error->all(FLERR, "Fix grflow/drag {}: t_damp = {} must be > 0", id, arg[3]);
  int iarg = 4;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "omega") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix grflow/drag omega", error);
      spin = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
    } else
      error->all(FLERR, "Fix grflow/drag {}: unknown keyword '{}'", id, arg[iarg]);
  }
  if (!atom->rmass_flag)
    error->all(FLERR, "Fix grflow/drag {} needs per-atom masses (atom_style sphere)", id);
  if (spin && !(atom->omega_flag && atom->torque_flag && atom->radius_flag))
    error->all(FLERR,
               "Fix grflow/drag {} omega yes needs the atom attributes radius, omega and torque "
               "(atom_style sphere)",
               id);
  dynamic_group_allow = 1;
  respa_level_support = 1;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWDrag::setmask()
{
  return POST_FORCE | POST_FORCE_RESPA;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWDrag::init()
{
  // a torque drag needs a moment of inertia: as fix langevin, no point
  // particle in the group
  if (spin) {
    const double *radius = atom->radius;
    const int *mask = atom->mask;
    int flag = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((mask[i] & groupbit) && radius[i] == 0.0) flag = 1;
    int flagall = 0;
    MPI_Allreduce(&flag, &flagall, 1, MPI_INT, MPI_MAX, world);
    if (flagall)
      error->all(FLERR, "Fix grflow/drag {} omega yes: group {} has particles of radius 0", id,
                 group->names[igroup]);
  }
  if (utils::strmatch(update->integrate_style, "^respa")) {
    const int max_respa = (dynamic_cast<Respa *>(update->integrate))->nlevels - 1;
    ilevel_respa = (respa_level >= 0) ? MIN(respa_level, max_respa) : max_respa;
  }
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWDrag::setup(int vflag)
{
  if (utils::strmatch(update->integrate_style, "^verlet"))
    post_force(vflag);
  else {
    auto respa = dynamic_cast<Respa *>(update->integrate);
    respa->copy_flevel_f(ilevel_respa);
    post_force_respa(vflag, ilevel_respa, 0);
    respa->copy_f_flevel(ilevel_respa);
  }
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWDrag::post_force(int /*vflag*/)
{
  const GRFLOW::Drag drag{t_damp, force->ftm2v};
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  double **v = atom->v;
  double **f = atom->f;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) drag.apply(rmass[i], v[i], f[i]);
  if (!spin) return;
  const double *radius = atom->radius;
  double **omega = atom->omega;
  double **torque = atom->torque;
  for (int i = 0; i < nlocal; i++)
    if ((mask[i] & groupbit) && radius[i] > 0.0)
      drag.apply_spin(rmass[i], radius[i], omega[i], torque[i]);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWDrag::post_force_respa(int vflag, int ilevel, int /*iloop*/)
{
  if (ilevel == ilevel_respa) post_force(vflag);
}
