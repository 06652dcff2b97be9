/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: fix grflow/compress (fix_grflow_compress.h).

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).

   LIGGGHTS specifics: the box changes through box_change_size (LAMMPS:
   box_change x y), the affine remap goes atom by atom (Domain has no
   group variant), the compute pe is made from an argument list, and
   LIGGGHTS's pair style gran tallies no energy: without the elastic
   keyword E_e is 0 (a warning says so).
------------------------------------------------------------------------- */

#include "fix_grflow_compress.h"

#include "grflow_restart.h"

#include "atom.h"
#include "compute.h"
#include "compute_grflow_network.h"
#include "domain.h"
#include "fix_grflow_wall.h"
#include "force.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <cstring>
#include <mpi.h>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
using GRFLOW::FixHost;
using GRFLOW::StressServo;

FixGRFLOWCompress::FixGRFLOWCompress(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), ivar_elastic(-1), warned_energy(false), wall(NULL), network(NULL),
    pe(NULL), vsolid(0.0)
{
  FixHost host = {lmp};
  settings.parse(narg, arg, host);
  const bool sphere = atom->radius_flag && atom->rmass_flag && atom->omega_flag;
  const bool periodic_xy = domain->xperiodic && domain->yperiodic;
  GRFLOW::CompressSettings::check_cell(sphere, domain->triclinic, periodic_xy, domain->dimension,
                                       host);
  vector_flag = 1;
  size_vector = NOUT;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  box_change_size = 1;

  // without elastic: the pair style's potential energy, by a compute pe
  // tallied on the servo steps only
  if (settings.elastic_var.empty()) {
    id_pe = std::string(id) + "_pe";
    std::vector<char> pe_id(id_pe.begin(), id_pe.end());
    pe_id.push_back('\0');
    char group_all[] = "all", style_pe[] = "pe";
    char *pe_arg[3] = {&pe_id[0], group_all, style_pe};
    modify->add_compute(3, pe_arg);
  }
  dt = update->dt;
}

FixGRFLOWCompress::~FixGRFLOWCompress()
{
  if (!id_pe.empty() && modify->find_compute(id_pe.c_str()) >= 0)
    modify->delete_compute(id_pe.c_str());
}

int FixGRFLOWCompress::setmask()
{
  return END_OF_STEP;
}

void FixGRFLOWCompress::init()
{
  wall = FixGRFLOWWall::find_cell(lmp, "Fix grflow/compress", settings.wall_id.c_str());
  network = ComputeGRFLOWNetwork::find(lmp, "Fix grflow/compress", settings.network_id.c_str());
  FixHost host = {lmp};
  if (!settings.elastic_var.empty()) {
    // Variable::find() takes a char * but only reads it
    ivar_elastic = input->variable->find(const_cast<char *>(settings.elastic_var.c_str()));
    const bool found = ivar_elastic >= 0;
    settings.check_variable(found, found && input->variable->equalstyle(ivar_elastic), host);
  } else {
    const int ipe = modify->find_compute(id_pe.c_str());
    GRFLOW::CompressSettings::check_pe(ipe >= 0, id_pe, host);
    pe = modify->compute[ipe];
    if (!warned_energy && force->pair_style && strcmp(force->pair_style, "gran") == 0)
      host.warning("Fix grflow/compress: pair style gran tallies no elastic energy, so E_e is 0 "
                   "and the convergence flag stays 0 while the packing moves; give the elastic "
                   "energy with elastic v_name");
    warned_energy = true;    // once, not at every run
  }

  // the solid volume of the fix group
  double sum = GRFLOW::cubed_radius_sum(atom->nlocal, atom->mask, groupbit, atom->radius);
  MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, world);
  vsolid = GRFLOW::solid_volume(sum);
  dt = update->dt;
  // the energy must be tallied on the step the first servo update reads
  // it: the compute pe here; the computes of an elastic variable are
  // scheduled for this step by LIGGGHTS's Modify::init() after the fixes'
  // init (which lists them only then: addstep_compute() may not run yet)
  if (pe) pe->addstep(update->ntimestep);
}

// update where an uninterrupted run would, else measure only
void FixGRFLOWCompress::setup(int)
{
  const bigint now = update->ntimestep;
  if (!servo.updates_at_setup(settings, now))
    read_state();
  else
    servo_update();
  servo.started = 1;
  tally_energy_on(settings.next_servo_step(now));
}

void FixGRFLOWCompress::end_of_step()
{
  const bigint now = update->ntimestep;
  if (settings.servo_step(now)) {
    servo_update();
    tally_energy_on(now + settings.servo_every);
  }
  scale_box();
}

void FixGRFLOWCompress::servo_update()
{
  read_state();
  FixHost host = {lmp};
  servo.update(settings, id, update->ntimestep, host);
  move_walls();
}

void FixGRFLOWCompress::tally_energy_on(bigint step)
{
  if (pe)
    pe->addstep(step);
  else
    modify->addstep_compute(step);
}

// stresses, kinetic and elastic energy
void FixGRFLOWCompress::read_state()
{
  // the whole vector, not the stress path (current_stress()): the servo
  // step then leaves the compute's vector current, and a library call or
  // variable reading it after the run gets the stresses the servo used,
  // not ones evaluated anew after the box was scaled
  if (network->invoked_vector != update->ntimestep) network->compute_vector();
  servo.set_stresses(settings, network->vector);
  double sum = GRFLOW::kinetic_sum(atom->nlocal, atom->mask, groupbit, atom->v, atom->omega,
                                   atom->rmass, atom->radius);
  MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, world);
  servo.ke = GRFLOW::kinetic_energy(sum, force->mvv2e);
  if (pe) {
    servo.eel = pe->compute_scalar();
  } else {
    modify->clearstep_compute();
    servo.eel = input->variable->compute_equal(ivar_elastic);
  }
}

void FixGRFLOWCompress::move_walls()
{
  const double speed = servo.wall_speed(GRFLOW::wall_gap(*wall));
  wall->set_velocity(FixGRFLOWWall::HI, 0.0, 0.0, speed);
  wall->set_velocity(FixGRFLOWWall::LO, 0.0, 0.0, -speed);
}

// the box about its centre in x and y, the fix group remapped affinely
void FixGRFLOWCompress::scale_box()
{
  if (!servo.deforms()) return;
  double **x = atom->x;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) domain->x2lamda(x[i], x[i]);
  servo.scale(0, dt, domain->boxlo[0], domain->boxhi[0]);
  servo.scale(1, dt, domain->boxlo[1], domain->boxhi[1]);
  domain->set_global_box();
  domain->set_local_box();
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) domain->lamda2x(x[i], x[i]);
}

void FixGRFLOWCompress::reset_dt()
{
  dt = update->dt;
}

double FixGRFLOWCompress::compute_vector(int n)
{
  const double h = wall ? GRFLOW::wall_gap(*wall) : 0.0;
  return servo.output(n, settings, h, domain->xprd, domain->yprd, vsolid);
}

void FixGRFLOWCompress::write_restart(FILE *fp)
{
  double values[StressServo::NRESTART];
  servo.pack(values);
  GRFLOW::write_restart_values(lmp, fp, StressServo::RESTART_VERSION, values,
                               StressServo::NRESTART);
}

void FixGRFLOWCompress::restart(char *buf)
{
  int version;
  const std::string who = std::string("Fix grflow/compress ") + id;
  servo.unpack(GRFLOW::read_restart_values(lmp, who, buf, StressServo::RESTART_VERSION,
                                           StressServo::NRESTART, version));
}
