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
   GRFLOW contact kernel: linear spring-dashpot contact between spheres
   (or a sphere and a flat wall) with sliding, rolling and torsion
   resistance, after Luding, Granular Matter 10:235 (2008).

   Header only and free of LAMMPS types: plain numbers in, forces out, so
   that unit tests, pair styles, wall fixes and accelerator variants share
   one implementation.  The equations are written out in
   doc/pair_granular_grflow.rst.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_CONTACT_H
#define LMP_GRFLOW_CONTACT_H

#include "grflow_contact_coeffs.h"

#include <cmath>

// the kernel is called once per neighbor pair: it must be inlined into the
// pair loop (GCC otherwise keeps contact_forces() out of line, ~2x slower).
// Under CUDA and HIP (the KOKKOS package on a GPU) it is callable from
// device code too.
#if defined(__CUDACC__) || defined(__HIPCC__)
#define GRFLOW_INLINE __host__ __device__ __forceinline__
#elif defined(__GNUC__) || defined(__clang__)
#define GRFLOW_INLINE inline __attribute__((always_inline))
#else
#define GRFLOW_INLINE inline
#endif

namespace LAMMPS_NS {
namespace GRFLOW {

  // per-contact history: sliding spring (3), rolling spring (3), torsion spring (1)

  enum { HIST_SLIDE = 0, HIST_ROLL = 3, HIST_TORSION = 6, HIST_SIZE = 7 };

  // factor applied to each history value when the owner of a pair changes
  // (i <-> j): n and the sliding displacement flip, rolling and torsion do not

  static constexpr double HISTORY_SWAP_FACTOR[HIST_SIZE] = {-1.0, -1.0, -1.0, 1.0, 1.0, 1.0, 1.0};

  // geometry of one contact, set up by the caller

  struct ContactGeometry {
    double n[3];      // unit normal, pointing from j to i
    double delta;     // overlap, > 0
    double arm_i;     // distance from centre of i to the contact point, a_i - delta/2
    double arm_j;     // same for j (unused for a wall)
    double varm_i;    // arms used for the contact-point velocity (= arm_i, arm_j
    double varm_j;    //   unless stock-compatible full radii are requested)
    double reff;      // reduced radius a' = a_i a_j / (a_i + a_j); a_i for a wall
  };

  // results of one contact evaluation

  struct ContactForces {
    double fn;             // normal force along n, >= 0 unless the law is unclipped
    double f[3];           // total force on i (on j: -f)
    double torque_i[3];    // torque on i
    double torque_j[3];    // torque on j
    double ft[3];          // sliding force on i
    double fr[3];          // rolling resistance force (pure torque couple)
    double fo;             // torsion resistance force, along n
  };

  // the extra values of a contact that pair granular/grflow's single()
  // gives (compute pair/local p1, p2, ...: position + 1): first those of
  // stock pair granular, with the same meaning (sliding force on i and its
  // length, rolling resistance and its length, twisting torque on i along
  // n, branch vector x_i - x_j), then GRFLOW's own (torsion force f_o, its
  // magnitude, normal force f_n)
  struct SingleLayout {
    // clang-format off
    enum {
      FS_X, FS_Y, FS_Z, FS_LEN, FR_X, FR_Y, FR_Z, FR_LEN, TWIST, DX, DY, DZ, FO, FO_LEN, FN,
      NVALUES
    };
    // clang-format on
  };

