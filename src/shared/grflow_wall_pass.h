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
    const double wzero[3] = {0.0, 0.0, 0.0};
    double **history = cell.history;
    double **contact = cell.contact;

    for (int iw = 0; iw < W::NWALL; iw++)
      cell.walls[iw].force[0] = cell.walls[iw].force[1] = cell.walls[iw].force[2] = 0.0;
    cell.contact_step = step;
    cell.force_flag = 0;

    // An atom farther than its radius from every wall touches none; for
    // it only its arms are cleared, and a wall's history only if the atom
    // touched that wall on the step before (the contact just ended).  Most
    // atoms are such atoms on most steps.
    //
    // Between neighbor list builds only the atoms of the near list can
    // touch a wall (grflow_wall_near.h); the others were cleared when it
    // was made.
    const bool lo_on = cell.walls[W::LO].active, hi_on = cell.walls[W::HI].active;
    const double zlo = cell.walls[W::LO].z, zhi = cell.walls[W::HI].z;
    const bool use_near = near.update(cell, s, ncalls, skin);
    const int nloop = use_near ? near.size() : s.nlocal;
    for (int ii = 0; ii < nloop; ii++) {
      const int i = use_near ? near[ii] : ii;
      double *ci = contact[i];
      const double rad = s.radius[i];
      const double z = s.x[i][2];
      if (!(s.mask[i] & s.groupbit) || ((!lo_on || z - zlo >= rad) && (!hi_on || zhi - z >= rad))) {
        for (int iw = 0; iw < W::NWALL; iw++)
          if (ci[W::REC_SIZE * iw] != 0.0) {
            ci[W::REC_SIZE * iw] = 0.0;
            for (int k = 0; k < HIST_SIZE; k++) history[i][iw * HIST_SIZE + k] = 0.0;
          }
        continue;
      }

      for (int iw = 0; iw < W::NWALL; iw++) {
        W::Wall &w = cell.walls[iw];
        if (!w.active) continue;
        double *hist = &history[i][iw * HIST_SIZE];
        const bool was_touching = (ci[W::REC_SIZE * iw] != 0.0);
        ci[W::REC_SIZE * iw] = 0.0;
        const double sign = W::normal_sign(iw);
        const double gap = sign * (z - w.z);    // centre to wall, along n
        if (gap <= 0.0) {
          cross_wall = iw;
          return i;
        }
        if (gap >= rad) {
          if (was_touching)
            for (int k = 0; k < HIST_SIZE; k++) hist[k] = 0.0;
          continue;
        }

        ContactGeometry g;
        wall_geometry(gap, rad, sign, cell.full_arm != 0, g);
        const double *v = s.v[i];
        const double vrel[3] = {v[0] - w.v[0], v[1] - w.v[1], v[2] - w.v[2]};
        ContactForces out;
        contact_forces(cell.coeff, g, vrel, s.omega[i], wzero, cell.dt, update_history, hist, out);

        for (int k = 0; k < 3; k++) {
          s.f[i][k] += out.f[k];
          s.torque[i][k] += out.torque_i[k];
          w.force[k] -= out.f[k];
        }
        if (out.fn > 0.0) {
          ci[W::REC_SIZE * iw + W::REC_ARM] = g.arm_i;
          for (int k = 0; k < 3; k++) ci[W::REC_SIZE * iw + W::REC_FORCE + k] = out.f[k];
        } else {
          ci[W::REC_SIZE * iw + W::REC_ARM] = -1.0;
        }

        // virial of the contact, branch vector from the contact point to
        // the centre: l = arm n; symmetrized, as the 6-component virial is
        if (virial) {
          const double l = g.arm_i * sign;
          double vir[6];
          vir[0] = vir[1] = vir[3] = 0.0;
          vir[2] = l * out.f[2];
          vir[4] = 0.5 * l * out.f[0];
          vir[5] = 0.5 * l * out.f[1];
          tally(i, vir);
        }
      }
    }
    return -1;
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
