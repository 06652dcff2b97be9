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

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixGRFLOWShear::FixGRFLOWShear(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), wall(nullptr), network(nullptr), iglue(-1), gluebit(0)
{
  GRFLOW::FixHost host{lmp};
  settings.parse(narg, arg, host);
  if (!settings.glue.empty()) {
    iglue = group->find(settings.glue);
    if (iglue < 0) error->all(FLERR, settings.glue_missing());
    gluebit = group->bitmask[iglue];
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
  dt = update->dt;
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
  wall = FixGRFLOWWall::find_cell(lmp, "Fix grflow/shear", settings.wall_id.c_str());
  network = ComputeGRFLOWNetwork::find(lmp, "Fix grflow/shear", settings.network_id.c_str());
  if (network->has_p0_keyword()) error->all(FLERR, settings.p0_owner(id));
  for (auto *ifix : modify->get_fix_by_style("^grflow/shear$")) {
    auto *other = dynamic_cast<FixGRFLOWShear *>(ifix);
    if (other && other != this && other->network_id() == settings.network_id)
      error->all(FLERR, settings.p0_second_owner(id, other->id));
  }
  // group delete guards only a fix's own group
  if (iglue >= 0 && group->find(settings.glue) != iglue) error->all(FLERR, settings.glue_deleted());
  dt = update->dt;
}

/* ----------------------------------------------------------------------
   start shearing (first run) or carry on (later runs, restart): the top
   wall moves in x at direction*vx, never in z, so the height is constant
------------------------------------------------------------------------- */

void FixGRFLOWShear::setup(int /*vflag*/)
{
  const bool first = !state.started;
  // the whole vector, evaluated afresh (atoms may have been changed
  // between runs since the compute's last evaluation on this step), so
  // that what reads the compute between runs finds it current; its r_u is
  // that of this fix's p0 (p0())
  network->compute_vector();
  if (first) {
    GRFLOW::FixHost host{lmp};
    state.start(network->vector[ComputeGRFLOWNetwork::PRESS], sim_time(), host);
    network->compute_vector();    // r_u with the p0 just taken
  }
  drive_wall();
  progress.start(platform::walltime(), update->ntimestep);
  // read tau, p, r_u for output; apply the reversal and liquefaction rules
  // only where an uninterrupted run would (every N-th step, and the very
  // start), so that a run split at any step (run N run M, read_restart)
  // takes the same decisions as one run
  check(settings.decides(first, update->ntimestep));
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::drive_wall()
{
  const double vw = state.velocity(settings);
  wall->set_velocity(FixGRFLOWWall::HI, vw, 0.0, 0.0);
  // the glued layer takes the wall velocity at once, so that between steps
  // (output, the setup of a next run) it moves with the wall as well
  if (iglue >= 0) GRFLOW::glue_layer(atom->nlocal, atom->mask, gluebit, vw, atom->v, atom->omega);
}

/* ----------------------------------------------------------------------
   the glued layer moves rigidly with the top wall
------------------------------------------------------------------------- */

void FixGRFLOWShear::initial_integrate(int /*vflag*/)
{
  GRFLOW::glue_layer(atom->nlocal, atom->mask, gluebit, state.velocity(settings), atom->v,
                     atom->omega, dt, atom->x);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::end_of_step()
{
  if (settings.decides(false, update->ntimestep)) check();
}

/* ----------------------------------------------------------------------
   read tau, p, r_u and apply the rules (grflow_shear_rule.h); a reversal
   drives the wall and prints a progress line (screen and log)
------------------------------------------------------------------------- */

void FixGRFLOWShear::check(bool decide)
{
  // the stress sums alone: the network quantities are evaluated only on
  // the steps that output them
  const double *stress = network->current_stress();
  state.tau = stress[ComputeGRFLOWNetwork::TAU];
  state.press = stress[ComputeGRFLOWNetwork::PRESS];
  state.ru = stress[ComputeGRFLOWNetwork::RU];
  if (!decide) return;
  const bigint step = update->ntimestep;
  if (state.reverse(settings, step, sim_time())) {
    drive_wall();
    if (settings.progress) {
      const double gamma = wall->wall(FixGRFLOWWall::HI).disp[0] / GRFLOW::wall_gap(*wall);
      const std::string line = progress.line(id, state, step, gamma, platform::walltime());
      if (comm->me == 0) utils::logmesg(lmp, line);
    }
  }
  state.liquefied(settings, step, sim_time());
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
  const double h = wall ? GRFLOW::wall_gap(*wall) : 0.0;
  return state.output(n, settings, update->ntimestep, wall != nullptr, xw, h);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::write_restart(FILE *fp)
{
  double list[GRFLOW::ShearProtocol::NRESTART];
  state.pack(list);
  GRFLOW::write_restart_values(lmp, fp, GRFLOW::ShearProtocol::RESTART_VERSION, list,
                               GRFLOW::ShearProtocol::NRESTART);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWShear::restart(char *buf)
{
  int version;
  const double *list = GRFLOW::read_restart_values(lmp, fmt::format("Fix grflow/shear {}", id), buf,
                                                   GRFLOW::ShearProtocol::RESTART_VERSION,
                                                   GRFLOW::ShearProtocol::NRESTART, version);
  GRFLOW::FixHost host{lmp};
  state.unpack(id, version, list, host);
}
