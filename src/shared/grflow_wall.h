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

/* ----------------------------------------------------------------------
   The walls of fix grflow/wall (doc/fix_grflow_wall.rst), host-free: flat
   walls normal to z, their state and motion, the layouts of their
   per-atom data and outputs.  The other jobs of the fix live beside it:
     grflow_wall_args.h   its arguments and fix_modify keywords
     grflow_wall_near.h   the near list (atoms that may touch a wall)
     grflow_wall_pass.h   the contact pass (the kernel of grflow_contact.h)
     grflow_wall_state.h  output vector, restart data, per-atom packing
   and the fix (src/GRFLOW/fix_grflow_wall.cpp) holds a FlatWalls.

   WallContacts is what a fix with wall contacts offers other commands
   (compute grflow/network) through Fix::extract("grflow/wall_contacts").

   Header only, no host types: the hosts give plain arrays (x, v, f, ...)
   and allocate the per-atom arrays.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_WALL_H
#define LMP_GRFLOW_WALL_H

#include "grflow_coeff_rules.h"    // pack_coeffs
#include "grflow_contact.h"

#include <cstdint>

namespace LAMMPS_NS {
namespace GRFLOW {

  /* ----------------------------------------------------------------------
     the particles' view that the walls need: the host's per-atom arrays
     of the owned atoms
  ------------------------------------------------------------------------- */

  struct WallSpheres {
    double **x, **v, **f, **omega, **torque;
    const double *radius;
    const int *mask;
    int groupbit;
    int nlocal;
  };

  /* ----------------------------------------------------------------------
     the contacts of the owned atoms with flat walls normal to z, as a fix
     that has them records them on each step (its per-atom array, one
     record of REC_SIZE columns per wall: the arm a - delta/2 of a
     force-bearing contact, <= 0 for none, then the force on the atom)
  ------------------------------------------------------------------------- */

  struct WallContacts {
    enum { REC_ARM = 0, REC_FORCE = 1, REC_SIZE = 4 };
    int nwall;                      // records per atom
    double normal[2];               // the z component of wall w's normal (+1 below, -1 above)
    const double *const *record;    // per owned atom: nwall records
    int64_t step;                   // the step of the records, -1 before the first
  };

  /* ----------------------------------------------------------------------
     the walls of one fix grflow/wall
  ------------------------------------------------------------------------- */

  class FlatWalls {
   public:
    enum { LO, HI, NWALL };

    // a flat wall normal to z: "lo" pushes up (+z), "hi" pushes down (-z)
    struct Wall {
      int active;
      double z;           // position
      double v[3];        // velocity
      double disp[2];     // accumulated x, y displacement
      double force[3];    // force of the particles on it, this step
    };

    // per atom: the kernel's history (HIST_SIZE values) per wall, and the
    // contact record per wall (WallContacts): the arm (a - delta/2) of a
    // force-bearing contact (f_n > 0), -1 for a touching one without force
    // (or, with the unclipped law, in tension: f_n <= 0) or one not known
    // (the atom came from another rank or a restart file), 0 for none;
    // then the force on the atom (3)
    enum { NHIST = NWALL * HIST_SIZE };
    enum {
      REC_ARM = WallContacts::REC_ARM,
      REC_FORCE = WallContacts::REC_FORCE,
      REC_SIZE = WallContacts::REC_SIZE,
      NCONTACT = NWALL * REC_SIZE
    };

    // the output vector (compute_vector, 0-based), per wall (lo, then hi):
    // force of the particles on it (3), position, x and y displacement
    // since the fix was defined
    enum { VEC_FX, VEC_FY, VEC_FZ, VEC_Z, VEC_DX, VEC_DY, VEC_PER_WALL };
    // clang-format off
    enum {
      LO_FX = LO * VEC_PER_WALL + VEC_FX, LO_FY = LO * VEC_PER_WALL + VEC_FY,
      LO_FZ = LO * VEC_PER_WALL + VEC_FZ, LO_Z = LO * VEC_PER_WALL + VEC_Z,
      LO_DX = LO * VEC_PER_WALL + VEC_DX, LO_DY = LO * VEC_PER_WALL + VEC_DY,
      HI_FX = HI * VEC_PER_WALL + VEC_FX, HI_FY = HI * VEC_PER_WALL + VEC_FY,
      HI_FZ = HI * VEC_PER_WALL + VEC_FZ, HI_Z = HI * VEC_PER_WALL + VEC_Z,
      HI_DX = HI * VEC_PER_WALL + VEC_DX, HI_DY = HI * VEC_PER_WALL + VEC_DY,
      NVECTOR = NWALL * VEC_PER_WALL
    };
    // clang-format on

    // restart data: global (the block of grflow_host.h) per wall active,
    // z, v (3), displacement (2), format RESTART_VERSION; per atom the
    // count, as other fixes read it, then the histories
    enum { RESTART_VERSION = 1, RESTART_PER_WALL = 7, NRESTART = NWALL * RESTART_PER_WALL };
    enum { NRESTART_ATOM = NHIST + 1 };

    FlatWalls() :
        full_arm(0), dt(0.0), force_flag(0), history(nullptr), contact(nullptr), contact_step(-1)
    {
      for (int w = 0; w < NWALL; w++) {
        Wall &wall = walls[w];
        wall.active = 0;
        wall.z = 0.0;
        wall.v[0] = wall.v[1] = wall.v[2] = 0.0;
        wall.disp[0] = wall.disp[1] = 0.0;
        wall.force[0] = wall.force[1] = wall.force[2] = 0.0;
        wall_force_all[w][0] = wall_force_all[w][1] = wall_force_all[w][2] = 0.0;
      }
      for (int k = 0; k < NCOEFF; k++) coeff_value[k] = 0.0;
      pack_coeffs(coeff_value, coeff);
    }

    const Wall &wall(int w) const { return walls[w]; }
    void set_velocity(int w, double vx, double vy, double vz)
    {
      walls[w].v[0] = vx;
      walls[w].v[1] = vy;
      walls[w].v[2] = vz;
    }
    // the height of the cell between the two walls
    double gap() const { return walls[HI].z - walls[LO].z; }

    // the normal force law of the walls (normal_force keyword)
    int normal_law() const { return coeff.normal_law; }

    // contact of atom i with wall w on this step: arm (a - delta/2; <= 0 if
    // no force-bearing contact) and force on the atom (set only where the
    // arm is > 0)
    double contact_arm(int i, int w) const { return contact[i][REC_SIZE * w + REC_ARM]; }
    const double *contact_force(int i, int w) const
    {
      return &contact[i][REC_SIZE * w + REC_FORCE];
    }
    static GRFLOW_INLINE double normal_sign(int w) { return w == LO ? 1.0 : -1.0; }
    // whether a centre at z reached or passed wall w at z_wall
    static GRFLOW_INLINE bool reached(int w, double z_wall, double z)
    {
      return normal_sign(w) * (z - z_wall) <= 0.0;
    }
    // the step of those contacts (-1 before the first run's setup)
    int64_t contacts_step() const { return contact_step; }

    // the contacts as other commands read them (WallContacts)
    const WallContacts &contacts()
    {
      offered.nwall = NWALL;
      for (int w = 0; w < NWALL; w++) offered.normal[w] = walls[w].active ? normal_sign(w) : 0.0;
      offered.record = contact;
      offered.step = contact_step;
      return offered;
    }

    bool both_walls() const { return walls[LO].active && walls[HI].active; }
    static const char *wall_name(int w) { return w == LO ? "zlo" : "zhi"; }

    /* --------------------------------------------------------------------
       the walls move with their velocities, as the atoms move (initial
       integration); false if the top wall has reached the bottom wall
    ------------------------------------------------------------------------- */

    bool move()
    {
      for (int iw = 0; iw < NWALL; iw++) {
        Wall &w = walls[iw];
        if (!w.active) continue;
        w.z += dt * w.v[2];
        w.disp[0] += dt * w.v[0];
        w.disp[1] += dt * w.v[1];
      }
      return !(both_walls() && walls[HI].z <= walls[LO].z);
    }

    // an owned atom of the group whose centre reached or passed a wall:
    // its index (w its wall), -1 if none
    int find_crossing(const WallSpheres &s, int &w) const
    {
      for (int iw = 0; iw < NWALL; iw++) {
        const Wall &wall = walls[iw];
        if (!wall.active) continue;
        for (int i = 0; i < s.nlocal; i++)
          if ((s.mask[i] & s.groupbit) && reached(iw, wall.z, s.x[i][2])) {
            w = iw;
            return i;
          }
      }
      return -1;
    }

    // the state, read and written by the other wall headers and the fix
    ContactCoeffs coeff;           // with the normal force law (normal_force keyword)
    double coeff_value[NCOEFF];    // as parsed, changed by fix_modify
    int full_arm;
    double dt;
    Wall walls[NWALL];
    double wall_force_all[NWALL][3];    // the walls' forces summed over processors
    int force_flag;                     // wall_force_all is current

    double **history;    // per atom: NHIST values (the host's array)
    double **contact;    // per atom: NCONTACT values (the host's array)
    int64_t contact_step;

   private:
    WallContacts offered;
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
