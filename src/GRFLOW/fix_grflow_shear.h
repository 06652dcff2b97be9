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
FixStyle(grflow/shear,FixGRFLOWShear);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_SHEAR_H
#define LMP_FIX_GRFLOW_SHEAR_H

#include "fix.h"
#include "grflow_shear_rule.h"

namespace LAMMPS_NS {

// the positions of the output vector: FixGRFLOWShear::DIRECTION, ... EVENT
// (GRFLOW::ShearLayout, shared with the LIGGGHTS build); the rule itself
// is GRFLOW::ShearProtocol (grflow_shear_rule.h)
class FixGRFLOWShear : public Fix, public GRFLOW::ShearLayout {
 public:
  FixGRFLOWShear(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void end_of_step() override;
  void reset_dt() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // the compute grflow/network this fix reads, and p0 of its r_u: this fix
  // owns p0 (0 until shearing starts); the compute reads it
  const std::string &network_id() const { return settings.network_id; }
  double p0() const { return state.p0; }

 private:
  GRFLOW::ShearSettings settings;    // the arguments
  GRFLOW::ShearProtocol state;       // direction, reversals, N, ... (restart)
  GRFLOW::ShearProgress progress;    // the progress lines' clock
  class FixGRFLOWWall *wall;
  class ComputeGRFLOWNetwork *network;
  int iglue, gluebit;
  double dt;

  void check(bool decide = true);
  void drive_wall();
  double sim_time() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
