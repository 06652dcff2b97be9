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
   fix grflow/drag through the LAMMPS library API:
   - it is LAMMPS's fix langevin at zero temperature with omega yes (and
     without it), bit for bit, on 64 polydisperse spheres in contact;
   - on free spheres the velocities and spins decay as fix nve/sphere
     integrates F = -m v / t_damp and T = -(10/3) I omega / t_damp by hand
     (the velocity-Verlet recurrence, below); atoms outside the group keep
     theirs;
   - bad input gives a clear error.
------------------------------------------------------------------------- */

#include "lammps_fixture.h"

#include <cmath>

using namespace grflow_test;

namespace {

const double DT = 5.0e-7, TDAMP = 1.0e-4;

// 64 spheres of 1.9-2.1 mm on a simple cubic lattice of 1.9 mm (so that
// neighbours overlap), SI units, deterministic velocities and spins; with
// spacing 5 mm instead none touches another
void spheres(Lammps &lmp, double spacing)
{
  lmp.cmds({"units si", "atom_style sphere", "atom_modify map array", "boundary p p p",
            "comm_modify vel yes", "lattice sc " + fmt_double(spacing),
            "region box block 0 4 0 4 0 4 units lattice", "create_box 1 box",
            "create_atoms 1 box", "variable d atom 1.9e-3+0.2e-3*(0.5+0.5*sin(7*id))",
            "set group all diameter v_d density 2650", "variable vx atom 0.01*sin(2*id)",
            "variable vy atom 0.01*cos(3*id)", "variable vz atom 0.01*sin(5*id+1)",
            "velocity all set v_vx v_vy v_vz", "variable wx atom 20*sin(11*id)",
            "variable wy atom 20*cos(13*id)", "variable wz atom 20*sin(17*id+2)",
            "set group all omega v_wx v_wy v_wz", "pair_style granular/grflow",
            "pair_coeff * * 1.0e6 1.15", "neighbor 2.0e-4 bin", "timestep " + fmt_double(DT),
            "fix nve all nve/sphere"});
}

struct State {
  std::vector<double> x, v, w, f, t;
};

State state(Lammps &lmp)
{
  return {lmp.gather3("x"), lmp.gather3("v"), lmp.gather3("omega"), lmp.gather3("f"),
          lmp.gather3("torque")};
}

// a - b == 0 for every entry (a +0.0 and a -0.0 count as equal: fix
// langevin adds a random term of zero, which may be -0.0)
int count_different(const std::vector<double> &a, const std::vector<double> &b)
{
  int n = 0;
  for (size_t k = 0; k < a.size(); k++)
    if (!(a[k] == b[k])) n++;
  return n;
}

}    // namespace

// the same trajectory as fix langevin 0.0 0.0 t_damp seed [omega yes]
TEST(Drag, IsLangevinAtZeroTemperature)
{
  for (const std::string omega : {" omega yes", ""}) {
    State a, b;
    {
      Lammps lmp;
      spheres(lmp, 1.9e-3);
      lmp.cmds({"fix drag all grflow/drag " + fmt_double(TDAMP) + omega, "run 400"});
      a = state(lmp);
    }
    {
      Lammps lmp;
      spheres(lmp, 1.9e-3);
      lmp.cmds({"fix drag all langevin 0.0 0.0 " + fmt_double(TDAMP) + " 48279" + omega,
                "run 400"});
      b = state(lmp);
    }
    ASSERT_EQ(a.x.size(), 3u * 64);
    EXPECT_EQ(count_different(a.x, b.x), 0) << omega;
    EXPECT_EQ(count_different(a.v, b.v), 0) << omega;
    EXPECT_EQ(count_different(a.w, b.w), 0) << omega;
    EXPECT_EQ(count_different(a.f, b.f), 0) << omega;
    EXPECT_EQ(count_different(a.t, b.t), 0) << omega;
    // the run is not trivial: the spheres are in contact, and they slowed
    double t0 = 0.0;
    for (double t : a.t) t0 = std::max(t0, std::fabs(t));
    EXPECT_GT(t0, 0.0);
  }
}

