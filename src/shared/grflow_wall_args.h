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
   The arguments of fix grflow/wall and its fix_modify keywords, host-free
   (the walls: grflow_wall.h).  Numbers and errors go through a Host
   (grflow_host.h).
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_WALL_ARGS_H
#define LMP_GRFLOW_WALL_ARGS_H

#include "grflow_coeff_rules.h"
#include "grflow_host.h"
#include "grflow_wall.h"

#include <cstring>
#include <string>

namespace LAMMPS_NS {
namespace GRFLOW {

  /* ----------------------------------------------------------------------
     the fix command's arguments after "fix ID group grflow/wall": kn cn
     [coefficient keywords] then zlo z, zhi z, velocity_arm reduced|full,
     normal_force clipped|unclipped in any order.  Returns the index after
     the last one.
  ------------------------------------------------------------------------- */

  template <class Host>
  static int read_wall_args(FlatWalls &cell, int narg, char **arg, int first, Host &host)
  {
    typedef FlatWalls W;
    const std::string cmd = "fix grflow/wall";
    int iarg = read_coeff_args(cmd, narg, arg, first, true, cell.coeff_value, host);
    pack_coeffs(cell.coeff_value, cell.coeff);

    while (iarg < narg) {
      const std::string kw = arg[iarg];
      if (kw == "zlo" || kw == "zhi") {
        if (iarg + 2 > narg) {
          host.missing(FLERR, cmd + " " + kw);
          return narg;
        }
        W::Wall &w = cell.walls[kw == "zlo" ? W::LO : W::HI];
        w.active = 1;
        w.z = host.number(FLERR, arg[iarg + 1], cmd + " " + kw);
        iarg += 2;
      } else if (kw == "velocity_arm") {
        if (iarg + 2 > narg) {
          host.missing(FLERR, cmd + " velocity_arm");
          return narg;
        }
        cell.full_arm = read_velocity_arm(cmd, arg[iarg + 1], host);
        iarg += 2;
      } else if (kw == "normal_force") {
        if (iarg + 2 > narg) {
          host.missing(FLERR, cmd + " normal_force");
          return narg;
        }
        cell.coeff.normal_law = read_normal_force(cmd, arg[iarg + 1], host);
        iarg += 2;
      } else {
        if (coeff_index(kw) < NCOEFF || kw == "rolling" || kw == "torsion")
          host.fail(FLERR,
                    "Fix grflow/wall contact keyword " + kw +
                        " must come right after kn cn, before zlo, zhi, velocity_arm and "
                        "normal_force");
        else
          host.fail(FLERR, "Unknown " + cmd + " keyword: " + kw);
        return narg;
      }
    }
    if (!cell.walls[W::LO].active && !cell.walls[W::HI].active)
      host.fail(FLERR, "Fix grflow/wall needs a wall: zlo and/or zhi");
    else if (cell.both_walls() && cell.walls[W::HI].z <= cell.walls[W::LO].z)
      host.fail(FLERR,
                "Fix grflow/wall zhi " + host.text(cell.walls[W::HI].z) + " must be above zlo " +
                    host.text(cell.walls[W::LO].z));
    return iarg;
  }

  /* ----------------------------------------------------------------------
     fix_modify ID: a coefficient keyword and a value (the histories are
     kept), wall lo|hi vel vx vy vz, wall lo|hi z value.  Returns the
     number of arguments used, 0 if arg[0] is none of these.
  ------------------------------------------------------------------------- */

  template <class Host>
  static int modify_wall_param(FlatWalls &cell, int narg, char **arg, const char *id, Host &host)
  {
    typedef FlatWalls W;
    const std::string fm = std::string("fix_modify ") + id;
    const int k = coeff_index(arg[0]);
    if (k < NCOEFF) {
      if (narg < 2) {
        host.missing(FLERR, fm + " " + arg[0]);
        return 0;
      }
      double value[NCOEFF];
      for (int m = 0; m < NCOEFF; m++) value[m] = cell.coeff_value[m];
      value[k] = host.number(FLERR, arg[1], fm + " " + arg[0]);
      check_coeff_values(fm, value, host);
      cell.coeff_value[k] = value[k];
      pack_coeffs(cell.coeff_value, cell.coeff);
      return 2;
    }
    if (strcmp(arg[0], "wall") != 0) return 0;
    if (narg < 4) {
      host.missing(FLERR, "fix_modify grflow/wall wall");
      return 0;
    }
    int iw = W::NWALL;
    if (strcmp(arg[1], "lo") == 0)
      iw = W::LO;
    else if (strcmp(arg[1], "hi") == 0)
      iw = W::HI;
    else {
      host.fail(FLERR, fm + " wall: expected lo or hi, got " + arg[1]);
      return 0;
    }
    W::Wall &w = cell.walls[iw];
    if (!w.active) {
      host.fail(FLERR, fm + " wall " + arg[1] + ": this fix has no such wall");
      return 0;
    }
    if (strcmp(arg[2], "vel") == 0) {
      if (narg < 6) {
        host.missing(FLERR, "fix_modify grflow/wall wall vel");
        return 0;
      }
      for (int d = 0; d < 3; d++)
        w.v[d] = host.number(FLERR, arg[3 + d], fm + " wall " + arg[1] + " vel");
      return 6;
    }
    if (strcmp(arg[2], "z") == 0) {
      w.z = host.number(FLERR, arg[3], fm + " wall " + arg[1] + " z");
      if (cell.both_walls() && cell.walls[W::HI].z <= cell.walls[W::LO].z)
        host.fail(FLERR,
                  fm + ": zhi " + host.text(cell.walls[W::HI].z) + " must be above zlo " +
                      host.text(cell.walls[W::LO].z));
      return 4;
    }
    host.fail(FLERR, fm + " wall " + arg[1] + ": expected vel or z, got " + arg[2]);
    return 0;
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
