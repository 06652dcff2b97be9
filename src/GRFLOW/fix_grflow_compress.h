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
FixStyle(grflow/compress,FixGRFLOWCompress);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_COMPRESS_H
#define LMP_FIX_GRFLOW_COMPRESS_H

#include "fix.h"
#include "grflow_overshoot.h"

namespace LAMMPS_NS {

class FixGRFLOWCompress : public Fix {
 public:
  FixGRFLOWCompress(class LAMMPS *, int, char **);
  ~FixGRFLOWCompress() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  void reset_dt() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // output vector (0-based)
  // clang-format off
  enum {
    CONVERGED, SXX, SYY, SZZ, ERRMAX, KE, EEL, RATIO, RATE_X, RATE_Y, RATE_Z, VOLUME, VOID, LX, LY,
    HEIGHT, FACTOR_X, FACTOR_Y, FACTOR_Z, NOUT
  };
  // clang-format on

 private:
  char *id_wall, *id_network, *id_pe;
  char *elastic_var;    // equal-style variable giving the elastic energy, or null
  int ivar_elastic;
  class FixGRFLOWWall *wall;
  class ComputeGRFLOWNetwork *network;
  class Compute *pe;
  double p_target, rate_max, gain, tol, ke_ratio_max;
  int servo_every;
  double dt;
  double vsolid;

  // servo state (restart): strain rates of x, y and the wall gap
  double rate[3];
  int started;

  // overshoot damping (restart): per axis the gain factor, the error of
  // the last update and the number of undamped overshoots in a row
  GRFLOW::OvershootDamping damping[3];    // one per axis

  // outputs, measured on the last servo step or at setup
  double sigma[3], errmax, ke, eel;

  void measure();
  void servo();
  void schedule_energy(bigint step);
  void damp_overshoot(int, double);
  void drive_walls();
  void deform_box();
  double height() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
