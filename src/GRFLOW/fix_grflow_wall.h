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

namespace LAMMPS_NS {
namespace GRFLOW {
  class FlatWalls;
  class WallNearList;
}    // namespace GRFLOW

class FixGRFLOWWall : public Fix {
 public:
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
  void *extract(const char *, int &) override;

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

  // the walls, for the fixes that drive them (fix grflow/shear, fix
  // grflow/compress): GRFLOW::FlatWalls, grflow_wall.h
  GRFLOW::FlatWalls &cell() { return *walls; }

  // the fix grflow/wall with ID id that has both walls, for another
  // command (caller, e.g. "Fix grflow/shear"); an error otherwise
  static FixGRFLOWWall *find_cell(class LAMMPS *lmp, const std::string &caller,
                                  const std::string &id);

 protected:
  GRFLOW::FlatWalls *walls;      // the walls, their contacts and histories
  GRFLOW::WallNearList *near;    // atoms that may touch a wall

  void crossed(int, int);

 private:
  void check_box();
};

}    // namespace LAMMPS_NS

#endif
#endif
