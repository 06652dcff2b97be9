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

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(grflow/network,ComputeGRFLOWNetwork);
// clang-format on
#else

#ifndef LMP_COMPUTE_GRFLOW_NETWORK_H
#define LMP_COMPUTE_GRFLOW_NETWORK_H

#include "compute.h"

#include <string>

#include <vector>

namespace LAMMPS_NS {

class ComputeGRFLOWNetwork : public Compute {
 public:
  ComputeGRFLOWNetwork(class LAMMPS *, int, char **);
  ~ComputeGRFLOWNetwork() override;

  // the compute grflow/network with ID id, for another command (caller,
  // e.g. "Fix grflow/shear"); an error otherwise
  static ComputeGRFLOWNetwork *find(class LAMMPS *lmp, const std::string &caller, const char *id);
  void init() override;
  void compute_vector() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // reference pressure for r_u, for fixes that capture it (e.g. when shear starts)
  void set_p0(double value)
  {
    p0 = value;
    p0flag = 1;
  }
  // true if the command gave the p0 keyword (then a fix must not set p0:
  // each p0 has one owner)
  bool has_p0_keyword() const { return p0_keyword; }

  // positions of the output vector entries (0-based)
  // clang-format off
  enum {
    SXX, SYY, SZZ, SXY, SXZ, SYZ, PRESS, TAU, QDEV, SNORM, RU, NP, NFLOAT, NCONTACT, ZG,
    ZPLAIN, AC, SC, AXX, AYY, AZZ, AXY, AXZ, AYZ, VOLUME, PC0
  };
  // clang-format on

 private:
  int cmax;                   // P_c for c = 0..cmax (last bin: cmax or more)
  int tau_a, tau_b;           // tau = -(sigma_ab + sigma_ba)/2
  double slab;                // central fraction of the height (no region)
  char *zlo_str, *zhi_str;    // sample bounds in z: number or v_name
  char *idregion;
  class Region *region;
  char *volume_str;    // volume of a non-block region: number or v_name
  double p0;
  int p0flag, p0first;
  bool p0_keyword;

  std::vector<class FixGRFLOWWall *> walls;

  int nmax;
  double *inside;      // 1 if the atom is in the group and the sub-volume
  double *ncontact;    // force-bearing contacts per atom
  int commflag;

  // the sums of compute_vector(), per processor and then over all: stress
  // sum l (x) f (9), fabric sum n (x) n (9), particles inside, floaters,
  // contact ends, histogram of contact numbers (cmax + 1)
  enum { SUMS_STRESS = 0, SUMS_FABRIC = 9, SUMS_NP = 18, SUMS_FLOAT, SUMS_ENDS, SUMS_HIST };

  void check_setup();
  double eval(const char *, const char *);
  void set_inside(double &volume);
  void require_current_contacts();
  void grow_peratom();
  double refresh_ghosts_and_inside();
  void sum_pair_contacts(double *sig, double *fab);
  void sum_wall_contacts(double *sig, double *fab);
  void count_particles(double *sums);
  void derive(const double *total, double volume);
};

}    // namespace LAMMPS_NS

#endif
#endif
