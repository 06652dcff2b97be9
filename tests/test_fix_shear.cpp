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

/* ----------------------------------------------------------------------
   fix grflow/shear through the LAMMPS library API, on 144 spheres
   compressed between two walls (frictionless, so the packing is dense),
   then sheared with friction at constant height:
   - the top wall moves at +vx until the first reversal, then at -vx, ...:
     its displacement is vx dt times the signed step count, the walls'
     z and the box volume do not change;
   - the direction flips exactly at the checks where tau >= tau_amp
     (moving +x) or tau <= -tau_amp (moving -x), and nowhere else;
   - p0 is p when shearing starts, r_u = 1 - p/p0, the initial
     liquefaction is the first check with r_u >= R;
   - a glued layer moves rigidly with the wall, its velocity follows a
     reversal at once, and it gives no false "integrated more than once"
     warning;
   - a p0 keyword of the compute does not leak into the first check;
   - the fractional cycle count N at the events and at initial
     liquefaction, by hand from the rule;
   - stop_cycles sets the done flag when N reaches it, fix halt stops;
   - restart continuation and split runs take the same decisions as one run;
   - bad input gives a clear error.
------------------------------------------------------------------------- */

#include "lammps_fixture.h"

#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

using namespace grflow_test;

namespace {

const double VX = 0.02, DT = 1.0e-7;
const int EVERY = 20;

std::vector<double> fvec(Lammps &lmp, const char *id, int n)
{
  return lmp.fix_vector(id, n);
}

std::vector<double> shear(Lammps &lmp)
{
  return fvec(lmp, "sh", ShearVector::NOUT);
}
std::vector<double> wallv(Lammps &lmp)
{
  return fvec(lmp, "w", WallVector::NVECTOR);
}

std::vector<double> cvec(Lammps &lmp, const char *id)
{
  auto *v = (double *) lammps_extract_compute(lmp.handle, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
  if (!v) {
    ADD_FAILURE() << "compute " << id << " vector not available";
    return std::vector<double>(30, 0.0);
  }
  return std::vector<double>(v, v + 26);
}

long step(Lammps &lmp)
{
  return (long) lmp.thermo("step");
}

std::string join(const std::vector<long> &v)
{
  std::string s;
  for (auto x : v) s += " " + std::to_string(x);
  return s;
}

std::string slurp(const std::string &file)
{
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// 144 polydisperse spheres, compressed without friction by a servo on the
// top wall to 5 N (about 150 kPa), then left to rest (tests/decks/wall_packing.lmp);
// Table 1 friction from then on; written once

class Shear : public ::testing::Test {
 public:
  static void SetUpTestSuite()
  {
    restart = workfile("shear_packing.restart");
    Lammps lmp;
    lmp.cmds({"variable restart string " + restart, "variable mut_prep string 0.0",
              "variable dump string " + workfile("shear_packing.dump"),
              "include " + deck("wall_packing.lmp")});
  }
  static std::string restart;

  // the packing with friction, walls, integrator and compute; returns p
  static double read(Lammps &lmp, const std::string &integrate = "fix nve all nve/sphere",
                     const std::string &file = restart, const std::string &before_run = "")
  {
    lmp.cmds({"read_restart " + file, "comm_modify vel yes", "neighbor 0.2e-3 bin",
              "neigh_modify delay 0 every 1 check yes",
              "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi 8.0e-3"});
    if (!integrate.empty()) lmp.cmd(integrate);
    lmp.cmds({"variable zlo equal f_w[4]", "variable zhi equal f_w[10]",
              "compute net all grflow/network zlimits v_zlo v_zhi"});
    if (!before_run.empty()) lmp.cmd(before_run);
    lmp.cmd("run 0 post no");
    return cvec(lmp, "net")[NetVector::PRESS];
  }
  static std::string shear_cmd(double p, const std::string &extra = "")
  {
    return "fix sh all grflow/shear w net " + fmt_double(VX) + " " + fmt_double(0.3 * p) +
        " every " + std::to_string(EVERY) + " " + extra;
  }
};
std::string Shear::restart;

// state after each check (chunks of EVERY steps)
struct Record {
  long step;
  std::vector<double> sh, wall, net;
  double lx, ly, vol, time;
};

std::vector<Record> run_chunks(Lammps &lmp, int nchunks)
{
  std::vector<Record> out;
  auto rec = [&]() {
    out.push_back({step(lmp), shear(lmp), wallv(lmp), cvec(lmp, "net"), lmp.thermo("lx"),
                   lmp.thermo("ly"), lmp.thermo("vol"), lmp.thermo("time")});
  };
  lmp.cmd("run 0 post no");    // the fix's setup: start of shearing
  rec();
  for (int k = 0; k < nchunks; k++) {
    lmp.cmd("run " + std::to_string(EVERY) + " post no");
    rec();
  }
  return out;
}

TEST_F(Shear, WallVelocityAndReversalRule)
{
  Lammps lmp;
  const double p = read(lmp);
  const double amp = 0.3 * p;
  lmp.cmd(shear_cmd(p));
  const auto rec = run_chunks(lmp, 300);    // 6000 steps
  ASSERT_EQ(rec.size(), 301u);

  // at the start: moving +x (or reversed at once if tau >= tau_amp already)
  EXPECT_EQ(rec[0].sh[ShearVector::REVERSALS], rec[0].net[NetVector::TAU] >= amp ? 1.0 : 0.0);

  double xw = rec[0].wall[WallVector::HI_DX], xerr = 0.0;
  int dir = 1, nrev = 0, nplus = 0, nminus = 0, nzero = 0;
  bool await_zero = false;
  double n_event = 0.0;
  std::vector<long> rev_steps;
  const double h0 = rec[0].wall[WallVector::HI_Z] - rec[0].wall[WallVector::LO_Z];
  for (size_t k = 0; k < rec.size(); k++) {
    const auto &r = rec[k];
    if (k > 0) {
      // the wall moved EVERY steps at the velocity set at the last check
      xw += EVERY * DT * dir * VX;
      xerr = std::max(xerr, std::fabs(r.sh[ShearVector::XWALL] - xw));
      EXPECT_EQ(r.sh[ShearVector::XWALL], r.wall[WallVector::HI_DX]);
    }
    // tau and p of the fix are those of the compute at the same step, r_u
    // the fix's own, 1 - p/p0 with its p0 (the compute has no p0)
    ASSERT_EQ(r.sh[ShearVector::TAU], r.net[NetVector::TAU]) << r.step;
    ASSERT_EQ(r.sh[ShearVector::PRESS], r.net[NetVector::PRESS]) << r.step;
    ASSERT_EQ(r.sh[ShearVector::RU], 1.0 - r.net[NetVector::PRESS] / r.sh[ShearVector::P0])
        << r.step;
    ASSERT_EQ(r.net[NetVector::RU], 0.0) << r.step;
    // the rule, applied by hand
    const double tau = r.net[NetVector::TAU];
    int event = 0;
    if (await_zero && ((dir < 0 && tau <= 0.0) || (dir > 0 && tau >= 0.0))) {
      await_zero = false;
      event = 2;
      nzero++;
      n_event = 0.5 * nrev;    // the crossing after reversal k is at N = k/2
    }
    if ((dir > 0 && tau >= amp) || (dir < 0 && tau <= -amp)) {
      (dir > 0 ? nplus : nminus)++;
      dir = -dir;
      nrev++;
      rev_steps.push_back(r.step);
      await_zero = true;
      event = 1;
      n_event = 0.5 * nrev - 0.25;    // reversal k is at N = k/2 - 1/4
    }
    // the event flag: 1 on a reversal step, 2 on the first zero-crossing after one
    ASSERT_EQ(r.sh[ShearVector::EVENT], event) << "step " << r.step;
    ASSERT_EQ(r.sh[ShearVector::DIRECTION], dir) << "step " << r.step << " tau " << tau;
    ASSERT_EQ(r.sh[ShearVector::REVERSALS], nrev) << "step " << r.step;
    EXPECT_EQ(r.sh[ShearVector::N_EVENT], n_event) << "step " << r.step;
    EXPECT_DOUBLE_EQ(r.sh[ShearVector::GAMMA], r.sh[ShearVector::XWALL] / h0);
    // constant height and volume, to the last bit
    EXPECT_EQ(r.wall[WallVector::HI_Z] - r.wall[WallVector::LO_Z], h0);
    EXPECT_EQ(r.wall[WallVector::HI_Z], rec[0].wall[WallVector::HI_Z]);
    EXPECT_EQ(r.lx, rec[0].lx);
    EXPECT_EQ(r.ly, rec[0].ly);
    EXPECT_EQ(r.vol, rec[0].vol);
  }
  printf("[ measured ] p0 = %.6g Pa, tau_amp = %.6g Pa, reversal steps:%s\n", p, amp,
         join(rev_steps).c_str());
  measured("max |x_w - vx dt sum(direction)| (m)", xerr);
  measured("x_w at the end (m)", rec.back().sh[ShearVector::XWALL]);
  EXPECT_LT(xerr, 1.0e-18);
  // not trivial: reversals both ways
  EXPECT_GE(nplus, 2);
  EXPECT_GE(nzero, 3);
  EXPECT_GE(nminus, 2);
}

TEST_F(Shear, P0RuAndInitialLiquefaction)
{
  Lammps lmp;
  const double p = read(lmp);
  const double R = 0.002;
  lmp.cmd(shear_cmd(p, "liquefaction " + fmt_double(R)));
  const auto rec = run_chunks(lmp, 300);
  EXPECT_EQ(rec[0].sh[ShearVector::P0], p);
  EXPECT_EQ(rec[0].sh[ShearVector::PRESS], p);
  EXPECT_EQ(rec[0].sh[ShearVector::RU], 0.0);
  long first = -1;
  double first_time = -1.0, maxru = 0.0;
  // N at initial liquefaction by hand, from the event flag and the event
  // counts of the rule (tested above): linear in time between the event
  // before it and the event after it
  double n_a = 0.0, t_a = rec[0].time, n_il = -1.0, n_il_a = 0.0, t_il_a = 0.0;
  for (const auto &r : rec) {
    if (r.sh[ShearVector::EVENT] != 0.0) {
      const double n =
          r.sh[ShearVector::REVERSALS] * 0.5 - (r.sh[ShearVector::EVENT] == 1.0 ? 0.25 : 0.0);
      if (first >= 0 && n_il < 0.0)
        n_il = n_il_a + (n - n_il_a) * (first_time - t_il_a) / (r.time - t_il_a);
      n_a = n;
      t_a = r.time;
    }
    EXPECT_EQ(r.sh[ShearVector::P0], p);
    EXPECT_NEAR(r.sh[ShearVector::RU], 1.0 - r.sh[ShearVector::PRESS] / p, 1.0e-15);
    maxru = std::max(maxru, r.sh[ShearVector::RU]);
    if (first < 0 && r.sh[ShearVector::RU] >= R) {
      first = r.step;
      first_time = r.time;
      n_il_a = n_a;
      t_il_a = t_a;
      if (r.time == t_a) n_il = n_a;
    }
    EXPECT_EQ(r.sh[ShearVector::STEP_IL], (double) first) << r.step;
    if (first < 0) {
      EXPECT_EQ(r.sh[ShearVector::TIME_IL], -1.0);
      EXPECT_EQ(r.sh[ShearVector::N_IL], -1.0);
    } else {
      EXPECT_EQ(r.sh[ShearVector::TIME_IL], first_time);
      // -1 until the event after initial liquefaction; the same division
      // of the same numbers, so equal to round-off of the operation order
      if (n_il < 0.0)
        EXPECT_EQ(r.sh[ShearVector::N_IL], -1.0) << r.step;
      else
        EXPECT_NEAR(r.sh[ShearVector::N_IL], n_il, 1.0e-14 * (1.0 + n_il)) << r.step;
    }
  }
  measured("max r_u", maxru);
  printf("[ measured ] initial liquefaction (r_u >= %g) at step %ld, N_IL = %.6f\n", R, first,
         n_il);
  ASSERT_GT(first, rec[0].step);
  // N_IL known (the interpolation itself is tested on exact numbers in
  // test_cycle_count.cpp; here liquefaction usually falls between events)
  ASSERT_GT(n_il, 0.0);
}

// data flow one way: the fix reads the compute's stress and derives r_u
// itself with the p0 it took when shearing started; a compute with a p0
// keyword keeps its own r_u, which the fix neither reads nor changes
TEST_F(Shear, ComputeWithItsOwnP0KeepsIt)
{
  for (const char *p0 : {"p0 1.0e5", "p0 first"}) {
    Lammps lmp;
    const double p = read(lmp);
    lmp.cmds({"uncompute net",
              std::string("compute net all grflow/network zlimits v_zlo v_zhi ") + p0,
              shear_cmd(p, "liquefaction 0.3"), "run 100 post no"});
    const auto f = fvec(lmp, "sh", ShearVector::NOUT);
    const auto c = cvec(lmp, "net");
    // the compute's r_u with its p0: 1e5, or the pressure of its first
    // evaluation (before the run: the fix's p0 is the same one)
    EXPECT_EQ(c[NetVector::RU], 1.0 - c[NetVector::PRESS] / (p0[3] == '1' ? 1.0e5 : f[ShearVector::P0]))
        << p0;
    // the fix's r_u with its own p0, from the pressure of its last check
    EXPECT_GT(f[ShearVector::P0], 0.0) << p0;
    EXPECT_EQ(f[ShearVector::RU], 1.0 - f[ShearVector::PRESS] / f[ShearVector::P0]) << p0;
  }
}

// two fixes may shear with one compute: each has its own p0 and r_u
TEST_F(Shear, TwoFixesShareOneCompute)
{
  Lammps lmp;
  const double p = read(lmp);
  lmp.cmds({shear_cmd(p), "fix sh2 all grflow/shear w net " + fmt_double(VX) + " " +
                              fmt_double(0.3 * p) + " progress no",
            "run 100 post no"});
  const auto f1 = fvec(lmp, "sh", ShearVector::NOUT);
  const auto f2 = fvec(lmp, "sh2", ShearVector::NOUT);
  EXPECT_EQ(f1[ShearVector::P0], f2[ShearVector::P0]);    // both took the same start
  EXPECT_EQ(f1[ShearVector::RU], f2[ShearVector::RU]);
  EXPECT_EQ(f1[ShearVector::RU], 1.0 - f1[ShearVector::PRESS] / f1[ShearVector::P0]);
}

// the fix's r_u is 1 - p/p0 of its own p0, at the start (0) and after it;
// the compute without a p0 keyword has r_u = 0 throughout
TEST_F(Shear, FixOwnsItsRu)
{
  Lammps lmp;
  const double p = read(lmp);
  EXPECT_EQ(cvec(lmp, "net")[NetVector::RU], 0.0);    // no p0
  lmp.cmds({shear_cmd(p), "run 0 post no"});
  const auto f = fvec(lmp, "sh", ShearVector::NOUT);
  const auto c = cvec(lmp, "net");
  EXPECT_GT(f[ShearVector::P0], 0.0);
  EXPECT_EQ(f[ShearVector::P0], c[NetVector::PRESS]);    // taken at the start
  EXPECT_EQ(f[ShearVector::RU], 0.0);
  EXPECT_EQ(c[NetVector::RU], 0.0);
  lmp.cmd("run 100 post no");
  const auto f2 = fvec(lmp, "sh", ShearVector::NOUT);
  const auto c2 = cvec(lmp, "net");
  EXPECT_EQ(f2[ShearVector::P0], f[ShearVector::P0]);
  EXPECT_EQ(f2[ShearVector::RU], 1.0 - f2[ShearVector::PRESS] / f[ShearVector::P0]);
  EXPECT_EQ(c2[NetVector::RU], 0.0);
}

TEST_F(Shear, GluedLayerMovesWithTheWall)
{
  Lammps lmp;
  // the layer: spheres with centres within 1.2 mm of the top wall, not
  // integrated by fix nve/sphere
  const double p = read(lmp, "");
  const double zcut = wallv(lmp)[WallVector::HI_Z] - 1.2e-3;
  const std::string log = workfile("shear_glue.log");
  lmp.cmds({"variable top atom z>" + fmt_double(zcut), "group glue variable top",
            "group mobile subtract all glue", "fix nve mobile nve/sphere",
            shear_cmd(p, "glue glue"), "log " + log, "run 0 post no", "log none"});
  // no false warning: the fix's group is all, its integrated atoms the glue
  EXPECT_EQ(slurp(log).find("time integrated more than once"), std::string::npos);
  {
    Lammps twice;
    read(twice, "fix nve all nve/sphere");
    twice.cmds({"variable top atom z>" + fmt_double(zcut), "group glue variable top",
                shear_cmd(p, "glue glue"), "log " + log, "run 0 post no", "log none"});
    EXPECT_NE(slurp(log).find("One or more atoms are time integrated more than once"),
              std::string::npos);
  }
  const int n = lmp.natoms();
  std::vector<int> image0(n), image(n);
  lammps_gather_atoms(lmp.handle, (char *) "image", 0, 1, image0.data());
  std::vector<double> g(n);
  {
    const auto x = lmp.gather3("x");
    for (int i = 0; i < n; i++) g[i] = x[3 * i + 2] > zcut ? 1.0 : 0.0;
  }
  int ng = 0;
  for (double v : g) ng += v > 0.5;
  measured("glued spheres", ng);
  ASSERT_GE(ng, 10);
  ASSERT_LT(ng, n / 2);
  ASSERT_EQ(ng, (int) lammps_eval(lmp.handle, "count(glue)"));

  const auto x0 = lmp.gather3("x");
  const double lx = lmp.thermo("lx");
  const double xw0 = shear(lmp)[ShearVector::XWALL];
  double errx = 0.0;
  int nrev = 0;
  for (int chunk = 0; chunk < 150; chunk++) {
    lmp.cmd("run " + std::to_string(EVERY) + " post no");
    const auto s = shear(lmp);
    nrev = (int) s[ShearVector::REVERSALS];
    const auto x = lmp.gather3("x"), v = lmp.gather3("v"), w = lmp.gather3("omega");
    lammps_gather_atoms(lmp.handle, (char *) "image", 0, 1, image.data());
    const double dxw = s[ShearVector::XWALL] - xw0;
    for (int i = 0; i < n; i++) {
      if (g[i] < 0.5) continue;
      const int ix0 = (image0[i] & 1023) - 512, ix = (image[i] & 1023) - 512;
      const double ux = x[3 * i] + ix * lx - (x0[3 * i] + ix0 * lx);
      errx = std::max(errx, std::fabs(ux - dxw));
      ASSERT_EQ(x[3 * i + 1], x0[3 * i + 1]);
      ASSERT_EQ(x[3 * i + 2], x0[3 * i + 2]);
      ASSERT_EQ(v[3 * i], s[ShearVector::DIRECTION] * VX);
      ASSERT_EQ(v[3 * i + 1], 0.0);
      ASSERT_EQ(v[3 * i + 2], 0.0);
      ASSERT_EQ(w[3 * i], 0.0);
      ASSERT_EQ(w[3 * i + 1], 0.0);
      ASSERT_EQ(w[3 * i + 2], 0.0);
    }
  }
  measured("glue: max |x - x0 - x_w| (m)", errx);
  measured("glue: reversals", nrev);
  EXPECT_LT(errx, 1.0e-15);
  EXPECT_GE(nrev, 1);
}

TEST_F(Shear, StopCyclesAndHalt)
{
  long stop_step = -1;
  {
    Lammps lmp;
    const double p = read(lmp);
    lmp.cmd(shear_cmd(p, "stop_cycles 1"));
    for (int chunk = 0; chunk < 400 && stop_step < 0; chunk++) {
      lmp.cmd("run " + std::to_string(EVERY) + " post no");
      const auto s = shear(lmp);
      // N reaches 1 at the first zero-crossing of tau after reversal 2
      const bool one = s[ShearVector::REVERSALS] >= 3 ||
          (s[ShearVector::REVERSALS] == 2 && s[ShearVector::N_EVENT] == 1.0);
      ASSERT_EQ(s[ShearVector::DONE], one ? 1.0 : 0.0) << step(lmp);
      if (one) stop_step = step(lmp);
    }
  }
  ASSERT_GT(stop_step, 0);
  Lammps lmp;
  const double p = read(lmp);
  const long start = step(lmp);
  lmp.cmds({shear_cmd(p, "stop_cycles 1"), "variable done equal f_sh[13]",
            "fix stop all halt " + std::to_string(EVERY) + " v_done > 0.5 error continue",
            "run 20000"});
  printf("[ measured ] N = 1 (done) at step %ld, %ld steps of shear\n", stop_step,
         stop_step - start);
  EXPECT_EQ(step(lmp), stop_step);
  EXPECT_EQ(shear(lmp)[ShearVector::REVERSALS], 2.0);
  EXPECT_EQ(shear(lmp)[ShearVector::N_EVENT], 1.0);
  EXPECT_EQ(shear(lmp)[ShearVector::EVENT], 2.0);
  EXPECT_EQ(shear(lmp)[ShearVector::DONE], 1.0);
}

// halt yes ends the runs where fix halt on the event and done flags (error
// continue) ends them: at each event, and once done at every check
TEST_F(Shear, HaltYesEndsRunsAsFixHalt)
{
  const std::string every = std::to_string(EVERY);
  auto ends = [](Lammps &lmp) {
    std::vector<long> out;
    for (int k = 0; k < 6; k++) {
      lmp.cmd("run 20000 post no");
      out.push_back(step(lmp));
    }
    return out;
  };
  std::vector<long> ref, got;
  {
    Lammps lmp;
    const double p = read(lmp);
    lmp.cmds({shear_cmd(p, "stop_cycles 1"), "variable ev equal f_sh[14]",
              "variable done equal f_sh[13]",
              "fix ev all halt " + every + " v_ev != 0 error continue message no",
              "fix stop all halt " + every + " v_done > 0.5 error continue message no"});
    ref = ends(lmp);
  }
  {
    Lammps lmp;
    const double p = read(lmp);
    lmp.cmd(shear_cmd(p, "stop_cycles 1 halt yes"));
    got = ends(lmp);
  }
  printf("[ measured ] runs ended at steps %ld %ld %ld %ld %ld %ld\n", got[0], got[1], got[2], got[3],
         got[4], got[5]);
  EXPECT_EQ(got, ref);
  // four events (two reversals, two zero-crossings: N = 1, done), then one
  // check each, and none reaches the end of its 20000 steps
  EXPECT_EQ(got[5] - got[4], EVERY);
  EXPECT_LT(got[3] - got[0], 20000);
}

// reversal steps from a fix print file (lines "step reversals"): the steps
// where the count differs from the line before, the first line compared
// with `last`
std::vector<long> reversal_steps(const std::string &file, double last = 0.0)
{
  std::ifstream in(file);
  std::vector<long> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    long s;
    double rev;
    ss >> s >> rev;
    if (rev != last) out.push_back(s);
    last = rev;
  }
  return out;
}

void shear_run_with_record(Lammps &lmp, double p, const std::string &file, bool newfix)
{
  if (newfix) lmp.cmd(Shear::shear_cmd(p, "liquefaction 0.002"));
  lmp.cmds({"variable rev equal f_sh[2]",
            "fix rec all print " + std::to_string(EVERY) + " \"$(step) ${rev}\" file " + file +
                " screen no"});
}

// A: one run of 6000 steps.  A2: the same split into two runs in one
// instance, with write_restart at the split.  B: read_restart in a new
// instance, the same fixes and compute, the rest of the run.  Splits at a
// multiple of every and elsewhere.  B must take the same decisions as A,
// and reproduce A2 to round-off.  (A2 and A differ by more than round-off
// even without this fix: a new run's setup recomputes the forces with
// full-step instead of half-step velocities, and the damping differs.)
TEST_F(Shear, RestartContinuesTheProtocol)
{
  const int S = 6000;
  std::vector<double> xa, wa, sa;
  std::vector<long> ra;
  {
    Lammps lmp;
    const double p = read(lmp);
    const std::string f = workfile("shear_A.txt");
    shear_run_with_record(lmp, p, f, true);
    lmp.cmd("run " + std::to_string(S));
    lmp.cmd("unfix rec");
    ra = reversal_steps(f);
    xa = lmp.gather3("x");
    wa = lmp.gather3("omega");
    sa = shear(lmp);
  }
  printf("[ measured ] uninterrupted: reversal steps%s\n", join(ra).c_str());
  ASSERT_GE(ra.size(), 3u);
  for (int split : {3000, 3010}) {
    const std::string tag = std::to_string(split);
    const std::string mid = workfile("shear_mid.restart");
    const std::string f1 = workfile("shear_A2.txt"), f2 = workfile("shear_B.txt");
    std::vector<double> xa2, wa2, sa2;
    std::vector<long> ra2;
    double rev_mid = 0.0;
    {
      Lammps lmp;
      const double p = read(lmp);
      shear_run_with_record(lmp, p, f1, true);
      lmp.cmds({"run " + std::to_string(split), "write_restart " + mid});
      rev_mid = shear(lmp)[ShearVector::REVERSALS];
      lmp.cmds({"run " + std::to_string(S - split), "unfix rec"});
      ra2 = reversal_steps(f1);
      xa2 = lmp.gather3("x");
      wa2 = lmp.gather3("omega");
      sa2 = shear(lmp);
    }
    Lammps lmp;
    // the same fix command, with the same ID (tau_amp from the old p0),
    // before the first run: that run's init drops unclaimed restart state
    read(lmp, "fix nve all nve/sphere", mid,
         "fix sh all grflow/shear w net " + fmt_double(VX) + " " +
             fmt_double(0.3 * sa[ShearVector::P0]) + " every " + std::to_string(EVERY) +
             " liquefaction 0.002");
    EXPECT_EQ(shear(lmp)[ShearVector::REVERSALS], rev_mid);
    shear_run_with_record(lmp, 0.0, f2, false);
    lmp.cmd("run " + std::to_string(S - split));
    lmp.cmd("unfix rec");
    std::vector<long> rb;
    for (long st : ra)
      if (st <= step(lmp) - (S - split)) rb.push_back(st);
    for (long st : reversal_steps(f2, rev_mid)) rb.push_back(st);
    printf("[ measured ] split at %d: reversal steps A2%s, B%s\n", split, join(ra2).c_str(),
           join(rb).c_str());
    EXPECT_EQ(ra2, ra) << "split at " << split;
    EXPECT_EQ(rb, ra) << "split at " << split;
    const auto sb = shear(lmp);
    for (int k : {ShearVector::DIRECTION, ShearVector::REVERSALS, ShearVector::XWALL,
                  ShearVector::P0, ShearVector::STEP_IL, ShearVector::N_IL, ShearVector::N_EVENT}) {
      EXPECT_EQ(sb[k], sa[k]) << "entry " << k + 1 << " split " << split;
      EXPECT_EQ(sa2[k], sa[k]) << "entry " << k + 1 << " split " << split;
    }
    EXPECT_DOUBLE_EQ(sb[ShearVector::TIME_IL], sa[ShearVector::TIME_IL]);
    const auto xb = lmp.gather3("x"), wb = lmp.gather3("omega");
    const double dx = max_rel_diff(xb, xa2), dw = max_rel_diff(wb, wa2);
    measured("restart B vs split A2: x rel diff (split " + tag + ")", dx);
    measured("restart B vs split A2: omega rel diff (split " + tag + ")", dw);
    measured("split A2 vs one run A: x rel diff (split " + tag + ")", max_rel_diff(xa2, xa));
    measured("split A2 vs one run A: omega rel diff (split " + tag + ")", max_rel_diff(wa2, wa));
    EXPECT_LT(dx, 1.0e-13);
    EXPECT_LT(dw, 1.0e-10);
    EXPECT_LT(max_rel_diff(xb, xa), 1.0e-7);
  }
}

// runs of 7 steps (most of them start between two checks) take the same
// decisions as one run: the setup of a run reads tau but decides only at
// multiples of every
TEST_F(Shear, DamagedRestartData)
{
  // the fix's block of a restart file goes through the checks of
  // grflow_host.h (tested in full for fix grflow/wall): a version from
  // the future and a NaN value are errors naming this fix
  const std::string file = workfile("shear_damage.restart");
  double p;
  {
    Lammps lmp;
    p = read(lmp);
    lmp.cmds({shear_cmd(p), "run 100 post no", "write_restart " + file});
  }
  const std::string nan_file =
      damaged_restart(file, 13.0, 4, std::numeric_limits<double>::quiet_NaN(), "shear_nan.restart",
                      2.0);    // (fix grflow/compress's block holds 13 values too, format 1)
  const std::string v99_file = damaged_restart(file, 13.0, 1, 99.0, "shear_v99.restart", 2.0);
  const std::string v1_file = damaged_restart(file, 13.0, 1, 1.0, "shear_v1.restart", 2.0);
  ASSERT_NE(nan_file, "");
  ASSERT_NE(v1_file, "");
  auto setup = [p](const std::string &restart) -> std::vector<std::string> {
    return {"read_restart " + restart,
            "comm_modify vel yes",
            "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi 8.0e-3",
            "variable zlo equal f_w[4]",
            "variable zhi equal f_w[10]",
            "compute net all grflow/network zlimits v_zlo v_zhi",
            shear_cmd(p)};
  };
  EXPECT_EQ(first_error(setup(file)), "");
  std::string msg = first_error(setup(v99_file));
  EXPECT_NE(msg.find("Fix grflow/shear sh: restart data of format version 99"), std::string::npos)
      << msg;
  msg = first_error(setup(nan_file));
  EXPECT_NE(msg.find("Fix grflow/shear sh: restart value 2 of 13 is nan"), std::string::npos)
      << msg;
  // format 1 (before the fractional cycle count) cannot go on
  msg = first_error(setup(v1_file));
  EXPECT_NE(msg.find("Fix grflow/shear sh: restart data of format version 1 were written before"),
            std::string::npos)
      << msg;
}

TEST_F(Shear, ShortRunsDecideOnlyEveryN)
{
  const int S = 4200;
  std::vector<long> ra, rb;
  std::vector<double> sa, sb;
  for (int chunk : {S, 7}) {
    Lammps lmp;
    const double p = read(lmp);
    const std::string f = workfile("shear_chunks.txt");
    lmp.cmd(shear_cmd(p, "every 100"));    // a wide window between checks
    shear_run_with_record(lmp, p, f, false);
    for (int done = 0; done < S; done += chunk)
      lmp.cmd("run " + std::to_string(std::min(chunk, S - done)) + " post no");
    lmp.cmd("unfix rec");
    (chunk == S ? ra : rb) = reversal_steps(f);
    (chunk == S ? sa : sb) = shear(lmp);
  }
  printf("[ measured ] one run: reversal steps%s; runs of 7 steps:%s\n", join(ra).c_str(),
         join(rb).c_str());
  ASSERT_GE(ra.size(), 3u);
  for (long st : ra) EXPECT_EQ(st % 100, 0) << st;
  EXPECT_EQ(rb, ra);
  EXPECT_EQ(sb[ShearVector::REVERSALS], sa[ShearVector::REVERSALS]);
  EXPECT_EQ(sb[ShearVector::DIRECTION], sa[ShearVector::DIRECTION]);
  EXPECT_NEAR(sb[ShearVector::XWALL], sa[ShearVector::XWALL], 1.0e-18);
}

// ---------------------------------------------------------------------------
// Errors
// ---------------------------------------------------------------------------

TEST_F(Shear, BadArguments)
{
  std::vector<std::string> setup = {"read_restart " + restart,
                                    "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi 8.0e-3",
                                    "compute net all grflow/network", "group none empty"};
  struct Case {
    const char *line, *expect;
  } cases[] = {
      {"fix sh all grflow/shear w net 0.02", "Illegal fix grflow/shear command: expected wall-ID"},
      {"fix sh all grflow/shear w net", "Illegal fix grflow/shear command"},
      {"fix sh all grflow/shear w net 0 1000", "Fix grflow/shear vx must be > 0, got 0"},
      {"fix sh all grflow/shear w net -0.1 1000", "vx must be > 0"},
      {"fix sh all grflow/shear w net 0.02 0", "Fix grflow/shear tau_amp must be > 0, got 0"},
      {"fix sh all grflow/shear w net 0.02 -5", "tau_amp must be > 0"},
      {"fix sh all grflow/shear w net abc 1000", "fix grflow/shear vx expects a number, got 'abc'"},
      {"fix sh all grflow/shear w net 0.02 1000 foo 1", "Unknown fix grflow/shear keyword: foo"},
      {"fix sh all grflow/shear w net 0.02 1000 foo", "Unknown fix grflow/shear keyword: foo"},
      {"fix sh all grflow/shear w net 0.02 1000 every", "fix grflow/shear every"},
      {"fix sh all grflow/shear w net 0.02 1000 every 0", "Fix grflow/shear every must be >= 1"},
      {"fix sh all grflow/shear w net 0.02 1000 every 2.5",
       "fix grflow/shear every expects an integer, got '2.5'"},
      {"fix sh all grflow/shear w net 0.02 1000 liquefaction 0",
       "Fix grflow/shear liquefaction threshold must be in (0,1], got 0"},
      {"fix sh all grflow/shear w net 0.02 1000 liquefaction 1.5", "must be in (0,1]"},
      {"fix sh all grflow/shear w net 0.02 1000 stop_cycles 0",
       "Fix grflow/shear stop_cycles must be > 0"},
      {"fix sh all grflow/shear w net 0.02 1000 stop_after_liquefaction -1",
       "Fix grflow/shear stop_after_liquefaction must be > 0"},
      {"fix sh all grflow/shear w net 0.02 1000 stop_gamma 0",
       "Fix grflow/shear stop_gamma must be > 0"},
      {"fix sh all grflow/shear w net 0.02 1000 glue nogroup",
       "Fix grflow/shear glue group nogroup does not exist"},
      {"fix sh all grflow/shear w net 0.02 1000 progress maybe",
       "Expected boolean parameter instead of 'maybe'"},
      {"fix sh all grflow/shear w net 0.02 1000 halt 1.5",
       "Expected boolean parameter instead of '1.5'"},
  };
  for (const auto &c : cases) {
    const std::string msg = error_after(setup, c.line);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.line << " -> '" << msg << "'";
  }

  // checked at init (run): the wall fix and the compute
  struct InitCase {
    std::vector<std::string> extra;
    const char *line, *expect;
  } init_cases[] = {
      {{},
       "fix sh all grflow/shear nowall net 0.02 1000",
       "Fix grflow/shear: fix nowall does not exist"},
      {{"fix nve all nve/sphere"},
       "fix sh all grflow/shear nve net 0.02 1000",
       "Fix grflow/shear: fix nve is not a fix grflow/wall"},
      {{"fix w1 all grflow/wall 1.0e6 1.15 zlo 0.0"},
       "fix sh all grflow/shear w1 net 0.02 1000",
       "Fix grflow/shear: fix w1 must have both walls, zlo and zhi"},
      {{"fix w2 all grflow/wall 1.0e6 1.15 zhi 8.0e-3"},
       "fix sh all grflow/shear w2 net 0.02 1000",
       "must have both walls"},
      {{},
       "fix sh all grflow/shear w nonet 0.02 1000",
       "Fix grflow/shear: compute nonet does not exist"},
      {{"compute ke all ke"},
       "fix sh all grflow/shear w ke 0.02 1000",
       "Fix grflow/shear: compute ke is not a compute grflow/network"},
      // its setup() reads the compute, which reads the wall's contacts of
      // the step: the wall fix must be set up first
      {{"unfix w"},
       "fix sh all grflow/shear w net 0.02 1000",
       "fix grflow/wall w has no contacts for step"},
  };
  for (const auto &c : init_cases) {
    auto s = setup;
    s.insert(s.end(), c.extra.begin(), c.extra.end());
    s.push_back(c.line);
    if (c.extra == std::vector<std::string>{"unfix w"}) s.push_back(setup[1]);    // after fix sh
    const std::string msg = error_after(s, "run 0");
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.line << " -> '" << msg << "'";
  }

  // the glue group deleted after the fix was made
  {
    auto s = setup;
    s.insert(
        s.end(),
        {"group top id 1", "fix sh all grflow/shear w net 0.02 1000 glue top", "group top delete"});
    const std::string msg = error_after(s, "run 0");
    EXPECT_NE(msg.find("Fix grflow/shear glue group top was deleted"), std::string::npos) << msg;
  }

  // no stress when shearing starts: spheres apart, p = 0
  const std::string msg = error_after(
      {"units si", "atom_style sphere", "boundary p p f", "region box block 0 0.01 0 0.01 0 0.01",
       "create_box 1 box", "create_atoms 1 single 0.005 0.005 0.005",
       "set atom 1 diameter 1.0e-3 density 2650", "comm_modify vel yes",
       "pair_style granular/grflow", "pair_coeff * * 1.0e6 1.15",
       "fix w all grflow/wall 1.0e6 1.15 zlo 0.001 zhi 0.009", "compute net all grflow/network",
       "fix sh all grflow/shear w net 0.02 1000"},
      "run 0");
  EXPECT_NE(msg.find("Fix grflow/shear: the mean stress is 0 when shearing starts; it must be > "
                     "0 to define r_u"),
            std::string::npos)
      << msg;
}

}    // namespace
