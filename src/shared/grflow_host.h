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
   What the host-free rules of GRFLOW (src/shared) need from a host
   (LAMMPS, LIGGGHTS), and the pieces of them that every command uses.

   The rules parse numbers and report errors through a Host object
   (GRFLOW::FixHost of grflow_host_api.h, one definition per host, or a
   struct like it).  Every call takes the file and line of its call site
   (FLERR), so that an error names the line of the rule that raised it:
     double number(FLERR, const char *text, const std::string &what)
       the value of a numeric argument (what names it, e.g. "fix
       grflow/wall zlo"); reports an error itself if text is no number
     int integer(FLERR, text, what), bool logical(FLERR, text, what)
     void missing(FLERR, const std::string &cmd)   missing arguments
     void fail(FLERR, const std::string &message)  any other error
     void warning(FLERR, const std::string &message)
     std::string text(double value)  a number as the host's messages print it
   The code does not rely on missing() and fail() not returning: it stops
   its work after calling them.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_HOST_H
#define LMP_GRFLOW_HOST_H

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

// a small function of the rules that device code (the KOKKOS variants on a
// GPU) calls too; on the host an ordinary function, inlined as the
// compiler chooses
#if defined(__CUDACC__) || defined(__HIPCC__)
#define GRFLOW_FUNCTION __host__ __device__
#else
#define GRFLOW_FUNCTION
#endif

// the call site of a Host call, as LAMMPS's and LIGGGHTS's FLERR give it
// (token for token as LAMMPS's pointers.h has it, so that either may come first)
// clang-format off
#ifndef FLERR
#define FLERR __FILE__,__LINE__
#endif
// clang-format on

namespace LAMMPS_NS {
namespace GRFLOW {

  // a number as LAMMPS's messages print it: the shortest form that reads
  // back to the same value
  static inline std::string format_number(double value)
  {
    std::ostringstream out;
    for (int digits = 1; digits <= std::numeric_limits<double>::max_digits10; digits++) {
      out.str("");
      out.precision(digits);
      out << value;
      std::istringstream in(out.str());
      double back = 0.0;
      if ((in >> back) && back == value) break;
    }
    return out.str();
  }

  /* ----------------------------------------------------------------------
     the keyword-value arguments of a command, from arg[first] on: each
     keyword must be one of known[] (a name and its number of values);
     apply(kw, values, what) reads the values of each (what: "command
     kw", for messages).  An unknown keyword is reported as such (also at
     the end of the line, before its values are looked for), then missing
     values, through the host as command ("fix grflow/shear", ...).
  ------------------------------------------------------------------------- */

  struct Keyword {
    const char *name;
    int nvalues;
  };

  template <class Host, class Apply, std::size_t N>
  static inline void parse_keywords(int narg, char **arg, int first, const std::string &command,
                                    const Keyword (&known)[N], Host &host, Apply apply)
  {
    int iarg = first;
    while (iarg < narg) {
      const std::string kw = arg[iarg];
      const Keyword *found = nullptr;
      for (const Keyword &k : known)
        if (kw == k.name) found = &k;
      if (!found) {
        host.fail(FLERR, "Unknown " + command + " keyword: " + kw);
        return;
      }
      const std::string what = command + " " + kw;
      if (iarg + 1 + found->nvalues > narg) {
        host.missing(FLERR, what);
        return;
      }
      apply(kw, arg + iarg + 1, what);
      iarg += 1 + found->nvalues;
    }
  }

  /* ----------------------------------------------------------------------
     global restart data of a GRFLOW fix: a tag that marks GRFLOW data, the
     fix's format version, the number of values, then the values
     (write_restart_values() and read_restart_values() of
     grflow_host_api.h write and read them on the host's processors).
     Data of format 0 (written before the header existed) are the values
     alone.
  ------------------------------------------------------------------------- */

  static constexpr double RESTART_BLOCK_TAG = -7.3e301;

  // the bytes a fix's write_restart() writes on rank 0: their size, then
  // the header and the n values
  static inline void write_restart_block(FILE *fp, int version, const double *values, int n)
  {
    std::vector<double> list(n + 3);
    list[0] = RESTART_BLOCK_TAG;
    list[1] = version;
    list[2] = n;
    for (int k = 0; k < n; k++) list[3 + k] = values[k];
    const int size = (n + 3) * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), n + 3, fp);
  }

  // the values of the data buf given to a fix's restart(): for a headed
  // block, check that its version is at most current and, for the current
  // version, that it holds count values, all finite; an error naming who
  // (e.g. "Fix grflow/wall w") otherwise.  version is set to the block's
  // version, 0 for data without the header (then buf itself is returned,
  // unchecked).
  template <class Host>
  static inline const double *read_restart_block(const std::string &who, const char *buf,
                                                 int current, int count, int &version, Host &host)
  {
    const double *list = (const double *) buf;
    if (list[0] != RESTART_BLOCK_TAG) {
      version = 0;
      return list;
    }
    const double v = list[1], n = list[2];
    if (!(v >= 1.0 && v == std::floor(v)) || v > current) {
      host.fail(FLERR,
                who + ": restart data of format version " + host.text(v) +
                    "; this GRFLOW reads versions up to " + std::to_string(current) +
                    " (a newer GRFLOW wrote it, or the file is damaged)");
      version = current;
      return list + 3;
    }
    version = (int) v;
    if (version == current) {
      if (n != count)
        host.fail(FLERR,
                  who + ": restart data of format version " + std::to_string(version) + " hold " +
                      host.text(n) + " values, expected " + std::to_string(count) +
                      ": the file is damaged");
      for (int k = 0; k < count; k++)
        if (!std::isfinite(list[3 + k]))
          host.fail(FLERR,
                    who + ": restart value " + std::to_string(k + 1) + " of " +
                        std::to_string(count) + " is " + host.text(list[3 + k]) +
                        ": the file is damaged");
    }
    return list + 3;
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
