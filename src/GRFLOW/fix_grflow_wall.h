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
FixStyle(grflow/wall,FixGRFLOWWall);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_WALL_H
#define LMP_FIX_GRFLOW_WALL_H

#include "fix.h"
#include "grflow_wall.h"

namespace LAMMPS_NS {

// the LAMMPS glue of fix grflow/wall; the walls, their contacts and the
// public interface used by other commands (wall(), set_velocity(),
// contact_arm(), contact_force(), normal_sign(), contacts_step(), LO, HI,
// NWALL, Wall) are GRFLOW::FlatWalls, shared with LIGGGHTS
class FixGRFLOWWall : public Fix, public GRFLOW::FlatWalls {
 public:
  // the positions of the output vector (0-based, NVECTOR of them): the
  // entries GRFLOW::FlatWalls::VEC_FX ... VEC_DY of the lower wall, then
  // of the upper one
  // clang-format off
  enum {
    LO_FX = LO * VEC_PER_WALL + VEC_FX, LO_FY = LO * VEC_PER_WALL + VEC_FY,
    LO_FZ = LO * VEC_PER_WALL + VEC_FZ, LO_Z = LO * VEC_PER_WALL + VEC_Z,
    LO_DX = LO * VEC_PER_WALL + VEC_DX, LO_DY = LO * VEC_PER_WALL + VEC_DY,
    HI_FX = HI * VEC_PER_WALL + VEC_FX, HI_FY = HI * VEC_PER_WALL + VEC_FY,
    HI_FZ = HI * VEC_PER_WALL + VEC_FZ, HI_Z = HI * VEC_PER_WALL + VEC_Z,
    HI_DX = HI * VEC_PER_WALL + VEC_DX, HI_DY = HI * VEC_PER_WALL + VEC_DY
  };
  // clang-format on

  FixGRFLOWWall(class LAMMPS *, int, char **);
  ~FixGRFLOWWall() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void pre_exchange() override;
  void post_force(int) override;
  void reset_dt() override;
  double compute_vector(int) override;
  int modify_param(int, char **) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  // the fix grflow/wall with ID id that has both walls, for another
  // command (caller, e.g. "Fix grflow/shear"); an error otherwise
  static FixGRFLOWWall *find_cell(class LAMMPS *lmp, const std::string &caller, const char *id);

 private:
  [[noreturn]] void crossed(int, int);
  void check_box();
  GRFLOW::WallSpheres spheres() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
