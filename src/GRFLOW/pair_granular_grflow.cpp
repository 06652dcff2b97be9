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

   Linear spring-dashpot contact with sliding, rolling and torsion
   resistance (Luding 2008) in one pass per neighbor pair.  The physics is
   in grflow_contact.h; this class does the LAMMPS bookkeeping.
------------------------------------------------------------------------- */

#include "pair_granular_grflow.h"
#include "pair_granular_grflow_eval.h"

#include "grflow_coeff_rules.h"
#include "grflow_coeffs.h"
#include "grflow_contact.h"
#include "grflow_host_api.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace GRFLOW;

// the settings in restart files: one int, bit 0 full_arm (velocity_arm
// full), bit 1 the unclipped normal force.  Files written before the
// normal_force keyword hold full_arm alone (0 or 1): the clipped law, as
// then; a clipped run writes the same int as before.
static constexpr int SETTINGS_FULL_ARM = 1, SETTINGS_UNCLIPPED = 2;

/* ---------------------------------------------------------------------- */

PairGranularGRFLOW::PairGranularGRFLOW(LAMMPS *lmp) : Pair(lmp)
{
  single_enable = 1;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  finitecutflag = 1;
  beyond_contact = 0;
  writedata = 1;

  nondefault_history_transfer = 1;    // see transfer_history()
  single_extra = SingleLayout::NVALUES;
  svector = new double[single_extra];

  dt = update->dt;
  full_arm = 0;
  normal_law = NORMAL_CLIPPED;
  param = new double **[NCOEFF];
  for (int k = 0; k < NCOEFF; k++) param[k] = nullptr;
  packed = nullptr;
  onerad_dynamic = maxrad_dynamic = nullptr;
  neighprev = 0;

  // placeholder for the FixNeighHistory created in init_style(), so that it
  // keeps its place in the fix list.  Its ID must be the same when a restart
  // file is read, so it counts GRFLOW pair styles in this LAMMPS instance
  // (Pair::instance_me counts them across all instances in the process).

  int n = 0;
  while (modify->get_fix_by_id(fmt::format("NEIGH_HISTORY_GRFLOW{}", n)) ||
         modify->get_fix_by_id(fmt::format("NEIGH_HISTORY_GRFLOW_DUMMY{}", n)))
    n++;
  id_history = fmt::format("NEIGH_HISTORY_GRFLOW{}", n);
  id_dummy = fmt::format("NEIGH_HISTORY_GRFLOW_DUMMY{}", n);
  fix_history = nullptr;
  fix_dummy = dynamic_cast<FixDummy *>(modify->add_fix(id_dummy + " all DUMMY"));
}

/* ---------------------------------------------------------------------- */

PairGranularGRFLOW::~PairGranularGRFLOW()
{
  if (copymode) return;
  delete[] svector;

  modify->delete_fix(fix_history ? id_history : id_dummy);

  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    for (int k = 0; k < NCOEFF; k++) memory->destroy(param[k]);
    memory->destroy(packed);
    delete[] onerad_dynamic;
    delete[] maxrad_dynamic;
  }
  delete[] param;
}

/* ---------------------------------------------------------------------- */

void PairGranularGRFLOW::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const auto tally = [this](int i, int j, int nlocal, int newton_pair, double evdwl, double fx,
                            double fy, double fz, double delx, double dely, double delz) {
    ev_tally_xyz(i, j, nlocal, newton_pair, evdwl, 0.0, fx, fy, fz, delx, dely, delz);
  };
  eval_dispatch(0, list->inum, eflag, atom->f, atom->torque, tally);
}

/* ----------------------------------------------------------------------
   allocate all arrays
------------------------------------------------------------------------- */

void PairGranularGRFLOW::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;

  memory->create(setflag, n, n, "pair:setflag");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n, n, "pair:cutsq");
  for (int k = 0; k < NCOEFF; k++) {
    memory->create(param[k], n, n, "pair:param");
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++) param[k][i][j] = 0.0;
  }
  memory->create(packed, n, n, "pair:packed");
  onerad_dynamic = new double[n];
  maxrad_dynamic = new double[n];
}

