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
   The near list of fix grflow/wall, host-free: the atoms of the group
   that may touch a wall (grflow_wall.h) before the next neighbor list
   build.  With "neigh_modify delay 0 every 1 check yes" every atom stays
   within skin/2 of where it was at the last build; the list is made
   again, on the step of each build (the host's count of builds, ncalls,
   changed) or when a wall has moved more than skin/2 since, with the
   atoms whose centre was then closer to an active wall than their radius
   plus 1.5 skins.  An atom left out is therefore farther from every wall
   than its radius plus skin/2 (a margin for round-off) until the list is
   made again: it cannot touch one, and its arms and histories were
   cleared (by the full pass of wall_contact_pass(), grflow_wall_pass.h,
   on the step the list is made).
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_WALL_NEAR_H
#define LMP_GRFLOW_WALL_NEAR_H

#include "grflow_wall.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace LAMMPS_NS {
namespace GRFLOW {

  class WallNearList {
   public:
    WallNearList() : allowed(false), nnear(0), made_ncalls(-1), made_nlocal(-1)
    {
      for (double &z : made_z) z = 0.0;
    }

    // at the start of a run: whether the host's neighbor settings allow
    // the list (builds checked on every step, the radii fixed); it is made
    // again on the first step
    void allow(int every, int delay, bool dist_check, bool build_once, double skin,
               bool radii_may_change)
    {
      allowed = (every == 1) && (delay == 0) && dist_check && !build_once && (skin > 0.0) &&
          !radii_may_change;
      made_ncalls = -1;
    }

    // true if the list is current for this step (the contact pass may
    // visit its atoms only); false on the steps it is made (the contact
    // pass then visits every atom), and always if not allowed
    bool update(const FlatWalls &cell, const WallSpheres &s, int64_t ncalls, double skin)
    {
      typedef FlatWalls W;
      if (!allowed) return false;
      const double half_skin = 0.5 * skin;
      bool fresh = (ncalls == made_ncalls) && (s.nlocal == made_nlocal);
      for (int iw = 0; iw < W::NWALL; iw++)
        if (cell.walls[iw].active && fabs(cell.walls[iw].z - made_z[iw]) > half_skin) fresh = false;
      if (fresh) return true;

      // make the list; this step's contact pass visits every atom
      if ((int) atoms.size() < s.nlocal) atoms.resize(s.nlocal);
      nnear = 0;
      const W::Wall &lo = cell.walls[W::LO], &hi = cell.walls[W::HI];
      for (int i = 0; i < s.nlocal; i++) {
        if (!(s.mask[i] & s.groupbit)) continue;
        const double reach = s.radius[i] + 1.5 * skin;
        const double z = s.x[i][2];
        if ((lo.active && z - lo.z < reach) || (hi.active && hi.z - z < reach)) atoms[nnear++] = i;
      }
      made_ncalls = ncalls;
      made_nlocal = s.nlocal;
      for (int iw = 0; iw < W::NWALL; iw++) made_z[iw] = cell.walls[iw].z;
      return false;
    }

    int size() const { return nnear; }
    int operator[](int k) const { return atoms[k]; }

   private:
    bool allowed;    // the host's settings allow the list (allow())
    std::vector<int> atoms;
    int nnear;
    int64_t made_ncalls;                // the host's count of builds when it was made
    int made_nlocal;                    // the number of owned atoms then
    double made_z[FlatWalls::NWALL];    // wall positions then
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
