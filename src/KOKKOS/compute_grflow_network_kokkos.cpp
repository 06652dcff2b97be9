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
   Contributing authors: GRFLOW developers

   KOKKOS variant of compute grflow/network: the sums over this
   processor's contacts and particles (GRFLOW::NetworkSums of
   grflow_network.h, the functions the plain compute calls) on the device,
   as device reductions whose results come to the host once per call.
   The contacts are those of pair granular/grflow/kk: its neighbor list,
   contact history and coefficients, with the force of each contact from
   contact_forces() of grflow_contact.h as the plain compute has it from
   Pair::single(); wall contacts are the records of fix grflow/wall/kk on
   the device (extract("grflow/wall_contacts/kk")).

   With newton pair off (the KOKKOS pair style's only setting) a contact
   of an owned atom with a ghost is counted at the owned end only, so
   neither the inside flags of ghosts nor the contact counts of ghosts are
   needed: no forward or reverse communication beyond the ghosts' state.
------------------------------------------------------------------------- */

#include "compute_grflow_network_kokkos.h"

#include "pair_granular_grflow_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "memory_kokkos.h"
#include "neigh_list_kokkos.h"
#include "update.h"

#include "grflow_contact.h"
#include "grflow_network.h"
#include "grflow_wall.h"
#include "grflow_wall_contacts_kokkos.h"

using namespace LAMMPS_NS;

namespace {

typedef GRFLOW::NetworkSums NS;

/* ----------------------------------------------------------------------
   a reduction into one array of NetworkSums::size(cmax) doubles
------------------------------------------------------------------------- */

struct NetworkArrayReduction {
  typedef double value_type[];
  unsigned value_count;

  KOKKOS_INLINE_FUNCTION void init(value_type sums) const
  {
    for (unsigned k = 0; k < value_count; k++) sums[k] = 0.0;
  }
  KOKKOS_INLINE_FUNCTION void join(value_type dst, const value_type src) const
  {
    for (unsigned k = 0; k < value_count; k++) dst[k] += src[k];
  }
};

/* ----------------------------------------------------------------------
   owned atom i: inside the slab lo <= z < hi and in the group (the plain
   compute's NetworkVolume::flag_slab()), no contacts counted yet
------------------------------------------------------------------------- */

template <class DeviceType> struct NetworkInside {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  typename AT::t_x_array_randomread x;
  typename AT::t_int_1d_randomread mask;
  typename AT::t_float_1d inside;
  typename AT::t_float_1d ncontact;
  int groupbit;
  bool zperiodic;
  double lo, hi, boxlo, boxhi, zprd;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    inside(i) = GRFLOW::NetworkVolume::in_slab(x(i, 2), mask(i), groupbit, lo, hi, zperiodic, boxlo,
                                               boxhi, zprd);
    ncontact(i) = 0.0;
  }
};

/* ----------------------------------------------------------------------
   particle-particle contacts of owned atom ilist[ii] (the plain compute's
   sum_pair_contacts() with newton off): the ends inside, their arms and
   n (x) f, n (x) n, and (network) the contact counts of owned atoms.
   network is a run-time flag, not a template parameter: the stress path
   and the whole vector run the same kernel, launched alike, so that their
   stress sums are added in the same order (on a GPU too), as the plain
   compute promises
------------------------------------------------------------------------- */

template <class DeviceType> struct NetworkPairSums : NetworkArrayReduction {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v;
  typename AT::t_v_array_randomread omega;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_int_1d_randomread type;
  typename AT::t_neighbors_2d d_neighbors;
  typename AT::t_int_1d_randomread d_ilist;
  typename AT::t_int_1d_randomread d_numneigh;
  typename AT::t_float_2d d_firsthistory;
  typename PairGranularGRFLOWKernel<DeviceType>::tdual_coeff_2d::t_dev_const_randomread d_coeff;
  typename AT::t_float_1d inside;
  typename AT::t_float_1d ncontact;
  int nlocal, full_arm, network;
  double dt;
  double weight_lj[4];

  KOKKOS_INLINE_FUNCTION void operator()(const int ii, value_type sums) const
  {
    using namespace GRFLOW;
    const int i = d_ilist(ii);
    const bool inside_i = inside(i) > 0.0;
    const double radi = radius(i);
    const int jnum = d_numneigh(i);

    for (int jj = 0; jj < jnum; jj++) {
      int j = d_neighbors(i, jj);
      const double factor = weight_lj[j >> SBBITS & 3];
      j &= NEIGHMASK;
      if (factor == 0.0) continue;

      // newton off: a ghost's end is counted by its owner
      const bool j_owned = j < nlocal;
      bool use_i, use_j;
      NS::count_ends(inside_i, j_owned && inside(j) > 0.0, j_owned, false, use_i, use_j);
      if (!use_i && !use_j) continue;

      const double del[3] = {x(i, 0) - x(j, 0), x(i, 1) - x(j, 1), x(i, 2) - x(j, 2)};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const double radj = radius(j);
      const double radsum = radi + radj;
      if (rsq >= radsum * radsum || rsq == 0.0) continue;

      // the force of the contact as Pair::single() gives it: the normal
      // force along del and the sliding force (no history update)
      const double r = sqrt(rsq);
      ContactGeometry g;
      pair_geometry(del, r, radi, radj, full_arm != 0, g);
      const double vrel[3] = {v(i, 0) - v(j, 0), v(i, 1) - v(j, 1), v(i, 2) - v(j, 2)};
      const double wi[3] = {omega(i, 0), omega(i, 1), omega(i, 2)};
      const double wj[3] = {omega(j, 0), omega(j, 1), omega(j, 2)};
      double hist[HIST_SIZE];
      for (int k = 0; k < HIST_SIZE; k++) hist[k] = d_firsthistory(i, HIST_SIZE * jj + k);
      ContactForces out;
      contact_forces(d_coeff(type(i), type(j)), g, vrel, wi, wj, dt, false, hist, out);
      const double fpair = factor * out.fn / r;
      // touching but carrying no normal force: not a contact of the network
      if (fpair <= 0.0) continue;

      double n[3], f[3];
      for (int k = 0; k < 3; k++) {
        n[k] = del[k] / r;
        f[k] = fpair * del[k] + factor * out.ft[k];
      }
      const double delta = radi + radj - r;
      if (network) {
        if (use_i) Kokkos::atomic_add(&ncontact(i), 1.0);
        if (use_j) Kokkos::atomic_add(&ncontact(j), 1.0);
      }
      NS::add_pair_contact(sums, n, f, delta, radi, radj, use_i, use_j, network != 0);
    }
  }
};

/* ----------------------------------------------------------------------
   contacts of owned atom i inside with the walls of one fix (the plain
   compute's add_wall_contacts()): records of nwall walls per atom
------------------------------------------------------------------------- */

template <class DeviceType> struct NetworkWallSums : NetworkArrayReduction {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef GRFLOW::WallContacts C;

  typename AT::t_float_1d inside;
  typename AT::t_float_1d ncontact;
  typename AT::t_float_2d records;
  int nwall, network;
  double normal[2];

  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type sums) const
  {
    if (inside(i) <= 0.0) return;
    for (int w = 0; w < nwall; w++) {
      const double arm = records(i, C::REC_SIZE * w + C::REC_ARM);
      if (arm <= 0.0) continue;
      double force[3];
      for (int k = 0; k < 3; k++) force[k] = records(i, C::REC_SIZE * w + C::REC_FORCE + k);
      if (network) {
        ncontact(i) += 1.0;
        NS::add_wall_contact(sums, normal[w], force, arm);
      } else {
        NS::add_wall_stress(sums, normal[w], force, arm);
      }
    }
  }
};

