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
   The global restart data of the GRFLOW fixes: a header (a tag that marks
   GRFLOW data, the fix's format version, the number of values), then the
   values.  LAMMPS passes Fix::restart() the bytes only, not their size:
   the header lets a fix tell its formats apart and stop with a clear
   error on data it cannot have written.  Data written before the header
   existed (format version 0 here) start with a value other than the tag.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_RESTART_H
#define LMP_GRFLOW_RESTART_H

#include <cstdio>
#include <string>

namespace LAMMPS_NS {
class LAMMPS;
namespace GRFLOW {

  // first double of a headed block: no value a GRFLOW fix stores begins so
  static constexpr double RESTART_TAG = -7.3e301;

  // write the header and n values (on rank 0, as Fix::write_restart() does)
  void write_restart_values(LAMMPS *lmp, FILE *fp, int version, const double *values, int n);

  // the values of buf: for a headed block, check that the version is at
  // most current and, for the current version, that it holds count values,
  // all finite; stop with an error naming who (e.g. "Fix grflow/wall w")
  // otherwise.  version is set to the block's version, 0 for data without
  // the header (then buf itself is returned, unchecked).
  const double *read_restart_values(LAMMPS *lmp, const std::string &who, const char *buf,
                                    int current, int count, int &version);

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
