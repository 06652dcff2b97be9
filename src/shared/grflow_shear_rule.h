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
   fix grflow/shear without a host: its arguments, the reversal rule
   (reverse when tau reaches +tau_amp moving +x or -tau_amp moving -x,
   then await the first zero-crossing of tau), the events and the cycle
   count N (grflow_cycle_count.h), initial liquefaction (the first check
   with r_u >= R), the stop conditions, the glued layer's motion, the
   output vector, the progress line and the restart block's values.  The
   fix (src/GRFLOW/fix_grflow_shear.cpp, compiled into both hosts) reads
   tau and p from its compute grflow/network, derives r_u = 1 - p/p0 with
   its own p0, and drives the top wall of its fix grflow/wall.  Header
   only, no host types.
   Doc: doc/fix_grflow_shear.rst.

   The host reads numbers and reports (GRFLOW::FixHost, grflow_host_api.h;
   FLERR: the call site):
     host.number(FLERR, const char *str, const std::string &what) -> double
     host.integer(FLERR, str, what) -> int, host.logical(FLERR, str, what) -> bool
     host.missing(FLERR, const std::string &cmd)     (no return)
     host.fail(FLERR, const std::string &message)    (no return)
     host.warning(FLERR, const std::string &message)
     host.text(double) -> std::string          (a number in a message)
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_SHEAR_RULE_H
#define LMP_GRFLOW_SHEAR_RULE_H

#include "grflow_cycle_count.h"
#include "grflow_host.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace LAMMPS_NS {
namespace GRFLOW {

  // positions of the output vector (0-based)
  struct ShearLayout {
    // clang-format off
    enum {
      DIRECTION, REVERSALS, XWALL, GAMMA, TAU, PRESS, RU, P0, STEP_IL, TIME_IL, N_IL, N_EVENT,
      DONE, EVENT, NOUT
    };
    // clang-format on
  };

  /* ----------------------------------------------------------------------
     the arguments: fix ID group grflow/shear wall-ID compute-ID vx tau_amp
     keyword value ...
  ------------------------------------------------------------------------- */

  struct ShearSettings {
    std::string wall_id, network_id;
    double vx = 0.0, tau_amp = 0.0;
    double ru_liq = 0.99;    // r_u of initial liquefaction
    int check_every = 1;
    double stop_cycles = 0.0, stop_cycles_after_il = 0.0, stop_gamma = 0.0;    // 0: none
    bool progress = true;
    bool halt = false;    // end the run at every event and when done (halt yes)
    std::string glue;     // group glued to the top wall, "" if none

    // read the arguments of the fix command
    template <class Host> void parse(int narg, char **arg, Host &host)
    {
      if (narg < 7) {
        host.fail(FLERR,
                  "Illegal fix grflow/shear command: expected wall-ID compute-ID vx tau_amp "
                  "[keyword value ...]");
        return;
      }
      wall_id = arg[3];
      network_id = arg[4];
      vx = host.number(FLERR, arg[5], "fix grflow/shear vx");
      tau_amp = host.number(FLERR, arg[6], "fix grflow/shear tau_amp");
      if (vx <= 0.0) host.fail(FLERR, "Fix grflow/shear vx must be > 0, got " + host.text(vx));
      if (tau_amp <= 0.0)
        host.fail(FLERR, "Fix grflow/shear tau_amp must be > 0, got " + host.text(tau_amp));

      static const Keyword known[] = {{"every", 1},       {"liquefaction", 1},
                                      {"stop_cycles", 1}, {"stop_after_liquefaction", 1},
                                      {"stop_gamma", 1},  {"progress", 1},
                                      {"glue", 1},        {"halt", 1}};
      parse_keywords(narg, arg, 7, "fix grflow/shear", known, host,
                     [&](const std::string &kw, char **values, const std::string &what) {
                       keyword(kw, values[0], what, host);
                     });
    }

    // the value of one keyword of parse()
    template <class Host>
    void keyword(const std::string &kw, const char *value, const std::string &what, Host &host)
    {
      if (kw == "every") {
        check_every = host.integer(FLERR, value, what);
        if (check_every < 1) host.fail(FLERR, "Fix grflow/shear every must be >= 1");
      } else if (kw == "liquefaction") {
        ru_liq = host.number(FLERR, value, what);
        if (ru_liq <= 0.0 || ru_liq > 1.0)
          host.fail(FLERR,
                    "Fix grflow/shear liquefaction threshold must be in (0,1], got " +
                        host.text(ru_liq));
      } else if (kw == "progress") {
        progress = host.logical(FLERR, value, what);
      } else if (kw == "halt") {
        halt = host.logical(FLERR, value, what);
      } else if (kw == "glue") {
        glue = value;
      } else if (kw == "stop_cycles" || kw == "stop_gamma" || kw == "stop_after_liquefaction") {
        double &stop = (kw == "stop_cycles") ? stop_cycles
            : (kw == "stop_gamma")           ? stop_gamma
                                             : stop_cycles_after_il;
        stop = host.number(FLERR, value, what);
        if (stop <= 0.0) host.fail(FLERR, "Fix grflow/shear " + kw + " must be > 0");
      }
    }

