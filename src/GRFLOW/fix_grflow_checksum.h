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
FixStyle(grflow/checksum,FixGRFLOWChecksum);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_CHECKSUM_H
#define LMP_FIX_GRFLOW_CHECKSUM_H

#include "fix.h"

namespace LAMMPS_NS {

class FixGRFLOWChecksum : public Fix {
 public:
  FixGRFLOWChecksum(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void end_of_step() override;
  void post_run() override;

 private:
  bigint done;    // step of the last restart write given its checksum file
  void check();
};

}    // namespace LAMMPS_NS

#endif
#endif
