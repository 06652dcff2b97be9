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
   shearing".  Contacts between particles are taken from the pair style's
   own neighbor list with the contact history it keeps
   (GRFLOW::PairContacts of grflow_host_api.h: Pair::single() in LAMMPS);
   contacts with walls from every fix that offers them through
   extract("grflow/wall_contacts") (fix grflow/wall).  The sums and what
   is derived from them are host-free (src/shared/grflow_network.h).
------------------------------------------------------------------------- */

#include "compute_grflow_network.h"

#include "grflow_host_api.h"
#include "grflow_network.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "input.h"
#include "memory.h"
#include "neigh_list.h"
#include "pair.h"
#include "region.h"
#include "update.h"
#include "variable.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

// the fixes whose wall contacts the sums include, in definition order
struct GRFLOW::NetworkWalls {
  std::vector<Fix *> fixes;
};

enum { INSIDE, NCONTACTS };

/* ---------------------------------------------------------------------- */

ComputeGRFLOWNetwork::ComputeGRFLOWNetwork(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), opt(nullptr), walls(nullptr), region(nullptr), stress(nullptr),
    invoked_stress(-1), nmax(0), inside(nullptr), ncontact(nullptr), commflag(INSIDE)
{
  opt = new GRFLOW::NetworkOptions;
  walls = new GRFLOW::NetworkWalls;
  GRFLOW::FixHost host{lmp};
  opt->parse(narg, arg, 3, host);
  if (!opt->region.empty() && !GRFLOW::region_by_id(lmp, opt->region))
    error->all(FLERR, "Region " + opt->region + " for compute grflow/network does not exist");

  if (!atom->radius_flag)
    error->all(FLERR, "Compute grflow/network requires atom attribute radius (atom_style sphere)");

  vector_flag = 1;
  size_vector = GRFLOW::NetworkLayout::size(opt->cmax);
  extvector = 0;
  vector = new double[size_vector];
  for (int k = 0; k < size_vector; k++) vector[k] = 0.0;
  stress = new double[GRFLOW::NetworkLayout::NSTRESS];
  for (int k = 0; k < GRFLOW::NetworkLayout::NSTRESS; k++) stress[k] = 0.0;

  comm_forward = 1;
  comm_reverse = 1;
}

/* ---------------------------------------------------------------------- */

ComputeGRFLOWNetwork::~ComputeGRFLOWNetwork()
{
  delete[] vector;
  delete[] stress;
  delete walls;
  delete opt;
  memory->destroy(inside);
  memory->destroy(ncontact);
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::init()
{
  check_setup();
}

/* ----------------------------------------------------------------------
   pair style, region, the fixes with wall contacts and variables; done at
   init() and again by compute_vector() between runs, where the library
   interface can call it on a compute that was defined after the last run
   and never initialized
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::check_setup()
{
  GRFLOW::PairContacts::check(lmp, std::string("Compute ") + style);

  region = nullptr;
  if (!opt->region.empty()) {
    region = GRFLOW::region_by_id(lmp, opt->region);
    if (!region)
      error->all(FLERR, "Region " + opt->region + " for compute grflow/network does not exist");
    if (opt->volume.empty() && (strcmp(region->style, "block") != 0 || !region->interior))
      error->all(FLERR,
                 "Compute grflow/network region " + opt->region +
                     " is not an inside block: give its volume with the volume keyword");
  }

  // every fix that offers wall contacts (fix grflow/wall): its per-atom
  // array holds them, and extract() says so
  walls->fixes.clear();
  for (Fix *ifix : GRFLOW::all_fixes(lmp)) {
    int dim = -1;
    if (ifix->peratom_flag && ifix->size_peratom_cols > 0 &&
        ifix->extract("grflow/wall_contacts", dim))
      walls->fixes.push_back(ifix);
  }

  for (const std::string &str : {opt->zlo, opt->zhi, opt->volume}) {
    if (str.compare(0, 2, "v_") != 0) continue;
    const std::string name = str.substr(2);
    const int ivar = GRFLOW::variable_index(lmp, name);
    if (ivar < 0)
      error->all(FLERR, "Variable " + name + " for compute grflow/network does not exist");
    if (!input->variable->equalstyle(ivar))
      error->all(FLERR, "Variable " + name + " for compute grflow/network is not equal-style");
  }
}

/* ----------------------------------------------------------------------
   value of a number or v_name argument
------------------------------------------------------------------------- */

double ComputeGRFLOWNetwork::eval(const std::string &str, const char *what)
{
  GRFLOW::FixHost host{lmp};
  if (str.compare(0, 2, "v_") != 0)
    return host.number(FLERR, str.c_str(), std::string("compute grflow/network ") + what);
  const std::string name = str.substr(2);
  const int ivar = GRFLOW::variable_index(lmp, name);
  if (ivar < 0)
    error->all(FLERR,
               "Variable " + name + " for compute grflow/network " + what + " does not exist");
  const double value = input->variable->compute_equal(ivar);
  if (!std::isfinite(value))
    error->all(FLERR,
               std::string("Compute grflow/network ") + what + ": variable " + name + " is " +
                   host.text(value) + ", not a finite number");
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
    if (!opt->volume.empty()) {
      volume = eval(opt->volume, "volume");
    } else {
      const double lo[3] = {region->extent_xlo, region->extent_ylo, region->extent_zlo};
      const double hi[3] = {region->extent_xhi, region->extent_yhi, region->extent_zhi};
      volume = GRFLOW::NetworkVolume::clipped_box(lo, hi, domain->boxlo, domain->boxhi);
    }
    for (int i = 0; i < nlocal; i++)
      inside[i] = ((mask[i] & groupbit) && region->match(x[i][0], x[i][1], x[i][2])) ? 1.0 : 0.0;
  } else {
    double lo, hi;
    volume = slab_volume(lo, hi);
    GRFLOW::NetworkVolume::flag_slab(x, mask, groupbit, nlocal, lo, hi, domain->zperiodic != 0,
                                     domain->boxlo[2], domain->boxhi[2], domain->zprd, inside);
  }
  check_volume(volume);
}