// free spheres: fix nve/sphere with F = -m v / tau gives, with a = dt / (2 tau),
// v_1 = v_0 (1 - a)^2 and v_(n+1) = (1 - 2a) v_n (the force of a step is
// taken at the half-step velocity; setup takes it at v_0); the spins
// likewise with b = (10/3) a.  Atoms outside the group keep v and omega.
TEST(Drag, FreeSpheresDecayAsIntegratedByHand)
{
  const int n = 200;
  Lammps lmp;
  spheres(lmp, 5.0e-3);
  const State s0 = state(lmp);
  lmp.cmds({"group odd id 1:64:2", "fix drag odd grflow/drag " + fmt_double(TDAMP) + " omega yes",
            "run " + std::to_string(n)});
  const State s = state(lmp);
  const double a = 0.5 * DT / TDAMP, b = (10.0 / 3.0) * a;
  const double fv = (1 - a) * (1 - a) * std::pow(1 - 2 * a, n - 1);
  const double fw = (1 - b) * (1 - b) * std::pow(1 - 2 * b, n - 1);
  double dv = 0.0, dw = 0.0, dv_out = 0.0, dw_out = 0.0;
  for (int i = 0; i < 64; i++) {
    const bool in = (i % 2 == 0);    // IDs 1, 3, ... (gather3 orders by ID)
    for (int k = 0; k < 3; k++) {
      const int j = 3 * i + k;
      const double v = in ? fv * s0.v[j] : s0.v[j], w = in ? fw * s0.w[j] : s0.w[j];
      double &ev = in ? dv : dv_out, &ew = in ? dw : dw_out;
      ev = std::max(ev, std::fabs(s.v[j] - v) / 0.01);
      ew = std::max(ew, std::fabs(s.w[j] - w) / 20.0);
    }
  }
  printf("[ measured ] after %d steps: v by %.6f, omega by %.6f of their start\n", n, fv, fw);
  // n steps of a few operations each, relative round-off 1.1e-16 apiece
  EXPECT_LT(measured("largest |v - v_hand| / v_max", dv), 1.0e-12);
  EXPECT_LT(measured("largest |omega - omega_hand| / omega_max", dw), 1.0e-12);
  EXPECT_EQ(dv_out, 0.0);
  EXPECT_EQ(dw_out, 0.0);
  // the test sees a decay: 200 steps of 5e-7 s are one t_damp
  EXPECT_LT(fv, 0.4);
  EXPECT_LT(fw, 0.04);
}

TEST(Drag, BadInput)
{
  auto after_spheres = [](const std::vector<std::string> &extra, const std::string &bad) {
    Lammps lmp;
    spheres(lmp, 5.0e-3);
    lmp.cmds(extra);
    return lmp.error_of(bad);
  };
  struct Case {
    const char *line, *expect;
  } cases[] = {
      {"fix d all grflow/drag", "Illegal fix grflow/drag command: missing argument"},
      {"fix d all grflow/drag 0", "t_damp = 0 must be > 0"},
      {"fix d all grflow/drag -1e-3", "t_damp = -1e-3 must be > 0"},
      {"fix d all grflow/drag nan", "Expected floating point parameter instead of 'nan'"},
      {"fix d all grflow/drag fast", "Expected floating point parameter instead of 'fast'"},
      {"fix d all grflow/drag 1e-3 omega", "Illegal fix grflow/drag omega command: missing"},
      {"fix d all grflow/drag 1e-3 omega maybe", "Expected boolean parameter instead of 'maybe'"},
      {"fix d all grflow/drag 1e-3 spin yes", "Fix grflow/drag d: unknown keyword 'spin'"},
  };
  for (const auto &c : cases) {
    const std::string msg = after_spheres({}, c.line);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.line << " -> '" << msg << "'";
  }
  // a point particle has no moment of inertia (at the run, as fix langevin;
  // without the pair style and fix nve/sphere, which would refuse it first)
  std::string msg = after_spheres({"pair_style none", "unfix nve",
                                   "fix d all grflow/drag 1e-3 omega yes", "set atom 5 diameter 0"},
                                  "run 0");
  EXPECT_NE(msg.find("omega yes: group all has particles of radius 0"), std::string::npos) << msg;
  // without per-atom masses or spins
  msg = first_error({"units si", "atom_style atomic", "region b block 0 1 0 1 0 1",
                     "create_box 1 b", "fix d all grflow/drag 1e-3"});
  EXPECT_NE(msg.find("needs per-atom masses"), std::string::npos) << msg;
  msg = first_error({"units si", "atom_style atomic", "atom_modify map array",
                     "fix p all property/atom rmass", "region b block 0 1 0 1 0 1",
                     "create_box 1 b", "fix d all grflow/drag 1e-3 omega yes"});
  EXPECT_NE(msg.find("omega yes needs the atom attributes radius, omega and torque"),
            std::string::npos)
      << msg;
}
