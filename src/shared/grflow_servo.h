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
   fix grflow/compress without a host: its arguments and the checks of
   the cell, the stress servo (strain rates from the stress errors with
   the gain, the overshoot damping of grflow_overshoot.h and rate_max),
   the box scaling and wall speeds it asks for, the kinetic energy and
   solid volume sums, the convergence test (stress error and energy
   ratio), the output vector and the restart block's values.  The fix
   (src/GRFLOW/fix_grflow_compress.cpp, compiled into both hosts) reads
   the stresses from its compute grflow/network and the energies, moves
   the walls of its fix grflow/wall and the periodic box, and adds over
   ranks; numbers and errors go through a host object (grflow_host.h).  Header only, no host types.
   Doc: doc/fix_grflow_compress.rst.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_SERVO_H
#define LMP_GRFLOW_SERVO_H

#include "grflow_network.h"
#include "grflow_overshoot.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace LAMMPS_NS {
namespace GRFLOW {

  // positions of the output vector (0-based)
  struct CompressLayout {
    // clang-format off
    enum {
      CONVERGED, SXX, SYY, SZZ, ERRMAX, KE, EEL, RATIO, RATE_X, RATE_Y, RATE_Z, VOLUME, VOID, LX,
      LY, HEIGHT, FACTOR_X, FACTOR_Y, FACTOR_Z, NOUT
    };
    // clang-format on
  };

  /* ----------------------------------------------------------------------
     the arguments: fix ID group grflow/compress wall-ID compute-ID
     p_target rate_max keyword value ...
  ------------------------------------------------------------------------- */

  struct CompressSettings {
    std::string wall_id, network_id;
    double p_target = 0.0, rate_max = 0.0;
    double gain = 10.0, tol = 0.01, ke_ratio_max = 1.0e-3;
    int servo_every = 1;
    std::string elastic_var;    // equal-style variable of the elastic energy, "" for the pair's
    // halt: end the run after a servo update that meets the stress
    // criterion (HALT_STRESS) or both criteria (HALT_READY)
    enum { HALT_NO, HALT_STRESS, HALT_READY };
    int halt = HALT_NO;

    // read the arguments of the fix command
    template <class Host> void parse(int narg, char **arg, Host &host)
    {
      if (narg < 7) {
        host.fail(FLERR,
                  "Illegal fix grflow/compress command: expected wall-ID compute-ID p_target "
                  "rate_max [keyword value ...]");
        return;
      }
      wall_id = arg[3];
      network_id = arg[4];
      p_target = host.number(FLERR, arg[5], "fix grflow/compress p_target");
      rate_max = host.number(FLERR, arg[6], "fix grflow/compress rate_max");
      if (p_target <= 0.0)
        host.fail(FLERR, "Fix grflow/compress p_target must be > 0, got " + host.text(p_target));
      if (rate_max <= 0.0)
        host.fail(FLERR, "Fix grflow/compress rate_max must be > 0, got " + host.text(rate_max));

      static const Keyword known[] = {{"elastic", 1},  {"gain", 1},  {"tol", 1},
                                      {"ke_ratio", 1}, {"every", 1}, {"halt", 1}};
      parse_keywords(narg, arg, 7, "fix grflow/compress", known, host,
                     [&](const std::string &kw, char **values, const std::string &what) {
                       keyword(kw, values[0], what, host);
                     });
    }

    // the value of one keyword of parse()
    template <class Host>
    void keyword(const std::string &kw, const char *value, const std::string &what, Host &host)
    {
      if (kw == "elastic") {
        if (std::string(value).compare(0, 2, "v_") != 0)
          host.fail(FLERR,
                    "Fix grflow/compress elastic takes an equal-style variable v_name, got " +
                        std::string(value));
        elastic_var = value + 2;
      } else if (kw == "every") {
        servo_every = host.integer(FLERR, value, what);
        if (servo_every < 1)
          host.fail(FLERR,
                    "Fix grflow/compress every must be >= 1, got " + std::to_string(servo_every));
      } else if (kw == "gain" || kw == "tol" || kw == "ke_ratio") {
        double &v = (kw == "gain") ? gain : (kw == "tol" ? tol : ke_ratio_max);
        v = host.number(FLERR, value, what);
        if (v <= 0.0)
          host.fail(FLERR, "Fix grflow/compress " + kw + " must be > 0, got " + host.text(v));
      } else if (kw == "halt") {
        const std::string v = value;
        if (v == "no")
          halt = HALT_NO;
        else if (v == "stress")
          halt = HALT_STRESS;
        else if (v == "ready")
          halt = HALT_READY;
        else
          host.fail(FLERR, "Fix grflow/compress halt must be no, stress or ready, got '" + v + "'");
      }
    }

    // halt: does a servo update with largest stress error err and
    // convergence flag converged end the run?  (As fix halt with
    // v_err < tol, or v_converged > 0.5, checked on the servo steps.)
    bool halts(double err, double converged) const
    {
      return (halt == HALT_STRESS && err < tol) || (halt == HALT_READY && converged > 0.5);
    }

