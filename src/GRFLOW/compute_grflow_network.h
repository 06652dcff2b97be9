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

namespace LAMMPS_NS {
namespace GRFLOW {
  struct NetworkOptions;
  struct NetworkWalls;
}    // namespace GRFLOW

// the positions of the output vector: GRFLOW::NetworkLayout (grflow_network.h)
class ComputeGRFLOWNetwork : public Compute {
 public:
  ComputeGRFLOWNetwork(class LAMMPS *, int, char **);
  ~ComputeGRFLOWNetwork() override;
  void init() override;
  void compute_vector() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // the compute grflow/network with ID id, for another command (caller,
  // e.g. "Fix grflow/shear"); an error otherwise
  static ComputeGRFLOWNetwork *find(class LAMMPS *lmp, const std::string &caller,
                                    const std::string &id);

  // the entries SXX..RU (the first NSTRESS of the vector) of this step,
  // for fixes that need no more (the reversal check of fix grflow/shear,
  // the servo of fix grflow/compress): the stress sums alone, without the
  // contact counts, fabric and P_c of the network quantities.
  // compute_stress() evaluates them; current_stress() reuses those of this
  // step (or of compute_vector() on this step) if there are any.  The same
  // to the bit as the vector's entries.
  const double *compute_stress();
  const double *current_stress();

  // the fixes whose wall contacts the sums include, in definition order
  int nwall_fixes() const;
  class Fix *wall_fix(int k) const;

 protected:
  GRFLOW::NetworkOptions *opt;    // the keywords (grflow_network.h)
  GRFLOW::NetworkWalls *walls;    // the fixes with wall contacts
  class Region *region;

  // the checks of init(), made again between runs; the pair style's list
  // and the step of a wall fix's contacts; the sums of evaluate()
  // (GRFLOW::NetworkSums) of this processor and the volume of the
  // sub-volume: the KOKKOS variant does them on the device
  virtual void check_setup();
  virtual void require_pair_list();
  virtual bigint wall_contacts_step(class Fix *);
  virtual double local_sums(double *sums, bool network);

  // the bounds lo <= z < hi and the volume of the slab (no region)
  double slab_volume(double &lo, double &hi);
  void check_volume(double volume);

 private:
  double *stress;    // compute_stress()'s entries, of step invoked_stress
  bigint invoked_stress;

  int nmax;
  double *inside;      // 1 if the atom is in the group and the sub-volume
  double *ncontact;    // force-bearing contacts per atom
  int commflag;

  double eval(const std::string &, const char *);
  void set_inside(double &volume);
  void require_current_contacts();
  void grow_peratom();
  double refresh_ghosts_and_inside();
  // the vector (network true) or the stress entries, into out
  void evaluate(bool network, double *out);
  // the sums of evaluate() (GRFLOW::NetworkSums), per processor; with
  // network false the stress sums only
  void sum_pair_contacts(double *sums, bool network);
  void sum_wall_contacts(double *sums, bool network);
  void count_particles(double *sums);
};

}    // namespace LAMMPS_NS

#endif
#endif
