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
   The coefficients of the GRFLOW contact law, the rules for them, shared
   by every host (LAMMPS: pair_coeff of granular/grflow and fix
   grflow/wall; LIGGGHTS: fix property/global of model grflow): their
   names, the defaults of the paper's Table 1 for those not given, and
   the check that each is finite, kn > 0 and the others >= 0.  Header
   only, no host types: the hosts parse and report errors their own way.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_CONTACT_COEFFS_H
#define LMP_GRFLOW_CONTACT_COEFFS_H

#include <cmath>
#include <string>

namespace LAMMPS_NS {
namespace GRFLOW {

  // coefficients of one type pair, SI units

  struct ContactCoeffs {
    double kn, cn;         // normal stiffness (N/m), viscosity (kg/s)
    double kt, ct, mut;    // sliding stiffness, viscosity, friction coefficient
    double kr, cr, mur;    // rolling
    double ko, co, muo;    // torsion
  };

  // order of ContactCoeffs' members; also the keywords (kn, cn first)
  enum { KN, CN, KT, CT, MUT, KR, CR, MUR, KO, CO, MUO, NCOEFF };
  static constexpr const char *COEFF_NAMES[NCOEFF] = {"kn", "cn",  "kt", "ct", "mut", "kr",
                                                      "cr", "mur", "ko", "co", "muo"};

  // the index of a coefficient's name, NCOEFF if it is none
  static inline int coeff_index(const std::string &name)
  {
    int k = 0;
    while (k < NCOEFF && name != COEFF_NAMES[k]) k++;
    return k;
  }

  // all coefficients from kn and cn with the ratios of the paper's Table 1
  static inline void default_coeffs(double kn, double cn, double *value)
  {
    value[KN] = kn;
    value[CN] = cn;
    value[KT] = 0.8 * kn;
    value[CT] = 0.2 * cn;
    value[MUT] = 0.5;
    value[KR] = 0.1 * kn;
    value[CR] = 0.05 * cn;
    value[MUR] = 0.1;
    value[KO] = 0.1 * kn;
    value[CO] = 0.05 * cn;
    value[MUO] = 0.1;
  }

  // "rolling off" / "torsion off": the mode's stiffness, viscosity and
  // friction coefficient are zero
  static inline void mode_off(int first, double *value)
  {
    for (int m = first; m < first + 3; m++) value[m] = 0.0;
  }

  // the first coefficient that breaks a rule (NCOEFF if none) and the rule
  // it breaks: "must be finite", "must be > 0" (kn), "must be >= 0"
  static inline int bad_coeff(const double *value, const char **rule)
  {
    for (int k = 0; k < NCOEFF; k++)
      if (!std::isfinite(value[k])) {
        *rule = "must be finite";
        return k;
      }
    if (!(value[KN] > 0.0)) {
      *rule = "must be > 0";
      return KN;
    }
    for (int k = 1; k < NCOEFF; k++)
      if (value[k] < 0.0) {
        *rule = "must be >= 0";
        return k;
      }
    *rule = "";
    return NCOEFF;
  }

  static inline void pack_coeffs(const double *value, ContactCoeffs &c)
  {
    c.kn = value[KN];
    c.cn = value[CN];
    c.kt = value[KT];
    c.ct = value[CT];
    c.mut = value[MUT];
    c.kr = value[KR];
    c.cr = value[CR];
    c.mur = value[MUR];
    c.ko = value[KO];
    c.co = value[CO];
    c.muo = value[MUO];
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
