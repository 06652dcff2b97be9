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

   Stress-controlled cyclic simple shear at constant height: the top wall
   of a fix grflow/wall (and a glued layer) moves in x at +-vx; the
   direction reverses when tau from a compute grflow/network reaches
   +tau_amp while moving +x or -tau_amp while moving -x.  Records p0 when
   shearing starts, initial liquefaction (first r_u >= threshold), the
   reversal count and the fractional cycle count N (grflow_cycle_count.h);
   all of it goes to restart files.
------------------------------------------------------------------------- */

#include "fix_grflow_shear.h"

#include "grflow_restart.h"

#include "atom.h"
#include "comm.h"
#include "compute_grflow_network.h"
#include "error.h"
#include "fix_grflow_wall.h"
#include "group.h"
#include "modify.h"
#include "platform.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using GRFLOW::read_restart_values;
using GRFLOW::write_restart_values;

static constexpr int NRESTART = 13;
static constexpr int RESTART_VERSION = 2;
enum { NO_EVENT, EVENT_REVERSAL, EVENT_ZERO };

/* ---------------------------------------------------------------------- */

FixGRFLOWShear::FixGRFLOWShear(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), id_wall(nullptr), id_network(nullptr), wall(nullptr), network(nullptr)
{
  if (narg < 7)
    error->all(FLERR,
               "Illegal fix grflow/shear command: expected wall-ID compute-ID vx tau_amp "
               "[keyword value ...]");
  id_wall = utils::strdup(arg[3]);
  id_network = utils::strdup(arg[4]);
  vx = utils::numeric(FLERR, arg[5], false, lmp);
  tau_amp = utils::numeric(FLERR, arg[6], false, lmp);
  if (vx <= 0.0) error->all(FLERR, "Fix grflow/shear vx must be > 0, got {}", vx);
  if (tau_amp <= 0.0) error->all(FLERR, "Fix grflow/shear tau_amp must be > 0, got {}", tau_amp);

  iglue = -1;
  gluebit = 0;
  ru_liq = 0.99;
  check_every = 1;
  stop_cycles_after_il = stop_cycles = stop_gamma = 0.0;
  progress = 1;

  int iarg = 7;
  while (iarg < narg) {
    const std::string kw = arg[iarg];
    // an unknown keyword is reported as such, also at the end of the line
    if (kw != "every" && kw != "liquefaction" && kw != "stop_cycles" &&
        kw != "stop_after_liquefaction" && kw != "stop_gamma" && kw != "progress" && kw != "glue")
      error->all(FLERR, "Unknown fix grflow/shear keyword: {}", kw);
    if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix grflow/shear " + kw, error);
    if (kw == "every") {
      check_every = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (check_every < 1) error->all(FLERR, "Fix grflow/shear every must be >= 1");
    } else if (kw == "liquefaction") {
      ru_liq = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (ru_liq <= 0.0 || ru_liq > 1.0)
        error->all(FLERR, "Fix grflow/shear liquefaction threshold must be in (0,1], got {}",
                   ru_liq);
    } else if (kw == "stop_cycles") {
      stop_cycles = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (stop_cycles <= 0.0) error->all(FLERR, "Fix grflow/shear stop_cycles must be > 0");
    } else if (kw == "stop_after_liquefaction") {
      stop_cycles_after_il = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (stop_cycles_after_il <= 0.0)
        error->all(FLERR, "Fix grflow/shear stop_after_liquefaction must be > 0");
    } else if (kw == "stop_gamma") {
      stop_gamma = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (stop_gamma <= 0.0) error->all(FLERR, "Fix grflow/shear stop_gamma must be > 0");
    } else if (kw == "progress") {
      progress = utils::logical(FLERR, arg[iarg + 1], false, lmp);
    } else if (kw == "glue") {
      iglue = group->find(arg[iarg + 1]);
      if (iglue < 0)
        error->all(FLERR, "Fix grflow/shear glue group {} does not exist", arg[iarg + 1]);
      gluebit = group->bitmask[iglue];
      glue_name = arg[iarg + 1];
    } else {
      error->all(FLERR, "Unknown fix grflow/shear keyword: {}", kw);
    }
    iarg += 2;
  }

  vector_flag = 1;
  size_vector = NOUT;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  // the glued layer is moved by this fix; LAMMPS warns about atoms that are
  // time integrated more than once by the groupbit of time-integrating
  // fixes, so that bit must be the glued layer's, not the fix group's
  if (iglue >= 0) {
    time_integrate = 1;
    groupbit = gluebit;
  }

  started = 0;
  direction = 1;
  reversals = 0;
  step_il = -1;
  p0 = 0.0;
  await_zero = 0;
  event_step = -1;
  event_kind = NO_EVENT;
  wall_start = wall_last = 0.0;
  step_last = 0;
  tau = press = ru = 0.0;
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

FixGRFLOWShear::~FixGRFLOWShear()
{
  delete[] id_wall;
  delete[] id_network;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWShear::setmask()
{
  int mask = END_OF_STEP;
  if (iglue >= 0) mask |= INITIAL_INTEGRATE;
  return mask;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::init()
{
  wall = FixGRFLOWWall::find_cell(lmp, "Fix grflow/shear", id_wall);
  network = ComputeGRFLOWNetwork::find(lmp, "Fix grflow/shear", id_network);
  if (network->has_p0_keyword())
    error->all(FLERR,
               "Fix grflow/shear {} sets p0 of compute {} when shearing starts: remove the "
               "compute's p0 keyword",
               id, id_network);

  if (iglue >= 0) {
    // group delete guards only a fix's own group
    if (group->find(glue_name) != iglue)
      error->all(FLERR, "Fix grflow/shear glue group {} was deleted", glue_name);
  }
  dt = update->dt;
}

/* ----------------------------------------------------------------------
   start shearing (first run) or carry on (later runs, restart): the top
   wall moves in x at direction*vx, never in z, so the height is constant
------------------------------------------------------------------------- */

void FixGRFLOWShear::setup(int /*vflag*/)
{
  const bool first = !started;
  if (!started) {
    network->compute_vector();
    p0 = network->vector[ComputeGRFLOWNetwork::PRESS];
    if (p0 <= 0.0)
      error->all(FLERR,
                 "Fix grflow/shear: the mean stress is {} when shearing starts; "
                 "it must be > 0 to define r_u",
                 p0);
    started = 1;
    direction = 1;
    count.start(sim_time());
  }
  // r_u at this step with this p0 (the compute may have been invoked with
  // another p0 of its own, its p0 keyword, just above or earlier)
  network->set_p0(p0);
  network->compute_vector();
  drive_wall();
  wall_start = wall_last = platform::walltime();
  step_last = update->ntimestep;
  // read tau, p, r_u for output; apply the reversal and liquefaction rules
  // only where an uninterrupted run would (every N-th step, and the very
  // start), so that a run split at any step (run N run M, read_restart)
  // takes the same decisions as one run
  check(first || update->ntimestep % check_every == 0);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::drive_wall()
{
  wall->set_velocity(FixGRFLOWWall::HI, direction * vx, 0.0, 0.0);

  // the glued layer takes the wall velocity at once, so that between steps
  // (output, the setup of a next run) it moves with the wall as well
  if (iglue < 0) return;
  double **v = atom->v;
  double **omega = atom->omega;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & gluebit)) continue;
    v[i][0] = direction * vx;
    v[i][1] = v[i][2] = 0.0;
    omega[i][0] = omega[i][1] = omega[i][2] = 0.0;
  }
}

/* ----------------------------------------------------------------------
   the glued layer moves rigidly with the top wall
------------------------------------------------------------------------- */

void FixGRFLOWShear::initial_integrate(int /*vflag*/)
{
  double **x = atom->x;
  double **v = atom->v;
  double **omega = atom->omega;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double vw = direction * vx;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & gluebit)) continue;
    v[i][0] = vw;
    v[i][1] = v[i][2] = 0.0;
    omega[i][0] = omega[i][1] = omega[i][2] = 0.0;
    x[i][0] += dt * vw;
  }
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::end_of_step()
{
  if (update->ntimestep % check_every == 0) check();
}

