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
------------------------------------------------------------------------- */

#include "fix_grflow_wall.h"

#include "grflow_contact.h"
#include "grflow_restart.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace GRFLOW;
using namespace FixConst;

static constexpr int NHIST = FixGRFLOWWall::NWALL * HIST_SIZE;
static constexpr int NCONTACT = FixGRFLOWWall::NWALL * 4;
static constexpr int NVECTOR = 6;    // per wall: Fx Fy Fz z dx dy
// global restart data: per wall active, z, v (3), displacement (2)
static constexpr int NRESTART = FixGRFLOWWall::NWALL * 7;
static constexpr int RESTART_VERSION = 1;

/* ---------------------------------------------------------------------- */

FixGRFLOWWall::FixGRFLOWWall(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), history(nullptr), contact(nullptr), contact_step(-1), near(nullptr),
    nnear(0), maxnear(0), near_allowed(false), near_ncalls(-1), near_nlocal(-1)
{
  near_z[LO] = near_z[HI] = 0.0;
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR,
               "Fix grflow/wall requires atom attributes radius, omega and torque "
               "(atom_style sphere)");

  int iarg = parse_coeffs(lmp, "fix grflow/wall", narg, arg, 3, true, coeff_value);
  pack_coeffs(coeff_value, coeff);

  full_arm = 0;
  for (auto &w : walls) {
    w.active = 0;
    w.z = 0.0;
    w.v[0] = w.v[1] = w.v[2] = 0.0;
    w.disp[0] = w.disp[1] = 0.0;
    w.force[0] = w.force[1] = w.force[2] = 0.0;
  }

  while (iarg < narg) {
    const std::string kw = arg[iarg];
    if (kw == "zlo" || kw == "zhi") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix grflow/wall " + kw, error);
      Wall &w = walls[kw == "zlo" ? LO : HI];
      w.active = 1;
      w.z = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
    } else if (kw == "velocity_arm") {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "fix grflow/wall velocity_arm", error);
      full_arm = parse_velocity_arm(lmp, "fix grflow/wall", arg[iarg + 1]);
      iarg += 2;
    } else {
      for (const char *name : COEFF_NAMES)
        if (kw == name || kw == "rolling" || kw == "torsion")
          error->all(FLERR,
                     "Fix grflow/wall contact keyword {} must come right after kn cn, "
                     "before zlo, zhi and velocity_arm",
                     kw);
      error->all(FLERR, "Unknown fix grflow/wall keyword: {}", kw);
    }
  }
  if (!walls[LO].active && !walls[HI].active)
    error->all(FLERR, "Fix grflow/wall needs a wall: zlo and/or zhi");
  if (walls[LO].active && walls[HI].active && walls[HI].z <= walls[LO].z)
    error->all(FLERR, "Fix grflow/wall zhi {} must be above zlo {}", walls[HI].z, walls[LO].z);
  if (domain->zperiodic) error->all(FLERR, "Fix grflow/wall needs a non-periodic z boundary");

  // forces are sums over atoms (extensive), positions and displacements not
  vector_flag = 1;
  size_vector = NWALL * NVECTOR;
  global_freq = 1;
  extvector = -1;
  extlist = new int[size_vector];
  for (int k = 0; k < size_vector; k++) extlist[k] = (k % NVECTOR < 3) ? 1 : 0;
  energy_global_flag = 0;
  virial_global_flag = virial_peratom_flag = 1;
  thermo_virial = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  dynamic_group_allow = 0;

  force_flag = 0;
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
  memory->destroy(near);
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::setmask()
{
  return INITIAL_INTEGRATE | PRE_EXCHANGE | POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::init()
{
  dt = update->dt;
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix grflow/wall does not support run_style respa");

  // the near list (update_near()) needs the displacement bound of
  // "neigh_modify delay 0 every 1 check yes" and fixed radii
  near_allowed = (neighbor->every == 1) && (neighbor->delay == 0) && neighbor->dist_check &&
      !neighbor->build_once && (neighbor->skin > 0.0) && modify->get_fix_by_style("^adapt").empty();
  near_ncalls = -1;

  // minimize calls no fix's post_force(), only min_post_force()
  if (update->whichflag == 2 && comm->me == 0)
    error->warning(FLERR,
                   "Fix grflow/wall {}: the walls do not act during a minimization; atoms can "
                   "cross them (and be lost where a wall sits on a box face)",
                   id);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::setup(int vflag)
{
  post_force(vflag);
}

/* ----------------------------------------------------------------------
   move the walls with their velocities, as the atoms move
------------------------------------------------------------------------- */

void FixGRFLOWWall::initial_integrate(int /*vflag*/)
{
  for (auto &w : walls) {
    if (!w.active) continue;
    w.z += dt * w.v[2];
    w.disp[0] += dt * w.v[0];
    w.disp[1] += dt * w.v[1];
  }
  if (walls[LO].active && walls[HI].active && walls[HI].z <= walls[LO].z)
    error->all(FLERR, "Fix grflow/wall {}: the top wall has reached the bottom wall", id);
}

/* ----------------------------------------------------------------------
   on the steps with a neighbor list build, before atoms move between ranks:
   an atom of the group that crossed a wall is an error here, not an atom
   lost by Comm::exchange() where the wall sits on a fixed box face (between
   builds post_force() finds it, the atom still being owned)
------------------------------------------------------------------------- */

void FixGRFLOWWall::pre_exchange()
{
  double **x = atom->x;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  for (int iw = 0; iw < NWALL; iw++) {
    const Wall &w = walls[iw];
    if (!w.active) continue;
    const double sign = normal_sign(iw);
    for (int i = 0; i < nlocal; i++)
      if ((mask[i] & groupbit) && sign * (x[i][2] - w.z) <= 0.0) crossed(iw, tag[i], x[i][2]);
  }
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::crossed(int iw, tagint itag, double z)
{
  error->one(FLERR, "Fix grflow/wall {}: atom {} crossed the {} wall (z = {}, wall at {})", id,
             itag, iw == LO ? "zlo" : "zhi", z, walls[iw].z);
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::post_force(int vflag)
{
  v_init(vflag);
  force_flag = 0;

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  double **omega = atom->omega;
  double **torque = atom->torque;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const bool update_history = (update->setupflag == 0);
  const double wzero[3] = {0.0, 0.0, 0.0};

  for (auto &w : walls) w.force[0] = w.force[1] = w.force[2] = 0.0;
  contact_step = update->ntimestep;

  // contact[i][4 w]: the arm of a force-bearing contact of atom i with wall
  // w on this step, -1 for a touching one without force, 0 for none (and
  // -1 after an atom came from another rank or a restart file: unknown).
  // An atom farther than its radius from every wall touches none; for it
  // only its arms are cleared, and a wall's history only if the atom
  // touched that wall on the step before (the contact just ended).  Most
  // atoms are such atoms on most steps.
  //
  // Between neighbor list builds only the atoms of the near list can touch
  // a wall (see update_near()); the others were cleared when it was made.
  const bool lo_on = walls[LO].active, hi_on = walls[HI].active;
  const double zlo = walls[LO].z, zhi = walls[HI].z;
  const bool use_near = update_near();
  const int nloop = use_near ? nnear : nlocal;
  for (int ii = 0; ii < nloop; ii++) {
    const int i = use_near ? near[ii] : ii;
    double *ci = contact[i];
    const double rad = radius[i];
    const double z = x[i][2];
    if (!(mask[i] & groupbit) || ((!lo_on || z - zlo >= rad) && (!hi_on || zhi - z >= rad))) {
      for (int iw = 0; iw < NWALL; iw++)
        if (ci[4 * iw] != 0.0) {
          ci[4 * iw] = 0.0;
          for (int k = 0; k < HIST_SIZE; k++) history[i][iw * HIST_SIZE + k] = 0.0;
        }
      continue;
    }

    for (int iw = 0; iw < NWALL; iw++) {
      Wall &w = walls[iw];
      if (!w.active) continue;
      double *hist = &history[i][iw * HIST_SIZE];
      const bool was_touching = (ci[4 * iw] != 0.0);
      ci[4 * iw] = 0.0;
      const double sign = normal_sign(iw);
      const double gap = sign * (z - w.z);    // centre to wall, along n
      if (gap <= 0.0) crossed(iw, tag[i], z);
      if (gap >= rad) {
        if (was_touching)
          for (int k = 0; k < HIST_SIZE; k++) hist[k] = 0.0;
        continue;
      }

      ContactGeometry g;
      wall_geometry(gap, rad, sign, full_arm != 0, g);
      const double vrel[3] = {v[i][0] - w.v[0], v[i][1] - w.v[1], v[i][2] - w.v[2]};
      ContactForces out;
      contact_forces(coeff, g, vrel, omega[i], wzero, dt, update_history, hist, out);

      for (int k = 0; k < 3; k++) {
        f[i][k] += out.f[k];
        torque[i][k] += out.torque_i[k];
        w.force[k] -= out.f[k];
      }
      if (out.fn > 0.0) {
        ci[4 * iw] = g.arm_i;
        for (int k = 0; k < 3; k++) ci[4 * iw + 1 + k] = out.f[k];
      } else {
        ci[4 * iw] = -1.0;
      }

      // virial of the contact, branch vector from the contact point to the
      // centre: l = arm n; symmetrized, as the 6-component virial is
      if (evflag) {
        const double l = g.arm_i * sign;
        double vir[6];
        vir[0] = vir[1] = vir[3] = 0.0;
        vir[2] = l * out.f[2];
        vir[4] = 0.5 * l * out.f[0];
        vir[5] = 0.5 * l * out.f[1];
        v_tally(i, vir);
      }
    }
  }
}

/* ----------------------------------------------------------------------
   the near list: the atoms of the group that may touch a wall before the
   next neighbor list build.  With "neigh_modify delay 0 every 1 check
   yes" every atom stays within skin/2 of where it was at the last build;
   the list is made again, on the step of each build or when a wall has
   moved more than skin/2 since, with the atoms whose centre was then
   closer to an active wall than their radius plus 1.5 skins.  An atom
   left out is therefore farther from every wall than its radius plus
   skin/2 (a margin for round-off) until the list is made again: it cannot touch one, and its arms and histories were
   cleared (by the full pass of post_force() on the step the list is made).
   Returns false (full pass over all atoms) on the steps the list is made,
   and always with other neighbor settings, a fix adapt (radii may grow)
   or a zero skin.
------------------------------------------------------------------------- */

bool FixGRFLOWWall::update_near()
{
  if (!near_allowed) return false;
  const double half_skin = 0.5 * neighbor->skin;
  bool fresh = (neighbor->ncalls == near_ncalls) && (atom->nlocal == near_nlocal);
  for (int iw = 0; iw < NWALL; iw++)
    if (walls[iw].active && fabs(walls[iw].z - near_z[iw]) > half_skin) fresh = false;
  if (fresh) return true;

  // make the list; this step's post_force() does the full pass
  const int nlocal = atom->nlocal;
  if (nlocal > maxnear) {
    memory->destroy(near);
    maxnear = atom->nmax;
    memory->create(near, maxnear, "grflow/wall:near");
  }
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  const double skin = neighbor->skin;
  nnear = 0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double reach = radius[i] + 1.5 * skin;
    const double z = x[i][2];
    if ((walls[LO].active && z - walls[LO].z < reach) ||
        (walls[HI].active && walls[HI].z - z < reach))
      near[nnear++] = i;
  }
  near_ncalls = neighbor->ncalls;
  near_nlocal = nlocal;
  for (int iw = 0; iw < NWALL; iw++) near_z[iw] = walls[iw].z;
  return false;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::reset_dt()
{
  dt = update->dt;
}

/* ----------------------------------------------------------------------
   per wall (lo, then hi): force of the particles on it (3), z, x and y
   displacement since the fix was defined
------------------------------------------------------------------------- */

double FixGRFLOWWall::compute_vector(int n)
{
  if (force_flag == 0) {
    double local[NWALL * 3], total[NWALL * 3];
    for (int iw = 0; iw < NWALL; iw++)
      for (int k = 0; k < 3; k++) local[3 * iw + k] = walls[iw].force[k];
    MPI_Allreduce(local, total, NWALL * 3, MPI_DOUBLE, MPI_SUM, world);
    for (int iw = 0; iw < NWALL; iw++)
      for (int k = 0; k < 3; k++) wall_force_all[iw][k] = total[3 * iw + k];
    force_flag = 1;
  }
  const int iw = n / NVECTOR, k = n % NVECTOR;
  const Wall &w = walls[iw];
  if (k < 3) return wall_force_all[iw][k];
  if (k == 3) return w.active ? w.z : 0.0;
  return w.disp[k - 4];
}

/* ----------------------------------------------------------------------
   fix_modify ID wall lo|hi vel vx vy vz
   fix_modify ID wall lo|hi z value
------------------------------------------------------------------------- */

int FixGRFLOWWall::modify_param(int narg, char **arg)
{
  // a contact coefficient, e.g. the friction between stages; the contact
  // histories are kept
  for (int k = 0; k < NCOEFF; k++) {
    if (strcmp(arg[0], COEFF_NAMES[k]) != 0) continue;
    if (narg < 2)
      utils::missing_cmd_args(FLERR, fmt::format("fix_modify {} {}", id, arg[0]), error);
    double value[NCOEFF];
    for (int m = 0; m < NCOEFF; m++) value[m] = coeff_value[m];
    value[k] = utils::numeric(FLERR, arg[1], false, lmp);
    check_coeffs(lmp, fmt::format("fix_modify {}", id), value);
    coeff_value[k] = value[k];
    pack_coeffs(coeff_value, coeff);
    return 2;
  }
  if (strcmp(arg[0], "wall") != 0) return 0;
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix_modify grflow/wall wall", error);
  int iw;
  if (strcmp(arg[1], "lo") == 0)
    iw = LO;
  else if (strcmp(arg[1], "hi") == 0)
    iw = HI;
  else
    error->all(FLERR, "fix_modify {} wall: expected lo or hi, got {}", id, arg[1]);
  Wall &w = walls[iw];
  if (!w.active) error->all(FLERR, "fix_modify {} wall {}: this fix has no such wall", id, arg[1]);
  if (strcmp(arg[2], "vel") == 0) {
    if (narg < 6) utils::missing_cmd_args(FLERR, "fix_modify grflow/wall wall vel", error);
    for (int k = 0; k < 3; k++) w.v[k] = utils::numeric(FLERR, arg[3 + k], false, lmp);
    return 6;
  }
  if (strcmp(arg[2], "z") == 0) {
    w.z = utils::numeric(FLERR, arg[3], false, lmp);
    if (walls[LO].active && walls[HI].active && walls[HI].z <= walls[LO].z)
      error->all(FLERR, "fix_modify {}: zhi {} must be above zlo {}", id, walls[HI].z, walls[LO].z);
    return 4;
  }
  error->all(FLERR, "fix_modify {} wall {}: expected vel or z, got {}", id, arg[1], arg[2]);
  return 0;
}

/* ----------------------------------------------------------------------
   wall state for restart files: active, z, v, displacement per wall
------------------------------------------------------------------------- */

void FixGRFLOWWall::write_restart(FILE *fp)
{
  double list[NRESTART];
  int n = 0;
  for (const auto &w : walls) {
    list[n++] = w.active;
    list[n++] = w.z;
    for (int k = 0; k < 3; k++) list[n++] = w.v[k];
    list[n++] = w.disp[0];
    list[n++] = w.disp[1];
  }
  write_restart_values(lmp, fp, RESTART_VERSION, list, NRESTART);
}

/* ----------------------------------------------------------------------
   format 1: the header of grflow_restart.h, then the values of
   write_restart(); format 0 (files written before the header): the same
   values without it
------------------------------------------------------------------------- */

void FixGRFLOWWall::restart(char *buf)
{
  int version;
  const double *list = read_restart_values(lmp, fmt::format("Fix grflow/wall {}", id), buf,
                                           RESTART_VERSION, NRESTART, version);
  int n = 0;
  for (auto &w : walls) {
    const int active = (int) list[n++];
    if (active != w.active)
      error->all(FLERR, "Fix grflow/wall {}: restart file has other walls than the command", id);
    w.z = list[n++];
    for (int k = 0; k < 3; k++) w.v[k] = list[n++];
    w.disp[0] = list[n++];
    w.disp[1] = list[n++];
  }
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
  for (int m = 0; m < NHIST; m++) history[j][m] = history[i][m];
  for (int m = 0; m < NCONTACT; m++) contact[j][m] = contact[i][m];
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::set_arrays(int i)
{
  for (int m = 0; m < NHIST; m++) history[i][m] = 0.0;
  for (int m = 0; m < NCONTACT; m++) contact[i][m] = 0.0;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::pack_exchange(int i, double *buf)
{
  for (int m = 0; m < NHIST; m++) buf[m] = history[i][m];
  return NHIST;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::unpack_exchange(int nlocal, double *buf)
{
  for (int m = 0; m < NHIST; m++) history[nlocal][m] = buf[m];
  mark_unknown(nlocal);
  return NHIST;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::pack_restart(int i, double *buf)
{
  // buf[0] is the count, as other fixes read it
  buf[0] = NHIST + 1;
  for (int m = 0; m < NHIST; m++) buf[m + 1] = history[i][m];
  return NHIST + 1;
}

/* ---------------------------------------------------------------------- */

void FixGRFLOWWall::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < NHIST; k++) history[nlocal][k] = extra[nlocal][m++];
  mark_unknown(nlocal);
}

/* ----------------------------------------------------------------------
   an atom whose wall histories came from elsewhere: no force-bearing
   contact on record, but the next post_force() clears a history of a
   wall it does not touch
------------------------------------------------------------------------- */

void FixGRFLOWWall::mark_unknown(int i)
{
  for (int m = 0; m < NCONTACT; m++) contact[i][m] = 0.0;
  for (int w = 0; w < NWALL; w++)
    if (walls[w].active) contact[i][4 * w] = -1.0;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::size_restart(int /*nlocal*/)
{
  return NHIST + 1;
}

/* ---------------------------------------------------------------------- */

int FixGRFLOWWall::maxsize_restart()
{
  return NHIST + 1;
}

/* ---------------------------------------------------------------------- */

FixGRFLOWWall *FixGRFLOWWall::find_cell(LAMMPS *lmp, const std::string &caller, const char *id)
{
  auto *ifix = lmp->modify->get_fix_by_id(id);
  if (!ifix) lmp->error->all(FLERR, "{}: fix {} does not exist", caller, id);
  auto *wall = dynamic_cast<FixGRFLOWWall *>(ifix);
  if (!wall || strcmp(ifix->style, "grflow/wall") != 0)
    lmp->error->all(FLERR, "{}: fix {} is not a fix grflow/wall", caller, id);
  if (!wall->walls[LO].active || !wall->walls[HI].active)
    lmp->error->all(FLERR, "{}: fix {} must have both walls, zlo and zhi", caller, id);
  return wall;
}
