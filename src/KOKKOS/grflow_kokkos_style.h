/* -*- c++ -*- ----------------------------------------------------------
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

   What GRFLOW's KOKKOS fixes share beside their plain fixes: the style
   name of the plain fix, taken once made.  LAMMPS matches per-atom
   restart data to a fix by ID and style, and global restart data by the
   style without its suffix only when -sf kk added the suffix; with the
   plain name a restart file goes between the two styles whichever way
   the variant was chosen.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_KOKKOS_STYLE_H
#define LMP_GRFLOW_KOKKOS_STYLE_H

#include "comm.h"
#include "fix.h"
#include "lammps.h"
#include "utils.h"

namespace LAMMPS_NS {
namespace GRFLOW {

  // fix (a KOKKOS variant, style e.g. grflow/shear/kk) takes the style
  // name plain and says so in the log, with what it runs on the device
  inline void take_plain_style(LAMMPS *lmp, Fix *fix, const char *plain, const char *what)
  {
    if (lmp->comm->me == 0)
      utils::logmesg(lmp, "Fix {} {}: {} on the Kokkos {}, as style {}\n", fix->style, fix->id,
                     what, (fix->execution_space == Device) ? "device" : "host", plain);
    delete[] fix->style;
    fix->style = utils::strdup(plain);
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