/* ----------------------------------------------------------------------
   read tau, p, r_u (global values: every rank decides alike) and reverse
------------------------------------------------------------------------- */

void FixGRFLOWShear::check(bool decide)
{
  if (network->invoked_vector != update->ntimestep) network->compute_vector();
  tau = network->vector[ComputeGRFLOWNetwork::TAU];
  press = network->vector[ComputeGRFLOWNetwork::PRESS];
  ru = network->vector[ComputeGRFLOWNetwork::RU];
  if (!decide) return;

  // the first zero-crossing of tau after a reversal (tau moves from the
  // amplitude just reached towards the other side)
  if (await_zero && ((direction < 0 && tau <= 0.0) || (direction > 0 && tau >= 0.0))) {
    await_zero = 0;
    event_step = update->ntimestep;
    event_kind = EVENT_ZERO;
    count.crossing(reversals, sim_time());
  }
  if ((direction > 0 && tau >= tau_amp) || (direction < 0 && tau <= -tau_amp)) {
    direction = -direction;
    reversals++;
    await_zero = 1;
    event_step = update->ntimestep;
    event_kind = EVENT_REVERSAL;
    count.reversal(reversals, sim_time());
    drive_wall();
    if (progress) report();
  }
  if (step_il < 0 && ru >= ru_liq) {
    step_il = update->ntimestep;
    count.liquefied(sim_time());
  }
}

