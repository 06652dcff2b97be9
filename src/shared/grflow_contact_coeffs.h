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
   The coefficients of the GRFLOW contact law for one type pair, as the
   kernel (grflow_contact.h) reads them: a plain struct and the names of
   its members' positions, no include, no function, so that any header
   may hold them (a KOKKOS DualView of them) and device code may read
   them.  Their rules (names, the paper's Table 1 defaults, checks,
   reading from a command) are in grflow_coeff_rules.h.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_CONTACT_COEFFS_H
#define LMP_GRFLOW_CONTACT_COEFFS_H

namespace LAMMPS_NS {
namespace GRFLOW {

  // coefficients of one type pair, SI units

  struct ContactCoeffs {
    double kn, cn;         // normal stiffness (N/m), viscosity (kg/s)
    double kt, ct, mut;    // sliding stiffness, viscosity, friction coefficient
    double kr, cr, mur;    // rolling
    double ko, co, muo;    // torsion
    // the normal force law, not a coefficient (no keyword of pair_coeff):
    // NORMAL_CLIPPED, f_n = max(k_n delta - c_n v_n, 0), or
    // NORMAL_UNCLIPPED, f_n = k_n delta - c_n v_n, which may be negative;
    // the hosts' normal_force keyword (read_normal_force()) sets it
    int normal_law = 0;
  };

  // values of ContactCoeffs::normal_law; clipped is the default
  enum { NORMAL_CLIPPED = 0, NORMAL_UNCLIPPED = 1 };

  // order of ContactCoeffs' coefficient members; also the keywords (kn, cn first)
  enum { KN, CN, KT, CT, MUT, KR, CR, MUR, KO, CO, MUO, NCOEFF };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