  static GRFLOW_INLINE double dot3(const double *a, const double *b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  static GRFLOW_INLINE void cross3(const double *a, const double *b, double *c)
  {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
  }

  /* ----------------------------------------------------------------------
     rotate a stored spring into the plane normal to n, keeping its length:
     xi <- (xi - p n) s with p = xi.n and s = (1 - q)^(-1/2), q = p^2/|xi|^2.
     n turns little per step, so q is tiny and the series 1 + q/2 + 3q^2/8
     (truncation 5q^3/16 < 3e-19 for q < 1e-6) replaces a sqrt and a division.
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE void rotate_into_plane(double *xi, const double *n)
  {
    const double p = dot3(xi, n);
    if (p == 0.0) return;
    const double len2 = dot3(xi, xi);
    const double p2 = p * p;
    double proj[3] = {xi[0] - p * n[0], xi[1] - p * n[1], xi[2] - p * n[2]};
    double s;
    if (p2 <= 1.0e-6 * len2) {
      const double q = p2 / len2;
      s = 1.0 + q * (0.5 + 0.375 * q);
    } else {
      // large turn: measure the projection itself (len2 - p2 would cancel)
      const double proj2 = dot3(proj, proj);
      s = (proj2 > 0.0) ? sqrt(len2 / proj2) : 0.0;
    }
    xi[0] = proj[0] * s;
    xi[1] = proj[1] * s;
    xi[2] = proj[2] * s;
  }

  /* ----------------------------------------------------------------------
     linear spring-dashpot on a 3-vector displacement xi with velocity v,
     capped at |f| <= cap (Coulomb): trial f = -k xi - c v; on slip f is
     scaled to length cap and xi reset to -(f + c v)/k.
     update: advance xi by v dt and store a slip reset; else xi is read only.
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE void spring_dashpot_capped(double k, double c, double cap, const double *v,
                                                  double dt, bool update, double *xi, double *f)
  {
    double x0 = xi[0], x1 = xi[1], x2 = xi[2];
    if (update) {
      x0 += v[0] * dt;
      x1 += v[1] * dt;
      x2 += v[2] * dt;
    }
    f[0] = -k * x0 - c * v[0];
    f[1] = -k * x1 - c * v[1];
    f[2] = -k * x2 - c * v[2];
    const double f2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    if (f2 > cap * cap) {
      const double s = cap / sqrt(f2);
      f[0] *= s;
      f[1] *= s;
      f[2] *= s;
      if (k > 0.0) {
        const double kinv = 1.0 / k;
        x0 = -(f[0] + c * v[0]) * kinv;
        x1 = -(f[1] + c * v[1]) * kinv;
        x2 = -(f[2] + c * v[2]) * kinv;
      } else {
        x0 = x1 = x2 = 0.0;
      }
    }
    if (update) {
      xi[0] = x0;
      xi[1] = x1;
      xi[2] = x2;
    }
  }

  /* ----------------------------------------------------------------------
     the same for a scalar displacement (torsion)
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE double spring_dashpot_capped(double k, double c, double cap, double v,
                                                    double dt, bool update, double *xi)
  {
    double x = *xi;
    if (update) x += v * dt;
    double f = -k * x - c * v;
    if (fabs(f) > cap) {
      f = (f > 0.0) ? cap : -cap;
      x = (k > 0.0) ? -(f + c * v) / k : 0.0;
    }
    if (update) *xi = x;
    return f;
  }

  /* ----------------------------------------------------------------------
     normal force along n: k_n delta - c_n v.n.  Clipped (the default) it is
     max(k_n delta - c_n v.n, 0): no attraction.  Unclipped it is the
     linear spring-dashpot as written, negative (attraction through the
     dashpot) near the end of a fast separation.  The Coulomb caps of
     sliding, rolling and torsion are mu |f_n| under both laws (clipped:
     mu f_n, as before), as LAMMPS pair granular without limit_damping,
     gran/hooke/history and MercuryDPM's linear viscoelastic law have them:
     a contact in tension still resists sliding up to mu |f_n|.
  ------------------------------------------------------------------------- */

  // the force of law normal_law (NORMAL_CLIPPED or NORMAL_UNCLIPPED); the
  // caps use its magnitude (fabs() of a clipped force is the force itself)
  static GRFLOW_INLINE double normal_force(int normal_law, double kn, double cn, double delta,
                                           double vn)
  {
    const double fn = kn * delta - cn * vn;
    return (normal_law == NORMAL_UNCLIPPED) ? fn : ((fn > 0.0) ? fn : 0.0);
  }

  /* ----------------------------------------------------------------------
     full contact, one mode after the other: forces and torques on i and j
     from coefficients c, geometry g, relative velocity vrel = v_i - v_j,
     spins wi, wj.  hist points to HIST_SIZE values; they are advanced by
     dt only if update.  (Until 2026-11-28 a second form ran the sliding
     and rolling springs in the two lanes of one SSE2 vector, to the bit
     the same numbers; on the whole shear step it bought 5% jammed and 2%
     liquefied, below the bar of 5% for a second implementation:
     doc/studies/pair-benchmark.md.)
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE void contact_forces(const ContactCoeffs &c, const ContactGeometry &g,
                                           const double *vrel, const double *wi, const double *wj,
                                           double dt, bool update, double *hist, ContactForces &out)
  {
    const double *n = g.n;

    // normal

    const double vn = dot3(vrel, n);
    const double fn = normal_force(c.normal_law, c.kn, c.cn, g.delta, vn);
    const double fnc = fabs(fn);    // for the caps
    out.fn = fn;

    // sliding: velocity of the material points at the contact point

    double warm[3], wxn[3], vt[3];
    warm[0] = g.varm_i * wi[0] + g.varm_j * wj[0];
    warm[1] = g.varm_i * wi[1] + g.varm_j * wj[1];
    warm[2] = g.varm_i * wi[2] + g.varm_j * wj[2];
    cross3(warm, n, wxn);
    vt[0] = vrel[0] - vn * n[0] - wxn[0];
    vt[1] = vrel[1] - vn * n[1] - wxn[1];
    vt[2] = vrel[2] - vn * n[2] - wxn[2];

    // work on local copies of the springs: one load and one store per
    // contact, so that nothing is reread through a pointer that may alias
    double xit[3] = {hist[HIST_SLIDE], hist[HIST_SLIDE + 1], hist[HIST_SLIDE + 2]};
    double xir[3] = {hist[HIST_ROLL], hist[HIST_ROLL + 1], hist[HIST_ROLL + 2]};
    double xio = hist[HIST_TORSION];
    if (update) {
      rotate_into_plane(xit, n);
      rotate_into_plane(xir, n);
    }
    spring_dashpot_capped(c.kt, c.ct, c.mut * fnc, vt, dt, update, xit, out.ft);

    // rolling: v_r = -a' n x (w_i - w_j)

    double wrel[3], nxw[3], vr[3];
    wrel[0] = wi[0] - wj[0];
    wrel[1] = wi[1] - wj[1];
    wrel[2] = wi[2] - wj[2];
    cross3(n, wrel, nxw);
    vr[0] = -g.reff * nxw[0];
    vr[1] = -g.reff * nxw[1];
    vr[2] = -g.reff * nxw[2];
    spring_dashpot_capped(c.kr, c.cr, c.mur * fnc, vr, dt, update, xir, out.fr);

    // torsion: v_o = a' (w_i - w_j).n

    const double vo = g.reff * dot3(wrel, n);
    out.fo = spring_dashpot_capped(c.ko, c.co, c.muo * fnc, vo, dt, update, &xio);

    if (update) {
      for (int k = 0; k < 3; k++) {
        hist[HIST_SLIDE + k] = xit[k];
        hist[HIST_ROLL + k] = xir[k];
      }
      hist[HIST_TORSION] = xio;
    }

    // force on i

    out.f[0] = fn * n[0] + out.ft[0];
    out.f[1] = fn * n[1] + out.ft[1];
    out.f[2] = fn * n[2] + out.ft[2];

    // torques: sliding -(a - delta/2) n x f_t on both;
    // rolling +-a' n x f_r and torsion +-a' f_o n, opposite on j

    double nxft[3], nxfr[3], tc[3];
    cross3(n, out.ft, nxft);
    cross3(n, out.fr, nxfr);
    tc[0] = g.reff * (nxfr[0] + out.fo * n[0]);
    tc[1] = g.reff * (nxfr[1] + out.fo * n[1]);
    tc[2] = g.reff * (nxfr[2] + out.fo * n[2]);
    out.torque_i[0] = -g.arm_i * nxft[0] + tc[0];
    out.torque_i[1] = -g.arm_i * nxft[1] + tc[1];
    out.torque_i[2] = -g.arm_i * nxft[2] + tc[2];
    out.torque_j[0] = -g.arm_j * nxft[0] - tc[0];
    out.torque_j[1] = -g.arm_j * nxft[1] - tc[1];
    out.torque_j[2] = -g.arm_j * nxft[2] - tc[2];
  }

  /* ----------------------------------------------------------------------
     the arm of a contact: distance from the centre of a sphere of radius
     rad to the contact point, the middle of the overlap delta
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE double contact_arm(double rad, double delta)
  {
    return rad - 0.5 * delta;
  }

  /* ----------------------------------------------------------------------
     geometry of a sphere-sphere contact from del = x_i - x_j (|del| = r > 0)
     full_arm: use the radii, not a - delta/2, for the contact-point velocity
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE void pair_geometry(const double *del, double r, double radi, double radj,
                                          bool full_arm, ContactGeometry &g)
  {
    const double rinv = 1.0 / r;
    g.n[0] = del[0] * rinv;
    g.n[1] = del[1] * rinv;
    g.n[2] = del[2] * rinv;
    g.delta = radi + radj - r;
    g.arm_i = contact_arm(radi, g.delta);
    g.arm_j = contact_arm(radj, g.delta);
    g.varm_i = full_arm ? radi : g.arm_i;
    g.varm_j = full_arm ? radj : g.arm_j;
    g.reff = radi * radj / (radi + radj);
  }

  /* ----------------------------------------------------------------------
     geometry of a sphere-plane contact: unit normal n pointing from the
     plane to the sphere's centre, overlap delta = rad - (distance of the
     centre from the plane) > 0.  The plane is a sphere of infinite
     radius: a' = a_i, and it does not spin (arm_j = 0).
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE void plane_geometry(const double *n, double delta, double rad, bool full_arm,
                                           ContactGeometry &g)
  {
    g.n[0] = n[0];
    g.n[1] = n[1];
    g.n[2] = n[2];
    g.delta = delta;
    g.arm_i = contact_arm(rad, g.delta);
    g.arm_j = 0.0;
    g.varm_i = full_arm ? rad : g.arm_i;
    g.varm_j = 0.0;
    g.reff = rad;
  }

  /* ----------------------------------------------------------------------
     a flat wall normal to z on the side sign (+1: the wall is below,
     n = +z; -1: above, n = -z), the sphere's centre at gap = sign (z -
     z_wall) from it, gap < rad
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE void wall_geometry(double gap, double rad, double sign, bool full_arm,
                                          ContactGeometry &g)
  {
    const double n[3] = {0.0, 0.0, sign};
    plane_geometry(n, rad - gap, rad, full_arm, g);
  }

  /* ----------------------------------------------------------------------
     elastic energy stored in the springs of one contact
  ------------------------------------------------------------------------- */

  static GRFLOW_INLINE double elastic_energy(const ContactCoeffs &c, double delta,
                                             const double *hist)
  {
    const double *xt = hist + HIST_SLIDE;
    const double *xr = hist + HIST_ROLL;
    const double xo = hist[HIST_TORSION];
    return 0.5 *
        (c.kn * delta * delta + c.kt * dot3(xt, xt) + c.kr * dot3(xr, xr) + c.ko * xo * xo);
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
