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
   Unit tests for the fractional cycle count N (grflow_cycle_count.h):
   the event counts k/2 - 1/4 and k/2, and N at initial liquefaction
   against the linear interpolation written out by hand for event times
   chosen here (binary fractions, so the expected values are exact).
------------------------------------------------------------------------- */

#include "grflow_cycle_count.h"

#include "gtest/gtest.h"

using LAMMPS_NS::GRFLOW::CycleCount;

TEST(CycleCount, EventCounts)
{
  EXPECT_EQ(CycleCount::reversal_n(1), 0.25);
  EXPECT_EQ(CycleCount::crossing_n(1), 0.5);
  EXPECT_EQ(CycleCount::reversal_n(2), 0.75);
  EXPECT_EQ(CycleCount::crossing_n(2), 1.0);
  EXPECT_EQ(CycleCount::reversal_n(45), 22.25);
}

TEST(CycleCount, StartAndEvents)
{
  CycleCount c;
  c.start(3.0);
  EXPECT_EQ(c.n_event, 0.0);
  EXPECT_EQ(c.t_event, 3.0);
  EXPECT_EQ(c.n_il, -1.0);
  c.reversal(1, 4.0);
  EXPECT_EQ(c.n_event, 0.25);
  EXPECT_EQ(c.t_event, 4.0);
  c.crossing(1, 4.5);
  EXPECT_EQ(c.n_event, 0.5);
  EXPECT_EQ(c.n_il, -1.0);    // no liquefaction: never known
}

TEST(CycleCount, LiquefactionBetweenEvents)
{
  CycleCount c;
  c.start(0.0);
  c.reversal(1, 1.0);
  c.crossing(1, 1.5);
  c.liquefied(2.0);           // 0.5 + 0.25 * (2.0 - 1.5) / (3.5 - 1.5) = 0.5625
  EXPECT_EQ(c.n_il, -1.0);    // not known before the next event
  c.reversal(2, 3.5);
  EXPECT_EQ(c.n_il, 0.5625);
  c.crossing(2, 4.0);    // later events leave it alone
  c.reversal(3, 5.0);
  EXPECT_EQ(c.n_il, 0.5625);
  EXPECT_EQ(c.n_event, 1.25);
}

TEST(CycleCount, LiquefactionBeforeTheFirstReversal)
{
  CycleCount c;
  c.start(2.0);
  c.liquefied(3.0);
  c.reversal(1, 6.0);    // 0.25 * (3 - 2) / (6 - 2) = 0.0625
  EXPECT_EQ(c.n_il, 0.0625);
}

TEST(CycleCount, LiquefactionOnAnEventStep)
{
  CycleCount c;
  c.start(0.0);
  c.reversal(1, 1.0);
  c.liquefied(1.0);    // the same check as the reversal
  EXPECT_EQ(c.n_il, 0.25);
}

TEST(CycleCount, TwoEventsOnOneStep)
{
  // a crossing and the next reversal seen by one check: N jumps by 1/2;
  // liquefaction just before takes the later event as its end
  CycleCount c;
  c.start(0.0);
  c.reversal(1, 1.0);
  c.liquefied(1.5);
  c.crossing(1, 2.0);
  c.reversal(2, 2.0);
  EXPECT_EQ(c.n_il, 0.375);    // 0.25 + 0.25 * (1.5 - 1) / (2 - 1)
  EXPECT_EQ(c.n_event, 0.75);
}
