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

  // the entries SXX..RU (the first NSTRESS of the vector) of this step,
  // for fixes that need no more (the reversal check of fix grflow/shear,
  // the servo of fix grflow/compress): the stress sums alone, as in LAMMPS
  // (compute_stress() evaluates them, current_stress() reuses those of
  // this step)
  const double *compute_stress();
  const double *current_stress();

  // true if the command gave the p0 keyword (then no fix may own p0: a
  // fix grflow/shear refuses the compute; each p0 has one owner).  Without
  // it, p0 of r_u is that of the fix grflow/shear that names this compute.
  bool has_p0_keyword() const { return opt.p0_keyword; }

 private:
  GRFLOW::NetworkOptions opt;    // the keywords (grflow_network.h)
  class Region *region;

  std::vector<class FixGRFLOWWall *> walls;
  class FixGRFLOWShear *p0_owner;    // the fix grflow/shear of this compute, if any

  double stress[NSTRESS];    // compute_stress()'s entries, of step invoked_stress
  bigint invoked_stress;

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
  void evaluate(bool network, double *out);
  void sum_pair_contacts(double *sums, bool network);
  void sum_wall_contacts(double *sums, bool network);
  void count_particles(double *sums);
};

}    // namespace LAMMPS_NS

#endif
#endif
