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
   +tau_amp while moving +x or -tau_amp while moving -x.  Takes p0 when
   shearing starts and r_u = 1 - p/p0 from the compute's p; records
   initial liquefaction (first r_u >= threshold), the reversal count and
   the fractional cycle count N (grflow_cycle_count.h); all of it goes to
   restart files.  The rules are host-free (grflow_shear_rule.h); this
   class is compiled into LAMMPS and GRFLOW's LIGGGHTS build alike.
------------------------------------------------------------------------- */

#include "fix_grflow_shear.h"

#include "grflow_host_api.h"
#include "grflow_network.h"
#include "grflow_shear_rule.h"
#include "grflow_wall.h"

#include "atom.h"
#include "compute_grflow_network.h"
#include "error.h"
#include "fix_grflow_wall.h"
#include "group.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;
using GRFLOW::FlatWalls;
using GRFLOW::NetworkLayout;
using GRFLOW::ShearProtocol;

/* ---------------------------------------------------------------------- */

FixGRFLOWShear::FixGRFLOWShear(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), iglue(-1), gluebit(0), dt(0.0), settings(nullptr), state(nullptr),
    progress(nullptr), wall(nullptr), network(nullptr)
{
  settings = new GRFLOW::ShearSettings;
  state = new GRFLOW::ShearProtocol;
  progress = new GRFLOW::ShearProgress;
  GRFLOW::FixHost host{lmp};
  settings->parse(narg, arg, host);
  if (settings->halt && !GRFLOW::can_end_run()) error->all(FLERR, settings->halt_unsupported());
  if (!settings->glue.empty()) {
    iglue = group->find(settings->glue.c_str());
    if (iglue < 0) error->all(FLERR, settings->glue_missing());
    gluebit = group->bitmask[iglue];
  }

  vector_flag = 1;
  size_vector = GRFLOW::ShearLayout::NOUT;
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
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

FixGRFLOWShear::~FixGRFLOWShear()
{
  delete progress;
  delete state;
  delete settings;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWShear::setmask()
{
  int mask = END_OF_STEP;
  if (iglue >= 0) mask |= INITIAL_INTEGRATE;
  if (settings->halt) mask |= POST_RUN;
  return mask;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::init()
{
  wall = FixGRFLOWWall::find_cell(lmp, "Fix grflow/shear", settings->wall_id);
  network = ComputeGRFLOWNetwork::find(lmp, "Fix grflow/shear", settings->network_id);
  // group delete guards only a fix's own group
  if (iglue >= 0 && group->find(settings->glue.c_str()) != iglue)
    error->all(FLERR, settings->glue_deleted());
  dt = update->dt;
}

/* ----------------------------------------------------------------------
   start shearing (first run: p0, direction +1) or carry on (later runs,
   restart): the top wall moves in x at direction*vx, never in z, so the
   height is constant
------------------------------------------------------------------------- */

void FixGRFLOWShear::setup(int /*vflag*/)
{
  const bool first = !state->started;
  // the whole vector, evaluated afresh (atoms may have been changed
  // between runs since the compute's last evaluation on this step), so
  // that what reads the compute between runs finds it current
  network->compute_vector();
  if (first) {
    GRFLOW::FixHost host{lmp};
    state->start(network->vector[NetworkLayout::PRESS], sim_time(), host);
  }
  drive_wall();
  progress->start(GRFLOW::walltime(), update->ntimestep);
  // read tau, p, r_u for output; apply the reversal and liquefaction rules
  // only where an uninterrupted run would (every N-th step, and the very
  // start), so that a run split at any step (run N run M, read_restart)
  // takes the same decisions as one run
  check(settings->decides(first, update->ntimestep));
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::drive_wall()
{
  const double vw = state->velocity(*settings);
  wall->cell().set_velocity(FlatWalls::HI, vw, 0.0, 0.0);
  // the glued layer takes the wall velocity at once, so that between steps
  // (output, the setup of a next run) it moves with the wall as well
  if (iglue >= 0) glue(vw, false);
}

/* ----------------------------------------------------------------------
   the glued layer moves rigidly with the top wall
------------------------------------------------------------------------- */

void FixGRFLOWShear::initial_integrate(int /*vflag*/)
{
  glue(state->velocity(*settings), true);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::glue(double vw, bool step)
{
  if (step)
    GRFLOW::glue_layer(atom->nlocal, atom->mask, gluebit, vw, atom->v, atom->omega, dt, atom->x);
  else
    GRFLOW::glue_layer(atom->nlocal, atom->mask, gluebit, vw, atom->v, atom->omega);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::end_of_step()
{
  if (!settings->decides(false, update->ntimestep)) return;
  check();
  // halt yes: the run ends after the step of an event, and after a check
  // once done (as fix halt every N with v_event != 0 or v_done > 0.5,
  // error continue); it reads no atom data
  if (settings->halt &&
      (compute_vector(GRFLOW::ShearLayout::EVENT) != 0.0 ||
       compute_vector(GRFLOW::ShearLayout::DONE) > 0.5))
    GRFLOW::end_run(lmp);
}

/* ----------------------------------------------------------------------
   halt yes: a later run goes on (the run ended early by end_run())
------------------------------------------------------------------------- */

void FixGRFLOWShear::post_run()
{
  GRFLOW::run_may_continue(lmp);
}

/* ----------------------------------------------------------------------
   read tau and p, derive r_u with this fix's p0, and apply the rules
   (grflow_shear_rule.h); a reversal drives the wall and prints a progress
   line (screen and log)
------------------------------------------------------------------------- */

void FixGRFLOWShear::check(bool decide)
{
  // the stress sums alone: the network quantities are evaluated only on
  // the steps that output them
  const double *stress = network->current_stress();
  state->tau = stress[NetworkLayout::TAU];
  state->press = stress[NetworkLayout::PRESS];
  state->ru = GRFLOW::pore_pressure_ratio(state->press, state->p0);
  if (!decide) return;
  const bigint step = update->ntimestep;
  if (state->reverse(*settings, step, sim_time())) {
    drive_wall();
    if (settings->progress) {
      const FlatWalls &cell = wall->cell();
      const double gamma = cell.wall(FlatWalls::HI).disp[0] / cell.gap();
      GRFLOW::log_text(lmp, progress->line(id, *state, step, gamma, GRFLOW::walltime()));
    }
  }
  state->liquefied(*settings, step, sim_time());
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
  if (!wall) return state->output(n, *settings, update->ntimestep, false, 0.0, 0.0);
  const FlatWalls &cell = wall->cell();
  return state->output(n, *settings, update->ntimestep, true, cell.wall(FlatWalls::HI).disp[0],
                       cell.gap());
}

/* ----------------------------------------------------------------------
   the values of grflow_shear_rule.h, and where the host's restart files
   do not keep the simulated time (LIGGGHTS), that time too
------------------------------------------------------------------------- */

void FixGRFLOWShear::write_restart(FILE *fp)
{
  double list[ShearProtocol::NRESTART_CLOCK];
  state->pack(list);
  const bool clock = !GRFLOW::restart_keeps_time();
  if (clock) list[ShearProtocol::R_CLOCK] = sim_time();
  GRFLOW::write_restart_values(lmp, fp, ShearProtocol::RESTART_VERSION, list,
                               clock ? ShearProtocol::NRESTART_CLOCK : ShearProtocol::NRESTART);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::restart(char *buf)
{
  int version;
  const bool clock = !GRFLOW::restart_keeps_time();
  const double *list = GRFLOW::read_restart_values(
      lmp, std::string("Fix grflow/shear ") + id, buf, ShearProtocol::RESTART_VERSION,
      clock ? ShearProtocol::NRESTART_CLOCK : ShearProtocol::NRESTART, version);
  GRFLOW::FixHost host{lmp};
  state->unpack(id, version, list, host);
  // the clock at the step of the restart file (its run's init sets
  // atimestep to this step again and keeps atime)
  if (clock) {
    update->atime = list[ShearProtocol::R_CLOCK];
    update->atimestep = update->ntimestep;
  }
}
