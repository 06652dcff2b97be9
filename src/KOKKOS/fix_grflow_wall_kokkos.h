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

#ifdef FIX_CLASS
// clang-format off
FixStyle(grflow/wall/kk,FixGRFLOWWallKokkos<LMPDeviceType>);
FixStyle(grflow/wall/kk/device,FixGRFLOWWallKokkos<LMPDeviceType>);
FixStyle(grflow/wall/kk/host,FixGRFLOWWallKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_WALL_KOKKOS_H
#define LMP_FIX_GRFLOW_WALL_KOKKOS_H

#include "fix_grflow_wall.h"
#include "grflow_wall_contacts_kokkos.h"
#include "kokkos_base.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

// the device kernels (fix_grflow_wall_kokkos.cpp)
template <class DeviceType> struct FixGRFLOWWallKernel;

template <class DeviceType> class FixGRFLOWWallKokkos : public FixGRFLOWWall, public KokkosBase {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  FixGRFLOWWallKokkos(class LAMMPS *, int, char **);
  ~FixGRFLOWWallKokkos() override;
  void post_constructor() override;
  void pre_exchange() override;
  void post_force(int) override;
  void *extract(const char *, int &) override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;

  void sort_kokkos(Kokkos::BinSort<KeyViewType, BinOp> &) override;
  int pack_exchange_kokkos(const int &, DAT::tdual_xfloat_2d &, DAT::tdual_int_1d,
                           DAT::tdual_int_1d, ExecutionSpace) override;
  void unpack_exchange_kokkos(DAT::tdual_xfloat_2d &, DAT::tdual_int_1d &, int, int, int,
                              ExecutionSpace) override;

 protected:
  FixGRFLOWWallKernel<DeviceType> *kernel;
  GRFLOW::WallContactsKokkos offered_kk;

  // per atom: the contact histories and records (GRFLOW::FlatWalls'
  // history and contact are the host rows)
  DAT::tdual_float_2d k_history, k_contact;

  void sync_host();
  void modify_host();
  void crossed_key(int, int);
};

}    // namespace LAMMPS_NS

#endif
#endif
