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
   compute grflow/network through the LAMMPS library API:
   - hand-built configurations with closed-form answers (compressed simple
     cubic lattice, whole and sliced; chains of unequal spheres; a floater;
     uniaxial and mixed fabrics with a_c of either sign; off-diagonal
     stress and fabric components; r_u);
   - on a sheared periodic packing: the stress equals compute stress/atom
     (and compute pressure for a triclinic box), the fabric equals compute
     fabric, the contact count equals compute contact/atom, for
     granular/grflow, stock granular and gran/hooke/history;
   - sub-volumes: slab membership, region partitions that add up exactly
     (the arm splitting), slab = zlimits = region block; tau sign in shear;
   - bad input gives a clear error.
   The layout of the output vector is the documented one (1-based c_ID[k]
   in the doc, 0-based here).
------------------------------------------------------------------------- */

#include "compute_grflow_network.h"
#include "lammps_fixture.h"

#include "lammps.h"
#include "modify.h"

#include <cstdio>

using namespace grflow_test;

namespace {

using Out = NetVector;    // the positions of the compute's vector (its header's enum)

const double KN = 1.0e6;

// global vector of a compute, evaluated now if not current
std::vector<double> cvec(Lammps &lmp, const char *id)
{
  auto *v = (double *) lammps_extract_compute(lmp.handle, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
  if (!v || lammps_has_error(lmp.handle)) {
    char buf[1024] = "";
    lammps_get_last_error_message(lmp.handle, buf, sizeof(buf));
    ADD_FAILURE() << "compute " << id << " vector not available: " << buf;
    return std::vector<double>(Out::PC0 + 13, 0.0);
  }
  const int n =
      *(int *) lammps_extract_compute(lmp.handle, id, LMP_STYLE_GLOBAL, LMP_SIZE_VECTOR);
  return std::vector<double>(v, v + n);
}

// error message when evaluating a compute vector must fail
std::string extract_error(Lammps &lmp, const char *id)
{
  lammps_extract_compute(lmp.handle, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
  char buf[1024] = "";
  if (lammps_has_error(lmp.handle)) lammps_get_last_error_message(lmp.handle, buf, sizeof(buf));
  return buf;
}

std::vector<double> slice(const std::vector<double> &v, int first, int n)
{
  return std::vector<double>(v.begin() + first, v.begin() + first + n);
}

// two vectors of this compute agree: stress part relative to the largest
// stress component, the rest relative to its largest entry
void expect_same(const std::vector<double> &a, const std::vector<double> &b, const std::string &what)
{
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_LT(max_rel_diff(slice(a, Out::SXX, Out::RU), slice(b, Out::SXX, Out::RU)), 1.0e-13)
      << what;
  const int rest = (int) a.size() - Out::RU;
  EXPECT_LT(max_rel_diff(slice(a, Out::RU, rest), slice(b, Out::RU, rest)), 1.0e-13) << what;
}

double box_volume(Lammps &lmp)
{
  return lmp.thermo("vol");
}

// ---------------------------------------------------------------------------
// Hand-built configurations: f = kn delta along n, nothing else
// ---------------------------------------------------------------------------

// empty periodic cube of side `side`; spheres then added by sphere()
void empty_box(Lammps &lmp, double side)
{
  lmp.cmds({"units si", "atom_style sphere", "atom_modify map array", "boundary p p p",
            "comm_modify vel yes",
            "region box block 0 " + fmt_double(side) + " 0 " + fmt_double(side) + " 0 " +
                fmt_double(side),
            "create_box 1 box", "neighbor 0.2e-3 bin"});
}

void sphere(Lammps &lmp, double x, double y, double z, double diameter)
{
  lmp.cmd("create_atoms 1 single " + fmt_double(x) + " " + fmt_double(y) + " " + fmt_double(z) +
          " units box");
  lmp.cmd("set atom " + std::to_string(lmp.natoms()) + " diameter " + fmt_double(diameter) +
          " density 2650");
}

void grflow_pair(Lammps &lmp)
{
  lmp.cmds({"pair_style granular/grflow", "pair_coeff * * 1.0e6 1.15"});
}

// deviatoric invariants of a diagonal stress, for expected values
struct Invariants {
  double p, q, snorm;
};
Invariants diag_invariants(double sxx, double syy, double szz)
{
  const double p = (sxx + syy + szz) / 3.0;
  const double ss = (sxx - p) * (sxx - p) + (syy - p) * (syy - p) + (szz - p) * (szz - p);
  return {p, sqrt(1.5 * ss), sqrt(ss)};
}

TEST(NetworkHandBuilt, CompressedSimpleCubicLattice)
{
  // n^3 spheres of diameter d on a periodic sc lattice of spacing L < d:
  // every sphere has 6 contacts carrying F = kn (d - L).  Per unit cell
  // (one sphere, volume L^3) three contacts of branch L along x, y, z give
  // sigma_aa = L F / L^3 = kn (d - L) / L^2, no shear, p = sigma_aa.
  const int n = 4;
  const double d = 1.0e-3, L = 0.99e-3;
  const double F = KN * (d - L);
  const double sigma = F / (L * L);

  Lammps lmp;
  lmp.cmds({"units si", "atom_style sphere", "atom_modify map array", "boundary p p p",
            "comm_modify vel yes", "lattice sc " + fmt_double(L) + " origin 0.5 0.5 0.5",
            "region box block 0 4 0 4 0 4", "create_box 1 box", "create_atoms 1 box",
            "set group all diameter " + fmt_double(d) + " density 2650",
            "neighbor 0.2e-3 bin"});
  grflow_pair(lmp);
  lmp.cmds({"compute all_ all grflow/network slab 1.0",
            "compute half all grflow/network slab 0.5",
            "compute p0 all grflow/network slab 1.0 p0 " + fmt_double(2.0 * sigma),
            "compute p0b all grflow/network slab 1.0 p0 " + fmt_double(0.25 * sigma),
            "run 0"});
  ASSERT_EQ(lmp.natoms(), n * n * n);

  const auto v = cvec(lmp, "all_");
  ASSERT_EQ((int) v.size(), Out::PC0 + 13);    // default cmax 12
  const std::vector<double> want = {sigma, sigma, sigma, 0.0, 0.0, 0.0};
  EXPECT_LT(measured("sc lattice stress vs kn delta / L^2",
                     max_rel_diff(slice(v, Out::SXX, 6), want)),
            1.0e-12);
  EXPECT_NEAR(v[Out::PRESS], sigma, 1.0e-12 * sigma);
  for (int k : {Out::TAU, Out::QDEV, Out::SNORM}) EXPECT_LT(fabs(v[k]), 1.0e-12 * sigma) << k;
  EXPECT_EQ(v[Out::RU], 0.0);    // no p0
  EXPECT_EQ(v[Out::NP], 64.0);
  EXPECT_EQ(v[Out::NFLOAT], 0.0);
  EXPECT_EQ(v[Out::NCONTACT], 64.0 * 6.0 / 2.0);
  EXPECT_EQ(v[Out::ZG], 6.0);
  EXPECT_EQ(v[Out::ZPLAIN], 6.0);
  for (int k = Out::AXX; k <= Out::AYZ; k++) EXPECT_LT(fabs(v[k]), 1.0e-14) << k;
  EXPECT_LT(fabs(v[Out::AC]), 1.0e-13);
  EXPECT_GE(v[Out::AC], 0.0);    // sign(0) = +
  EXPECT_DOUBLE_EQ(v[Out::VOLUME], pow(n * L, 3));
  for (int c = 0; c <= 12; c++) EXPECT_EQ(v[Out::PC0 + c], c == 6 ? 1.0 : 0.0) << "P_" << c;

  // central half of the height: layers 2 and 3 of 4 (32 spheres).  The z
  // contacts to layers 1 and 4 cross the boundary and count with the arm
  // a - delta/2 = L/2 only: 16 L F + 32 (L/2) F over V = 32 L^3, the same
  // stress as the whole lattice.  Coordination stays 6 (both ends' contacts).
  const auto h = cvec(lmp, "half");
  EXPECT_LT(measured("sc lattice half slab stress vs kn delta / L^2",
                     max_rel_diff(slice(h, Out::SXX, 6), want)),
            1.0e-12);
  EXPECT_EQ(h[Out::NP], 32.0);
  EXPECT_EQ(h[Out::NCONTACT], 32.0 * 6.0 / 2.0);
  EXPECT_EQ(h[Out::ZG], 6.0);
  EXPECT_DOUBLE_EQ(h[Out::VOLUME], 0.5 * pow(n * L, 3));

  // r_u = 1 - p/p0
  EXPECT_NEAR(cvec(lmp, "p0")[Out::RU], 0.5, 1.0e-12);
  EXPECT_NEAR(cvec(lmp, "p0b")[Out::RU], -3.0, 1.0e-12);
}

TEST(NetworkHandBuilt, ChainOfUnequalSpheresAndFloater)
{
  // three spheres stacked along z, overlaps 1e-5 and 2e-5 m
  const double side = 0.01, V = side * side * side;
  const double d1 = 1.0e-3, d2 = 1.4e-3, d3 = 1.2e-3;
  const double r1 = d1 / 2, r2 = d2 / 2, r3 = d3 / 2;
  const double ov12 = 1.0e-5, ov23 = 2.0e-5;
  const double l12 = r1 + r2 - ov12, l23 = r2 + r3 - ov23;    // branch lengths
  const double F12 = KN * ov12, F23 = KN * ov23;
  const double z1 = 3.0e-3, z2 = z1 + l12, z3 = z2 + l23;

  Lammps lmp;
  empty_box(lmp, side);
  sphere(lmp, 5.0e-3, 5.0e-3, z1, d1);
  sphere(lmp, 5.0e-3, 5.0e-3, z2, d2);
  sphere(lmp, 5.0e-3, 5.0e-3, z3, d3);
  grflow_pair(lmp);
  // only the middle sphere, only the bottom one, and a group of the bottom two
  const double slab = 0.5e-3;
  lmp.cmds({"region mid block INF INF INF INF " + fmt_double(z2 - slab) + " " +
                fmt_double(z2 + slab),
            "region bot block INF INF INF INF " + fmt_double(z1 - slab) + " " +
                fmt_double(z1 + slab),
            "group lower id 1 2", "compute net all grflow/network slab 1.0",
            "compute mid all grflow/network region mid",
            "compute bot all grflow/network region bot",
            "compute lower lower grflow/network slab 1.0",
            "compute c1 all grflow/network slab 1.0 cmax 1", "run 0"});

  // whole chain: sigma_zz = (l12 F12 + l23 F23)/V only
  const double szz = (l12 * F12 + l23 * F23) / V;
  auto v = cvec(lmp, "net");
  EXPECT_LT(measured("chain stress vs l F / V",
                     max_rel_diff(slice(v, Out::SXX, 6), {0.0, 0.0, szz, 0.0, 0.0, 0.0})),
            1.0e-12);
  const Invariants inv = diag_invariants(0.0, 0.0, szz);
  EXPECT_NEAR(v[Out::PRESS], szz / 3.0, 1.0e-12 * szz);
  EXPECT_NEAR(v[Out::QDEV], szz, 1.0e-12 * szz);    // q = |szz| for uniaxial stress
  EXPECT_NEAR(v[Out::QDEV], inv.q, 1.0e-12 * szz);
  EXPECT_NEAR(v[Out::SNORM], sqrt(2.0 / 3.0) * szz, 1.0e-12 * szz);
  EXPECT_EQ(v[Out::TAU], 0.0);
  EXPECT_EQ(v[Out::NP], 3.0);
  EXPECT_EQ(v[Out::NFLOAT], 0.0);
  EXPECT_EQ(v[Out::NCONTACT], 2.0);
  EXPECT_DOUBLE_EQ(v[Out::ZG], 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(v[Out::ZPLAIN], 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(v[Out::PC0 + 1], 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(v[Out::PC0 + 2], 1.0 / 3.0);
  // all contacts along z: <nn> = e_z e_z, a = 15/2 diag(-1/3,-1/3,2/3),
  // a:a = 75/2, a_c = sqrt(3/2 a:a) = 15/2, coaxial with s: S_c = 1
  EXPECT_LT(measured("chain fabric vs 15/2 dev(e_z e_z)",
                     max_rel_diff(slice(v, Out::AXX, 6), {-2.5, -2.5, 5.0, 0.0, 0.0, 0.0})),
            1.0e-14);
  EXPECT_NEAR(v[Out::AC], 7.5, 1.0e-13);
  EXPECT_NEAR(v[Out::SC], 1.0, 1.0e-13);
  EXPECT_DOUBLE_EQ(v[Out::VOLUME], V);

  // middle sphere alone: both contacts cross the boundary and count with
  // its arms r2 - ov/2
  const double Vmid = side * side * 2 * slab;
  auto m = cvec(lmp, "mid");
  const double szz_mid = ((r2 - ov12 / 2) * F12 + (r2 - ov23 / 2) * F23) / Vmid;
  EXPECT_LT(measured("middle sphere stress vs arm r - delta/2",
                     max_rel_diff(slice(m, Out::SXX, 6), {0.0, 0.0, szz_mid, 0.0, 0.0, 0.0})),
            1.0e-12);
  EXPECT_DOUBLE_EQ(m[Out::VOLUME], Vmid);
  EXPECT_EQ(m[Out::NP], 1.0);
  EXPECT_EQ(m[Out::NCONTACT], 1.0);    // half of its 2 contacts
  EXPECT_EQ(m[Out::ZG], 2.0);
  EXPECT_EQ(m[Out::PC0 + 2], 1.0);
  EXPECT_NEAR(m[Out::AC], 7.5, 1.0e-13);

  auto b = cvec(lmp, "bot");
  const double szz_bot = (r1 - ov12 / 2) * F12 / Vmid;
  EXPECT_NEAR(b[Out::SZZ], szz_bot, 1.0e-12 * szz_bot);
  EXPECT_EQ(b[Out::NP], 1.0);
  EXPECT_EQ(b[Out::NCONTACT], 0.5);
  EXPECT_EQ(b[Out::PC0 + 1], 1.0);

  // group of the bottom two: sphere 3 is outside, its contact with 2
  // counts for 2 with 2's arm only
  auto g = cvec(lmp, "lower");
  const double szz_low = (l12 * F12 + (r2 - ov23 / 2) * F23) / V;
  EXPECT_NEAR(g[Out::SZZ], szz_low, 1.0e-12 * szz_low);
  EXPECT_EQ(g[Out::NP], 2.0);
  EXPECT_EQ(g[Out::NCONTACT], 1.5);
  EXPECT_EQ(g[Out::ZG], 1.5);

  // last bin of P_c is c >= cmax
  auto c1 = cvec(lmp, "c1");
  ASSERT_EQ((int) c1.size(), Out::PC0 + 2);
  EXPECT_DOUBLE_EQ(c1[Out::PC0 + 0], 0.0);
  EXPECT_DOUBLE_EQ(c1[Out::PC0 + 1], 1.0);

  // a floater far away: counted in N_p and N_p^0 but not in z_g
  sphere(lmp, 8.0e-3, 2.0e-3, 8.0e-3, 1.0e-3);
  lmp.cmd("run 0");
  v = cvec(lmp, "net");
  EXPECT_EQ(v[Out::NP], 4.0);
  EXPECT_EQ(v[Out::NFLOAT], 1.0);
  EXPECT_EQ(v[Out::NCONTACT], 2.0);
  EXPECT_DOUBLE_EQ(v[Out::ZG], 4.0 / 3.0);    // 2 N_c / (N_p - N_p^0)
  EXPECT_DOUBLE_EQ(v[Out::ZPLAIN], 1.0);      // 2 N_c / N_p
  EXPECT_DOUBLE_EQ(v[Out::PC0 + 0], 0.25);    // floaters are in the denominator
  EXPECT_DOUBLE_EQ(v[Out::PC0 + 1], 0.5);
  EXPECT_DOUBLE_EQ(v[Out::PC0 + 2], 0.25);
  EXPECT_NEAR(v[Out::SZZ], szz, 1.0e-12 * szz);    // stress unchanged
  EXPECT_NEAR(v[Out::AC], 7.5, 1.0e-13);
  c1 = cvec(lmp, "c1");
  EXPECT_DOUBLE_EQ(c1[Out::PC0 + 0], 0.25);
  EXPECT_DOUBLE_EQ(c1[Out::PC0 + 1], 0.75);
}

TEST(NetworkHandBuilt, FabricAgainstStressGivesNegativeAc)
{
  // a chain of 5 along z with a tiny overlap (4 contacts) and one pair along
  // x with a large overlap: <nn> = diag(1/5, 0, 4/5),
  // a = 15/2 (<nn> - I/3) = diag(-1, -5/2, 7/2), a:a = 39/2, |a_c| = sqrt(117/4).
  // The stress is mostly sigma_xx, so a:s = -sxx + 7/2 szz < 0: a_c < 0.
  const double side = 0.01, V = side * side * side, d = 1.0e-3;
  const double ovz = 1.0e-6, ovx = 4.0e-5;
  Lammps lmp;
  empty_box(lmp, side);
  for (int k = 0; k < 5; k++) sphere(lmp, 2.5e-3, 2.5e-3, 2.0e-3 + k * (d - ovz), d);
  sphere(lmp, 6.0e-3, 6.0e-3, 6.0e-3, d);
  sphere(lmp, 6.0e-3 + d - ovx, 6.0e-3, 6.0e-3, d);
  grflow_pair(lmp);
  lmp.cmds({"compute net all grflow/network slab 1.0", "run 0"});

  const double sxx = (d - ovx) * KN * ovx / V, szz = 4 * (d - ovz) * KN * ovz / V;
  const auto v = cvec(lmp, "net");
  EXPECT_LT(measured("x pair + z chain stress",
                     max_rel_diff(slice(v, Out::SXX, 6), {sxx, 0.0, szz, 0.0, 0.0, 0.0})),
            1.0e-9);
  const double a[3] = {-1.0, -2.5, 3.5};
  EXPECT_LT(measured("x pair + z chain fabric",
                     max_rel_diff(slice(v, Out::AXX, 6), {a[0], a[1], a[2], 0.0, 0.0, 0.0})),
            1.0e-14);
  const Invariants inv = diag_invariants(sxx, 0.0, szz);
  const double s[3] = {sxx - inv.p, -inv.p, szz - inv.p};
  const double as = a[0] * s[0] + a[1] * s[1] + a[2] * s[2];
  const double sc = as / (sqrt(19.5) * inv.snorm);
  ASSERT_LT(sc, -0.1);    // the arrangement does what it is meant to
  EXPECT_NEAR(v[Out::SC], sc, 1.0e-9);
  EXPECT_NEAR(measured("negative a_c", v[Out::AC]), -sqrt(29.25), 1.0e-13);
  EXPECT_NEAR(v[Out::QDEV], inv.q, 1.0e-9 * inv.q);
  EXPECT_NEAR(v[Out::SNORM], inv.snorm, 1.0e-9 * inv.snorm);
  EXPECT_EQ(v[Out::NP], 7.0);
  EXPECT_EQ(v[Out::NCONTACT], 5.0);
  EXPECT_DOUBLE_EQ(v[Out::ZPLAIN], 10.0 / 7.0);
  EXPECT_DOUBLE_EQ(v[Out::PC0 + 1], 4.0 / 7.0);
  EXPECT_DOUBLE_EQ(v[Out::PC0 + 2], 3.0 / 7.0);
}

TEST(NetworkHandBuilt, OffDiagonalComponentsAndShearAxes)
{
  // three separate pairs along the diagonals (1,1,0), (1,0,1), (0,1,1) with
  // overlaps 1, 2, 3 e-5: w = l F per pair, sigma = sum w n n / V, so
  // sxy = wA/2V, sxz = wB/2V, syz = wC/2V, sxx = (wA+wB)/2V, ...
  // <nn> = I/3 + 1/6 off the diagonal: a_xy = a_xz = a_yz = 5/4, a_c = 15/4.
  const double side = 0.01, V = side * side * side, d = 1.0e-3;
  const double ov[3] = {1.0e-5, 2.0e-5, 3.0e-5};
  const double dir[3][3] = {{1, 1, 0}, {1, 0, 1}, {0, 1, 1}};
  const double c[3][3] = {{2.0e-3, 2.0e-3, 2.0e-3}, {6.0e-3, 2.0e-3, 6.0e-3},
                          {2.0e-3, 6.0e-3, 6.0e-3}};
  Lammps lmp;
  empty_box(lmp, side);
  double w[3];
  for (int k = 0; k < 3; k++) {
    const double r = d - ov[k];
    w[k] = r * KN * ov[k];
    sphere(lmp, c[k][0], c[k][1], c[k][2], d);
    sphere(lmp, c[k][0] + r * dir[k][0] / sqrt(2.0), c[k][1] + r * dir[k][1] / sqrt(2.0),
           c[k][2] + r * dir[k][2] / sqrt(2.0), d);
  }
  grflow_pair(lmp);
  lmp.cmds({"compute xz all grflow/network slab 1.0",
            "compute zx all grflow/network slab 1.0 shear zx",
            "compute xy all grflow/network slab 1.0 shear xy",
            "compute yz all grflow/network slab 1.0 shear zy", "run 0"});
  const auto v = cvec(lmp, "xz");
  const std::vector<double> want = {(w[0] + w[1]) / (2 * V), (w[0] + w[2]) / (2 * V),
                                    (w[1] + w[2]) / (2 * V), w[0] / (2 * V),
                                    w[1] / (2 * V),          w[2] / (2 * V)};
  EXPECT_LT(measured("diagonal pairs stress", max_rel_diff(slice(v, Out::SXX, 6), want)), 1.0e-9);
  EXPECT_LT(measured("diagonal pairs fabric",
                     max_rel_diff(slice(v, Out::AXX, 6), {0.0, 0.0, 0.0, 1.25, 1.25, 1.25})),
            1.0e-12);
  EXPECT_NEAR(v[Out::AC], 3.75, 1.0e-12);
  // tau = -(s_ab + s_ba)/2: a compressed contact along x+z pushes the top
  // toward -x, i.e. resists a shear with the top moving -x: tau < 0
  EXPECT_NEAR(v[Out::TAU], -want[4], 1.0e-9 * want[4]);
  EXPECT_EQ(cvec(lmp, "zx")[Out::TAU], v[Out::TAU]);
  EXPECT_NEAR(cvec(lmp, "xy")[Out::TAU], -want[3], 1.0e-9 * want[3]);
  EXPECT_NEAR(cvec(lmp, "yz")[Out::TAU], -want[5], 1.0e-9 * want[5]);
  EXPECT_EQ(v[Out::NP], 6.0);
  EXPECT_EQ(v[Out::ZG], 1.0);
}

TEST(NetworkHandBuilt, P0FirstTakesFirstPositivePressure)
{
  // two spheres along z: separated, then overlapping by 1e-5, then 3e-5;
  // p = (d - ov) kn ov / (3V)
  const double side = 0.01, V = side * side * side, d = 1.0e-3, z0 = 4.0e-3;
  Lammps lmp;
  empty_box(lmp, side);
  sphere(lmp, 5.0e-3, 5.0e-3, z0, d);
  sphere(lmp, 5.0e-3, 5.0e-3, z0 + 1.5 * d, d);
  grflow_pair(lmp);
  lmp.cmds({"compute net all grflow/network slab 1.0 p0 first", "run 0"});
  auto v = cvec(lmp, "net");
  EXPECT_EQ(v[Out::PRESS], 0.0);
  EXPECT_EQ(v[Out::RU], 0.0);    // no pressure yet: p0 not taken (r_u would be 0/0)
  EXPECT_EQ(v[Out::NFLOAT], 2.0);

  auto p_of = [&](double ov) { return (d - ov) * KN * ov / (3.0 * V); };
  lmp.cmds({"set atom 2 z " + fmt_double(z0 + d - 1.0e-5), "run 0"});
  v = cvec(lmp, "net");
  EXPECT_NEAR(v[Out::PRESS], p_of(1.0e-5), 1.0e-9 * p_of(1.0e-5));
  EXPECT_EQ(v[Out::RU], 0.0);    // p0 = this p
  lmp.cmds({"set atom 2 z " + fmt_double(z0 + d - 3.0e-5), "run 0"});
  v = cvec(lmp, "net");
  EXPECT_NEAR(measured("r_u with p0 first", v[Out::RU]), 1.0 - p_of(3.0e-5) / p_of(1.0e-5), 1.0e-9);
}

// ---------------------------------------------------------------------------
// Packings: stock computes, sub-volumes, shear
// ---------------------------------------------------------------------------

class NetworkPackings : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { poly = make_packing("network_poly", 6, 1.0e-3, 2.0e-3, 0.60); }
  static std::string poly;

  static void read(Lammps &lmp)
  {
    lmp.cmds({"units si", "atom_style sphere", "atom_modify map array", "comm_modify vel yes",
              "read_data " + poly + " nocoeff", "neighbor 0.2e-3 bin",
              "neigh_modify delay 0 every 1 check yes", "timestep 1.0e-7"});
  }

  // keep the packing deforming so that contacts slide (as test_pair_grflow)
  static void drive(Lammps &lmp)
  {
    lmp.cmds({"fix nve all nve/sphere",
              "fix shear all deform 1 x erate -20 y erate 10 z erate 10 remap x units box"});
  }
};
std::string NetworkPackings::poly;

const std::vector<std::string> GRFLOW_PAIR = {"pair_style granular/grflow",
                                              "pair_coeff * * 1.0e6 1.15"};
const std::vector<std::string> STOCK_GRANULAR = {
    "pair_style granular",
    "pair_coeff * * hooke 1.0e6 1.15 damping velocity limit_damping tangential linear_history "
    "8.0e5 0.2 0.5"};
const std::vector<std::string> STOCK_HOOKE = {
    "pair_style gran/hooke/history 1.0e6 8.0e5 1.0e6 5.0e5 0.5 1 limit_damping", "pair_coeff * *"};

void compare_with_stock_computes(Lammps &lmp, const std::string &tag, bool all_loaded)
{
  const double V = box_volume(lmp);
  const auto v = cvec(lmp, "net");
  const auto sr = cvec(lmp, "sr");
  const auto fab = cvec(lmp, "fab");
  const auto pl = cvec(lmp, "plsum");
  auto *cr = (double *) lammps_extract_compute(lmp.handle, "cr", LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR);
  ASSERT_NE(cr, nullptr);
  const double touching = *cr / 2.0;
  const int n = lmp.natoms();

  std::vector<double> stock(6);
  for (int k = 0; k < 6; k++) stock[k] = -sr[k] / V;
  EXPECT_LT(measured(tag + " stress vs stress/atom", max_rel_diff(slice(v, Out::SXX, 6), stock)),
            1.0e-10);
  EXPECT_NEAR(v[Out::VOLUME], V, 1.0e-14 * V);
  EXPECT_EQ(v[Out::NP], n);
  EXPECT_GT(v[Out::PRESS], 0.0);
  // tangential forces are really there: sum |f_t| / sum f_n over contacts
  EXPECT_GT(measured(tag + " sum|ft|/sum fn", pl[1] / pl[0]), 1.0e-2);

  // contacts: contact/atom and compute fabric count touching pairs, this
  // compute only those with a positive normal force.  Find the touching
  // pairs without normal force (pair/local) and take them out of the stock
  // numbers: sum over pairs of n n is nt <nn>, and a = 15/2 dev <nn>.
  const auto radius = (double *) lammps_extract_atom(lmp.handle, "radius");
  const auto atag = (int *) lammps_extract_atom(lmp.handle, "id");
  std::vector<double> rad(n + 1);
  for (int k = 0; k < n; k++) rad[atag[k]] = radius[k];
  const int nrows =
      *(int *) lammps_extract_compute(lmp.handle, "pln", LMP_STYLE_LOCAL, LMP_SIZE_ROWS);
  auto pln = (double **) lammps_extract_compute(lmp.handle, "pln", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY);
  auto ids = (double **) lammps_extract_compute(lmp.handle, "ids", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY);
  ASSERT_EQ(nrows,
            *(int *) lammps_extract_compute(lmp.handle, "ids", LMP_STYLE_LOCAL, LMP_SIZE_ROWS));
  double unloaded = 0.0, zz[3][3] = {{0.0}};
  for (int row = 0; row < nrows; row++) {
    const double *q = pln[row];
    if (q[0] >= rad[(int) ids[row][0]] + rad[(int) ids[row][1]] || q[4] > 0.0) continue;
    unloaded += 1.0;
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) zz[a][b] += q[1 + a] * q[1 + b] / (q[0] * q[0]);
  }
  measured(tag + " touching pairs without normal force", unloaded);
  if (all_loaded) EXPECT_EQ(unloaded, 0.0);
  EXPECT_EQ(v[Out::NCONTACT], touching - unloaded);
  auto *nt_ptr =
      (double *) lammps_extract_compute(lmp.handle, "fab", LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR);
  ASSERT_NE(nt_ptr, nullptr);
  const double nt = *nt_ptr;
  EXPECT_EQ(nt, touching);
  const double trz = (zz[0][0] + zz[1][1] + zz[2][2]) / 3.0;
  const double devz[6] = {zz[0][0] - trz, zz[1][1] - trz, zz[2][2] - trz,
                          zz[0][1],       zz[0][2],       zz[1][2]};
  std::vector<double> want(6);
  for (int k = 0; k < 6; k++) want[k] = (nt * fab[k] - 7.5 * devz[k]) / (nt - unloaded);
  EXPECT_LT(measured(tag + " fabric vs compute fabric (less unloaded pairs)",
                     max_rel_diff(slice(v, Out::AXX, 6), want)),
            1.0e-12);
  if (unloaded > 0.0)    // and the correction was needed
    EXPECT_GT(max_rel_diff(slice(v, Out::AXX, 6), fab), 1.0e-6);
  EXPECT_DOUBLE_EQ(v[Out::ZPLAIN], 2.0 * v[Out::NCONTACT] / n);
  // P_c sums to 1 and its mean is z
  double sum = 0.0, mean = 0.0;
  for (size_t c = Out::PC0; c < v.size(); c++) {
    sum += v[c];
    mean += (c - Out::PC0) * v[c];
  }
  EXPECT_NEAR(sum, 1.0, 1.0e-14);
  if (v.back() == 0.0) EXPECT_NEAR(mean, v[Out::ZPLAIN], 1.0e-13);
  EXPECT_NEAR(v[Out::PC0], v[Out::NFLOAT] / n, 1.0e-15);
}

void stock_comparison(const std::string &data_read_tag, const std::vector<std::string> &pair,
                      void (*read)(Lammps &), void (*drive)(Lammps &))
{
  Lammps lmp;
  read(lmp);
  lmp.cmds(pair);
  drive(lmp);
  lmp.cmds({"compute net all grflow/network slab 1.0",
            "compute sa all stress/atom NULL pair",
            "compute sr all reduce sum c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]",
            "compute fab all fabric radius contact", "compute ca all contact/atom",
            "compute cr all reduce sum c_ca", "compute pl all pair/local force p4",
            "compute plsum all reduce sum c_pl[1] c_pl[2] inputs local",
            "compute pln all pair/local dist dx dy dz force",
            "compute ids all property/local patom1 patom2",
            // thermo invokes the stock computes on the step (per-atom virial)
            "thermo_style custom step c_net[7] c_sr[1] c_fab[1] c_cr c_plsum[1]", "thermo 500",
            "run 1000", "run 0"});
  ASSERT_FALSE(::testing::Test::HasFailure());    // stock computes need the run
  compare_with_stock_computes(lmp, data_read_tag + " moving", false);
  // at rest every touching pair carries kn delta > 0; the sliding springs
  // still give tangential forces
  lmp.cmds({"velocity all set 0 0 0", "set group all omega 0 0 0", "run 0"});
  compare_with_stock_computes(lmp, data_read_tag + " at rest", true);
}

TEST_F(NetworkPackings, MatchesStockComputesGRFLOW)
{
  stock_comparison("granular/grflow", GRFLOW_PAIR, read, drive);
}

TEST_F(NetworkPackings, MatchesStockComputesPairGranular)
{
  stock_comparison("granular", STOCK_GRANULAR, read, drive);
}

TEST_F(NetworkPackings, MatchesStockComputesGranHookeHistory)
{
  stock_comparison("gran/hooke/history", STOCK_HOOKE, read, drive);
}

TEST_F(NetworkPackings, SlabHoldsTheCentralParticles)
{
  Lammps lmp;
  read(lmp);
  lmp.cmds(GRFLOW_PAIR);
  drive(lmp);
  lmp.cmds({"run 1000", "compute slab all grflow/network",
            "compute whole all grflow/network slab 1.0",
            "variable bot equal zlo+0.1*lz", "variable top equal zhi-0.1*lz",
            "region mid block INF INF INF INF ${bot} ${top}",
            "compute reg all grflow/network region mid",
            "compute zl all grflow/network slab 1.0 zlimits v_bot v_top",
            "compute zn all grflow/network slab 0.5 zlimits $(zlo-0.3*lz) $(zhi+0.3*lz)",
            "variable a equal zlo+0.25*lz", "variable b equal zlo+0.75*lz",
            "region quarter block INF INF INF INF ${a} ${b}",
            "compute q1 all grflow/network region quarter",
            "compute q2 all grflow/network slab 0.5", "run 0"});

  const auto x = lmp.gather3("x");
  const double zlo = lmp.thermo("zlo"), zhi = lmp.thermo("zhi");
  const double lo = zlo + 0.1 * (zhi - zlo), hi = zhi - 0.1 * (zhi - zlo);
  int count = 0;
  for (int i = 0; i < lmp.natoms(); i++) count += (x[3 * i + 2] >= lo && x[3 * i + 2] < hi);
  const auto s = cvec(lmp, "slab"), w = cvec(lmp, "whole");
  EXPECT_EQ(s[Out::NP], count);
  EXPECT_GT(count, 0.6 * lmp.natoms());
  EXPECT_LT(count, lmp.natoms());
  EXPECT_NEAR(s[Out::VOLUME], 0.8 * w[Out::VOLUME], 1.0e-14 * w[Out::VOLUME]);
  EXPECT_GT(measured("slab 0.8 vs whole box stress", max_rel_diff(slice(s, Out::SXX, 6),
                                                                  slice(w, Out::SXX, 6))),
            1.0e-6);

  // the same sub-volume given as a region block, as zlimits with variables
  // (central 100%) and as zlimits with numbers (central 50% of a range 1.6
  // times the box height)
  for (const char *id : {"reg", "zl", "zn"}) expect_same(cvec(lmp, id), s, id);
  expect_same(cvec(lmp, "q1"), cvec(lmp, "q2"), "quarter");
}

TEST_F(NetworkPackings, SlabOfWholePeriodicBoxHoldsAllParticlesDuringRun)
{
  // between reneighborings atoms may be slightly outside the periodic box;
  // the slab uses their image inside it
  Lammps lmp;
  read(lmp);
  lmp.cmds(GRFLOW_PAIR);
  drive(lmp);
  lmp.cmds({"neigh_modify delay 0 every 1 check yes", "compute whole all grflow/network slab 1.0",
            "variable missing equal abs(c_whole[12]-count(all))",
            "fix m all ave/time 1 1000 1000 v_missing", "run 1000"});
  auto *missing =
      (double *) lammps_extract_fix(lmp.handle, "m", LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR, 0, 0);
  ASSERT_NE(missing, nullptr);
  EXPECT_EQ(measured("missing particles averaged over 1000 steps", *missing), 0.0);
  lammps_free(missing);
}

TEST_F(NetworkPackings, RegionPartitionAddsUp)
{
  // three block regions that partition the periodic box: every contact that
  // crosses a boundary is split into the two centre-to-contact-point arms,
  // so V_A sigma_A + V_B sigma_B + V_C sigma_C = V sigma exactly, and counts,
  // contact ends, fabric sums and P_c histograms add up
  Lammps lmp;
  read(lmp);
  lmp.cmds(GRFLOW_PAIR);
  drive(lmp);
  lmp.cmds({"run 1000", "variable zm equal zlo+0.37*lz", "variable xm equal xlo+0.61*lx",
            "region A block INF INF INF INF INF ${zm}",
            "region B block INF ${xm} INF INF ${zm} INF",
            "region C block ${xm} INF INF INF ${zm} INF",
            "compute whole all grflow/network slab 1.0",
            "compute A all grflow/network region A", "compute B all grflow/network region B",
            "compute C all grflow/network region C", "run 0"});
  const auto w = cvec(lmp, "whole");
  std::vector<double> vs(6, 0.0), fab(6, 0.0), hist(13, 0.0);
  double vol = 0.0, np = 0.0, ends = 0.0, nfloat = 0.0;
  for (const char *id : {"A", "B", "C"}) {
    const auto r = cvec(lmp, id);
    vol += r[Out::VOLUME];
    np += r[Out::NP];
    nfloat += r[Out::NFLOAT];
    ends += 2.0 * r[Out::NCONTACT];
    for (int k = 0; k < 6; k++) {
      vs[k] += r[Out::VOLUME] * r[Out::SXX + k];
      fab[k] += 2.0 * r[Out::NCONTACT] * r[Out::AXX + k];
    }
    for (int c = 0; c <= 12; c++) hist[c] += r[Out::NP] * r[Out::PC0 + c];
    EXPECT_GT(r[Out::NP], 20.0) << id;
  }
  EXPECT_NEAR(vol, w[Out::VOLUME], 1.0e-14 * vol);
  EXPECT_EQ(np, w[Out::NP]);
  EXPECT_EQ(nfloat, w[Out::NFLOAT]);
  EXPECT_EQ(ends, 2.0 * w[Out::NCONTACT]);
  std::vector<double> whole_vs(6), whole_fab(6), whole_hist(13);
  for (int k = 0; k < 6; k++) {
    whole_vs[k] = w[Out::VOLUME] * w[Out::SXX + k];
    whole_fab[k] = 2.0 * w[Out::NCONTACT] * w[Out::AXX + k];
  }
  for (int c = 0; c <= 12; c++) whole_hist[c] = w[Out::NP] * w[Out::PC0 + c];
  EXPECT_LT(measured("partition: sum V_k sigma_k vs V sigma", max_rel_diff(vs, whole_vs)),
            1.0e-12);
  EXPECT_LT(measured("partition: fabric sums", max_rel_diff(fab, whole_fab)), 1.0e-12);
  EXPECT_LT(max_rel_diff(hist, whole_hist), 1.0e-12);

  // and a region's stress is not the whole-box stress
  const auto a = cvec(lmp, "A");
  EXPECT_GT(measured("region A vs whole box stress",
                     max_rel_diff(slice(a, Out::SXX, 6), slice(w, Out::SXX, 6))),
            1.0e-6);
}

TEST_F(NetworkPackings, TauPositiveWhenTopMovesPlusX)
{
  // simple shear of a triclinic box, the top (high z) moving +x: the
  // material resists, the LAMMPS (compression-positive) sigma_xz < 0, and
  // tau = -(sigma_xz + sigma_zx)/2 > 0; reversed shear gives tau < 0.
  // The stress also equals compute pressure (virial only) in a tilted box.
  for (double rate : {+50.0, -50.0}) {
    Lammps lmp;
    read(lmp);
    lmp.cmds(GRFLOW_PAIR);
    lmp.cmds({"change_box all triclinic", "fix nve all nve/sphere",
              "fix shear all deform 1 xz erate " + fmt_double(rate) + " remap x units box",
              "compute net all grflow/network slab 1.0",
              "compute zx all grflow/network slab 1.0 shear zx",
              "compute pv all pressure NULL virial",
              "thermo_style custom step c_net[8] c_pv[5]", "thermo 500", "run 3000"});
    auto v = cvec(lmp, "net");
    // during a run the dashpot forces differ: single() sees the velocities
    // at the end of the step, the pair style used the half-step ones
    const double during = max_rel_diff(slice(v, Out::SXX, 6), cvec(lmp, "pv"));
    measured("triclinic stress vs compute pressure virial during the run", during);
    EXPECT_LT(during, 1.0e-3);
    lmp.cmd("run 0");
    v = cvec(lmp, "net");
    const double tau = v[Out::TAU];
    measured("tau/p for xz erate " + fmt_double(rate), tau / v[Out::PRESS]);
    if (rate > 0) {
      EXPECT_GT(tau, 0.02 * v[Out::PRESS]);
      EXPECT_LT(v[Out::SXZ], 0.0);
    } else {
      EXPECT_LT(tau, -0.02 * v[Out::PRESS]);
      EXPECT_GT(v[Out::SXZ], 0.0);
    }
    EXPECT_EQ(cvec(lmp, "zx")[Out::TAU], tau);
    const auto pv = cvec(lmp, "pv");
    EXPECT_GT(fabs(lmp.thermo("xz")), 0.0);
    EXPECT_LT(measured("triclinic stress vs compute pressure virial after run 0",
                       max_rel_diff(slice(v, Out::SXX, 6), pv)),
              1.0e-10);
  }
}

// the stress path (compute_stress(), what fix grflow/shear's checks read)
// gives the vector's first NSTRESS entries to the bit, for a moving
// packing, a slab and a region, with and without p0
TEST_F(NetworkPackings, StressPathIsTheVectorsStress)
{
  Lammps lmp;
  read(lmp);
  lmp.cmds(GRFLOW_PAIR);
  lmp.cmds({"change_box all triclinic", "fix nve all nve/sphere",
            "fix shear all deform 1 xz erate 50.0 remap x units box",
            "compute slab all grflow/network slab 0.8",
            "region mid block INF INF INF INF EDGE EDGE side in",
            "compute reg all grflow/network region mid p0 1.0e3",
            "thermo_style custom step c_slab[8]", "thermo 500", "run 1000 post no"});
  auto *lammps = (LAMMPS_NS::LAMMPS *) lmp.handle;
  for (const char *id : {"slab", "reg"}) {
    auto *net = dynamic_cast<LAMMPS_NS::ComputeGRFLOWNetwork *>(
        lammps->modify->get_compute_by_id(id));
    ASSERT_NE(net, nullptr);
    const double *s = net->compute_stress();
    const std::vector<double> stress(s, s + Out::NSTRESS);
    net->compute_vector();
    EXPECT_GT(fabs(stress[Out::TAU]), 0.0) << id;
    for (int k = 0; k < Out::NSTRESS; k++) EXPECT_EQ(stress[k], net->vector[k]) << id << " " << k;
    // a current vector's entries serve the stress path
    EXPECT_EQ(net->current_stress()[Out::TAU], net->vector[Out::TAU]) << id;
  }
}

TEST_F(NetworkPackings, P0FirstFollowsPressure)
{
  Lammps lmp;
  read(lmp);
  lmp.cmds(GRFLOW_PAIR);
  lmp.cmds({"fix nve all nve/sphere",
            "fix comp all deform 1 x erate -5 y erate -5 z erate -5 remap x units box",
            "compute ref all grflow/network", "compute first all grflow/network p0 first",
            "compute fixed all grflow/network p0 1.0e5",
            "thermo_style custom step c_ref[7] c_first[11] c_fixed[11]", "thermo 100", "run 0"});
  const double p_first = cvec(lmp, "ref")[Out::PRESS];
  EXPECT_EQ(cvec(lmp, "first")[Out::RU], 0.0);
  lmp.cmd("run 500");
  const double p = cvec(lmp, "ref")[Out::PRESS];
  const double ru = cvec(lmp, "first")[Out::RU];
  EXPECT_NEAR(measured("r_u after compression (p0 first)", ru), 1.0 - p / p_first, 1.0e-13);
  EXPECT_GT(fabs(ru), 1.0e-3);    // p has changed
  EXPECT_NEAR(cvec(lmp, "fixed")[Out::RU], 1.0 - p / 1.0e5, 1.0e-13);
}

// ---------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------

const std::vector<std::string> sphere_box = {
    "units si",
    "atom_style sphere",
    "comm_modify vel yes",
    "region box block 0 0.01 0 0.01 0 0.01",
    "create_box 1 box",
    "create_atoms 1 single 0.005 0.005 0.005",
    "set atom 1 diameter 1.0e-3 density 2650",
    "region ball sphere 0.005 0.005 0.005 0.002",
    "region outside block 0 0.005 0 0.005 0 0.005 side out",
    "variable h equal 0.01",
    "variable xa atom x"};


TEST(NetworkErrors, BadArguments)
{
  struct Case {
    const char *line, *expect;
  } cases[] = {
      {"compute n all grflow/network foo 1", "Unknown compute grflow/network keyword: foo"},
      {"compute n all grflow/network slab", "Illegal compute grflow/network slab command: missing"},
      {"compute n all grflow/network slab 0", "slab must be in (0,1], got 0"},
      {"compute n all grflow/network slab 1.2", "slab must be in (0,1], got 1.2"},
      {"compute n all grflow/network slab abc", "slab expects a number, got 'abc'"},
      {"compute n all grflow/network shear xx", "shear must be two different axes"},
      {"compute n all grflow/network shear xw", "shear must be two different axes"},
      {"compute n all grflow/network shear xyz", "shear must be two different axes"},
      {"compute n all grflow/network p0 0", "p0 must be > 0"},
      {"compute n all grflow/network p0 -1e5", "p0 must be > 0"},
      {"compute n all grflow/network p0 last", "p0 expects a number, got 'last'"},
      {"compute n all grflow/network cmax 0", "cmax must be in 1..100"},
      {"compute n all grflow/network cmax 101", "cmax must be in 1..100"},
      {"compute n all grflow/network cmax 2.5", "cmax expects an integer, got '2.5'"},
      {"compute n all grflow/network region nope", "Region nope for compute grflow/network does not exist"},
      {"compute n all grflow/network region ball zlimits 0 1", "use either region or zlimits"},
      {"compute n all grflow/network volume 1e-6", "volume goes with region"},
      {"compute n all grflow/network zlimits 0", "Illegal compute grflow/network zlimits command: missing"},
      {"compute n all grflow/network zlimits 0 abc", "zlimits expects a number, got 'abc'"},
  };
  for (const auto &c : cases) {
    const std::string msg = error_after(sphere_box, c.line);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.line << " -> '" << msg << "'";
  }

  std::string msg = error_after({"units si", "atom_style atomic", "region box block 0 1 0 1 0 1",
                                 "create_box 1 box"},
                                "compute n all grflow/network");
  EXPECT_NE(msg.find("requires atom attribute radius"), std::string::npos) << msg;
}

// errors found at init (run) or when the vector is evaluated
TEST(NetworkErrors, BadSetupAtRun)
{
  auto with_pair = sphere_box;
  with_pair.insert(with_pair.end(), GRFLOW_PAIR.begin(), GRFLOW_PAIR.end());
  struct Case {
    std::vector<std::string> extra;
    const char *expect;
  } cases[] = {
      {{"compute n all grflow/network region ball"},
       "region ball is not an inside block: give its volume"},
      {{"compute n all grflow/network region outside"},
       "region outside is not an inside block: give its volume"},
      {{"compute n all grflow/network zlimits 0.006 0.004"}, "zlimits must have zlo < zhi"},
      {{"compute n all grflow/network zlimits 0.004 v_nope"},
       "Variable nope for compute grflow/network does not exist"},
      {{"compute n all grflow/network zlimits 0.0 v_xa"},
       "Variable xa for compute grflow/network is not equal-style"},
      {{"compute n all grflow/network region ball volume -1.0"}, "sub-volume is -1"},
      {{"region gone block 0 1 0 1 0 1", "compute n all grflow/network region gone",
        "region gone delete"},
       "Region gone for compute grflow/network does not exist"},
  };
  for (const auto &c : cases) {
    Lammps lmp;
    lmp.cmds(with_pair);
    lmp.cmds(c.extra);
    lmp.cmds({"thermo_style custom step c_n[1]"});
    const std::string msg = lmp.error_of("run 0");
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.extra.back() << " -> '" << msg << "'";
  }
  // a region with its volume given is fine
  Lammps ok;
  ok.cmds(with_pair);
  ok.cmds({"compute n all grflow/network region ball volume 3.0e-8", "run 0"});
  EXPECT_EQ(cvec(ok, "n")[Out::VOLUME], 3.0e-8);
  EXPECT_EQ(cvec(ok, "n")[Out::NP], 1.0);
}

TEST(NetworkErrors, NeedsGranularPairAndARun)
{
  // no pair style
  {
    Lammps lmp;
    lmp.cmds(sphere_box);
    lmp.cmd("compute n all grflow/network");
    std::string msg = extract_error(lmp, "n");
    EXPECT_NE(msg.find("requires a pair style"), std::string::npos) << msg;
    msg = lmp.error_of("run 0");
    EXPECT_NE(msg.find("requires a pair style"), std::string::npos) << msg;
  }
  // a pair style without a granular single()
  {
    Lammps lmp;
    lmp.cmds(sphere_box);
    lmp.cmds({"pair_style lj/cut 1.0e-3", "pair_coeff * * 1.0 1.0e-3",
              "compute n all grflow/network"});
    const std::string msg = lmp.error_of("run 0");
    EXPECT_NE(msg.find("requires a granular pair style with single()"), std::string::npos) << msg;
    EXPECT_NE(msg.find("not lj/cut"), std::string::npos) << msg;
  }
  // granular pair style, but evaluated before any run: no neighbor list
  {
    Lammps lmp;
    lmp.cmds(sphere_box);
    lmp.cmds(GRFLOW_PAIR);
    lmp.cmd("compute n all grflow/network");
    const std::string msg = extract_error(lmp, "n");
    EXPECT_NE(msg.find("use it after a run (run 0 will do)"), std::string::npos) << msg;
  }
  // defined after a run and evaluated before the next one: the region and
  // the pair style are checked even though init() has not been called
  {
    Lammps lmp;
    lmp.cmds(sphere_box);
    lmp.cmds(GRFLOW_PAIR);
    lmp.cmds({"run 0", "region low block INF INF INF INF INF 0.004",
              "compute n all grflow/network region low"});
    EXPECT_EQ(cvec(lmp, "n")[Out::NP], 0.0);    // the sphere at z = 0.005 is not in it
    EXPECT_DOUBLE_EQ(cvec(lmp, "n")[Out::VOLUME], 0.01 * 0.01 * 0.004);
  }
}

}    // namespace
