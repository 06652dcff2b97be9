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

   KOKKOS variant of fix grflow/shear: the glued layer moves with the top
   wall on the device (GRFLOW::glue_atom() of grflow_shear_rule.h, the
   function of the plain fix), so that the fix touches no atom data on
   the host.  Everything else is the plain fix's: it reads the stress of
   its compute (grflow/network/kk reduces it on the device) every N steps
   and drives the wall of fix grflow/wall/kk, whose state is on the host.
------------------------------------------------------------------------- */

#include "fix_grflow_shear_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"

#include "grflow_kokkos_style.h"
#include "grflow_shear_rule.h"

using namespace LAMMPS_NS;

namespace {

// one owned atom of the glued layer: velocity (vw, 0, 0), no spin, and
// with STEP its x advanced by dt vw (as GRFLOW::glue_layer())
template <class DeviceType, int STEP> struct FixGRFLOWShearGlue {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  typename AT::t_x_array x;
  typename AT::t_v_array v;
  typename AT::t_v_array omega;
  typename AT::t_int_1d_randomread mask;
  int gluebit;
  double vw, dt;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(mask(i) & gluebit)) return;
    double vi[3], wi[3];
    GRFLOW::glue_atom(vw, vi, wi);
    for (int k = 0; k < 3; k++) {
      v(i, k) = vi[k];
      omega(i, k) = wi[k];
    }
    if (STEP) x(i, 0) += dt * vw;
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixGRFLOWShearKokkos<DeviceType>::FixGRFLOWShearKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixGRFLOWShear(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  // the fix's own atom data (the compute and the wall fix sync theirs);
  // glue() marks what it changes itself, as it changes it
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | MASK_MASK;
  datamask_modify = EMPTY_MASK;
}

/* ----------------------------------------------------------------------
   the style name of fix grflow/shear (after the suffix was added to it),
   for restart files: LAMMPS matches a fix's restart data by ID and by the
   style without the suffix only when -sf kk added it
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWShearKokkos<DeviceType>::post_constructor()
{
  GRFLOW::take_plain_style(lmp, this, "grflow/shear", "the glued layer");
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWShearKokkos<DeviceType>::glue(double vw, bool step)
{
  const int nlocal = atom->nlocal;
  atomKK->sync(execution_space, X_MASK | V_MASK | OMEGA_MASK | MASK_MASK);
  auto set = [&](auto &s) {
    s.x = atomKK->k_x.template view<DeviceType>();
    s.v = atomKK->k_v.template view<DeviceType>();
    s.omega = atomKK->k_omega.template view<DeviceType>();
    s.mask = atomKK->k_mask.template view<DeviceType>();
    s.gluebit = gluebit;
    s.vw = vw;
    s.dt = dt;
    if (nlocal > 0) Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), s);
  };
  if (step) {
    FixGRFLOWShearGlue<DeviceType, 1> s;
    set(s);
    atomKK->modified(execution_space, X_MASK | V_MASK | OMEGA_MASK);
  } else {
    FixGRFLOWShearGlue<DeviceType, 0> s;
    set(s);
    atomKK->modified(execution_space, V_MASK | OMEGA_MASK);
  }
}

namespace LAMMPS_NS {
template class FixGRFLOWShearKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixGRFLOWShearKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