    // what a host that cannot end a run early (LIGGGHTS 3.8) says to halt
    static std::string halt_unsupported()
    {
      return "Fix grflow/compress halt: this program cannot end a run early (LIGGGHTS 3.8: run "
             "in segments and test the fix's outputs between them)";
    }

    // the cell this fix needs: atoms with radius, rmass and omega (sphere),
    // an orthogonal 3d box periodic in x and y
    template <class Host>
    static void check_cell(bool sphere, bool triclinic, bool periodic_xy, int dimension, Host &host)
    {
      if (!sphere)
        host.fail(FLERR,
                  "Fix grflow/compress requires atom attributes radius, rmass and omega "
                  "(atom_style sphere)");
      if (triclinic) host.fail(FLERR, "Fix grflow/compress requires an orthogonal box");
      if (!periodic_xy) host.fail(FLERR, "Fix grflow/compress requires a box periodic in x and y");
      if (dimension != 3) host.fail(FLERR, "Fix grflow/compress requires a 3d system");
    }

    // the internal compute pe of the fix (found or deleted by the user)
    template <class Host> static void check_pe(bool found, const std::string &id_pe, Host &host)
    {
      if (!found) host.fail(FLERR, "Fix grflow/compress: its compute " + id_pe + " was deleted");
    }

    // the elastic-energy variable, found (exists) and equal-style or not
    template <class Host> void check_variable(bool exists, bool equal_style, Host &host) const
    {
      if (!exists)
        host.fail(FLERR, "Fix grflow/compress: variable " + elastic_var + " does not exist");
      if (!equal_style)
        host.fail(FLERR, "Fix grflow/compress: variable " + elastic_var + " is not equal-style");
    }

    // the servo updates on multiples of every
    bool servo_step(std::int64_t step) const { return step % servo_every == 0; }
    std::int64_t next_servo_step(std::int64_t step) const
    {
      return (step / servo_every + 1) * servo_every;
    }
  };

  /* ----------------------------------------------------------------------
     the servo: strain rates of x, y and the wall gap, per axis the
     overshoot damping, and what the last update or setup measured
  ------------------------------------------------------------------------- */

  struct StressServo {
    // state of the restart block
    double rate[3] = {0.0, 0.0, 0.0};
    int started = 0;
    OvershootDamping damping[3];

    // measured on the last servo step or at setup
    double sigma[3] = {0.0, 0.0, 0.0};
    double errmax = 0.0, ke = 0.0, eel = 0.0;

    // a run's setup updates the rates where an uninterrupted run would
    // (the very start and every N-th step); otherwise it keeps those of
    // the last update (they and the wall velocities are in the restart
    // files), so that a run split at a step that is not a multiple of N
    // gives the same trajectory as one run
    bool updates_at_setup(const CompressSettings &s, std::int64_t step) const
    {
      return !started || s.servo_step(step);
    }

    // the normal stresses of the compute's vector (NetworkLayout) and
    // their largest relative error
    void set_stresses(const CompressSettings &s, const double *vector)
    {
      sigma[0] = vector[NetworkLayout::SXX];
      sigma[1] = vector[NetworkLayout::SYY];
      sigma[2] = vector[NetworkLayout::SZZ];
      errmax = 0.0;
      for (int a = 0; a < 3; a++) {
        const double err = std::fabs((sigma[a] - s.p_target) / s.p_target);
        errmax = (errmax > err) ? errmax : err;
      }
    }

    // new strain rates from the stresses
    //   rate_a = rate_max * clamp(factor_a * gain * (sigma_aa - p_target) / p_target, -1, 1)
    // (compression is positive, a negative rate shrinks the cell); a
    // warning for each axis whose gain factor the overshoot damping halves
    // (fix id, at step)
    template <class Host>
    void update(const CompressSettings &s, const char *id, std::int64_t step, Host &host)
    {
      for (int a = 0; a < 3; a++) {
        const double err = (sigma[a] - s.p_target) / s.p_target;
        if (damping[a].update(err, s.tol))
          host.warning(FLERR,
                       "Fix " + std::string(id) + " grflow/compress: sigma_" +
                           std::string(2, "xyz"[a]) + " overshot the target " +
                           std::to_string(OvershootDamping::NOVERSHOOT) +
                           " servo updates in a row at step " +
                           std::to_string(static_cast<long long>(step)) +
                           "; its gain factor is halved to " + host.text(damping[a].factor));
        const double x = damping[a].factor * s.gain * err;
        const double upper = (1.0 < x) ? 1.0 : x;
        rate[a] = s.rate_max * ((-1.0 > upper) ? -1.0 : upper);
      }
    }

    // walls move symmetrically: the gap h changes at rate[2] * h; the
    // velocity of the upper wall (the lower one's is its opposite)
    double wall_speed(double h) const { return 0.5 * rate[2] * h; }

