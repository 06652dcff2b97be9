/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: compute grflow/network (see the header).

   Contacts come from the neighbor list of pair_style gran model grflow;
   the force of each contact is evaluated by the contact kernel from the
   springs stored in the pair's contact history, without advancing them
   (as LAMMPS's Pair::single() does), with the coefficients the model
   published (grflow_liggghts.h).

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).
------------------------------------------------------------------------- */

#include "compute_grflow_network.h"

#include "grflow_contact.h"
#include "grflow_liggghts.h"
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
#include "pair_gran.h"
#include "region.h"
#include "update.h"
#include "variable.h"

#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

using namespace LAMMPS_NS;

enum { INSIDE, NCONTACTS };

namespace {
// an error message from its pieces
template <class... T> std::string message(const T &...piece)
{
  std::ostringstream out;
  int expand[] = {0, ((out << piece), 0)...};
  (void) expand;
  return out.str();
}
}    // namespace

/* ---------------------------------------------------------------------- */

ComputeGRFLOWNetwork::ComputeGRFLOWNetwork(LAMMPS *lmp, int &iarg, int narg, char **arg) :
    Compute(lmp, iarg, narg, arg), region(NULL), p0_owner(NULL), invoked_stress(-1), nmax(0),
    inside(NULL), ncontact(NULL), commflag(INSIDE)
{
  GRFLOW::FixHost host = {lmp};
  opt.parse(narg, arg, iarg, host);
  iarg = narg;
  if (!opt.region.empty() && domain->find_region(opt.region.c_str()) < 0)
    host.fail(message("Region ", opt.region, " for compute grflow/network does not exist"));
  if (!atom->radius_flag)
    host.fail("Compute grflow/network requires atom attribute radius (atom_style granular)");

  vector_flag = 1;
  size_vector = NetworkLayout::size(opt.cmax);
  extvector = 0;
  vector = new double[size_vector];
  for (int k = 0; k < size_vector; k++) vector[k] = 0.0;
  for (int k = 0; k < NSTRESS; k++) stress[k] = 0.0;

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
   pair style, region, wall fixes and variables
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::check_setup()
{
  if (!force->pair || !GRFLOW::liggghts_pair_laws().count(lmp) ||
      !dynamic_cast<PairGran *>(force->pair))
    error->all(FLERR,
               "Compute grflow/network requires pair_style gran model grflow "
               "(its contact forces come from GRFLOW's contact law)");

  region = NULL;
  if (!opt.region.empty()) {
    const int iregion = domain->find_region(opt.region.c_str());
    if (iregion < 0)
      error->all(
          FLERR,
          message("Region ", opt.region, " for compute grflow/network does not exist").c_str());
    region = domain->regions[iregion];
    if (opt.volume.empty() && (strcmp(region->style, "block") != 0 || !region->interior))
      error->all(FLERR,
                 message("Compute grflow/network region ", opt.region,
                         " is not an inside block: give its volume with the volume keyword")
                     .c_str());
  }
  walls.clear();
  for (int i = 0; i < modify->nfix; i++) {
    if (strcmp(modify->fix[i]->style, "grflow/wall") != 0) continue;
    FixGRFLOWWall *wfix = dynamic_cast<FixGRFLOWWall *>(modify->fix[i]);
    if (wfix) walls.push_back(wfix);
  }
  // the owner of p0 (none with the p0 keyword: fix grflow/shear refuses it)
  p0_owner = NULL;
  for (int i = 0; i < modify->nfix; i++) {
    if (strcmp(modify->fix[i]->style, "grflow/shear") != 0) continue;
    FixGRFLOWShear *shear = dynamic_cast<FixGRFLOWShear *>(modify->fix[i]);
    if (shear && shear->network_id() == id) p0_owner = shear;
  }

  const std::string *values[] = {&opt.zlo, &opt.zhi, &opt.volume};
  for (const std::string *s : values) {
    if (s->compare(0, 2, "v_") != 0) continue;
    std::vector<char> name(s->begin() + 2, s->end());
    name.push_back('\0');
    const int ivar = input->variable->find(name.data());
    if (ivar < 0)
      error->all(
          FLERR,
          message("Variable ", name.data(), " for compute grflow/network does not exist").c_str());
    if (!input->variable->equalstyle(ivar))
      error->all(FLERR,
                 message("Variable ", name.data(), " for compute grflow/network is not equal-style")
                     .c_str());
  }
}

/* ----------------------------------------------------------------------
   value of a number or v_name argument
------------------------------------------------------------------------- */

double ComputeGRFLOWNetwork::eval(const std::string &str, const char *what)
{
  if (str.compare(0, 2, "v_") != 0) return force->numeric(FLERR, str.c_str());
  std::vector<char> name(str.begin() + 2, str.end());
  name.push_back('\0');
  const int ivar = input->variable->find(name.data());
  if (ivar < 0)
    error->all(
        FLERR,
        message("Variable ", name.data(), " for compute grflow/network ", what, " does not exist")
            .c_str());
  const double value = input->variable->compute_equal(ivar);
  if (!std::isfinite(value))
    error->all(FLERR,
               message("Compute grflow/network ", what, ": variable ", name.data(), " is ", value,
                       ", not a finite number")
                   .c_str());
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
      volume = eval(opt.volume, "volume");
    } else {
      const double lo[3] = {region->extent_xlo, region->extent_ylo, region->extent_zlo};
      const double hi[3] = {region->extent_xhi, region->extent_yhi, region->extent_zhi};
      volume = GRFLOW::NetworkVolume::clipped_box(lo, hi, domain->boxlo, domain->boxhi);
    }
    for (int i = 0; i < nlocal; i++)
      inside[i] = ((mask[i] & groupbit) && region->match(x[i][0], x[i][1], x[i][2])) ? 1.0 : 0.0;
  } else {
    const double zlo = opt.zlo.empty() ? domain->boxlo[2] : eval(opt.zlo, "zlimits");
    const double zhi = opt.zhi.empty() ? domain->boxhi[2] : eval(opt.zhi, "zlimits");
    if (!(zhi > zlo))
      error->all(FLERR,
                 message("Compute grflow/network zlimits must have zlo < zhi, got ", zlo, " ", zhi)
                     .c_str());
    double lo, hi;
    opt.slab_bounds(zlo, zhi, lo, hi);
    volume = domain->xprd * domain->yprd * (hi - lo);
    GRFLOW::NetworkVolume::flag_slab(x, mask, groupbit, nlocal, lo, hi, domain->zperiodic != 0,
                                     domain->boxlo[2], domain->boxhi[2], domain->zprd, inside);
  }
  if (!(volume > 0.0) || !std::isfinite(volume))
    error->all(FLERR,
               message("Compute grflow/network sub-volume is ", volume, ": must be finite and > 0")
                   .c_str());
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::compute_vector()
{
  invoked_vector = update->ntimestep;
  evaluate(true, vector);
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
   the output vector (network) or its stress entries, into out: the
   stress sums are added in the same order either way (as in LAMMPS)
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::evaluate(bool network, double *out)
{
  if (update->whichflag == 0) check_setup();
  require_current_contacts();
  grow_peratom();

  const double volume = refresh_ghosts_and_inside();
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
  if (!list || !list->numneigh || !force->pair->listgranhistory)
    error->all(FLERR,
               "Compute grflow/network needs the pair style's neighbor list: "
               "use it after a run (run 0 will do)");
  for (size_t k = 0; k < walls.size(); k++) {
    if (walls[k]->contacts_step() == update->ntimestep) continue;
    error->all(FLERR,
               message("Compute grflow/network ", id, ": fix grflow/wall ", walls[k]->id,
                       " has no contacts for step ", update->ntimestep,
                       ": define it before the fixes that invoke this compute, and use the "
                       "compute after a run (run 0 will do)")
                   .c_str());
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
   ghosts as the pair style saw them, and inside[] of owned and ghost
   atoms; returns the volume of the sub-volume
------------------------------------------------------------------------- */

double ComputeGRFLOWNetwork::refresh_ghosts_and_inside()
{
  // ghost velocities are refreshed before the forces, not after: bring
  // them up to date so that results do not depend on which atoms are ghosts
  comm->forward_comm();

  double volume = 0.0;
  set_inside(volume);
  commflag = INSIDE;
  comm->forward_comm_compute(this);
  return volume;
}

/* ----------------------------------------------------------------------
   particle-particle contacts: the force of each touching pair from the
   kernel and the stored springs (not advanced); the ends inside
   contribute to the sums (GRFLOW::NetworkSums), ncontact[] counts them
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::sum_pair_contacts(double *sums, bool network)
{
  using namespace GRFLOW;
  const LiggghtsPairLaw &law = liggghts_pair_laws()[lmp];
  PairGran *pair = static_cast<PairGran *>(force->pair);
  NeighList *list = pair->list;
  double **firsthistory = pair->listgranhistory->firstdouble;
  const int dnum = pair->dnum();
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  if (network)
    for (int i = 0; i < nall; i++) ncontact[i] = 0.0;

  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const bool newton_pair = force->newton_pair != 0;
  const double step = static_cast<double>(update->ntimestep);

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      bool use_i, use_j;
      NetworkSums::count_ends(inside[i] > 0.0, inside[j] > 0.0, j < nlocal, newton_pair, use_i,
                              use_j);
      if (!use_i && !use_j) continue;

      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const double radsum = radius[i] + radius[j];
      if (rsq >= radsum * radsum) continue;

      ContactGeometry g;
      pair_geometry(del, sqrt(rsq), radius[i], radius[j], false, g);
      const double vrel[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
      double hist[HIST_SIZE];
      current_springs(&firsthistory[i][dnum * jj + law.history_offset], step, false, hist);
      ContactForces out;
      contact_forces((*law.coeff)[type[i] * (law.ntypes + 1) + type[j]], g, vrel, omega[i],
                     omega[j], update->dt, false, hist, out);
      if (out.fn <= 0.0) continue;    // touching but carrying no normal force

      if (network) {
        if (use_i) ncontact[i] += 1.0;
        if (use_j) ncontact[j] += 1.0;
      }
      NetworkSums::add_pair_contact(sums, g.n, out.f, g.delta, radius[i], radius[j], use_i, use_j,
                                    network);
    }
  }

  if (network && newton_pair) {
    commflag = NCONTACTS;
    comm->reverse_comm_compute(this);
  }
}

/* ----------------------------------------------------------------------
   contacts of owned particles inside with GRFLOW walls (the force-bearing
   ones its post_force() recorded on this step): n is the wall normal
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::sum_wall_contacts(double *sums, bool network)
{
  GRFLOW::add_wall_contacts(walls, inside, atom->nlocal, network ? ncontact : NULL, sums);
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::count_particles(double *sums)
{
  GRFLOW::add_particles(inside, ncontact, atom->nlocal, opt.cmax, sums);
}

/* ---------------------------------------------------------------------- */

int ComputeGRFLOWNetwork::pack_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  for (int i = 0; i < n; i++) buf[i] = inside[list[i]];
  return 1;    // values per atom (LIGGGHTS's Comm multiplies by n)
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::unpack_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) inside[first + i] = buf[i];
}

/* ---------------------------------------------------------------------- */

int ComputeGRFLOWNetwork::pack_reverse_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) buf[i] = ncontact[first + i];
  return 1;    // values per atom
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
  const int icompute = lmp->modify->find_compute(id);
  if (icompute < 0)
    lmp->error->all(FLERR, message(caller, ": compute ", id, " does not exist").c_str());
  Compute *c = lmp->modify->compute[icompute];
  ComputeGRFLOWNetwork *network = dynamic_cast<ComputeGRFLOWNetwork *>(c);
  if (!network || strcmp(c->style, "grflow/network") != 0)
    lmp->error->all(FLERR,
                    message(caller, ": compute ", id, " is not a compute grflow/network").c_str());
  return network;
}
