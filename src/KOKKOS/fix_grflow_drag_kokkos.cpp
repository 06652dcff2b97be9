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

   KOKKOS variant of fix grflow/drag: GRFLOW::Drag (grflow_drag.h, the
   formulas of the plain fix) per particle on the device.  Unlike LAMMPS's
   fix langevin/kk it has the spin term, so that a drag with omega yes
   keeps the particles on the device.
------------------------------------------------------------------------- */

#include "fix_grflow_drag_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "update.h"

#include "grflow_drag.h"

using namespace LAMMPS_NS;

namespace {

// one owned particle: F += gamma v (and with SPIN, for r > 0, T += gamma' omega)
template <class DeviceType, int SPIN> struct FixGRFLOWDragKernel {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  GRFLOW::Drag drag;
  typename AT::t_v_array_randomread v, omega;
  typename AT::t_f_array f, torque;
  typename AT::t_float_1d_randomread rmass, radius;
  typename AT::t_int_1d_randomread mask;
  int groupbit;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(mask(i) & groupbit)) return;
    double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
    double fi[3] = {f(i, 0), f(i, 1), f(i, 2)};
    drag.apply(rmass(i), vi, fi);
    for (int k = 0; k < 3; k++) f(i, k) = fi[k];
    if (!SPIN || !(radius(i) > 0.0)) return;
    double wi[3] = {omega(i, 0), omega(i, 1), omega(i, 2)};
    double ti[3] = {torque(i, 0), torque(i, 1), torque(i, 2)};
    drag.apply_spin(rmass(i), radius(i), wi, ti);
    for (int k = 0; k < 3; k++) torque(i, k) = ti[k];
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixGRFLOWDragKokkos<DeviceType>::FixGRFLOWDragKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixGRFLOWDrag(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  // post_force syncs and marks what it touches itself
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

/* ----------------------------------------------------------------------
   the log says where the drag runs (once the style has its suffix)
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWDragKokkos<DeviceType>::post_constructor()
{
  if (comm->me == 0)
    utils::logmesg(lmp, "Fix {} {}: the drag on the Kokkos {}\n", style, id,
                   (execution_space == Device) ? "device" : "host");
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWDragKokkos<DeviceType>::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix grflow/drag/kk {}: run_style respa is not supported with KOKKOS", id);
  // the plain fix's check of the radii reads them on the host (once a run)
  if (spin) atomKK->sync(Host, RADIUS_MASK | MASK_MASK);
  FixGRFLOWDrag::init();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWDragKokkos<DeviceType>::post_force(int /*vflag*/)
{
  const int nlocal = atom->nlocal;
  unsigned int read = V_MASK | F_MASK | RMASS_MASK | MASK_MASK, changed = F_MASK;
  if (spin) {
    read |= OMEGA_MASK | TORQUE_MASK | RADIUS_MASK;
    changed |= TORQUE_MASK;
  }
  atomKK->sync(execution_space, read);
  auto run = [&](auto &k) {
    k.drag = GRFLOW::Drag{t_damp, force->ftm2v};
    k.v = atomKK->k_v.template view<DeviceType>();
    k.f = atomKK->k_f.template view<DeviceType>();
    k.rmass = atomKK->k_rmass.template view<DeviceType>();
    k.mask = atomKK->k_mask.template view<DeviceType>();
    k.groupbit = groupbit;
    if (spin) {
      k.omega = atomKK->k_omega.template view<DeviceType>();
      k.torque = atomKK->k_torque.template view<DeviceType>();
      k.radius = atomKK->k_radius.template view<DeviceType>();
    }
    if (nlocal > 0) Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), k);
  };
  if (spin) {
    FixGRFLOWDragKernel<DeviceType, 1> k;
    run(k);
  } else {
    FixGRFLOWDragKernel<DeviceType, 0> k;
    run(k);
  }
  atomKK->modified(execution_space, changed);
}

namespace LAMMPS_NS {
template class FixGRFLOWDragKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixGRFLOWDragKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
