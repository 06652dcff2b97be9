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

   The contact history of pair granular/grflow/kk: the per-neighbor values
   of the pair loop on the device, and the per-atom partner lists that
   carry them across neighbor list builds, atom sorting, migration between
   MPI ranks and restart files.

   Unlike fix NEIGH_HISTORY/KK of LAMMPS 4Feb2025, which negates every
   value when a pair changes owner (the default of fix NEIGH_HISTORY), a
   value k is multiplied by the factor the pair style's transfer_history()
   gives it (for granular/grflow: the sliding spring flips, the rolling
   and torsion springs keep their sign; GRFLOW::HISTORY_SWAP_FACTOR).  The
   factors are read from the pair style at init().

   The fix is created by the pair style; its style name is registered by
   the pair style (the CMake build of LAMMPS registers KOKKOS styles only
   as variants of existing styles), and the class is compiled in the pair
   style's translation unit (fix_neigh_history_grflow_kokkos_impl.h).
   Its per-atom restart data have the layout of fix NEIGH_HISTORY and the
   fix calls itself NEIGH_HISTORY, so that restart files carry the
   contact history between granular/grflow and granular/grflow/kk.

   Newton off only (the pair style checks it): every pair of an owned and
   a ghost atom is then computed and stored on both ranks, and nothing is
   sent back from ghosts.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_NEIGH_HISTORY_GRFLOW_KOKKOS_H
#define LMP_FIX_NEIGH_HISTORY_GRFLOW_KOKKOS_H

#include "fix_neigh_history.h"
#include "kokkos_base.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

struct TagFixNeighHistoryGRFLOWCount {};
struct TagFixNeighHistoryGRFLOWMax {};
struct TagFixNeighHistoryGRFLOWFill {};
struct TagFixNeighHistoryGRFLOWRestore {};
struct TagFixNeighHistoryGRFLOWPackExchange {};
struct TagFixNeighHistoryGRFLOWUnpackExchange {};

template <class DeviceType>
class FixNeighHistoryGRFLOWKokkos : public FixNeighHistory, public KokkosBase {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  // the most values per contact
  static constexpr int MAXDNUM = 16;

  FixNeighHistoryGRFLOWKokkos(class LAMMPS *, int, char **);
  ~FixNeighHistoryGRFLOWKokkos() override;

  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void post_neighbor() override;
  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  void sort_kokkos(Kokkos::BinSort<KeyViewType, BinOp> &) override;
  int pack_exchange_kokkos(const int &, DAT::tdual_xfloat_2d &, DAT::tdual_int_1d,
                           DAT::tdual_int_1d, ExecutionSpace) override;
  void unpack_exchange_kokkos(DAT::tdual_xfloat_2d &, DAT::tdual_int_1d &, int, int, int,
                              ExecutionSpace) override;

  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixNeighHistoryGRFLOWCount, const int &) const;
  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixNeighHistoryGRFLOWMax, const int &, int &) const;
  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixNeighHistoryGRFLOWFill, const int &) const;
  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixNeighHistoryGRFLOWRestore, const int &) const;
  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixNeighHistoryGRFLOWPackExchange, const int &, int &, const bool &) const;
  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixNeighHistoryGRFLOWUnpackExchange, const int &) const;

  // per neighbor of the pair style's list: touching flag and values (the
  // pair style reads and writes them; host row pointers in firstflag and
  // firstvalue of FixNeighHistory)
  DAT::tdual_int_2d k_firstflag;
  DAT::tdual_float_2d k_firstvalue;

  // number of neighbor list builds seen by post_neighbor()
  bigint nbuild;

 protected:
  // factor of each value when the owner of a pair changes
  double swap[MAXDNUM];
  int capacity;          // partners per atom the partner arrays hold
  int beyond_contact;    // of the pair style: history also for pairs not touching

  typename AT::t_tagint_1d d_tag;
  typename AT::t_neighbors_2d d_neighbors;
  typename AT::t_int_1d_randomread d_ilist;
  typename AT::t_int_1d_randomread d_numneigh;
  typename AT::t_int_2d d_firstflag;
  typename AT::t_float_2d d_firstvalue;

  // per atom: partners and their values, between pre_exchange() and
  // post_neighbor() (host pointers npartner, partner, valuepartner of
  // FixNeighHistory point into the host views)
  DAT::tdual_int_1d k_npartner;
  DAT::tdual_tagint_2d k_partner;
  DAT::tdual_float_2d k_valuepartner;
  typename AT::t_int_1d d_npartner;
  typename AT::t_tagint_2d d_partner;
  typename AT::t_float_2d d_valuepartner;

  // exchange buffers
  int nsend, nrecv1, nextrarecv1;
  typename AT::t_int_1d d_sendlist, d_copylist, d_indices;
  typename AT::t_xfloat_1d_um d_buf;
  typename AT::t_int_scalar d_count;

  void grow_capacity(int);
  void sync_partners_host();
  void modify_partners_host();

  KOKKOS_INLINE_FUNCTION
  int histmask(int j) const { return j >> HISTBITS & 1; }
};

}    // namespace LAMMPS_NS

#endif
