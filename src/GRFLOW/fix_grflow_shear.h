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

namespace LAMMPS_NS {
namespace GRFLOW {
  struct ShearSettings;
  struct ShearProtocol;
  struct ShearProgress;
}    // namespace GRFLOW

// the positions of the output vector: GRFLOW::ShearLayout
// (grflow_shear_rule.h); the rule itself is GRFLOW::ShearProtocol
class FixGRFLOWShear : public Fix {
 public:
  FixGRFLOWShear(class LAMMPS *, int, char **);
  ~FixGRFLOWShear() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void end_of_step() override;
  void post_run() override;
  void reset_dt() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  int iglue, gluebit;
  double dt;

  // the glued layer moves with the top wall at velocity vw: velocities
  // and spins, and with step its positions by one time step (the KOKKOS
  // variant does it on the device)
  virtual void glue(double vw, bool step);

 private:
  GRFLOW::ShearSettings *settings;    // the arguments
  GRFLOW::ShearProtocol *state;       // direction, reversals, p0, N, ... (restart)
  GRFLOW::ShearProgress *progress;    // the progress lines' clock
  class FixGRFLOWWall *wall;
  class ComputeGRFLOWNetwork *network;

  void check(bool decide = true);
  void drive_wall();
  double sim_time() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
