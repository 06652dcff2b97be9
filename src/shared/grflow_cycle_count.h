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
   The fractional cycle count N of a stress-reversal protocol, the one
   definition GRFLOW uses (fix grflow/shear, its doc page, the decks and
   analysis/): shearing starts at N = 0; reversal k is at N = k/2 - 1/4;
   the first zero-crossing of the shear stress after reversal k is at
   N = k/2; between two of these events N is linear in time.

   N between two events is known only once the second one has happened, so
   the count keeps the last event and fixes N at initial liquefaction (a
   time between two events) when the next event comes.  Header only, no
   LAMMPS types.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_CYCLE_COUNT_H
#define LMP_GRFLOW_CYCLE_COUNT_H

namespace LAMMPS_NS {
namespace GRFLOW {

  struct CycleCount {
    double n_event = 0.0;        // N of the last event
    double t_event = 0.0;        // its time
    bool il = false;             // initial liquefaction has happened
    double t_il = 0.0;           // its time
    double n_il = -1.0;          // N at initial liquefaction, -1 until known
    double n_before_il = 0.0;    // N and time of the last event before it
    double t_before_il = 0.0;

    static double reversal_n(long k) { return 0.5 * k - 0.25; }
    static double crossing_n(long k) { return 0.5 * k; }

    // shearing starts at time t
    void start(double t)
    {
      *this = CycleCount();
      t_event = t;
    }

    // an event with count n at time t (events come in time order)
    void event(double n, double t)
    {
      if (il && n_il < 0.0)
        n_il = (t > t_before_il)
            ? n_before_il + (n - n_before_il) * (t_il - t_before_il) / (t - t_before_il)
            : n;
      n_event = n;
      t_event = t;
    }
    void reversal(long k, double t) { event(reversal_n(k), t); }
    void crossing(long k, double t) { event(crossing_n(k), t); }

    // initial liquefaction at time t (after the events up to t)
    void liquefied(double t)
    {
      il = true;
      t_il = t;
      n_before_il = n_event;
      t_before_il = t_event;
      if (t == t_event) n_il = n_event;
    }
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