/* ----------------------------------------------------------------------
   global settings: pair_style granular/grflow [velocity_arm reduced|full]
                                               [normal_force clipped|unclipped]
------------------------------------------------------------------------- */

void PairGranularGRFLOW::settings(int narg, char **arg)
{
  full_arm = 0;
  normal_law = NORMAL_CLIPPED;
  int iarg = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "velocity_arm") == 0) {
      if (iarg + 2 > narg)
        utils::missing_cmd_args(FLERR, "pair_style granular/grflow velocity_arm", error);
      full_arm = GRFLOW::parse_velocity_arm(lmp, "pair_style granular/grflow", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "normal_force") == 0) {
      if (iarg + 2 > narg)
        utils::missing_cmd_args(FLERR, "pair_style granular/grflow normal_force", error);
      FixHost host{lmp};
      normal_law = read_normal_force("pair_style granular/grflow", arg[iarg + 1], host);
      iarg += 2;
    } else {
      error->all(FLERR, "Unknown pair_style granular/grflow keyword: {}", arg[iarg]);
    }
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I J kn cn [kt v] [ct v] [mut v] [kr v] [cr v] [mur v]
                        [ko v] [co v] [muo v] [rolling off] [torsion off]
   unset keywords take the ratios of the paper's Table 1
------------------------------------------------------------------------- */

void PairGranularGRFLOW::coeff(int narg, char **arg)
{
  if (narg < 4)
    error->all(
        FLERR,
        "Incorrect args for pair_coeff granular/grflow: expected I J kn cn [keyword value ...]");
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  double value[NCOEFF];
  parse_coeffs(lmp, "pair_coeff granular/grflow", narg, arg, 2, false, value);

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      for (int k = 0; k < NCOEFF; k++) param[k][i][j] = value[k];
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0)
    error->all(FLERR, "Incorrect args for pair_coeff granular/grflow: no type pair in range");
}

/* ----------------------------------------------------------------------
   init specific to this pair style
------------------------------------------------------------------------- */

void PairGranularGRFLOW::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag)
    error->all(FLERR,
               "Pair style granular/grflow requires atom attributes radius, rmass and "
               "omega (atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR,
               "Pair style granular/grflow requires ghost atoms to store velocity: "
               "use comm_modify vel yes");

  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Pair style granular/grflow does not support run_style respa");

  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_HISTORY);

  dt = update->dt;
  if (!(dt > 0.0) || !std::isfinite(dt))
    error->all(FLERR,
               "Pair granular/grflow needs a timestep > 0 (the contact springs grow by "
               "v dt), got {}",
               dt);

  // on first init, create the fix that stores the contact history;
  // it replaces the FixDummy created in the constructor.  Never its
  // accelerator variant (no suffix): the OPENMP one (4Feb2025) negates
  // every history value when a pair changes owner and ignores
  // transfer_history(), which would flip the rolling and torsion springs.

  if (fix_history == nullptr) {
    auto cmd = fmt::format("{} all NEIGH_HISTORY {}", id_history, (int) HIST_SIZE);
    fix_history = dynamic_cast<FixNeighHistory *>(modify->replace_fix(id_dummy, cmd, 0));
    fix_history->pair = this;
  }
  fix_history = dynamic_cast<FixNeighHistory *>(modify->get_fix_by_id(id_history));
  if (!fix_history) error->all(FLERR, "Could not find pair granular/grflow fix neigh history ID");

  // largest radius per type, including particles that fix pour or fix
  // deposit will insert later

  auto pours = modify->get_fix_by_style("^pour");
  auto deps = modify->get_fix_by_style("^deposit");
  const int ntypes = atom->ntypes;
  for (int i = 1; i <= ntypes; i++) {
    onerad_dynamic[i] = 0.0;
    for (auto &ifix : pours) {
      int itype = i;
      double maxrad = *((double *) ifix->extract("radius", itype));
      if (maxrad > 0.0) onerad_dynamic[i] = maxrad;
    }
    for (auto &ifix : deps) {
      int itype = i;
      double maxrad = *((double *) ifix->extract("radius", itype));
      if (maxrad > 0.0) onerad_dynamic[i] = maxrad;
    }
  }
  const double *radius = atom->radius;
  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++)
    onerad_dynamic[type[i]] = MAX(onerad_dynamic[type[i]], radius[i]);
  MPI_Allreduce(&onerad_dynamic[1], &maxrad_dynamic[1], ntypes, MPI_DOUBLE, MPI_MAX, world);

  // every particle a sphere of finite, positive radius (a data file or a
  // set command can give a zero, negative or non-finite diameter): the
  // first such atom by ID is named
  const tagint *tag = atom->tag;
  tagint bad = MAXTAGINT, badall;
  double badrad = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (!(radius[i] > 0.0) || !std::isfinite(radius[i])) {
      if (tag[i] < bad) {
        bad = tag[i];
        badrad = radius[i];
      }
    }
  MPI_Allreduce(&bad, &badall, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (badall != MAXTAGINT) {
    // its radius to every rank: only its owner adds a value other than 0
    double r = (bad == badall) ? badrad : 0.0, rall;
    MPI_Allreduce(&r, &rall, 1, MPI_DOUBLE, MPI_SUM, world);
    error->all(FLERR,
               "Pair granular/grflow: atom {} has diameter {}: every particle must be a sphere "
               "with a finite diameter > 0",
               badall, 2.0 * rall);
  }
}