/* ----------------------------------------------------------------------
   the slab of the sample between zlimits (or the box), lo <= z < hi;
   returns its volume
------------------------------------------------------------------------- */

double ComputeGRFLOWNetwork::slab_volume(double &lo, double &hi)
{
  const double zlo = opt->zlo.empty() ? domain->boxlo[2] : eval(opt->zlo, "zlimits");
  const double zhi = opt->zhi.empty() ? domain->boxhi[2] : eval(opt->zhi, "zlimits");
  GRFLOW::FixHost host{lmp};
  if (!(zhi > zlo))
    error->all(FLERR,
               "Compute grflow/network zlimits must have zlo < zhi, got " + host.text(zlo) + " " +
                   host.text(zhi));
  opt->slab_bounds(zlo, zhi, lo, hi);
  return domain->xprd * domain->yprd * (hi - lo);
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::check_volume(double volume)
{
  if (!(volume > 0.0) || !std::isfinite(volume)) {
    GRFLOW::FixHost host{lmp};
    error->all(FLERR,
               "Compute grflow/network sub-volume is " + host.text(volume) +
                   ": must be finite and > 0");
  }
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::compute_vector()
{
  invoked_vector = update->ntimestep;
  evaluate(true, vector);
  // its stress entries are those compute_stress() would give
  for (int k = 0; k < GRFLOW::NetworkLayout::NSTRESS; k++) stress[k] = vector[k];
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

  // per processor: stress sums sum l (x) f (9), fabric sums sum n (x) n (9),
  // particles inside, floaters, contact ends, histogram of contact numbers
  // (the stress path fills only the first 9)
  std::vector<double> local(GRFLOW::NetworkSums::size(opt->cmax), 0.0);
  const double volume = local_sums(local.data(), network);
  opt->reduce_and_derive(world, local, volume, out, network);
}

/* ----------------------------------------------------------------------
   this processor's sums (zeroed by the caller); returns the volume of the
   sub-volume
------------------------------------------------------------------------- */

double ComputeGRFLOWNetwork::local_sums(double *sums, bool network)
{
  grow_peratom();
  const double volume = refresh_ghosts_and_inside();
  sum_pair_contacts(sums, network);
  sum_wall_contacts(sums, network);
  if (network) count_particles(sums);
  return volume;
}

/* ----------------------------------------------------------------------
   the pair style's neighbor list exists and every fix with wall contacts
   recorded them on this step
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::require_current_contacts()
{
  require_pair_list();
  // the wall contacts are those its post_force() recorded on this step: a
  // fix that invokes the compute in its setup() before the wall fix's
  // setup() has run (it was defined first) would read the last run's
  for (Fix *wfix : walls->fixes) {
    if (wall_contacts_step(wfix) == update->ntimestep) continue;
    if (update->whichflag == 2)
      error->all(FLERR,
                 std::string("Compute grflow/network ") + id +
                     " cannot be used during a minimization: fix " + wfix->style + " " + wfix->id +
                     " records no wall contacts there");
    error->all(FLERR,
               std::string("Compute grflow/network ") + id + ": fix " + wfix->style + " " +
                   wfix->id + " has no contacts for step " + std::to_string(update->ntimestep) +
                   ": define it before the fixes that invoke this compute, and use the compute "
                   "after a run (run 0 will do)");
  }
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::require_pair_list()
{
  GRFLOW::PairContacts::require_list(lmp, std::string("Compute ") + style);
}

/* ---------------------------------------------------------------------- */

bigint ComputeGRFLOWNetwork::wall_contacts_step(Fix *wfix)
{
  int dim = -1;
  const auto *contacts =
      static_cast<const GRFLOW::WallContacts *>(wfix->extract("grflow/wall_contacts", dim));
  return contacts->step;
}

/* ---------------------------------------------------------------------- */

int ComputeGRFLOWNetwork::nwall_fixes() const
{
  return (int) walls->fixes.size();
}

/* ---------------------------------------------------------------------- */

Fix *ComputeGRFLOWNetwork::wall_fix(int k) const
{
  return walls->fixes[k];
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
  NeighList *list = force->pair->list;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  if (network)
    for (int i = 0; i < nall; i++) ncontact[i] = 0.0;

  double **x = atom->x;
  const double *radius = atom->radius;
  const bool newton_pair = force->newton_pair != 0;
  GRFLOW::PairContacts contacts(lmp);

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const double factor = contacts.factor(jlist[jj]);
      const int j = jlist[jj] & NEIGHMASK;
      if (factor == 0.0) continue;

      bool use_i, use_j;
      GRFLOW::NetworkSums::count_ends(inside[i] > 0.0, inside[j] > 0.0, j < nlocal, newton_pair,
                                      use_i, use_j);
      if (!use_i && !use_j) continue;

      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const double radsum = radius[i] + radius[j];
      if (rsq >= radsum * radsum) continue;

      double n[3], f[3], delta;
      // touching but carrying no normal force: not a contact of the network
      if (!contacts.contact(i, j, jj, del, rsq, factor, n, f, delta)) continue;
      if (network) {
        if (use_i) ncontact[i] += 1.0;
        if (use_j) ncontact[j] += 1.0;
      }
      GRFLOW::NetworkSums::add_pair_contact(sums, n, f, delta, radius[i], radius[j], use_i, use_j,
                                            network);
    }
  }

  if (network && newton_pair) {
    commflag = NCONTACTS;
    comm->reverse_comm(this);
  }
}

