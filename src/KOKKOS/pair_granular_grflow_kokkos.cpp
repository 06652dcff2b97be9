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

   KOKKOS variant of pair granular/grflow: the pair loop on the device,
   one thread per owned atom i, the contact law of grflow_contact.h
   (contact_forces(), the scalar kernel that device code can
   call), the contact history in FixNeighHistoryGRFLOWKokkos.  Settings,
   coefficients, restart and data files, fix adapt and single() are those
   of PairGranularGRFLOW.

   Half neighbor lists with newton pair off: a pair of an owned atom and a
   ghost is computed on both ranks, each keeps its own history, and the
   forces on ghosts are not summed back.  With threads (HALFTHREAD) the
   forces and torques on j are added atomically.
------------------------------------------------------------------------- */

#include "pair_granular_grflow_kokkos.h"

#include "fix_neigh_history_grflow_kokkos_impl.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "compute.h"
#include "error.h"
#include "force.h"
#include "grflow_contact.h"
#include "kokkos.h"
#include "memory_kokkos.h"
#include "modify.h"
#include "neigh_list_kokkos.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <type_traits>

using namespace LAMMPS_NS;

namespace {

// the contact history fix, made by modify->replace_fix() in init_style()
template <class DeviceType> Fix *history_fix_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixNeighHistoryGRFLOWKokkos<DeviceType>(lmp, narg, arg);
}

