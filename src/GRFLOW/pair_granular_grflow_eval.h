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
   The pair loop of pair granular/grflow, shared by the serial style and
   its OPENMP variant (granular/grflow/omp): each calls it on its range of
   the neighbor list with its own force and torque arrays and its own
   energy/virial tally.  Included by their .cpp files only.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_GRANULAR_GRFLOW_EVAL_H
#define LMP_PAIR_GRANULAR_GRFLOW_EVAL_H

#include "pair_granular_grflow.h"

#include "grflow_contact.h"

#include "atom.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "neigh_list.h"
#include "update.h"

#include <cmath>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the pair loop, compiled for each combination of energy/virial tallying,
   newton_pair and special bonds (as in the OPT package), so that it
   carries no tests of them; neighbor lists carry special-bond bits only in
   molecular systems, without them no special_lj lookup is needed
   (together about 10% of the pair time, doc/studies/pair-benchmark.md)
------------------------------------------------------------------------- */

template <class Tally>
void PairGranularGRFLOW::eval_dispatch(int iifrom, int iito, int eflag, double *const *f,
                                       double *const *torque, const Tally &tally)
{
  const bool special = (atom->molecular != Atom::ATOMIC);
  if (evflag) {
    if (force->newton_pair) {
      if (special)
        eval<1, 1, 1>(iifrom, iito, eflag, f, torque, tally);
      else
        eval<1, 1, 0>(iifrom, iito, eflag, f, torque, tally);
    } else {
      if (special)
        eval<1, 0, 1>(iifrom, iito, eflag, f, torque, tally);
      else
        eval<1, 0, 0>(iifrom, iito, eflag, f, torque, tally);
    }
  } else {
    if (force->newton_pair) {
      if (special)
        eval<0, 1, 1>(iifrom, iito, eflag, f, torque, tally);
      else
        eval<0, 1, 0>(iifrom, iito, eflag, f, torque, tally);
    } else {
      if (special)
        eval<0, 0, 1>(iifrom, iito, eflag, f, torque, tally);
      else
        eval<0, 0, 0>(iifrom, iito, eflag, f, torque, tally);
    }
  }
}

/* ----------------------------------------------------------------------
   forces and torques of the pairs of ilist[iifrom..iito) into f, torque;
   tally(i, j, nlocal, newton_pair, evdwl, fx, fy, fz, delx, dely, delz)
   takes the energy and virial of each contact when EVFLAG is set
------------------------------------------------------------------------- */

template <int EVFLAG, int NEWTON_PAIR, int SPECIAL, class Tally>
void PairGranularGRFLOW::eval(int iifrom, int iito, int eflag, double *const *f,
                              double *const *torque, const Tally &tally)
{
  using namespace GRFLOW;

  // no history updates during setup (forces are recomputed for the same state)
  const bool update_history = (update->setupflag == 0);
  const bool use_full_arm = (full_arm != 0);

  const double *const *const x = atom->x;
  const double *const *const v = atom->v;
  const double *const *const omega = atom->omega;
  const double *const radius = atom->radius;
  const int *const type = atom->type;
  const int nlocal = atom->nlocal;
  const double *const special_lj = force->special_lj;

  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firsthistory = fix_history->firstvalue;

  ContactGeometry g;
  ContactForces out;
  double del[3], vrel[3];
  double evdwl = 0.0;
  int nsame = 0;

  for (int ii = iifrom; ii < iito; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0];
    const double ytmp = x[i][1];
    const double ztmp = x[i][2];
    const double radi = radius[i];
    const ContactCoeffs *coeff_i = packed[type[i]];
    int *touch = firsttouch[i];
    double *allhistory = firsthistory[i];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj];
      double factor_lj = 1.0;
      if (SPECIAL) {
        factor_lj = special_lj[sbmask(j)];
        if (factor_lj == 0.0) continue;
      }
      j &= NEIGHMASK;

      del[0] = xtmp - x[j][0];
      del[1] = ytmp - x[j][1];
      del[2] = ztmp - x[j][2];
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const double radj = radius[j];
      const double radsum = radi + radj;
      double *hist = &allhistory[HIST_SIZE * jj];

      if (rsq >= radsum * radsum) {
        // a contact that ended: its springs are gone
        if (touch[jj]) {
          touch[jj] = 0;
          for (int k = 0; k < HIST_SIZE; k++) hist[k] = 0.0;
        }
        continue;
      }
      touch[jj] = 1;
      nsame += (rsq == 0.0);    // no contact normal: an error after the loop

      pair_geometry(del, sqrt(rsq), radi, radj, use_full_arm, g);
      vrel[0] = v[i][0] - v[j][0];
      vrel[1] = v[i][1] - v[j][1];
      vrel[2] = v[i][2] - v[j][2];
      const ContactCoeffs &c = coeff_i[type[j]];
      contact_forces(c, g, vrel, omega[i], omega[j], dt, update_history, hist, out);

      double fx = out.f[0], fy = out.f[1], fz = out.f[2];
      if (SPECIAL && factor_lj != 1.0) {
        fx *= factor_lj;
        fy *= factor_lj;
        fz *= factor_lj;
        for (int k = 0; k < 3; k++) {
          out.torque_i[k] *= factor_lj;
          out.torque_j[k] *= factor_lj;
        }
      }

      // f[i] is summed contact by contact (not in locals written once per
      // i): the summation order, and so the trajectories, of the serial
      // style before the /omp variant shared this loop
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;
      torque[i][0] += out.torque_i[0];
      torque[i][1] += out.torque_i[1];
      torque[i][2] += out.torque_i[2];

      if (NEWTON_PAIR || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        torque[j][0] += out.torque_j[0];
        torque[j][1] += out.torque_j[1];
        torque[j][2] += out.torque_j[2];
      }

      if (EVFLAG) {
        if (eflag) evdwl = factor_lj * elastic_energy(c, g.delta, hist);
        tally(i, j, nlocal, NEWTON_PAIR, evdwl, fx, fy, fz, del[0], del[1], del[2]);
      }
    }
  }
  // (a call inside the loop, even to a cold function, cost the loop 4%)
  if (nsame) same_position(iifrom, iito);
}

}    // namespace LAMMPS_NS

#endif