    // a check of tau, p and r_u applies the rules on multiples of every
    // (and at the start of shearing: first)
    bool decides(bool first, std::int64_t step) const { return first || step % check_every == 0; }

    // messages of the hosts' checks
    std::string glue_missing() const
    {
      return "Fix grflow/shear glue group " + glue + " does not exist";
    }
    std::string glue_deleted() const
    {
      return "Fix grflow/shear glue group " + glue + " was deleted";
    }
    std::string halt_unsupported() const
    {
      return "Fix grflow/shear halt yes: this program cannot end a run early (LIGGGHTS 3.8: run "
             "fixed segments instead)";
    }
  };

  /* ----------------------------------------------------------------------
     the protocol state: direction, reversals, p0, initial liquefaction,
     the awaited zero-crossing, the cycle count; the last check and event
  ------------------------------------------------------------------------- */

  struct ShearProtocol {
    enum { NO_EVENT, EVENT_REVERSAL, EVENT_ZERO };

    // state of the restart block
    int started = 0, direction = 1;
    std::int64_t reversals = 0, step_il = -1;
    double p0 = 0.0;
    int await_zero = 0;    // a reversal happened, tau has not crossed zero since
    CycleCount count;      // N, and the time of initial liquefaction

    // the last event and check
    std::int64_t event_step = -1;
    int event_kind = NO_EVENT;
    double tau = 0.0, press = 0.0, ru = 0.0;

    // shearing starts at time t with mean stress p
    template <class Host> void start(double p, double t, Host &host)
    {
      p0 = p;
      if (p0 <= 0.0)
        host.fail(FLERR,
                  "Fix grflow/shear: the mean stress is " + host.text(p0) +
                      " when shearing starts; it must be > 0 to define r_u");
      started = 1;
      direction = 1;
      count.start(t);
    }

    // the top wall's (and glued layer's) velocity along x
    double velocity(const ShearSettings &s) const { return direction * s.vx; }

    // a check with tau, p and r_u of step at time t (global values: every
    // rank decides alike).  First the events: the first zero-crossing of
    // tau after a reversal (tau moves from the amplitude just reached
    // towards the other side), then the reversal; true if the direction
    // reversed (the host then drives the wall and reports).  Then
    // liquefied(), after the host's report.
    bool reverse(const ShearSettings &s, std::int64_t step, double t)
    {
      if (await_zero && ((direction < 0 && tau <= 0.0) || (direction > 0 && tau >= 0.0))) {
        await_zero = 0;
        event_step = step;
        event_kind = EVENT_ZERO;
        count.crossing(reversals, t);
      }
      if ((direction > 0 && tau >= s.tau_amp) || (direction < 0 && tau <= -s.tau_amp)) {
        direction = -direction;
        reversals++;
        await_zero = 1;
        event_step = step;
        event_kind = EVENT_REVERSAL;
        count.reversal(reversals, t);
        return true;
      }
      return false;
    }

    // initial liquefaction: the first check with r_u >= R
    void liquefied(const ShearSettings &s, std::int64_t step, double t)
    {
      if (step_il < 0 && ru >= s.ru_liq) {
        step_il = step;
        count.liquefied(t);
      }
    }

    // the output vector (ShearLayout) at step; cell: the wall fix is
    // known, with top wall displacement xw and height h
    double output(int n, const ShearSettings &s, std::int64_t step, bool cell, double xw,
                  double h) const
    {
      switch (n) {
        case ShearLayout::DIRECTION:
          return direction;
        case ShearLayout::REVERSALS:
          return reversals;
        case ShearLayout::XWALL:
          return xw;
        case ShearLayout::GAMMA:
          return cell ? xw / h : 0.0;
        case ShearLayout::TAU:
          return tau;
        case ShearLayout::PRESS:
          return press;
        case ShearLayout::RU:
          return ru;
        case ShearLayout::P0:
          return p0;
        case ShearLayout::STEP_IL:
          return step_il;
        case ShearLayout::TIME_IL:
          return count.il ? count.t_il : -1.0;
        case ShearLayout::N_IL:
          return count.n_il;
        case ShearLayout::N_EVENT:
          return count.n_event;
        case ShearLayout::DONE: {
          int done = 0;
          if (s.stop_cycles > 0.0 && count.n_event >= s.stop_cycles) done = 1;
          if (s.stop_cycles_after_il > 0.0 && count.n_il >= 0.0 &&
              count.n_event - count.n_il >= s.stop_cycles_after_il)
            done = 1;
          if (s.stop_gamma > 0.0 && cell && std::fabs(xw / h) >= s.stop_gamma) done = 1;
          return done;
        }
        case ShearLayout::EVENT:
          return (event_step == step) ? event_kind : NO_EVENT;
      }
      return 0.0;
    }