/* ----------------------------------------------------------------------
   one progress line per reversal (screen and log)
------------------------------------------------------------------------- */

void FixGRFLOWShear::report()
{
  const double now = platform::walltime();
  const double rate = (now > wall_last) ? (update->ntimestep - step_last) / (now - wall_last) : 0.0;
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "grflow/shear {}: reversal {} N {:.2f} step {} gamma {:.6g} tau {:.6g} "
                   "r_u {:.4f}{} elapsed {:.1f} s {:.0f} steps/s\n",
                   id, reversals, count.n_event, update->ntimestep,
                   wall->wall(FixGRFLOWWall::HI).disp[0] / height(), tau, ru,
                   step_il >= 0 ? " (liquefied)" : "", now - wall_start, rate);
  wall_last = now;
  step_last = update->ntimestep;
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWShear::height() const
{
  return wall->wall(FixGRFLOWWall::HI).z - wall->wall(FixGRFLOWWall::LO).z;
}

/* ----------------------------------------------------------------------
   simulated time of this step, as thermo keyword time
------------------------------------------------------------------------- */

double FixGRFLOWShear::sim_time() const
{
  return update->atime + (update->ntimestep - update->atimestep) * update->dt;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::reset_dt()
{
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWShear::compute_vector(int n)
{
  const double xw = wall ? wall->wall(FixGRFLOWWall::HI).disp[0] : 0.0;
  switch (n) {
    case DIRECTION:
      return direction;
    case REVERSALS:
      return reversals;
    case XWALL:
      return xw;
    case GAMMA:
      return wall ? xw / height() : 0.0;
    case TAU:
      return tau;
    case PRESS:
      return press;
    case RU:
      return ru;
    case P0:
      return p0;
    case STEP_IL:
      return step_il;
    case TIME_IL:
      return count.il ? count.t_il : -1.0;
    case N_IL:
      return count.n_il;
    case N_EVENT:
      return count.n_event;
    case DONE: {
      int done = 0;
      if (stop_cycles > 0.0 && count.n_event >= stop_cycles) done = 1;
      if (stop_cycles_after_il > 0.0 && count.n_il >= 0.0 &&
          count.n_event - count.n_il >= stop_cycles_after_il)
        done = 1;
      if (stop_gamma > 0.0 && wall && fabs(xw / height()) >= stop_gamma) done = 1;
      return done;
    }
    case EVENT:
      return (event_step == update->ntimestep) ? event_kind : NO_EVENT;
  }
  return 0.0;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::write_restart(FILE *fp)
{
  double list[NRESTART] = {
      (double) started,    (double) direction, (double) reversals, (double) step_il,  p0,
      (double) await_zero, count.n_event,      count.t_event,      (double) count.il, count.t_il,
      count.n_il,          count.n_before_il,  count.t_before_il};
  write_restart_values(lmp, fp, RESTART_VERSION, list, NRESTART);
}

/* ----------------------------------------------------------------------
   format 2: the header of grflow_restart.h, then the values of
   write_restart().  Formats 1 and 0 (before the fractional cycle count)
   lack the times of the cycle events, so N cannot go on from them.
------------------------------------------------------------------------- */

void FixGRFLOWShear::restart(char *buf)
{
  int version;
  const double *list = read_restart_values(lmp, fmt::format("Fix grflow/shear {}", id), buf,
                                           RESTART_VERSION, NRESTART, version);
  if (version < RESTART_VERSION)
    error->all(FLERR,
               "Fix grflow/shear {}: restart data of format version {} were written before "
               "GRFLOW counted fractional cycles and lack the times of the cycle events: continue "
               "that run with the GRFLOW that wrote it, or start its shear stage again",
               id, version);
  started = (int) list[0];
  direction = (int) list[1];
  reversals = (bigint) list[2];
  step_il = (bigint) list[3];
  p0 = list[4];
  await_zero = (int) list[5];
  count.n_event = list[6];
  count.t_event = list[7];
  count.il = list[8] != 0.0;
  count.t_il = list[9];
  count.n_il = list[10];
  count.n_before_il = list[11];
  count.t_before_il = list[12];
}
