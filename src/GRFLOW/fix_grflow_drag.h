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

#ifdef FIX_CLASS
// clang-format off
FixStyle(grflow/drag,FixGRFLOWDrag);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_DRAG_H
#define LMP_FIX_GRFLOW_DRAG_H

#include "fix.h"

namespace LAMMPS_NS {

// F += -m v / t_damp, and with omega yes T += -(10/3) I omega / t_damp
// (GRFLOW::Drag of grflow_drag.h): fix langevin at zero temperature
class FixGRFLOWDrag : public Fix {
 public:
  FixGRFLOWDrag(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void post_force_respa(int, int, int) override;

 protected:
  double t_damp;
  int spin;    // omega yes: the torque too
  int ilevel_respa;
};

}    // namespace LAMMPS_NS

#endif
#endif
