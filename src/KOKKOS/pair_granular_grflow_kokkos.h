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
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(granular/grflow/kk,PairGranularGRFLOWKokkos<LMPDeviceType>);
PairStyle(granular/grflow/kk/device,PairGranularGRFLOWKokkos<LMPDeviceType>);
PairStyle(granular/grflow/kk/host,PairGranularGRFLOWKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_GRANULAR_GRFLOW_KOKKOS_H
#define LMP_PAIR_GRANULAR_GRFLOW_KOKKOS_H

#include "grflow_contact_coeffs.h"
#include "kokkos_type.h"
#include "pair_granular_grflow.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixNeighHistoryGRFLOWKokkos;

template <int NEIGHFLAG, int EVFLAG, int HISTUPDATE> struct TagPairGranularGRFLOWCompute {
};

/* ----------------------------------------------------------------------
   the pair loop on the device: what it reads and writes, copied into the
   kernels (not the pair style: PairGranularGRFLOW holds strings)
------------------------------------------------------------------------- */

template <class DeviceType> struct PairGranularGRFLOWKernel {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef EV_FLOAT value_type;
  typedef Kokkos::DualView<GRFLOW::ContactCoeffs **, Kokkos::LayoutRight, DeviceType>
      tdual_coeff_2d;

  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v;
  typename AT::t_v_array_randomread omega;
  typename AT::t_f_array f;
  typename AT::t_f_array torque;
  typename AT::t_int_1d_randomread type;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_efloat_1d d_eatom;
  typename AT::t_virial_array d_vatom;

  typename AT::t_neighbors_2d d_neighbors;
  typename AT::t_int_1d_randomread d_ilist;
  typename AT::t_int_1d_randomread d_numneigh;

  // touch flags and springs of each neighbor (the history fix's)
  typename AT::t_int_2d d_firsttouch;
  typename AT::t_float_2d d_firsthistory;

  // coefficients of each type pair
  typename tdual_coeff_2d::t_dev_const_randomread d_coeff;

  // one pair of atoms at the same position (no contact normal): flag, i, j
  typename AT::t_int_1d d_same;

  int inum, nlocal, full_arm, eflag, eflag_global, eflag_atom, vflag_either, vflag_global,
      vflag_atom;
  double dt;
  double weight_lj[4];    // force->special_lj (Pair::special_lj holds ints)

  template <int NEIGHFLAG, int EVFLAG, int HISTUPDATE>
  KOKKOS_INLINE_FUNCTION void
  operator()(TagPairGranularGRFLOWCompute<NEIGHFLAG, EVFLAG, HISTUPDATE>, const int,
             EV_FLOAT &) const;
  template <int NEIGHFLAG, int EVFLAG, int HISTUPDATE>
  KOKKOS_INLINE_FUNCTION void
  operator()(TagPairGranularGRFLOWCompute<NEIGHFLAG, EVFLAG, HISTUPDATE>, const int) const;

  template <int NEIGHFLAG>
  KOKKOS_INLINE_FUNCTION void ev_tally(EV_FLOAT &, const int, const int, const double,
                                       const double *, const double *) const;

  KOKKOS_INLINE_FUNCTION
  int sbmask(const int &j) const { return j >> SBBITS & 3; }
};

template <class DeviceType> class PairGranularGRFLOWKokkos : public PairGranularGRFLOW {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  PairGranularGRFLOWKokkos(class LAMMPS *);
  ~PairGranularGRFLOWKokkos() override;

  void compute(int, int) override;
  void init_style() override;
  double init_one(int, int) override;
  double single(int, int, int, int, double, double, double, double &) override;
  double memory_usage() override;

  // what the last compute() used (neighbor list, contact history,
  // coefficients, settings) for compute grflow/network/kk, which finds
  // the contacts and their forces again; nullptr before the first
  // compute().  Its atom views may be stale: take those from the atoms.
  const PairGranularGRFLOWKernel<DeviceType> *contact_data() const
  {
    return computed ? &kernel : nullptr;
  }

 protected:
  int neighflag;
  bool computed;
  PairGranularGRFLOWKernel<DeviceType> kernel;

  DAT::tdual_efloat_1d k_eatom;
  DAT::tdual_virial_array k_vatom;

  // the coefficients of each type pair (PairGranularGRFLOW::packed)
  typename PairGranularGRFLOWKernel<DeviceType>::tdual_coeff_2d k_coeff;

  typename AT::t_int_1d::HostMirror h_same;

  FixNeighHistoryGRFLOWKokkos<DeviceType> *fix_historyKK;

  // host copy of the neighbor list for single() (PairGranularGRFLOW reads
  // the history through list and fix_history->firstvalue on the host)
  class NeighList *host_list;
  Kokkos::View<int **, Kokkos::LayoutRight, Kokkos::HostSpace> host_neighbors;
  bigint host_list_build;

  void update_host_list();
  void same_position_error();
};

}    // namespace LAMMPS_NS

#endif
#endif
