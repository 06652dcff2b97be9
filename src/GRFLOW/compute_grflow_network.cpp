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

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
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
    Compute(lmp, narg, arg), zlo_str(nullptr), zhi_str(nullptr), idregion(nullptr), region(nullptr),
    volume_str(nullptr), inside(nullptr), ncontact(nullptr)
{
  cmax = 12;
  tau_a = 0;
  tau_b = 2;
  slab = 0.8;
  p0 = 0.0;
  p0flag = p0first = 0;
  p0_keyword = false;
  nmax = 0;
  commflag = INSIDE;

  int iarg = 3;
  while (iarg < narg) {
    const std::string kw = arg[iarg];
    const std::string cmd = "compute grflow/network " + kw;
    if (kw == "region") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, cmd, error);
      delete[] idregion;
      idregion = utils::strdup(arg[iarg + 1]);
      if (!domain->get_region_by_id(idregion))
        error->all(FLERR, "Region {} for compute grflow/network does not exist", idregion);
      iarg += 2;
    } else if (kw == "slab") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, cmd, error);
      slab = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (slab <= 0.0 || slab > 1.0)
        error->all(FLERR, "Compute grflow/network slab must be in (0,1], got {}", slab);
      iarg += 2;
    } else if (kw == "zlimits") {
      if (iarg + 3 > narg) utils::missing_cmd_args(FLERR, cmd, error);
      delete[] zlo_str;
      delete[] zhi_str;
      zlo_str = utils::strdup(arg[iarg + 1]);
      zhi_str = utils::strdup(arg[iarg + 2]);
      iarg += 3;
    } else if (kw == "volume") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, cmd, error);
      delete[] volume_str;
      volume_str = utils::strdup(arg[iarg + 1]);
      iarg += 2;
    } else if (kw == "shear") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, cmd, error);
      const std::string c = arg[iarg + 1];
      const int a = c.size() == 2 ? c[0] - 'x' : -1;
      const int b = c.size() == 2 ? c[1] - 'x' : -1;
      if (a < 0 || a > 2 || b < 0 || b > 2 || a == b)
        error->all(FLERR,
                   "Compute grflow/network shear must be two different axes "
                   "(xy, xz, yz, ...), got {}",
                   c);
      tau_a = a;
      tau_b = b;
      iarg += 2;
    } else if (kw == "p0") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, cmd, error);
      p0_keyword = true;
      if (strcmp(arg[iarg + 1], "first") == 0) {
        p0first = 1;
        p0flag = 0;
      } else {
        p0 = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
        if (p0 <= 0.0) error->all(FLERR, "Compute grflow/network p0 must be > 0, got {}", p0);
        p0flag = 1;
        p0first = 0;
      }
      iarg += 2;
    } else if (kw == "cmax") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, cmd, error);
      cmax = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (cmax < 1 || cmax > 100)
        error->all(FLERR, "Compute grflow/network cmax must be in 1..100, got {}", cmax);
      iarg += 2;
    } else {
      error->all(FLERR, "Unknown compute grflow/network keyword: {}", kw);
    }
  }

  if (idregion && zlo_str)
    error->all(FLERR, "Compute grflow/network: use either region or zlimits, not both");
  if (!idregion && volume_str)
    error->all(FLERR, "Compute grflow/network volume goes with region (the slab volume is known)");

  // check numbers now, variables at init()
  for (const char *s : {zlo_str, zhi_str, volume_str})
    if (s && strncmp(s, "v_", 2) != 0) utils::numeric(FLERR, s, false, lmp);

  if (!atom->radius_flag)
    error->all(FLERR, "Compute grflow/network requires atom attribute radius (atom_style sphere)");

  vector_flag = 1;
  size_vector = PC0 + cmax + 1;
  extvector = 0;
  vector = new double[size_vector];
  for (int k = 0; k < size_vector; k++) vector[k] = 0.0;

  comm_forward = 1;
  comm_reverse = 1;
}

/* ---------------------------------------------------------------------- */

