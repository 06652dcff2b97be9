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
FixStyle(grflow/drag/kk,FixGRFLOWDragKokkos<LMPDeviceType>);
FixStyle(grflow/drag/kk/device,FixGRFLOWDragKokkos<LMPDeviceType>);
FixStyle(grflow/drag/kk/host,FixGRFLOWDragKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_GRFLOW_DRAG_KOKKOS_H
#define LMP_FIX_GRFLOW_DRAG_KOKKOS_H

#include "fix_grflow_drag.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

// the drag of FixGRFLOWDrag (GRFLOW::Drag) on the device
template <class DeviceType> class FixGRFLOWDragKokkos : public FixGRFLOWDrag {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  FixGRFLOWDragKokkos(class LAMMPS *, int, char **);
  void post_constructor() override;
  void init() override;
  void post_force(int) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
