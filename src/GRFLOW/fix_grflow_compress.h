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

namespace LAMMPS_NS {
namespace GRFLOW {
  struct CompressSettings;
  struct StressServo;
}    // namespace GRFLOW

// the positions of the output vector: GRFLOW::CompressLayout
// (grflow_servo.h); the servo itself is GRFLOW::StressServo
class FixGRFLOWCompress : public Fix {
 public:
  FixGRFLOWCompress(class LAMMPS *, int, char **);
  ~FixGRFLOWCompress() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  void post_run() override;
  int modify_param(int, char **) override;
  void reset_dt() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  double dt;

  // this processor's sum of kinetic_term() over the group, and the
  // group's positions to and from lamda coordinates around the box change
  // (the KOKKOS variant does both on the device)
  virtual double kinetic_local();
  virtual void remap_group(bool to_lamda);

 private:
  GRFLOW::CompressSettings *settings;    // the arguments
  GRFLOW::StressServo *servo;            // rates, gain factors (restart), last measurements
  std::string id_pe;                     // the internal compute pe, "" with elastic
  int ivar_elastic;
  bool warned_energy;    // that the pair style tallies no energy (once)
  class FixGRFLOWWall *wall;
  class ComputeGRFLOWNetwork *network;
  class Compute *pe;
  double vsolid;

  void measure();
  void update_servo();
  void schedule_energy(bigint step);
  void drive_walls();
  void deform_box();
};

}    // namespace LAMMPS_NS

#endif
#endif