ComputeGRFLOWNetwork::~ComputeGRFLOWNetwork()
{
  delete[] vector;
  delete[] zlo_str;
  delete[] zhi_str;
  delete[] idregion;
  delete[] volume_str;
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

  if (idregion) {
    region = domain->get_region_by_id(idregion);
    if (!region) error->all(FLERR, "Region {} for compute grflow/network does not exist", idregion);
    if (!volume_str && (strcmp(region->style, "block") != 0 || !region->interior))
      error->all(FLERR,
                 "Compute grflow/network region {} is not an inside block: give its "
                 "volume with the volume keyword",
                 idregion);
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

  for (const char *s : {zlo_str, zhi_str, volume_str}) {
    if (!s || strncmp(s, "v_", 2) != 0) continue;
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
    if (volume_str) {
      volume = eval(volume_str, "volume");
    } else {
      const double lo[3] = {MAX(region->extent_xlo, domain->boxlo[0]),
                            MAX(region->extent_ylo, domain->boxlo[1]),
                            MAX(region->extent_zlo, domain->boxlo[2])};
      const double hi[3] = {MIN(region->extent_xhi, domain->boxhi[0]),
                            MIN(region->extent_yhi, domain->boxhi[1]),
                            MIN(region->extent_zhi, domain->boxhi[2])};
      volume = MAX(hi[0] - lo[0], 0.0) * MAX(hi[1] - lo[1], 0.0) * MAX(hi[2] - lo[2], 0.0);
    }
    for (int i = 0; i < nlocal; i++)
      inside[i] = ((mask[i] & groupbit) && region->match(x[i][0], x[i][1], x[i][2])) ? 1.0 : 0.0;
  } else {
    const double zlo = zlo_str ? eval(zlo_str, "zlimits") : domain->boxlo[2];
    const double zhi = zhi_str ? eval(zhi_str, "zlimits") : domain->boxhi[2];
    if (!(zhi > zlo))
      error->all(FLERR, "Compute grflow/network zlimits must have zlo < zhi, got {} {}", zlo, zhi);
    const double half = 0.5 * slab * (zhi - zlo);
    const double zmid = 0.5 * (zlo + zhi);
    const double lo = zmid - half, hi = zmid + half;
    volume = domain->xprd * domain->yprd * (hi - lo);
    // between reneighborings an atom may be up to half the skin outside a
    // periodic box: use the image of its centre inside the box
    const int zperiodic = domain->zperiodic;
    const double boxlo = domain->boxlo[2], boxhi = domain->boxhi[2], zprd = domain->zprd;
    for (int i = 0; i < nlocal; i++) {
      double z = x[i][2];
      if (zperiodic) {
        if (z < boxlo)
          z += zprd;
        else if (z >= boxhi)
          z -= zprd;
      }
      inside[i] = ((mask[i] & groupbit) && z >= lo && z < hi) ? 1.0 : 0.0;
    }
  }
  if (!(volume > 0.0) || !std::isfinite(volume))
    error->all(FLERR, "Compute grflow/network sub-volume is {}: must be finite and > 0", volume);
}

/* ---------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::compute_vector()
{
  // during a run or minimization init() has done the checks and found the
  // walls (fixes cannot come or go within a run); between runs (library
  // calls, variables) they are done here, as init() may not have been
  if (update->whichflag == 0) check_setup();
  require_current_contacts();
  invoked_vector = update->ntimestep;
  grow_peratom();

  const double volume = refresh_ghosts_and_inside();
  // per processor: stress sums sum l (x) f (9), fabric sums sum n (x) n (9),
  // particles inside, floaters, contact ends, histogram of contact numbers
  std::vector<double> local(SUMS_HIST + cmax + 1, 0.0), total(local.size());
  sum_pair_contacts(&local[SUMS_STRESS], &local[SUMS_FABRIC]);
  sum_wall_contacts(&local[SUMS_STRESS], &local[SUMS_FABRIC]);
  count_particles(local.data());
  MPI_Allreduce(local.data(), total.data(), (int) local.size(), MPI_DOUBLE, MPI_SUM, world);
  derive(total.data(), volume);
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

void ComputeGRFLOWNetwork::sum_pair_contacts(double *sig, double *fab)
{
  Pair *pair = force->pair;
  NeighList *list = pair->list;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
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

      // with newton off a pair with a ghost is listed by both owners:
      // each side counts only its own particle
      const bool use_i = inside[i] > 0.0;
      const bool use_j = inside[j] > 0.0 && (j < nlocal || newton_pair);
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
      // the contact law's arms a - delta/2 (the kernel's contact_arm)
      const double delta = radsum - r;
      double arm = 0.0;
      if (use_i) {
        ncontact[i] += 1.0;
        arm += GRFLOW::contact_arm(radius[i], delta);
      }
      if (use_j) {
        ncontact[j] += 1.0;
        arm += GRFLOW::contact_arm(radius[j], delta);
      }
      const double ends = (use_i ? 1.0 : 0.0) + (use_j ? 1.0 : 0.0);
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
          sig[3 * a + b] += arm * n[a] * f[b];
          fab[3 * a + b] += ends * n[a] * n[b];
        }
    }
  }

  if (newton_pair) {
    commflag = NCONTACTS;
    comm->reverse_comm(this);
  }
}

/* ----------------------------------------------------------------------
   contacts of owned particles inside with GRFLOW walls (the force-bearing
   ones its post_force() recorded on this step): n is the wall normal
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::sum_wall_contacts(double *sig, double *fab)
{
  const int nlocal = atom->nlocal;
  for (auto *wfix : walls)
    for (int i = 0; i < nlocal; i++) {
      if (inside[i] <= 0.0) continue;
      for (int w = 0; w < FixGRFLOWWall::NWALL; w++) {
        const double arm = wfix->contact_arm(i, w);
        if (arm <= 0.0) continue;
        const double *fw = wfix->contact_force(i, w);
        const double nz = wfix->normal_sign(w);
        ncontact[i] += 1.0;
        for (int b = 0; b < 3; b++) sig[3 * 2 + b] += arm * nz * fw[b];
        fab[3 * 2 + 2] += 1.0;
      }
    }
}

/* ----------------------------------------------------------------------
   per owned particle inside: the count, floaters, contact ends and the
   histogram of contact numbers (sums[SUMS_NP...])
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::count_particles(double *sums)
{
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    if (inside[i] <= 0.0) continue;
    const int c = (int) ncontact[i];
    sums[SUMS_NP] += 1.0;
    if (c == 0) sums[SUMS_FLOAT] += 1.0;
    sums[SUMS_ENDS] += c;
    sums[SUMS_HIST + MIN(c, cmax)] += 1.0;
  }
}

/* ----------------------------------------------------------------------
   the output vector from the sums over all processors
------------------------------------------------------------------------- */

void ComputeGRFLOWNetwork::derive(const double *total, double volume)
{
  double s[3][3], sym[3][3], fabric[3][3];
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      s[a][b] = total[SUMS_STRESS + 3 * a + b] / volume;
      fabric[a][b] = total[SUMS_FABRIC + 3 * a + b];
    }
  const double np = total[SUMS_NP], nfloat = total[SUMS_FLOAT], csum = total[SUMS_ENDS];

  // stress: LAMMPS order and convention (compression positive,
  // sigma_ab = sum l_a f_b / V); derived values use the symmetric part

  vector[SXX] = s[0][0];
  vector[SYY] = s[1][1];
  vector[SZZ] = s[2][2];
  vector[SXY] = s[0][1];
  vector[SXZ] = s[0][2];
  vector[SYZ] = s[1][2];
  const double p = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
  double ss = 0.0;
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      sym[a][b] = 0.5 * (s[a][b] + s[b][a]) - (a == b ? p : 0.0);    // deviatoric
      ss += sym[a][b] * sym[a][b];
    }
  vector[PRESS] = p;
  vector[TAU] = -0.5 * (s[tau_a][tau_b] + s[tau_b][tau_a]);
  vector[QDEV] = sqrt(1.5 * ss);
  vector[SNORM] = sqrt(ss);
  // p0 first: the first positive pressure (r_u = 1 - p/p0 needs p0 > 0)
  if (p0first && !p0flag && p > 0.0) set_p0(p);
  vector[RU] = p0flag ? 1.0 - p / p0 : 0.0;

  // contacts

  vector[NP] = np;
  vector[NFLOAT] = nfloat;
  vector[NCONTACT] = 0.5 * csum;
  vector[ZG] = (np - nfloat > 0.0) ? csum / (np - nfloat) : 0.0;
  vector[ZPLAIN] = (np > 0.0) ? csum / np : 0.0;

  // fabric F = <n n> over contact ends, a = 15/2 dev F,
  // a_c = sign(a:s) sqrt(3/2 a:a)

  double an[3][3], aa = 0.0, as = 0.0;
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      const double fn = (csum > 0.0) ? fabric[a][b] / csum : 0.0;
      an[a][b] = (csum > 0.0) ? 7.5 * (fn - (a == b ? 1.0 / 3.0 : 0.0)) : 0.0;
    }
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      aa += an[a][b] * an[a][b];
      as += an[a][b] * sym[a][b];
    }
  const double sc = (aa > 0.0 && ss > 0.0) ? as / (sqrt(aa) * sqrt(ss)) : 0.0;
  vector[SC] = sc;
  vector[AC] = (sc < 0.0 ? -1.0 : 1.0) * sqrt(1.5 * aa);
  vector[AXX] = an[0][0];
  vector[AYY] = an[1][1];
  vector[AZZ] = an[2][2];
  vector[AXY] = an[0][1];
  vector[AXZ] = an[0][2];
  vector[AYZ] = an[1][2];
  vector[VOLUME] = volume;
  for (int c = 0; c <= cmax; c++) vector[PC0 + c] = (np > 0.0) ? total[SUMS_HIST + c] / np : 0.0;
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
