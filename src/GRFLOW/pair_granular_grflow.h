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

#ifdef PAIR_CLASS
// clang-format off
PairStyle(granular/grflow,PairGranularGRFLOW);
// clang-format on
#else

#ifndef LMP_PAIR_GRANULAR_GRFLOW_H
#define LMP_PAIR_GRANULAR_GRFLOW_H

#include "pair.h"

// Pair::atom2cut() and Pair::radii2cut(): virtual in LAMMPS 4Feb2025 (the
// per-atom cutoffs of finite-size particles for "neighbor multi"), gone in
// 4Jul2026.  GRFLOW's builds set GRFLOW_PAIR_HAS_ATOM2CUT from the tree's
// pair.h (cmake/GRFLOWCompileSettings.cmake); otherwise it is inferred from
// a header that 4Jul2026 has and 4Feb2025 does not (nbin_manual.h).
#ifndef GRFLOW_PAIR_HAS_ATOM2CUT
#if defined(__has_include)
#if __has_include("nbin_manual.h")
#define GRFLOW_PAIR_HAS_ATOM2CUT 0
#else
#define GRFLOW_PAIR_HAS_ATOM2CUT 1
#endif
#else
#define GRFLOW_PAIR_HAS_ATOM2CUT 1
#endif
#endif

namespace LAMMPS_NS {
namespace GRFLOW {
  struct ContactCoeffs;
}    // namespace GRFLOW

class PairGranularGRFLOW : public Pair {
 public:
  PairGranularGRFLOW(class LAMMPS *);
  ~PairGranularGRFLOW() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  void reset_dt() override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;
  void transfer_history(double *, double *, int, int) override;
  double memory_usage() override;
#if GRFLOW_PAIR_HAS_ATOM2CUT
  double atom2cut(int) override;
  double radii2cut(double, double) override;
#endif

 protected:
  double dt;
  int full_arm;      // 1: contact-point velocity with full radii (stock compatible)
  int normal_law;    // GRFLOW::NORMAL_CLIPPED or NORMAL_UNCLIPPED (keyword normal_force)

  // user-facing per type pair coefficients, one array per name in
  // GRFLOW::COEFF_NAMES (NCOEFF of them, grflow_coeff_rules.h), changed
  // by pair_coeff or fix adapt, and their packed copy for the kernel
  double ***param;
  GRFLOW::ContactCoeffs **packed;

  double *onerad_dynamic, *maxrad_dynamic;

  std::string id_history, id_dummy;
  class FixDummy *fix_dummy;
  class FixNeighHistory *fix_history;
  int neighprev;    // search start for single()

  void allocate();
  // the pair loop (pair_granular_grflow_eval.h), shared with granular/grflow/omp
  template <class Tally>
  void eval_dispatch(int, int, int, double *const *, double *const *, const Tally &);
  template <int EVFLAG, int NEWTON_PAIR, int SPECIAL, class Tally>
  void eval(int, int, int, double *const *, double *const *, const Tally &);
  void write_coeffs(FILE *, int, int, bool);
  void find_history(int, int, double *);
  // error naming the first two atoms at the same position (no contact
  // normal) among the pairs of ilist[iifrom..iito); called by the pair
  // loop after it counted such a pair
#if defined(__GNUC__) || defined(__clang__)
  __attribute__((noinline, cold))
#endif
  void
  same_position(int, int);
};

}    // namespace LAMMPS_NS

#endif
#endif