// its style name for an execution space
std::string history_fix_style(ExecutionSpace space)
{
  return (space == Device) ? "NEIGH_HISTORY/GRFLOW/KK/DEVICE" : "NEIGH_HISTORY/GRFLOW/KK/HOST";
}

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairGranularGRFLOWKokkos<DeviceType>::PairGranularGRFLOWKokkos(LAMMPS *lmp) :
    PairGranularGRFLOW(lmp)
{
  kokkosable = 1;
  respa_enable = 0;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | TYPE_MASK | RADIUS_MASK |
      ENERGY_MASK | VIRIAL_MASK;
  datamask_modify = F_MASK | TORQUE_MASK | ENERGY_MASK | VIRIAL_MASK;

  neighflag = HALF;
  computed = false;
  fix_historyKK = nullptr;
  host_list = nullptr;
  host_list_build = -1;
  kernel.d_same = typename AT::t_int_1d("pair:same_position", 3);
  h_same = Kokkos::create_mirror_view(kernel.d_same);

  // the style of the history fix is known to LAMMPS only through this
  // pair style: the CMake build registers KOKKOS styles as variants of
  // existing styles, and there is no plain style it is a variant of

  const std::string hstyle = history_fix_style(execution_space);
  if (modify->fix_map->find(hstyle) == modify->fix_map->end())
    (*modify->fix_map)[hstyle] = &history_fix_creator<DeviceType>;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> PairGranularGRFLOWKokkos<DeviceType>::~PairGranularGRFLOWKokkos()
{
  if (copymode) return;

  memoryKK->destroy_kokkos(k_eatom, eatom);
  memoryKK->destroy_kokkos(k_vatom, vatom);
  delete host_list;
}

/* ----------------------------------------------------------------------
   the history fix of this style, the settings it supports, the KOKKOS
   neighbor list
------------------------------------------------------------------------- */

template <class DeviceType> void PairGranularGRFLOWKokkos<DeviceType>::init_style()
{
  neighflag = lmp->kokkos->neighflag;
  if (neighflag == FULL)
    error->all(FLERR,
               "Pair style granular/grflow/kk needs a half neighbor list: use the KOKKOS package "
               "option 'neigh half' (-pk kokkos neigh half); the KOKKOS package of this LAMMPS "
               "builds no full neighbor lists of finite-size particles");
  if (force->newton_pair)
    error->all(FLERR,
               "Pair style granular/grflow/kk requires newton pair off (its contact history "
               "sends nothing back from ghost atoms): use 'newton off' or the KOKKOS package "
               "option 'newton off' (-pk kokkos newton off)");

  // the plain compute grflow/network reads this pair style's neighbor
  // list on the host, which a KOKKOS list does not fill: it would count no
  // contacts.  Its KOKKOS variant reads them on the device.
  for (auto *icompute : modify->get_compute_by_style("^grflow/network$"))
    error->all(FLERR,
               "Compute {} (grflow/network) does not work with pair style granular/grflow/kk "
               "(it reads the pair style's neighbor list on the host): use compute "
               "grflow/network/kk (-sf kk), or granular/grflow",
               icompute->id);

  // on first init, the history fix replaces the FixDummy of the
  // constructor (keeping its place in the fix list).  Not fix
  // NEIGH_HISTORY/KK: it negates every value when a pair changes owner,
  // and the rolling and torsion springs must keep their sign.

  if (fix_history == nullptr) {
    const auto cmd = fmt::format("{} all {} {}", id_history, history_fix_style(execution_space),
                                 (int) GRFLOW::HIST_SIZE);
    fix_history = dynamic_cast<FixNeighHistory *>(modify->replace_fix(id_dummy, cmd, 0));
    fix_history->pair = this;
  }

  // checks of the plain style, the neighbor request, the timestep, radii
  PairGranularGRFLOW::init_style();

  fix_historyKK = dynamic_cast<FixNeighHistoryGRFLOWKokkos<DeviceType> *>(fix_history);
  if (!fix_historyKK || fix_historyKK->get_dnum() != GRFLOW::HIST_SIZE)
    error->all(FLERR,
               "Pair style granular/grflow/kk: fix {} is not the contact history of this "
               "KOKKOS style (a pair style of another accelerator defined before?)",
               id_history);

  auto request = neighbor->find_request(this);
  request->set_kokkos_host(std::is_same_v<DeviceType, LMPHostType> &&
                           !std::is_same_v<DeviceType, LMPDeviceType>);
  request->set_kokkos_device(std::is_same_v<DeviceType, LMPDeviceType>);
}

/* ----------------------------------------------------------------------
   coefficients of types i,j (and j,i) for the device
------------------------------------------------------------------------- */

template <class DeviceType> double PairGranularGRFLOWKokkos<DeviceType>::init_one(int i, int j)
{
  const double cut = PairGranularGRFLOW::init_one(i, j);

  const int n = atom->ntypes + 1;
  if ((int) k_coeff.extent(0) != n || (int) k_coeff.extent(1) != n)
    k_coeff = typename PairGranularGRFLOWKernel<DeviceType>::tdual_coeff_2d("pair:coeff", n, n);
  k_coeff.sync_host();
  k_coeff.h_view(i, j) = packed[i][j];
  k_coeff.h_view(j, i) = packed[j][i];
  k_coeff.modify_host();
  return cut;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairGranularGRFLOWKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);

  // per-atom energy and virial, reallocated (zeroed) as the KOKKOS styles do

  if (eflag_atom) {
    memoryKK->destroy_kokkos(k_eatom, eatom);
    memoryKK->create_kokkos(k_eatom, eatom, maxeatom, "pair:eatom");
    kernel.d_eatom = k_eatom.template view<DeviceType>();
  }
  if (vflag_atom) {
    memoryKK->destroy_kokkos(k_vatom, vatom);
    memoryKK->create_kokkos(k_vatom, vatom, maxvatom, "pair:vatom");
    kernel.d_vatom = k_vatom.template view<DeviceType>();
  }

  atomKK->sync(execution_space, datamask_read);
  if (eflag || vflag)
    atomKK->modified(execution_space, datamask_modify);
  else
    atomKK->modified(execution_space, F_MASK | TORQUE_MASK);

  PairGranularGRFLOWKernel<DeviceType> &k = kernel;
  k.x = atomKK->k_x.template view<DeviceType>();
  k.v = atomKK->k_v.template view<DeviceType>();
  k.omega = atomKK->k_omega.template view<DeviceType>();
  k.f = atomKK->k_f.template view<DeviceType>();
  k.torque = atomKK->k_torque.template view<DeviceType>();
  k.type = atomKK->k_type.template view<DeviceType>();
  k.radius = atomKK->k_radius.template view<DeviceType>();
  k.nlocal = atom->nlocal;
  k.full_arm = full_arm;
  k.dt = dt;
  k.eflag = eflag;
  k.eflag_global = eflag_global;
  k.eflag_atom = eflag_atom;
  k.vflag_either = vflag_either;
  k.vflag_global = vflag_global;
  k.vflag_atom = vflag_atom;
  for (int m = 0; m < 4; m++) k.weight_lj[m] = force->special_lj[m];

  k_coeff.template sync<DeviceType>();
  k.d_coeff = k_coeff.template view<DeviceType>();

  auto k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  const int inum = list->inum;
  k.inum = inum;
  k.d_ilist = k_list->d_ilist;
  k.d_numneigh = k_list->d_numneigh;
  k.d_neighbors = k_list->d_neighbors;

  fix_historyKK->k_firstflag.template sync<DeviceType>();
  fix_historyKK->k_firstvalue.template sync<DeviceType>();
  k.d_firsttouch = fix_historyKK->k_firstflag.template view<DeviceType>();
  k.d_firsthistory = fix_historyKK->k_firstvalue.template view<DeviceType>();

  // no history updates during setup (forces are recomputed for the same state)
  const bool update_history = (update->setupflag == 0);

  EV_FLOAT ev;
  if (inum > 0) {
    if (neighflag == HALF) {
      if (evflag) {
        if (update_history)
          Kokkos::parallel_reduce(
              Kokkos::RangePolicy<DeviceType, TagPairGranularGRFLOWCompute<HALF, 1, 1>>(0, inum),
              kernel, ev);
        else
          Kokkos::parallel_reduce(
              Kokkos::RangePolicy<DeviceType, TagPairGranularGRFLOWCompute<HALF, 1, 0>>(0, inum),
              kernel, ev);
      } else {
        if (update_history)
          Kokkos::parallel_for(
              Kokkos::RangePolicy<DeviceType, TagPairGranularGRFLOWCompute<HALF, 0, 1>>(0, inum),
              kernel);
        else
          Kokkos::parallel_for(
              Kokkos::RangePolicy<DeviceType, TagPairGranularGRFLOWCompute<HALF, 0, 0>>(0, inum),
              kernel);
      }
    } else {    // HALFTHREAD
      if (evflag) {
        if (update_history)
          Kokkos::parallel_reduce(
              Kokkos::RangePolicy<DeviceType, TagPairGranularGRFLOWCompute<HALFTHREAD, 1, 1>>(0,
                                                                                              inum),
              kernel, ev);
        else
          Kokkos::parallel_reduce(
              Kokkos::RangePolicy<DeviceType, TagPairGranularGRFLOWCompute<HALFTHREAD, 1, 0>>(0,
                                                                                              inum),
              kernel, ev);
      } else {
        if (update_history)
          Kokkos::parallel_for(
              Kokkos::RangePolicy<DeviceType, TagPairGranularGRFLOWCompute<HALFTHREAD, 0, 1>>(0,
                                                                                              inum),
              kernel);
        else
          Kokkos::parallel_for(
              Kokkos::RangePolicy<DeviceType, TagPairGranularGRFLOWCompute<HALFTHREAD, 0, 0>>(0,
                                                                                              inum),
              kernel);
      }
    }
  }

  // the touch flags change on every call, the springs when updated
  fix_historyKK->k_firstflag.template modify<DeviceType>();
  fix_historyKK->k_firstvalue.template modify<DeviceType>();
  computed = true;

  if (eflag_global) eng_vdwl += ev.evdwl;
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += ev.v[k];
  if (eflag_atom) {
    k_eatom.template modify<DeviceType>();
    k_eatom.template sync<LMPHostType>();
  }
  if (vflag_atom) {
    k_vatom.template modify<DeviceType>();
    k_vatom.template sync<LMPHostType>();
  }

  // two atoms at the same position: no contact normal.  Read back when the
  // list was just built (or at setup), not every step: a copy from the
  // device waits for the kernel.  Such atoms come from the input (they
  // cannot move into each other between two builds); the loop skips them.
  if (update->setupflag || neighbor->ago == 0) {
    Kokkos::deep_copy(h_same, kernel.d_same);
    if (h_same(0)) same_position_error();
  }
}

