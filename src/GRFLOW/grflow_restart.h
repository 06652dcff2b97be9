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
   The LAMMPS side of the GRFLOW fixes' host-free code:

   - their global restart data: the block of grflow_host.h (a header with
     a tag that marks GRFLOW data, the fix's format version and the
     number of values, then the values), written on rank 0, its errors
     reported through LAMMPS.  LAMMPS passes Fix::restart() the bytes
     only, not their size: the header lets a fix tell its formats apart
     and stop with a clear error on data it cannot have written.  Data
     written before the header existed (format version 0 here) start
     with a value other than the tag.
   - FixHost: numbers read and errors reported the LAMMPS way (utils::,
     fmt; a value that is no number names its parameter), for the
     argument rules of the shared headers (coefficients, compute, walls,
     shear, servo; the Host of grflow_host.h).
   The LIGGGHTS build has the same (src/LIGGGHTS/grflow_restart.h).
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_RESTART_H
#define LMP_GRFLOW_RESTART_H

#include "grflow_host.h"

#include <cstdio>
#include <string>

namespace LAMMPS_NS {
class LAMMPS;
namespace GRFLOW {

  // first double of a headed block: no value a GRFLOW fix stores begins so
  static constexpr double RESTART_TAG = RESTART_BLOCK_TAG;

  // write the header and n values (on rank 0, as Fix::write_restart() does)
  void write_restart_values(LAMMPS *lmp, FILE *fp, int version, const double *values, int n);

  // the values of buf: for a headed block, check that the version is at
  // most current and, for the current version, that it holds count values,
  // all finite; stop with an error naming who (e.g. "Fix grflow/wall w")
  // otherwise.  version is set to the block's version, 0 for data without
  // the header (then buf itself is returned, unchecked).
  const double *read_restart_values(LAMMPS *lmp, const std::string &who, const char *buf,
                                    int current, int count, int &version);

  // the host object of the fixes' host-free rules (grflow_shear_rule.h)
  struct FixHost {
    LAMMPS *lmp;
    double number(const char *str, const std::string &what) const;
    int integer(const char *str, const std::string &what) const;
    bool logical(const char *str, const std::string &what) const;
    void missing(const std::string &cmd) const;
    void fail(const std::string &message) const;
    void warning(const std::string &message) const;    // from rank 0
    std::string text(double value) const;
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
