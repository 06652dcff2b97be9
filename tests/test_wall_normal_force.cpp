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
   fix grflow/wall normal_force clipped|unclipped through the LAMMPS
   library API:
   - a sphere bouncing head-on off the lo wall: the restitution
     coefficient against the closed forms (the wall a body of infinite
     mass: m_eff = m) and against stock fix wall/gran hooke without and
     with limit_damping;
   - while the unclipped contact is in tension (f_n < 0) the contact
     record says "touching, no force": compute grflow/network does not
     count it;
   - bad input gives a clear error.
------------------------------------------------------------------------- */

#include "fix_grflow_wall.h"
#include "lammps_fixture.h"

#include "lammps.h"
#include "modify.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace grflow_test;
using namespace LAMMPS_NS::GRFLOW;

namespace {

const double PI = 3.14159265358979323846;
const double A = 0.5e-3, V0 = 0.1;    // the smallest sphere of the sample, approach speed

// a sphere of radius A just above the lo wall at z = 0, moving down at V0;
// wall: the fix command after "fix w all "
void bounce_setup(Lammps &lmp, const std::string &wall, double dt)
{
  lmp.cmds({"units si", "atom_style sphere", "atom_modify map array", "boundary p p f",
            "region box block -0.002 0.002 -0.002 0.002 -0.001 0.003", "create_box 1 box",
            "create_atoms 1 single 0 0 " + fmt_double(1.0001 * A) + " units box",
            "set atom 1 diameter " + fmt_double(2.0 * A) + " density 2650 vz " + fmt_double(-V0),
            "fix w all " + wall, "fix nve all nve/sphere", "timestep " + fmt_double(dt)});
}

struct Closed {
  double t_c, e_unclipped, e_clipped;
};

Closed closed_forms(double kn, double cn, double m)
{
  const double w0 = sqrt(kn / m), eta = cn / (2.0 * m);
  const double w = sqrt(w0 * w0 - eta * eta), zeta = eta / w0;
  const double t_f = (PI - atan2(2.0 * eta * w, w * w - eta * eta)) / w;
  return {PI / w, exp(-PI * zeta / sqrt(1.0 - zeta * zeta)), exp(-eta * t_f)};
}

TEST(WallNormalForce, HeadOnRestitutionBothLaws)
{
  const double m = 2650.0 * 4.0 / 3.0 * PI * A * A * A;
  const Closed c = closed_forms(1.0e6, 1.15, m);
  // 20000 steps per contact (first-order error of e below 3e-4 of e,
  // test_contact_kernel.cpp); the sphere starts 0.05 um above the wall
  const double dt = c.t_c / 20000;
  const std::string nsteps = "run 60000";
  const std::string stock = "wall/gran granular hooke 1.0e6 1.15 damping velocity ";
  const std::string stock_t = "tangential linear_history 8.0e5 0.2 0.5 zplane 0.0 NULL";
  std::vector<double> v[4];
  const std::string walls[4] = {"grflow/wall 1.0e6 1.15 zlo 0.0 normal_force unclipped",
                                "grflow/wall 1.0e6 1.15 zlo 0.0", stock + stock_t,
                                stock + "limit_damping " + stock_t};
  for (int k = 0; k < 4; k++) {
    Lammps lmp;
    bounce_setup(lmp, walls[k], dt);
    lmp.cmd(nsteps);
    v[k] = lmp.gather3("v");
  }
  const double eu = v[0][2] / V0, ec = v[1][2] / V0;
  printf("[ measured ] wall, d = 1 mm: e unclipped closed form %.5f, grflow/wall %.5f, stock "
         "%.5f; clipped closed form %.5f, grflow/wall %.5f, stock limit_damping %.5f\n",
         c.e_unclipped, eu, v[2][2] / V0, c.e_clipped, ec, v[3][2] / V0);
  EXPECT_NEAR(eu, c.e_unclipped, 1.0e-3 * c.e_unclipped);
  EXPECT_NEAR(ec, c.e_clipped, 1.0e-3 * c.e_clipped);
  EXPECT_GT(ec - eu, 0.1);
  // stock: the same law (head-on: no sliding, so its torque arm does not enter)
  EXPECT_LT(measured("wall head-on unclipped vs stock", max_rel_diff(v[0], v[2])), 1.0e-10);
  EXPECT_LT(measured("wall head-on clipped vs stock limit_damping", max_rel_diff(v[1], v[3])),
            1.0e-10);
}

// while the sphere leaves the wall the unclipped force pulls it (the wall
// is pulled up: its force, f_w[3], is > 0) and the contact record holds
// -1: touching, not force-bearing
TEST(WallNormalForce, TensionIsTouchingNotForceBearing)
{
  const double m = 2650.0 * 4.0 / 3.0 * PI * A * A * A;
  const Closed c = closed_forms(1.0e6, 1.15, m);
  const double dt = c.t_c / 200;
  Lammps lmp;
  bounce_setup(lmp, "grflow/wall 1.0e6 1.15 zlo 0.0 normal_force unclipped", dt);
  auto *lmpp = static_cast<LAMMPS_NS::LAMMPS *>(lmp.handle);
  auto *wall = dynamic_cast<LAMMPS_NS::FixGRFLOWWall *>(lmpp->modify->get_fix_by_id("w"));
  ASSERT_NE(wall, nullptr);
  EXPECT_EQ(wall->cell().normal_law(), NORMAL_UNCLIPPED);
  int tension = 0, pushing = 0;
  lmp.cmd("run 0");
  for (int step = 0; step < 400; step++) {
    lmp.cmd("run 1 pre no post no");
    const double fz = lmp.fix_vector("w", 3)[2];
    const double arm = wall->cell().contact_arm(0, LAMMPS_NS::GRFLOW::FlatWalls::LO);
    if (fz > 0.0) {
      ++tension;
      EXPECT_EQ(arm, -1.0) << "step " << step;
    } else if (fz < 0.0) {
      ++pushing;
      EXPECT_GT(arm, 0.0) << "step " << step;
    }
  }
  EXPECT_GT(tension, 0);
  EXPECT_GT(pushing, tension);
}

TEST(WallNormalForce, BadInput)
{
  const std::vector<std::string> box = {"units si", "atom_style sphere", "boundary p p f",
                                        "region box block 0 0.01 0 0.01 0 0.01",
                                        "create_box 1 box"};
  std::string msg =
      error_after(box, "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 normal_force sometimes");
  EXPECT_NE(msg.find("Unknown fix grflow/wall normal_force value sometimes: expected clipped or "
                     "unclipped"),
            std::string::npos)
      << msg;
  msg = error_after(box, "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 normal_force");
  EXPECT_NE(msg.find("fix grflow/wall normal_force"), std::string::npos) << msg;
  // a coefficient keyword after it is still misplaced
  msg = error_after(box, "fix w all grflow/wall 1.0e6 1.15 normal_force unclipped mut 0.3 zlo 0");
  EXPECT_NE(msg.find("must come right after kn cn"), std::string::npos) << msg;
}

}    // namespace