/* ----------------------------------------------------------------------
   the contacts of owned atom ilist[ii]
------------------------------------------------------------------------- */

template <class DeviceType>
template <int NEIGHFLAG, int EVFLAG, int HISTUPDATE>
KOKKOS_INLINE_FUNCTION void PairGranularGRFLOWKernel<DeviceType>::operator()(
    TagPairGranularGRFLOWCompute<NEIGHFLAG, EVFLAG, HISTUPDATE>, const int ii, EV_FLOAT &ev) const
{
  using namespace GRFLOW;

  // atomic updates of j with threads (HALFTHREAD)
  Kokkos::View<F_FLOAT *[3], typename DAT::t_f_array::array_layout,
               typename KKDevice<DeviceType>::value,
               Kokkos::MemoryTraits<AtomicF<NEIGHFLAG>::value>>
      a_f = f;
  Kokkos::View<F_FLOAT *[3], typename DAT::t_f_array::array_layout,
               typename KKDevice<DeviceType>::value,
               Kokkos::MemoryTraits<AtomicF<NEIGHFLAG>::value>>
      a_torque = torque;

  const int i = d_ilist[ii];
  const double xi[3] = {x(i, 0), x(i, 1), x(i, 2)};
  const double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
  const double wi[3] = {omega(i, 0), omega(i, 1), omega(i, 2)};
  const double radi = radius(i);
  const int itype = type(i);
  const int jnum = d_numneigh(i);

  double fi[3] = {0.0, 0.0, 0.0};
  double ti[3] = {0.0, 0.0, 0.0};

  for (int jj = 0; jj < jnum; jj++) {
    int j = d_neighbors(i, jj);
    const double factor_lj = weight_lj[sbmask(j)];
    j &= NEIGHMASK;
    if (factor_lj == 0.0) continue;

    double del[3] = {xi[0] - x(j, 0), xi[1] - x(j, 1), xi[2] - x(j, 2)};
    const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
    const double radj = radius(j);
    const double radsum = radi + radj;

    if (rsq >= radsum * radsum) {
      // a contact that ended: its springs are gone
      if (d_firsttouch(i, jj)) {
        d_firsttouch(i, jj) = 0;
        for (int k = 0; k < HIST_SIZE; k++) d_firsthistory(i, HIST_SIZE * jj + k) = 0.0;
      }
      continue;
    }
    d_firsttouch(i, jj) = 1;

    if (rsq == 0.0) {
      // no contact normal: the host names the atoms after the loop
      if (Kokkos::atomic_compare_exchange(&d_same(0), 0, 1) == 0) {
        d_same(1) = i;
        d_same(2) = j;
      }
      continue;
    }

    ContactGeometry g;
    pair_geometry(del, sqrt(rsq), radi, radj, full_arm != 0, g);
    const double vrel[3] = {vi[0] - v(j, 0), vi[1] - v(j, 1), vi[2] - v(j, 2)};
    const double wj[3] = {omega(j, 0), omega(j, 1), omega(j, 2)};
    const ContactCoeffs c = d_coeff(itype, type(j));

    double hist[HIST_SIZE];
    for (int k = 0; k < HIST_SIZE; k++) hist[k] = d_firsthistory(i, HIST_SIZE * jj + k);
    ContactForces out;
    contact_forces(c, g, vrel, wi, wj, dt, HISTUPDATE != 0, hist, out);
    if (HISTUPDATE)
      for (int k = 0; k < HIST_SIZE; k++) d_firsthistory(i, HIST_SIZE * jj + k) = hist[k];

    const double fc[3] = {factor_lj * out.f[0], factor_lj * out.f[1], factor_lj * out.f[2]};
    for (int k = 0; k < 3; k++) {
      fi[k] += fc[k];
      ti[k] += factor_lj * out.torque_i[k];
    }
    if (j < nlocal) {
      for (int k = 0; k < 3; k++) {
        a_f(j, k) -= fc[k];
        a_torque(j, k) += factor_lj * out.torque_j[k];
      }
    }

    if (EVFLAG) {
      const double evdwl = eflag ? factor_lj * elastic_energy(c, g.delta, hist) : 0.0;
      ev_tally<NEIGHFLAG>(ev, i, j, evdwl, fc, del);
    }
  }

  for (int k = 0; k < 3; k++) {
    a_f(i, k) += fi[k];
    a_torque(i, k) += ti[k];
  }
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
template <int NEIGHFLAG, int EVFLAG, int HISTUPDATE>
KOKKOS_INLINE_FUNCTION void PairGranularGRFLOWKernel<DeviceType>::operator()(
    TagPairGranularGRFLOWCompute<NEIGHFLAG, EVFLAG, HISTUPDATE>, const int ii) const
{
  EV_FLOAT ev;
  this->template operator()<NEIGHFLAG, EVFLAG, HISTUPDATE>(
      TagPairGranularGRFLOWCompute<NEIGHFLAG, EVFLAG, HISTUPDATE>(), ii, ev);
}

/* ----------------------------------------------------------------------
   energy and virial of the contact of owned i and j (newton pair off: half
   to each of them that is owned), as Pair::ev_tally_xyz() tallies them
------------------------------------------------------------------------- */

template <class DeviceType>
template <int NEIGHFLAG>
KOKKOS_INLINE_FUNCTION void
PairGranularGRFLOWKernel<DeviceType>::ev_tally(EV_FLOAT &ev, const int i, const int j,
                                               const double evdwl, const double *fc,
                                               const double *del) const
{
  const bool jown = (j < nlocal);

  if (eflag_global) {
    const double half = 0.5 * evdwl;
    ev.evdwl += half;
    if (jown) ev.evdwl += half;
  }
  if (eflag_atom) {
    Kokkos::View<E_FLOAT *, typename DAT::t_efloat_1d::array_layout,
                 typename KKDevice<DeviceType>::value,
                 Kokkos::MemoryTraits<AtomicF<NEIGHFLAG>::value>>
        a_eatom = d_eatom;
    const double half = 0.5 * evdwl;
    a_eatom(i) += half;
    if (jown) a_eatom(j) += half;
  }

  if (vflag_either) {
    const double vv[6] = {del[0] * fc[0], del[1] * fc[1], del[2] * fc[2],
                          del[0] * fc[1], del[0] * fc[2], del[1] * fc[2]};
    if (vflag_global) {
      for (int k = 0; k < 6; k++) {
        ev.v[k] += 0.5 * vv[k];
        if (jown) ev.v[k] += 0.5 * vv[k];
      }
    }
    if (vflag_atom) {
      Kokkos::View<F_FLOAT *[6], typename DAT::t_virial_array::array_layout,
                   typename KKDevice<DeviceType>::value,
                   Kokkos::MemoryTraits<AtomicF<NEIGHFLAG>::value>>
          a_vatom = d_vatom;
      for (int k = 0; k < 6; k++) {
        a_vatom(i, k) += 0.5 * vv[k];
        if (jown) a_vatom(j, k) += 0.5 * vv[k];
      }
    }
  }
}

/* ----------------------------------------------------------------------
   force of one pair for compute pair/local and friends: that of
   PairGranularGRFLOW, reading the history through a host copy of the
   neighbor list and the host side of the history fix's values
------------------------------------------------------------------------- */

template <class DeviceType>
double PairGranularGRFLOWKokkos<DeviceType>::single(int i, int j, int itype, int jtype, double rsq,
                                                    double factor_coul, double factor_lj,
                                                    double &fforce)
{
  atomKK->sync(Host, X_MASK | V_MASK | OMEGA_MASK | RADIUS_MASK | TYPE_MASK);
  update_host_list();

  NeighList *own = list;
  list = host_list;
  const double e =
      PairGranularGRFLOW::single(i, j, itype, jtype, rsq, factor_coul, factor_lj, fforce);
  list = own;
  return e;
}

/* ----------------------------------------------------------------------
   the host copy of the neighbor list (rebuilt after each list build) and
   of the history values
------------------------------------------------------------------------- */

template <class DeviceType> void PairGranularGRFLOWKokkos<DeviceType>::update_host_list()
{
  if (!fix_historyKK || !list) return;
  fix_historyKK->k_firstflag.sync_host();
  fix_historyKK->k_firstvalue.sync_host();
  if (host_list && host_list_build == fix_historyKK->nbuild) return;

  auto k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  auto h_ilist = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), k_list->d_ilist);
  auto h_numneigh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), k_list->d_numneigh);
  auto h_neighbors = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), k_list->d_neighbors);

  if (!host_list) host_list = new NeighList(lmp);
  const int inum = list->inum;
  const int rows = h_numneigh.extent(0);
  const int cols = h_neighbors.extent(1);
  memory->destroy(host_list->ilist);
  memory->destroy(host_list->numneigh);
  memory->sfree(host_list->firstneigh);
  memory->create(host_list->ilist, MAX(inum, 1), "pair:host_ilist");
  memory->create(host_list->numneigh, MAX(rows, 1), "pair:host_numneigh");
  host_list->firstneigh =
      (int **) memory->smalloc(sizeof(int *) * MAX(rows, 1), "pair:host_firstneigh");
  host_neighbors = decltype(host_neighbors)("pair:host_neighbors", MAX(rows, 1), MAX(cols, 1));
  for (int r = 0; r < rows; r++) {
    host_list->numneigh[r] = 0;
    host_list->firstneigh[r] = &host_neighbors(r, 0);
  }
  for (int ii = 0; ii < inum; ii++) {
    const int i = h_ilist(ii);
    host_list->ilist[ii] = i;
    host_list->numneigh[i] = h_numneigh(i);
    for (int jj = 0; jj < h_numneigh(i); jj++) host_neighbors(i, jj) = h_neighbors(i, jj);
  }
  host_list->inum = inum;
  host_list->gnum = 0;
  host_list_build = fix_historyKK->nbuild;
}

/* ----------------------------------------------------------------------
   error naming two atoms at the same position (found by the pair loop)
------------------------------------------------------------------------- */

template <class DeviceType> void PairGranularGRFLOWKokkos<DeviceType>::same_position_error()
{
  atomKK->sync(Host, X_MASK | TAG_MASK);
  const int i = h_same(1), j = h_same(2);
  error->one(FLERR,
             "Pair granular/grflow/kk: atoms {} and {} are at the same position {} {} {}: "
             "the contact normal is undefined",
             atom->tag[i], atom->tag[j], atom->x[i][0], atom->x[i][1], atom->x[i][2]);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> double PairGranularGRFLOWKokkos<DeviceType>::memory_usage()
{
  double bytes = PairGranularGRFLOW::memory_usage();
  bytes += MemKK::memory_usage(k_coeff.d_view);
  bytes += MemKK::memory_usage(host_neighbors);
  bytes += MemKK::memory_usage(kernel.d_same);
  return bytes;
}

namespace LAMMPS_NS {
template class PairGranularGRFLOWKokkos<LMPDeviceType>;
template class FixNeighHistoryGRFLOWKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairGranularGRFLOWKokkos<LMPHostType>;
template class FixNeighHistoryGRFLOWKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
