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

/* ----------------------------------------------------------------------
   Helpers for GRFLOW tests that drive LAMMPS through its C library API.
------------------------------------------------------------------------- */

#ifndef GRFLOW_TEST_LAMMPS_FIXTURE_H
#define GRFLOW_TEST_LAMMPS_FIXTURE_H

#include "grflow_host.h"
#include "grflow_network.h"
#include "grflow_servo.h"
#include "grflow_shear_rule.h"
#include "grflow_wall.h"
#include "library.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

namespace grflow_test {

// the output layouts (0-based positions of the vectors), from the
// host-free headers: the one source of each (tests/test_layouts.py checks
// the decks and docs against them)
using NetVector = LAMMPS_NS::GRFLOW::NetworkLayout;        // compute grflow/network
using ShearVector = LAMMPS_NS::GRFLOW::ShearLayout;        // fix grflow/shear
using CompressVector = LAMMPS_NS::GRFLOW::CompressLayout;  // fix grflow/compress
using WallVector = LAMMPS_NS::GRFLOW::FlatWalls;           // fix grflow/wall: LO_FX ... HI_DY, NVECTOR

// one LAMMPS instance, quiet, closed on destruction
class Lammps {
 public:
  Lammps()
  {
    const char *args[] = {"grflow_test", "-log",    "none", "-echo",
                          "none",        "-screen", "none", "-nocite"};
    handle = lammps_open_no_mpi(8, (char **) args, nullptr);
  }
  ~Lammps() { lammps_close(handle); }
  Lammps(const Lammps &) = delete;
  Lammps &operator=(const Lammps &) = delete;

  // run one command; record a test failure with LAMMPS's message if it fails
  bool cmd(const std::string &line)
  {
    lammps_command(handle, line.c_str());
    if (lammps_has_error(handle)) {
      char buf[1024];
      lammps_get_last_error_message(handle, buf, sizeof(buf));
      ADD_FAILURE() << "LAMMPS command failed: " << line << "\n  " << buf;
      return false;
    }
    return true;
  }
  void cmds(const std::vector<std::string> &lines)
  {
    for (const auto &l : lines)
      if (!cmd(l)) return;
  }

  // run one command that must fail; returns LAMMPS's error message
  std::string error_of(const std::string &line)
  {
    lammps_command(handle, line.c_str());
    if (!lammps_has_error(handle)) return "";
    char buf[1024];
    lammps_get_last_error_message(handle, buf, sizeof(buf));
    return buf;
  }

  int natoms() { return (int) lammps_get_natoms(handle); }

  // per-atom 3-vector ordered by atom ID (needs an atom map)
  std::vector<double> gather3(const char *name)
  {
    std::vector<double> data(3 * (size_t) natoms());
    lammps_gather_atoms(handle, name, 1, 3, data.data());
    return data;
  }

  double thermo(const char *keyword) { return lammps_get_thermo(handle, keyword); }

  // the first n entries of a fix's global vector
  std::vector<double> fix_vector(const char *id, int n)
  {
    std::vector<double> out(n, 0.0);
    for (int k = 0; k < n; k++) {
      auto *p = (double *) lammps_extract_fix(handle, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, k, 0);
      if (!p) {
        ADD_FAILURE() << "fix " << id << " vector entry " << k << " not available";
        return out;
      }
      out[k] = *p;
      lammps_free(p);
    }
    return out;
  }

  void *handle;
};

// largest |a_k - b_k| over all k, relative to the largest |b_k|
inline double max_rel_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double dmax = 0.0, scale = 0.0;
  for (size_t k = 0; k < a.size(); k++) {
    dmax = std::max(dmax, std::fabs(a[k] - b[k]));
    scale = std::max(scale, std::fabs(b[k]));
  }
  return scale > 0.0 ? dmax / scale : dmax;
}

// print a measured number with the test output, for the record
inline double measured(const std::string &what, double value)
{
  printf("[ measured ] %s = %.3e\n", what.c_str(), value);
  return value;
}

// a double as LAMMPS input text, exactly (std::to_string would print %f)
inline std::string fmt_double(double value)
{
  char buf[64];
  snprintf(buf, sizeof(buf), "%.17g", value);
  return buf;
}

// a command that must fail after some setup commands; returns LAMMPS's message
inline std::string error_after(const std::vector<std::string> &setup, const std::string &bad)
{
  Lammps lmp;
  lmp.cmds(setup);
  return lmp.error_of(bad);
}

// the error of the first of some commands that fails, in a new instance
// ("" if none fails)
inline std::string first_error(const std::vector<std::string> &lines)
{
  Lammps lmp;
  for (const auto &line : lines) {
    std::string msg = lmp.error_of(line);
    if (!msg.empty()) return msg;
  }
  return "";
}

