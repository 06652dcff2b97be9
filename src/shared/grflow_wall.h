/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   The host-free part of fix grflow/wall (doc/fix_grflow_wall.rst), shared
   by its LAMMPS adapter (src/GRFLOW/fix_grflow_wall.*) and its LIGGGHTS
   adapter (src/LIGGGHTS/fix_grflow_wall.*): flat walls normal to z, their
   motion, the contact of each sphere with them through the kernel of
   grflow_contact.h, the per-atom contact history and contact record, the
   near list, the output vector, fix_modify, the restart layout, the
   argument rules and the error messages.  Both hosts' FixGRFLOWWall derive
   from FlatWalls, so that their public interface (wall(), set_velocity(),
   contact_arm(), ..., LO/HI/NWALL, Wall) is this one.

   Header only, no host types: the hosts give plain arrays (x, v, f, ...)
   and allocate the per-atom arrays; they parse numbers and report errors
   through a Host object (grflow_host.h).
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_WALL_H
#define LMP_GRFLOW_WALL_H

#include "grflow_contact.h"
#include "grflow_host.h"

#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace GRFLOW {

  /* ----------------------------------------------------------------------
     the particles' view that the walls need: the host's per-atom arrays
     of the owned atoms
  ------------------------------------------------------------------------- */

  struct WallSpheres {
    double **x, **v, **f, **omega, **torque;
    const double *radius;
    const int *mask;
    int groupbit;
    int nlocal;
  };

  /* ----------------------------------------------------------------------
     the walls of one fix grflow/wall and everything about them that is
     not the host's
  ------------------------------------------------------------------------- */

  class FlatWalls {
   public:
    enum { LO, HI, NWALL };

    // a flat wall normal to z: "lo" pushes up (+z), "hi" pushes down (-z)
    struct Wall {
      int active;
      double z;           // position
      double v[3];        // velocity
      double disp[2];     // accumulated x, y displacement
      double force[3];    // force of the particles on the wall, this step
    };

    // per atom: the kernel's history (HIST_SIZE values) per wall, and the
    // contact record per wall: the arm (a - delta/2) of a force-bearing
    // contact (f_n > 0), -1 for a touching one without force (or, with the
    // unclipped law, in tension: f_n <= 0) or one not known (the
    // atom came from another rank or a restart file), 0 for none; then
    // the force on the atom (3)
    enum { NHIST = NWALL * HIST_SIZE };
    enum { REC_ARM = 0, REC_FORCE = 1, REC_SIZE = 4, NCONTACT = NWALL * REC_SIZE };

    // the output vector (compute_vector), per wall (lo, then hi): force of
    // the particles on it (3), position, x and y displacement since the
    // fix was defined
    enum { VEC_FX, VEC_FY, VEC_FZ, VEC_Z, VEC_DX, VEC_DY, VEC_PER_WALL };
    enum { NVECTOR = NWALL * VEC_PER_WALL };

    // restart data: global (the block above) per wall active, z, v (3),
    // displacement (2), format RESTART_VERSION; per atom the count, as
    // other fixes read it, then the histories
    enum { RESTART_VERSION = 1, RESTART_PER_WALL = 7, NRESTART = NWALL * RESTART_PER_WALL };
    enum { NRESTART_ATOM = NHIST + 1 };

    FlatWalls() :
        full_arm(0), dt(0.0), force_flag(0), history(nullptr), contact(nullptr), contact_step(-1),
        near_allowed(false), nnear(0), near_ncalls(-1), near_nlocal(-1)
    {
      for (int w = 0; w < NWALL; w++) {
        Wall &wall = walls[w];
        wall.active = 0;
        wall.z = 0.0;
        wall.v[0] = wall.v[1] = wall.v[2] = 0.0;
        wall.disp[0] = wall.disp[1] = 0.0;
        wall.force[0] = wall.force[1] = wall.force[2] = 0.0;
        wall_force_all[w][0] = wall_force_all[w][1] = wall_force_all[w][2] = 0.0;
        near_z[w] = 0.0;
      }
      for (int k = 0; k < NCOEFF; k++) coeff_value[k] = 0.0;
      pack_coeffs(coeff_value, coeff);
    }

    const Wall &wall(int w) const { return walls[w]; }
    void set_velocity(int w, double vx, double vy, double vz)
    {
      walls[w].v[0] = vx;
      walls[w].v[1] = vy;
      walls[w].v[2] = vz;
    }

    // the normal force law of the walls (normal_force keyword)
    int normal_law() const { return coeff.normal_law; }

    // contact of atom i with wall w on this step: arm (a - delta/2; <= 0 if
    // no force-bearing contact) and force on the atom (set only where the
    // arm is > 0); for compute grflow/network
    double contact_arm(int i, int w) const { return contact[i][REC_SIZE * w + REC_ARM]; }
    const double *contact_force(int i, int w) const
    {
      return &contact[i][REC_SIZE * w + REC_FORCE];
    }
    double normal_sign(int w) const { return w == LO ? 1.0 : -1.0; }
    // the step of those contacts (-1 before the first run's setup)
    int64_t contacts_step() const { return contact_step; }

    bool both_walls() const { return walls[LO].active && walls[HI].active; }
    static const char *wall_name(int w) { return w == LO ? "zlo" : "zhi"; }

    /* --------------------------------------------------------------------
       the fix command's arguments after "fix ID group grflow/wall":
       kn cn [coefficient keywords] then zlo z, zhi z, velocity_arm
       reduced|full, normal_force clipped|unclipped in any order.  Returns
       the index after the last one.
    ------------------------------------------------------------------------- */

    template <class Host> int read_args(int narg, char **arg, int first, Host &host)
    {
      const std::string cmd = "fix grflow/wall";
      int iarg = read_coeff_args(cmd, narg, arg, first, true, coeff_value, host);
      pack_coeffs(coeff_value, coeff);

      while (iarg < narg) {
        const std::string kw = arg[iarg];
        if (kw == "zlo" || kw == "zhi") {
          if (iarg + 2 > narg) {
            host.missing(cmd + " " + kw);
            return narg;
          }
          Wall &w = walls[kw == "zlo" ? LO : HI];
          w.active = 1;
          w.z = host.number(arg[iarg + 1], cmd + " " + kw);
          iarg += 2;
        } else if (kw == "velocity_arm") {
          if (iarg + 2 > narg) {
            host.missing(cmd + " velocity_arm");
            return narg;
          }
          full_arm = read_velocity_arm(cmd, arg[iarg + 1], host);
          iarg += 2;
        } else if (kw == "normal_force") {
          if (iarg + 2 > narg) {
            host.missing(cmd + " normal_force");
            return narg;
          }
          coeff.normal_law = read_normal_force(cmd, arg[iarg + 1], host);
          iarg += 2;
        } else {
          if (coeff_index(kw) < NCOEFF || kw == "rolling" || kw == "torsion")
            host.fail("Fix grflow/wall contact keyword " + kw +
                      " must come right after kn cn, before zlo, zhi, velocity_arm and "
                      "normal_force");
          else
            host.fail("Unknown " + cmd + " keyword: " + kw);
          return narg;
        }
      }
      if (!walls[LO].active && !walls[HI].active)
        host.fail("Fix grflow/wall needs a wall: zlo and/or zhi");
      else if (both_walls() && walls[HI].z <= walls[LO].z)
        host.fail("Fix grflow/wall zhi " + host.text(walls[HI].z) + " must be above zlo " +
                  host.text(walls[LO].z));
      return iarg;
    }

    /* --------------------------------------------------------------------
       fix_modify ID: a coefficient keyword and a value (the histories are
       kept), wall lo|hi vel vx vy vz, wall lo|hi z value.  Returns the
       number of arguments used, 0 if arg[0] is none of these.
    ------------------------------------------------------------------------- */

    template <class Host> int modify_wall_param(int narg, char **arg, const char *id, Host &host)
    {
      const std::string fm = std::string("fix_modify ") + id;
      const int k = coeff_index(arg[0]);
      if (k < NCOEFF) {
        if (narg < 2) {
          host.missing(fm + " " + arg[0]);
          return 0;
        }
        double value[NCOEFF];
        for (int m = 0; m < NCOEFF; m++) value[m] = coeff_value[m];
        value[k] = host.number(arg[1], fm + " " + arg[0]);
        check_coeff_values(fm, value, host);
        coeff_value[k] = value[k];
        pack_coeffs(coeff_value, coeff);
        return 2;
      }
      if (strcmp(arg[0], "wall") != 0) return 0;
      if (narg < 4) {
        host.missing("fix_modify grflow/wall wall");
        return 0;
      }
      int iw = NWALL;
      if (strcmp(arg[1], "lo") == 0)
        iw = LO;
      else if (strcmp(arg[1], "hi") == 0)
        iw = HI;
      else {
        host.fail(fm + " wall: expected lo or hi, got " + arg[1]);
        return 0;
      }
      Wall &w = walls[iw];
      if (!w.active) {
        host.fail(fm + " wall " + arg[1] + ": this fix has no such wall");
        return 0;
      }
      if (strcmp(arg[2], "vel") == 0) {
        if (narg < 6) {
          host.missing("fix_modify grflow/wall wall vel");
          return 0;
        }
        for (int d = 0; d < 3; d++)
          w.v[d] = host.number(arg[3 + d], fm + " wall " + arg[1] + " vel");
        return 6;
      }
      if (strcmp(arg[2], "z") == 0) {
        w.z = host.number(arg[3], fm + " wall " + arg[1] + " z");
        if (both_walls() && walls[HI].z <= walls[LO].z)
          host.fail(fm + ": zhi " + host.text(walls[HI].z) + " must be above zlo " +
                    host.text(walls[LO].z));
        return 4;
      }
      host.fail(fm + " wall " + arg[1] + ": expected vel or z, got " + arg[2]);
      return 0;
    }

    /* --------------------------------------------------------------------
       messages of the hosts' checks
    ------------------------------------------------------------------------- */

    static std::string needs_sphere_message()
    {
      return "Fix grflow/wall requires atom attributes radius, omega and torque "
             "(atom_style sphere)";
    }
    static std::string periodic_message()
    {
      return "Fix grflow/wall needs a non-periodic z boundary";
    }
    static std::string respa_message()
    {
      return "Fix grflow/wall does not support run_style respa";
    }
    static std::string minimize_message(const char *id)
    {
      return std::string("Fix grflow/wall ") + id +
          ": the walls do not act during a minimization; atoms can cross them (and be lost "
          "where a wall sits on a box face)";
    }
    static std::string top_reached_message(const char *id)
    {
      return std::string("Fix grflow/wall ") + id + ": the top wall has reached the bottom wall";
    }
    template <class Host>
    std::string crossed_message(const char *id, int64_t tag, int w, double z, Host &host) const
    {
      return std::string("Fix grflow/wall ") + id + ": atom " + std::to_string(tag) +
          " crossed the " + wall_name(w) + " wall (z = " + host.text(z) + ", wall at " +
          host.text(walls[w].z) + ")";
    }

    // a wall beyond a fixed (non-periodic, not shrink-wrapped) face of the
    // box in z: an atom that reaches that face leaves the box (the host's
    // "Lost atoms") before it can touch the wall.  The message, or empty
    // when both active walls are within the box's fixed faces.
    template <class Host>
    std::string outside_box_message(const char *id, double boxlo, double boxhi, bool fixed_lo,
                                    bool fixed_hi, Host &host) const
    {
      for (int iw = 0; iw < NWALL; iw++) {
        const Wall &wall = walls[iw];
        if (!wall.active) continue;
        const bool below = (iw == LO) && fixed_lo && wall.z < boxlo;
        const bool above = (iw == HI) && fixed_hi && wall.z > boxhi;
        if (below || above)
          return std::string("Fix grflow/wall ") + id + ": the " + wall_name(iw) +
              " wall (z = " + host.text(wall.z) + ") is outside the box's fixed " +
              (below ? "lower face (z = " + host.text(boxlo)
                     : "upper face (z = " + host.text(boxhi)) +
              "): atoms would leave the box there before they reach the wall; move the wall "
              "inside the box or use boundary s or m in z";
      }
      return "";
    }

    // another command's use of a fix as the cell of two walls (find_cell()):
    // the fix does not exist, is not a fix grflow/wall, has one wall only
    enum { CELL_MISSING, CELL_NOT_WALL, CELL_ONE_WALL };
    static std::string cell_message(int problem, const std::string &caller, const char *id)
    {
      const std::string head = caller + ": fix " + id;
      if (problem == CELL_MISSING) return head + " does not exist";
      if (problem == CELL_NOT_WALL) return head + " is not a fix grflow/wall";
      return head + " must have both walls, zlo and zhi";
    }

    /* --------------------------------------------------------------------
       the walls move with their velocities, as the atoms move (initial
       integration); false if the top wall has reached the bottom wall
    ------------------------------------------------------------------------- */

    bool move()
    {
      for (int iw = 0; iw < NWALL; iw++) {
        Wall &w = walls[iw];
        if (!w.active) continue;
        w.z += dt * w.v[2];
        w.disp[0] += dt * w.v[0];
        w.disp[1] += dt * w.v[1];
      }
      return !(both_walls() && walls[HI].z <= walls[LO].z);
    }

    // an owned atom of the group whose centre reached or passed a wall:
    // its index (w its wall), -1 if none
    int find_crossing(const WallSpheres &s, int &w) const
    {
      for (int iw = 0; iw < NWALL; iw++) {
        const Wall &wall = walls[iw];
        if (!wall.active) continue;
        const double sign = normal_sign(iw);
        for (int i = 0; i < s.nlocal; i++)
          if ((s.mask[i] & s.groupbit) && sign * (s.x[i][2] - wall.z) <= 0.0) {
            w = iw;
            return i;
          }
      }
      return -1;
    }

    /* --------------------------------------------------------------------
       the near list: the atoms of the group that may touch a wall before
       the next neighbor list build.  With "neigh_modify delay 0 every 1
       check yes" every atom stays within skin/2 of where it was at the
       last build; the list is made again, on the step of each build (the
       host's count of builds, ncalls, changed) or when a wall has moved
       more than skin/2 since, with the atoms whose centre was then closer
       to an active wall than their radius plus 1.5 skins.  An atom left
       out is therefore farther from every wall than its radius plus
       skin/2 (a margin for round-off) until the list is made again: it
       cannot touch one, and its arms and histories were cleared (by the
       full pass of contact_pass() on the step the list is made).
       Returns false (full pass over all atoms) on the steps the list is
       made, and always if not allowed (allow_near(): other neighbor
       settings, radii that may change, no skin).
    ------------------------------------------------------------------------- */

    bool update_near(const WallSpheres &s, int64_t ncalls, double skin)
    {
      if (!near_allowed) return false;
      const double half_skin = 0.5 * skin;
      bool fresh = (ncalls == near_ncalls) && (s.nlocal == near_nlocal);
      for (int iw = 0; iw < NWALL; iw++)
        if (walls[iw].active && fabs(walls[iw].z - near_z[iw]) > half_skin) fresh = false;
      if (fresh) return true;

      // make the list; this step's contact_pass() does the full pass
      if ((int) near.size() < s.nlocal) near.resize(s.nlocal);
      nnear = 0;
      for (int i = 0; i < s.nlocal; i++) {
        if (!(s.mask[i] & s.groupbit)) continue;
        const double reach = s.radius[i] + 1.5 * skin;
        const double z = s.x[i][2];
        if ((walls[LO].active && z - walls[LO].z < reach) ||
            (walls[HI].active && walls[HI].z - z < reach))
          near[nnear++] = i;
      }
      near_ncalls = ncalls;
      near_nlocal = s.nlocal;
      for (int iw = 0; iw < NWALL; iw++) near_z[iw] = walls[iw].z;
      return false;
    }

    // at the start of a run: whether the host's neighbor settings allow
    // the near list (builds checked on every step, the radii fixed), and it
    // is made again on the first step
    void allow_near(int every, int delay, bool dist_check, bool build_once, double skin,
                    bool radii_may_change)
    {
      near_allowed = (every == 1) && (delay == 0) && dist_check && !build_once && (skin > 0.0) &&
          !radii_may_change;
      near_ncalls = -1;
    }

    /* --------------------------------------------------------------------
       the contacts of the owned atoms with the walls on this step (the
       fix's post_force()): forces and torques added to f and torque, the
       walls' forces, the contact records and, if virial, tally(i, vir)
       with the contact's virial.  Springs advance only if update_history
       (not while the host sets up a run).  ncalls (the host's count of
       neighbor list builds) and skin are for the near list.  Returns -1, or the index of an
       atom whose centre reached or passed a wall (w: that wall): the host
       stops with an error.
    ------------------------------------------------------------------------- */

    template <class Tally>
    int contact_pass(const WallSpheres &s, int64_t step, bool update_history, int64_t ncalls,
                     double skin, bool virial, Tally &tally, int &cross_wall)
    {
      const double wzero[3] = {0.0, 0.0, 0.0};

      for (int iw = 0; iw < NWALL; iw++)
        walls[iw].force[0] = walls[iw].force[1] = walls[iw].force[2] = 0.0;
      contact_step = step;
      force_flag = 0;

      // An atom farther than its radius from every wall touches none; for
      // it only its arms are cleared, and a wall's history only if the atom
      // touched that wall on the step before (the contact just ended).  Most
      // atoms are such atoms on most steps.
      //
      // Between neighbor list builds only the atoms of the near list can
      // touch a wall (see update_near()); the others were cleared when it
      // was made.
      const bool lo_on = walls[LO].active, hi_on = walls[HI].active;
      const double zlo = walls[LO].z, zhi = walls[HI].z;
      const bool use_near = update_near(s, ncalls, skin);
      const int nloop = use_near ? nnear : s.nlocal;
      for (int ii = 0; ii < nloop; ii++) {
        const int i = use_near ? near[ii] : ii;
        double *ci = contact[i];
        const double rad = s.radius[i];
        const double z = s.x[i][2];
        if (!(s.mask[i] & s.groupbit) ||
            ((!lo_on || z - zlo >= rad) && (!hi_on || zhi - z >= rad))) {
          for (int iw = 0; iw < NWALL; iw++)
            if (ci[REC_SIZE * iw] != 0.0) {
              ci[REC_SIZE * iw] = 0.0;
              for (int k = 0; k < HIST_SIZE; k++) history[i][iw * HIST_SIZE + k] = 0.0;
            }
          continue;
        }

        for (int iw = 0; iw < NWALL; iw++) {
          Wall &w = walls[iw];
          if (!w.active) continue;
          double *hist = &history[i][iw * HIST_SIZE];
          const bool was_touching = (ci[REC_SIZE * iw] != 0.0);
          ci[REC_SIZE * iw] = 0.0;
          const double sign = normal_sign(iw);
          const double gap = sign * (z - w.z);    // centre to wall, along n
          if (gap <= 0.0) {
            cross_wall = iw;
            return i;
          }
          if (gap >= rad) {
            if (was_touching)
              for (int k = 0; k < HIST_SIZE; k++) hist[k] = 0.0;
            continue;
          }

          ContactGeometry g;
          wall_geometry(gap, rad, sign, full_arm != 0, g);
          const double *v = s.v[i];
          const double vrel[3] = {v[0] - w.v[0], v[1] - w.v[1], v[2] - w.v[2]};
          ContactForces out;
          contact_forces(coeff, g, vrel, s.omega[i], wzero, dt, update_history, hist, out);

          for (int k = 0; k < 3; k++) {
            s.f[i][k] += out.f[k];
            s.torque[i][k] += out.torque_i[k];
            w.force[k] -= out.f[k];
          }
          if (out.fn > 0.0) {
            ci[REC_SIZE * iw + REC_ARM] = g.arm_i;
            for (int k = 0; k < 3; k++) ci[REC_SIZE * iw + REC_FORCE + k] = out.f[k];
          } else {
            ci[REC_SIZE * iw + REC_ARM] = -1.0;
          }

          // virial of the contact, branch vector from the contact point to
          // the centre: l = arm n; symmetrized, as the 6-component virial is
          if (virial) {
            const double l = g.arm_i * sign;
            double vir[6];
            vir[0] = vir[1] = vir[3] = 0.0;
            vir[2] = l * out.f[2];
            vir[4] = 0.5 * l * out.f[0];
            vir[5] = 0.5 * l * out.f[1];
            tally(i, vir);
          }
        }
      }
      return -1;
    }

    /* --------------------------------------------------------------------
       the output vector: the walls' forces summed over the processors
       once per step (force_flag), then entry n (0-based)
    ------------------------------------------------------------------------- */

    static int vector_extensive(int n) { return (n % VEC_PER_WALL < 3) ? 1 : 0; }

    double vector_value(int n, MPI_Comm world)
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
      const int iw = n / VEC_PER_WALL, k = n % VEC_PER_WALL;
      const Wall &w = walls[iw];
      if (k < 3) return wall_force_all[iw][k];
      if (k == VEC_Z) return w.active ? w.z : 0.0;
      return w.disp[k - VEC_DX];
    }

    /* --------------------------------------------------------------------
       global restart data (write_restart_block() and read_restart_block()
       around them): the walls' state; restoring it checks that the
       command has the walls of the file
    ------------------------------------------------------------------------- */

    void pack_state(double *list) const
    {
      int n = 0;
      for (int iw = 0; iw < NWALL; iw++) {
        const Wall &w = walls[iw];
        list[n++] = w.active;
        list[n++] = w.z;
        for (int k = 0; k < 3; k++) list[n++] = w.v[k];
        list[n++] = w.disp[0];
        list[n++] = w.disp[1];
      }
    }

    template <class Host> void restore_state(const char *buf, const char *id, Host &host)
    {
      const std::string who = std::string("Fix grflow/wall ") + id;
      int version;
      const double *list = read_restart_block(who, buf, RESTART_VERSION, NRESTART, version, host);
      int n = 0;
      for (int iw = 0; iw < NWALL; iw++) {
        Wall &w = walls[iw];
        const int active = (int) list[n++];
        if (active != w.active) {
          host.fail(who + ": restart file has other walls than the command");
          return;
        }
        w.z = list[n++];
        for (int k = 0; k < 3; k++) w.v[k] = list[n++];
        w.disp[0] = list[n++];
        w.disp[1] = list[n++];
      }
    }

    /* --------------------------------------------------------------------
       per-atom data (the host allocates history and contact with NHIST
       and NCONTACT columns)
    ------------------------------------------------------------------------- */

    void clear_atom(int i)
    {
      for (int m = 0; m < NHIST; m++) history[i][m] = 0.0;
      for (int m = 0; m < NCONTACT; m++) contact[i][m] = 0.0;
    }

    void copy_atom(int i, int j)
    {
      for (int m = 0; m < NHIST; m++) history[j][m] = history[i][m];
      for (int m = 0; m < NCONTACT; m++) contact[j][m] = contact[i][m];
    }

    // an atom moving to another processor: its histories
    int pack_atom(int i, double *buf) const
    {
      for (int m = 0; m < NHIST; m++) buf[m] = history[i][m];
      return NHIST;
    }

    int unpack_atom(int i, const double *buf)
    {
      for (int m = 0; m < NHIST; m++) history[i][m] = buf[m];
      mark_unknown(i);
      return NHIST;
    }

    // the restart data of an atom: the count, then its histories
    int pack_atom_restart(int i, double *buf) const
    {
      buf[0] = NRESTART_ATOM;
      for (int m = 0; m < NHIST; m++) buf[m + 1] = history[i][m];
      return NRESTART_ATOM;
    }

    // extra: the atom's restart data of all fixes, this fix's the nth
    void unpack_atom_restart(int i, const double *extra, int nth)
    {
      int m = 0;
      for (int k = 0; k < nth; k++) m += static_cast<int>(extra[m]);
      m++;
      for (int k = 0; k < NHIST; k++) history[i][k] = extra[m++];
      mark_unknown(i);
    }

    // an atom whose wall histories came from elsewhere: no force-bearing
    // contact on record, but the next contact_pass() clears a history of a
    // wall it does not touch
    void mark_unknown(int i)
    {
      for (int m = 0; m < NCONTACT; m++) contact[i][m] = 0.0;
      for (int w = 0; w < NWALL; w++)
        if (walls[w].active) contact[i][REC_SIZE * w + REC_ARM] = -1.0;
    }

   protected:
    ContactCoeffs coeff;           // with the normal force law (normal_force keyword)
    double coeff_value[NCOEFF];    // as parsed, changed by fix_modify
    int full_arm;
    double dt;
    Wall walls[NWALL];
    double wall_force_all[NWALL][3];
    int force_flag;

    double **history;    // per atom: NHIST values (the host's array)
    double **contact;    // per atom: NCONTACT values (the host's array)
    int64_t contact_step;

    // atoms that may touch a wall until the next neighbor list build
    bool near_allowed;    // the host's settings allow the list (allow_near())
    std::vector<int> near;
    int nnear;
    int64_t near_ncalls;     // the host's count of builds when it was made
    int near_nlocal;         // the number of owned atoms then
    double near_z[NWALL];    // wall positions then
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
