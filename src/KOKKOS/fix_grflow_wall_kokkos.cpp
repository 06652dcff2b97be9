// clang-format off
/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */
// clang-format on

/* ----------------------------------------------------------------------
   Contributing authors: GRFLOW developers

   KOKKOS variant of fix grflow/wall: the contacts of the atoms with the
   walls on the device, one thread per owned atom, through the functions
   of grflow_wall_pass.h that the host's contact pass calls too
   (wall_atom_apart(), wall_atom_release(), wall_atom_contact(): the
   kernel of grflow_contact.h with the wall as a sphere of infinite
   radius).  The walls' forces, the global virial and an atom that
   crossed a wall come from one parallel_reduce.  Every owned atom is
   visited: the near list of the host's pass (grflow_wall_near.h) is not
   used.

   The walls (positions, velocities, motion, fix_modify, output vector,
   global restart data) stay on the host, in FixGRFLOWWall's
   GRFLOW::FlatWalls, and are copied into the kernel on each step.  The
   per-atom histories and contact records are DualViews whose host rows
   are FlatWalls' history and contact arrays, so that the host's packing,
   restart data, per-atom array and extract("grflow/wall_contacts") work
   on them after a sync.  They move with the atoms on the device
   (sort_kokkos, pack/unpack_exchange_kokkos) and on the host.

   The fix takes the style name grflow/wall after construction, as fix
   grflow/wall's restart files name their per-atom data (LAMMPS gives
   those only to a fix of the same style), so that restart files go
   between the two.
------------------------------------------------------------------------- */

#include "fix_grflow_wall_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "error.h"
#include "memory_kokkos.h"
#include "output.h"
#include "update.h"

#include "grflow_kokkos_style.h"
#include "grflow_wall.h"
#include "grflow_wall_pass.h"
#include "grflow_wall_state.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace LAMMPS_NS {

template <int VIRIAL> struct TagFixGRFLOWWallContact {
};
struct TagFixGRFLOWWallCrossing {};
struct TagFixGRFLOWWallPackExchange {};
struct TagFixGRFLOWWallUnpackExchange {};

/* ----------------------------------------------------------------------
   what the contact pass sums over the atoms: the forces on the walls,
   the global virial, and an atom that crossed a wall (the smallest key,
   NONE if none).  Partial sums are joined by += (as EV_FLOAT's), which
   takes the smaller of the two keys.
------------------------------------------------------------------------- */

struct FixGRFLOWWallSums {
  enum { NWALL = GRFLOW::FlatWalls::NWALL, NONE = 2147483647 };
  double force[NWALL][3];
  double virial[6];
  int crossing;

  KOKKOS_INLINE_FUNCTION
  FixGRFLOWWallSums()
  {
    for (int iw = 0; iw < NWALL; iw++)
      for (int k = 0; k < 3; k++) force[iw][k] = 0.0;
    for (int k = 0; k < 6; k++) virial[k] = 0.0;
    crossing = NONE;
  }

  KOKKOS_INLINE_FUNCTION
  void operator+=(const FixGRFLOWWallSums &src)
  {
    for (int iw = 0; iw < NWALL; iw++)
      for (int k = 0; k < 3; k++) force[iw][k] += src.force[iw][k];
    for (int k = 0; k < 6; k++) virial[k] += src.virial[k];
    if (src.crossing < crossing) crossing = src.crossing;
  }
};

/* ----------------------------------------------------------------------
   the kernels: views and plain numbers only (FixGRFLOWWall holds strings
   and host pointers, which a device kernel must not copy)
------------------------------------------------------------------------- */

