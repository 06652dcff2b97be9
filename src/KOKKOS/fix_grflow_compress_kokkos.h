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
FixStyle(grflow/compress/kk,FixGRFLOWCompressKokkos<LMPDeviceType>);
FixStyle(grflow/compress/kk/device,FixGRFLOWCompressKokkos<LMPDeviceType>);
FixStyle(grflow/compress/kk/host,FixGRFLOWCompressKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_COMPRESS_KOKKOS_H
#define LMP_FIX_GRFLOW_COMPRESS_KOKKOS_H

#include "fix_grflow_compress.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

// the box remap of the group and the kinetic energy sum on the device;
// the servo (rates, gains, convergence, restart data, outputs) is that of
// FixGRFLOWCompress, which reads only reduced values
template <class DeviceType> class FixGRFLOWCompressKokkos : public FixGRFLOWCompress {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  FixGRFLOWCompressKokkos(class LAMMPS *, int, char **);
  void post_constructor() override;
  void init() override;

 protected:
  double kinetic_local() override;
  void remap_group(bool to_lamda) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
