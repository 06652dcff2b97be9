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
   fix grflow/wall through the LAMMPS library API:
   - one sphere pressed on the lo or the hi wall: forces, torques, wall
     force output and virial against the contact law written out by hand;
   - spheres sliding, rolling and spinning on moving walls follow the
     kernel with an independent velocity-Verlet integrator, bit for bit;
   - stock fix wall/gran: the same law except for the sliding torque arm
     (a, not a - delta/2), which is measured, not hidden;
   - moving walls: positions, displacements, dragging by friction;
   - a packing compressed between walls: pressure (pair + fix virial) and
     compute grflow/network against the wall forces at equilibrium;
   - restart files keep the wall state and the per-atom history;
   - bad input gives a clear error.
------------------------------------------------------------------------- */

#include "grflow_contact.h"
#include "grflow_host.h"
#include "lammps_fixture.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

using namespace grflow_test;
using namespace LAMMPS_NS::GRFLOW;

namespace {

const double KN = 1.0e6, CN = 1.15;

// global vector of a fix
std::vector<double> fvec(Lammps &lmp, const char *id)
{
  return lmp.fix_vector(id, WallVector::NVECTOR);
}

// global vector of a compute
std::vector<double> cvec(Lammps &lmp, const char *id)
{
  auto *v = (double *) lammps_extract_compute(lmp.handle, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
  if (!v || lammps_has_error(lmp.handle)) {
    char buf[1024] = "";
    lammps_get_last_error_message(lmp.handle, buf, sizeof(buf));
    ADD_FAILURE() << "compute " << id << " vector not available: " << buf;
    return std::vector<double>(40, 0.0);
  }
  const int n = *(int *) lammps_extract_compute(lmp.handle, id, LMP_STYLE_GLOBAL, LMP_SIZE_VECTOR);
  return std::vector<double>(v, v + n);
}

double cscalar(Lammps &lmp, const char *id)
{
  auto *v = (double *) lammps_extract_compute(lmp.handle, id, LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR);
  if (!v) {
    ADD_FAILURE() << "compute " << id << " scalar not available";
    return 0.0;
  }
  return *v;
}

std::vector<double> gather1(Lammps &lmp, const char *name)
{
  std::vector<double> data((size_t) lmp.natoms());
  lammps_gather_atoms(lmp.handle, name, 1, 1, data.data());
  return data;
}

std::vector<double> slice(const std::vector<double> &v, int first, int n)
{
  return std::vector<double>(v.begin() + first, v.begin() + first + n);
}

std::vector<double> negated(const std::vector<double> &v)
{
  std::vector<double> out(v);
  for (auto &x : out) x = -x;
  return out;
}

// ---------------------------------------------------------------------------
// Spheres and a hand-written integrator
// ---------------------------------------------------------------------------

struct Ball {
  double x[3], v[3], w[3], rad;
  double mass = 0.0;
  double f[3] = {0.0, 0.0, 0.0}, t[3] = {0.0, 0.0, 0.0};
};

// an empty box, periodic in x and y, walls to be added in z
void wall_box(Lammps &lmp, double xlo, double xhi, double zlo, double zhi)
{
  lmp.cmds({"units si", "atom_style sphere", "atom_modify map array", "boundary p p f",
            "region box block " + fmt_double(xlo) + " " + fmt_double(xhi) + " " + fmt_double(xlo) +
                " " + fmt_double(xhi) + " " + fmt_double(zlo) + " " + fmt_double(zhi),
            "create_box 1 box"});
}

void add_ball(Lammps &lmp, const Ball &b)
{
  lmp.cmd("create_atoms 1 single " + fmt_double(b.x[0]) + " " + fmt_double(b.x[1]) + " " +
          fmt_double(b.x[2]) + " units box");
  lmp.cmd("set atom " + std::to_string(lmp.natoms()) + " diameter " + fmt_double(2.0 * b.rad) +
          " density 2650 vx " + fmt_double(b.v[0]) + " vy " + fmt_double(b.v[1]) + " vz " +
          fmt_double(b.v[2]) + " omega " + fmt_double(b.w[0]) + " " + fmt_double(b.w[1]) + " " +
          fmt_double(b.w[2]));
}

struct Plane {
  bool active = false;
  double z = 0.0;
  double v[3] = {0.0, 0.0, 0.0};
  double force[3] = {0.0, 0.0, 0.0};    // of the particles on the wall
};

// Mirrors fix nve/sphere (inertia 0.4 m a^2) and a flat wall taken as a
// sphere of infinite radius (n = +-e_z, a' = a, wall spin 0), with the
// kernel for every contact; walls move by v dt before the forces.
// stock_arm: sliding torque arm a instead of a - delta/2 (fix wall/gran).
class WallIntegrator {
 public:
  WallIntegrator(std::vector<Ball> balls, const ContactCoeffs &c, double dt, bool full_arm,
                 bool stock_arm = false) :
      b(std::move(balls)),
      c(c), dt(dt), full_arm(full_arm), stock_arm(stock_arm), hist(b.size())
  {
  }

  void forces(bool update)
  {
    const double wzero[3] = {0.0, 0.0, 0.0};
    for (auto &w : wall)
      for (double &k : w.force) k = 0.0;
    for (size_t i = 0; i < b.size(); i++) {
      Ball &p = b[i];
      for (int k = 0; k < 3; k++) p.f[k] = p.t[k] = 0.0;
      for (int iw = 0; iw < 2; iw++) {
        Plane &w = wall[iw];
        if (!w.active) continue;
        auto &h = hist[i][iw];
        const double sign = iw == 0 ? 1.0 : -1.0;
        const double gap = sign * (p.x[2] - w.z);
        if (gap >= p.rad) {
          if (h[0] != 0.0 || h[3] != 0.0) separated = true;
          h.fill(0.0);
          continue;
        }
        ContactGeometry g;
        g.n[0] = g.n[1] = 0.0;
        g.n[2] = sign;
        g.delta = p.rad - gap;
        const double arm = p.rad - 0.5 * g.delta;
        g.arm_i = stock_arm ? p.rad : arm;
        g.arm_j = 0.0;
        g.varm_i = full_arm ? p.rad : arm;
        g.varm_j = 0.0;
        g.reff = p.rad;
        const double vrel[3] = {p.v[0] - w.v[0], p.v[1] - w.v[1], p.v[2] - w.v[2]};
        ContactForces out;
        contact_forces(c, g, vrel, p.w, wzero, dt, update, h.data(), out);
        if (update && out.fn > 0.0) {
          const double cap = 1.0 - 1.0e-12;
          slid[iw] = slid[iw] || sqrt(dot3(out.ft, out.ft)) >= cap * c.mut * out.fn;
          rolled[iw] = rolled[iw] || sqrt(dot3(out.fr, out.fr)) >= cap * c.mur * out.fn;
          twisted[iw] = twisted[iw] || fabs(out.fo) >= cap * c.muo * out.fn;
        }
        for (int k = 0; k < 3; k++) {
          p.f[k] += out.f[k];
          p.t[k] += out.torque_i[k];
          w.force[k] -= out.f[k];
        }
      }
      for (int k = 0; k < 3; k++) p.f[k] += external[k];
    }
  }

  void run(int nsteps)
  {
    forces(false);    // setup: springs are read, not advanced
    for (int n = 0; n < nsteps; n++) {
      for (auto &w : wall) {
        if (!w.active) continue;
        w.z += dt * w.v[2];
      }
      nve_sphere_initial(b, dt);
      forces(true);
      nve_sphere_final(b, dt);
    }
  }

  std::vector<double> field(int which) const { return body_field(b, which); }

  std::vector<Ball> b;
  Plane wall[2];
  ContactCoeffs c;
  double dt;
  bool full_arm, stock_arm;
  double external[3] = {0.0, 0.0, 0.0};    // constant force on every ball (fix addforce)
  std::vector<std::array<std::array<double, HIST_SIZE>, 2>> hist;
  bool slid[2] = {false, false}, rolled[2] = {false, false}, twisted[2] = {false, false};
  bool separated = false;
};

ContactCoeffs table1(double kn, double cn)
{
  return {kn, cn, 0.8 * kn, 0.2 * cn, 0.5, 0.1 * kn, 0.05 * cn, 0.1, 0.1 * kn, 0.05 * cn, 0.1};
}

const char *FIELDS[5] = {"x", "v", "omega", "f", "torque"};

// ---------------------------------------------------------------------------
// One sphere on a wall: the law written out by hand, springs unstretched
// (run 0 evaluates the forces without advancing the springs)
// ---------------------------------------------------------------------------

void cross(const double *a, const double *b, double *c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// a trial force -c w capped at cap; true if capped
bool capped(double c, double cap, const double *w, double *f)
{
  const double len = c * sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const double s = len > cap ? cap / len : 1.0;
  for (int k = 0; k < 3; k++) f[k] = -c * w[k] * s;
  return len > cap;
}

struct Expected {
  double f[3], t[3], fn;
  bool slip, roll, twist;    // at the cap
};

// force and torque on a sphere of radius a with overlap delta on a wall of
// normal n = (0,0,sign) moving with vwall, fresh contact, Table 1 ratios
Expected fresh_contact(double a, double delta, double sign, const double *v, const double *w,
                       const double *vwall, bool full)
{
  const double n[3] = {0.0, 0.0, sign};
  const double ct = 0.2 * CN, cr = 0.05 * CN, co = 0.05 * CN;
  const double vr[3] = {v[0] - vwall[0], v[1] - vwall[1], v[2] - vwall[2]};
  Expected e;
  const double vn = vr[2] * sign;
  e.fn = std::max(0.0, KN * delta - CN * vn);
  const double ell = a - delta / 2.0, ellv = full ? a : ell;
  // contact-point sliding velocity: v_t - (ell w) x n
  double wxn[3], lw[3] = {ellv * w[0], ellv * w[1], ellv * w[2]};
  cross(lw, n, wxn);
  const double vt[3] = {vr[0] - wxn[0], vr[1] - wxn[1], 0.0};
  double ft[3];
  e.slip = capped(ct, 0.5 * e.fn, vt, ft);
  // rolling: v_r = -a n x w; torsion v_o = a w.n
  double nxw[3];
  cross(n, w, nxw);
  const double vroll[3] = {-a * nxw[0], -a * nxw[1], -a * nxw[2]};
  double fr[3];
  e.roll = capped(cr, 0.1 * e.fn, vroll, fr);
  const double vo[3] = {a * w[2] * sign, 0.0, 0.0};
  double fo3[3];
  e.twist = capped(co, 0.1 * e.fn, vo, fo3);
  const double fo = fo3[0];
  double nxft[3], nxfr[3];
  cross(n, ft, nxft);
  cross(n, fr, nxfr);
  for (int k = 0; k < 3; k++) {
    e.f[k] = e.fn * n[k] + ft[k];
    e.t[k] = -ell * nxft[k] + a * nxfr[k] + a * fo * n[k];
  }
  return e;
}

class OneSphere : public ::testing::TestWithParam<int> {};

TEST_P(OneSphere, PressedOnWall)
{
  const int iw = GetParam();    // 0: lo wall, 1: hi wall
  const double sign = iw == 0 ? 1.0 : -1.0;
  const double a = 0.5e-3, zlo = 1.0e-3, zhi = 9.0e-3;
  const double zwall = iw == 0 ? zlo : zhi;
  const double z = zwall + sign * (a - 1.0e-5);    // overlap about 1e-5
  const char *side = iw == 0 ? "lo" : "hi";

  Lammps lmp;
  wall_box(lmp, 0.0, 0.01, 0.0, 0.01);
  add_ball(lmp, {{5.0e-3, 5.0e-3, z}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, a});
  lmp.cmds({"fix w all grflow/wall 1.0e6 1.15 zlo 1.0e-3 zhi 9.0e-3",
            "compute pf all pressure NULL fix", "compute pv all pressure NULL virial",
            "thermo_style custom step c_pf[1] c_pv[1]", "run 0"});
  const double zat = lmp.gather3("x")[2];
  const double delta = a - sign * (zat - zwall);
  const double arm = a - delta / 2.0;
  const double vol = lmp.thermo("vol");
  ASSERT_GT(delta, 0.9e-5);

  // at rest: k_n delta along the wall normal, nothing else
  auto f = lmp.gather3("f"), t = lmp.gather3("torque");
  auto w = fvec(lmp, "w");
  EXPECT_EQ(f[0], 0.0);
  EXPECT_EQ(f[1], 0.0);
  EXPECT_DOUBLE_EQ(f[2], sign * KN * delta);
  measured(std::string("at rest on ") + side + " wall: fz/(kn delta) - 1",
           f[2] / (sign * KN * delta) - 1.0);
  for (int k = 0; k < 3; k++) EXPECT_EQ(t[k], 0.0) << k;
  // the force on the wall is minus the force on the atom; the other wall has none
  const int mine = iw == 0 ? WallVector::LO_FX : WallVector::HI_FX,
            other = iw == 0 ? WallVector::HI_FX : WallVector::LO_FX;
  EXPECT_EQ(slice(w, mine, 3), negated(f));
  EXPECT_EQ(slice(w, other, 3), std::vector<double>(3, 0.0));
  EXPECT_EQ(w[WallVector::LO_Z], zlo);
  EXPECT_EQ(w[WallVector::HI_Z], zhi);
  for (int k : {WallVector::LO_DX, WallVector::LO_DY, WallVector::HI_DX, WallVector::HI_DY})
    EXPECT_EQ(w[k], 0.0);
  // virial: branch (a - delta/2) n from the contact point to the centre
  auto pf = cvec(lmp, "pf");
  EXPECT_NEAR(pf[2] * vol, arm * KN * delta, 1.0e-12 * arm * KN * delta);
  for (int k : {0, 1, 3, 4, 5}) EXPECT_EQ(pf[k], 0.0) << k;
  EXPECT_EQ(cvec(lmp, "pv")[2], pf[2]);    // no pair style: the whole virial

  // moving: damping, sliding, rolling and torsion, every cap on or off
  struct Motion {
    double v[3], w[3];
    const char *what;
  } motions[] = {
      {{0.0, 0.0, -0.2}, {0.0, 0.0, 0.0}, "moving down"},
      {{0.0, 0.0, 0.2}, {0.0, 0.0, 0.0}, "moving up"},
      {{0.0, 0.0, 20.0 * sign}, {0.0, 0.0, 0.0}, "separating fast (no force)"},
      {{0.1, -0.05, 0.0}, {0.0, 0.0, 0.0}, "sliding below the cap"},
      {{30.0, -20.0, 0.0}, {0.0, 0.0, 0.0}, "sliding at the cap"},
      {{0.1, 0.0, 0.0}, {40.0, 100.0, 50.0}, "sliding, rolling, spinning"},
      {{0.0, 0.0, 0.0}, {4.0e4, -1.0e5, 6.0e4}, "rolling and spinning at the caps"},
  };
  for (bool full : {false, true}) {
    if (full) {
      lmp.cmds(
          {"unfix w", "fix w all grflow/wall 1.0e6 1.15 zlo 1.0e-3 zhi 9.0e-3 velocity_arm full"});
    }
    for (const auto &m : motions) {
      const std::string what = std::string(side) + " wall, " + m.what + (full ? ", full arm" : "");
      SCOPED_TRACE(what);
      char line[256];
      snprintf(line, sizeof(line), "set atom 1 vx %.17g vy %.17g vz %.17g omega %.17g %.17g %.17g",
               m.v[0], m.v[1], m.v[2], m.w[0], m.w[1], m.w[2]);
      lmp.cmds({line, "run 0"});
      const double vwall[3] = {0.0, 0.0, 0.0};
      const Expected e = fresh_contact(a, delta, sign, m.v, m.w, vwall, full);
      f = lmp.gather3("f");
      t = lmp.gather3("torque");
      w = fvec(lmp, "w");
      const std::vector<double> ef(e.f, e.f + 3), et(e.t, e.t + 3);
      EXPECT_LT(max_rel_diff(f, ef), 1.0e-13) << f[0] << " " << f[1] << " " << f[2];
      if (e.fn > 0.0) {
        EXPECT_LT(max_rel_diff(t, et), 1.0e-13) << t[0] << " " << t[1] << " " << t[2];
      } else {
        EXPECT_EQ(t, std::vector<double>(3, 0.0));
      }
      EXPECT_EQ(slice(w, mine, 3), negated(f));
      // virial zz and the symmetrized xz, yz: 0.5 l_z f_x, 0.5 l_z f_y
      pf = cvec(lmp, "pf");
      const double l = sign * arm;
      EXPECT_NEAR(pf[2] * vol, l * f[2], 1.0e-13 * fabs(l * f[2]) + 1.0e-300);
      EXPECT_NEAR(pf[4] * vol, 0.5 * l * f[0], 1.0e-13 * fabs(l * f[0]) + 1.0e-300);
      EXPECT_NEAR(pf[5] * vol, 0.5 * l * f[1], 1.0e-13 * fabs(l * f[1]) + 1.0e-300);
      for (int k : {0, 1, 3}) EXPECT_EQ(pf[k], 0.0) << k;
    }
  }
  // fix_modify virial no: the same forces, no virial
  lmp.cmds({"fix_modify w virial no", "run 0"});
  EXPECT_EQ(lmp.gather3("f"), f);
  EXPECT_EQ(cvec(lmp, "pf"), std::vector<double>(6, 0.0));

  // the cases did what they were meant to: caps hit or not, f_n can vanish
  const double vw[3] = {0.0, 0.0, 0.0};
  auto expect = [&](int k) {
    return fresh_contact(a, delta, sign, motions[k].v, motions[k].w, vw, false);
  };
  EXPECT_EQ(expect(2).fn, 0.0);
  EXPECT_FALSE(expect(3).slip);
  EXPECT_TRUE(expect(4).slip);
  EXPECT_NEAR(hypot(expect(4).f[0], expect(4).f[1]), 0.5 * expect(4).fn, 1.0e-12 * expect(4).fn);
  EXPECT_FALSE(expect(5).roll || expect(5).twist);
  EXPECT_TRUE(expect(6).roll && expect(6).twist && expect(6).slip);
}

INSTANTIATE_TEST_SUITE_P(Walls, OneSphere, ::testing::Values(0, 1),
                         [](const ::testing::TestParamInfo<int> &i) {
                           return std::string(i.param == 0 ? "Lo" : "Hi");
                         });

TEST(FixWallOutput, MovingWallVelocityEntersTheContact)
{
  // the relative velocity is v - v_wall: a sphere at rest on a wall moving
  // at u feels the same force as a sphere moving at -u on a wall at rest
  const double a = 0.5e-3, u[3] = {0.3, -0.2, 0.01};
  std::vector<double> f[2], t[2];
  for (int moving = 0; moving < 2; moving++) {
    Lammps lmp;
    wall_box(lmp, 0.0, 0.01, 0.0, 0.01);
    const double vball[3] = {moving ? 0.0 : -u[0], moving ? 0.0 : -u[1], moving ? 0.0 : -u[2]};
    add_ball(lmp,
             {{5.0e-3, 5.0e-3, a - 1.0e-5}, {vball[0], vball[1], vball[2]}, {10.0, 20.0, 30.0}, a});
    lmp.cmd("fix w all grflow/wall 1.0e6 1.15 zlo 0.0");
    if (moving)
      lmp.cmd("fix_modify w wall lo vel " + fmt_double(u[0]) + " " + fmt_double(u[1]) + " " +
              fmt_double(u[2]));
    lmp.cmd("run 0");
    f[moving] = lmp.gather3("f");
    t[moving] = lmp.gather3("torque");
  }
  EXPECT_EQ(f[0], f[1]);
  EXPECT_EQ(t[0], t[1]);
  EXPECT_GT(fabs(f[1][0]), 0.01);
}

TEST(FixWallOutput, ForcesExtensivePositionsIntensive)
{
  // thermo_modify norm yes divides extensive outputs by the number of atoms:
  // the wall forces are extensive (sums over atoms), the positions and
  // displacements are not
  Lammps lmp;
  wall_box(lmp, 0.0, 0.01, 0.0, 0.01);
  const double a = 0.5e-3;
  add_ball(lmp, {{3.0e-3, 5.0e-3, 1.0e-3 + a - 1.0e-5}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, a});
  add_ball(lmp, {{7.0e-3, 5.0e-3, 5.0e-3}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, a});
  lmp.cmds({"fix w all grflow/wall 1.0e6 1.15 zlo 1.0e-3 zhi 9.0e-3",
            "fix_modify w wall hi vel 0.5 0.25 0", "run 10",
            "thermo_style custom step f_w[3] f_w[4] f_w[10] f_w[11] f_w[12]",
            "thermo_modify norm yes", "run 0"});
  const auto w = fvec(lmp, "w");
  auto last = [&](int k) {
    return *(double *) lammps_last_thermo(lmp.handle, "data", k);
  };
  EXPECT_DOUBLE_EQ(last(1), w[WallVector::LO_FZ] / 2.0);
  EXPECT_EQ(last(2), 1.0e-3);
  EXPECT_EQ(last(3), 9.0e-3);
  EXPECT_EQ(last(4), w[WallVector::HI_DX]);
  EXPECT_EQ(last(5), w[WallVector::HI_DY]);
  EXPECT_GT(w[WallVector::HI_DX], 0.0);
}

TEST(FixWallNetwork, WallContactsInComputeNetwork)
{
  // A between the walls (overlaps 1e-5 below, 2e-5 above), B on the lo wall
  // sliding slowly in x (overlap 3e-5), C floating.  The wall contacts count
  // for the particle inside: arm (a - delta/2) n (x) f, one contact, n n = e_z e_z

  const double aA = 0.5e-3, aB = 0.3e-3, aC = 0.4e-3;
  const double dA1 = 1.0e-5, dA2 = 2.0e-5, dB = 3.0e-5, vB = 0.1;
  const double zA = aA - dA1, zhi = zA + aA - dA2;
  Lammps lmp;
  wall_box(lmp, 0.0, 0.01, -1.0e-3, 2.0e-3);
  add_ball(lmp, {{2.0e-3, 5.0e-3, zA}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, aA});
  add_ball(lmp, {{6.0e-3, 5.0e-3, aB - dB}, {vB, 0.0, 0.0}, {0.0, 0.0, 0.0}, aB});
  add_ball(lmp, {{8.0e-3, 5.0e-3, 0.5e-3}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, aC});
  lmp.cmds({"comm_modify vel yes", "neighbor 0.2e-3 bin", "pair_style granular/grflow",
            "pair_coeff * * 1.0e6 1.15",
            "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi " + fmt_double(zhi),
            "variable zlo equal f_w[4]", "variable zhi equal f_w[10]",
            "compute net all grflow/network slab 1.0 zlimits v_zlo v_zhi",
            "region left block INF 4.0e-3 INF INF INF INF", "group right id 2 3",
            "compute left all grflow/network region left",
            "compute right right grflow/network slab 1.0 zlimits v_zlo v_zhi",
            "compute pf all pressure NULL fix", "thermo_style custom step c_pf[3]", "run 0"});
  const auto x = lmp.gather3("x");
  const double d1 = aA - x[2], d2 = aA - (zhi - x[2]), d3 = aB - x[5];
  const double wA = (aA - d1 / 2) * KN * d1 + (aA - d2 / 2) * KN * d2;
  const double wB = (aB - d3 / 2) * KN * d3;
  const double fxB = -0.2 * CN * vB;    // empty spring, below the cap
  const double A = 0.01 * 0.01, V = A * zhi;

  auto v = cvec(lmp, "net");
  EXPECT_NEAR(v[NetVector::VOLUME], V, 1.0e-15 * V);
  EXPECT_LT(measured("network with walls: sigma_zz vs sum (a - delta/2) kn delta / V",
                     fabs(v[NetVector::SZZ] - (wA + wB) / V) / v[NetVector::SZZ]),
            1.0e-12);
  EXPECT_EQ(v[NetVector::SXX], 0.0);
  // the wall contact's branch is along z: sigma_zx = l f_x, sigma_xz = 0;
  // tau uses the symmetric part, like the fix virial
  EXPECT_EQ(v[NetVector::SXZ], 0.0);
  EXPECT_NEAR(v[NetVector::TAU], -0.5 * (aB - d3 / 2) * fxB / V, 1.0e-12 * fabs(v[NetVector::TAU]));
  EXPECT_NE(v[NetVector::TAU], 0.0);
  EXPECT_EQ(v[NetVector::NP], 3.0);
  EXPECT_EQ(v[NetVector::NFLOAT], 1.0);
  EXPECT_EQ(v[NetVector::NCONTACT], 1.5);
  EXPECT_EQ(v[NetVector::ZG], 1.5);
  EXPECT_DOUBLE_EQ(v[NetVector::PC0 + 0], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(v[NetVector::PC0 + 1], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(v[NetVector::PC0 + 2], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(v[NetVector::AZZ], 5.0);
  EXPECT_DOUBLE_EQ(v[NetVector::AXX], -2.5);
  EXPECT_DOUBLE_EQ(v[NetVector::AC], 7.5);

  // only A (region), only B and C (group)
  const auto l = cvec(lmp, "left");
  EXPECT_EQ(l[NetVector::NP], 1.0);
  EXPECT_EQ(l[NetVector::NCONTACT], 1.0);
  EXPECT_NEAR(l[NetVector::SZZ] * l[NetVector::VOLUME], wA, 1.0e-12 * wA);
  const auto r = cvec(lmp, "right");
  EXPECT_EQ(r[NetVector::NP], 2.0);
  EXPECT_EQ(r[NetVector::NCONTACT], 0.5);
  EXPECT_NEAR(r[NetVector::SZZ] * r[NetVector::VOLUME], wB, 1.0e-12 * wB);
  // the same forces in the virial
  EXPECT_NEAR(cvec(lmp, "pf")[2] * lmp.thermo("vol"), wA + wB, 1.0e-12 * (wA + wB));
}

// ---------------------------------------------------------------------------
// Spheres sliding, rolling and spinning on moving walls against the kernel
// ---------------------------------------------------------------------------

// A: squeezed between the two walls (overlap 1e-6 each), sliding fast and
// spinning; B: falls onto the lo wall with spin, bounces off and leaves
std::vector<Ball> sliding_balls(double &zhi)
{
  const double aA = 0.5e-3, aB = 0.4e-3;
  Ball A{{0.0, 0.0, aA - 1.0e-6}, {2.0, -1.0, 0.05}, {3.0e4, -1.0e4, 5.0e4}, aA};
  Ball B{{5.0e-3, 0.0, aB + 1.0e-7}, {1.0, 0.5, -0.5}, {2.0e4, -1.0e4, 3.0e4}, aB};
  zhi = A.x[2] + aA - 1.0e-6;
  return {A, B};
}

class SlidingOnWalls : public ::testing::TestWithParam<bool> {};

TEST_P(SlidingOnWalls, FollowsKernel)
{
  const bool full = GetParam();
  const double dt = 1.0e-8;
  const int nsteps = 600;
  const double vlo[3] = {-0.3, 0.0, 0.0}, vhi[3] = {0.2, -0.1, -0.002};
  double zhi;
  auto balls = sliding_balls(zhi);

  Lammps lmp;
  wall_box(lmp, -0.01, 0.01, -1.0e-3, 3.0e-3);
  for (const auto &p : balls) add_ball(lmp, p);
  const auto mass = gather1(lmp, "rmass");
  for (size_t i = 0; i < balls.size(); i++) balls[i].mass = mass[i];
  auto vel = [](const double *v) {
    return fmt_double(v[0]) + " " + fmt_double(v[1]) + " " + fmt_double(v[2]);
  };
  lmp.cmds({"fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi " + fmt_double(zhi) +
                (full ? " velocity_arm full" : ""),
            "fix_modify w wall lo vel " + vel(vlo) + " wall hi vel " + vel(vhi),
            "fix nve all nve/sphere", "timestep " + fmt_double(dt),
            "run " + std::to_string(nsteps)});

  auto reference = [&](bool full_arm) {
    WallIntegrator r(balls, table1(KN, CN), dt, full_arm);
    r.wall[0].active = r.wall[1].active = true;
    r.wall[1].z = zhi;
    for (int k = 0; k < 3; k++) {
      r.wall[0].v[k] = vlo[k];
      r.wall[1].v[k] = vhi[k];
    }
    r.run(nsteps);
    return r;
  };
  const WallIntegrator ref = reference(full);

  const std::string tag = std::string("sliding on walls") + (full ? " (full arm)" : "");
  for (int which = 0; which < 5; which++)
    EXPECT_LT(measured(tag + ": kernel vs fix " + FIELDS[which],
                       max_rel_diff(lmp.gather3(FIELDS[which]), ref.field(which))),
              1.0e-12);
  const auto w = fvec(lmp, "w");
  const std::vector<double> want = {
      ref.wall[0].force[0], ref.wall[0].force[1], ref.wall[0].force[2], ref.wall[0].z, 0.0, 0.0,
      ref.wall[1].force[0], ref.wall[1].force[1], ref.wall[1].force[2], ref.wall[1].z, 0.0, 0.0};
  for (int k : {WallVector::LO_FX, WallVector::LO_FY, WallVector::LO_FZ, WallVector::HI_FX,
                WallVector::HI_FY, WallVector::HI_FZ, WallVector::LO_Z, WallVector::HI_Z})
    EXPECT_NEAR(w[k], want[k], 1.0e-12 * std::max(1.0, fabs(want[k]))) << k;
  EXPECT_NEAR(w[WallVector::LO_DX], nsteps * dt * vlo[0], 1.0e-15);
  EXPECT_NEAR(w[WallVector::HI_DY], nsteps * dt * vhi[1], 1.0e-15);
  // every cap was reached on both walls, and B left the lo wall
  for (int iw = 0; iw < 2; iw++) {
    EXPECT_TRUE(ref.slid[iw]) << iw;
    EXPECT_TRUE(ref.rolled[iw]) << iw;
    EXPECT_TRUE(ref.twisted[iw]) << iw;
  }
  EXPECT_TRUE(ref.separated);
  EXPECT_GT(ref.b[1].v[2], 0.0);

  // the velocity arm matters: the other setting gives another trajectory
  EXPECT_GT(measured(tag + ": other velocity_arm, omega",
                     max_rel_diff(reference(!full).field(2), ref.field(2))),
            1.0e-9);
}

INSTANTIATE_TEST_SUITE_P(Arm, SlidingOnWalls, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool> &i) {
                           return std::string(i.param ? "FullArm" : "ReducedArm");
                         });

// ---------------------------------------------------------------------------
// Stock fix wall/gran with the same law (shared/notes/contact-law.md)
// ---------------------------------------------------------------------------

// monodisperse spheres landing on the lo wall, each pressed by 1 N: they
// bounce a little, then slide, roll and spin with their caps reached.  They
// start out of contact: stock fix wall/gran zeroes a sliding or rolling
// force above its cap while the spring is empty, which happens only when
// forces are evaluated without advancing the springs (setup)
std::vector<Ball> landing_balls()
{
  const double a = 0.5e-3;
  return {{{0.0, 0.0, a + 1.0e-7}, {1.5, -0.5, -0.3}, {2.0e4, 1.0e4, 4.0e4}, a},
          {{3.0e-3, 0.0, a + 3.0e-7}, {0.0, 0.2, -0.5}, {-1.0e4, 3.0e3, -2.0e4}, a},
          {{-3.0e-3, 0.0, a + 2.0e-7}, {0.5, 0.0, -0.6}, {0.0, 2.0e4, 1.0e4}, a}};
}

// spheres in contact, slow enough that no cap is reached at setup, and one
// fast sphere that is above its caps
std::vector<Ball> resting_balls()
{
  const double a = 0.5e-3;
  return {{{0.0, 0.0, a - 1.0e-6}, {0.05, -0.02, 0.0}, {20.0, 50.0, 40.0}, a},
          {{3.0e-3, 0.0, a - 2.0e-6}, {0.0, 0.03, 0.01}, {-30.0, 10.0, -60.0}, a},
          {{-3.0e-3, 0.0, a - 1.5e-6}, {1.5, -0.5, 0.0}, {2.0e4, 1.0e4, 4.0e4}, a}};
}

void stock_setup(Lammps &lmp, const std::vector<Ball> &balls, bool stock, double mut, double dt)
{
  const double a = 0.5e-3;
  wall_box(lmp, -0.01, 0.01, -1.0e-3, 3.0e-3);
  for (const auto &p : balls) add_ball(lmp, p);
  char line[512];
  if (stock)
    snprintf(line, sizeof(line),
             "fix w all wall/gran granular hooke 1.0e6 1.15 damping velocity limit_damping "
             "tangential linear_history 8.0e5 0.2 %.17g rolling sds 1.0e5 0.0575 0.1 "
             "twisting sds %.17g %.17g %.17g zplane 0.0 NULL",
             mut, 1.0e5 * a * a, 0.0575 * a * a, 0.1 * a);
  else
    snprintf(line, sizeof(line),
             "fix w all grflow/wall 1.0e6 1.15 mut %.17g zlo 0.0 velocity_arm full", mut);
  lmp.cmds({line, "fix load all addforce 0.0 0.0 -1.0", "fix nve all nve/sphere",
            "timestep " + fmt_double(dt)});
}

TEST(FixWallStock, StepZeroSameForcesTorqueArmDiffers)
{
  Lammps ours, stock;
  const auto balls = resting_balls();
  stock_setup(ours, balls, false, 0.5, 1.0e-8);
  stock_setup(stock, balls, true, 0.5, 1.0e-8);
  ours.cmd("run 0");
  stock.cmd("run 0");
  const auto f = ours.gather3("f"), fs = stock.gather3("f");
  const auto t = ours.gather3("torque"), ts = stock.gather3("torque");
  const auto x = ours.gather3("x");
  // the slow spheres, 1 and 2
  const std::vector<double> f12(f.begin(), f.begin() + 6), fs12(fs.begin(), fs.begin() + 6);
  EXPECT_LT(measured("stock wall/gran step 0 force", max_rel_diff(f12, fs12)), 1.0e-14);
  // torques: stock takes the sliding torque with arm a, this fix with
  // a - delta/2: T_stock - T_ours = -(delta/2) n x f_t = (delta/2)(f_y, -f_x, 0)
  std::vector<double> t12(t.begin(), t.begin() + 6), ts12(ts.begin(), ts.begin() + 6);
  const double raw = max_rel_diff(t12, ts12);
  for (int i = 0; i < 2; i++) {
    const double delta = 0.5e-3 - x[3 * i + 2];
    ASSERT_GT(delta, 0.0);
    t12[3 * i + 0] += 0.5 * delta * f[3 * i + 1];
    t12[3 * i + 1] -= 0.5 * delta * f[3 * i + 0];
  }
  measured("stock wall/gran step 0 torque, as computed", raw);
  EXPECT_GT(raw, 1.0e-4);    // the conventions differ, visibly
  EXPECT_LT(measured("stock wall/gran step 0 torque, arm a - delta/2 replaced by a",
                     max_rel_diff(t12, ts12)),
            1.0e-14);

  // the fast sphere: its sliding trial force is above the cap with an empty
  // spring.  This fix caps it at mu_t f_n; stock sets it to zero (also rolling)
  const double fn = f[8] + 1.0;    // less the load of fix addforce
  EXPECT_NEAR(hypot(f[6], f[7]), 0.5 * fn, 1.0e-12 * fn);
  EXPECT_EQ(fs[6], 0.0);
  EXPECT_EQ(fs[7], 0.0);
  EXPECT_DOUBLE_EQ(fs[8], f[8]);
}

TEST(FixWallStock, NoSlidingSameTrajectory)
{
  // with mut = 0 there is no sliding force, so no sliding torque: normal,
  // rolling and torsion are the same law in both
  const double dt = 1.0e-8;
  Lammps ours, stock;
  auto balls = landing_balls();
  stock_setup(ours, balls, false, 0.0, dt);
  stock_setup(stock, balls, true, 0.0, dt);
  ours.cmd("run 1000");
  stock.cmd("run 1000");
  for (const char *name : FIELDS)
    EXPECT_LT(measured(std::string("stock wall/gran mut 0, 1000 steps: ") + name,
                       max_rel_diff(ours.gather3(name), stock.gather3(name))),
              1.0e-10);
  // and both are the kernel's trajectory, with rolling and torsion at their caps
  const auto mass = gather1(ours, "rmass");
  for (size_t i = 0; i < balls.size(); i++) balls[i].mass = mass[i];
  ContactCoeffs c = table1(KN, CN);
  c.mut = 0.0;
  WallIntegrator ref(balls, c, dt, true);
  ref.wall[0].active = true;
  ref.external[2] = -1.0;
  ref.run(1000);
  EXPECT_LT(max_rel_diff(ours.gather3("omega"), ref.field(2)), 1.0e-12);
  EXPECT_TRUE(ref.rolled[0]);
  EXPECT_TRUE(ref.twisted[0]);
}

TEST(FixWallStock, SlidingTrajectoryIsTheKernelWithStockArm)
{
  // with sliding, stock fix wall/gran follows the kernel with the torque arm
  // a (and the contact-point velocity with a); this fix uses a - delta/2
  const double dt = 1.0e-8;
  const int nsteps = 1000;
  Lammps ours, stock;
  auto balls = landing_balls();
  stock_setup(ours, balls, false, 0.5, dt);
  stock_setup(stock, balls, true, 0.5, dt);
  const auto mass = gather1(ours, "rmass");
  for (size_t i = 0; i < balls.size(); i++) balls[i].mass = mass[i];
  ours.cmd("run " + std::to_string(nsteps));
  stock.cmd("run " + std::to_string(nsteps));

  WallIntegrator as_stock(balls, table1(KN, CN), dt, true, true);
  as_stock.wall[0].active = true;
  as_stock.external[2] = -1.0;
  as_stock.run(nsteps);
  WallIntegrator as_ours(balls, table1(KN, CN), dt, true, false);
  as_ours.wall[0].active = true;
  as_ours.external[2] = -1.0;
  as_ours.run(nsteps);
  EXPECT_TRUE(as_stock.slid[0]);
  EXPECT_TRUE(as_stock.rolled[0]);
  EXPECT_TRUE(as_stock.twisted[0]);

  for (int which = 0; which < 5; which++) {
    const auto s = stock.gather3(FIELDS[which]), o = ours.gather3(FIELDS[which]);
    EXPECT_LT(measured(std::string("stock wall/gran vs kernel with arm a: ") + FIELDS[which],
                       max_rel_diff(s, as_stock.field(which))),
              1.0e-10);
    EXPECT_LT(max_rel_diff(o, as_ours.field(which)), 1.0e-12);
    measured(std::string("stock wall/gran vs this fix, sliding, 1000 steps: ") + FIELDS[which],
             max_rel_diff(o, s));
  }
  EXPECT_GT(max_rel_diff(ours.gather3("omega"), stock.gather3("omega")), 1.0e-7);
}

// ---------------------------------------------------------------------------
// Moving walls
// ---------------------------------------------------------------------------

TEST(FixWallMoving, WallsMoveByVelocityTimesTime)
{
  Lammps lmp;
  wall_box(lmp, 0.0, 0.01, 0.0, 0.01);
  add_ball(lmp, {{5.0e-3, 5.0e-3, 5.0e-3}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.5e-3});
  const double vlo[3] = {0.1, -0.2, 0.3}, vhi[3] = {-0.05, 0.07, -0.4};
  double dt = 1.0e-6;
  lmp.cmds({"fix w all grflow/wall 1.0e6 1.15 zlo 1.0e-3 zhi 9.0e-3", "fix nve all nve/sphere",
            "timestep " + fmt_double(dt),
            "fix_modify w wall lo vel 0.1 -0.2 0.3 wall hi vel -0.05 0.07 -0.4", "run 1000"});
  // the same sums, done here
  double zlo = 1.0e-3, zhi = 9.0e-3, d[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  auto advance = [&](int n, bool hi_moves) {
    for (int s = 0; s < n; s++) {
      zlo += dt * vlo[2];
      d[0][0] += dt * vlo[0];
      d[0][1] += dt * vlo[1];
      if (!hi_moves) continue;
      zhi += dt * vhi[2];
      d[1][0] += dt * vhi[0];
      d[1][1] += dt * vhi[1];
    }
  };
  advance(1000, true);
  auto w = fvec(lmp, "w");
  EXPECT_EQ(w[WallVector::LO_Z], zlo);
  EXPECT_EQ(w[WallVector::HI_Z], zhi);
  EXPECT_EQ(w[WallVector::LO_DX], d[0][0]);
  EXPECT_EQ(w[WallVector::LO_DY], d[0][1]);
  EXPECT_EQ(w[WallVector::HI_DX], d[1][0]);
  EXPECT_EQ(w[WallVector::HI_DY], d[1][1]);
  const double t = 1000 * dt;
  const std::vector<double> vt = {1.0e-3 + vlo[2] * t, vlo[0] * t, vlo[1] * t,
                                  9.0e-3 + vhi[2] * t, vhi[0] * t, vhi[1] * t};
  const std::vector<double> got = {w[WallVector::LO_Z], w[WallVector::LO_DX], w[WallVector::LO_DY],
                                   w[WallVector::HI_Z], w[WallVector::HI_DX], w[WallVector::HI_DY]};
  EXPECT_LT(measured("wall positions vs z0 + v t after 1000 steps", max_rel_diff(got, vt)),
            1.0e-13);

  // run 0 does not move them; a new time step is used from the next run
  lmp.cmd("run 0");
  EXPECT_EQ(fvec(lmp, "w")[WallVector::HI_Z], zhi);
  dt = 2.0e-6;
  lmp.cmds({"timestep " + fmt_double(dt), "run 500"});
  advance(500, true);
  w = fvec(lmp, "w");
  EXPECT_EQ(w[WallVector::LO_Z], zlo);
  EXPECT_EQ(w[WallVector::HI_DX], d[1][0]);

  // fix_modify z places a wall; displacements stay; vel 0 stops it
  lmp.cmds({"fix_modify w wall hi z 8.0e-3 wall hi vel 0 0 0", "run 100"});
  advance(100, false);
  w = fvec(lmp, "w");
  EXPECT_EQ(w[WallVector::HI_Z], 8.0e-3);
  EXPECT_EQ(w[WallVector::HI_DX], d[1][0]);
  EXPECT_EQ(w[WallVector::HI_DY], d[1][1]);
  EXPECT_EQ(w[WallVector::LO_Z], zlo);
  EXPECT_EQ(w[WallVector::LO_DY], d[0][1]);
}

TEST(FixWallMoving, WallDragsSphereByFriction)
{
  // a sphere pressed on the lo wall by 1 N; the wall then moves at +u in x:
  // friction pulls the sphere along +x, never more than mu_t f_n, and
  // spins it backwards, until it rides along with the wall
  const double a = 0.5e-3, u = 2.0, dt = 5.0e-8;
  Lammps lmp;
  wall_box(lmp, 0.0, 0.01, 0.0, 0.01);
  add_ball(lmp, {{5.0e-3, 5.0e-3, a - 1.0e-6}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, a});
  lmp.cmds({"fix w all grflow/wall 1.0e6 1.15 zlo 0.0", "fix load all addforce 0.0 0.0 -1.0",
            "fix nve all nve/sphere", "timestep " + fmt_double(dt), "run 2000"});
  EXPECT_NEAR(fvec(lmp, "w")[WallVector::LO_FZ], -1.0, 1.0e-3);    // settled on the wall
  const double x0 = lmp.gather3("x")[0];

  const int nsteps = 4000;
  lmp.cmds({"fix_modify w wall lo vel " + fmt_double(u) + " 0 0", "variable vx equal vx[1]",
            "compute om all property/atom omegay", "compute wy all reduce sum c_om",
            "variable wy equal c_wy", "fix recf all vector 1 f_w[1] f_w[3]",
            "fix recv all vector 1 v_vx v_wy", "run " + std::to_string(nsteps)});
  auto rec = [&](int row, int col) {
    auto *p = (double *) lammps_extract_fix(lmp.handle, col < 2 ? "recf" : "recv", LMP_STYLE_GLOBAL,
                                            LMP_TYPE_ARRAY, row, col % 2);
    const double v = p ? *p : NAN;
    lammps_free(p);
    return v;
  };
  double ratio_max = 0.0, wy_min = 0.0, vx_max = 0.0;
  int slipping = 0;
  for (int s = 1; s <= nsteps; s++) {
    const double fx = -rec(s, 0), fn = -rec(s, 1), vx = rec(s, 2), wy = rec(s, 3);
    ASSERT_GT(fn, 0.5) << s;
    ASSERT_LE(fx, 0.5 * fn * (1.0 + 1.0e-12)) << s;
    ratio_max = std::max(ratio_max, fx / fn);
    slipping += fx >= 0.5 * fn * (1.0 - 1.0e-12);
    wy_min = std::min(wy_min, wy);
    vx_max = std::max(vx_max, vx);
    if (s <= 50) {
      EXPECT_GT(fx, 0.0) << s;    // along the wall's motion while it slips
    }
  }
  EXPECT_NEAR(measured("drag: largest f_x / f_n", ratio_max), 0.5, 1.0e-12);
  EXPECT_GT(measured("drag: steps slipping at the cap", slipping), 10);
  // the friction force below the centre spins it backwards: the torque
  // -(a - delta/2) n x f_t has y component -(a - delta/2) f_x
  EXPECT_LT(measured("drag: most negative omega_y", wy_min), -100.0);
  const double vx_end = lmp.gather3("v")[0];
  EXPECT_NEAR(measured("drag: sphere v_x / wall u at the end", vx_end / u), 1.0, 0.02);
  EXPECT_LT(vx_max, 1.2 * u);
  EXPECT_GT(lmp.gather3("x")[0], x0);
}

// ---------------------------------------------------------------------------
// A packing compressed between walls
// ---------------------------------------------------------------------------

// 144 polydisperse spheres between walls at z = 0 and a top wall that is
// servo-controlled to a force of 5 N (about 140 kPa), then left to rest
// (tests/decks/wall_packing.lmp); written to a restart file once per test program.

class WallPacking : public ::testing::Test {
 protected:
  static void SetUpTestSuite()
  {
    restart = workfile("wall_packing.restart");
    Lammps lmp;
    lmp.cmds({"variable restart string " + restart, "variable mut_prep string 0.5",
              "variable dump string " + workfile("wall_packing.dump"),
              "include " + deck("wall_packing.lmp")});
  }
  static std::string restart;

  // the packing with its walls, pair style and contact histories
  static void read(Lammps &lmp)
  {
    lmp.cmds({"read_restart " + restart, "comm_modify vel yes", "neighbor 0.2e-3 bin",
              "neigh_modify delay 0 every 1 check yes",
              "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi 8.0e-3", "fix nve all nve/sphere"});
  }
};
std::string WallPacking::restart;

TEST_F(WallPacking, PressureAndNetworkStressMatchWallForces)
{
  Lammps lmp;
  read(lmp);
  lmp.cmds({"compute pv all pressure NULL virial", "compute pp all pressure NULL pair",
            "compute pf all pressure NULL fix", "variable zlo equal f_w[4]",
            "variable zhi equal f_w[10]",
            "compute net all grflow/network slab 1.0 zlimits v_zlo v_zhi",
            "compute ca all contact/atom", "compute cs all reduce sum c_ca",
            "compute fab all fabric radius contact", "compute sa all stress/atom NULL fix",
            "compute sas all reduce sum c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]",
            "thermo_style custom step ke c_pv[3] c_pp[3] c_pf[3] c_cs c_fab[1] c_sas[3]", "run 0"});
  const auto w = fvec(lmp, "w");
  const double vol = lmp.thermo("vol"), lx = lmp.thermo("lx"), ly = lmp.thermo("ly");
  const double flo = w[WallVector::LO_FZ], fhi = w[WallVector::HI_FZ], zlo = w[WallVector::LO_Z],
               zhi = w[WallVector::HI_Z];
  ASSERT_EQ(zlo, 0.0);
  ASSERT_LT(zhi, 8.0e-3);
  measured("packing: kinetic energy (J)", lmp.thermo("ke"));
  measured("packing: top wall force (N)", fhi);
  // precondition, not a result: a loaded packing (the deck servoes the top
  // wall to about 5 N, then lets it relax at rest); the identities below
  // hold at any load.  Particles push the lo wall down, the hi wall up.
  ASSERT_GT(fhi, 0.0);
  ASSERT_LT(flo, 0.0);
  // force balance, exact: the pair forces cancel, so the walls carry minus
  // the total force on the particles (round-off of sums of a few hundred
  // contact forces: 1e-12 of the load)
  const auto f = lmp.gather3("f");
  double fz_sum = 0.0, zf_sum = 0.0;
  for (int i = 0; i < lmp.natoms(); i++) fz_sum += f[3 * i + 2];
  measured("packing: |F_lo + F_hi| / F_hi (residual force of the packing at rest)",
           fabs(flo + fhi) / fhi);
  EXPECT_LT(fabs(flo + fhi + fz_sum) / fhi, 1.0e-12);

  // independent sum over wall contacts (run 0: f_n = k_n delta - c_n v_n)
  const auto x = lmp.gather3("x"), v = lmp.gather3("v");
  const auto rad = gather1(lmp, "radius");
  double wall_virial = 0.0, half_delta_fn = 0.0, fn_lo = 0.0, fn_hi = 0.0, delta_max = 0.0;
  int nwall = 0;
  for (int i = 0; i < lmp.natoms(); i++) zf_sum += x[3 * i + 2] * f[3 * i + 2];
  for (int i = 0; i < lmp.natoms(); i++)
    for (int iw = 0; iw < 2; iw++) {
      const double sign = iw == 0 ? 1.0 : -1.0;
      const double delta = rad[i] - sign * (x[3 * i + 2] - (iw == 0 ? zlo : zhi));
      if (delta <= 0.0) continue;
      const double fn = std::max(0.0, KN * delta - CN * sign * v[3 * i + 2]);
      if (fn <= 0.0) continue;
      nwall++;
      delta_max = std::max(delta_max, delta);
      wall_virial += (rad[i] - 0.5 * delta) * fn;
      half_delta_fn += 0.5 * delta * fn;
      (iw == 0 ? fn_lo : fn_hi) += fn;
    }
  measured("packing: wall contacts", nwall);
  ASSERT_GT(nwall, 6);
  EXPECT_NEAR(fn_lo, -flo, 1.0e-12 * fn_lo);
  EXPECT_NEAR(fn_hi, fhi, 1.0e-12 * fn_hi);

  // the fix virial is the sum of (a - delta/2) f_n over wall contacts, exactly
  const auto pf = cvec(lmp, "pf"), pp = cvec(lmp, "pp"), pv = cvec(lmp, "pv");
  EXPECT_LT(measured("packing: fix virial zz vs sum (a - delta/2) f_n",
                     fabs(pf[2] * vol - wall_virial) / wall_virial),
            1.0e-12);
  for (int k = 0; k < 6; k++) EXPECT_NEAR(pv[k], pp[k] + pf[k], 1.0e-12 * pv[2]) << k;
  // per-atom virial (compute stress/atom NULL fix): the same, atom by atom summed
  const auto sas = cvec(lmp, "sas");
  for (int k = 0; k < 6; k++) EXPECT_NEAR(-sas[k], pf[k] * vol, 1.0e-12 * pf[2] * vol) << k;
  EXPECT_GT(fabs(pf[4]) + fabs(pf[5]), 0.0);    // static friction at the walls

  // the virial identity, exact: W = sum_i z_i F_i + F_hi z_hi - F_lo z_lo
  // plus the contact points' offset delta/2 behind the walls (F_i the total
  // force on particle i, small at rest); round-off: 1e-12
  const double W = pv[2] * vol;
  const double balance = fhi * zhi - (-flo) * zlo + half_delta_fn;
  measured("packing: sum z_i F_i / W (the packing's residual at rest)", zf_sum / W);
  EXPECT_LT(measured("packing: P_zz V vs sum z_i F_i + F_hi z_hi - F_lo z_lo + sum f_n delta/2",
                     fabs(W - balance - zf_sum) / W),
            1.0e-12);
  // so W / (F_hi h) - 1 is bounded by the offsets, delta_max/h (with
  // F_lo ~ F_hi), and the residual; the doc's "within a fraction of order
  // delta/h"
  const double h = zhi - zlo;
  const double bound = delta_max / h + fabs(zf_sum) / (fhi * h) + fabs(flo + fhi) / fhi;
  measured("packing: P_zz V / (F (z_hi - z_lo)) - 1", W / (fhi * h) - 1.0);
  measured("packing: its bound delta_max/h + residuals", bound);
  EXPECT_LT(fabs(W / (fhi * h) - 1.0), bound);

  // compute grflow/network between the walls: sigma_zz A = |F| on each wall
  const auto net = cvec(lmp, "net");
  EXPECT_NEAR(net[NetVector::VOLUME], lx * ly * (zhi - zlo), 1.0e-14 * net[NetVector::VOLUME]);
  EXPECT_EQ(net[NetVector::NP], lmp.natoms());
  const double A = lx * ly;
  // sigma_zz A = W / h (checked exactly below): the same bound
  EXPECT_LT(measured("packing: sigma_zz A / F_hi - 1", fabs(net[NetVector::SZZ] * A / fhi - 1.0)),
            bound);
  EXPECT_LT(
      measured("packing: sigma_zz A / |F_lo| - 1", fabs(net[NetVector::SZZ] * A / -flo - 1.0)),
      bound * fhi / -flo + fabs(flo + fhi) / -flo);
  // and it is the virial of the same forces, pair and walls
  EXPECT_LT(measured("packing: sigma_zz V_net vs P_zz V_box",
                     fabs(net[NetVector::SZZ] * net[NetVector::VOLUME] - W) / W),
            1.0e-12);
  // without the wall contacts it would be far off
  EXPECT_GT((pp[2] * vol) / W, 0.0);
  EXPECT_GT(fabs(pp[2] * vol - W) / W, 0.01);

  // contacts: the pairs that touch (all loaded, at rest) and the wall contacts
  const double pairs = cscalar(lmp, "cs") / 2.0;
  EXPECT_EQ(net[NetVector::NCONTACT], pairs + 0.5 * nwall);
  // fabric: pair ends from compute fabric (a = 15/2 dev <nn>), wall ends n = e_z
  const auto fab = cvec(lmp, "fab");
  const double ends = 2.0 * pairs + nwall;
  EXPECT_NEAR(net[NetVector::AZZ], (2.0 * pairs * fab[2] + nwall * 5.0) / ends, 1.0e-12);
  EXPECT_NEAR(net[NetVector::AXX], (2.0 * pairs * fab[0] - nwall * 2.5) / ends, 1.0e-12);
}

TEST_F(WallPacking, RestartContinuesTrajectory)
{
  // shear: the top wall moves in x and y and slowly down
  const std::vector<std::string> shear = {"fix_modify w wall hi vel 0.05 -0.02 -0.002"};
  const std::string file = workfile("wall_restart.bin");
  std::vector<double> want_x, want_w, want_wall;
  double zhi_mid = 0.0, dx_mid = 0.0, dy_mid = 0.0;
  {
    Lammps lmp;
    read(lmp);
    lmp.cmds(shear);
    lmp.cmds({"run 1000"});
    const auto w = fvec(lmp, "w");
    zhi_mid = w[WallVector::HI_Z];
    dx_mid = w[WallVector::HI_DX];
    dy_mid = w[WallVector::HI_DY];
    lmp.cmds({"write_restart " + file, "run 1000"});
    want_x = lmp.gather3("x");
    want_w = lmp.gather3("omega");
    want_wall = fvec(lmp, "w");
  }
  EXPECT_GT(fabs(want_wall[WallVector::HI_FX]), 0.01);    // the top wall really shears

  // read_restart and the same fix command: walls and histories restored
  {
    Lammps lmp;
    lmp.cmds({"read_restart " + file, "comm_modify vel yes", "neighbor 0.2e-3 bin",
              "neigh_modify delay 0 every 1 check yes",
              "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi 8.0e-3", "fix nve all nve/sphere"});
    const auto w0 = fvec(lmp, "w");
    EXPECT_EQ(w0[WallVector::HI_Z], zhi_mid);
    EXPECT_EQ(w0[WallVector::HI_DX], dx_mid);
    EXPECT_EQ(w0[WallVector::HI_DY], dy_mid);
    lmp.cmd("run 1000");
    EXPECT_LT(measured("wall restart x", max_rel_diff(lmp.gather3("x"), want_x)), 1.0e-13);
    EXPECT_LT(measured("wall restart omega", max_rel_diff(lmp.gather3("omega"), want_w)), 1.0e-11);
    const auto w = fvec(lmp, "w");
    EXPECT_LT(measured("wall restart wall vector", max_rel_diff(w, want_wall)), 1.0e-10);
    EXPECT_EQ(w[WallVector::HI_Z], want_wall[WallVector::HI_Z]);
  }

  // the same walls (position and velocity set by hand) without the per-atom
  // wall history: the fix has another ID, so nothing is read for it
  {
    Lammps lmp;
    lmp.cmds({"read_restart " + file, "comm_modify vel yes", "neighbor 0.2e-3 bin",
              "neigh_modify delay 0 every 1 check yes",
              "fix other all grflow/wall 1.0e6 1.15 zlo 0.0 zhi " + fmt_double(zhi_mid),
              "fix_modify other wall hi vel 0.05 -0.02 -0.002", "fix nve all nve/sphere",
              "run 1000"});
    EXPECT_EQ(fvec(lmp, "other")[WallVector::HI_Z], want_wall[WallVector::HI_Z]);
    EXPECT_GT(measured("wall restart without wall history: omega",
                       max_rel_diff(lmp.gather3("omega"), want_w)),
              1.0e-6);
  }

  // a data file has no history at all
  {
    const std::string data = workfile("wall_restart.data");
    {
      Lammps mid;
      mid.cmds({"read_restart " + file, "write_data " + data});
    }
    Lammps lmp;
    lmp.cmds({"units si", "atom_style sphere", "atom_modify map array", "boundary p p f",
              "comm_modify vel yes", "read_data " + data + " nocoeff", "neighbor 0.2e-3 bin",
              "neigh_modify delay 0 every 1 check yes", "timestep 1.0e-7",
              "pair_style granular/grflow", "pair_coeff * * 1.0e6 1.15",
              "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi " + fmt_double(zhi_mid),
              "fix_modify w wall hi vel 0.05 -0.02 -0.002", "fix nve all nve/sphere", "run 1000"});
    EXPECT_GT(measured("wall restart from a data file: omega",
                       max_rel_diff(lmp.gather3("omega"), want_w)),
              1.0e-6);
  }
}

// ---------------------------------------------------------------------------
// The near list: between neighbor list builds only atoms near a wall are
// visited.  A fix adapt that changes nothing turns the list off (radii
// might change) and leaves the trajectory as it is, so with it the fix
// takes the full pass over all atoms on every step: both ways must give
// the same trajectory to the last bit, through many list builds and wall
// moves of more than skin/2.
// ---------------------------------------------------------------------------

TEST(FixWallNearList, SameTrajectoryAsTheFullPass)
{
  auto run = [](bool full_pass) {
    Lammps lmp;
    // a hot gas of 64 spheres at about 1 m/s (with a small skin the
    // neighbor lists are built every few dozen steps) between a fixed
    // bottom wall and a top wall coming down at 0.5 m/s
    lmp.cmds({"units si",
              "atom_style sphere",
              "atom_modify map array",
              "boundary p p f",
              "comm_modify vel yes",
              "lattice sc 2.0e-3",
              "region box block 0 4 0 4 0 5",
              "create_box 1 box",
              "region gas block 0 4 0 4 0.5 4.5",
              "create_atoms 1 region gas",
              "variable d atom 1.0e-3+random(0,1,4321)*0.6e-3",
              "set group all diameter v_d density 2650",
              "velocity all create 1.4e17 5 dist gaussian",
              "neighbor 1.0e-5 bin",
              "neigh_modify delay 0 every 1 check yes",
              "timestep 1.0e-7",
              "pair_style granular/grflow",
              "pair_coeff * * 1.0e6 1.15 mut 0.4",
              "fix w all grflow/wall 1.0e6 1.15 mut 0.4 zlo 0.0 zhi 9.0e-3",
              "fix_modify w wall hi vel 0.1 0 -0.5",
              "fix nve all nve/sphere",
              "variable mu equal 0.4",
              "thermo 1000"});
    if (full_pass) lmp.cmd("fix adapt all adapt 1 pair granular/grflow mut * * v_mu");
    // the mean normal force on the walls over the run: they are touched
    lmp.cmds({"variable fz equal abs(f_w[3])+abs(f_w[9])", "fix fz all ave/time 1 20000 20000 v_fz",
              "run 20000"});
    struct Result {
      std::vector<double> x, v, w, wall;
      double builds, fz;
    } r{lmp.gather3("x"),
        lmp.gather3("v"),
        lmp.gather3("omega"),
        fvec(lmp, "w"),
        lmp.thermo("nbuild"),
        *(double *) lammps_extract_fix(lmp.handle, "fz", LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR, 0, 0)};
    return r;
  };
  const auto near = run(false), full = run(true);
  measured("near list: neighbor list builds in 20000 steps", near.builds);
  EXPECT_GT(near.builds, 50.0);
  EXPECT_EQ(near.builds, full.builds);
  EXPECT_EQ(near.x, full.x);
  EXPECT_EQ(near.v, full.v);
  EXPECT_EQ(near.w, full.w);
  EXPECT_EQ(near.wall, full.wall);
  EXPECT_GT(measured("near list: mean wall normal force (N)", near.fz), 0.0);
  EXPECT_EQ(near.fz, full.fz);
  // the top wall came down 1 mm, 20 times skin/2
  EXPECT_NEAR(near.wall[WallVector::HI_Z], 8.0e-3, 1.0e-9);
}

// ---------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------

const std::vector<std::string> one_sphere = {"units si",
                                             "atom_style sphere",
                                             "atom_modify map array",
                                             "boundary p p f",
                                             "region box block 0 0.01 0 0.01 0 0.01",
                                             "create_box 1 box",
                                             "create_atoms 1 single 0.005 0.005 0.005",
                                             "set atom 1 diameter 1.0e-3 density 2650",
                                             "timestep 1.0e-6"};

TEST(FixWallErrors, BadFixCommand)
{
  struct Case {
    const char *line, *expect;
  } cases[] = {
      {"fix w all grflow/wall 1.0e6", "Incorrect args for fix grflow/wall: expected kn cn"},
      // kn and cn left out: the message names the coefficient
      {"fix w all grflow/wall zlo 0.0 zhi 0.02", "fix grflow/wall kn expects a number, got 'zlo'"},
      {"fix w all grflow/wall 1.0e6 1.15", "Fix grflow/wall needs a wall: zlo and/or zhi"},
      {"fix w all grflow/wall 1.0e6 1.15 mut 0.3", "needs a wall"},
      {"fix w all grflow/wall 1.0e6 1.15 zlo", "Illegal fix grflow/wall zlo command: missing"},
      {"fix w all grflow/wall 1.0e6 1.15 zhi", "Illegal fix grflow/wall zhi command: missing"},
      {"fix w all grflow/wall 1.0e6 1.15 zlo abc",
       "fix grflow/wall zlo expects a number, got 'abc'"},
      {"fix w all grflow/wall 1.0e6 1.15 zlo 0.0 foo 1", "Unknown fix grflow/wall keyword: foo"},
      {"fix w all grflow/wall 1.0e6 1.15 zlo 0.006 zhi 0.004",
       "Fix grflow/wall zhi 0.004 must be above zlo 0.006"},
      {"fix w all grflow/wall 1.0e6 1.15 zlo 0.005 zhi 0.005", "must be above zlo"},
      {"fix w all grflow/wall 1.0e6 1.15 zlo 0.0 velocity_arm half",
       "Unknown fix grflow/wall velocity_arm value half: expected reduced or full"},
      {"fix w all grflow/wall 1.0e6 1.15 zlo 0.0 velocity_arm",
       "Illegal fix grflow/wall velocity_arm command: missing"},
      {"fix w all grflow/wall 1.0e6 1.15 mut -0.1 zlo 0.0", "fix grflow/wall: mut must be >= 0"},
      {"fix w all grflow/wall 0 1.15 zlo 0.0", "fix grflow/wall: kn must be > 0"},
      {"fix w all grflow/wall 1.0e6 -1 zlo 0.0", "fix grflow/wall: cn must be >= 0"},
      {"fix w all grflow/wall 1.0e6 1.15 rolling on zlo 0.0",
       "fix grflow/wall rolling takes only the value off, not on"},
      {"fix w all grflow/wall 1.0e6 1.15 kt", "Missing value for fix grflow/wall keyword kt"},
      {"fix w all grflow/wall 1.0e6 1.15 zlo 0.0 mut 0.3",
       "contact keyword mut must come right after kn cn"},
  };
  for (const auto &c : cases) {
    const std::string msg = error_after(one_sphere, c.line);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.line << " -> '" << msg << "'";
  }

  std::string msg = error_after({"units si", "atom_style sphere", "boundary p p p",
                                 "region box block 0 0.01 0 0.01 0 0.01", "create_box 1 box"},
                                "fix w all grflow/wall 1.0e6 1.15 zlo 0.0");
  EXPECT_NE(msg.find("Fix grflow/wall needs a non-periodic z boundary"), std::string::npos) << msg;
  msg = error_after({"units si", "atom_style atomic", "boundary p p f",
                     "region box block 0 0.01 0 0.01 0 0.01", "create_box 1 box"},
                    "fix w all grflow/wall 1.0e6 1.15 zlo 0.0");
  EXPECT_NE(msg.find("requires atom attributes radius, omega and torque"), std::string::npos)
      << msg;
}

TEST(FixWallErrors, BadFixModify)
{
  auto setup = one_sphere;
  setup.push_back("fix w all grflow/wall 1.0e6 1.15 zlo 0.001 zhi 0.009");
  struct Case {
    const char *line, *expect;
  } cases[] = {
      {"fix_modify w wall", "Illegal fix_modify grflow/wall wall command: missing"},
      {"fix_modify w wall lo vel", "Illegal fix_modify grflow/wall wall command: missing"},
      {"fix_modify w wall mid vel 0 0 0", "fix_modify w wall: expected lo or hi, got mid"},
      {"fix_modify w wall lo vel 0 0", "Illegal fix_modify grflow/wall wall vel command: missing"},
      {"fix_modify w wall lo vel a 0 0", "expects a number, got 'a'"},
      {"fix_modify w wall lo speed 0 0 0", "fix_modify w wall lo: expected vel or z, got speed"},
      {"fix_modify w wall lo z 0.0095", "fix_modify w: zhi 0.009 must be above zlo 0.0095"},
      {"fix_modify w wall hi z 0.0005", "must be above zlo"},
      {"fix_modify w bogus 1", "does not support fix_modify bogus command"},
  };
  for (const auto &c : cases) {
    const std::string msg = error_after(setup, c.line);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.line << " -> '" << msg << "'";
  }
  auto lo_only = one_sphere;
  lo_only.push_back("fix w all grflow/wall 1.0e6 1.15 zlo 0.001");
  const std::string msg = error_after(lo_only, "fix_modify w wall hi vel 0 0 -1");
  EXPECT_NE(msg.find("fix_modify w wall hi: this fix has no such wall"), std::string::npos) << msg;
}

TEST(FixWallErrors, CrossingAWall)
{
  // centre already beyond a wall
  auto setup = one_sphere;
  setup.push_back("fix w all grflow/wall 1.0e6 1.15 zlo 0.0055");
  std::string msg = error_after(setup, "run 0");
  EXPECT_NE(msg.find("Fix grflow/wall w: atom 1 crossed the zlo wall (z = 0.005, wall at 0.0055)"),
            std::string::npos)
      << msg;
  setup.back() = "fix w all grflow/wall 1.0e6 1.15 zhi 0.0045";
  msg = error_after(setup, "run 0");
  EXPECT_NE(msg.find("atom 1 crossed the zhi wall"), std::string::npos) << msg;

  // a fast sphere on a soft wall goes through during the run: an error,
  // not a hang, and the instance is still usable
  {
    Lammps lmp;
    lmp.cmds(one_sphere);
    lmp.cmds({"fix w all grflow/wall 1.0 0.0 zlo 0.001", "fix nve all nve/sphere",
              "set atom 1 vz -100.0", "timestep 1.0e-7"});
    msg = lmp.error_of("run 10000");
    EXPECT_NE(msg.find("atom 1 crossed the zlo wall"), std::string::npos) << msg;
    EXPECT_LT(lmp.gather3("x")[2], 0.001);
  }
  // a wall moved onto a sphere
  {
    Lammps lmp;
    lmp.cmds(one_sphere);
    lmp.cmds({"fix w all grflow/wall 1.0 0.0 zlo 0.001 zhi 0.009", "fix nve all nve/sphere",
              "fix_modify w wall hi vel 0 0 -100"});
    msg = lmp.error_of("run 1000");
    EXPECT_NE(msg.find("crossed the zhi wall"), std::string::npos) << msg;
  }
  // the top wall reaching the bottom one (no atom in the way)
  {
    Lammps lmp;
    lmp.cmds(one_sphere);
    lmp.cmds({"group nobody empty", "fix w nobody grflow/wall 1.0e6 1.15 zlo 0.001 zhi 0.009",
              "fix_modify w wall hi vel 0 0 -100"});
    msg = lmp.error_of("run 1000");
    EXPECT_NE(msg.find("Fix grflow/wall w: the top wall has reached the bottom wall"),
              std::string::npos)
        << msg;
  }
}

TEST(FixWallErrors, RespaAndRestartMismatch)
{
  auto setup = one_sphere;
  setup.insert(setup.end(), {"fix w all grflow/wall 1.0e6 1.15 zlo 0.001", "run_style respa 2 2"});
  std::string msg = error_after(setup, "run 0");
  EXPECT_NE(msg.find("Fix grflow/wall does not support run_style respa"), std::string::npos) << msg;

  const std::string file = workfile("wall_mismatch.restart");
  {
    Lammps lmp;
    lmp.cmds(one_sphere);
    lmp.cmds(
        {"fix w all grflow/wall 1.0e6 1.15 zlo 0.001 zhi 0.009", "run 0", "write_restart " + file});
  }
  msg = error_after({"read_restart " + file}, "fix w all grflow/wall 1.0e6 1.15 zlo 0.001");
  EXPECT_NE(msg.find("Fix grflow/wall w: restart file has other walls than the command"),
            std::string::npos)
      << msg;
}

// The wall's restart data carry a header (grflow_host.h): a restart
// file whose block was written by a newer format, has another size or
// holds a non-finite value stops read_restart's fix command with an error
// that names the fix.  The damage is made in the bytes of a written file,
// found by the header's tag.
TEST(FixWallErrors, DamagedRestartData)
{
  const std::string file = workfile("wall_damage.restart");
  {
    Lammps lmp;
    lmp.cmds(one_sphere);
    lmp.cmds({"fix w all grflow/wall 1.0e6 1.15 zlo 0.001 zhi 0.009",
              "fix_modify w wall hi vel 0.01 0 0", "run 0", "write_restart " + file});
  }
  ASSERT_NE(grflow_block(file_bytes(file), 14.0), std::string::npos)
      << "no single GRFLOW restart block of 14 values in " << file;
  auto damaged = [&](int k, double x) {
    return error_after(
        {"read_restart " + damaged_restart(file, 14.0, k, x, "wall_damaged.restart")},
        "fix w all grflow/wall 1.0e6 1.15 zlo 0.001 zhi 0.009");
  };
  // undamaged: read back
  {
    Lammps lmp;
    lmp.cmds({"read_restart " + file, "fix w all grflow/wall 1.0e6 1.15 zlo 0.001 zhi 0.009"});
  }
  std::string msg = damaged(1, 99.0);
  EXPECT_NE(msg.find("Fix grflow/wall w: restart data of format version 99; this GRFLOW reads "
                     "versions up to 1"),
            std::string::npos)
      << msg;
  msg = damaged(2, 13.0);
  EXPECT_NE(msg.find("hold 13 values, expected 14: the file is damaged"), std::string::npos) << msg;
  // the top wall's z (values: lo active z vx vy vz dx dy, hi active z ...)
  msg = damaged(3 + 8, std::numeric_limits<double>::quiet_NaN());
  EXPECT_NE(msg.find("Fix grflow/wall w: restart value 9 of 14 is nan"), std::string::npos) << msg;
  msg = damaged(3 + 9, std::numeric_limits<double>::infinity());
  EXPECT_NE(msg.find("restart value 10 of 14 is inf"), std::string::npos) << msg;
}

}    // namespace
