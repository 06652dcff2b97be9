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
#include "grflow_cycle_count.h"

namespace LAMMPS_NS {

class FixGRFLOWShear : public Fix {
 public:
  FixGRFLOWShear(class LAMMPS *, int, char **);
  ~FixGRFLOWShear() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void end_of_step() override;
  void reset_dt() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // output vector (0-based)
  // clang-format off
  enum {
    DIRECTION, REVERSALS, XWALL, GAMMA, TAU, PRESS, RU, P0, STEP_IL, TIME_IL, N_IL, N_EVENT,
    DONE, EVENT, NOUT
  };
  // clang-format on

 private:
  char *id_wall, *id_network;
  class FixGRFLOWWall *wall;
  class ComputeGRFLOWNetwork *network;
  int iglue, gluebit;
  std::string glue_name;
  double vx, tau_amp, ru_liq;
  int check_every;
  double stop_cycles_after_il, stop_cycles, stop_gamma;
  double dt;

  // protocol state (restart)
  int started, direction;
  bigint reversals, step_il;
  double p0;
  int await_zero;              // a reversal happened, tau has not crossed zero since
  GRFLOW::CycleCount count;    // N, and the time of initial liquefaction (grflow_cycle_count.h)

  // events and progress
  bigint event_step;
  int event_kind;
  int progress;
  double wall_start, wall_last;
  bigint step_last;

  // last check
  double tau, press, ru;

  void check(bool decide = true);
  void report();
  void drive_wall();
  double height() const;
  double sim_time() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