/* ----------------------------------------------------------------------
   init for one type pair i,j and corresponding j,i
   unset I,J coefficients are the geometric means of the I,I and J,J ones
------------------------------------------------------------------------- */

double PairGranularGRFLOW::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    for (int k = 0; k < NCOEFF; k++) param[k][i][j] = sqrt(param[k][i][i] * param[k][j][j]);

  for (int k = 0; k < NCOEFF; k++) param[k][j][i] = param[k][i][j];

  // every road a coefficient takes (pair_coeff, mixing, fix adapt through
  // reinit(), restart and data files) ends here: check it once more
  double value[NCOEFF];
  for (int k = 0; k < NCOEFF; k++) value[k] = param[k][i][j];
  check_coeffs(lmp, fmt::format("Pair granular/grflow coefficients of types {} {}", i, j), value);
  ContactCoeffs &c = packed[i][j];
  pack_coeffs(value, c);
  c.normal_law = normal_law;
  packed[j][i] = c;

  // contact range: sum of the largest radii of the two types
  return maxrad_dynamic[i] + maxrad_dynamic[j];
}

/* ----------------------------------------------------------------------
   proc 0 writes to restart file
------------------------------------------------------------------------- */

void PairGranularGRFLOW::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j])
        for (int k = 0; k < NCOEFF; k++) fwrite(&param[k][i][j], sizeof(double), 1, fp);
    }
}

/* ----------------------------------------------------------------------
   proc 0 reads from restart file, bcasts
------------------------------------------------------------------------- */

void PairGranularGRFLOW::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      // a damaged file: a clear error, not coefficients nobody gave
      if (setflag[i][j] != 0 && setflag[i][j] != 1)
        error->all(FLERR,
                   "Pair granular/grflow: damaged restart file: types {} {} have the set flag {}",
                   i, j, setflag[i][j]);
      if (setflag[i][j]) {
        double value[NCOEFF];
        for (int k = 0; k < NCOEFF; k++) {
          if (me == 0) utils::sfread(FLERR, &param[k][i][j], sizeof(double), 1, fp, nullptr, error);
          MPI_Bcast(&param[k][i][j], 1, MPI_DOUBLE, 0, world);
          value[k] = param[k][i][j];
        }
        FixHost host{lmp};
        GRFLOW::check_coeff_values(
            fmt::format("Pair granular/grflow: damaged restart file: types {} {}", i, j), value,
            host);
      }
    }
}

/* ---------------------------------------------------------------------- */

void PairGranularGRFLOW::write_restart_settings(FILE *fp)
{
  int word = full_arm ? SETTINGS_FULL_ARM : 0;
  if (normal_law == NORMAL_UNCLIPPED) word |= SETTINGS_UNCLIPPED;
  fwrite(&word, sizeof(int), 1, fp);
}