    /* --------------------------------------------------------------------
       restart block (the GRFLOW header, then these values): format 2.
       Formats 1 and 0 (before the fractional cycle count) lack the times
       of the cycle events, so N cannot go on from them.  A host whose
       restart files do not keep the simulated time (LIGGGHTS) appends it
       (R_CLOCK, NRESTART_CLOCK values).
    ----------------------------------------------------------------------- */

    // clang-format off
    enum {
      R_STARTED, R_DIRECTION, R_REVERSALS, R_STEP_IL, R_P0, R_AWAIT_ZERO, R_N_EVENT, R_T_EVENT,
      R_IL, R_T_IL, R_N_IL, R_N_BEFORE_IL, R_T_BEFORE_IL, NRESTART, R_CLOCK = NRESTART,
      NRESTART_CLOCK
    };
    // clang-format on
    enum { RESTART_VERSION = 2 };

    void pack(double *list) const
    {
      list[R_STARTED] = started;
      list[R_DIRECTION] = direction;
      list[R_REVERSALS] = static_cast<double>(reversals);
      list[R_STEP_IL] = static_cast<double>(step_il);
      list[R_P0] = p0;
      list[R_AWAIT_ZERO] = await_zero;
      list[R_N_EVENT] = count.n_event;
      list[R_T_EVENT] = count.t_event;
      list[R_IL] = count.il;
      list[R_T_IL] = count.t_il;
      list[R_N_IL] = count.n_il;
      list[R_N_BEFORE_IL] = count.n_before_il;
      list[R_T_BEFORE_IL] = count.t_before_il;
    }

    // the values of a block of format version
    template <class Host> void unpack(const char *id, int version, const double *list, Host &host)
    {
      if (version < RESTART_VERSION) {
        host.fail(FLERR,
                  "Fix grflow/shear " + std::string(id) + ": restart data of format version " +
                      std::to_string(version) +
                      " were written before GRFLOW counted fractional cycles and lack the times of "
                      "the cycle events: continue that run with the GRFLOW that wrote it, or start "
                      "its shear stage again");
        return;
      }
      started = static_cast<int>(list[R_STARTED]);
      direction = static_cast<int>(list[R_DIRECTION]);
      reversals = static_cast<std::int64_t>(list[R_REVERSALS]);
      step_il = static_cast<std::int64_t>(list[R_STEP_IL]);
      p0 = list[R_P0];
      await_zero = static_cast<int>(list[R_AWAIT_ZERO]);
      count.n_event = list[R_N_EVENT];
      count.t_event = list[R_T_EVENT];
      count.il = list[R_IL] != 0.0;
      count.t_il = list[R_T_IL];
      count.n_il = list[R_N_IL];
      count.n_before_il = list[R_N_BEFORE_IL];
      count.t_before_il = list[R_T_BEFORE_IL];
    }
  };

  /* ----------------------------------------------------------------------
     the glued layer (atoms with mask & bit) moves rigidly with the top
     wall: velocity (vw, 0, 0), no spin, and, in a step of dt (x given),
     x += dt vw
  ------------------------------------------------------------------------- */

  static inline GRFLOW_FUNCTION void glue_atom(double vw, double *v, double *omega)
  {
    v[0] = vw;
    v[1] = v[2] = 0.0;
    omega[0] = omega[1] = omega[2] = 0.0;
  }

  static inline void glue_layer(int nlocal, const int *mask, int bit, double vw, double **v,
                                double **omega, double dt = 0.0, double **x = nullptr)
  {
    for (int i = 0; i < nlocal; i++) {
      if (!(mask[i] & bit)) continue;
      glue_atom(vw, v[i], omega[i]);
      if (x) x[i][0] += dt * vw;
    }
  }

  /* ----------------------------------------------------------------------
     one progress line per reversal: wall-clock time since the run
     started and steps per second since the last line
  ------------------------------------------------------------------------- */

  struct ShearProgress {
    double wall_start = 0.0, wall_last = 0.0;    // wall-clock times (s)
    std::int64_t step_last = 0;

    void start(double now, std::int64_t step)
    {
      wall_start = wall_last = now;
      step_last = step;
    }

    // the line of a reversal at step, wall-clock time now
    std::string line(const char *id, const ShearProtocol &p, std::int64_t step, double gamma,
                     double now)
    {
      const double rate = (now > wall_last) ? (step - step_last) / (now - wall_last) : 0.0;
      const char *format = "grflow/shear %s: reversal %lld N %.2f step %lld gamma %.6g tau %.6g "
                           "r_u %.4f%s elapsed %.1f s %.0f steps/s\n";
      const long long k = p.reversals, st = step;
      const char *liquefied = p.step_il >= 0 ? " (liquefied)" : "";
      const int n = snprintf(nullptr, 0, format, id, k, p.count.n_event, st, gamma, p.tau, p.ru,
                             liquefied, now - wall_start, rate);
      std::string text(n + 1, '\0');
      snprintf(&text[0], n + 1, format, id, k, p.count.n_event, st, gamma, p.tau, p.ru, liquefied,
               now - wall_start, rate);
      text.resize(n);
      wall_last = now;
      step_last = step;
      return text;
    }
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
