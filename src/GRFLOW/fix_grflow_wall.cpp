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

   Flat, frictional walls normal to z at the bottom (lo) and/or top (hi) of
   the box, interacting with spheres by the GRFLOW contact law with the
   wall as a sphere of infinite radius: a' = a_i, the wall does not spin.
   The walls move with velocities set by fix_modify (or by other GRFLOW
   fixes); their positions, velocities and displacements and the contact
   history go to restart files.

   The walls, the contacts, the argument rules, the output and the restart
   layout are host-free (GRFLOW::FlatWalls, src/shared/grflow_wall.h, the
   same code as in LIGGGHTS); this file is the LAMMPS glue: atoms,
   memory, neighbor settings, processors; numbers and errors through
   GRFLOW::FixHost (grflow_restart.h).
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
#include "pair.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace GRFLOW;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixGRFLOWWall::FixGRFLOWWall(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, needs_sphere_message());

  FixHost host{lmp};
  read_args(narg, arg, 3, host);
  if (domain->zperiodic) error->all(FLERR, periodic_message());

  // forces are sums over atoms (extensive), positions and displacements not
  vector_flag = 1;
  size_vector = NVECTOR;
  global_freq = 1;
  extvector = -1;
  extlist = new int[size_vector];
  for (int k = 0; k < size_vector; k++) extlist[k] = vector_extensive(k);
  energy_global_flag = 0;
  virial_global_flag = virial_peratom_flag = 1;
  thermo_virial = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  dynamic_group_allow = 0;

  dt = update->dt;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

/* ---------------------------------------------------------------------- */

FixGRFLOWWall::~FixGRFLOWWall()
{
  if (copymode) return;
  delete[] extlist;
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
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
  FixHost host{lmp};
  dt = update->dt;
  if (utils::strmatch(update->integrate_style, "^respa")) error->all(FLERR, respa_message());

  // the near list (FlatWalls::update_near()) needs the displacement bound
  // of "neigh_modify delay 0 every 1 check yes" and fixed radii
  allow_near(neighbor->every, neighbor->delay, neighbor->dist_check, neighbor->build_once,
             neighbor->skin, !modify->get_fix_by_style("^adapt").empty());

  // minimize calls no fix's post_force(), only min_post_force()
  if (update->whichflag == 2) host.warning(minimize_message(id));

  // the walls' normal force law is their own (as fix wall/gran's model is),
  // but another one than the particles' is more likely a slip than meant
  if (Pair *pair = force->pair_match("^granular/grflow", 0)) {
    int dim = -1;
    const int *law = static_cast<const int *>(pair->extract("normal_force", dim));
    if (law && dim == 0 && *law != normal_law())
      host.warning(fmt::format("Fix grflow/wall {}: the walls' normal_force {} is not the pair "
                               "style's normal_force {}",
                               id, normal_law_name(normal_law()), normal_law_name(*law)));
  }
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
  if (!move()) error->all(FLERR, top_reached_message(id));
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
  if (!message.empty()) error->all(FLERR, message);
}

/* ----------------------------------------------------------------------
   on the steps with a neighbor list build, before atoms move between ranks:
   an atom of the group that crossed a wall is an error here, not an atom
   lost by Comm::exchange() where the wall sits on a fixed box face (between
   builds post_force() finds it, the atom still being owned)
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
  FixHost host{lmp};
  error->one(FLERR, crossed_message(id, atom->tag[i], w, atom->x[i][2], host));
}

/* ---------------------------------------------------------------------- */

GRFLOW::WallSpheres FixGRFLOWWall::spheres() const
{
  return {atom->x,      atom->v,    atom->f,  atom->omega, atom->torque,
          atom->radius, atom->mask, groupbit, atom->nlocal};
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::post_force(int vflag)
{
  v_init(vflag);
  auto tally = [this](int i, double *vir) {
    v_tally(i, vir);
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

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::modify_param(int narg, char **arg)
{
  FixHost host{lmp};
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
  FixHost host{lmp};
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
  auto *ifix = lmp->modify->get_fix_by_id(id);
  if (!ifix) lmp->error->all(FLERR, cell_message(CELL_MISSING, caller, id));
  auto *wall = dynamic_cast<FixGRFLOWWall *>(ifix);
  if (!wall || strcmp(ifix->style, "grflow/wall") != 0)
    lmp->error->all(FLERR, cell_message(CELL_NOT_WALL, caller, id));
  if (!wall->both_walls()) lmp->error->all(FLERR, cell_message(CELL_ONE_WALL, caller, id));
  return wall;
}