/* ---------------------------------------------------------------------- */

void PairGranularGRFLOW::read_restart_settings(FILE *fp)
{
  int word = 0;
  if (comm->me == 0) utils::sfread(FLERR, &word, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&word, 1, MPI_INT, 0, world);
  if (word & ~(SETTINGS_FULL_ARM | SETTINGS_UNCLIPPED))
    error->all(FLERR,
               "Pair granular/grflow: unknown settings {} in the restart file (written by a newer "
               "version of GRFLOW?)",
               word);
  full_arm = (word & SETTINGS_FULL_ARM) ? 1 : 0;
  normal_law = (word & SETTINGS_UNCLIPPED) ? NORMAL_UNCLIPPED : NORMAL_CLIPPED;
}

/* ----------------------------------------------------------------------
   one line of coefficients, in pair_coeff syntax after the type(s)
------------------------------------------------------------------------- */

void PairGranularGRFLOW::write_coeffs(FILE *fp, int i, int j, bool both)
{
  if (both)
    fprintf(fp, "%d %d", i, j);
  else
    fprintf(fp, "%d", i);
  fprintf(fp, " %.17g %.17g", param[KN][i][j], param[CN][i][j]);
  for (int k = KT; k < NCOEFF; k++) fprintf(fp, " %s %.17g", COEFF_NAMES[k], param[k][i][j]);
  fprintf(fp, "\n");
}

/* ----------------------------------------------------------------------
   proc 0 writes to data file
------------------------------------------------------------------------- */

void PairGranularGRFLOW::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) write_coeffs(fp, i, i, false);
}

/* ---------------------------------------------------------------------- */

void PairGranularGRFLOW::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) write_coeffs(fp, i, j, true);
}

/* ---------------------------------------------------------------------- */

void PairGranularGRFLOW::reset_dt()
{
  dt = update->dt;
}

/* ----------------------------------------------------------------------
   force of one pair for compute pair/local and friends; the history is
   read, never advanced.  fforce = F_n / r; returns the elastic energy.
------------------------------------------------------------------------- */

double PairGranularGRFLOW::single(int i, int j, int itype, int jtype, double rsq,
                                  double /*factor_coul*/, double factor_lj, double &fforce)
{
  for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
  fforce = 0.0;

  const double radi = atom->radius[i];
  const double radj = atom->radius[j];
  const double radsum = radi + radj;
  if (rsq >= radsum * radsum) return 0.0;

  double **x = atom->x;
  double **v = atom->v;
  double **omega = atom->omega;
  double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
  const double r = sqrt(rsq);

  // history of this pair: stored with I or, when the caller's list has the
  // pair the other way round (e.g. an occasional list built later), with J
  // and then seen through transfer_history()

  double history[HIST_SIZE];
  find_history(i, j, history);
  const double *hist = history;

  ContactGeometry g;
  ContactForces out;
  pair_geometry(del, r, radi, radj, full_arm != 0, g);
  const double vrel[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
  const ContactCoeffs &c = packed[itype][jtype];
  contact_forces(c, g, vrel, omega[i], omega[j], dt, false, history, out);

  // the layout of stock pair granular first (GRFLOW::SingleLayout), so
  // that commands reading p1-p12 of compute pair/local (and computes the
  // sliding force from svector[0-2]) get the same quantities from either
  typedef SingleLayout S;
  fforce = factor_lj * out.fn / r;
  for (int k = 0; k < 3; k++) {
    svector[S::FS_X + k] = factor_lj * out.ft[k];
    svector[S::FR_X + k] = factor_lj * out.fr[k];
    svector[S::DX + k] = del[k];
  }
  svector[S::FS_LEN] = factor_lj * sqrt(dot3(out.ft, out.ft));
  svector[S::FR_LEN] = factor_lj * sqrt(dot3(out.fr, out.fr));
  svector[S::TWIST] = factor_lj * g.reff * out.fo;    // the torque on i is a' f_o n
  svector[S::FO] = factor_lj * out.fo;
  svector[S::FO_LEN] = factor_lj * fabs(out.fo);
  svector[S::FN] = factor_lj * out.fn;
  return factor_lj * elastic_energy(c, g.delta, hist);
}

/* ----------------------------------------------------------------------
   two atoms at the same position: the contact normal is undefined
------------------------------------------------------------------------- */

void PairGranularGRFLOW::same_position(int iifrom, int iito)
{
  double **x = atom->x;
  for (int ii = iifrom; ii < iito; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      if (x[i][0] == x[j][0] && x[i][1] == x[j][1] && x[i][2] == x[j][2])
        error->one(FLERR,
                   "Pair granular/grflow: atoms {} and {} are at the same position {} {} {}: "
                   "the contact normal is undefined",
                   atom->tag[i], atom->tag[j], x[i][0], x[i][1], x[i][2]);
    }
  }
}

