/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: fix grflow/wall (see fix_grflow_wall.h).

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).

   The LIGGGHTS glue of GRFLOW::FlatWalls (grflow_wall.h): atoms, memory,
   neighbor settings, processors, in the API of LIGGGHTS 3.8 (a 2013
   LAMMPS: v_setup/v_tally with a list of atoms, virial_flag for fix_modify
   virial, error->all with a message only); numbers and errors through
   GRFLOW::FixHost (grflow_restart.h), which names a bad parameter.
------------------------------------------------------------------------- */

#include "fix_grflow_wall.h"

#include "grflow_restart.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace GRFLOW;
using namespace FixConst;

namespace {

// the per-atom callbacks of LIGGGHTS's Atom (no names there)
enum { CALLBACK_GROW = 0, CALLBACK_RESTART = 1 };

}    // namespace

/* ---------------------------------------------------------------------- */

FixGRFLOWWall::FixGRFLOWWall(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  FixHost host = {lmp};
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag)
    host.fail(needs_sphere_message());

  read_args(narg, arg, 3, host);
  if (domain->zperiodic) host.fail(periodic_message());

  // forces are sums over atoms (extensive), positions and displacements not
  vector_flag = 1;
  size_vector = NVECTOR;
  global_freq = 1;
  extvector = -1;
  extlist = new int[size_vector];
  for (int k = 0; k < size_vector; k++) extlist[k] = vector_extensive(k);
  virial_flag = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  dynamic_group_allow = 0;

  dt = update->dt;

  grow_arrays(atom->nmax);
  atom->add_callback(CALLBACK_GROW);
  atom->add_callback(CALLBACK_RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

/* ---------------------------------------------------------------------- */

FixGRFLOWWall::~FixGRFLOWWall()
{
  delete[] extlist;
  atom->delete_callback(id, CALLBACK_GROW);
  atom->delete_callback(id, CALLBACK_RESTART);
  memory->destroy(history);
  memory->destroy(contact);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::setmask()
{
  return INITIAL_INTEGRATE | PRE_EXCHANGE | POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::init()
{
  FixHost host = {lmp};
  dt = update->dt;
  if (strstr(update->integrate_style, "respa")) host.fail(respa_message());

  // the near list (FlatWalls::update_near()) needs the displacement bound
  // of "neigh_modify delay 0 every 1 check yes" and fixed radii
  bool radii_vary = false;
  for (int k = 0; k < modify->nfix; k++)
    if (modify->fix[k]->rad_mass_vary_flag) radii_vary = true;
  allow_near(neighbor->every, neighbor->delay, neighbor->dist_check, neighbor->build_once,
             neighbor->skin, radii_vary);

  // minimize calls no fix's post_force(), only min_post_force()
  if (update->whichflag == 2) host.warning(minimize_message(id));
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::setup(int vflag)
{
  check_box();
  post_force(vflag);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::initial_integrate(int /*vflag*/)
{
  if (!move()) error->all(FLERR, top_reached_message(id).c_str());
  check_box();
}

/* ----------------------------------------------------------------------
   a wall beyond a fixed face of the box (boundary f in z): an error that
   names it, before atoms reach that face and are lost
------------------------------------------------------------------------- */

void FixGRFLOWWall::check_box()
{
  FixHost host{lmp};
  const std::string message =
      outside_box_message(id, domain->boxlo[2], domain->boxhi[2], domain->boundary[2][0] == 1,
                          domain->boundary[2][1] == 1, host);
  if (!message.empty()) error->all(FLERR, message.c_str());
}

/* ----------------------------------------------------------------------
   on the steps with a neighbor list build, before atoms move between
   ranks: an atom of the group that crossed a wall is an error here, not an
   atom lost in the exchange
------------------------------------------------------------------------- */

void FixGRFLOWWall::pre_exchange()
{
  int w = LO;
  const int i = find_crossing(spheres(), w);
  if (i >= 0) crossed(i, w);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::crossed(int i, int w)
{
  FixHost host = {lmp};
  const std::string message = crossed_message(id, atom->tag[i], w, atom->x[i][2], host);
  // LIGGGHTS's error->one() aborts without flushing the screen: where that
  // is a pipe, its message would be lost, so it goes out here first
  if (screen) {
    fprintf(screen, "ERROR on proc %d: %s\n", comm->me, message.c_str());
    fflush(screen);
  }
  if (logfile) {
    fprintf(logfile, "ERROR on proc %d: %s\n", comm->me, message.c_str());
    fflush(logfile);
  }
  error->one(FLERR, message.c_str());
}

/* ---------------------------------------------------------------------- */

GRFLOW::WallSpheres FixGRFLOWWall::spheres() const
{
  const WallSpheres s = {atom->x,      atom->v,    atom->f,  atom->omega, atom->torque,
                         atom->radius, atom->mask, groupbit, atom->nlocal};
  return s;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::post_force(int vflag)
{
  if (vflag && virial_flag)
    v_setup(vflag);
  else
    evflag = 0;
  auto tally = [this](int i, double *vir) {
    v_tally(1, &i, 1.0, vir);
  };
  int w = LO;
  const int i = contact_pass(spheres(), update->ntimestep, update->setupflag == 0, neighbor->ncalls,
                             neighbor->skin, evflag != 0, tally, w);
  if (i >= 0) crossed(i, w);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::reset_dt()
{
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWWall::compute_vector(int n)
{
  return vector_value(n, world);
}

/* ----------------------------------------------------------------------
   fix_modify: "virial yes|no" (LAMMPS's Fix does that one itself), then
   the walls' keywords
------------------------------------------------------------------------- */

int FixGRFLOWWall::modify_param(int narg, char **arg)
{
  FixHost host = {lmp};
  if (strcmp(arg[0], "virial") == 0) {
    if (narg < 2) host.missing(std::string("fix_modify ") + id + " virial");
    if (strcmp(arg[1], "yes") == 0)
      virial_flag = 1;
    else if (strcmp(arg[1], "no") == 0)
      virial_flag = 0;
    else
      host.fail(std::string("fix_modify ") + id + " virial: expected yes or no, got " + arg[1]);
    return 2;
  }
  return modify_wall_param(narg, arg, id, host);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::write_restart(FILE *fp)
{
  double list[NRESTART];
  pack_state(list);
  write_restart_values(lmp, fp, RESTART_VERSION, list, NRESTART);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::restart(char *buf)
{
  FixHost host = {lmp};
  restore_state(buf, id, host);
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWWall::memory_usage()
{
  return (double) atom->nmax * (NHIST + NCONTACT) * sizeof(double);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::grow_arrays(int nmax)
{
  memory->grow(history, nmax, NHIST, "grflow/wall:history");
  memory->grow(contact, nmax, NCONTACT, "grflow/wall:contact");
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::copy_arrays(int i, int j, int /*delflag*/)
{
  copy_atom(i, j);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::set_arrays(int i)
{
  clear_atom(i);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::pack_exchange(int i, double *buf)
{
  return pack_atom(i, buf);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::unpack_exchange(int nlocal, double *buf)
{
  return unpack_atom(nlocal, buf);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::pack_restart(int i, double *buf)
{
  return pack_atom_restart(i, buf);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::unpack_restart(int nlocal, int nth)
{
  unpack_atom_restart(nlocal, atom->extra[nlocal], nth);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::size_restart(int /*nlocal*/)
{
  return NRESTART_ATOM;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::maxsize_restart()
{
  return NRESTART_ATOM;
}

/* ---------------------------------------------------------------------- */

FixGRFLOWWall *FixGRFLOWWall::find_cell(LAMMPS *lmp, const std::string &caller, const char *id)
{
  FixHost host = {lmp};
  const int ifix = lmp->modify->find_fix(id);
  if (ifix < 0) host.fail(cell_message(CELL_MISSING, caller, id));
  Fix *fix = lmp->modify->fix[ifix];
  FixGRFLOWWall *wall = dynamic_cast<FixGRFLOWWall *>(fix);
  if (!wall || strcmp(fix->style, "grflow/wall") != 0)
    host.fail(cell_message(CELL_NOT_WALL, caller, id));
  if (!wall->both_walls()) host.fail(cell_message(CELL_ONE_WALL, caller, id));
  return wall;
}
