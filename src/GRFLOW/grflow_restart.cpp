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

#include "grflow_restart.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"

using namespace LAMMPS_NS;
using GRFLOW::FixHost;

void GRFLOW::write_restart_values(LAMMPS *lmp, FILE *fp, int version, const double *values, int n)
{
  if (lmp->comm->me == 0) write_restart_block(fp, version, values, n);
}

const double *GRFLOW::read_restart_values(LAMMPS *lmp, const std::string &who, const char *buf,
                                          int current, int count, int &version)
{
  FixHost host{lmp};
  return read_restart_block(who, buf, current, count, version, host);
}

/* ---------------------------------------------------------------------- */

// a value that is not a number stops with the parameter's name (as in
// the LIGGGHTS build), not only with the word that was found
double FixHost::number(const char *str, const std::string &what) const
{
  if (!utils::is_double(str)) fail(what + " expects a number, got '" + std::string(str) + "'");
  return utils::numeric(FLERR, str, false, lmp);
}

int FixHost::integer(const char *str, const std::string &what) const
{
  if (!utils::is_integer(str)) fail(what + " expects an integer, got '" + std::string(str) + "'");
  return utils::inumeric(FLERR, str, false, lmp);
}

bool FixHost::logical(const char *str, const std::string & /*what*/) const
{
  return utils::logical(FLERR, str, false, lmp) != 0;
}

void FixHost::missing(const std::string &cmd) const
{
  utils::missing_cmd_args(FLERR, cmd, lmp->error);
}

void FixHost::fail(const std::string &message) const
{
  lmp->error->all(FLERR, message);
}

void FixHost::warning(const std::string &message) const
{
  if (lmp->comm->me == 0) lmp->error->warning(FLERR, message);
}

std::string FixHost::text(double value) const
{
  return fmt::format("{}", value);
}
