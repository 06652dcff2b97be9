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
   Unit tests for the overshoot damping rule of fix grflow/compress
   (grflow_overshoot.h) on error sequences written here, each with the
   answer the rule gives by hand: NOVERSHOOT = 4 overshoots in a row halve
   the factor; an update on the same side, within tol, or with less than
   half the previous error breaks the row; the factor stops at FACTOR_MIN.
   The sequence of runs of one servo interval (end-of-step errors all on
   one side, the setup re-measurements on the other) is the case that the
   fix must feed with every update, setup ones included
   (test_fix_compress.cpp checks that it does).
------------------------------------------------------------------------- */

#include "grflow_overshoot.h"

#include "gtest/gtest.h"

#include <vector>

using LAMMPS_NS::GRFLOW::OvershootDamping;

namespace {
const double TOL = 0.01;

// the factor after each update of errs
std::vector<double> factors(const std::vector<double> &errs, OvershootDamping d = {})
{
  std::vector<double> f;
  for (double e : errs) {
    d.update(e, TOL);
    f.push_back(d.factor);
  }
  return f;
}
}    // namespace

TEST(Overshoot, TwoUpdateCycleHalvesAfterFourOvershoots)
{
  // +0.2 -0.2 +0.2 ...: the first update has no predecessor on the other
  // side (err_last 0), updates 2..5 are the four overshoots
  OvershootDamping d;
  const std::vector<double> errs = {0.2, -0.2, 0.2, -0.2, 0.2, -0.2, 0.2, -0.2, 0.2};
  std::vector<bool> halved;
  for (double e : errs) halved.push_back(d.update(e, TOL));
  EXPECT_EQ(halved,
            (std::vector<bool>{false, false, false, false, true, false, false, false, true}));
  EXPECT_EQ(d.factor, 0.25);
  EXPECT_EQ(d.count, 0);    // the row starts again after each halving
  EXPECT_EQ(d.err_last, 0.2);
}

TEST(Overshoot, SplitRunPattern)
{
  // runs of one servo interval: end-of-step updates at +0.03, the setup
  // re-measurement of the same step at -0.02 (more than half of 0.03);
  // fed with every update the rule halves after 4 overshoots ...
  EXPECT_EQ(factors({0.03, -0.02, 0.03, -0.02, 0.03}), (std::vector<double>{1, 1, 1, 1, 0.5}));
  // ... while the end-of-step updates alone never overshoot
  EXPECT_EQ(factors({0.03, 0.03, 0.03, 0.03, 0.03, 0.03}), std::vector<double>(6, 1.0));
}

TEST(Overshoot, RowBreaks)
{
  // an update on the same side resets the row: 3 overshoots, a break, 3 more
  EXPECT_EQ(factors({0.2, -0.2, 0.2, -0.2, -0.2, 0.2, -0.2, 0.2}), std::vector<double>(8, 1.0));
  // within tol: not an overshoot, whatever the sign
  EXPECT_EQ(factors({0.2, -0.2, 0.2, -0.2, 0.005, -0.2, 0.2, -0.2}), std::vector<double>(8, 1.0));
  // exactly tol is within it (|err| > tol is required)
  EXPECT_EQ(factors({0.2, -0.2, 0.2, -0.2, TOL, -0.2}), std::vector<double>(6, 1.0));
  // shrinking by more than half each time converges: no damping
  EXPECT_EQ(factors({0.8, -0.39, 0.19, -0.09, 0.04, -0.019}), std::vector<double>(6, 1.0));
  // exactly half is not more than half
  EXPECT_EQ(factors({0.8, -0.4, 0.2, -0.1, 0.05, -0.025}), std::vector<double>(6, 1.0));
  // more than half, growing or not, counts
  EXPECT_EQ(factors({0.8, -0.41, 0.21, -0.11, 0.06}), (std::vector<double>{1, 1, 1, 1, 0.5}));
}

TEST(Overshoot, FloorAtFactorMin)
{
  OvershootDamping d;
  int halvings = 0;
  for (int k = 0; k < 1000; k++) halvings += d.update((k % 2) ? -0.3 : 0.3, TOL);
  // 999 overshoots in a row, a halving every 4 of them, until 1/1024
  EXPECT_EQ(halvings, 10);
  EXPECT_EQ(d.factor, OvershootDamping::FACTOR_MIN);
  EXPECT_EQ(d.factor, 1.0 / 1024.0);
}

TEST(Overshoot, ContinuesFromSavedState)
{
  // a restart restores factor, err_last and count: the row goes on
  OvershootDamping d;
  d.factor = 0.5;
  d.err_last = -0.2;
  d.count = 3;
  EXPECT_TRUE(d.update(0.2, TOL));
  EXPECT_EQ(d.factor, 0.25);
}
