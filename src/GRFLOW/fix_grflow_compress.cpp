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

   Isotropic compression of the bi-periodic cell by all six sides: the
   periodic box shrinks (or grows) in x and y with an affine remap of the
   fix group, and the two walls of a fix grflow/wall move in z.  A
   proportional stress servo sets the three strain rates from the
   stresses of a compute grflow/network, so that sigma_xx, sigma_yy and
   sigma_zz go to a target and stay there.  An axis whose stress keeps
   overshooting the target from one update to the next gets its gain
   halved.  Reports the stresses, the kinetic-to-elastic energy ratio and
   a convergence flag.
------------------------------------------------------------------------- */

#include "fix_grflow_compress.h"

#include "grflow_restart.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "compute_grflow_network.h"
#include "domain.h"
#include "error.h"
#include "fix_grflow_wall.h"
#include "force.h"
#include "input.h"
#include "math_const.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using GRFLOW::read_restart_values;
using GRFLOW::write_restart_values;

// restart: rates x y z, RESTART_V2 + started, gain factors x y z, last
// errors x y z, overshoot counts x y z.  Files written before the
// overshoot damping hold only the first four, with started 0 or 1: the
// offset tells them apart (LAMMPS does not pass the size to restart()).
static constexpr int NRESTART = 13;
static constexpr int RESTART_V2 = 2;
static constexpr int RESTART_VERSION = 1;    // of the headed block (grflow_restart.h)

/* ---------------------------------------------------------------------- */

FixGRFLOWCompress::FixGRFLOWCompress(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), id_wall(nullptr), id_network(nullptr), id_pe(nullptr),
    elastic_var(nullptr), ivar_elastic(-1), wall(nullptr), network(nullptr), pe(nullptr)
{
  if (narg < 7)
    error->all(FLERR,
               "Illegal fix grflow/compress command: expected wall-ID compute-ID "
               "p_target rate_max [keyword value ...]");
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag)
    error->all(FLERR,
               "Fix grflow/compress requires atom attributes radius, rmass and omega "
               "(atom_style sphere)");
  if (domain->triclinic) error->all(FLERR, "Fix grflow/compress requires an orthogonal box");
  if (!domain->xperiodic || !domain->yperiodic)
    error->all(FLERR, "Fix grflow/compress requires a box periodic in x and y");
  if (domain->dimension != 3) error->all(FLERR, "Fix grflow/compress requires a 3d system");

  id_wall = utils::strdup(arg[3]);
  id_network = utils::strdup(arg[4]);
  p_target = utils::numeric(FLERR, arg[5], false, lmp);
  rate_max = utils::numeric(FLERR, arg[6], false, lmp);
  if (p_target <= 0.0)
    error->all(FLERR, "Fix grflow/compress p_target must be > 0, got {}", p_target);
  if (rate_max <= 0.0)
    error->all(FLERR, "Fix grflow/compress rate_max must be > 0, got {}", rate_max);

  gain = 10.0;
  tol = 0.01;
  ke_ratio_max = 1.0e-3;
  servo_every = 1;

  int iarg = 7;
  while (iarg < narg) {
    const std::string kw = arg[iarg];
    // an unknown keyword is reported as such, before its value is read
    if (kw != "elastic" && kw != "gain" && kw != "tol" && kw != "ke_ratio" && kw != "every")
      error->all(FLERR, "Unknown fix grflow/compress keyword: {}", kw);
    if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix grflow/compress " + kw, error);
    if (kw == "elastic") {
      if (!utils::strmatch(arg[iarg + 1], "^v_"))
        error->all(FLERR,
                   "Fix grflow/compress elastic takes an equal-style variable v_name, got {}",
                   arg[iarg + 1]);
      delete[] elastic_var;
      elastic_var = utils::strdup(arg[iarg + 1] + 2);
      iarg += 2;
      continue;
    }
    if (kw == "every") {
      servo_every = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (servo_every < 1)
        error->all(FLERR, "Fix grflow/compress every must be >= 1, got {}", servo_every);
      iarg += 2;
      continue;
    }
    const double value = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (kw == "gain") {
      gain = value;
      if (gain <= 0.0) error->all(FLERR, "Fix grflow/compress gain must be > 0, got {}", value);
    } else if (kw == "tol") {
      tol = value;
      if (tol <= 0.0) error->all(FLERR, "Fix grflow/compress tol must be > 0, got {}", value);
    } else if (kw == "ke_ratio") {
      ke_ratio_max = value;
      if (ke_ratio_max <= 0.0)
        error->all(FLERR, "Fix grflow/compress ke_ratio must be > 0, got {}", value);
    }
    iarg += 2;
  }

  vector_flag = 1;
  size_vector = NOUT;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  box_change |= BOX_CHANGE_X | BOX_CHANGE_Y;

  // without an elastic variable the elastic energy is the potential energy
  // of the pair style, tallied on the servo steps only (as fix box/relax
  // does with its compute pe)
  if (!elastic_var) {
    id_pe = utils::strdup(std::string(id) + "_pe");
    pe = modify->add_compute(fmt::format("{} all pe", id_pe));
  }

  for (int a = 0; a < 3; a++) { rate[a] = sigma[a] = 0.0; }
  errmax = ke = eel = 0.0;
  vsolid = 0.0;
  started = 0;
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

