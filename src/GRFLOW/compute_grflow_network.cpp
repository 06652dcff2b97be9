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

   Stress (from contact forces), coordination, connectivity and fabric
   anisotropy of the particles in a sub-volume, after Eqs. (1)-(3) of
   "Geometrical network of granular materials under isochoric cyclic
   shearing".  Contacts are taken from the pair style's own neighbor list
   through Pair::single(), so that the stored contact history is used.
------------------------------------------------------------------------- */

#include "compute_grflow_network.h"

#include "grflow_contact.h"
#include "grflow_network.h"
#include "grflow_restart.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_grflow_shear.h"
#include "fix_grflow_wall.h"
#include "force.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "pair.h"
#include "region.h"
#include "update.h"
#include "variable.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

enum { INSIDE, NCONTACTS };

/* ---------------------------------------------------------------------- */

ComputeGRFLOWNetwork::ComputeGRFLOWNetwork(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), region(nullptr), p0_owner(nullptr), invoked_stress(-1),
    inside(nullptr), ncontact(nullptr)
{
  nmax = 0;
  commflag = INSIDE;

  GRFLOW::FixHost host{lmp};
  opt.parse(narg, arg, 3, host);
  if (!opt.region.empty() && !domain->get_region_by_id(opt.region))
    error->all(FLERR, "Region {} for compute grflow/network does not exist", opt.region);

  if (!atom->radius_flag)
    error->all(FLERR, "Compute grflow/network requires atom attribute radius (atom_style sphere)");

  vector_flag = 1;
  size_vector = NetworkLayout::size(opt.cmax);
  extvector = 0;
  vector = new double[size_vector];
  for (int k = 0; k < size_vector; k++) vector[k] = 0.0;
  for (double &value : stress) value = 0.0;

  comm_forward = 1;
  comm_reverse = 1;
}

/* ---------------------------------------------------------------------- */

