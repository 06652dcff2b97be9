/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: fix grflow/shear, stress-controlled cyclic
   simple shear at constant height (doc/fix_grflow_shear.rst).

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).

   The same command, outputs and rule as in LAMMPS: the rule, the events,
   the cycle count, the outputs and the restart values are those of the
   host-free grflow_shear_rule.h; this class is the LIGGGHTS glue (the
   compute grflow/network read, the fix grflow/wall driven, the glued
   layer's atoms, errors and the progress lines).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(grflow/shear,FixGRFLOWShear)
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_SHEAR_H
#define LMP_FIX_GRFLOW_SHEAR_H

#include "fix.h"
#include "grflow_shear_rule.h"

namespace LAMMPS_NS {

// the positions of the output vector: FixGRFLOWShear::DIRECTION, ... EVENT
// (GRFLOW::ShearLayout, as in the LAMMPS build)
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

  void read_network(bool decide);
  void move_wall();
};

}    // namespace LAMMPS_NS

#endif
#endif
