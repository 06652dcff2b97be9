// clang-format off
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
// clang-format on

/* ----------------------------------------------------------------------
   Contributing authors: GRFLOW developers

   The member functions of FixNeighHistoryGRFLOWKokkos, compiled in the
   translation unit of pair granular/grflow/kk, which creates the fix
   (fix_neigh_history_grflow_kokkos.h says why).  Include once.

   The per-atom partner lists hold, for each owned atom, the tag of every
   partner it touched at the last pre_exchange() and the history values
   as seen from the atom.  pre_exchange() fills them from the neighbor
   list: a pair (i,j) stored with i gives i the values as they are and j
   (when j is owned) the values times the transfer factors.  post_neighbor()
   puts them back into the new neighbor list.  In between they travel
   with their atoms (sorting, exchange between ranks, restart files).
------------------------------------------------------------------------- */

#include "fix_neigh_history_grflow_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory_kokkos.h"
#include "modify.h"
#include "neigh_list_kokkos.h"
#include "pair.h"

#include <cstring>

namespace LAMMPS_NS {

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixNeighHistoryGRFLOWKokkos<DeviceType>::FixNeighHistoryGRFLOWKokkos(LAMMPS *lmp, int narg,
                                                                     char **arg) :
    FixNeighHistory(lmp, narg, arg)
{
  kokkosable = 1;
  exchange_comm_device = 1;
  sort_device = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;

  if (dnum < 1 || dnum > MAXDNUM)
    error->all(FLERR, "Fix {} stores 1 to {} values per contact, not {}", style, MAXDNUM, dnum);

  // the per-atom restart data are those of fix NEIGH_HISTORY, and LAMMPS
  // gives restart data to a fix of the same ID and style: so that the
  // contact history goes between this fix and fix NEIGH_HISTORY of
  // granular/grflow, it carries that style name

  delete[] style;
  style = utils::strdup("NEIGH_HISTORY");

  // the host arrays of FixNeighHistory give way to DualViews

  memory->destroy(npartner);
  memory->sfree(partner);
  memory->sfree(valuepartner);
  npartner = nullptr;
  partner = nullptr;
  valuepartner = nullptr;

  for (int k = 0; k < MAXDNUM; k++) swap[k] = -1.0;
  beyond_contact = 0;
  nbuild = 0;
  nsend = nrecv1 = nextrarecv1 = 0;
  capacity = maxpartner = 8;
  grow_arrays(atom->nmax);

  d_count = typename AT::t_int_scalar("neighbor_history/grflow:count");
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> FixNeighHistoryGRFLOWKokkos<DeviceType>::~FixNeighHistoryGRFLOWKokkos()
{
  if (copymode) return;

  memoryKK->destroy_kokkos(k_npartner, npartner);
  memoryKK->destroy_kokkos(k_partner, partner);
  memoryKK->destroy_kokkos(k_valuepartner, valuepartner);
  memoryKK->destroy_kokkos(k_firstflag, firstflag);
  memoryKK->destroy_kokkos(k_firstvalue, firstvalue);
}

/* ----------------------------------------------------------------------
   checks of FixNeighHistory::init() (no memory pages: the values live in
   DualViews), and the transfer factors of the pair style
------------------------------------------------------------------------- */

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::init()
{
  if (atom->tag_enable == 0) error->all(FLERR, "Neighbor history requires that atoms have IDs");

  for (const auto &ifix : modify->get_fix_list()) {
    if (ifix == this) break;
    if (ifix->pre_exchange_migrate)
      error->all(FLERR,
                 "Pair styles using neighbor history must be defined before "
                 "fix {} {} which migrates atoms in pre_exchange",
                 ifix->id, ifix->style);
  }
  if (!pair) error->all(FLERR, "Fix {} {} has no pair style", id, style);

  newton_pair = force->newton_pair;
  if (newton_pair)
    error->all(FLERR,
               "The KOKKOS contact history of pair style {} requires newton pair off "
               "(no partner data are sent back from ghost atoms)",
               force->pair_style);

  // factor of each value when a pair changes owner: what the pair style's
  // transfer_history() makes of a 1 (values are transferred one by one,
  // e.g. granular/grflow: -1 for the sliding spring, +1 for rolling and
  // torsion), or -1 for every value if it keeps the default transfer

  for (int k = 0; k < MAXDNUM; k++) swap[k] = -1.0;
  if (pair->nondefault_history_transfer) {
    double one[MAXDNUM], out[MAXDNUM];
    for (int k = 0; k < dnum; k++) one[k] = 1.0;
    pair->transfer_history(one, out, 1, 1);
    for (int k = 0; k < dnum; k++) swap[k] = out[k];
  }
  beyond_contact = pair->beyond_contact;
}

/* ----------------------------------------------------------------------
   before the exchange of a run's setup: partner arrays as wide on every
   rank, so that the atoms a rank receives fit in its arrays
------------------------------------------------------------------------- */

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::setup_pre_exchange()
{
  int all;
  MPI_Allreduce(&capacity, &all, 1, MPI_INT, MPI_MAX, world);
  if (all > capacity) grow_capacity(all);
  maxexchange = (dnum + 1) * capacity + 2;
}

/* ----------------------------------------------------------------------
   neighbor list -> per-atom partner lists, on the device (newton off)
------------------------------------------------------------------------- */

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::pre_exchange()
{
  if (onesided) error->all(FLERR, "Fix {} has no one-sided exchange (line/tri history)", style);
  if (newton_pair)
    error->all(FLERR, "The KOKKOS contact history of pair style {} requires newton pair off",
               force->pair_style);

  // nlocal_neigh <= nlocal: the list was built with nlocal_neigh owned atoms,
  // other fixes may have added atoms in their pre_exchange()

  auto k_list = static_cast<NeighListKokkos<DeviceType> *>(pair->list);
  const int inum = pair->list->inum;
  d_ilist = k_list->d_ilist;
  d_numneigh = k_list->d_numneigh;
  d_neighbors = k_list->d_neighbors;

  atomKK->sync(execution_space, TAG_MASK);
  d_tag = atomKK->k_tag.template view<DeviceType>();
  k_firstflag.template sync<DeviceType>();
  k_firstvalue.template sync<DeviceType>();
  d_firstflag = k_firstflag.template view<DeviceType>();
  d_firstvalue = k_firstvalue.template view<DeviceType>();

  // the old partner lists are overwritten, wherever they were last changed

  k_npartner.clear_sync_state();
  k_partner.clear_sync_state();
  k_valuepartner.clear_sync_state();
  d_npartner = k_npartner.template view<DeviceType>();

  copymode = 1;

  // count the partners of each atom, widen the arrays to the most on any rank

  Kokkos::deep_copy(d_npartner, 0);
  if (inum > 0)
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType, TagFixNeighHistoryGRFLOWCount>(0, inum),
                         *this);
  int most = 0;
  if (nlocal_neigh > 0)
    Kokkos::parallel_reduce(
        Kokkos::RangePolicy<DeviceType, TagFixNeighHistoryGRFLOWMax>(0, nlocal_neigh), *this,
        Kokkos::Max<int>(most));
  int mostall;
  MPI_Allreduce(&most, &mostall, 1, MPI_INT, MPI_MAX, world);
  if (mostall > capacity) grow_capacity(mostall);
  d_partner = k_partner.template view<DeviceType>();
  d_valuepartner = k_valuepartner.template view<DeviceType>();

  // fill them

  Kokkos::deep_copy(d_npartner, 0);
  if (inum > 0)
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType, TagFixNeighHistoryGRFLOWFill>(0, inum),
                         *this);

