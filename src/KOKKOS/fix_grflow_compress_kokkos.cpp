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

   KOKKOS variant of fix grflow/compress: on every step the group's
   positions go to lamda coordinates and back around the change of the
   box on the device (the formulas of Domain::x2lamda() and lamda2x()),
   and on servo steps the kinetic energy of the group is a device
   reduction of GRFLOW::kinetic_term() (grflow_servo.h, the function of the
   plain fix).  The servo itself, the box and the walls stay on the host
   and read only reduced values: the stresses of compute grflow/network/kk
   and the energy of the pair style.
------------------------------------------------------------------------- */

#include "fix_grflow_compress_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "domain.h"

#include "grflow_kokkos_style.h"
#include "grflow_servo.h"

using namespace LAMMPS_NS;

namespace {

// an owned atom of the group to lamda coordinates (TO_LAMDA) or back
template <class DeviceType, int TO_LAMDA> struct FixGRFLOWCompressRemap {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  typename AT::t_x_array x;
  typename AT::t_int_1d_randomread mask;
  int groupbit;
  double h[6], h_inv[6], boxlo[3];

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(mask(i) & groupbit)) return;
    if (TO_LAMDA) {
      const double d0 = x(i, 0) - boxlo[0];
      const double d1 = x(i, 1) - boxlo[1];
      const double d2 = x(i, 2) - boxlo[2];
      x(i, 0) = h_inv[0] * d0 + h_inv[5] * d1 + h_inv[4] * d2;
      x(i, 1) = h_inv[1] * d1 + h_inv[3] * d2;
      x(i, 2) = h_inv[2] * d2;
    } else {
      const double l0 = x(i, 0), l1 = x(i, 1), l2 = x(i, 2);
      x(i, 0) = h[0] * l0 + h[5] * l1 + h[4] * l2 + boxlo[0];
      x(i, 1) = h[1] * l1 + h[3] * l2 + boxlo[1];
      x(i, 2) = h[2] * l2 + boxlo[2];
    }
  }
};

// twice the kinetic energy of the group's owned atoms
template <class DeviceType> struct FixGRFLOWCompressKinetic {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef double value_type;

  typename AT::t_v_array_randomread v;
  typename AT::t_v_array_randomread omega;
  typename AT::t_float_1d_randomread rmass;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_int_1d_randomread mask;
  int groupbit;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, double &sum) const
  {
    if (!(mask(i) & groupbit)) return;
    const double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
    const double wi[3] = {omega(i, 0), omega(i, 1), omega(i, 2)};
    sum += GRFLOW::kinetic_term(vi, wi, rmass(i), radius(i));
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixGRFLOWCompressKokkos<DeviceType>::FixGRFLOWCompressKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixGRFLOWCompress(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  // the fix's own atom data (the compute and the wall fix sync theirs);
  // remap_group() marks what it changes itself
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK;
  datamask_modify = EMPTY_MASK;
}

/* ----------------------------------------------------------------------
   the style name of fix grflow/compress (after the suffix was added to it),
   for restart files: LAMMPS matches a fix's restart data by ID and by the
   style without the suffix only when -sf kk added it
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWCompressKokkos<DeviceType>::post_constructor()
{
  GRFLOW::take_plain_style(lmp, this, "grflow/compress", "the box remap and kinetic energy");
}

/* ----------------------------------------------------------------------
   the plain fix's init() sums the group's solid volume on the host
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWCompressKokkos<DeviceType>::init()
{
  atomKK->sync(Host, MASK_MASK | RADIUS_MASK);
  FixGRFLOWCompress::init();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> double FixGRFLOWCompressKokkos<DeviceType>::kinetic_local()
{
  const int nlocal = atom->nlocal;
  atomKK->sync(execution_space, V_MASK | OMEGA_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  FixGRFLOWCompressKinetic<DeviceType> s;
  s.v = atomKK->k_v.template view<DeviceType>();
  s.omega = atomKK->k_omega.template view<DeviceType>();
  s.rmass = atomKK->k_rmass.template view<DeviceType>();
  s.radius = atomKK->k_radius.template view<DeviceType>();
  s.mask = atomKK->k_mask.template view<DeviceType>();
  s.groupbit = groupbit;
  double sum = 0.0;
  if (nlocal > 0) Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, nlocal), s, sum);
  return sum;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWCompressKokkos<DeviceType>::remap_group(bool to_lamda)
{
  const int nlocal = atom->nlocal;
  atomKK->sync(execution_space, X_MASK | MASK_MASK);
  auto set = [&](auto &s) {
    s.x = atomKK->k_x.template view<DeviceType>();
    s.mask = atomKK->k_mask.template view<DeviceType>();
    s.groupbit = groupbit;
    for (int k = 0; k < 6; k++) {
      s.h[k] = domain->h[k];
      s.h_inv[k] = domain->h_inv[k];
    }
    for (int k = 0; k < 3; k++) s.boxlo[k] = domain->boxlo[k];
    if (nlocal > 0) Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), s);
  };
  if (to_lamda) {
    FixGRFLOWCompressRemap<DeviceType, 1> s;
    set(s);
  } else {
    FixGRFLOWCompressRemap<DeviceType, 0> s;
    set(s);
  }
  atomKK->modified(execution_space, X_MASK);
}

namespace LAMMPS_NS {
template class FixGRFLOWCompressKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixGRFLOWCompressKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
