/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: fix grflow/shear (fix_grflow_shear.h).

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).

   LIGGGHTS specifics: no fmt (messages come whole from
   grflow_shear_rule.h), MPI_Wtime() for the wall clock, and the
   simulated time: LIGGGHTS restart files do not keep it (LAMMPS's do),
   so this fix appends it to its restart values (R_CLOCK) and sets the
   clock back when it reads them, so that the times of the cycle events
   and of initial liquefaction go on as in one run.
------------------------------------------------------------------------- */

#include "fix_grflow_shear.h"

#include "grflow_restart.h"

#include "atom.h"
#include "compute_grflow_network.h"
#include "fix_grflow_wall.h"
#include "group.h"
#include "modify.h"
#include "update.h"

#include <mpi.h>

using namespace LAMMPS_NS;
using namespace FixConst;
using GRFLOW::FixHost;
using GRFLOW::ShearProtocol;

FixGRFLOWShear::FixGRFLOWShear(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), wall(NULL), network(NULL), iglue(-1), gluebit(0)
{
  FixHost host = {lmp};
  settings.parse(narg, arg, host);
  if (!settings.glue.empty()) {
    iglue = group->find(settings.glue.c_str());
    if (iglue < 0) host.fail(settings.glue_missing());
    gluebit = group->bitmask[iglue];
    // the glued layer is moved by this fix: the integrators' check of atoms
    // integrated twice must see its bit
    time_integrate = 1;
    groupbit = gluebit;
  }
  vector_flag = 1;
  size_vector = NOUT;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  dt = update->dt;
}

int FixGRFLOWShear::setmask()
{
  return iglue >= 0 ? END_OF_STEP | INITIAL_INTEGRATE : END_OF_STEP;
}

void FixGRFLOWShear::init()
{
  wall = FixGRFLOWWall::find_cell(lmp, "Fix grflow/shear", settings.wall_id.c_str());
  network = ComputeGRFLOWNetwork::find(lmp, "Fix grflow/shear", settings.network_id.c_str());
  FixHost host = {lmp};
  if (network->has_p0_keyword()) host.fail(settings.p0_owner(id));
  for (int i = 0; i < modify->nfix; i++) {
    FixGRFLOWShear *other = dynamic_cast<FixGRFLOWShear *>(modify->fix[i]);
    if (other && other != this && other->network_id() == settings.network_id)
      host.fail(settings.p0_second_owner(id, other->id));
  }
  if (iglue >= 0 && group->find(settings.glue.c_str()) != iglue) host.fail(settings.glue_deleted());
  dt = update->dt;
}

// start shearing (first run: p0, direction +1) or carry on; the checks
// at setup decide only where an uninterrupted run would
void FixGRFLOWShear::setup(int)
{
  const bool first = !state.started;
  // the whole vector afresh (atoms may have changed between runs): the
  // decks' variables read the compute between runs, and LIGGGHTS requires
  // it current there; its r_u is that of this fix's p0 (p0())
  network->compute_vector();
  if (first) {
    FixHost host = {lmp};
    state.start(network->vector[ComputeGRFLOWNetwork::PRESS], update->get_cur_time(), host);
    network->compute_vector();    // r_u with the p0 just taken
  }
  move_wall();
  progress.start(MPI_Wtime(), update->ntimestep);
  read_network(settings.decides(first, update->ntimestep));
}

void FixGRFLOWShear::move_wall()
{
  const double vw = state.velocity(settings);
  wall->set_velocity(FixGRFLOWWall::HI, vw, 0.0, 0.0);
  if (iglue < 0) return;
  GRFLOW::glue_layer(atom->nlocal, atom->mask, gluebit, vw, atom->v, atom->omega);
}

void FixGRFLOWShear::initial_integrate(int)
{
  const double vw = state.velocity(settings);
  GRFLOW::glue_layer(atom->nlocal, atom->mask, gluebit, vw, atom->v, atom->omega, dt, atom->x);
}

void FixGRFLOWShear::end_of_step()
{
  if (!settings.decides(false, update->ntimestep)) return;
  read_network(true);
}

// tau, p, r_u of the compute; the rules if decide
void FixGRFLOWShear::read_network(bool decide)
{
  const bigint now = update->ntimestep;
  // the stress sums alone: the network quantities only where output
  const double *stress = network->current_stress();
  state.tau = stress[ComputeGRFLOWNetwork::TAU];
  state.press = stress[ComputeGRFLOWNetwork::PRESS];
  state.ru = stress[ComputeGRFLOWNetwork::RU];
  if (!decide) return;
  if (state.reverse(settings, now, update->get_cur_time())) {
    move_wall();
    const double xw = wall->wall(FixGRFLOWWall::HI).disp[0];
    if (settings.progress)
      GRFLOW::log_text(lmp,
                       progress.line(id, state, now, xw / GRFLOW::wall_gap(*wall), MPI_Wtime()));
  }
  state.liquefied(settings, now, update->get_cur_time());
}

void FixGRFLOWShear::reset_dt()
{
  dt = update->dt;
}

double FixGRFLOWShear::compute_vector(int n)
{
  if (!wall) return state.output(n, settings, update->ntimestep, false, 0.0, 0.0);
  const double xw = wall->wall(FixGRFLOWWall::HI).disp[0];
  return state.output(n, settings, update->ntimestep, true, xw, GRFLOW::wall_gap(*wall));
}

// the values of grflow_shear_rule.h and the simulated time
void FixGRFLOWShear::write_restart(FILE *fp)
{
  double values[ShearProtocol::NRESTART_CLOCK];
  state.pack(values);
  values[ShearProtocol::R_CLOCK] = update->get_cur_time();
  GRFLOW::write_restart_values(lmp, fp, ShearProtocol::RESTART_VERSION, values,
                               ShearProtocol::NRESTART_CLOCK);
}

void FixGRFLOWShear::restart(char *buf)
{
  int version;
  const std::string who = std::string("Fix grflow/shear ") + id;
  const double *values = GRFLOW::read_restart_values(lmp, who, buf, ShearProtocol::RESTART_VERSION,
                                                     ShearProtocol::NRESTART_CLOCK, version);
  FixHost host = {lmp};
  state.unpack(id, version, values, host);
  // the clock at the step of the restart file (its run's init sets
  // atimestep to this step again and keeps atime)
  update->atime = values[ShearProtocol::R_CLOCK];
  update->atimestep = update->ntimestep;
}
