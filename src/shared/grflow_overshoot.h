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
   The overshoot damping of fix grflow/compress, for one axis: a
   proportional servo updated every N steps overshoots the target when the
   stress responds to one interval's motion by more than the error, and at
   twice the error it locks into a cycle of two updates that never
   converges.  After NOVERSHOOT updates in a row that each land on the
   other side of the target with more than half the previous error (and
   beyond tol), the axis's gain factor is halved, down to FACTOR_MIN.  A
   servo that converges without overshooting, or whose overshoots shrink
   by more than half each time, keeps factor 1.  Header only, no LAMMPS
   types.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_OVERSHOOT_H
#define LMP_GRFLOW_OVERSHOOT_H

#include <cmath>

namespace LAMMPS_NS {
namespace GRFLOW {

  struct OvershootDamping {
    static constexpr int NOVERSHOOT = 4;
    static constexpr double FACTOR_MIN = 1.0 / 1024.0;

    double factor = 1.0;      // multiplies the servo's gain
    double err_last = 0.0;    // relative error of the last update
    int count = 0;            // overshoots in a row so far

    // one servo update with relative error err = (sigma - target)/target;
    // true when it halved the factor
    bool update(double err, double tol)
    {
      const bool overshoot = std::fabs(err) > tol && err * err_last < 0.0 &&
          std::fabs(err) > 0.5 * std::fabs(err_last);
      count = overshoot ? count + 1 : 0;
      err_last = err;
      if (count < NOVERSHOOT) return false;
      count = 0;
      if (factor <= FACTOR_MIN) return false;
      factor *= 0.5;
      return true;
    }
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
