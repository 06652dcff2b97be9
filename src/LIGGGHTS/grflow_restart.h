/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: the LIGGGHTS side of the GRFLOW fixes'
   host-free code, as src/GRFLOW/grflow_restart.h is LAMMPS's:

   - FixHost: numbers read and errors reported for the argument rules of
     the shared headers (the Host of grflow_host.h) and for the checks of
     the fixes' global restart data (the block of grflow_host.h: a header with
     a tag, the fix's format version and the number of values, then the
     values; write_restart_block() on rank 0, read_restart_block() with
     this host).  LIGGGHTS's own readers (force->numeric) do not say which
     parameter is wrong: these do.
   - log_text(): text to the screen and the log file (LIGGGHTS has no
     utils::logmesg).

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_RESTART_H
#define LMP_GRFLOW_RESTART_H

#include "grflow_host.h"

#include <cstdio>
#include <string>

namespace LAMMPS_NS {
class LAMMPS;
namespace GRFLOW {

  // write the header and n values (on rank 0, as Fix::write_restart() does)
  void write_restart_values(LAMMPS *lmp, FILE *fp, int version, const double *values, int n);

  // the values of buf: for a headed block, check that the version is at
  // most current and, for the current version, that it holds count values,
  // all finite; stop with an error naming who (e.g. "Fix grflow/shear s")
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

  // text to the screen and the log file, from rank 0
  void log_text(LAMMPS *lmp, const std::string &text);

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
