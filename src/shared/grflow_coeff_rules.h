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
   The rules for the coefficients of the GRFLOW contact law
   (grflow_contact_coeffs.h), shared by every host (LAMMPS: pair_coeff of
   granular/grflow and fix grflow/wall; LIGGGHTS: fix property/global of
   model grflow): their names, the defaults of the paper's Table 1 for
   those not given, the check that each is finite, kn > 0 and the others
   >= 0, and the reading of the coefficient arguments of a command.
   Header only, no host types: the hosts read numbers and report errors
   through a Host object (grflow_host.h).
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_COEFF_RULES_H
#define LMP_GRFLOW_COEFF_RULES_H

#include "grflow_contact_coeffs.h"
#include "grflow_host.h"

#include <cmath>
#include <cstring>
#include <string>

namespace LAMMPS_NS {
namespace GRFLOW {

  // the coefficients' keywords, in the order of ContactCoeffs' members
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

  // the coefficients of value into c (c.normal_law is left as it is)
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

  /* ----------------------------------------------------------------------
     contact coefficient arguments, kn cn [kt v] ... [rolling off]
     [torsion off] (the names, Table 1 defaults and rules of
     this file), read from arg[first] on: returns the index
     after the last one used.  A word that is no coefficient keyword ends
     the list if stop_at_unknown, else it is an error.
  ------------------------------------------------------------------------- */

  // stop with an error naming the first coefficient that breaks a rule;
  // where: the command (or the source) of the values
  template <class Host>
  static inline void check_coeff_values(const std::string &where, const double *value, Host &host)
  {
    const char *rule = nullptr;
    const int k = bad_coeff(value, &rule);
    if (k < NCOEFF)
      host.fail(FLERR, where + ": " + COEFF_NAMES[k] + " " + rule + ", got " + host.text(value[k]));
  }

  template <class Host>
  static inline int read_coeff_args(const std::string &cmd, int narg, char **arg, int first,
                                    bool stop_at_unknown, double *value, Host &host)
  {
    if (first + 2 > narg) {
      host.fail(FLERR, "Incorrect args for " + cmd + ": expected kn cn [keyword value ...]");
      return narg;
    }
    const double kn = host.number(FLERR, arg[first], cmd + " kn");
    const double cn = host.number(FLERR, arg[first + 1], cmd + " cn");
    default_coeffs(kn, cn, value);

    int iarg = first + 2;
    while (iarg < narg) {
      const std::string kw = arg[iarg];
      const int k = coeff_index(kw);
      const bool off = (kw == "rolling" || kw == "torsion");
      if ((k == NCOEFF || k < KT) && !off) {
        if (stop_at_unknown) break;
        host.fail(FLERR, "Unknown " + cmd + " keyword: " + kw);
        return narg;
      }
      if (iarg + 2 > narg) {
        host.fail(FLERR, "Missing value for " + cmd + " keyword " + kw);
        return narg;
      }
      if (off) {
        if (strcmp(arg[iarg + 1], "off") != 0) {
          host.fail(FLERR, cmd + " " + kw + " takes only the value off, not " + arg[iarg + 1]);
          return narg;
        }
        mode_off((kw == "rolling") ? KR : KO, value);
      } else {
        value[k] = host.number(FLERR, arg[iarg + 1], cmd + " " + kw);
      }
      iarg += 2;
    }

    check_coeff_values(cmd, value, host);
    return iarg;
  }

  // the value of a velocity_arm keyword: 0 for reduced (a - delta/2), 1 for
  // full (the radii)
  template <class Host>
  static inline int read_velocity_arm(const std::string &cmd, const char *value, Host &host)
  {
    if (strcmp(value, "reduced") == 0) return 0;
    if (strcmp(value, "full") == 0) return 1;
    host.fail(FLERR,
              "Unknown " + cmd + " velocity_arm value " + value + ": expected reduced or full");
    return 0;
  }

  // the keyword value of a normal force law
  static inline const char *normal_law_name(int normal_law)
  {
    return normal_law == NORMAL_UNCLIPPED ? "unclipped" : "clipped";
  }

  // the value of a normal_force keyword: NORMAL_CLIPPED for clipped,
  // NORMAL_UNCLIPPED for unclipped
  template <class Host>
  static inline int read_normal_force(const std::string &cmd, const char *value, Host &host)
  {
    if (strcmp(value, "clipped") == 0) return NORMAL_CLIPPED;
    if (strcmp(value, "unclipped") == 0) return NORMAL_UNCLIPPED;
    host.fail(FLERR,
              "Unknown " + cmd + " normal_force value " + value +
                  ": expected clipped or unclipped");
    return NORMAL_CLIPPED;
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
