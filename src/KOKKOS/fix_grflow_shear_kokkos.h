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
FixStyle(grflow/shear/kk,FixGRFLOWShearKokkos<LMPDeviceType>);
FixStyle(grflow/shear/kk/device,FixGRFLOWShearKokkos<LMPDeviceType>);
FixStyle(grflow/shear/kk/host,FixGRFLOWShearKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_SHEAR_KOKKOS_H
#define LMP_FIX_GRFLOW_SHEAR_KOKKOS_H

#include "fix_grflow_shear.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

// the glued layer on the device; the rule (reversals, cycle count,
// liquefaction, restart data, outputs) is that of FixGRFLOWShear, which
// reads only the reduced stress of its compute
template <class DeviceType> class FixGRFLOWShearKokkos : public FixGRFLOWShear {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  FixGRFLOWShearKokkos(class LAMMPS *, int, char **);
  void post_constructor() override;

 protected:
  void glue(double vw, bool step) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
