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
   The contact pass of fix grflow/wall, host-free: the contacts of the
   owned atoms with the walls (grflow_wall.h) on one step, through the
   kernel of grflow_contact.h with the wall as a sphere of infinite
   radius (a' = a_i; the wall does not spin).

   The contacts of one atom (wall_atom_apart(), wall_atom_release(),
   wall_atom_contact()) are GRFLOW_INLINE, as the kernel is: the host's
   loop, wall_contact_pass(), and the device kernel of fix grflow/wall/kk
   (src/KOKKOS) call the same functions, with the walls' state of the
   step in a WallPass of plain numbers.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_WALL_PASS_H
#define LMP_GRFLOW_WALL_PASS_H

#include "grflow_contact.h"
#include "grflow_wall.h"
#include "grflow_wall_near.h"

#include <cstdint>

namespace LAMMPS_NS {
namespace GRFLOW {

  /* ----------------------------------------------------------------------
     what the contacts of an atom need of the walls on one step: plain
     numbers, which a device kernel copies (FlatWalls holds host arrays)
  ------------------------------------------------------------------------- */

  struct WallPass {
    int active[FlatWalls::NWALL];
    double z[FlatWalls::NWALL];       // positions
    double v[FlatWalls::NWALL][3];    // velocities
    ContactCoeffs coeff;
    int full_arm;
    double dt;
    int update_history;    // springs advance (not while the host sets up a run)
  };

  static inline WallPass wall_pass(const FlatWalls &cell, bool update_history)
  {
    WallPass p;
    for (int iw = 0; iw < FlatWalls::NWALL; iw++) {
      const FlatWalls::Wall &w = cell.walls[iw];
      p.active[iw] = w.active;
      p.z[iw] = w.z;
      for (int k = 0; k < 3; k++) p.v[iw][k] = w.v[k];
    }
    p.coeff = cell.coeff;
    p.full_arm = cell.full_arm;
    p.dt = cell.dt;
    p.update_history = update_history ? 1 : 0;
    return p;
  }

  /* ----------------------------------------------------------------------
     the contacts of one atom with the walls, for any loop over atoms.
     hist: its NHIST history values, rec: its NCONTACT record values
     (FlatWalls), both rows of the per-atom arrays.
  ------------------------------------------------------------------------- */

  // an atom that touches no wall on this step: not in the group (in_group
  // false), or farther than its radius from every active wall.  Most atoms
  // are such atoms on most steps.
  static GRFLOW_INLINE bool wall_atom_apart(const WallPass &p, bool in_group, double z, double rad)
  {
    typedef FlatWalls W;
    return !in_group ||
        ((!p.active[W::LO] || z - p.z[W::LO] >= rad) &&
         (!p.active[W::HI] || p.z[W::HI] - z >= rad));
  }

  // such an atom: its arms are cleared, and a wall's history only if it
  // touched that wall on the step before (the contact just ended)
  static GRFLOW_INLINE void wall_atom_release(double *hist, double *rec)
  {
    typedef FlatWalls W;
    for (int iw = 0; iw < W::NWALL; iw++)
      if (rec[W::REC_SIZE * iw + W::REC_ARM] != 0.0) {
        rec[W::REC_SIZE * iw + W::REC_ARM] = 0.0;
        for (int k = 0; k < HIST_SIZE; k++) hist[iw * HIST_SIZE + k] = 0.0;
      }
  }

  // what wall_atom_contact() gives besides forces and torques
  struct WallAtomContact {
    int crossed;                      // -1, or the wall the centre reached or passed
    int tallied[FlatWalls::NWALL];    // wall w's contact has its virial in vir[w]
    double vir[FlatWalls::NWALL][6];
  };

  // the contacts of an atom that may touch a wall (not wall_atom_apart()),
  // centre height z, velocity v, spin omega, radius rad: the forces and
  // torques of the walls added to f and torque, their opposites to
  // wall_force[w] (the force on wall w), the records and histories of
  // each wall; if virial, the virial of each contact in out.  An atom whose
  // centre reached or passed a wall stops the loop over the walls with
  // out.crossed that wall: the host stops with an error.
  static GRFLOW_INLINE void wall_atom_contact(const WallPass &p, double z, const double *v,
                                              const double *omega, double rad, double *hist,
                                              double *rec, double *f, double *torque,
                                              double (*wall_force)[3], bool virial,
                                              WallAtomContact &out)
  {
    typedef FlatWalls W;
    const double wzero[3] = {0.0, 0.0, 0.0};
    out.crossed = -1;
    for (int iw = 0; iw < W::NWALL; iw++) out.tallied[iw] = 0;

    for (int iw = 0; iw < W::NWALL; iw++) {
      if (!p.active[iw]) continue;
      double *hw = &hist[iw * HIST_SIZE];
      double *rw = &rec[W::REC_SIZE * iw];
      const bool was_touching = (rw[W::REC_ARM] != 0.0);
      rw[W::REC_ARM] = 0.0;
      const double sign = W::normal_sign(iw);
      const double gap = sign * (z - p.z[iw]);    // centre to wall, along n
      if (gap <= 0.0) {
        out.crossed = iw;
        return;
      }
      if (gap >= rad) {
        if (was_touching)
          for (int k = 0; k < HIST_SIZE; k++) hw[k] = 0.0;
        continue;
      }

      ContactGeometry g;
      wall_geometry(gap, rad, sign, p.full_arm != 0, g);
      const double vrel[3] = {v[0] - p.v[iw][0], v[1] - p.v[iw][1], v[2] - p.v[iw][2]};
      ContactForces c;
      contact_forces(p.coeff, g, vrel, omega, wzero, p.dt, p.update_history != 0, hw, c);

      for (int k = 0; k < 3; k++) {
        f[k] += c.f[k];
        torque[k] += c.torque_i[k];
        wall_force[iw][k] -= c.f[k];
      }
      if (c.fn > 0.0) {
        rw[W::REC_ARM] = g.arm_i;
        for (int k = 0; k < 3; k++) rw[W::REC_FORCE + k] = c.f[k];
      } else {
        rw[W::REC_ARM] = -1.0;
      }

      // virial of the contact, branch vector from the contact point to
      // the centre: l = arm n; symmetrized, as the 6-component virial is
      if (virial) {
        const double l = g.arm_i * sign;
        double *vir = out.vir[iw];
        vir[0] = vir[1] = vir[3] = 0.0;
        vir[2] = l * c.f[2];
        vir[4] = 0.5 * l * c.f[0];
        vir[5] = 0.5 * l * c.f[1];
        out.tallied[iw] = 1;
      }
    }
  }

  /* ----------------------------------------------------------------------
     the contacts of the owned atoms with the walls on this step (the fix's
     post_force()): forces and torques added to f and torque, the walls'
     forces, the contact records and, if virial, tally(i, vir) with the
     contact's virial.  Springs advance only if update_history (not while
     the host sets up a run).  ncalls (the host's count of neighbor list
     builds) and skin are for the near list.  Returns -1, or the index of
     an atom whose centre reached or passed a wall (cross_wall: that
     wall): the host stops with an error.
  ------------------------------------------------------------------------- */

  template <class Tally>
  static int wall_contact_pass(FlatWalls &cell, WallNearList &near, const WallSpheres &s,
                               int64_t step, bool update_history, int64_t ncalls, double skin,
                               bool virial, Tally &tally, int &cross_wall)
  {
    typedef FlatWalls W;
    const WallPass p = wall_pass(cell, update_history);
    double wall_force[W::NWALL][3];
    for (int iw = 0; iw < W::NWALL; iw++)
      wall_force[iw][0] = wall_force[iw][1] = wall_force[iw][2] = 0.0;
    cell.contact_step = step;
    cell.force_flag = 0;

    // Between neighbor list builds only the atoms of the near list can
    // touch a wall (grflow_wall_near.h); the others were cleared when it
    // was made.
    const bool use_near = near.update(cell, s, ncalls, skin);
    const int nloop = use_near ? near.size() : s.nlocal;
    int crossing = -1;
    for (int ii = 0; ii < nloop; ii++) {
      const int i = use_near ? near[ii] : ii;
      const double z = s.x[i][2], rad = s.radius[i];
      if (wall_atom_apart(p, (s.mask[i] & s.groupbit) != 0, z, rad)) {
        wall_atom_release(cell.history[i], cell.contact[i]);
        continue;
      }
      WallAtomContact out;
      wall_atom_contact(p, z, s.v[i], s.omega[i], rad, cell.history[i], cell.contact[i], s.f[i],
                        s.torque[i], wall_force, virial, out);
      for (int iw = 0; iw < W::NWALL; iw++)
        if (out.tallied[iw]) tally(i, out.vir[iw]);
      if (out.crossed >= 0) {
        cross_wall = out.crossed;
        crossing = i;
        break;
      }
    }
    for (int iw = 0; iw < W::NWALL; iw++)
      for (int k = 0; k < 3; k++) cell.walls[iw].force[k] = wall_force[iw][k];
    return crossing;
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
