/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: compute grflow/network, the stress, coordination
   z_g, connectivity P_c and fabric anisotropy a_c of a sub-volume, as in
   LAMMPS (doc/compute_grflow_network.rst).  The keywords, sums and derived
   quantities are GRFLOW's host-free grflow_network.h; this class finds the
   contacts in LIGGGHTS.

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(grflow/network,ComputeGRFLOWNetwork)
// clang-format on
#else

#ifndef LMP_COMPUTE_GRFLOW_NETWORK_H
#define LMP_COMPUTE_GRFLOW_NETWORK_H

#include "compute.h"
#include "grflow_network.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// the positions of the output vector: ComputeGRFLOWNetwork::SXX, ... PC0
// (GRFLOW::NetworkLayout, as in LAMMPS)
class ComputeGRFLOWNetwork : public Compute, public GRFLOW::NetworkLayout {
 public:
  ComputeGRFLOWNetwork(class LAMMPS *, int &iarg, int, char **);
  ~ComputeGRFLOWNetwork();

  // the compute grflow/network with ID id, for another command (caller,
  // e.g. "Fix grflow/shear"); an error otherwise
  static ComputeGRFLOWNetwork *find(class LAMMPS *lmp, const std::string &caller, const char *id);
  void init();
  void compute_vector();
  int pack_comm(int, int *, double *, int, int *);
  void unpack_comm(int, int, double *);
  int pack_reverse_comm(int, int, double *);
  void unpack_reverse_comm(int, int *, double *);
  double memory_usage();

  // reference pressure for r_u, for fixes that capture it (e.g. when shear starts)
  void set_p0(double value)
  {
    opt.p0 = value;
    opt.p0flag = true;
  }
  // true if the command gave the p0 keyword (then a fix must not set p0:
  // each p0 has one owner)
  bool has_p0_keyword() const { return opt.p0_keyword; }

 private:
  GRFLOW::NetworkOptions opt;    // the keywords (grflow_network.h)
  class Region *region;

  std::vector<class FixGRFLOWWall *> walls;

  int nmax;
  double *inside;      // 1 if the atom is in the group and the sub-volume
  double *ncontact;    // force-bearing contacts per atom
  int commflag;

  void check_setup();
  double eval(const std::string &, const char *);
  void set_inside(double &volume);
  void require_current_contacts();
  void grow_peratom();
  double refresh_ghosts_and_inside();
  void sum_pair_contacts(double *sums);
  void sum_wall_contacts(double *sums);
  void count_particles(double *sums);
};

}    // namespace LAMMPS_NS

#endif
#endif