  copymode = 0;

  k_npartner.template modify<DeviceType>();
  k_partner.template modify<DeviceType>();
  k_valuepartner.template modify<DeviceType>();

  maxexchange = (dnum + 1) * capacity + 2;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
KOKKOS_INLINE_FUNCTION void
FixNeighHistoryGRFLOWKokkos<DeviceType>::operator()(TagFixNeighHistoryGRFLOWCount,
                                                    const int &ii) const
{
  const int i = d_ilist[ii];
  const int jnum = d_numneigh[i];
  int mine = 0;
  for (int jj = 0; jj < jnum; jj++) {
    if (!d_firstflag(i, jj)) continue;
    mine++;
    const int j = d_neighbors(i, jj) & NEIGHMASK;
    if (j < nlocal_neigh) Kokkos::atomic_inc(&d_npartner(j));
  }
  if (mine) Kokkos::atomic_add(&d_npartner(i), mine);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
KOKKOS_INLINE_FUNCTION void
FixNeighHistoryGRFLOWKokkos<DeviceType>::operator()(TagFixNeighHistoryGRFLOWMax, const int &i,
                                                    int &most) const
{
  if (d_npartner(i) > most) most = d_npartner(i);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
KOKKOS_INLINE_FUNCTION void
FixNeighHistoryGRFLOWKokkos<DeviceType>::operator()(TagFixNeighHistoryGRFLOWFill,
                                                    const int &ii) const
{
  const int i = d_ilist[ii];
  const int jnum = d_numneigh[i];
  for (int jj = 0; jj < jnum; jj++) {
    if (!d_firstflag(i, jj)) continue;
    const int j = d_neighbors(i, jj) & NEIGHMASK;
    int m = Kokkos::atomic_fetch_add(&d_npartner(i), 1);
    d_partner(i, m) = d_tag(j);
    for (int k = 0; k < dnum; k++) d_valuepartner(i, dnum * m + k) = d_firstvalue(i, dnum * jj + k);
    if (j < nlocal_neigh) {
      m = Kokkos::atomic_fetch_add(&d_npartner(j), 1);
      d_partner(j, m) = d_tag(i);
      for (int k = 0; k < dnum; k++)
        d_valuepartner(j, dnum * m + k) = swap[k] * d_firstvalue(i, dnum * jj + k);
    }
  }
}

/* ----------------------------------------------------------------------
   per-atom partner lists -> the neighbor list just built
------------------------------------------------------------------------- */

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::post_neighbor()
{
  auto k_list = static_cast<NeighListKokkos<DeviceType> *>(pair->list);
  const int inum = pair->list->inum;
  d_ilist = k_list->d_ilist;
  d_numneigh = k_list->d_numneigh;
  d_neighbors = k_list->d_neighbors;

  atomKK->sync(execution_space, TAG_MASK);
  d_tag = atomKK->k_tag.template view<DeviceType>();
  k_npartner.template sync<DeviceType>();
  k_partner.template sync<DeviceType>();
  k_valuepartner.template sync<DeviceType>();
  d_npartner = k_npartner.template view<DeviceType>();
  d_partner = k_partner.template view<DeviceType>();
  d_valuepartner = k_valuepartner.template view<DeviceType>();

  const int nlocal = atom->nlocal;
  nlocal_neigh = nlocal;
  nall_neigh = nlocal + atom->nghost;
  beyond_contact = pair->beyond_contact;

  // per-neighbor arrays as large as the list (host row pointers firstflag
  // and firstvalue for single())

  const int maxneighs = d_neighbors.extent(1);
  if ((int) k_firstflag.extent(0) < nlocal || (int) k_firstflag.extent(1) < maxneighs) {
    maxatom = MAX(atom->nmax, nlocal);
    memoryKK->destroy_kokkos(k_firstflag, firstflag);
    memoryKK->destroy_kokkos(k_firstvalue, firstvalue);
    memoryKK->create_kokkos(k_firstflag, firstflag, maxatom, maxneighs,
                            "neighbor_history/grflow:firstflag");
    memoryKK->create_kokkos(k_firstvalue, firstvalue, maxatom, dnum * maxneighs,
                            "neighbor_history/grflow:firstvalue");
  }
  // every entry of the list is written below
  k_firstflag.clear_sync_state();
  k_firstvalue.clear_sync_state();
  d_firstflag = k_firstflag.template view<DeviceType>();
  d_firstvalue = k_firstvalue.template view<DeviceType>();

  copymode = 1;
  if (inum > 0)
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType, TagFixNeighHistoryGRFLOWRestore>(0, inum),
                         *this);
  copymode = 0;

  k_firstflag.template modify<DeviceType>();
  k_firstvalue.template modify<DeviceType>();
  nbuild++;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
KOKKOS_INLINE_FUNCTION void
FixNeighHistoryGRFLOWKokkos<DeviceType>::operator()(TagFixNeighHistoryGRFLOWRestore,
                                                    const int &ii) const
{
  const int i = d_ilist[ii];
  const int jnum = d_numneigh[i];
  const int np = d_npartner(i);

  for (int jj = 0; jj < jnum; jj++) {
    int j = d_neighbors(i, jj);

    // a partner is looked for only where the list builder saw an overlap
    // (or the pair style keeps history beyond contact)
    const int rflag = use_bit_flag ? (histmask(j) | beyond_contact) : 1;
    j &= NEIGHMASK;

    int m = np;
    if (rflag) {
      const tagint jtag = d_tag(j);
      for (m = 0; m < np; m++)
        if (d_partner(i, m) == jtag) break;
    }
    if (m < np) {
      d_firstflag(i, jj) = 1;
      for (int k = 0; k < dnum; k++)
        d_firstvalue(i, dnum * jj + k) = d_valuepartner(i, dnum * m + k);
    } else {
      d_firstflag(i, jj) = 0;
      for (int k = 0; k < dnum; k++) d_firstvalue(i, dnum * jj + k) = 0.0;
    }
  }
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> double FixNeighHistoryGRFLOWKokkos<DeviceType>::memory_usage()
{
  double bytes = MemKK::memory_usage(k_npartner.d_view);
  bytes += MemKK::memory_usage(k_partner.d_view);
  bytes += MemKK::memory_usage(k_valuepartner.d_view);
  bytes += MemKK::memory_usage(k_firstflag.d_view);
  bytes += MemKK::memory_usage(k_firstvalue.d_view);
  return bytes;
}

/* ----------------------------------------------------------------------
   per-atom arrays for nmax atoms
------------------------------------------------------------------------- */

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::grow_arrays(int nmax)
{
  memoryKK->grow_kokkos(k_npartner, npartner, nmax, "neighbor_history/grflow:npartner");
  memoryKK->grow_kokkos(k_partner, partner, nmax, capacity, "neighbor_history/grflow:partner");
  memoryKK->grow_kokkos(k_valuepartner, valuepartner, nmax, dnum * capacity,
                        "neighbor_history/grflow:valuepartner");
  d_npartner = k_npartner.template view<DeviceType>();
  d_partner = k_partner.template view<DeviceType>();
  d_valuepartner = k_valuepartner.template view<DeviceType>();
}

/* ----------------------------------------------------------------------
   room for n partners per atom (contents kept)
------------------------------------------------------------------------- */

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::grow_capacity(int n)
{
  if (n <= capacity) return;
  capacity = maxpartner = n;
  const int nmax = k_npartner.extent(0);
  memoryKK->grow_kokkos(k_partner, partner, nmax, capacity, "neighbor_history/grflow:partner");
  memoryKK->grow_kokkos(k_valuepartner, valuepartner, nmax, dnum * capacity,
                        "neighbor_history/grflow:valuepartner");
  d_partner = k_partner.template view<DeviceType>();
  d_valuepartner = k_valuepartner.template view<DeviceType>();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::sync_partners_host()
{
  k_npartner.sync_host();
  k_partner.sync_host();
  k_valuepartner.sync_host();
}

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::modify_partners_host()
{
  k_npartner.modify_host();
  k_partner.modify_host();
  k_valuepartner.modify_host();
}

/* ----------------------------------------------------------------------
   copy the partners of atom i to atom j (host, classic sort and exchange)
------------------------------------------------------------------------- */

template <class DeviceType>
void FixNeighHistoryGRFLOWKokkos<DeviceType>::copy_arrays(int i, int j, int /*delflag*/)
{
  sync_partners_host();
  const int n = npartner[i];
  npartner[j] = n;
  for (int m = 0; m < n; m++) partner[j][m] = partner[i][m];
  for (int m = 0; m < dnum * n; m++) valuepartner[j][m] = valuepartner[i][m];
  modify_partners_host();
}

/* ----------------------------------------------------------------------
   a new atom has no partners
------------------------------------------------------------------------- */

template <class DeviceType> void FixNeighHistoryGRFLOWKokkos<DeviceType>::set_arrays(int i)
{
  sync_partners_host();
  npartner[i] = 0;
  modify_partners_host();
}

/* ----------------------------------------------------------------------
   the partners of atom i for another rank (host, classic exchange), in the
   layout of FixNeighHistory::pack_exchange()
------------------------------------------------------------------------- */

template <class DeviceType>
int FixNeighHistoryGRFLOWKokkos<DeviceType>::pack_exchange(int i, double *buf)
{
  sync_partners_host();
  int m = 0;
  const int n = npartner[i];
  buf[m++] = n;
  for (int p = 0; p < n; p++) {
    buf[m++] = ubuf(partner[i][p]).d;
    for (int k = 0; k < dnum; k++) buf[m++] = valuepartner[i][dnum * p + k];
  }
  return m;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
int FixNeighHistoryGRFLOWKokkos<DeviceType>::unpack_exchange(int nlocal, double *buf)
{
  sync_partners_host();
  int m = 0;
  const int n = static_cast<int>(buf[m++]);
  if (n > capacity) grow_capacity(n);
  npartner[nlocal] = n;
  for (int p = 0; p < n; p++) {
    partner[nlocal][p] = static_cast<tagint>(ubuf(buf[m++]).i);
    for (int k = 0; k < dnum; k++) valuepartner[nlocal][dnum * p + k] = buf[m++];
  }
  modify_partners_host();
  return m;
}

/* ----------------------------------------------------------------------
   restart data of atom i, in the layout of FixNeighHistory::pack_restart()
   (the partner lists are current: write_restart() called pre_exchange())
------------------------------------------------------------------------- */

template <class DeviceType>
int FixNeighHistoryGRFLOWKokkos<DeviceType>::pack_restart(int i, double *buf)
{
  sync_partners_host();
  int m = 1;
  const int n = npartner[i];
  buf[m++] = n;
  for (int p = 0; p < n; p++) {
    buf[m++] = ubuf(partner[i][p]).d;
    for (int k = 0; k < dnum; k++) buf[m++] = valuepartner[i][dnum * p + k];
  }
  buf[0] = m;
  return m;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
void FixNeighHistoryGRFLOWKokkos<DeviceType>::unpack_restart(int nlocal, int nth)
{
  sync_partners_host();

  // skip to the nth set of values, then the layout of pack_restart()
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;

  const int n = static_cast<int>(extra[nlocal][m++]);
  if (n > capacity) grow_capacity(n);
  npartner[nlocal] = n;
  for (int p = 0; p < n; p++) {
    partner[nlocal][p] = static_cast<tagint>(ubuf(extra[nlocal][m++]).i);
    for (int k = 0; k < dnum; k++) valuepartner[nlocal][dnum * p + k] = extra[nlocal][m++];
  }
  modify_partners_host();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> int FixNeighHistoryGRFLOWKokkos<DeviceType>::size_restart(int nlocal)
{
  sync_partners_host();
  return (dnum + 1) * npartner[nlocal] + 2;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> int FixNeighHistoryGRFLOWKokkos<DeviceType>::maxsize_restart()
{
  int all;
  MPI_Allreduce(&capacity, &all, 1, MPI_INT, MPI_MAX, world);
  return (dnum + 1) * all + 2;
}

/* ----------------------------------------------------------------------
   atom sorting on the device: the partner lists move with their atoms
------------------------------------------------------------------------- */

template <class DeviceType>
void FixNeighHistoryGRFLOWKokkos<DeviceType>::sort_kokkos(
    Kokkos::BinSort<KeyViewType, BinOp> &Sorter)
{
  k_npartner.sync_device();
  k_partner.sync_device();
  k_valuepartner.sync_device();

  Sorter.sort(LMPDeviceType(), k_npartner.d_view);
  Sorter.sort(LMPDeviceType(), k_partner.d_view);
  Sorter.sort(LMPDeviceType(), k_valuepartner.d_view);

  k_npartner.modify_device();
  k_partner.modify_device();
  k_valuepartner.modify_device();
}

/* ----------------------------------------------------------------------
   exchange on the device: the partners of the atoms in k_sendlist into
   k_buf (an offset per atom, then the data: n, then tag and values of each
   partner), and the atoms of k_copylist moved into the holes they leave.
   The layout and the hole filling are what CommKokkos's exchange on the
   device asks of a fix, and so the same as in LAMMPS's fix
   neigh/history/kk (fix_neigh_history_kokkos.cpp), whose pack and unpack
   this follows in one scan; the values are GRFLOW's springs as they are
------------------------------------------------------------------------- */

template <class DeviceType>
int FixNeighHistoryGRFLOWKokkos<DeviceType>::pack_exchange_kokkos(const int &nsend_in,
                                                                  DAT::tdual_xfloat_2d &k_buf,
                                                                  DAT::tdual_int_1d k_sendlist,
                                                                  DAT::tdual_int_1d k_copylist,
                                                                  ExecutionSpace /*space*/)
{
  k_npartner.template sync<DeviceType>();
  k_partner.template sync<DeviceType>();
  k_valuepartner.template sync<DeviceType>();
  d_npartner = k_npartner.template view<DeviceType>();
  d_partner = k_partner.template view<DeviceType>();
  d_valuepartner = k_valuepartner.template view<DeviceType>();

  k_buf.template sync<DeviceType>();
  k_sendlist.template sync<DeviceType>();
  k_copylist.template sync<DeviceType>();
  d_sendlist = k_sendlist.template view<DeviceType>();
  d_copylist = k_copylist.template view<DeviceType>();
  d_buf = typename AT::t_xfloat_1d_um(k_buf.template view<DeviceType>().data(),
                                      k_buf.extent(0) * k_buf.extent(1));
  nsend = nsend_in;

  Kokkos::deep_copy(d_count, 0);
  copymode = 1;
  if (nsend > 0)
    Kokkos::parallel_scan(
        Kokkos::RangePolicy<DeviceType, TagFixNeighHistoryGRFLOWPackExchange>(0, nsend), *this);
  copymode = 0;

  // (k_buf is not marked: CommKokkos sends its device data as they are)
  k_npartner.template modify<DeviceType>();
  k_partner.template modify<DeviceType>();
  k_valuepartner.template modify<DeviceType>();

  int count = 0;
  Kokkos::deep_copy(count, d_count);
  return count;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
KOKKOS_INLINE_FUNCTION void FixNeighHistoryGRFLOWKokkos<DeviceType>::operator()(
    TagFixNeighHistoryGRFLOWPackExchange, const int &isend, int &offset, const bool &final) const
{
  const int i = d_sendlist(isend);
  const int n = d_npartner(i);
  if (!final) {
    offset += 1 + n * (dnum + 1);
    return;
  }

  int m = nsend + offset;
  d_buf(isend) = d_ubuf(m).d;
  d_buf(m++) = n;
  for (int p = 0; p < n; p++) {
    d_buf(m++) = d_ubuf(d_partner(i, p)).d;
    for (int k = 0; k < dnum; k++) d_buf(m++) = d_valuepartner(i, dnum * p + k);
  }
  if (isend == nsend - 1) d_count() = m;
  offset = m - nsend;

  // the atom that fills the hole of i
  const int j = d_copylist(isend);
  if (j > -1) {
    const int nj = d_npartner(j);
    d_npartner(i) = nj;
    for (int p = 0; p < nj; p++) {
      d_partner(i, p) = d_partner(j, p);
      for (int k = 0; k < dnum; k++)
        d_valuepartner(i, dnum * p + k) = d_valuepartner(j, dnum * p + k);
    }
  }
}

/* ----------------------------------------------------------------------
   the partners of the atoms received, from the one or two messages in
   k_buf (the second starts at nextrarecv1_in, its atoms at nrecv1_in)
------------------------------------------------------------------------- */

template <class DeviceType>
void FixNeighHistoryGRFLOWKokkos<DeviceType>::unpack_exchange_kokkos(DAT::tdual_xfloat_2d &k_buf,
                                                                     DAT::tdual_int_1d &k_indices,
                                                                     int nrecv, int nrecv1_in,
                                                                     int nextrarecv1_in,
                                                                     ExecutionSpace /*space*/)
{
  // the message is in the device view of k_buf (received there by MPI)
  d_buf = typename AT::t_xfloat_1d_um(k_buf.template view<DeviceType>().data(),
                                      k_buf.extent(0) * k_buf.extent(1));
  d_indices = k_indices.template view<DeviceType>();
  nrecv1 = nrecv1_in;
  nextrarecv1 = nextrarecv1_in;

  k_npartner.template sync<DeviceType>();
  k_partner.template sync<DeviceType>();
  k_valuepartner.template sync<DeviceType>();
  d_npartner = k_npartner.template view<DeviceType>();
  d_partner = k_partner.template view<DeviceType>();
  d_valuepartner = k_valuepartner.template view<DeviceType>();

  copymode = 1;
  if (nrecv > 0)
    Kokkos::parallel_for(
        Kokkos::RangePolicy<DeviceType, TagFixNeighHistoryGRFLOWUnpackExchange>(0, nrecv), *this);
  copymode = 0;

  k_npartner.template modify<DeviceType>();
  k_partner.template modify<DeviceType>();
  k_valuepartner.template modify<DeviceType>();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
KOKKOS_INLINE_FUNCTION void
FixNeighHistoryGRFLOWKokkos<DeviceType>::operator()(TagFixNeighHistoryGRFLOWUnpackExchange,
                                                    const int &irecv) const
{
  const int index = d_indices(irecv);
  if (index < 0) return;

  int m;
  if (irecv < nrecv1)
    m = (int) d_ubuf(d_buf(irecv)).i;
  else
    m = nextrarecv1 + (int) d_ubuf(d_buf(nextrarecv1 + irecv - nrecv1)).i;

  const int n = static_cast<int>(d_buf(m++));
  d_npartner(index) = n;
  for (int p = 0; p < n; p++) {
    d_partner(index, p) = (tagint) d_ubuf(d_buf(m++)).i;
    for (int k = 0; k < dnum; k++) d_valuepartner(index, dnum * p + k) = d_buf(m++);
  }
}

}    // namespace LAMMPS_NS
