/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: fix grflow/wall, flat frictional walls normal
   to z with the GRFLOW contact law (doc/fix_grflow_wall.rst), the same
   command as in LAMMPS.

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).

   The walls, their contacts with the spheres, the argument rules, the
   output vector, the restart layout and the messages are host-free
   (GRFLOW::FlatWalls in grflow_wall.h, the code LAMMPS's fix grflow/wall
   runs); this class is the LIGGGHTS glue.  Its public interface is that
   of the LAMMPS class (other GRFLOW commands call it the same way).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(grflow/wall,FixGRFLOWWall)
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_WALL_H
#define LMP_FIX_GRFLOW_WALL_H

#include "fix.h"
#include "grflow_wall.h"

#include <string>

namespace LAMMPS_NS {

class FixGRFLOWWall : public Fix, public GRFLOW::FlatWalls {
 public:
  FixGRFLOWWall(class LAMMPS *, int, char **);
  ~FixGRFLOWWall();
  int setmask();
  void init();
  void setup(int);
  void initial_integrate(int);
  void pre_exchange();
  void post_force(int);
  void reset_dt();
  double compute_vector(int);
  int modify_param(int, char **);
  void write_restart(FILE *);
  void restart(char *);

  double memory_usage();
  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  int pack_restart(int, double *);
  void unpack_restart(int, int);
  int size_restart(int);
  int maxsize_restart();

  // the fix grflow/wall with ID id that has both walls, for another
  // command (caller, e.g. "Fix grflow/shear"); an error otherwise
  static FixGRFLOWWall *find_cell(class LAMMPS *lmp, const std::string &caller, const char *id);

 private:
  void crossed(int, int);
  void check_box();
  GRFLOW::WallSpheres spheres() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
