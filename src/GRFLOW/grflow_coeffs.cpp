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

int GRFLOW::parse_coeffs(LAMMPS *lmp, const std::string &cmd, int narg, char **arg, int first,
                         bool stop_at_unknown, double *value)
{
  Error *error = lmp->error;
  if (first + 2 > narg)
    error->all(FLERR, "Incorrect args for {}: expected kn cn [keyword value ...]", cmd);

  default_coeffs(utils::numeric(FLERR, arg[first], false, lmp),
                 utils::numeric(FLERR, arg[first + 1], false, lmp), value);

  int iarg = first + 2;
  while (iarg < narg) {
    const std::string kw = arg[iarg];
    const int k = coeff_index(kw);
    const bool mode_off = (kw == "rolling" || kw == "torsion");
    if ((k == NCOEFF || k < KT) && !mode_off) {
      if (stop_at_unknown) break;
      error->all(FLERR, "Unknown {} keyword: {}", cmd, kw);
    }
    if (iarg + 2 > narg) error->all(FLERR, "Missing value for {} keyword {}", cmd, kw);
    if (mode_off) {
      if (strcmp(arg[iarg + 1], "off") != 0)
        error->all(FLERR, "{} {} takes only the value off, not {}", cmd, kw, arg[iarg + 1]);
      GRFLOW::mode_off((kw == "rolling") ? KR : KO, value);
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
  const char *rule = nullptr;
  const int k = bad_coeff(value, &rule);
  if (k < NCOEFF)
    lmp->error->all(FLERR, "{}: {} {}, got {}", where, COEFF_NAMES[k], rule, value[k]);
}

/* ---------------------------------------------------------------------- */

int GRFLOW::parse_velocity_arm(LAMMPS *lmp, const std::string &cmd, const char *value)
{
  if (strcmp(value, "reduced") == 0) return 0;
  if (strcmp(value, "full") == 0) return 1;
  lmp->error->all(FLERR, "Unknown {} velocity_arm value {}: expected reduced or full", cmd, value);
  return 0;
}