// the two half steps of fix nve/sphere (solid spheres, I = 0.4 m r^2), in
// its order of operations, for hand integrations of a few bodies; Body has
// x, v, w, f, t (3 each), rad and mass
template <class Body> void nve_sphere_initial(std::vector<Body> &bodies, double dt)
{
  const double dtf = 0.5 * dt;
  for (auto &p : bodies) {
    const double dtfm = dtf / p.mass;
    const double dtir = (dtf / 0.4) / (p.rad * p.rad * p.mass);
    for (int k = 0; k < 3; k++) {
      p.v[k] += dtfm * p.f[k];
      p.x[k] += dt * p.v[k];
      p.w[k] += dtir * p.t[k];
    }
  }
}

template <class Body> void nve_sphere_final(std::vector<Body> &bodies, double dt)
{
  const double dtf = 0.5 * dt;
  for (auto &p : bodies) {
    const double dtfm = dtf / p.mass;
    const double dtir = (dtf / 0.4) / (p.rad * p.rad * p.mass);
    for (int k = 0; k < 3; k++) {
      p.v[k] += dtfm * p.f[k];
      p.w[k] += dtir * p.t[k];
    }
  }
}

// x, v, omega, f or torque (which = 0..4) of all bodies, as gather3() orders them
template <class Body> std::vector<double> body_field(const std::vector<Body> &bodies, int which)
{
  std::vector<double> out;
  for (const auto &p : bodies) {
    const double *q = which == 0 ? p.x
        : which == 1             ? p.v
        : which == 2             ? p.w
        : which == 3             ? p.f
                                 : p.t;
    out.insert(out.end(), q, q + 3);
  }
  return out;
}

// a file in the test work directory, private to this process: ctest may run
// several test programs at once, and they must not share files
inline std::string workfile(const std::string &name)
{
  return std::string(GRFLOW_TEST_WORKDIR) + "/" + std::to_string((long) getpid()) + "_" + name;
}

// The GRFLOW restart block that holds count values (the wall fix 14, the
// compress fix 13, the shear fix 13) of format version (any if 0) in the
// bytes of a restart file: its offset (at its tag; then version, count,
// values), npos if there is none or more than one.
inline size_t grflow_block(const std::string &bytes, double count, double version = 0.0)
{
  const double tag = LAMMPS_NS::GRFLOW::RESTART_BLOCK_TAG;
  const std::string tagbytes((const char *) &tag, sizeof(double));
  size_t at = std::string::npos;
  for (size_t pos = bytes.find(tagbytes); pos != std::string::npos;
       pos = bytes.find(tagbytes, pos + 1)) {
    double n, v;
    memcpy(&v, &bytes[pos + sizeof(double)], sizeof(double));
    memcpy(&n, &bytes[pos + 2 * sizeof(double)], sizeof(double));
    if (n != count || (version != 0.0 && v != version)) continue;
    if (at != std::string::npos) return std::string::npos;
    at = pos;
  }
  return at;
}

inline std::string file_bytes(const std::string &file)
{
  std::ifstream in(file, std::ios::binary);
  return {(std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()};
}

// a copy of a restart file (named name in the work directory) with value k
// of the GRFLOW block of count values (and format version, any if 0) set
// to x (k = 0: tag, 1: version, 2: count, 3...: the values); "" if the
// file has no such single block
inline std::string damaged_restart(const std::string &file, double count, int k, double x,
                                   const std::string &name, double version = 0.0)
{
  std::string b = file_bytes(file);
  const size_t at = grflow_block(b, count, version);
  if (at == std::string::npos) return "";
  memcpy(&b[at + k * sizeof(double)], &x, sizeof(double));
  const std::string out = workfile(name);
  std::ofstream(out, std::ios::binary) << b;
  return out;
}

// path of a deck or data file known to the build
inline std::string deck(const std::string &name)
{
  return std::string(GRFLOW_TEST_DECKS) + "/" + name;
}

// a dense periodic packing written as a data file (once per test program)
inline std::string make_packing(const std::string &tag, int nside, double dmin, double dmax,
                                double phi)
{
  const std::string out = workfile("packing_" + tag + ".data");
  Lammps lmp;
  lmp.cmds({"units si", "atom_style sphere", "variable nside equal " + std::to_string(nside),
            "variable seed equal 4321", "variable dmin equal " + fmt_double(dmin),
            "variable dmax equal " + fmt_double(dmax), "variable phi equal " + fmt_double(phi),
            "variable ncomp equal 40000", "variable out string " + out,
            "include " + deck("dense_packing.lmp")});
  return out;
}

}    // namespace grflow_test

#endif
