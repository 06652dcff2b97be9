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

#include <cmath>
#include <vector>

using namespace LAMMPS_NS;

void GRFLOW::write_restart_values(LAMMPS *lmp, FILE *fp, int version, const double *values, int n)
{
  if (lmp->comm->me != 0) return;
  std::vector<double> list(n + 3);
  list[0] = RESTART_TAG;
  list[1] = version;
  list[2] = n;
  for (int k = 0; k < n; k++) list[3 + k] = values[k];
  const int size = (n + 3) * sizeof(double);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list.data(), sizeof(double), n + 3, fp);
}

const double *GRFLOW::read_restart_values(LAMMPS *lmp, const std::string &who, const char *buf,
                                          int current, int count, int &version)
{
  const auto *list = (const double *) buf;
  if (list[0] != RESTART_TAG) {
    version = 0;
    return list;
  }
  const double v = list[1], n = list[2];
  if (!(v >= 1.0 && v == std::floor(v)) || v > current)
    lmp->error->all(FLERR,
                    "{}: restart data of format version {}; this GRFLOW reads versions up to {} "
                    "(a newer GRFLOW wrote it, or the file is damaged)",
                    who, v, current);
  version = (int) v;
  if (version == current) {
    if (n != count)
      lmp->error->all(FLERR,
                      "{}: restart data of format version {} hold {} values, expected {}: "
                      "the file is damaged",
                      who, version, n, count);
    for (int k = 0; k < count; k++)
      if (!std::isfinite(list[3 + k]))
        lmp->error->all(FLERR, "{}: restart value {} of {} is {}: the file is damaged", who, k + 1,
                        count, list[3 + k]);
  }
  return list + 3;
}
