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
   history go to restart files.  The contact records of the owned atoms
   are the fix's per-atom array, and other commands (compute
   grflow/network) read them through extract("grflow/wall_contacts").

   The walls, the contact pass, the argument rules, the output and the
   restart layout are host-free (src/shared/grflow_wall*.h); this class
   connects them to the host.  It is compiled into LAMMPS and into
   GRFLOW's LIGGGHTS build alike (grflow_host_api.h).
------------------------------------------------------------------------- */

#include "fix_grflow_wall.h"

#include "grflow_host_api.h"
#include "grflow_wall.h"
#include "grflow_wall_args.h"
#include "grflow_wall_near.h"
#include "grflow_wall_pass.h"
#include "grflow_wall_state.h"

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

/* ---------------------------------------------------------------------- */

FixGRFLOWWall::FixGRFLOWWall(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), walls(nullptr), near(nullptr)
{
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR,
               "Fix grflow/wall requires atom attributes radius, omega and torque "
               "(atom_style sphere)");

  walls = new FlatWalls;
  near = new WallNearList;
  FixHost host{lmp};
  read_wall_args(*walls, narg, arg, 3, host);
  if (domain->zperiodic) error->all(FLERR, "Fix grflow/wall needs a non-periodic z boundary");

  // forces are sums over atoms (extensive), positions and displacements not
  vector_flag = 1;
  size_vector = FlatWalls::NVECTOR;
  global_freq = 1;
  extvector = -1;
  extlist = new int[size_vector];
  for (int k = 0; k < size_vector; k++) extlist[k] = wall_vector_extensive(k);
  // the contact records: per wall the arm a - delta/2 of a force-bearing
  // contact (<= 0 for none) and the force on the atom
  peratom_flag = 1;
  size_peratom_cols = FlatWalls::NCONTACT;
  peratom_freq = 1;
  declare_virial(this);
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  dynamic_group_allow = 0;

  walls->dt = update->dt;

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
  memory->destroy(walls->history);
  memory->destroy(walls->contact);
  delete near;
  delete walls;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::setmask()
{
  return INITIAL_INTEGRATE | PRE_EXCHANGE | POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::init()
{
  walls->dt = update->dt;
  if (strncmp(update->integrate_style, "respa", 5) == 0)
    error->all(FLERR, "Fix grflow/wall does not support run_style respa");

  // the near list (grflow_wall_near.h) needs the displacement bound of
  // "neigh_modify delay 0 every 1 check yes" and fixed radii
  near->allow(neighbor->every, neighbor->delay, neighbor->dist_check, neighbor->build_once,
              neighbor->skin, radii_may_change(lmp));

  // minimize calls no fix's post_force(), only min_post_force()
  if (update->whichflag == 2 && comm->me == 0)
    error->warning(FLERR,
                   std::string("Fix grflow/wall ") + id +
                       ": the walls do not act during a minimization; atoms can cross them (and "
                       "be lost where a wall sits on a box face)");

  // the walls' normal force law is their own (as fix wall/gran's model is),
  // but another one than the particles' is more likely a slip than meant
  const int law = pair_normal_law(lmp);
  if (law >= 0 && law != walls->normal_law() && comm->me == 0)
    error->warning(FLERR,
                   std::string("Fix grflow/wall ") + id + ": the walls' normal_force " +
                       normal_law_name(walls->normal_law()) +
                       " is not the pair style's normal_force " + normal_law_name(law));
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
  if (!walls->move())
    error->all(FLERR,
               std::string("Fix grflow/wall ") + id + ": the top wall has reached the bottom wall");
  check_box();
}

/* ----------------------------------------------------------------------
   a wall beyond a fixed face of the box (boundary f in z): atoms that
   reach that face leave the box (the host's "Lost atoms") before they can
   touch the wall, so this is an error that names it
------------------------------------------------------------------------- */

void FixGRFLOWWall::check_box()
{
  FixHost host{lmp};
  for (int iw = 0; iw < FlatWalls::NWALL; iw++) {
    const FlatWalls::Wall &wall = walls->wall(iw);
    if (!wall.active) continue;
    const bool below =
        (iw == FlatWalls::LO) && domain->boundary[2][0] == 1 && wall.z < domain->boxlo[2];
    const bool above =
        (iw == FlatWalls::HI) && domain->boundary[2][1] == 1 && wall.z > domain->boxhi[2];
    if (below || above)
      error->all(FLERR,
                 std::string("Fix grflow/wall ") + id + ": the " + FlatWalls::wall_name(iw) +
                     " wall (z = " + host.text(wall.z) + ") is outside the box's fixed " +
                     (below ? "lower face (z = " + host.text(domain->boxlo[2])
                            : "upper face (z = " + host.text(domain->boxhi[2])) +
                     "): atoms would leave the box there before they reach the wall; move the "
                     "wall inside the box or use boundary s or m in z");
  }
}

/* ----------------------------------------------------------------------
   on the steps with a neighbor list build, before atoms move between ranks:
   an atom of the group that crossed a wall is an error here, not an atom
   lost by Comm::exchange() where the wall sits on a fixed box face (between
   builds post_force() finds it, the atom still being owned)
------------------------------------------------------------------------- */

void FixGRFLOWWall::pre_exchange()
{
  const WallSpheres s = {atom->x,      atom->v,    atom->f,  atom->omega, atom->torque,
                         atom->radius, atom->mask, groupbit, atom->nlocal};
  int w = FlatWalls::LO;
  const int i = walls->find_crossing(s, w);
  if (i >= 0) crossed(i, w);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::crossed(int i, int w)
{
  FixHost host{lmp};
  error->one(FLERR,
             std::string("Fix grflow/wall ") + id + ": atom " + std::to_string(atom->tag[i]) +
                 " crossed the " + FlatWalls::wall_name(w) + " wall (z = " +
                 host.text(atom->x[i][2]) + ", wall at " + host.text(walls->wall(w).z) + ")");
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::post_force(int vflag)
{
  v_init(vflag);
  auto tally = [this](int i, double *vir) {
    v_tally(i, vir);
  };
  const WallSpheres s = {atom->x,      atom->v,    atom->f,  atom->omega, atom->torque,
                         atom->radius, atom->mask, groupbit, atom->nlocal};
  int w = FlatWalls::LO;
  const int i = wall_contact_pass(*walls, *near, s, update->ntimestep, update->setupflag == 0,
                                  neighbor->ncalls, neighbor->skin, evflag != 0, tally, w);
  if (i >= 0) crossed(i, w);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::reset_dt()
{
  walls->dt = update->dt;
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWWall::compute_vector(int n)
{
  return wall_vector_value(*walls, n, world);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::modify_param(int narg, char **arg)
{
  const int n = host_modify_param(lmp, this, narg, arg);
  if (n > 0) return n;
  FixHost host{lmp};
  return modify_wall_param(*walls, narg, arg, id, host);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::write_restart(FILE *fp)
{
  double list[FlatWalls::NRESTART];
  pack_wall_state(*walls, list);
  write_restart_values(lmp, fp, FlatWalls::RESTART_VERSION, list, FlatWalls::NRESTART);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::restart(char *buf)
{
  FixHost host{lmp};
  restore_wall_state(*walls, buf, id, host);
}

/* ----------------------------------------------------------------------
   "grflow/wall_contacts": the contact records of this step
   (GRFLOW::WallContacts, grflow_wall.h), for compute grflow/network
------------------------------------------------------------------------- */

void *FixGRFLOWWall::extract(const char *name, int &dim)
{
  if (strcmp(name, "grflow/wall_contacts") == 0) {
    dim = 0;
    return (void *) &walls->contacts();
  }
  return nullptr;
}

/* ---------------------------------------------------------------------- */

double FixGRFLOWWall::memory_usage()
{
  return (double) atom->nmax * (FlatWalls::NHIST + FlatWalls::NCONTACT) * sizeof(double);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::grow_arrays(int nmax)
{
  memory->grow(walls->history, nmax, FlatWalls::NHIST, "grflow/wall:history");
  memory->grow(walls->contact, nmax, FlatWalls::NCONTACT, "grflow/wall:contact");
  array_atom = walls->contact;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::copy_arrays(int i, int j, int /*delflag*/)
{
  copy_wall_atom(*walls, i, j);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::set_arrays(int i)
{
  clear_wall_atom(*walls, i);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::pack_exchange(int i, double *buf)
{
  return pack_wall_atom(*walls, i, buf);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::unpack_exchange(int nlocal, double *buf)
{
  return unpack_wall_atom(*walls, nlocal, buf);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::pack_restart(int i, double *buf)
{
  return pack_wall_atom_restart(*walls, i, buf);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::unpack_restart(int nlocal, int nth)
{
  unpack_wall_atom_restart(*walls, nlocal, atom->extra[nlocal], nth);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::size_restart(int /*nlocal*/)
{
  return FlatWalls::NRESTART_ATOM;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::maxsize_restart()
{
  return FlatWalls::NRESTART_ATOM;
}

/* ---------------------------------------------------------------------- */

FixGRFLOWWall *FixGRFLOWWall::find_cell(LAMMPS *lmp, const std::string &caller,
                                        const std::string &id)
{
  Fix *ifix = fix_by_id(lmp, id);
  const std::string head = caller + ": fix " + id;
  if (!ifix) lmp->error->all(FLERR, head + " does not exist");
  auto *wall = dynamic_cast<FixGRFLOWWall *>(ifix);
  if (!wall || strcmp(ifix->style, "grflow/wall") != 0)
    lmp->error->all(FLERR, head + " is not a fix grflow/wall");
  if (!wall->walls->both_walls())
    lmp->error->all(FLERR, head + " must have both walls, zlo and zhi");
  return wall;
}