ComputeGRFLOWNetwork::~ComputeGRFLOWNetwork()
{
  delete[] vector;
  memory->destroy(inside);
  memory->destroy(ncontact);
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::init()
{
  check_setup();
}

/* ----------------------------------------------------------------------
   pair style, region, wall fixes and variables; done at init() and again
   by compute_vector() between runs, where the library interface can call
   it on a compute that was defined after the last run and never
   initialized
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::check_setup()
{
  Pair *pair = force->pair;
  if (!pair) error->all(FLERR, "Compute grflow/network requires a pair style");
  if (!pair->single_enable || !pair->finitecutflag || !pair->svector || pair->single_extra < 3)
    error->all(FLERR,
               "Compute grflow/network requires a granular pair style with single() "
               "giving the sliding force in svector[0-2] (granular/grflow, granular, gran/*), "
               "not {}",
               force->pair_style);

  if (!opt.region.empty()) {
    region = domain->get_region_by_id(opt.region);
    if (!region)
      error->all(FLERR, "Region {} for compute grflow/network does not exist", opt.region);
    if (opt.volume.empty() && (strcmp(region->style, "block") != 0 || !region->interior))
      error->all(FLERR,
                 "Compute grflow/network region {} is not an inside block: give its "
                 "volume with the volume keyword",
                 opt.region);
  }
  walls.clear();
  for (auto *ifix : modify->get_fix_by_style("^grflow/wall$")) {
    auto *wfix = dynamic_cast<FixGRFLOWWall *>(ifix);
    if (!wfix)
      error->all(FLERR,
                 "Compute grflow/network cannot read fix {}: it comes from another build "
                 "of GRFLOW (plugin and built-in styles mixed)",
                 ifix->id);
    walls.push_back(wfix);
  }
  // the owner of p0 (none with the p0 keyword: fix grflow/shear refuses it)
  p0_owner = nullptr;
  for (auto *ifix : modify->get_fix_by_style("^grflow/shear$")) {
    auto *shear = dynamic_cast<FixGRFLOWShear *>(ifix);
    if (shear && shear->network_id() == id) p0_owner = shear;
  }

  for (const std::string &str : {opt.zlo, opt.zhi, opt.volume}) {
    const char *s = str.c_str();
    if (strncmp(s, "v_", 2) != 0) continue;
    const int ivar = input->variable->find(s + 2);
    if (ivar < 0) error->all(FLERR, "Variable {} for compute grflow/network does not exist", s + 2);
    if (!input->variable->equalstyle(ivar))
      error->all(FLERR, "Variable {} for compute grflow/network is not equal-style", s + 2);
  }
}

/* ----------------------------------------------------------------------
   value of a number or v_name argument
------------------------------------------------------------------------- */

double ComputeGRFLOWNetwork::eval(const char *str, const char *what)
{
  if (strncmp(str, "v_", 2) != 0) return utils::numeric(FLERR, str, false, lmp);
  const int ivar = input->variable->find(str + 2);
  if (ivar < 0)
    error->all(FLERR, "Variable {} for compute grflow/network {} does not exist", str + 2, what);
  const double value = input->variable->compute_equal(ivar);
  if (!std::isfinite(value))
    error->all(FLERR, "Compute grflow/network {}: variable {} is {}, not a finite number", what,
               str + 2, value);
  return value;
}

/* ----------------------------------------------------------------------
   flag owned atoms in the group and the sub-volume; return its volume
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::set_inside(double &volume)
{
  double **x = atom->x;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;

  if (region) {
    region->prematch();
    if (!opt.volume.empty()) {
      volume = eval(opt.volume.c_str(), "volume");
    } else {
      const double lo[3] = {region->extent_xlo, region->extent_ylo, region->extent_zlo};
      const double hi[3] = {region->extent_xhi, region->extent_yhi, region->extent_zhi};
      volume = GRFLOW::NetworkVolume::clipped_box(lo, hi, domain->boxlo, domain->boxhi);
    }
    for (int i = 0; i < nlocal; i++)
      inside[i] = ((mask[i] & groupbit) && region->match(x[i][0], x[i][1], x[i][2])) ? 1.0 : 0.0;
  } else {
    const double zlo = opt.zlo.empty() ? domain->boxlo[2] : eval(opt.zlo.c_str(), "zlimits");
    const double zhi = opt.zhi.empty() ? domain->boxhi[2] : eval(opt.zhi.c_str(), "zlimits");
    if (!(zhi > zlo))
      error->all(FLERR, "Compute grflow/network zlimits must have zlo < zhi, got {} {}", zlo, zhi);
    double lo, hi;
    opt.slab_bounds(zlo, zhi, lo, hi);
    volume = domain->xprd * domain->yprd * (hi - lo);
    GRFLOW::NetworkVolume::flag_slab(x, mask, groupbit, nlocal, lo, hi, domain->zperiodic != 0,
                                     domain->boxlo[2], domain->boxhi[2], domain->zprd, inside);
  }
  if (!(volume > 0.0) || !std::isfinite(volume))
    error->all(FLERR, "Compute grflow/network sub-volume is {}: must be finite and > 0", volume);
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::compute_vector()
{
  invoked_vector = update->ntimestep;
  evaluate(true, vector);
  // its stress entries are those compute_stress() would give
  for (int k = 0; k < NSTRESS; k++) stress[k] = vector[k];
  invoked_stress = update->ntimestep;
}

/* ---------------------------------------------------------------------- */

const double *ComputeGRFLOWNetwork::compute_stress()
{
  invoked_stress = update->ntimestep;
  evaluate(false, stress);
  return stress;
}

/* ---------------------------------------------------------------------- */

const double *ComputeGRFLOWNetwork::current_stress()
{
  if (invoked_stress == update->ntimestep) return stress;
  return compute_stress();
}

/* ----------------------------------------------------------------------
   the output vector (network) or its stress entries (NetworkLayout,
   GRFLOW::derive_stress()), into out.  The stress sums are added in the
   same order either way, and both pass the same ghost and inside[]
   communication, so the stress path changes no result.
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::evaluate(bool network, double *out)
{
  // during a run or minimization init() has done the checks and found the
  // walls (fixes cannot come or go within a run); between runs (library
  // calls, variables) they are done here, as init() may not have been
  if (update->whichflag == 0) check_setup();
  require_current_contacts();
  grow_peratom();

  const double volume = refresh_ghosts_and_inside();
  // per processor: stress sums sum l (x) f (9), fabric sums sum n (x) n (9),
  // particles inside, floaters, contact ends, histogram of contact numbers
  // (the stress path fills only the first 9)
  std::vector<double> local(GRFLOW::NetworkSums::size(opt.cmax), 0.0);
  sum_pair_contacts(local.data(), network);
  sum_wall_contacts(local.data(), network);
  if (network) count_particles(local.data());
  opt.reduce_and_derive(world, local, volume, out, network, p0_owner ? p0_owner->p0() : 0.0);
}

/* ----------------------------------------------------------------------
   the pair style's neighbor list exists and every wall fix recorded its
   contacts on this step
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::require_current_contacts()
{
  NeighList *list = force->pair->list;
  if (!list || !list->numneigh)
    error->all(FLERR,
               "Compute grflow/network needs the pair style's neighbor list: "
               "use it after a run (run 0 will do)");
  // the wall contacts are those its post_force() recorded on this step: a
  // fix that invokes the compute in its setup() before the wall fix's
  // setup() has run (it was defined first) would read the last run's
  for (auto *wfix : walls) {
    if (wfix->contacts_step() == update->ntimestep) continue;
    if (update->whichflag == 2)
      error->all(FLERR,
                 "Compute grflow/network {} cannot be used during a minimization: fix "
                 "grflow/wall {} records no wall contacts there",
                 id, wfix->id);
    error->all(FLERR,
               "Compute grflow/network {}: fix grflow/wall {} has no contacts for step "
               "{}: define it before the fixes that invoke this compute, and use the compute "
               "after a run (run 0 will do)",
               id, wfix->id, update->ntimestep);
  }
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::grow_peratom()
{
  if (atom->nmax <= nmax) return;
  memory->destroy(inside);
  memory->destroy(ncontact);
  nmax = atom->nmax;
  memory->create(inside, nmax, "grflow/network:inside");
  memory->create(ncontact, nmax, "grflow/network:ncontact");
}

/* ----------------------------------------------------------------------
   ghosts as the pair style would see them, and inside[] of owned and
   ghost atoms; returns the volume of the sub-volume
------------------------------------------------------------------------- */

double ComputeGRFLOWNetwork::refresh_ghosts_and_inside()
{
  // ghosts are refreshed by the integrator before the forces, not after:
  // at the end of a step their velocities are half a step old and, after
  // a box change (fix deform), their positions are those of the old box.
  // Bring positions, velocities and spins up to date, as the pair style
  // would see them, so that results do not depend on which atoms are ghosts.
  comm->forward_comm();

  double volume = 0.0;
  set_inside(volume);
  commflag = INSIDE;
  comm->forward_comm(this);
  return volume;
}

/* ----------------------------------------------------------------------
   particle-particle contacts: per contact, the end of each particle inside
   contributes its arm to the stress, (a - delta/2) n (x) f with f the
   force on i, and n (x) n to the fabric; ncontact[] counts them (summed
   from ghosts to owners with newton on)
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::sum_pair_contacts(double *sums, bool network)
{
  Pair *pair = force->pair;
  NeighList *list = pair->list;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  if (network)
    for (int i = 0; i < nall; i++) ncontact[i] = 0.0;

  double **x = atom->x;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int newton_pair = force->newton_pair;
  const double *special_lj = force->special_lj;
  const double *svector = pair->svector;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj];
      const double factor_lj = special_lj[sbmask(j)];
      j &= NEIGHMASK;
      if (factor_lj == 0.0) continue;

      bool use_i, use_j;
      GRFLOW::NetworkSums::count_ends(inside[i] > 0.0, inside[j] > 0.0, j < nlocal,
                                      newton_pair != 0, use_i, use_j);
      if (!use_i && !use_j) continue;

      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const double radsum = radius[i] + radius[j];
      if (rsq >= radsum * radsum) continue;

      double fpair = 0.0;
      pair->single(i, j, type[i], type[j], rsq, 1.0, factor_lj, fpair);
      if (fpair <= 0.0) continue;    // touching but carrying no normal force

      const double r = sqrt(rsq);
      const double n[3] = {del[0] / r, del[1] / r, del[2] / r};
      const double f[3] = {fpair * del[0] + svector[0], fpair * del[1] + svector[1],
                           fpair * del[2] + svector[2]};
      if (network) {
        if (use_i) ncontact[i] += 1.0;
        if (use_j) ncontact[j] += 1.0;
      }
      GRFLOW::NetworkSums::add_pair_contact(sums, n, f, radsum - r, radius[i], radius[j], use_i,
                                            use_j, network);
    }
  }

  if (network && newton_pair) {
    commflag = NCONTACTS;
    comm->reverse_comm(this);
  }
}

/* ----------------------------------------------------------------------
   contacts of owned particles inside with GRFLOW walls (the force-bearing
   ones its post_force() recorded on this step): n is the wall normal
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::sum_wall_contacts(double *sums, bool network)
{
  GRFLOW::add_wall_contacts(walls, inside, atom->nlocal, network ? ncontact : nullptr, sums);
}

/* ----------------------------------------------------------------------
   per owned particle inside: the count, floaters, contact ends and the
   histogram of contact numbers
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::count_particles(double *sums)
{
  GRFLOW::add_particles(inside, ncontact, atom->nlocal, opt.cmax, sums);
}

/* ---------------------------------------------------------------------- */

int ComputeGRFLOWNetwork::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/,
                                            int * /*pbc*/)
{
  for (int i = 0; i < n; i++) buf[i] = inside[list[i]];
  return n;
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::unpack_forward_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) inside[first + i] = buf[i];
}

/* ---------------------------------------------------------------------- */

int ComputeGRFLOWNetwork::pack_reverse_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) buf[i] = ncontact[first + i];
  return n;
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int i = 0; i < n; i++) ncontact[list[i]] += buf[i];
}

/* ---------------------------------------------------------------------- */

double ComputeGRFLOWNetwork::memory_usage()
{
  return 2.0 * nmax * sizeof(double);
}

/* ---------------------------------------------------------------------- */

ComputeGRFLOWNetwork *ComputeGRFLOWNetwork::find(LAMMPS *lmp, const std::string &caller,
                                                 const char *id)
{
  auto *icompute = lmp->modify->get_compute_by_id(id);
  if (!icompute) lmp->error->all(FLERR, "{}: compute {} does not exist", caller, id);
  auto *network = dynamic_cast<ComputeGRFLOWNetwork *>(icompute);
  if (!network || strcmp(icompute->style, "grflow/network") != 0)
    lmp->error->all(FLERR, "{}: compute {} is not a compute grflow/network", caller, id);
  return network;
}
