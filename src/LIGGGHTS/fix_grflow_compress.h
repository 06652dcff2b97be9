/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: fix grflow/compress, isotropic compression of
   the bi-periodic cell by all six sides with a stress servo
   (doc/fix_grflow_compress.rst).

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).

   The same command, outputs and servo as in LAMMPS: the servo, its
   overshoot damping, the convergence test, the outputs and the restart
   values are those of the host-free grflow_servo.h; this class is the
   LIGGGHTS glue (the compute grflow/network read, the fix grflow/wall and
   the periodic box moved, the energies, sums over ranks, errors).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(grflow/compress,FixGRFLOWCompress)
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_COMPRESS_H
#define LMP_FIX_GRFLOW_COMPRESS_H

#include "fix.h"
#include "grflow_servo.h"

#include <string>

namespace LAMMPS_NS {

// the positions of the output vector: FixGRFLOWCompress::CONVERGED, ...
// FACTOR_Z (GRFLOW::CompressLayout, as in the LAMMPS build)
class FixGRFLOWCompress : public Fix, public GRFLOW::CompressLayout {
 public:
  FixGRFLOWCompress(class LAMMPS *, int, char **);
  ~FixGRFLOWCompress();
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  void reset_dt() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 private:
  GRFLOW::CompressSettings settings;    // the arguments
  GRFLOW::StressServo servo;            // rates, gain factors (restart), last measurements
  std::string id_pe;                    // the internal compute pe, "" with elastic
  int ivar_elastic;
  bool warned_energy;    // that LIGGGHTS's pair style gran tallies no energy
  class FixGRFLOWWall *wall;
  class ComputeGRFLOWNetwork *network;
  class Compute *pe;
  double dt;
  double vsolid;

  void read_state();
  void servo_update();
  void tally_energy_on(bigint step);
  void move_walls();
  void scale_box();
};

}    // namespace LAMMPS_NS

#endif
#endif
