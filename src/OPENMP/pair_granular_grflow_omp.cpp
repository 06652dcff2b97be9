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

   OpenMP variant of pair granular/grflow: the same pair loop
   (pair_granular_grflow_eval.h) and contact kernel (grflow_contact.h),
   each thread on its share of the neighbor list with its own force and
   torque arrays, reduced by the OPENMP package (ThrOMP).  A thread writes
   only the contact histories of its own atoms i, so the histories need
   no synchronization.
------------------------------------------------------------------------- */

#include "pair_granular_grflow_omp.h"
#include "pair_granular_grflow_eval.h"

#include "comm.h"
#include "omp_compat.h"
#include "suffix.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PairGranularGRFLOWOMP::PairGranularGRFLOWOMP(LAMMPS *lmp) :
    PairGranularGRFLOW(lmp), ThrOMP(lmp, THR_PAIR)
{
  suffix_flag |= Suffix::OMP;
  respa_enable = 0;
}

/* ---------------------------------------------------------------------- */

void PairGranularGRFLOWOMP::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  const int nall = atom->nlocal + atom->nghost;
  const int nthreads = comm->nthreads;
  const int inum = list->inum;

#if defined(_OPENMP)
#pragma omp parallel LMP_DEFAULT_NONE LMP_SHARED(eflag, vflag)
#endif
  {
    int ifrom, ito, tid;

    loop_setup_thr(ifrom, ito, tid, inum, nthreads);
    ThrData *thr = fix->get_thr(tid);
    thr->timer(Timer::START);
    ev_setup_thr(eflag, vflag, nall, eatom, vatom, nullptr, thr);

    const auto tally = [this, thr](int i, int j, int nlocal, int newton_pair, double evdwl,
                                   double fx, double fy, double fz, double delx, double dely,
                                   double delz) {
      ev_tally_xyz_thr(this, i, j, nlocal, newton_pair, evdwl, 0.0, fx, fy, fz, delx, dely, delz,
                       thr);
    };
    eval_dispatch(ifrom, ito, eflag, thr->get_f(), thr->get_torque(), tally);

    thr->timer(Timer::PAIR);
    reduce_thr(this, eflag, vflag, thr);
  }    // end of omp parallel region
}

/* ---------------------------------------------------------------------- */

double PairGranularGRFLOWOMP::memory_usage()
{
  double bytes = memory_usage_thr();
  bytes += PairGranularGRFLOW::memory_usage();
  return bytes;
}
