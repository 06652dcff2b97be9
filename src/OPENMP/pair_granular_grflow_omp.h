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
   Contributing authors: GRFLOW developers
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(granular/grflow/omp,PairGranularGRFLOWOMP);
// clang-format on
#else

#ifndef LMP_PAIR_GRANULAR_GRFLOW_OMP_H
#define LMP_PAIR_GRANULAR_GRFLOW_OMP_H

#include "pair_granular_grflow.h"
#include "thr_omp.h"

namespace LAMMPS_NS {

class PairGranularGRFLOWOMP : public PairGranularGRFLOW, public ThrOMP {
 public:
  PairGranularGRFLOWOMP(class LAMMPS *);

  void compute(int, int) override;
  double memory_usage() override;
};

}    // namespace LAMMPS_NS

#endif
#endif