    // the periodic box changes in x or y
    bool deforms() const { return !(rate[0] == 0.0 && rate[1] == 0.0); }

    // box bounds lo, hi along axis a (0 or 1) after a step dt, scaled
    // about the centre
    void scale(int a, double dt, double &lo, double &hi) const
    {
      const double mid = 0.5 * (lo + hi);
      const double half = 0.5 * (hi - lo) * (1.0 + rate[a] * dt);
      lo = mid - half;
      hi = mid + half;
    }

    // the output vector (CompressLayout) with the wall gap h and box
    // lengths lx, ly, the solid volume vsolid
    double output(int n, const CompressSettings &s, double h, double lx, double ly,
                  double vsolid) const
    {
      const double volume = lx * ly * h;
      const double ratio = (eel > 0.0) ? ke / eel
                                       : (ke > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
      switch (n) {
        case CompressLayout::CONVERGED:
          return (errmax <= s.tol && ratio <= s.ke_ratio_max) ? 1.0 : 0.0;
        case CompressLayout::SXX:
        case CompressLayout::SYY:
        case CompressLayout::SZZ:
          return sigma[n - CompressLayout::SXX];
        case CompressLayout::ERRMAX:
          return errmax;
        case CompressLayout::KE:
          return ke;
        case CompressLayout::EEL:
          return eel;
        case CompressLayout::RATIO:
          return ratio;
        case CompressLayout::RATE_X:
        case CompressLayout::RATE_Y:
        case CompressLayout::RATE_Z:
          return rate[n - CompressLayout::RATE_X];
        case CompressLayout::VOLUME:
          return volume;
        case CompressLayout::VOID:
          return vsolid > 0.0 ? volume / vsolid - 1.0 : 0.0;
        case CompressLayout::LX:
          return lx;
        case CompressLayout::LY:
          return ly;
        case CompressLayout::HEIGHT:
          return h;
        case CompressLayout::FACTOR_X:
        case CompressLayout::FACTOR_Y:
        case CompressLayout::FACTOR_Z:
          return damping[n - CompressLayout::FACTOR_X].factor;
      }
      return 0.0;
    }

    /* --------------------------------------------------------------------
       restart block (the GRFLOW header, then these values), format 1: rates x y z,
       RESTART_V2 + started, gain factors x y z, last errors x y z,
       overshoot counts x y z.  Format 0 (files written before the
       header): the same values without it, or only the first four
       (files written before the overshoot damping, with started 0 or 1:
       the flag tells them apart, the hosts do not pass the size).
    ----------------------------------------------------------------------- */

    enum { NRESTART = 13, RESTART_V2 = 2, RESTART_VERSION = 1 };

    void pack(double *list) const
    {
      for (int a = 0; a < 3; a++) list[a] = rate[a];
      list[3] = RESTART_V2 + started;
      for (int a = 0; a < 3; a++) {
        list[4 + a] = damping[a].factor;
        list[7 + a] = damping[a].err_last;
        list[10 + a] = damping[a].count;
      }
    }

    void unpack(const double *list)
    {
      for (int a = 0; a < 3; a++) rate[a] = list[a];
      const int flag = static_cast<int>(list[3]);
      started = flag % RESTART_V2;
      if (flag < RESTART_V2) return;    // older file: no damping state, keep factors 1
      for (int a = 0; a < 3; a++) {
        damping[a].factor = list[4 + a];
        damping[a].err_last = list[7 + a];
        damping[a].count = static_cast<int>(list[10 + a]);
      }
    }
  };

  /* ----------------------------------------------------------------------
     per-rank sums over the atoms with mask & bit: the kinetic energy,
     translational and rotational (solid spheres), in units of mass
     velocity^2 without the factor 1/2 (kinetic_energy() completes the
     total), and the sum of radius^3 (solid_volume() completes it)
  ------------------------------------------------------------------------- */

  // twice the kinetic energy of one sphere, translation and rotation
  static inline GRFLOW_FUNCTION double kinetic_term(const double *v, const double *omega,
                                                    double rmass, double radius)
  {
    const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    const double ww = omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2];
    return rmass * (vv + 0.4 * radius * radius * ww);
  }

  static inline double kinetic_sum(int nlocal, const int *mask, int bit, const double *const *v,
                                   const double *const *omega, const double *rmass,
                                   const double *radius)
  {
    double sum = 0.0;
    for (int i = 0; i < nlocal; i++) {
      if (!(mask[i] & bit)) continue;
      sum += kinetic_term(v[i], omega[i], rmass[i], radius[i]);
    }
    return sum;
  }

  static inline double kinetic_energy(double total, double mvv2e)
  {
    return total * (0.5 * mvv2e);
  }

  static inline double cubed_radius_sum(int nlocal, const int *mask, int bit, const double *radius)
  {
    double sum = 0.0;
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & bit) sum += radius[i] * radius[i] * radius[i];
    return sum;
  }

  static inline double solid_volume(double total)
  {
    return total * (4.0 / 3.0 * 3.14159265358979323846);
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