/* ----------------------------------------------------------------------
   owned atom i inside with its contacts (the plain compute's
   add_particles())
------------------------------------------------------------------------- */

template <class DeviceType> struct NetworkParticleSums : NetworkArrayReduction {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  typename AT::t_float_1d inside;
  typename AT::t_float_1d ncontact;
  int cmax;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type sums) const
  {
    if (inside(i) > 0.0) NS::add_particle(sums, (int) ncontact(i), cmax);
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
ComputeGRFLOWNetworkKokkos<DeviceType>::ComputeGRFLOWNetworkKokkos(LAMMPS *lmp, int narg,
                                                                   char **arg) :
    ComputeGRFLOWNetwork(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | RADIUS_MASK | TYPE_MASK | MASK_MASK;
  datamask_modify = EMPTY_MASK;

  // the sub-volume on the device is the slab of zlimits (or of the box)
  if (!opt->region.empty())
    error->all(FLERR,
               "Compute grflow/network/kk takes no region keyword (its sub-volume on the device is "
               "a slab: use slab and zlimits), or use compute grflow/network with pair style "
               "granular/grflow");
}

/* ----------------------------------------------------------------------
   the plain compute's checks, then what the sums on the device need: pair
   granular/grflow/kk on this device, newton off, walls on the device
------------------------------------------------------------------------- */

template <class DeviceType> void ComputeGRFLOWNetworkKokkos<DeviceType>::check_setup()
{
  ComputeGRFLOWNetwork::check_setup();

  if (!dynamic_cast<PairGranularGRFLOWKokkos<DeviceType> *>(force->pair))
    error->all(FLERR,
               "Compute {} (grflow/network/kk) requires pair style granular/grflow/kk on the same "
               "Kokkos device, not {}: use -sf kk for both, or compute grflow/network",
               id, force->pair_style);
  if (force->newton_pair)
    error->all(FLERR, "Compute {} (grflow/network/kk) requires newton pair off", id);

  for (int k = 0; k < nwall_fixes(); k++) {
    Fix *wfix = wall_fix(k);
    int dim = -1;
    if (!wfix->extract("grflow/wall_contacts/kk", dim))
      error->all(FLERR,
                 "Compute {} (grflow/network/kk): fix {} ({}) keeps its wall contacts on the host: "
                 "use fix grflow/wall/kk (-sf kk)",
                 id, wfix->id, wfix->style);
  }
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void ComputeGRFLOWNetworkKokkos<DeviceType>::require_pair_list()
{
  auto *pairKK = dynamic_cast<PairGranularGRFLOWKokkos<DeviceType> *>(force->pair);
  if (!pairKK || !pairKK->contact_data())
    error->all(FLERR,
               "Compute {} (grflow/network/kk) needs the pair style's neighbor list: use it after "
               "a run (run 0 will do)",
               id);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
bigint ComputeGRFLOWNetworkKokkos<DeviceType>::wall_contacts_step(Fix *wfix)
{
  int dim = -1;
  auto *offered =
      static_cast<GRFLOW::WallContactsKokkos *>(wfix->extract("grflow/wall_contacts/kk", dim));
  return offered->contacts->step;
}

/* ----------------------------------------------------------------------
   this processor's sums (zeroed by the caller), in the order of the plain
   compute: pair contacts, wall contacts of each fix, particles; returns
   the volume of the sub-volume
------------------------------------------------------------------------- */

template <class DeviceType>
double ComputeGRFLOWNetworkKokkos<DeviceType>::local_sums(double *sums, bool network)
{
  // ghosts as the pair style sees them (ComputeGRFLOWNetwork says why)
  comm->forward_comm();

  double lo, hi;
  const double volume = slab_volume(lo, hi);
  check_volume(volume);

  const int nlocal = atom->nlocal;
  if ((int) d_inside.extent(0) < atom->nmax) {
    d_inside = typename AT::t_float_1d("grflow/network/kk:inside", atom->nmax);
    d_ncontact = typename AT::t_float_1d("grflow/network/kk:ncontact", atom->nmax);
  }
  const int nsums = GRFLOW::NetworkSums::size(opt->cmax);
  const int nwall = nwall_fixes();
  const int nrow = 1 + nwall + 1;
  if ((int) d_sums.extent(0) != nrow || (int) d_sums.extent(1) != nsums)
    d_sums = Kokkos::View<double **, Kokkos::LayoutRight, DeviceType>("grflow/network/kk:sums",
                                                                      nrow, nsums);
  Kokkos::deep_copy(d_sums, 0.0);

  atomKK->sync(execution_space, datamask_read);
  auto x = atomKK->k_x.template view<DeviceType>();

  // inside flags of owned atoms, contact counts zeroed
  if (nlocal > 0) {
    NetworkInside<DeviceType> s;
    s.x = x;
    s.mask = atomKK->k_mask.template view<DeviceType>();
    s.inside = d_inside;
    s.ncontact = d_ncontact;
    s.groupbit = groupbit;
    s.zperiodic = domain->zperiodic != 0;
    s.lo = lo;
    s.hi = hi;
    s.boxlo = domain->boxlo[2];
    s.boxhi = domain->boxhi[2];
    s.zprd = domain->zprd;
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), s);
  }

  // particle-particle contacts
  auto *pairKK = static_cast<PairGranularGRFLOWKokkos<DeviceType> *>(force->pair);
  const PairGranularGRFLOWKernel<DeviceType> &pk = *pairKK->contact_data();
  {
    NetworkPairSums<DeviceType> s;
    s.value_count = nsums;
    s.x = x;
    s.v = atomKK->k_v.template view<DeviceType>();
    s.omega = atomKK->k_omega.template view<DeviceType>();
    s.radius = atomKK->k_radius.template view<DeviceType>();
    s.type = atomKK->k_type.template view<DeviceType>();
    s.d_neighbors = pk.d_neighbors;
    s.d_ilist = pk.d_ilist;
    s.d_numneigh = pk.d_numneigh;
    s.d_firsthistory = pk.d_firsthistory;
    s.d_coeff = pk.d_coeff;
    s.inside = d_inside;
    s.ncontact = d_ncontact;
    s.nlocal = nlocal;
    s.full_arm = pk.full_arm;
    s.network = network ? 1 : 0;
    s.dt = pk.dt;
    for (int m = 0; m < 4; m++) s.weight_lj[m] = force->special_lj[m];
    if (pk.inum > 0)
      Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, pk.inum), s,
                              Kokkos::subview(d_sums, 0, Kokkos::ALL()));
  }

  // contacts with the walls of each fix, in the order of the fixes
  for (int k = 0; k < nwall; k++) {
    int dim = -1;
    auto *offered = static_cast<GRFLOW::WallContactsKokkos *>(
        wall_fix(k)->extract("grflow/wall_contacts/kk", dim));
    offered->records->template sync<DeviceType>();
    NetworkWallSums<DeviceType> s;
    s.value_count = nsums;
    s.inside = d_inside;
    s.ncontact = d_ncontact;
    s.records = offered->records->template view<DeviceType>();
    s.nwall = offered->contacts->nwall;
    s.network = network ? 1 : 0;
    for (int w = 0; w < 2; w++) s.normal[w] = offered->contacts->normal[w];
    if (nlocal > 0)
      Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nlocal), s,
                              Kokkos::subview(d_sums, 1 + k, Kokkos::ALL()));
  }

  // particles inside with their contact numbers
  if (network && nlocal > 0) {
    NetworkParticleSums<DeviceType> s;
    s.value_count = nsums;
    s.inside = d_inside;
    s.ncontact = d_ncontact;
    s.cmax = opt->cmax;
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nlocal), s,
                            Kokkos::subview(d_sums, nrow - 1, Kokkos::ALL()));
  }

  // one copy to the host, added in the plain compute's order
  auto h_sums = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), d_sums);
  for (int row = 0; row < nrow; row++)
    for (int m = 0; m < nsums; m++) sums[m] += h_sums(row, m);
  return volume;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> double ComputeGRFLOWNetworkKokkos<DeviceType>::memory_usage()
{
  double bytes = ComputeGRFLOWNetwork::memory_usage();
  bytes += MemKK::memory_usage(d_inside);
  bytes += MemKK::memory_usage(d_ncontact);
  bytes += MemKK::memory_usage(d_sums);
  return bytes;
}

namespace LAMMPS_NS {
template class ComputeGRFLOWNetworkKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class ComputeGRFLOWNetworkKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
