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
#include "grflow_coeffs.h"

namespace LAMMPS_NS {

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

  enum { LO, HI, NWALL };

  // the fix grflow/wall with ID id that has both walls, for another
  // command (caller, e.g. "Fix grflow/shear"); an error otherwise
  static FixGRFLOWWall *find_cell(class LAMMPS *lmp, const std::string &caller, const char *id);

  // a flat wall normal to z: "lo" pushes up (+z), "hi" pushes down (-z)
  struct Wall {
    int active;
    double z;           // position
    double v[3];        // velocity
    double disp[2];     // accumulated x, y displacement
    double force[3];    // force of the particles on the wall, this step
  };
  const Wall &wall(int w) const { return walls[w]; }
  void set_velocity(int w, double vx, double vy, double vz)
  {
    walls[w].v[0] = vx;
    walls[w].v[1] = vy;
    walls[w].v[2] = vz;
  }

  // contact of atom i with wall w on this step: arm (a - delta/2; <= 0 if
  // no force-bearing contact) and force on the atom (set only where the arm
  // is > 0); for compute grflow/network
  double contact_arm(int i, int w) const { return contact[i][4 * w]; }
  const double *contact_force(int i, int w) const { return &contact[i][4 * w + 1]; }
  double normal_sign(int w) const { return w == LO ? 1.0 : -1.0; }
  // the step of those contacts (-1 before the first run's setup)
  bigint contacts_step() const { return contact_step; }

 private:
  GRFLOW::ContactCoeffs coeff;
  double coeff_value[GRFLOW::NCOEFF];    // as parsed, changed by fix_modify
  int full_arm;
  double dt;
  Wall walls[NWALL];
  double wall_force_all[NWALL][3];
  int force_flag;

  double **history;    // per atom: 7 values per wall
  double **contact;    // per atom: arm, fx, fy, fz per wall (this step, see post_force())
  bigint contact_step;

  // atoms that may touch a wall until the next neighbor list build
  int *near;
  int nnear, maxnear;
  bool near_allowed;       // neighbor settings allow the near list
  bigint near_ncalls;      // neighbor->ncalls when it was made
  int near_nlocal;         // atom->nlocal then
  double near_z[NWALL];    // wall positions then
  bool update_near();
  [[noreturn]] void crossed(int, tagint, double);

  void mark_unknown(int);
};

}    // namespace LAMMPS_NS

#endif
#endif