/* ----------------------------------------------------------------------
   copy the history of pair I,J as seen from I into hist; zero if the pair
   is not in I's neighbors nor (for an owned J) J's neighbors
------------------------------------------------------------------------- */

void PairGranularGRFLOW::find_history(int i, int j, double *hist)
{
  for (int k = 0; k < HIST_SIZE; k++) hist[k] = 0.0;
  if (!list || !fix_history || !fix_history->firstvalue) return;

  // search I's neighbors, starting after the previous hit, since callers
  // usually walk a list in the same order
  const int jnum = list->numneigh[i];
  const int *jlist = list->firstneigh[i];
  for (int jj = 0; jj < jnum; jj++) {
    if (++neighprev >= jnum) neighprev = 0;
    if ((jlist[neighprev] & NEIGHMASK) == j) {
      const double *h = &fix_history->firstvalue[i][HIST_SIZE * neighprev];
      for (int k = 0; k < HIST_SIZE; k++) hist[k] = h[k];
      return;
    }
  }
  if (j >= atom->nlocal) return;
  const int inum = list->numneigh[j];
  const int *ilist = list->firstneigh[j];
  for (int ii = 0; ii < inum; ii++)
    if ((ilist[ii] & NEIGHMASK) == i) {
      const double *h = &fix_history->firstvalue[j][HIST_SIZE * ii];
      for (int k = 0; k < HIST_SIZE; k++) hist[k] = HISTORY_SWAP_FACTOR[k] * h[k];
      return;
    }
}

/* ----------------------------------------------------------------------
   per type pair coefficient arrays, for fix adapt; the normal force law
------------------------------------------------------------------------- */

void *PairGranularGRFLOW::extract(const char *str, int &dim)
{
  // the normal force law (NORMAL_CLIPPED or NORMAL_UNCLIPPED), for fix grflow/wall
  if (strcmp(str, "normal_force") == 0) {
    dim = 0;
    return (void *) &normal_law;
  }
  dim = 2;
  for (int k = 0; k < NCOEFF; k++)
    if (strcmp(str, COEFF_NAMES[k]) == 0) return (void *) param[k];
  return nullptr;
}

/* ----------------------------------------------------------------------
   history of a pair seen from the other atom: the sliding spring flips
   with n, the rolling and torsion springs do not
------------------------------------------------------------------------- */

void PairGranularGRFLOW::transfer_history(double *source, double *target, int /*itype*/,
                                          int /*jtype*/)
{
  for (int k = 0; k < HIST_SIZE; k++) target[k] = HISTORY_SWAP_FACTOR[k] * source[k];
}

/* ---------------------------------------------------------------------- */

double PairGranularGRFLOW::memory_usage()
{
  const double n = atom->ntypes + 1;
  return n * n * (NCOEFF * sizeof(double) + sizeof(ContactCoeffs));
}

#if GRFLOW_PAIR_HAS_ATOM2CUT
/* ----------------------------------------------------------------------
   self-interaction range of particle
------------------------------------------------------------------------- */

double PairGranularGRFLOW::atom2cut(int i)
{
  return 2.0 * atom->radius[i];
}

/* ----------------------------------------------------------------------
   maximum interaction range for two finite particles
------------------------------------------------------------------------- */

double PairGranularGRFLOW::radii2cut(double r1, double r2)
{
  return r1 + r2;
}
#endif