template <class DeviceType> struct FixGRFLOWWallKernel {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef FixGRFLOWWallSums value_type;
  typedef GRFLOW::FlatWalls W;

  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v;
  typename AT::t_v_array_randomread omega;
  typename AT::t_f_array f;
  typename AT::t_f_array torque;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_int_1d_randomread mask;

  typename AT::t_float_2d d_history;    // NHIST per atom
  typename AT::t_float_2d d_contact;    // NCONTACT per atom
  Kokkos::View<double *[6], Kokkos::LayoutRight, DeviceType> d_vatom;

  // exchange
  typename AT::t_int_1d d_sendlist, d_copylist, d_indices;
  typename AT::t_xfloat_1d_um d_buf;
  int nrecv1, nextrarecv1;

  GRFLOW::WallPass walls;
  int groupbit, nlocal, vflag_global, vflag_atom;

  // the contacts of owned atom i; a crossing has the key i NWALL + wall
  template <int VIRIAL>
  KOKKOS_INLINE_FUNCTION void operator()(TagFixGRFLOWWallContact<VIRIAL>, const int i,
                                         value_type &sum) const
  {
    const double z = x(i, 2);
    const double rad = radius(i);
    double *hist = &d_history(i, 0);
    double *rec = &d_contact(i, 0);
    if (GRFLOW::wall_atom_apart(walls, (mask(i) & groupbit) != 0, z, rad)) {
      GRFLOW::wall_atom_release(hist, rec);
      return;
    }

    const double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
    const double wi[3] = {omega(i, 0), omega(i, 1), omega(i, 2)};
    double fi[3] = {f(i, 0), f(i, 1), f(i, 2)};
    double ti[3] = {torque(i, 0), torque(i, 1), torque(i, 2)};
    GRFLOW::WallAtomContact out;
    GRFLOW::wall_atom_contact(walls, z, vi, wi, rad, hist, rec, fi, ti, sum.force, VIRIAL != 0,
                              out);
    for (int k = 0; k < 3; k++) {
      f(i, k) = fi[k];
      torque(i, k) = ti[k];
    }

    // one thread per atom: its per-atom virial without atomics
    if (VIRIAL) {
      for (int iw = 0; iw < W::NWALL; iw++) {
        if (!out.tallied[iw]) continue;
        if (vflag_global)
          for (int k = 0; k < 6; k++) sum.virial[k] += out.vir[iw][k];
        if (vflag_atom)
          for (int k = 0; k < 6; k++) d_vatom(i, k) += out.vir[iw][k];
      }
    }
    if (out.crossed >= 0) {
      const int key = i * W::NWALL + out.crossed;
      if (key < sum.crossing) sum.crossing = key;
    }
  }

  // an owned atom of the group whose centre reached or passed a wall: the
  // key wall nlocal + i, so that the smallest is the atom
  // FlatWalls::find_crossing() names
  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixGRFLOWWallCrossing, const int i, value_type &sum) const
  {
    if (!(mask(i) & groupbit)) return;
    for (int iw = 0; iw < W::NWALL; iw++)
      if (walls.active[iw] && W::reached(iw, walls.z[iw], x(i, 2))) {
        const int key = iw * nlocal + i;
        if (key < sum.crossing) sum.crossing = key;
        return;
      }
  }

  // the histories of the atoms leaving (NHIST values each, in the order of
  // the send list), and the atom that fills the hole of each
  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixGRFLOWWallPackExchange, const int isend) const
  {
    const int i = d_sendlist(isend);
    const int m = isend * W::NHIST;
    for (int k = 0; k < W::NHIST; k++) d_buf(m + k) = d_history(i, k);
    const int j = d_copylist(isend);
    if (j > -1) {
      for (int k = 0; k < W::NHIST; k++) d_history(i, k) = d_history(j, k);
      for (int k = 0; k < W::NCONTACT; k++) d_contact(i, k) = d_contact(j, k);
    }
  }

  // the histories of the atoms received, from one or two messages (the
  // second starts at nextrarecv1, its atoms at nrecv1); their records are
  // unknown until the next contact pass (as unpack_wall_atom())
  KOKKOS_INLINE_FUNCTION
  void operator()(TagFixGRFLOWWallUnpackExchange, const int irecv) const
  {
    const int index = d_indices(irecv);
    if (index < 0) return;
    const int m = (irecv < nrecv1) ? irecv * W::NHIST : nextrarecv1 + (irecv - nrecv1) * W::NHIST;
    for (int k = 0; k < W::NHIST; k++) d_history(index, k) = d_buf(m + k);
    GRFLOW::mark_wall_records_unknown(walls.active, &d_contact(index, 0));
  }
};

}    // namespace LAMMPS_NS

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixGRFLOWWallKokkos<DeviceType>::FixGRFLOWWallKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixGRFLOWWall(lmp, narg, arg), kernel(nullptr)
{
  kokkosable = 1;
  exchange_comm_device = 1;
  sort_device = 1;
  maxexchange = GRFLOW::FlatWalls::NHIST;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  // each member function syncs what it reads and marks what it writes
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;

  kernel = new FixGRFLOWWallKernel<DeviceType>();

  // the per-atom arrays of FixGRFLOWWall's constructor give way to
  // DualViews (zero, as set_arrays() left them)
  memory->destroy(walls->history);
  memory->destroy(walls->contact);
  walls->history = walls->contact = nullptr;
  grow_arrays(atom->nmax);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> FixGRFLOWWallKokkos<DeviceType>::~FixGRFLOWWallKokkos()
{
  if (copymode) return;
  memoryKK->destroy_kokkos(k_history, walls->history);
  memoryKK->destroy_kokkos(k_contact, walls->contact);
  delete kernel;
}

/* ----------------------------------------------------------------------
   the style name of fix grflow/wall (after the suffix was added to it),
   for restart files: LAMMPS matches per-atom restart data to a fix by ID
   and style
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWWallKokkos<DeviceType>::post_constructor()
{
  GRFLOW::take_plain_style(lmp, this, "grflow/wall", "the walls' contacts");
}

/* ----------------------------------------------------------------------
   both per-atom arrays current on the host; marked as changed there
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWWallKokkos<DeviceType>::sync_host()
{
  k_history.sync_host();
  k_contact.sync_host();
}

template <class DeviceType> void FixGRFLOWWallKokkos<DeviceType>::modify_host()
{
  k_history.modify_host();
  k_contact.modify_host();
}

/* ----------------------------------------------------------------------
   on the steps with a neighbor list build, before atoms move between
   ranks: an atom of the group that crossed a wall (FixGRFLOWWall says why)
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWWallKokkos<DeviceType>::pre_exchange()
{
  const int nlocal = atom->nlocal;
  if (nlocal == 0) return;
  atomKK->sync(execution_space, X_MASK | MASK_MASK);
  FixGRFLOWWallKernel<DeviceType> &k = *kernel;
  k.x = atomKK->k_x.template view<DeviceType>();
  k.mask = atomKK->k_mask.template view<DeviceType>();
  k.walls = GRFLOW::wall_pass(*walls, false);
  k.groupbit = groupbit;
  k.nlocal = nlocal;

  FixGRFLOWWallSums sums;
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType, TagFixGRFLOWWallCrossing>(0, nlocal), k,
                          sums);
  if (sums.crossing != FixGRFLOWWallSums::NONE)
    crossed_key(sums.crossing % nlocal, sums.crossing / nlocal);
}

/* ----------------------------------------------------------------------
   the error of an atom i that crossed wall w, found on the device
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWWallKokkos<DeviceType>::crossed_key(int i, int w)
{
  atomKK->sync(Host, X_MASK | TAG_MASK);
  crossed(i, w);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWWallKokkos<DeviceType>::post_force(int vflag)
{
  typedef GRFLOW::FlatWalls Wl;
  const int nlocal = atom->nlocal;

  // the virial: global by the reduction, per atom in a device view copied
  // into the host array vatom of Fix::v_setup() (zeroed there)
  v_init(vflag);
  FixGRFLOWWallKernel<DeviceType> &k = *kernel;
  if (vflag_atom) {
    if ((int) k.d_vatom.extent(0) < maxvatom)
      k.d_vatom = Kokkos::View<double *[6], Kokkos::LayoutRight, DeviceType>("grflow/wall/kk:vatom",
                                                                             maxvatom);
    else
      Kokkos::deep_copy(k.d_vatom, 0.0);
  }

  atomKK->sync(execution_space,
               X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RADIUS_MASK | MASK_MASK);
  k_history.template sync<DeviceType>();
  k_contact.template sync<DeviceType>();

  k.x = atomKK->k_x.template view<DeviceType>();
  k.v = atomKK->k_v.template view<DeviceType>();
  k.omega = atomKK->k_omega.template view<DeviceType>();
  k.f = atomKK->k_f.template view<DeviceType>();
  k.torque = atomKK->k_torque.template view<DeviceType>();
  k.radius = atomKK->k_radius.template view<DeviceType>();
  k.mask = atomKK->k_mask.template view<DeviceType>();
  k.d_history = k_history.template view<DeviceType>();
  k.d_contact = k_contact.template view<DeviceType>();
  // no history updates during setup (forces are recomputed for the same state)
  k.walls = GRFLOW::wall_pass(*walls, update->setupflag == 0);
  k.groupbit = groupbit;
  k.nlocal = nlocal;
  k.vflag_global = vflag_global;
  k.vflag_atom = vflag_atom;

  FixGRFLOWWallSums sums;
  if (nlocal > 0) {
    if (evflag)
      Kokkos::parallel_reduce(
          Kokkos::RangePolicy<DeviceType, TagFixGRFLOWWallContact<1>>(0, nlocal), k, sums);
    else
      Kokkos::parallel_reduce(
          Kokkos::RangePolicy<DeviceType, TagFixGRFLOWWallContact<0>>(0, nlocal), k, sums);
  }

  atomKK->modified(execution_space, F_MASK | TORQUE_MASK);
  k_history.template modify<DeviceType>();
  k_contact.template modify<DeviceType>();

  for (int iw = 0; iw < Wl::NWALL; iw++)
    for (int m = 0; m < 3; m++) walls->walls[iw].force[m] = sums.force[iw][m];
  walls->contact_step = update->ntimestep;
  walls->force_flag = 0;
  if (vflag_global)
    for (int m = 0; m < 6; m++) virial[m] += sums.virial[m];
  if (vflag_atom && nlocal > 0) {
    Kokkos::View<double *[6], Kokkos::LayoutRight, Kokkos::HostSpace,
                 Kokkos::MemoryTraits<Kokkos::Unmanaged>>
        h_vatom(&vatom[0][0], nlocal);
    Kokkos::deep_copy(h_vatom, Kokkos::subview(k.d_vatom, std::make_pair(0, nlocal), Kokkos::ALL));
  }

  if (sums.crossing != FixGRFLOWWallSums::NONE)
    crossed_key(sums.crossing / Wl::NWALL, sums.crossing % Wl::NWALL);

  // the per-atom array on the host for output: at the setup of a run and
  // on the steps with output (thermo, dumps, restart files); other readers
  // between them find the last output step's values (doc/fix_grflow_wall.rst)
  if (update->setupflag || update->ntimestep == output->next) k_contact.sync_host();
}

/* ----------------------------------------------------------------------
   "grflow/wall_contacts" (compute grflow/network): the records of the
   last contact pass, on the host; "grflow/wall_contacts/kk" (compute
   grflow/network/kk): the same, the records where they are
------------------------------------------------------------------------- */

template <class DeviceType>
void *FixGRFLOWWallKokkos<DeviceType>::extract(const char *name, int &dim)
{
  if (strcmp(name, "grflow/wall_contacts/kk") == 0) {
    offered_kk.contacts = static_cast<const GRFLOW::WallContacts *>(
        FixGRFLOWWall::extract("grflow/wall_contacts", dim));
    offered_kk.records = &k_contact;
    dim = 0;
    return &offered_kk;
  }
  if (strcmp(name, "grflow/wall_contacts") == 0) k_contact.sync_host();
  return FixGRFLOWWall::extract(name, dim);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> double FixGRFLOWWallKokkos<DeviceType>::memory_usage()
{
  double bytes = MemKK::memory_usage(k_history.d_view);
  bytes += MemKK::memory_usage(k_contact.d_view);
  bytes += MemKK::memory_usage(kernel->d_vatom);
  return bytes;
}

/* ----------------------------------------------------------------------
   per-atom arrays for nmax atoms (contents kept on the side changed
   last); FlatWalls' rows and the per-atom array are the host rows
------------------------------------------------------------------------- */

template <class DeviceType> void FixGRFLOWWallKokkos<DeviceType>::grow_arrays(int nmax)
{
  memoryKK->grow_kokkos(k_history, walls->history, nmax, GRFLOW::FlatWalls::NHIST,
                        "grflow/wall/kk:history");
  memoryKK->grow_kokkos(k_contact, walls->contact, nmax, GRFLOW::FlatWalls::NCONTACT,
                        "grflow/wall/kk:contact");
  array_atom = walls->contact;
}

/* ----------------------------------------------------------------------
   host versions (classic sorting and exchange, new atoms, restart files):
   those of FixGRFLOWWall on the host rows
------------------------------------------------------------------------- */

template <class DeviceType>
void FixGRFLOWWallKokkos<DeviceType>::copy_arrays(int i, int j, int delflag)
{
  sync_host();
  FixGRFLOWWall::copy_arrays(i, j, delflag);
  modify_host();
}

template <class DeviceType> void FixGRFLOWWallKokkos<DeviceType>::set_arrays(int i)
{
  sync_host();
  FixGRFLOWWall::set_arrays(i);
  modify_host();
}

template <class DeviceType> int FixGRFLOWWallKokkos<DeviceType>::pack_exchange(int i, double *buf)
{
  sync_host();
  return FixGRFLOWWall::pack_exchange(i, buf);
}

template <class DeviceType>
int FixGRFLOWWallKokkos<DeviceType>::unpack_exchange(int nlocal, double *buf)
{
  sync_host();
  const int n = FixGRFLOWWall::unpack_exchange(nlocal, buf);
  modify_host();
  return n;
}

template <class DeviceType> int FixGRFLOWWallKokkos<DeviceType>::pack_restart(int i, double *buf)
{
  sync_host();
  return FixGRFLOWWall::pack_restart(i, buf);
}

template <class DeviceType>
void FixGRFLOWWallKokkos<DeviceType>::unpack_restart(int nlocal, int nth)
{
  sync_host();
  FixGRFLOWWall::unpack_restart(nlocal, nth);
  modify_host();
}

/* ----------------------------------------------------------------------
   atom sorting on the device: histories and records move with the atoms
------------------------------------------------------------------------- */

template <class DeviceType>
void FixGRFLOWWallKokkos<DeviceType>::sort_kokkos(Kokkos::BinSort<KeyViewType, BinOp> &Sorter)
{
  k_history.sync_device();
  k_contact.sync_device();
  Sorter.sort(LMPDeviceType(), k_history.d_view);
  Sorter.sort(LMPDeviceType(), k_contact.d_view);
  k_history.modify_device();
  k_contact.modify_device();
}

/* ----------------------------------------------------------------------
   exchange on the device: the histories of the atoms in k_sendlist into
   k_buf, NHIST values each; the atoms of k_copylist fill their holes
------------------------------------------------------------------------- */

template <class DeviceType>
int FixGRFLOWWallKokkos<DeviceType>::pack_exchange_kokkos(const int &nsend,
                                                          DAT::tdual_xfloat_2d &k_buf,
                                                          DAT::tdual_int_1d k_sendlist,
                                                          DAT::tdual_int_1d k_copylist,
                                                          ExecutionSpace /*space*/)
{
  k_history.template sync<DeviceType>();
  k_contact.template sync<DeviceType>();
  k_buf.template sync<DeviceType>();
  k_sendlist.template sync<DeviceType>();
  k_copylist.template sync<DeviceType>();

  FixGRFLOWWallKernel<DeviceType> &k = *kernel;
  k.d_history = k_history.template view<DeviceType>();
  k.d_contact = k_contact.template view<DeviceType>();
  k.d_sendlist = k_sendlist.template view<DeviceType>();
  k.d_copylist = k_copylist.template view<DeviceType>();
  k.d_buf = typename AT::t_xfloat_1d_um(k_buf.template view<DeviceType>().data(),
                                        k_buf.extent(0) * k_buf.extent(1));
  if (nsend > 0)
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType, TagFixGRFLOWWallPackExchange>(0, nsend),
                         k);

  // (k_buf is not marked: CommKokkos sends its device data as they are)
  k_history.template modify<DeviceType>();
  k_contact.template modify<DeviceType>();
  return nsend * GRFLOW::FlatWalls::NHIST;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
void FixGRFLOWWallKokkos<DeviceType>::unpack_exchange_kokkos(DAT::tdual_xfloat_2d &k_buf,
                                                             DAT::tdual_int_1d &k_indices,
                                                             int nrecv, int nrecv1, int nextrarecv1,
                                                             ExecutionSpace /*space*/)
{
  k_history.template sync<DeviceType>();
  k_contact.template sync<DeviceType>();

  FixGRFLOWWallKernel<DeviceType> &k = *kernel;
  k.d_history = k_history.template view<DeviceType>();
  k.d_contact = k_contact.template view<DeviceType>();
  // the message is in the device view of k_buf (received there by MPI)
  k.d_buf = typename AT::t_xfloat_1d_um(k_buf.template view<DeviceType>().data(),
                                        k_buf.extent(0) * k_buf.extent(1));
  k.d_indices = k_indices.template view<DeviceType>();
  k.nrecv1 = nrecv1;
  k.nextrarecv1 = nextrarecv1;
  k.walls = GRFLOW::wall_pass(*walls, false);
  if (nrecv > 0)
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType, TagFixGRFLOWWallUnpackExchange>(0, nrecv),
                         k);

  k_history.template modify<DeviceType>();
  k_contact.template modify<DeviceType>();
}

namespace LAMMPS_NS {
template class FixGRFLOWWallKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixGRFLOWWallKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