FixGRFLOWCompress::~FixGRFLOWCompress()
{
  if (id_pe && modify->get_compute_by_id(id_pe)) modify->delete_compute(id_pe);
  delete[] id_wall;
  delete[] id_network;
  delete[] id_pe;
  delete[] elastic_var;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWCompress::setmask()
{
  return END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::init()
{
  wall = FixGRFLOWWall::find_cell(lmp, "Fix grflow/compress", id_wall);
  network = ComputeGRFLOWNetwork::find(lmp, "Fix grflow/compress", id_network);

  if (!elastic_var) {
    pe = modify->get_compute_by_id(id_pe);
    if (!pe) error->all(FLERR, "Fix grflow/compress: its compute {} was deleted", id_pe);
  } else {
    ivar_elastic = input->variable->find(elastic_var);
    if (ivar_elastic < 0)
      error->all(FLERR, "Fix grflow/compress: variable {} does not exist", elastic_var);
    if (!input->variable->equalstyle(ivar_elastic))
      error->all(FLERR, "Fix grflow/compress: variable {} is not equal-style", elastic_var);
  }

  // solid volume of the fix group, for the void ratio
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  double vlocal = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) vlocal += radius[i] * radius[i] * radius[i];
  MPI_Allreduce(&vlocal, &vsolid, 1, MPI_DOUBLE, MPI_SUM, world);
  vsolid *= 4.0 / 3.0 * MathConst::MY_PI;

  dt = update->dt;

  // the energy must be tallied on the step the first servo update reads it
  schedule_energy(update->ntimestep);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::setup(int /*vflag*/)
{
  // update the rates where an uninterrupted run would (the very start and
  // every N-th step); otherwise keep those of the last update (they and the
  // wall velocities are in the restart files), so that a run split at a
  // step that is not a multiple of N gives the same trajectory as one run.
  // On a multiple of N this repeats that step's update with stresses
  // re-measured at setup (full-step velocities in the dashpots).
  // A run that starts between servo steps (a split run, a restart) keeps
  // the rates and re-measures the outputs only.
  if (!started || update->ntimestep % servo_every == 0)
    servo();
  else
    measure();
  started = 1;
  schedule_energy((update->ntimestep / servo_every + 1) * servo_every);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::end_of_step()
{
  if (update->ntimestep % servo_every == 0) {
    servo();
    schedule_energy(update->ntimestep + servo_every);
  }
  deform_box();
}

/* ----------------------------------------------------------------------
   new strain rates from the stresses
   rate_a = rate_max * clamp(factor_a * gain * (sigma_aa - p_target) / p_target, -1, 1)
   (compression is positive, a negative rate shrinks the cell)
------------------------------------------------------------------------- */

void FixGRFLOWCompress::servo()
{
  measure();
  for (int a = 0; a < 3; a++) {
    const double err = (sigma[a] - p_target) / p_target;
    damp_overshoot(a, err);
    rate[a] = rate_max * MAX(-1.0, MIN(1.0, damping[a].factor * gain * err));
  }
  drive_walls();
}

/* ----------------------------------------------------------------------
   the energy compute or the elastic-energy variable's computes must be
   tallied on the next step that reads them
------------------------------------------------------------------------- */

void FixGRFLOWCompress::schedule_energy(bigint step)
{
  if (elastic_var)
    modify->addstep_compute(step);
  else
    pe->addstep(step);
}

/* ----------------------------------------------------------------------
   the outputs: stresses, their largest error, kinetic and elastic energy
------------------------------------------------------------------------- */

void FixGRFLOWCompress::measure()
{
  if (network->invoked_vector != update->ntimestep) network->compute_vector();
  const double *s = network->vector;
  sigma[0] = s[ComputeGRFLOWNetwork::SXX];
  sigma[1] = s[ComputeGRFLOWNetwork::SYY];
  sigma[2] = s[ComputeGRFLOWNetwork::SZZ];

  errmax = 0.0;
  for (int a = 0; a < 3; a++) errmax = MAX(errmax, fabs((sigma[a] - p_target) / p_target));

  // kinetic energy, translational and rotational, of the fix group
  const double *const *v = atom->v;
  const double *const *omega = atom->omega;
  const double *rmass = atom->rmass;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  double kelocal = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double vv = v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2];
    const double ww =
        omega[i][0] * omega[i][0] + omega[i][1] * omega[i][1] + omega[i][2] * omega[i][2];
    kelocal += rmass[i] * (vv + 0.4 * radius[i] * radius[i] * ww);
  }
  MPI_Allreduce(&kelocal, &ke, 1, MPI_DOUBLE, MPI_SUM, world);
  ke *= 0.5 * force->mvv2e;
  if (elastic_var) {
    modify->clearstep_compute();
    eel = input->variable->compute_equal(ivar_elastic);
  } else {
    eel = pe->compute_scalar();
  }
}

/* ----------------------------------------------------------------------
   the overshoot damping (grflow_overshoot.h) of axis a.  Every update
   counts, also the one a run makes at its start on a servo step: it
   re-measures the stresses (the dashpots then see the full-step
   velocities) and sets the rates, and in runs of one servo interval these
   setup updates are what alternates.
------------------------------------------------------------------------- */

void FixGRFLOWCompress::damp_overshoot(int a, double err)
{
  if (!damping[a].update(err, tol)) return;
  if (comm->me == 0)
    error->warning(FLERR,
                   "Fix {} grflow/compress: sigma_{}{} overshot the target {} servo updates in "
                   "a row at step {}; its gain factor is halved to {}",
                   id, "xyz"[a], "xyz"[a], GRFLOW::OvershootDamping::NOVERSHOOT,
                   update -> ntimestep, damping[a].factor);
}

/* ----------------------------------------------------------------------
   walls move symmetrically: the gap h changes at rate[2] * h
------------------------------------------------------------------------- */

void FixGRFLOWCompress::drive_walls()
{
  const double vz = 0.5 * rate[2] * height();
  wall->set_velocity(FixGRFLOWWall::LO, 0.0, 0.0, -vz);
  wall->set_velocity(FixGRFLOWWall::HI, 0.0, 0.0, vz);
}

/* ----------------------------------------------------------------------
   scale the box in x and y about its centre, remapping the fix group
   affinely (as fix deform with remap x)
------------------------------------------------------------------------- */

void FixGRFLOWCompress::deform_box()
{
  if (rate[0] == 0.0 && rate[1] == 0.0) return;
  domain->x2lamda(atom->nlocal, groupbit);
  for (int a = 0; a < 2; a++) {
    const double mid = 0.5 * (domain->boxlo[a] + domain->boxhi[a]);
    const double half = 0.5 * (domain->boxhi[a] - domain->boxlo[a]) * (1.0 + rate[a] * dt);
    domain->boxlo[a] = mid - half;
    domain->boxhi[a] = mid + half;
  }
  domain->set_global_box();
  domain->set_local_box();
  domain->lamda2x(atom->nlocal, groupbit);
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWCompress::height() const
{
  return wall->wall(FixGRFLOWWall::HI).z - wall->wall(FixGRFLOWWall::LO).z;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::reset_dt()
{
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWCompress::compute_vector(int n)
{
  const double h = wall ? height() : 0.0;
  const double volume = domain->xprd * domain->yprd * h;
  const double ratio = (eel > 0.0) ? ke / eel : (ke > 0.0 ? INFINITY : 0.0);
  switch (n) {
    case CONVERGED:
      return (errmax <= tol && ratio <= ke_ratio_max) ? 1.0 : 0.0;
    case SXX:
    case SYY:
    case SZZ:
      return sigma[n - SXX];
    case ERRMAX:
      return errmax;
    case KE:
      return ke;
    case EEL:
      return eel;
    case RATIO:
      return ratio;
    case RATE_X:
    case RATE_Y:
    case RATE_Z:
      return rate[n - RATE_X];
    case VOLUME:
      return volume;
    case VOID:
      return vsolid > 0.0 ? volume / vsolid - 1.0 : 0.0;
    case LX:
      return domain->xprd;
    case LY:
      return domain->yprd;
    case HEIGHT:
      return h;
    case FACTOR_X:
    case FACTOR_Y:
    case FACTOR_Z:
      return damping[n - FACTOR_X].factor;
  }
  return 0.0;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::write_restart(FILE *fp)
{
  double list[NRESTART] = {rate[0], rate[1], rate[2], (double) (RESTART_V2 + started)};
  for (int a = 0; a < 3; a++) {
    list[4 + a] = damping[a].factor;
    list[7 + a] = damping[a].err_last;
    list[10 + a] = (double) damping[a].count;
  }
  write_restart_values(lmp, fp, RESTART_VERSION, list, NRESTART);
}

/* ----------------------------------------------------------------------
   format 1: the header of grflow_restart.h, then the values of
   write_restart(); format 0 (files written before the header): the same
   values without it, or only the first four (files written before the
   overshoot damping, told apart by RESTART_V2)
------------------------------------------------------------------------- */

void FixGRFLOWCompress::restart(char *buf)
{
  int version;
  const double *list = read_restart_values(lmp, fmt::format("Fix grflow/compress {}", id), buf,
                                           RESTART_VERSION, NRESTART, version);
  rate[0] = list[0];
  rate[1] = list[1];
  rate[2] = list[2];
  const int flag = (int) list[3];
  started = flag % RESTART_V2;
  if (flag < RESTART_V2) return;    // older file: no damping state, keep factors 1
  for (int a = 0; a < 3; a++) {
    damping[a].factor = list[4 + a];
    damping[a].err_last = list[7 + a];
    damping[a].count = (int) list[10 + a];
  }
}
