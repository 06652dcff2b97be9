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

#include "grflow_coeff_rules.h"

#include "grflow_host_api.h"

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

int GRFLOW::parse_coeffs(LAMMPS *lmp, const std::string &cmd, int narg, char **arg, int first,
                         bool stop_at_unknown, double *value)
{
  FixHost host{lmp};
  return read_coeff_args(cmd, narg, arg, first, stop_at_unknown, value, host);
}

void GRFLOW::check_coeffs(LAMMPS *lmp, const std::string &where, const double *value)
{
  FixHost host{lmp};
  check_coeff_values(where, value, host);
}

int GRFLOW::parse_velocity_arm(LAMMPS *lmp, const std::string &cmd, const char *value)
{
  FixHost host{lmp};
  return read_velocity_arm(cmd, value, host);
}
