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
   The drag of fix grflow/drag (doc/fix_grflow_drag.rst), for one particle
   of mass m and radius r:

     F += -m v / t_damp                        (every particle of the group)
     T += -(10/3) I omega / t_damp,  I = 2/5 m r^2    (with omega yes, r > 0)

   in LAMMPS's units (ftm2v converts force * time / mass to velocity).
   It is the deterministic part of LAMMPS's fix langevin with omega yes,
   whose random part vanishes at zero temperature; the factor 10/3 is fix
   langevin's for the rotation of a sphere.  The factors are formed in
   fix langevin's order of operations, so that the two fixes give the same
   bits.  Host-free: the plain fix and its KOKKOS variant call the same
   functions.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_DRAG_H
#define LMP_GRFLOW_DRAG_H

#include "grflow_host.h"

namespace LAMMPS_NS {
namespace GRFLOW {

  struct Drag {
    double t_damp = 0.0;    // time constant (time units)
    double ftm2v = 1.0;     // force->ftm2v of the host

    // gamma of F += gamma v
    GRFLOW_FUNCTION double force_factor(double m) const { return -m / t_damp / ftm2v; }

    // gamma of T += gamma omega, for a sphere of radius r
    GRFLOW_FUNCTION double torque_factor(double m, double r) const
    {
      const double inertia = 0.4 * r * r * m;
      return -(10.0 / 3.0) * inertia / t_damp / ftm2v;
    }

    // one particle: its force (and with spin its torque) gets the drag
    GRFLOW_FUNCTION void apply(double m, const double *v, double *f) const
    {
      const double g = force_factor(m);
      f[0] += g * v[0];
      f[1] += g * v[1];
      f[2] += g * v[2];
    }
    GRFLOW_FUNCTION void apply_spin(double m, double r, const double *omega, double *torque) const
    {
      const double g = torque_factor(m, r);
      torque[0] += g * omega[0];
      torque[1] += g * omega[1];
      torque[2] += g * omega[2];
    }
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