/* ----------------------------------------------------------------------
   contacts of owned particles inside with walls (the force-bearing ones
   each fix with wall contacts recorded on this step): n is the wall
   normal
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::sum_wall_contacts(double *sums, bool network)
{
  for (Fix *wfix : walls->fixes) {
    int dim = -1;
    const auto *contacts =
        static_cast<const GRFLOW::WallContacts *>(wfix->extract("grflow/wall_contacts", dim));
    GRFLOW::add_wall_contacts(*contacts, inside, atom->nlocal, network ? ncontact : nullptr, sums);
  }
}

/* ----------------------------------------------------------------------
   per owned particle inside: the count, floaters, contact ends and the
   histogram of contact numbers
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::count_particles(double *sums)
{
  GRFLOW::add_particles(inside, ncontact, atom->nlocal, opt->cmax, sums);
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
                                                 const std::string &id)
{
  Compute *icompute = GRFLOW::compute_by_id(lmp, id);
  if (!icompute) lmp->error->all(FLERR, caller + ": compute " + id + " does not exist");
  // the plain style or one of its accelerator variants (grflow/network/kk)
  auto *network = dynamic_cast<ComputeGRFLOWNetwork *>(icompute);
  if (!network || strncmp(icompute->style, "grflow/network", 14) != 0)
    lmp->error->all(FLERR, caller + ": compute " + id + " is not a compute grflow/network");
  return network;
}
