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
   a convergence flag.  The servo is host-free (grflow_servo.h); this class
   is compiled into LAMMPS and GRFLOW's LIGGGHTS build alike.
------------------------------------------------------------------------- */

#include "fix_grflow_compress.h"

#include "grflow_host_api.h"
#include "grflow_network.h"
#include "grflow_servo.h"
#include "grflow_wall.h"

#include "atom.h"
#include "compute.h"
#include "compute_grflow_network.h"
#include "domain.h"
#include "error.h"
#include "fix_grflow_wall.h"
#include "force.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using GRFLOW::FlatWalls;
using GRFLOW::StressServo;

/* ---------------------------------------------------------------------- */

FixGRFLOWCompress::FixGRFLOWCompress(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), dt(0.0), settings(nullptr), servo(nullptr), ivar_elastic(-1),
    warned_energy(false), wall(nullptr), network(nullptr), pe(nullptr), vsolid(0.0)
{
  settings = new GRFLOW::CompressSettings;
  servo = new GRFLOW::StressServo;
  GRFLOW::FixHost host{lmp};
  settings->parse(narg, arg, host);
  if (settings->halt != GRFLOW::CompressSettings::HALT_NO && !GRFLOW::can_end_run())
    error->all(FLERR, GRFLOW::CompressSettings::halt_unsupported());
  GRFLOW::CompressSettings::check_cell(atom->radius_flag && atom->rmass_flag && atom->omega_flag,
                                       domain->triclinic, domain->xperiodic && domain->yperiodic,
                                       domain->dimension, host);

  vector_flag = 1;
  size_vector = GRFLOW::CompressLayout::NOUT;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  GRFLOW::declare_box_change_xy(this);

  // without an elastic variable the elastic energy is the potential energy
  // of the pair style, tallied on the servo steps only (as fix box/relax
  // does with its compute pe)
  if (settings->elastic_var.empty()) {
    id_pe = std::string(id) + "_pe";
    pe = GRFLOW::add_compute(lmp, id_pe + " all pe");
  }
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

FixGRFLOWCompress::~FixGRFLOWCompress()
{
  if (!id_pe.empty() && GRFLOW::compute_by_id(lmp, id_pe)) GRFLOW::delete_compute(lmp, id_pe);
  delete servo;
  delete settings;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWCompress::setmask()
{
  // POST_RUN: halt, also when fix_modify sets it later
  return END_OF_STEP | POST_RUN;
}

/* ----------------------------------------------------------------------
   fix_modify halt no|stress|ready
------------------------------------------------------------------------- */

int FixGRFLOWCompress::modify_param(int narg, char **arg)
{
  if (strcmp(arg[0], "halt") != 0) return 0;
  GRFLOW::FixHost host{lmp};
  if (narg < 2) {
    host.missing(FLERR, "fix_modify halt");
    return 0;
  }
  settings->keyword("halt", arg[1], "fix_modify halt", host);
  if (settings->halt != GRFLOW::CompressSettings::HALT_NO && !GRFLOW::can_end_run())
    error->all(FLERR, GRFLOW::CompressSettings::halt_unsupported());
  return 2;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::init()
{
  wall = FixGRFLOWWall::find_cell(lmp, "Fix grflow/compress", settings->wall_id);
  network = ComputeGRFLOWNetwork::find(lmp, "Fix grflow/compress", settings->network_id);

  GRFLOW::FixHost host{lmp};
  if (settings->elastic_var.empty()) {
    pe = GRFLOW::compute_by_id(lmp, id_pe);
    GRFLOW::CompressSettings::check_pe(pe != nullptr, id_pe, host);
    if (!warned_energy && !GRFLOW::pair_tallies_energy(lmp))
      host.warning(FLERR,
                   std::string("Fix grflow/compress: pair style ") + force->pair_style +
                       " tallies no elastic energy, so E_e is 0 and the convergence flag stays 0 "
                       "while the packing moves; give the elastic energy with elastic v_name");
    warned_energy = true;    // once, not at every run
  } else {
    ivar_elastic = GRFLOW::variable_index(lmp, settings->elastic_var);
    const bool found = ivar_elastic >= 0;
    settings->check_variable(found, found && input->variable->equalstyle(ivar_elastic), host);
  }

  // solid volume of the fix group, for the void ratio
  double vlocal = GRFLOW::cubed_radius_sum(atom->nlocal, atom->mask, groupbit, atom->radius);
  MPI_Allreduce(&vlocal, &vsolid, 1, MPI_DOUBLE, MPI_SUM, world);
  vsolid = GRFLOW::solid_volume(vsolid);

  dt = update->dt;

  // the energy must be tallied on the step the first servo update reads
  // it: the compute pe here; the computes of an elastic variable are
  // scheduled for this step by the host's Modify::init()
  // (addstep_compute_all())
  if (pe) pe->addstep(update->ntimestep);
}

/* ----------------------------------------------------------------------
   update the rates where an uninterrupted run would (StressServo::
   updates_at_setup()).  On a multiple of N this repeats that step's update
   with stresses re-measured at setup (full-step velocities in the
   dashpots).  A run that starts between servo steps (a split run, a
   restart) keeps the rates and re-measures the outputs only.
------------------------------------------------------------------------- */

void FixGRFLOWCompress::setup(int /*vflag*/)
{
  if (servo->updates_at_setup(*settings, update->ntimestep))
    update_servo();
  else
    measure();
  servo->started = 1;
  schedule_energy(settings->next_servo_step(update->ntimestep));
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::end_of_step()
{
  if (settings->servo_step(update->ntimestep)) {
    update_servo();
    schedule_energy(update->ntimestep + settings->servo_every);
    // halt: the run ends after this step (as fix halt ... error continue,
    // on the outputs of this update); it reads no atom data
    const double err = compute_vector(GRFLOW::CompressLayout::ERRMAX);
    if (settings->halts(err, compute_vector(GRFLOW::CompressLayout::CONVERGED))) {
      GRFLOW::FixHost host{lmp};
      const bool ready = settings->halt == GRFLOW::CompressSettings::HALT_READY;
      GRFLOW::log_text(lmp,
                       std::string("Fix grflow/compress ") + id + ": halt " +
                           (ready ? "ready" : "stress") + " met on step " +
                           std::to_string(update->ntimestep) + " (largest stress error " +
                           host.text(err) + "): the run ends\n");
      GRFLOW::end_run(lmp);
    }
  }
  deform_box();
}

/* ----------------------------------------------------------------------
   halt: a later run goes on (a run ended early by end_run())
------------------------------------------------------------------------- */

void FixGRFLOWCompress::post_run()
{
  if (settings->halt != GRFLOW::CompressSettings::HALT_NO) GRFLOW::run_may_continue(lmp);
}

/* ----------------------------------------------------------------------
   new strain rates from the stresses (grflow_servo.h).  Every update
   counts for the overshoot damping, also the one a run makes at its start
   on a servo step: it re-measures the stresses (the dashpots then see the
   full-step velocities) and sets the rates, and in runs of one servo
   interval these setup updates are what alternates.
------------------------------------------------------------------------- */

void FixGRFLOWCompress::update_servo()
{
  measure();
  GRFLOW::FixHost host{lmp};
  servo->update(*settings, id, update->ntimestep, host);
  drive_walls();
}

/* ----------------------------------------------------------------------
   the energy compute or the elastic-energy variable's computes must be
   tallied on the next step that reads them
------------------------------------------------------------------------- */

void FixGRFLOWCompress::schedule_energy(bigint step)
{
  if (pe)
    pe->addstep(step);
  else
    modify->addstep_compute(step);
}

/* ----------------------------------------------------------------------
   the outputs: stresses, their largest error, kinetic and elastic energy
------------------------------------------------------------------------- */

void FixGRFLOWCompress::measure()
{
  // the whole vector, not the stress path (current_stress()): the servo
  // step then leaves the compute's vector current, and a library call or
  // variable reading it after the run gets the stresses the servo used,
  // not ones evaluated anew after the box was scaled
  if (network->invoked_vector != update->ntimestep) network->compute_vector();
  servo->set_stresses(*settings, network->vector);

  // kinetic energy, translational and rotational, of the fix group
  double kelocal = kinetic_local();
  double ke;
  MPI_Allreduce(&kelocal, &ke, 1, MPI_DOUBLE, MPI_SUM, world);
  servo->ke = GRFLOW::kinetic_energy(ke, force->mvv2e);
  if (pe) {
    servo->eel = pe->compute_scalar();
  } else {
    modify->clearstep_compute();
    servo->eel = input->variable->compute_equal(ivar_elastic);
  }
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::drive_walls()
{
  FlatWalls &cell = wall->cell();
  const double vz = servo->wall_speed(cell.gap());
  cell.set_velocity(FlatWalls::LO, 0.0, 0.0, -vz);
  cell.set_velocity(FlatWalls::HI, 0.0, 0.0, vz);
}

/* ----------------------------------------------------------------------
   scale the box in x and y about its centre, remapping the fix group
   affinely (as fix deform with remap x)
------------------------------------------------------------------------- */

void FixGRFLOWCompress::deform_box()
{
  if (!servo->deforms()) return;
  remap_group(true);
  for (int a = 0; a < 2; a++) servo->scale(a, dt, domain->boxlo[a], domain->boxhi[a]);
  domain->set_global_box();
  domain->set_local_box();
  remap_group(false);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::remap_group(bool to_lamda)
{
  double **x = atom->x;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) {
      if (to_lamda)
        domain->x2lamda(x[i], x[i]);
      else
        domain->lamda2x(x[i], x[i]);
    }
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWCompress::kinetic_local()
{
  return GRFLOW::kinetic_sum(atom->nlocal, atom->mask, groupbit, atom->v, atom->omega, atom->rmass,
                             atom->radius);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::reset_dt()
{
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWCompress::compute_vector(int n)
{
  const double h = wall ? wall->cell().gap() : 0.0;
  return servo->output(n, *settings, h, domain->xprd, domain->yprd, vsolid);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWCompress::write_restart(FILE *fp)
{
  double list[StressServo::NRESTART];
  servo->pack(list);
  GRFLOW::write_restart_values(lmp, fp, StressServo::RESTART_VERSION, list, StressServo::NRESTART);
}

/* ----------------------------------------------------------------------
   format 1 and the older ones: StressServo::unpack()
------------------------------------------------------------------------- */

void FixGRFLOWCompress::restart(char *buf)
{
  int version;
  servo->unpack(GRFLOW::read_restart_values(lmp, std::string("Fix grflow/compress ") + id, buf,
                                            StressServo::RESTART_VERSION, StressServo::NRESTART,
                                            version));
}
