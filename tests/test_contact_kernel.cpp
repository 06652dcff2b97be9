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
   Unit tests for the GRFLOW contact kernel (src/shared/grflow_contact.h)
   against closed-form results of the contact law written out in
   notes/contact-law.md (linear spring-dashpot after Luding 2008):

   - sphere-sphere geometry (normal, overlap, arms, reduced radius)
   - head-on collision: restitution coefficient and duration of the
     linear spring-dashpot with the no-attraction clip, and without it
     (the unclipped law: closed-form restitution, caps in tension)
   - sliding, rolling and torsion: elastic phase, slip step, Coulomb caps,
     slip reset, torques and contact-point kinematics
   - energy balance (work = stored + viscous + friction) and the power
     identity (bodies' power = sum of mode force * mode velocity)
   - invariance under i <-> j with HISTORY_SWAP_FACTOR
   - update = false, rotate_into_plane() and springs following a turning
     normal, zero coefficients / zero f_n

   Reference values are computed here from the analytic formulas, never
   taken from output of the kernel.
------------------------------------------------------------------------- */

#include "grflow_contact.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace LAMMPS_NS::GRFLOW;

namespace {

using V3 = std::array<double, 3>;

constexpr double PI = 3.14159265358979323846;
constexpr double RHO = 2650.0;    // grain density, kg/m^3 (Table 1)

/* ---------------------------------------------------------------------- */
// small vector helpers (named functions: no operator overloads on std::array)

V3 add(const V3 &a, const V3 &b)
{
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

V3 sub(const V3 &a, const V3 &b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

V3 mul(double s, const V3 &a)
{
  return {s * a[0], s * a[1], s * a[2]};
}

double dotv(const V3 &a, const V3 &b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

V3 crossv(const V3 &a, const V3 &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double norm(const V3 &a)
{
  return std::sqrt(dotv(a, a));
}

V3 unit(const V3 &a)
{
  return mul(1.0 / norm(a), a);
}

V3 tov(const double *p)
{
  return {p[0], p[1], p[2]};
}

bool finite3(const double *p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// orthonormal triad with n x t1 = -t2 (exact in real numbers)

const V3 N_AX = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
const V3 T1_AX = {2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0};
const V3 T2_AX = {2.0 / 3.0, -2.0 / 3.0, 1.0 / 3.0};

#define EXPECT_VEC_NEAR(a, b, tol)          \
  do {                                      \
    const V3 a_ = (a), b_ = (b);            \
    EXPECT_NEAR(a_[0], b_[0], (tol)) << #a; \
    EXPECT_NEAR(a_[1], b_[1], (tol)) << #a; \
    EXPECT_NEAR(a_[2], b_[2], (tol)) << #a; \
  } while (0)

/* ---------------------------------------------------------------------- */

// Table 1 of the paper (SI units)

ContactCoeffs table1()
{
  const double kn = 1.0e6, cn = 1.15;
  ContactCoeffs c;
  c.kn = kn;
  c.cn = cn;
  c.kt = 0.8 * kn;
  c.ct = 0.2 * cn;
  c.mut = 0.5;
  c.kr = 0.1 * kn;
  c.cr = 0.05 * cn;
  c.mur = 0.1;
  c.ko = 0.1 * kn;
  c.co = 0.05 * cn;
  c.muo = 0.1;
  return c;
}

double sphere_mass(double radius)
{
  return 4.0 / 3.0 * PI * radius * radius * radius * RHO;
}

// geometry written out from the spec (independent of pair_geometry())

ContactGeometry make_geometry(const V3 &n, double radi, double radj, double delta, bool full_arm)
{
  ContactGeometry g;
  for (int d = 0; d < 3; ++d) g.n[d] = n[d];
  g.delta = delta;
  g.arm_i = radi - 0.5 * delta;
  g.arm_j = radj - 0.5 * delta;
  g.varm_i = full_arm ? radi : g.arm_i;
  g.varm_j = full_arm ? radj : g.arm_j;
  g.reff = radi * radj / (radi + radj);
  return g;
}

// mode velocities of the spec, from body velocities (varm: arms for the contact point)

struct ModeVelocities {
  double vn;
  V3 vt, vr;
  double vo;
};

ModeVelocities mode_velocities(const ContactGeometry &g, const V3 &vrel, const V3 &wi, const V3 &wj)
{
  const V3 n = tov(g.n);
  ModeVelocities m;
  m.vn = dotv(vrel, n);
  const V3 warm = add(mul(g.varm_i, wi), mul(g.varm_j, wj));
  m.vt = sub(sub(vrel, mul(m.vn, n)), crossv(warm, n));
  const V3 wrel = sub(wi, wj);
  m.vr = mul(-g.reff, crossv(n, wrel));
  m.vo = g.reff * dotv(wrel, n);
  return m;
}

}    // namespace

/* ----------------------------------------------------------------------
   pair_geometry(): n = del/|del|, delta = a_i + a_j - r, arms a - delta/2
   (or full radii), a' = a_i a_j/(a_i + a_j). del = (3,-4,12)e-4 has |del| =
   13e-4 exactly.
------------------------------------------------------------------------- */

TEST(ContactKernel, PairGeometryMatchesSpec)
{
  const double del[3] = {3.0e-4, -4.0e-4, 12.0e-4};
  const double r = 13.0e-4, radi = 0.8e-3, radj = 0.6e-3;
  const double tol = 1.0e-15;

  for (bool full_arm : {false, true}) {
    ContactGeometry g;
    pair_geometry(del, r, radi, radj, full_arm, g);
    EXPECT_NEAR(g.n[0], 3.0 / 13.0, 1.0e-15);
    EXPECT_NEAR(g.n[1], -4.0 / 13.0, 1.0e-15);
    EXPECT_NEAR(g.n[2], 12.0 / 13.0, 1.0e-15);
    EXPECT_NEAR(g.delta, 1.0e-4, tol);
    EXPECT_NEAR(g.arm_i, 0.75e-3, tol);
    EXPECT_NEAR(g.arm_j, 0.55e-3, tol);
    EXPECT_NEAR(g.varm_i, full_arm ? 0.8e-3 : 0.75e-3, tol);
    EXPECT_NEAR(g.varm_j, full_arm ? 0.6e-3 : 0.55e-3, tol);
    EXPECT_NEAR(g.reff, 0.48e-6 / 1.4e-3, tol);
  }
}

// wall_geometry(): a flat wall normal to z, sphere of radius 0.8 mm whose
// centre is 0.7 mm from it: delta = 0.1 mm, arm a - delta/2, the wall a
// sphere of infinite radius (a' = a), normal +z for a wall below, -z above
TEST(ContactKernel, WallGeometryMatchesSpec)
{
  const double rad = 0.8e-3, gap = 0.7e-3, tol = 1.0e-18;
  for (double sign : {1.0, -1.0})
    for (bool full_arm : {false, true}) {
      ContactGeometry g;
      wall_geometry(gap, rad, sign, full_arm, g);
      EXPECT_EQ(g.n[0], 0.0);
      EXPECT_EQ(g.n[1], 0.0);
      EXPECT_EQ(g.n[2], sign);
      EXPECT_NEAR(g.delta, 0.1e-3, tol);
      EXPECT_NEAR(g.arm_i, 0.75e-3, tol);
      EXPECT_EQ(g.arm_j, 0.0);
      EXPECT_NEAR(g.varm_i, full_arm ? 0.8e-3 : 0.75e-3, tol);
      EXPECT_EQ(g.varm_j, 0.0);
      EXPECT_EQ(g.reff, rad);
    }
}

/* ----------------------------------------------------------------------
   Head-on collision of two spheres (no rotation).

   With x = overlap, x' = -v_n, m = m1 m2/(m1+m2), w0^2 = kn/m, eta = cn/(2m),
   w^2 = w0^2 - eta^2, the contact obeys m x'' = -(kn x + cn x') while that
   force is > 0, from x(0) = 0, x'(0) = v0:
     x(t)  = (v0/w) e^{-eta t} sin(w t)
     x'(t) = v0 e^{-eta t} (cos wt - (eta/w) sin wt)
   The force kn x + cn x' = -m x'' vanishes first at w t_f = phi, with
     tan(phi) = -2 eta w/(w^2 - eta^2),  phi in (0, pi)
   i.e. cos(phi) = -(w^2 - eta^2)/w0^2, sin(phi) = 2 eta w/w0^2, and there
     x'(t_f) = -v0 e^{-eta t_f} (w^2 + eta^2)/w0^2 = -v0 e^{-eta t_f}.
   Afterwards x' stays constant and kn x + cn x' keeps decreasing, so the
   clipped force stays zero although x > 0: the spheres leave with
     e = exp(-eta t_f)    (not exp(-pi eta/w) at t = pi/w, the unclipped law).
   Integration: velocity Verlet as in LAMMPS (force from half-step
   velocities), dt = t_f/NSTEPS. Its error is O(dt).
------------------------------------------------------------------------- */

// one head-on collision, integrated as LAMMPS's velocity Verlet does
// (force from half-step velocities) with timestep dt; analytic values above

struct HeadOn {
  double e_ana, e_unclipped, t_f;    // analytic
  double e_num, t_num, vsep;         // numeric; vsep: separation speed when fn first is 0
  V3 v_rel, p, p0;                   // final relative velocity, momentum before and after
  bool separated, overlapping_at_zero;
};

HeadOn head_on(const ContactCoeffs &c, double r1, double r2, double dt_per_tf, double dt_abs,
               const V3 &e_ax)
{
  HeadOn h{};
  const double m1 = sphere_mass(r1), m2 = sphere_mass(r2);
  const double meff = m1 * m2 / (m1 + m2);
  const double w0 = std::sqrt(c.kn / meff);
  const double eta = c.cn / (2.0 * meff);
  const double w = std::sqrt(w0 * w0 - eta * eta);
  const double phi = PI - std::atan2(2.0 * eta * w, w * w - eta * eta);
  h.t_f = phi / w;
  h.e_ana = std::exp(-eta * h.t_f);
  h.e_unclipped = std::exp(-PI * eta / w);
  const double dt = (dt_abs > 0.0) ? dt_abs : h.t_f * dt_per_tf;

  // start touching (delta = 0), centre of mass at rest, approach speed v0

  const double v0 = 1.0;
  V3 x1 = {1.0e-3, 2.0e-3, -0.5e-3};
  V3 x2 = sub(x1, mul(r1 + r2, e_ax));
  V3 v1 = mul(-v0 * m2 / (m1 + m2), e_ax);
  V3 v2 = mul(v0 * m1 / (m1 + m2), e_ax);
  h.p0 = add(mul(m1, v1), mul(m2, v2));
  const V3 zero = {0.0, 0.0, 0.0};
  double hist[HIST_SIZE] = {0.0};
  ContactForces out;
  ContactGeometry g;

  auto force = [&](V3 &f1) {
    const V3 del = sub(x1, x2);
    pair_geometry(del.data(), norm(del), r1, r2, false, g);
    const V3 vrel = sub(v1, v2);
    contact_forces(c, g, vrel.data(), zero.data(), zero.data(), dt, true, hist, out);
    f1 = tov(out.f);
  };

  V3 f1;
  force(f1);    // t = 0: delta = 0, fn = cn v0
  EXPECT_NEAR(out.fn, c.cn * v0, 1.0e-9 * c.cn * v0);

  int k_zero = -1;    // first step with fn == 0
  const int kmax = 10 * static_cast<int>(h.t_f / dt + 1.0);
  for (int k = 1; k < kmax; ++k) {
    v1 = add(v1, mul(0.5 * dt / m1, f1));
    v2 = add(v2, mul(-0.5 * dt / m2, f1));
    x1 = add(x1, mul(dt, v1));
    x2 = add(x2, mul(dt, v2));
    const V3 del = sub(x1, x2);
    if (r1 + r2 - norm(del) > 0.0) {
      force(f1);
    } else {
      f1 = zero;
      h.separated = true;
    }
    v1 = add(v1, mul(0.5 * dt / m1, f1));
    v2 = add(v2, mul(-0.5 * dt / m2, f1));
    if (k_zero < 0 && out.fn == 0.0) {
      k_zero = k;
      h.vsep = dotv(sub(v1, v2), e_ax);
      h.overlapping_at_zero = (g.delta > 0.0);
    }
    if (h.separated) break;
  }
  h.e_num = dotv(sub(v1, v2), e_ax) / v0;
  h.t_num = (k_zero - 0.5) * dt;    // fn = 0 somewhere in the last step
  h.v_rel = sub(v1, v2);
  h.p = add(mul(m1, v1), mul(m2, v2));
  return h;
}

TEST(ContactKernel, HeadOnRestitutionAndDuration)
{
  const ContactCoeffs c = table1();
  const double radii[][2] = {{1.0e-3, 1.0e-3}, {1.0e-3, 0.5e-3}, {0.7e-3, 0.6e-3}};
  const int NSTEPS = 2000;                   // integration steps per analytic contact time
  const double tol_e = 1.0e-3;               // relative tolerance on e
  const double tol_t = 1.0e-3;               // relative tolerance on the contact duration
  const V3 e_ax = unit({2.0, -1.0, 2.0});    // direction from j to i

  for (const auto &rad : radii) {
    const double r1 = rad[0], r2 = rad[1];
    SCOPED_TRACE("radii " + std::to_string(r1) + " " + std::to_string(r2));
    const double m1 = sphere_mass(r1), m2 = sphere_mass(r2);
    const double meff = m1 * m2 / (m1 + m2);
    ASSERT_LT(c.cn / (2.0 * meff), std::sqrt(c.kn / meff));    // underdamped
    const HeadOn h = head_on(c, r1, r2, 1.0 / NSTEPS, 0.0, e_ax);
    ASSERT_TRUE(h.separated);
    ASSERT_GT(h.t_num, 0.0);
    EXPECT_TRUE(h.overlapping_at_zero);    // force-free while still overlapping

    const double err_e = std::fabs(h.e_num - h.e_ana) / h.e_ana;
    const double err_t = std::fabs(h.t_num - h.t_f) / h.t_f;
    std::printf("[   INFO   ] a=(%g,%g): e analytic %.6f (unclipped %.6f) numeric %.6f "
                "rel err %.2e (tol %.0e); t_f %.4e s rel err %.2e (tol %.0e)\n",
                r1, r2, h.e_ana, h.e_unclipped, h.e_num, err_e, tol_e, h.t_f, err_t, tol_t);
    EXPECT_NEAR(h.e_num, h.e_ana, tol_e * h.e_ana);
    EXPECT_NEAR(h.t_num, h.t_f, tol_t * h.t_f);
    // after fn has returned to zero the spheres fly freely
    EXPECT_NEAR(dotv(h.v_rel, e_ax), h.vsep, 1.0e-12);
    // momentum is conserved (force on j = -force on i)
    EXPECT_VEC_NEAR(h.p, h.p0, 1.0e-12 * m1);
    // the test must tell the clipped law from the unclipped one
    EXPECT_GT(std::fabs(h.e_ana - h.e_unclipped), 20.0 * tol_e * h.e_ana);
  }
}

/* ----------------------------------------------------------------------
   The decks' timestep rule dt = dt_factor sqrt(m_min/kn) (inputs/params.lmp)
   for the collision of two smallest spheres (d_min = 1 mm, rho = 2650), the
   shortest and most strongly damped contact of the sample (eta/w0 = 0.69,
   t_f = 1.58 sqrt(m_min/kn)): the error of the restitution coefficient at
   each dt_factor, printed for the docs (inputs/README.md, "Timestep").
   Velocity Verlet with the damping force from half-step velocities is
   first order here, so the error halves with dt once the contact spans
   enough steps (checked from dt_factor 0.1 down: ratio 0.5 +- 0.1, the
   slack for where in its last step the contact ends); above that the
   error is not monotone (the end of the contact jumps between steps), but
   the collision must stay stable and dissipative.
------------------------------------------------------------------------- */

TEST(ContactKernel, RestitutionAtDeckTimesteps)
{
  const ContactCoeffs c = table1();
  const double r = 0.5e-3;
  const double m = sphere_mass(r);
  const V3 e_ax = unit({1.0, 2.0, -2.0});
  const double factors[] = {0.6, 0.4, 0.3, 0.2, 0.1, 0.05, 0.025};
  double prev = -1.0;
  for (double f : factors) {
    const HeadOn h = head_on(c, r, r, 0.0, f * std::sqrt(m / c.kn), e_ax);
    ASSERT_TRUE(h.separated) << "dt_factor " << f;
    const double err = std::fabs(h.e_num - h.e_ana) / h.e_ana;
    std::printf("[ measured ] dt_factor %.3f (%.1f steps per contact): e analytic %.5f numeric "
                "%.5f rel err %.2e\n",
                f, h.t_f / (f * std::sqrt(m / c.kn)), h.e_ana, h.e_num, err);
    EXPECT_GT(h.e_num, 0.0) << "dt_factor " << f;    // the spheres separate ...
    EXPECT_LT(h.e_num, 1.0) << "dt_factor " << f;    // ... with less energy
    if (f < 0.1) EXPECT_NEAR(err / prev, 0.5, 0.1) << "dt_factor " << f;
    prev = err;
  }
}

/* ----------------------------------------------------------------------
   Sliding at constant overlap (fn = kn delta, v_n = 0), constant tangential
   velocity v = V t1, no spin, dt per step, from xi = 0:
     stick, step k:  f_t = -(kt k V dt + ct V) t1
     slip when kt k V dt + ct V > mut fn, i.e. from k* = floor(K) + 1,
       K = (mut fn - ct V)/(kt V dt); then f_t = -mut fn t1 and
       xi = -(f_t + ct v)/kt = (mut fn - ct V)/kt t1.
   Reversal (v = -V t1) from the slip state, step m:
     f_t = (-mut fn + 2 ct V + kt m V dt) t1    (the reset keeps ct v in xi)
     slip again (f_t = +mut fn t1) from m* = floor(M) + 1,
       M = 2 (mut fn - ct V)/(kt V dt).
   Torques: on i -(a_i - delta/2) n x f_t, on j -(a_j - delta/2) n x f_t.
------------------------------------------------------------------------- */

TEST(ContactKernel, SlidingStickThenSlip)
{
  const ContactCoeffs c = table1();
  const double radi = 1.0e-3, radj = 0.8e-3, delta = 1.0e-5;
  const ContactGeometry g = make_geometry(N_AX, radi, radj, delta, false);
  const double fn = c.kn * delta;
  const double cap = c.mut * fn;
  const double V = 0.1, dt = 1.0e-8;
  const double tol = 1.0e-9 * cap;    // round-off of ~1e4 accumulated increments
  const V3 zero = {0.0, 0.0, 0.0};

  const double K = (cap - c.ct * V) / (c.kt * V * dt);
  const double M = 2.0 * (cap - c.ct * V) / (c.kt * V * dt);
  // setup sanity: elastic limits not within round-off of a step
  ASSERT_GT(K - std::floor(K), 0.05);
  ASSERT_LT(K - std::floor(K), 0.95);
  ASSERT_GT(M - std::floor(M), 0.05);
  ASSERT_LT(M - std::floor(M), 0.95);
  const int kslip = static_cast<int>(std::floor(K)) + 1;
  const int mslip = static_cast<int>(std::floor(M)) + 1;

  double hist[HIST_SIZE] = {0.0};
  ContactForces out;
  double max_err = 0.0;

  auto check_torques = [&](const V3 &ft) {
    const V3 nxft = crossv(N_AX, ft);
    EXPECT_VEC_NEAR(tov(out.torque_i), mul(-(radi - 0.5 * delta), nxft), tol * radi);
    EXPECT_VEC_NEAR(tov(out.torque_j), mul(-(radj - 0.5 * delta), nxft), tol * radi);
    EXPECT_VEC_NEAR(tov(out.f), add(mul(fn, N_AX), ft), tol);
  };

  // loading

  const V3 v = mul(V, T1_AX);
  int first_slip = -1;
  for (int k = 1; k <= kslip + 50; ++k) {
    contact_forces(c, g, v.data(), zero.data(), zero.data(), dt, true, hist, out);
    ASSERT_NEAR(out.fn, fn, 1.0e-12 * fn);
    const V3 ft = tov(out.ft);
    if (first_slip < 0 && norm(ft) >= cap * (1.0 - 1.0e-12)) first_slip = k;
    V3 ft_ana;
    if (k < kslip) {
      ft_ana = mul(-(c.kt * k * V * dt + c.ct * V), T1_AX);
      EXPECT_LT(norm(ft), cap);
    } else {
      ft_ana = mul(-cap, T1_AX);
      EXPECT_NEAR(norm(ft), cap, 1.0e-13 * cap);
      EXPECT_VEC_NEAR(tov(hist + HIST_SLIDE), mul((cap - c.ct * V) / c.kt, T1_AX), tol / c.kt);
    }
    EXPECT_VEC_NEAR(ft, ft_ana, tol);
    max_err = std::fmax(max_err, norm(sub(ft, ft_ana)) / cap);
    check_torques(ft_ana);
  }
  EXPECT_EQ(first_slip, kslip);
  const int first_slip_load = first_slip;

  // unloading from the slip state, then slip the other way

  const V3 vback = mul(-V, T1_AX);
  first_slip = -1;
  for (int m = 1; m <= mslip + 50; ++m) {
    contact_forces(c, g, vback.data(), zero.data(), zero.data(), dt, true, hist, out);
    const V3 ft = tov(out.ft);
    if (first_slip < 0 && m > 1 && norm(ft) >= cap * (1.0 - 1.0e-12)) first_slip = m;
    const V3 ft_ana = (m < mslip) ? mul(-cap + 2.0 * c.ct * V + c.kt * m * V * dt, T1_AX)
                                  : mul(cap, T1_AX);
    EXPECT_VEC_NEAR(ft, ft_ana, tol);
    max_err = std::fmax(max_err, norm(sub(ft, ft_ana)) / cap);
    check_torques(ft_ana);
  }
  EXPECT_EQ(first_slip, mslip);
  std::printf("[   INFO   ] sliding: slip at step %d (analytic %d), reverse slip at %d "
              "(analytic %d); max |f_t - analytic|/(mu_t f_n) = %.2e (tol 1e-9)\n",
              first_slip_load, kslip, first_slip, mslip, max_err);
}

/* ----------------------------------------------------------------------
   Sliding velocity = relative velocity of the material points at the contact
   point c = x_i - (a_i - delta/2) n, from rigid-body kinematics:
     u_i = v_i + w_i x (c - x_i),  u_j = v_j + w_j x (c - x_j),
     v_t = (u_i - u_j) - ((u_i - u_j).n) n
   (full radii for the stock-compatible arms). First step from xi = 0 in
   stick: f_t = -(kt dt + ct) v_t. Rolling without slip gives f_t = 0.
------------------------------------------------------------------------- */

TEST(ContactKernel, SlidingVelocityFromSpins)
{
  const ContactCoeffs c = table1();
  const double radi = 1.0e-3, radj = 0.6e-3, delta = 2.0e-5, dt = 1.0e-7;
  const V3 n = unit({-1.0, 0.3, 0.8});
  const V3 xj = {0.1e-3, -0.2e-3, 0.3e-3};
  const V3 xi = add(xj, mul(radi + radj - delta, n));
  const V3 vi = {0.01, -0.02, 0.005}, vj = {-0.004, 0.01, 0.02};
  const V3 wi = {12.0, -7.0, 3.0}, wj = {-5.0, 9.0, 11.0};

  for (bool full_arm : {false, true}) {
    SCOPED_TRACE(full_arm ? "full arm" : "arm a - delta/2");
    const ContactGeometry g = make_geometry(n, radi, radj, delta, full_arm);
    const double li = full_arm ? radi : radi - 0.5 * delta;
    const double lj = full_arm ? radj : radj - 0.5 * delta;
    const V3 ci = sub(xi, mul(li, n));    // contact point seen from i
    const V3 cj = add(xj, mul(lj, n));    // and from j (the same unless full_arm)
    const V3 ui = add(vi, crossv(wi, sub(ci, xi)));
    const V3 uj = add(vj, crossv(wj, sub(cj, xj)));
    const V3 u = sub(ui, uj);
    const V3 vt = sub(u, mul(dotv(u, n), n));
    ASSERT_GT(norm(vt), 1.0e-3);

    double hist[HIST_SIZE] = {0.0};
    ContactForces out;
    const V3 vrel = sub(vi, vj);
    contact_forces(c, g, vrel.data(), wi.data(), wj.data(), dt, true, hist, out);
    const V3 ft_ana = mul(-(c.kt * dt + c.ct), vt);
    ASSERT_LT(norm(ft_ana), c.mut * out.fn);
    EXPECT_VEC_NEAR(tov(out.ft), ft_ana, 1.0e-12 * norm(ft_ana));
    EXPECT_VEC_NEAR(tov(hist + HIST_SLIDE), mul(dt, vt), 1.0e-12 * norm(vt) * dt);

    // i rolls on a fixed j without sliding: u_i = 0 at the contact point
    const V3 wroll = mul(50.0, unit(crossv(n, {0.3, 0.1, 0.2})));
    const V3 vroll = mul(-1.0, crossv(wroll, sub(ci, xi)));
    const V3 z = {0.0, 0.0, 0.0};
    double hist2[HIST_SIZE] = {0.0};
    contact_forces(c, g, vroll.data(), wroll.data(), z.data(), dt, true, hist2, out);
    EXPECT_LT(norm(tov(out.ft)), 1.0e-12 * c.ct * norm(vroll));
    EXPECT_GT(norm(tov(out.fr)), 0.0);    // but it rolls
  }
}

/* ----------------------------------------------------------------------
   Rolling at constant overlap: w_i = W t1, w_j = -(varm_i/varm_j) W t1 so
   that the contact point does not slide; v_r = -a' n x (w_i - w_j).
     stick, step k: f_r = -(kr k dt + cr) v_r
     slip from k* = floor((mur fn - cr|v_r|)/(kr |v_r| dt)) + 1, then
       f_r = -mur fn v_r/|v_r|
   Torques: on i a' n x f_r, on j -a' n x f_r; no net force (f = fn n).
------------------------------------------------------------------------- */

TEST(ContactKernel, RollingStickThenSlip)
{
  const ContactCoeffs c = table1();
  const double radi = 1.0e-3, radj = 0.6e-3, delta = 1.0e-5, dt = 1.0e-7;
  const ContactGeometry g = make_geometry(N_AX, radi, radj, delta, false);
  const double fn = c.kn * delta, cap = c.mur * fn;
  const double ar = radi * radj / (radi + radj);
  const double W = 100.0;
  const V3 wi = mul(W, T1_AX);
  const V3 wj = mul(-W * g.varm_i / g.varm_j, T1_AX);
  const V3 vr = mul(-ar, crossv(N_AX, sub(wi, wj)));    // = a' W (1 + varm_i/varm_j) t2
  const double vrm = norm(vr);
  const V3 zero = {0.0, 0.0, 0.0};
  const double tol = 1.0e-9 * cap;

  const double K = (cap - c.cr * vrm) / (c.kr * vrm * dt);
  ASSERT_GT(K - std::floor(K), 0.05);
  ASSERT_LT(K - std::floor(K), 0.95);
  const int kslip = static_cast<int>(std::floor(K)) + 1;

  double hist[HIST_SIZE] = {0.0};
  ContactForces out;
  int first_slip = -1;
  double max_err = 0.0;
  for (int k = 1; k <= kslip + 50; ++k) {
    contact_forces(c, g, zero.data(), wi.data(), wj.data(), dt, true, hist, out);
    const V3 fr = tov(out.fr);
    if (first_slip < 0 && norm(fr) >= cap * (1.0 - 1.0e-12)) first_slip = k;
    const V3 fr_ana = (k < kslip) ? mul(-(c.kr * k * dt + c.cr), vr) : mul(-cap / vrm, vr);
    if (k >= kslip) { EXPECT_NEAR(norm(fr), cap, 1.0e-13 * cap); }
    EXPECT_VEC_NEAR(fr, fr_ana, tol);
    max_err = std::fmax(max_err, norm(sub(fr, fr_ana)) / cap);

    // no sliding, no torsion, no net force from rolling
    EXPECT_LT(norm(tov(out.ft)), tol);
    EXPECT_NEAR(out.fo, 0.0, tol);
    EXPECT_VEC_NEAR(tov(out.f), mul(fn, N_AX), tol);
    const V3 tr = mul(ar, crossv(N_AX, fr_ana));
    EXPECT_VEC_NEAR(tov(out.torque_i), tr, tol * radi);
    EXPECT_VEC_NEAR(tov(out.torque_j), mul(-1.0, tr), tol * radi);
  }
  EXPECT_EQ(first_slip, kslip);
  std::printf("[   INFO   ] rolling: slip at step %d (analytic %d); "
              "max |f_r - analytic|/(mu_r f_n) = %.2e (tol 1e-9)\n",
              first_slip, kslip, max_err);
}

/* ----------------------------------------------------------------------
   Torsion at constant overlap: spins along n, v_o = a' (w_i - w_j).n.
     stick, step k: f_o = -(ko k dt + co) v_o
     slip from k* = floor((muo fn - co|v_o|)/(ko |v_o| dt)) + 1, then
       f_o = -muo fn sign(v_o)
   Torques: on i a' f_o n, on j -a' f_o n; no net force. Both signs of v_o.
------------------------------------------------------------------------- */

TEST(ContactKernel, TorsionStickThenSlip)
{
  const ContactCoeffs c = table1();
  const double radi = 0.9e-3, radj = 0.5e-3, delta = 1.0e-5, dt = 1.0e-7;
  const ContactGeometry g = make_geometry(N_AX, radi, radj, delta, false);
  const double fn = c.kn * delta, cap = c.muo * fn;
  const double ar = radi * radj / (radi + radj);
  const V3 zero = {0.0, 0.0, 0.0};
  const double tol = 1.0e-9 * cap;

  for (double W : {300.0, -300.0}) {
    SCOPED_TRACE(W > 0 ? "positive spin" : "negative spin");
    const V3 wi = mul(W, N_AX);
    const V3 wj = mul(-0.5 * W, N_AX);
    const double vo = ar * 1.5 * W;
    const double K = (cap - c.co * std::fabs(vo)) / (c.ko * std::fabs(vo) * dt);
    ASSERT_GT(K - std::floor(K), 0.05);
    ASSERT_LT(K - std::floor(K), 0.95);
    const int kslip = static_cast<int>(std::floor(K)) + 1;

    double hist[HIST_SIZE] = {0.0};
    ContactForces out;
    int first_slip = -1;
    double max_err = 0.0;
    for (int k = 1; k <= kslip + 50; ++k) {
      contact_forces(c, g, zero.data(), wi.data(), wj.data(), dt, true, hist, out);
      if (first_slip < 0 && std::fabs(out.fo) >= cap * (1.0 - 1.0e-12)) first_slip = k;
      const double fo_ana = (k < kslip) ? -(c.ko * k * dt + c.co) * vo : -std::copysign(cap, vo);
      EXPECT_NEAR(out.fo, fo_ana, tol);
      max_err = std::fmax(max_err, std::fabs(out.fo - fo_ana) / cap);
      if (k >= kslip) {
        EXPECT_DOUBLE_EQ(std::fabs(out.fo), cap);
        EXPECT_NEAR(hist[HIST_TORSION], -(fo_ana + c.co * vo) / c.ko, tol / c.ko);
      }
      EXPECT_LT(norm(tov(out.ft)), tol);
      EXPECT_LT(norm(tov(out.fr)), tol);
      EXPECT_VEC_NEAR(tov(out.f), mul(fn, N_AX), tol);
      EXPECT_VEC_NEAR(tov(out.torque_i), mul(ar * fo_ana, N_AX), tol * radi);
      EXPECT_VEC_NEAR(tov(out.torque_j), mul(-ar * fo_ana, N_AX), tol * radi);
    }
    EXPECT_EQ(first_slip, kslip);
    std::printf("[   INFO   ] torsion (w %+g): slip at step %d (analytic %d); "
                "max |f_o - analytic|/(mu_o f_n) = %.2e (tol 1e-9)\n",
                W, first_slip, kslip, max_err);
  }
}

/* ----------------------------------------------------------------------
   Energy balance along a loading path with all modes driven (fixed n,
   varying overlap). In step k the body velocities are taken at mid-step and
   held; the mode velocities follow from the spec; the overlap goes
   delta_k = delta_{k-1} - v_n dt. The driver's work in the step is the
   trapezoidal rule on the mode forces before (update = false, old history
   and overlap) and after (update = true) the step:
     dW = -dt/2 [(fn_a + fn_b) v_n + (ft_a + ft_b).v_t + (fr_a + fr_b).v_r
                 + (fo_a + fo_b) v_o]
   For a spring xi_k = xi_{k-1} + v dt this is exactly
     k/2 (|xi_k|^2 - |xi_{k-1}|^2) + c |v|^2 dt,
   so in stick: W = dE + D_visc to round-off, D_visc = sum c|v|^2 dt.
   On slip the spring is reset; the slip increment s = xi_{k-1} + v dt - xi_k
   dissipates D_fric = k xi_k . s (spring force times slip; in steady slip
   this is (mu f_n - c|v|)|v| dt, since the dashpot share c|v|^2 dt is already
   in D_visc). With slip the balance holds up to O(dt^2) per stick/slip
   transition or change of the cap.
   Full radii are used for the contact-point velocity, so the mode
   velocities do not depend on the overlap within a step. The path runs for
   0.85 of its period (so it ends loaded) and the balance is checked after
   every step.
------------------------------------------------------------------------- */

namespace {

struct EnergyTotals {
  double work = 0.0;             // done by the driver on the contact
  double dE = 0.0;               // change of elastic_energy()
  double visc = 0.0;             // viscous dissipation
  double fric = 0.0;             // friction dissipation
  double gross = 0.0;            // sum of |dW| (scale for tolerances)
  double fric_min = 0.0;         // most negative friction dissipation in one step
  double max_imbalance = 0.0;    // max over steps of |W - dE - D_visc - D_fric|
  int slip_t = 0, slip_r = 0, slip_o = 0;
};

EnergyTotals run_energy_path(const ContactCoeffs &c, int nsteps)
{
  const double radi = 1.0e-3, radj = 0.7e-3;
  const double T = 2.0e-4, dt = T / nsteps, om = 2.0 * PI / T;
  const V3 n = N_AX, t1 = T1_AX, t2 = T2_AX;
  double delta = 1.5e-5;    // overlap stays in [0.7e-5, 1.5e-5]
  const double An = 0.4e-5 * om, At = 3.0e-5 * om, Aw = 2500.0;

  double hist[HIST_SIZE] = {0.0};
  const double E0 = elastic_energy(c, delta, hist);
  EnergyTotals e;
  ContactForces fa, fb;

  const int nrun = static_cast<int>(0.85 * nsteps);
  for (int k = 1; k <= nrun; ++k) {
    const double t = (k - 0.5) * dt;
    const double s1 = std::sin(om * t), c1 = std::cos(om * t);
    const double s2 = std::sin(2.0 * om * t), c2 = std::cos(2.0 * om * t);
    const double c3 = std::cos(3.0 * om * t);
    const V3 vrel = add(mul(An * s1, n), add(mul(At * c1, t1), mul(0.7 * At * s2, t2)));
    const V3 wi = add(mul(Aw * s1, t1), add(mul(0.6 * Aw * c3, t2), mul(0.8 * Aw * s2, n)));
    const V3 wj = add(mul(-0.4 * Aw * c2, t2), mul(-0.9 * Aw * c1, n));

    const ContactGeometry ga = make_geometry(n, radi, radj, delta, true);
    const ModeVelocities mv = mode_velocities(ga, vrel, wi, wj);
    const double delta_new = delta - mv.vn * dt;
    const ContactGeometry gb = make_geometry(n, radi, radj, delta_new, true);

    double old[HIST_SIZE];
    for (int m = 0; m < HIST_SIZE; ++m) old[m] = hist[m];
    contact_forces(c, ga, vrel.data(), wi.data(), wj.data(), dt, false, hist, fa);
    contact_forces(c, gb, vrel.data(), wi.data(), wj.data(), dt, true, hist, fb);
    EXPECT_GT(fb.fn, 0.0);

    const double dW = -0.5 * dt *
        ((fa.fn + fb.fn) * mv.vn + dotv(add(tov(fa.ft), tov(fb.ft)), mv.vt) +
         dotv(add(tov(fa.fr), tov(fb.fr)), mv.vr) + (fa.fo + fb.fo) * mv.vo);
    e.work += dW;
    e.gross += std::fabs(dW);
    e.visc += dt *
        (c.cn * mv.vn * mv.vn + c.ct * dotv(mv.vt, mv.vt) + c.cr * dotv(mv.vr, mv.vr) +
         c.co * mv.vo * mv.vo);

    // slip increments and friction dissipation
    const V3 st = sub(add(tov(old + HIST_SLIDE), mul(dt, mv.vt)), tov(hist + HIST_SLIDE));
    const V3 sr = sub(add(tov(old + HIST_ROLL), mul(dt, mv.vr)), tov(hist + HIST_ROLL));
    const double so = old[HIST_TORSION] + mv.vo * dt - hist[HIST_TORSION];
    const double dft = c.kt * dotv(tov(hist + HIST_SLIDE), st);
    const double dfr = c.kr * dotv(tov(hist + HIST_ROLL), sr);
    const double dfo = c.ko * hist[HIST_TORSION] * so;
    const double tiny = 1.0e-6 * dt;    // slip much smaller than a step is round-off
    if (norm(st) > tiny * norm(mv.vt)) ++e.slip_t;
    if (norm(sr) > tiny * norm(mv.vr)) ++e.slip_r;
    if (std::fabs(so) > tiny * std::fabs(mv.vo)) ++e.slip_o;
    e.fric += dft + dfr + dfo;
    e.fric_min = std::fmin(e.fric_min, std::fmin(dft, std::fmin(dfr, dfo)));

    delta = delta_new;
    e.dE = elastic_energy(c, delta, hist) - E0;
    e.max_imbalance = std::fmax(e.max_imbalance, std::fabs(e.work - e.dE - e.visc - e.fric));
  }
  return e;
}

}    // namespace

TEST(ContactKernel, EnergyBalanceElasticStick)
{
  ContactCoeffs c = table1();
  c.cn = c.ct = c.cr = c.co = 0.0;
  c.mut = c.mur = c.muo = 1.0e3;    // never slips
  c.ko = 0.07 * c.kn;               // k_o != k_r, so that mixed-up modes show
  const EnergyTotals e = run_energy_path(c, 4000);
  const double err = e.max_imbalance / e.gross;
  std::printf("[   INFO   ] energy, elastic stick: W %.6e J, dE %.6e J, "
              "max |W - dE|/sum|dW| = %.2e (tol 1e-10)\n",
              e.work, e.dE, err);
  EXPECT_EQ(e.slip_t + e.slip_r + e.slip_o, 0);
  EXPECT_EQ(e.visc, 0.0);
  EXPECT_NEAR(e.fric, 0.0, 1.0e-12 * e.gross);
  EXPECT_GT(e.dE, 0.005 * e.gross);    // ends loaded: the balance is not 0 = 0
  EXPECT_LT(err, 1.0e-10);
}

TEST(ContactKernel, EnergyBalanceDampedStick)
{
  ContactCoeffs c = table1();
  c.mut = c.mur = c.muo = 1.0e3;    // never slips
  c.ko = 0.07 * c.kn;               // k_o != k_r, c_o != c_r
  c.co = 0.03 * c.cn;
  const EnergyTotals e = run_energy_path(c, 4000);
  const double err = e.max_imbalance / e.gross;
  std::printf("[   INFO   ] energy, damped stick: W %.6e J, dE %.6e J, D_visc %.6e J, "
              "max |W - dE - D_visc|/sum|dW| = %.2e (tol 1e-10)\n",
              e.work, e.dE, e.visc, err);
  EXPECT_EQ(e.slip_t + e.slip_r + e.slip_o, 0);
  EXPECT_NEAR(e.fric, 0.0, 1.0e-12 * e.gross);
  EXPECT_GT(e.dE, 0.005 * e.gross);
  EXPECT_GT(e.visc, 0.005 * e.gross);    // damping matters far above the tolerance
  EXPECT_LT(err, 1.0e-10);
}

TEST(ContactKernel, EnergyBalanceWithSlip)
{
  const ContactCoeffs c = table1();
  const int nsteps = 20000;
  const EnergyTotals e = run_energy_path(c, nsteps);
  const int nrun = static_cast<int>(0.85 * nsteps);
  const double err = e.max_imbalance / e.gross;
  std::printf("[   INFO   ] energy, with slip: W %.6e J, dE %.6e J, D_visc %.6e J, "
              "D_fric %.6e J, max |W - dE - D|/sum|dW| = %.2e (tol 1e-4); slip steps t/r/o "
              "%d/%d/%d of %d\n",
              e.work, e.dE, e.visc, e.fric, err, e.slip_t, e.slip_r, e.slip_o, nrun);
  // all modes slip during part of the path, and stick during another part
  EXPECT_GT(e.slip_t, nrun / 20);
  EXPECT_GT(e.slip_r, nrun / 20);
  EXPECT_GT(e.slip_o, nrun / 20);
  EXPECT_LT(e.slip_t, nrun);
  EXPECT_LT(e.slip_r, nrun);
  EXPECT_LT(e.slip_o, nrun);
  EXPECT_GT(e.visc, 0.01 * e.gross);
  EXPECT_GT(e.fric, 0.1 * e.gross);
  // friction never releases energy
  EXPECT_GE(e.fric_min, -1.0e-12 * e.gross);
  EXPECT_LT(err, 1.0e-4);
}

/* ----------------------------------------------------------------------
   Power identity. Force f on i and -f on j, torques t_i, t_j:
     P = f.(v_i - v_j) + t_i.w_i + t_j.w_j
   must equal sum over modes of force times velocity:
     fn v_n + f_t.v_t + f_r.v_r + f_o v_o
   whenever the torque arm equals the arm in v_t (a - delta/2 here). Proof:
   -arm_i (n x f_t).w_i = -arm_i f_t.(w_i x n) (sliding torques cancel the
   spin part of f_t.vrel), a' (n x f_r).(w_i - w_j) = f_r.v_r and
   a' f_o n.(w_i - w_j) = f_o v_o. Random states, random (partly slipping)
   history with components along n.
------------------------------------------------------------------------- */

TEST(ContactKernel, PowerIdentityBodiesEqualsModes)
{
  const ContactCoeffs c = table1();
  std::mt19937 gen(20250204);
  std::uniform_real_distribution<double> u(-1.0, 1.0), upos(0.0, 1.0);
  auto rvec = [&](double s) {
    return V3{s * u(gen), s * u(gen), s * u(gen)};
  };
  double max_err = 0.0;

  for (int trial = 0; trial < 200; ++trial) {
    const double radi = 0.5e-3 + 0.5e-3 * upos(gen), radj = 0.5e-3 + 0.5e-3 * upos(gen);
    const double delta = 1.0e-6 + 2.0e-5 * upos(gen);
    const V3 n = unit(rvec(1.0));
    const V3 del = mul(radi + radj - delta, n);
    ContactGeometry g;
    pair_geometry(del.data(), norm(del), radi, radj, false, g);
    const V3 vrel = rvec(0.5), wi = rvec(500.0), wj = rvec(500.0);
    double hist[HIST_SIZE];
    for (int m = 0; m < HIST_SIZE; ++m) hist[m] = 2.0e-5 * u(gen);
    ContactForces out;
    contact_forces(c, g, vrel.data(), wi.data(), wj.data(), 1.0e-7, true, hist, out);

    const ModeVelocities mv = mode_velocities(g, vrel, wi, wj);
    const V3 f = tov(out.f), ti = tov(out.torque_i), tj = tov(out.torque_j);
    const V3 ft = tov(out.ft), fr = tov(out.fr);
    const double pb = dotv(f, vrel) + dotv(ti, wi) + dotv(tj, wj);
    const double pm = out.fn * mv.vn + dotv(ft, mv.vt) + dotv(fr, mv.vr) + out.fo * mv.vo;
    const double scale = std::fabs(out.fn * mv.vn) + norm(ft) * norm(mv.vt) +
        norm(fr) * norm(mv.vr) + std::fabs(out.fo * mv.vo) + norm(f) * norm(vrel) +
        norm(ti) * norm(wi) + norm(tj) * norm(wj);
    EXPECT_NEAR(pb, pm, 1.0e-12 * scale) << "trial " << trial;
    max_err = std::fmax(max_err, std::fabs(pb - pm) / scale);
  }
  std::printf("[   INFO   ] power identity: max |P_bodies - P_modes|/scale = %.2e (tol 1e-12)\n",
              max_err);
}

/* ----------------------------------------------------------------------
   Swapping i and j: del -> -del, vrel -> -vrel, w_i <-> w_j, radii swapped,
   history multiplied by HISTORY_SWAP_FACTOR. Then f -> -f, torque_i <->
   torque_j, f_t -> -f_t, f_r, f_o, f_n unchanged, and the history stays
   related by the factors. Many steps with random (seeded) inputs, turning
   normal, stick and slip in all modes. Control: negating the whole history (the fix
   neigh/history default) breaks rolling and torsion.
------------------------------------------------------------------------- */

TEST(ContactKernel, SwapSymmetry)
{
  const ContactCoeffs c = table1();
  std::mt19937 gen(4711);
  std::uniform_real_distribution<double> u(-1.0, 1.0), upos(0.0, 1.0);
  auto rvec = [&](double s) {
    return V3{s * u(gen), s * u(gen), s * u(gen)};
  };
  const double radi = 0.9e-3, radj = 0.55e-3, dt = 1.0e-6;

  double ha[HIST_SIZE], hb[HIST_SIZE], hc[HIST_SIZE];
  for (int m = 0; m < HIST_SIZE; ++m) {
    ha[m] = 3.0e-6 * u(gen);
    hb[m] = HISTORY_SWAP_FACTOR[m] * ha[m];
    hc[m] = -ha[m];
  }
  V3 n = unit(rvec(1.0));
  double max_err = 0.0, max_ctrl = 0.0;
  int slip_t = 0, slip_r = 0, slip_o = 0;

  for (int step = 0; step < 40; ++step) {
    n = unit(add(n, rvec(0.05)));
    const double delta = 5.0e-6 + 1.5e-5 * upos(gen);
    const double r = radi + radj - delta;
    const V3 del = mul(r, n), mdel = mul(-r, n);
    const V3 vrel = rvec(1.0), mvrel = mul(-1.0, vrel);
    // random spins plus a drift (reversed half way) so that rolling and
    // torsion springs build up to slip and unload again
    const double drift = (step < 20) ? 4000.0 : -4000.0;
    const V3 wi = add(rvec(2000.0), mul(drift, n));
    const V3 wj = add(rvec(2000.0), mul(drift, unit(crossv(n, {1.0, 0.0, 0.0}))));

    ContactGeometry ga, gb;
    pair_geometry(del.data(), r, radi, radj, false, ga);
    pair_geometry(mdel.data(), r, radj, radi, false, gb);
    ContactForces a, b, cc;
    contact_forces(c, ga, vrel.data(), wi.data(), wj.data(), dt, true, ha, a);
    contact_forces(c, gb, mvrel.data(), wj.data(), wi.data(), dt, true, hb, b);
    contact_forces(c, ga, vrel.data(), wi.data(), wj.data(), dt, true, hc, cc);
    if (norm(tov(a.ft)) >= c.mut * a.fn * (1.0 - 1.0e-12)) ++slip_t;
    if (norm(tov(a.fr)) >= c.mur * a.fn * (1.0 - 1.0e-12)) ++slip_r;
    if (std::fabs(a.fo) >= c.muo * a.fn * (1.0 - 1.0e-12)) ++slip_o;

    const double fs = a.fn, ts = a.fn * radi;    // force and torque scales
    const double tol = 1.0e-12;
    EXPECT_NEAR(b.fn, a.fn, tol * fs);
    EXPECT_VEC_NEAR(tov(b.f), mul(-1.0, tov(a.f)), tol * fs);
    EXPECT_VEC_NEAR(tov(b.ft), mul(-1.0, tov(a.ft)), tol * fs);
    EXPECT_VEC_NEAR(tov(b.fr), tov(a.fr), tol * fs);
    EXPECT_NEAR(b.fo, a.fo, tol * fs);
    EXPECT_VEC_NEAR(tov(b.torque_i), tov(a.torque_j), tol * ts);
    EXPECT_VEC_NEAR(tov(b.torque_j), tov(a.torque_i), tol * ts);
    for (int m = 0; m < HIST_SIZE; ++m)
      EXPECT_NEAR(hb[m], HISTORY_SWAP_FACTOR[m] * ha[m], tol * 1.0e-5) << "history " << m;
    max_err = std::fmax(max_err, norm(sub(tov(b.torque_i), tov(a.torque_j))) / ts);
    max_err = std::fmax(max_err, norm(add(tov(b.f), tov(a.f))) / fs);
    max_ctrl = std::fmax(max_ctrl, norm(sub(tov(cc.fr), tov(a.fr))) / (c.mur * a.fn));
  }
  // history is loaded in all modes
  EXPECT_GT(norm(tov(ha + HIST_SLIDE)), 1.0e-7);
  EXPECT_GT(norm(tov(ha + HIST_ROLL)), 1.0e-7);
  EXPECT_GT(std::fabs(ha[HIST_TORSION]), 1.0e-7);
  EXPECT_GT(slip_t, 0);
  EXPECT_GT(slip_r, 0);
  EXPECT_GT(slip_o, 0);
  EXPECT_LT(slip_t + slip_r + slip_o, 3 * 40);    // and stick in some steps
  // the control must differ, or the test could not fail
  EXPECT_GT(max_ctrl, 0.1);
  std::printf("[   INFO   ] swap: max relative mismatch %.2e (tol 1e-12), slip steps t/r/o "
              "%d/%d/%d of 40; negating all history instead gives %.2f of the rolling cap\n",
              max_err, slip_t, slip_r, slip_o, max_ctrl);
}

/* ----------------------------------------------------------------------
   update = false: history unchanged bit for bit (no advance, no rotation
   into the plane, no slip reset); forces from the old history:
   f = -k xi - c v, capped at mu fn.
------------------------------------------------------------------------- */

TEST(ContactKernel, NoUpdateLeavesHistory)
{
  const ContactCoeffs c = table1();
  const double radi = 1.0e-3, radj = 0.8e-3, delta = 1.0e-5, dt = 1.0e-6;
  const ContactGeometry g = make_geometry(N_AX, radi, radj, delta, false);
  const V3 vrel = mul(0.05, T1_AX), wi = mul(30.0, T2_AX), wj = mul(-20.0, N_AX);
  const ModeVelocities mv = mode_velocities(g, vrel, wi, wj);
  const double fn = c.kn * delta;

  // stick-range history in the tangent plane, and slip-range history with
  // components along n (would be rotated and reset by an update)
  const double h_stick[HIST_SIZE] = {1.0e-6 * T1_AX[0],
                                     1.0e-6 * T1_AX[1],
                                     1.0e-6 * T1_AX[2],
                                     1.0e-6 * T2_AX[0],
                                     1.0e-6 * T2_AX[1],
                                     1.0e-6 * T2_AX[2],
                                     -2.0e-6};
  const double h_slip[HIST_SIZE] = {3.0e-5, -1.0e-5, 2.0e-5, 4.0e-5, 1.0e-5, -3.0e-5, 5.0e-5};

  for (const double *h0 : {h_stick, h_slip}) {
    double hist[HIST_SIZE];
    for (int m = 0; m < HIST_SIZE; ++m) hist[m] = h0[m];
    ContactForces out;
    for (int rep = 0; rep < 3; ++rep) {
      contact_forces(c, g, vrel.data(), wi.data(), wj.data(), dt, false, hist, out);
      for (int m = 0; m < HIST_SIZE; ++m) EXPECT_EQ(hist[m], h0[m]) << "history " << m;
    }
    const V3 ft_trial = sub(mul(-c.kt, tov(h0 + HIST_SLIDE)), mul(c.ct, mv.vt));
    const V3 fr_trial = sub(mul(-c.kr, tov(h0 + HIST_ROLL)), mul(c.cr, mv.vr));
    const double fo_trial = -c.ko * h0[HIST_TORSION] - c.co * mv.vo;
    auto capv = [](const V3 &f, double cap) {
      return norm(f) > cap ? mul(cap / norm(f), f) : f;
    };
    const V3 ft_ana = capv(ft_trial, c.mut * fn), fr_ana = capv(fr_trial, c.mur * fn);
    const double fo_ana = std::fabs(fo_trial) > c.muo * fn ? std::copysign(c.muo * fn, fo_trial)
                                                           : fo_trial;
    const double tol = 1.0e-12 * fn;
    EXPECT_NEAR(out.fn, fn, tol);
    EXPECT_VEC_NEAR(tov(out.ft), ft_ana, tol);
    EXPECT_VEC_NEAR(tov(out.fr), fr_ana, tol);
    EXPECT_NEAR(out.fo, fo_ana, tol);
  }
  // and update = true does change the slip-range history
  double hist[HIST_SIZE];
  for (int m = 0; m < HIST_SIZE; ++m) hist[m] = h_slip[m];
  ContactForces out;
  contact_forces(c, g, vrel.data(), wi.data(), wj.data(), dt, true, hist, out);
  int changed = 0;
  for (int m = 0; m < HIST_SIZE; ++m) changed += (hist[m] != h_slip[m]);
  EXPECT_EQ(changed, HIST_SIZE);
}

/* ----------------------------------------------------------------------
   rotate_into_plane(): keeps |xi|, makes xi.n = 0, and keeps the direction
   of the projection xi - (xi.n) n. A vector already in the plane stays
   unchanged; one along n does not become NaN.
------------------------------------------------------------------------- */

TEST(ContactKernel, RotateIntoPlane)
{
  std::mt19937 gen(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double max_len = 0.0, max_perp = 0.0;

  for (int trial = 0; trial < 1000; ++trial) {
    const V3 n = unit({u(gen), u(gen), u(gen)});
    const double scale = std::pow(10.0, -7.0 + 3.0 * (u(gen) + 1.0));
    const V3 x0 = {scale * u(gen), scale * u(gen), scale * u(gen)};
    V3 x = x0;
    rotate_into_plane(x.data(), n.data());
    const V3 proj = sub(x0, mul(dotv(x0, n), n));
    const double len = norm(x0);
    EXPECT_NEAR(norm(x), len, 1.0e-14 * len);
    // the rescaling by |xi|/|proj| amplifies round-off of the projection
    const double amp = len / norm(proj);
    EXPECT_NEAR(dotv(x, n), 0.0, 1.0e-14 * len * amp);
    EXPECT_GT(dotv(x, proj), 0.0);
    EXPECT_LT(norm(crossv(x, proj)), 1.0e-14 * len * len);
    max_len = std::fmax(max_len, std::fabs(norm(x) - len) / len);
    max_perp = std::fmax(max_perp, std::fabs(dotv(x, n)) / (len * amp));
  }
  std::printf("[   INFO   ] rotate_into_plane: max rel length change %.2e, "
              "max |xi.n| |proj|/|xi|^2 %.2e (tol 1e-14)\n",
              max_len, max_perp);

  // already in the plane: untouched
  const V3 ez = {0.0, 0.0, 1.0};
  V3 x = {1.0e-6, -2.0e-6, 0.0};
  rotate_into_plane(x.data(), ez.data());
  EXPECT_EQ(x[0], 1.0e-6);
  EXPECT_EQ(x[1], -2.0e-6);
  EXPECT_EQ(x[2], 0.0);

  // along n: no direction in the plane, must stay finite
  x = {0.0, 0.0, 3.0e-6};
  rotate_into_plane(x.data(), ez.data());
  EXPECT_TRUE(finite3(x.data()));
}

/* ----------------------------------------------------------------------
   Step 1 of sliding and rolling: when n turns, contact_forces(update = true)
   rotates the stored springs into the new tangent plane with their length
   kept. With all velocities zero: xi -> |xi| p/|p|, p = xi - (xi.n) n, and
   f = -k xi (below the cap); the torsion spring is a scalar and is kept.
------------------------------------------------------------------------- */

TEST(ContactKernel, SpringsFollowTurningNormal)
{
  const ContactCoeffs c = table1();
  const double radi = 1.0e-3, radj = 0.8e-3, delta = 1.0e-5;
  const double theta = 0.3;    // rotation of n about t2, from N_AX towards T1_AX
  const V3 n = add(mul(std::cos(theta), N_AX), mul(std::sin(theta), T1_AX));
  const ContactGeometry g = make_geometry(n, radi, radj, delta, false);
  const V3 zero = {0.0, 0.0, 0.0};
  const V3 xt0 = mul(2.0e-6, T1_AX), xr0 = add(mul(1.0e-6, T1_AX), mul(1.0e-6, T2_AX));
  double hist[HIST_SIZE] = {xt0[0], xt0[1], xt0[2], xr0[0], xr0[1], xr0[2], 1.5e-6};
  ContactForces out;
  contact_forces(c, g, zero.data(), zero.data(), zero.data(), 1.0e-7, true, hist, out);

  auto rotated = [&](const V3 &x) {
    const V3 p = sub(x, mul(dotv(x, n), n));
    return mul(norm(x) / norm(p), p);
  };
  const V3 xt = rotated(xt0), xr = rotated(xr0);
  const double tol = 1.0e-15 * 2.0e-6;
  EXPECT_VEC_NEAR(tov(hist + HIST_SLIDE), xt, tol);
  EXPECT_VEC_NEAR(tov(hist + HIST_ROLL), xr, tol);
  EXPECT_EQ(hist[HIST_TORSION], 1.5e-6);
  EXPECT_VEC_NEAR(tov(out.ft), mul(-c.kt, xt), c.kt * tol);
  EXPECT_VEC_NEAR(tov(out.fr), mul(-c.kr, xr), c.kr * tol);
  EXPECT_NEAR(out.fo, -c.ko * 1.5e-6, c.ko * tol);
}

/* ----------------------------------------------------------------------
   Zero coefficients: with k = c = mu = 0 in one mode that mode gives exactly
   zero force and no NaN, and the other modes are unchanged. With k = 0 but
   c, mu > 0 the force is the capped dashpot and the reset history is 0.
   With f_n = 0 (separating fast) all caps are 0: no force, no NaN.
------------------------------------------------------------------------- */

TEST(ContactKernel, ZeroCoefficientModes)
{
  const ContactCoeffs base = table1();
  const double radi = 1.0e-3, radj = 0.6e-3, delta = 1.0e-5, dt = 1.0e-7;
  const ContactGeometry g = make_geometry(N_AX, radi, radj, delta, false);
  const V3 vrel = {0.03, -0.02, 0.01};
  const V3 wi = add(mul(40.0, T1_AX), mul(300.0, N_AX)), wj = mul(-25.0, T2_AX);
  const double h0[HIST_SIZE] = {1.0e-6, -2.0e-6, 0.5e-6, -1.0e-6, 0.5e-6, 1.0e-6, 3.0e-6};

  auto run = [&](const ContactCoeffs &c, const V3 &v, ContactForces &out, double *hist) {
    for (int m = 0; m < HIST_SIZE; ++m) hist[m] = h0[m];
    contact_forces(c, g, v.data(), wi.data(), wj.data(), dt, true, hist, out);
    EXPECT_TRUE(std::isfinite(out.fn));
    EXPECT_TRUE(std::isfinite(out.fo));
    EXPECT_TRUE(finite3(out.f) && finite3(out.ft) && finite3(out.fr));
    EXPECT_TRUE(finite3(out.torque_i) && finite3(out.torque_j));
    for (int m = 0; m < HIST_SIZE; ++m) EXPECT_TRUE(std::isfinite(hist[m]));
  };

  ContactForces ref, out;
  double href[HIST_SIZE], hist[HIST_SIZE];
  run(base, vrel, ref, href);

  // torsion off
  ContactCoeffs c = base;
  c.ko = c.co = c.muo = 0.0;
  run(c, vrel, out, hist);
  EXPECT_EQ(out.fo, 0.0);
  EXPECT_VEC_NEAR(tov(out.ft), tov(ref.ft), 1.0e-15);
  EXPECT_VEC_NEAR(tov(out.fr), tov(ref.fr), 1.0e-15);
  // torque_i + torque_j carries no rolling or torsion part
  const V3 tsum_ana = mul(-(g.arm_i + g.arm_j), crossv(N_AX, tov(ref.ft)));
  EXPECT_VEC_NEAR(add(tov(out.torque_i), tov(out.torque_j)), tsum_ana, 1.0e-15);
  EXPECT_VEC_NEAR(
      tov(out.torque_i),
      add(mul(-g.arm_i, crossv(N_AX, tov(ref.ft))), mul(g.reff, crossv(N_AX, tov(ref.fr)))),
      1.0e-15);

  // rolling off
  c = base;
  c.kr = c.cr = c.mur = 0.0;
  run(c, vrel, out, hist);
  EXPECT_EQ(norm(tov(out.fr)), 0.0);
  EXPECT_EQ(out.fo, ref.fo);

  // sliding off
  c = base;
  c.kt = c.ct = c.mut = 0.0;
  run(c, vrel, out, hist);
  EXPECT_EQ(norm(tov(out.ft)), 0.0);
  EXPECT_VEC_NEAR(tov(out.f), mul(out.fn, N_AX), 0.0);

  // torsion and rolling as pure dashpots (k = 0), slipping at a small cap
  c = base;
  c.ko = c.kr = 0.0;
  c.muo = c.mur = 1.0e-6;
  run(c, vrel, out, hist);
  const ModeVelocities mv = mode_velocities(g, vrel, wi, wj);
  const double cap = 1.0e-6 * out.fn;
  ASSERT_GT(c.co * std::fabs(mv.vo), cap);
  EXPECT_NEAR(out.fo, -std::copysign(cap, mv.vo), 1.0e-15 * cap);
  EXPECT_VEC_NEAR(tov(out.fr), mul(-cap / norm(mv.vr), mv.vr), 1.0e-12 * cap);
  EXPECT_EQ(hist[HIST_TORSION], 0.0);
  EXPECT_EQ(norm(tov(hist + HIST_ROLL)), 0.0);
  // ... and in stick (large cap): f = -c v
  c.muo = c.mur = 1.0;
  run(c, vrel, out, hist);
  EXPECT_NEAR(out.fo, -c.co * mv.vo, 1.0e-12 * c.co * std::fabs(mv.vo));
  EXPECT_VEC_NEAR(tov(out.fr), mul(-c.cr, mv.vr), 1.0e-12 * c.cr * norm(mv.vr));

  // f_n clipped to zero: separating faster than kn delta/cn; no tangential force
  const V3 vsep = add(vrel, mul(2.0 * base.kn * delta / base.cn, N_AX));
  run(base, vsep, out, hist);
  EXPECT_EQ(out.fn, 0.0);
  EXPECT_EQ(norm(tov(out.f)), 0.0);
  EXPECT_EQ(norm(tov(out.fr)), 0.0);
  EXPECT_EQ(out.fo, 0.0);
  EXPECT_EQ(norm(tov(out.torque_i)), 0.0);
  EXPECT_EQ(norm(tov(out.torque_j)), 0.0);
}

/* ----------------------------------------------------------------------
   The unclipped law (normal_law = NORMAL_UNCLIPPED): f_n = kn x + cn x'
   (x the overlap, x' = -v_n) as written, negative near the end of the
   collision.  The contact of the head-on collision above then lasts until
   the overlap is gone, x(t_c) = 0, i.e. w t_c = pi: t_c = pi/w, and the
   spheres leave with
     e = -x'(t_c)/v0 = exp(-eta pi/w) = exp(-pi zeta/sqrt(1 - zeta^2)),
   zeta = eta/w0 = cn/(2 sqrt(m kn)).  The clipped law's e = exp(-eta t_f)
   with t_f < t_c is greater.  The Coulomb caps of both laws are mu |f_n|
   (as stock LAMMPS and MercuryDPM): in tension up to mu |f_n|.
------------------------------------------------------------------------- */

namespace {

struct Collision {
  double e_num;        // restitution coefficient, numeric
  double t_sep;        // time at which the overlap ends (interpolated in the last step)
  double fn_min;       // most negative normal force during the contact
  double cap_ratio;    // largest |f_t| / (mut |f_n|) while f_n < 0
  bool separated;
};

// one head-on collision with velocity Verlet as in LAMMPS, dt = t_c /
// nsteps, from touching at approach speed v0 = 1; an initial tangential
// relative velocity vt0 (along a direction normal to e_ax) exercises the
// caps
Collision collide(const ContactCoeffs &c, double r1, double r2, double dt, const V3 &e_ax,
                  const V3 &t_ax, double vt0)
{
  Collision h{};
  h.fn_min = 0.0;
  const double m1 = sphere_mass(r1), m2 = sphere_mass(r2);
  const double v0 = 1.0;
  V3 x1 = {1.0e-3, 2.0e-3, -0.5e-3};
  V3 x2 = sub(x1, mul(r1 + r2, e_ax));
  V3 v1 = add(mul(-v0 * m2 / (m1 + m2), e_ax), mul(vt0 * m2 / (m1 + m2), t_ax));
  V3 v2 = add(mul(v0 * m1 / (m1 + m2), e_ax), mul(-vt0 * m1 / (m1 + m2), t_ax));
  const V3 zero = {0.0, 0.0, 0.0};
  double hist[HIST_SIZE] = {0.0};
  ContactForces out;
  ContactGeometry g;
  auto force = [&](V3 &f1) {
    const V3 del = sub(x1, x2);
    pair_geometry(del.data(), norm(del), r1, r2, false, g);
    const V3 vrel = sub(v1, v2);
    contact_forces(c, g, vrel.data(), zero.data(), zero.data(), dt, true, hist, out);
    f1 = tov(out.f);
    h.fn_min = std::min(h.fn_min, out.fn);
    if (out.fn < 0.0)
      h.cap_ratio = std::max(h.cap_ratio, norm(tov(out.ft)) / (c.mut * std::fabs(out.fn)));
  };
  V3 f1;
  force(f1);
  double delta_prev = 0.0;
  const int kmax = 100000000;
  for (int k = 1; k < kmax; ++k) {
    v1 = add(v1, mul(0.5 * dt / m1, f1));
    v2 = add(v2, mul(-0.5 * dt / m2, f1));
    x1 = add(x1, mul(dt, v1));
    x2 = add(x2, mul(dt, v2));
    const double delta = r1 + r2 - norm(sub(x1, x2));
    if (delta > 0.0) {
      force(f1);
    } else {
      f1 = zero;
      // linear interpolation of the overlap within the step (error O(dt^2))
      h.t_sep = (k - 1) * dt + dt * delta_prev / (delta_prev - delta);
      h.separated = true;
    }
    v1 = add(v1, mul(0.5 * dt / m1, f1));
    v2 = add(v2, mul(-0.5 * dt / m2, f1));
    delta_prev = delta;
    if (h.separated) break;
  }
  h.e_num = dotv(sub(v1, v2), e_ax) / v0;
  return h;
}

struct Damping {
  double zeta, w, t_c, e_unclipped, e_clipped;
};

// closed forms of the head-on collision of spheres r1, r2 (see above)
Damping damping(const ContactCoeffs &c, double r1, double r2)
{
  const double m1 = sphere_mass(r1), m2 = sphere_mass(r2);
  const double meff = m1 * m2 / (m1 + m2);
  const double w0 = std::sqrt(c.kn / meff);
  const double eta = c.cn / (2.0 * meff);
  Damping d;
  d.zeta = eta / w0;
  d.w = std::sqrt(w0 * w0 - eta * eta);
  d.t_c = PI / d.w;
  d.e_unclipped = std::exp(-PI * d.zeta / std::sqrt(1.0 - d.zeta * d.zeta));
  const double phi = PI - std::atan2(2.0 * eta * d.w, d.w * d.w - eta * eta);
  d.e_clipped = std::exp(-eta * phi / d.w);
  return d;
}

}    // namespace

TEST(ContactKernel, UnclippedHeadOnRestitution)
{
  ContactCoeffs c = table1();
  c.normal_law = NORMAL_UNCLIPPED;
  ContactCoeffs clipped = table1();
  // the sample's smallest, number-mean and largest spheres (d 1, 4/3, 2 mm;
  // inputs/params.lmp) and two unequal pairs
  const double d_mean = 2.0 * (1.0e3 - 0.5e3) / (1.0e6 - 0.25e6);
  const double radii[][2] = {{0.5e-3, 0.5e-3},
                             {0.5 * d_mean, 0.5 * d_mean},
                             {1.0e-3, 1.0e-3},
                             {1.0e-3, 0.5e-3},
                             {0.7e-3, 0.6e-3}};
  // velocity Verlet with the dashpot force from half-step velocities is
  // first order in dt: at 2000 steps per contact the error of e was 1.6e-4
  // (absolute) for the most damped pair, 3e-3 of its e = 0.05; at 20000
  // steps a tenth of that, within 1e-3 with a factor 3 of room.  t_sep is
  // interpolated within the step (O(dt^2))
  const int NSTEPS = 20000;
  const double tol_e = 1.0e-3, tol_t = 1.0e-3;
  const V3 e_ax = unit({2.0, -1.0, 2.0});
  for (const auto &rad : radii) {
    const double r1 = rad[0], r2 = rad[1];
    SCOPED_TRACE("radii " + std::to_string(r1) + " " + std::to_string(r2));
    const Damping d = damping(c, r1, r2);
    ASSERT_LT(d.zeta, 1.0);
    const double dt = d.t_c / NSTEPS;
    const Collision u = collide(c, r1, r2, dt, e_ax, T1_AX, 0.0);
    const Collision k = collide(clipped, r1, r2, dt, e_ax, T1_AX, 0.0);
    ASSERT_TRUE(u.separated);
    ASSERT_TRUE(k.separated);
    std::printf("[ measured ] a=(%.4g,%.4g) mm zeta %.4f: unclipped e closed form %.5f numeric "
                "%.5f, t_c %.4e s numeric %.4e; clipped e closed form %.5f numeric %.5f\n",
                1e3 * r1, 1e3 * r2, d.zeta, d.e_unclipped, u.e_num, d.t_c, u.t_sep, d.e_clipped,
                k.e_num);
    EXPECT_NEAR(u.e_num, d.e_unclipped, tol_e * d.e_unclipped);
    EXPECT_NEAR(u.t_sep, d.t_c, tol_t * d.t_c);
    // the force turns attractive before the overlap ends; the clipped one never
    EXPECT_LT(u.fn_min, 0.0);
    EXPECT_EQ(k.fn_min, 0.0);
    // the clipped law returns more energy, by far more than the tolerance
    EXPECT_NEAR(k.e_num, d.e_clipped, tol_e * d.e_clipped);
    EXPECT_GT(d.e_clipped - d.e_unclipped, 20.0 * tol_e * d.e_unclipped);
    EXPECT_GT(k.e_num, u.e_num);
  }
}

// with an oblique impact the sliding spring is loaded; while f_n < 0 the
// sliding force is held at mu |f_n| (it slips: the spring's trial force
// exceeds the shrinking cap)
TEST(ContactKernel, UnclippedCapsInTension)
{
  ContactCoeffs c = table1();
  c.normal_law = NORMAL_UNCLIPPED;
  const double r = 0.5e-3;
  const Damping d = damping(c, r, r);
  const Collision u = collide(c, r, r, d.t_c / 2000, N_AX, T1_AX, 0.3);
  ASSERT_TRUE(u.separated);
  EXPECT_LT(u.fn_min, 0.0);
  EXPECT_NEAR(u.cap_ratio, 1.0, 1.0e-12);

  // one contact, separating fast: f_n = kn delta - cn v_n < 0; every
  // tangential mode slips at mu |f_n| (clipped: at 0), its spring reset
  const double delta = 1.0e-7, vn = 1.0;
  ASSERT_LT(c.kn * delta - c.cn * vn, 0.0);
  const ContactGeometry g = make_geometry(N_AX, r, r, delta, false);
  const V3 vrel = add(mul(vn, N_AX), mul(0.2, T1_AX));
  const V3 wi = mul(100.0, T2_AX), wj = mul(-50.0, N_AX);
  for (int law : {NORMAL_CLIPPED, NORMAL_UNCLIPPED}) {
    c.normal_law = law;
    double hist[HIST_SIZE] = {1e-5, 2e-5, -1e-5, 1e-5, 0.0, 1e-5, 1e-5};    // all above the caps
    ContactForces out;
    contact_forces(c, g, vrel.data(), wi.data(), wj.data(), 1.0e-7, true, hist, out);
    const double fn = (law == NORMAL_UNCLIPPED) ? c.kn * delta - c.cn * vn : 0.0;
    // (the geometry's overlap is delta to the last bits: 1e-12 relative)
    const double tol = 1.0e-12 * c.cn * vn;
    EXPECT_NEAR(out.fn, fn, tol);
    EXPECT_NEAR(norm(tov(out.ft)), c.mut * std::fabs(fn), tol);
    EXPECT_NEAR(norm(tov(out.fr)), c.mur * std::fabs(fn), tol);
    EXPECT_NEAR(std::fabs(out.fo), c.muo * std::fabs(fn), tol);
    EXPECT_VEC_NEAR(tov(out.f), add(mul(fn, N_AX), tov(out.ft)), tol);
  }
}
