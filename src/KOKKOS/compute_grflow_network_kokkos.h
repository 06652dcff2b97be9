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

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(grflow/network/kk,ComputeGRFLOWNetworkKokkos<LMPDeviceType>);
ComputeStyle(grflow/network/kk/device,ComputeGRFLOWNetworkKokkos<LMPDeviceType>);
ComputeStyle(grflow/network/kk/host,ComputeGRFLOWNetworkKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_COMPUTE_GRFLOW_NETWORK_KOKKOS_H
#define LMP_COMPUTE_GRFLOW_NETWORK_KOKKOS_H

#include "compute_grflow_network.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

// the sums over the contacts and the particles of this processor on the
// device; the rest (keywords, reduction over processors, the derived
// quantities, the stress path of fix grflow/shear and fix grflow/compress)
// is that of ComputeGRFLOWNetwork
template <class DeviceType> class ComputeGRFLOWNetworkKokkos : public ComputeGRFLOWNetwork {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  ComputeGRFLOWNetworkKokkos(class LAMMPS *, int, char **);
  double memory_usage() override;

 protected:
  void check_setup() override;
  void require_pair_list() override;
  bigint wall_contacts_step(class Fix *) override;
  double local_sums(double *sums, bool network) override;

 private:
  // per owned atom: in the group and the sub-volume; force-bearing contacts
  typename AT::t_float_1d d_inside, d_ncontact;
  // the sums of each pass (one row each), copied to the host once
  Kokkos::View<double **, Kokkos::LayoutRight, DeviceType> d_sums;
};

}    // namespace LAMMPS_NS

#endif
#endif
