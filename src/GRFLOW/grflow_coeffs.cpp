// clang-format off
/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */
// clang-format on

#include "grflow_coeffs.h"

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

const char *const GRFLOW::COEFF_NAMES[GRFLOW::NCOEFF] = {"kn", "cn",  "kt", "ct", "mut", "kr",
                                                         "cr", "mur", "ko", "co", "muo"};

int GRFLOW::parse_coeffs(LAMMPS *lmp, const std::string &cmd, int narg, char **arg, int first,
                         bool stop_at_unknown, double *value)
{
  Error *error = lmp->error;
  if (first + 2 > narg)
    error->all(FLERR, "Incorrect args for {}: expected kn cn [keyword value ...]", cmd);

  value[KN] = utils::numeric(FLERR, arg[first], false, lmp);
  value[CN] = utils::numeric(FLERR, arg[first + 1], false, lmp);
  value[KT] = 0.8 * value[KN];
  value[CT] = 0.2 * value[CN];
  value[MUT] = 0.5;
  value[KR] = 0.1 * value[KN];
  value[CR] = 0.05 * value[CN];
  value[MUR] = 0.1;
  value[KO] = 0.1 * value[KN];
  value[CO] = 0.05 * value[CN];
  value[MUO] = 0.1;

  int iarg = first + 2;
  while (iarg < narg) {
    const std::string kw = arg[iarg];
    int k = KT;
    while (k < NCOEFF && kw != COEFF_NAMES[k]) k++;
    const bool mode_off = (kw == "rolling" || kw == "torsion");
    if (k == NCOEFF && !mode_off) {
      if (stop_at_unknown) break;
      error->all(FLERR, "Unknown {} keyword: {}", cmd, kw);
    }
    if (iarg + 2 > narg) error->all(FLERR, "Missing value for {} keyword {}", cmd, kw);
    if (mode_off) {
      if (strcmp(arg[iarg + 1], "off") != 0)
        error->all(FLERR, "{} {} takes only the value off, not {}", cmd, kw, arg[iarg + 1]);
      const int firstk = (kw == "rolling") ? KR : KO;
      for (int m = firstk; m < firstk + 3; m++) value[m] = 0.0;
    } else {
      value[k] = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    }
    iarg += 2;
  }

  check_coeffs(lmp, cmd, value);
  return iarg;
}

void GRFLOW::check_coeffs(LAMMPS *lmp, const std::string &where, const double *value)
{
  for (int k = 0; k < NCOEFF; k++)
    if (!std::isfinite(value[k]))
      lmp->error->all(FLERR, "{}: {} must be finite, got {}", where, COEFF_NAMES[k], value[k]);
  if (value[KN] <= 0.0) lmp->error->all(FLERR, "{}: kn must be > 0, got {}", where, value[KN]);
  for (int k = 1; k < NCOEFF; k++)
    if (value[k] < 0.0)
      lmp->error->all(FLERR, "{}: {} must be >= 0, got {}", where, COEFF_NAMES[k], value[k]);
}

void GRFLOW::pack_coeffs(const double *value, ContactCoeffs &c)
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

/* ---------------------------------------------------------------------- */

int GRFLOW::parse_velocity_arm(LAMMPS *lmp, const std::string &cmd, const char *value)
{
  if (strcmp(value, "reduced") == 0) return 0;
  if (strcmp(value, "full") == 0) return 1;
  lmp->error->all(FLERR, "Unknown {} velocity_arm value {}: expected reduced or full", cmd, value);
  return 0;
}
