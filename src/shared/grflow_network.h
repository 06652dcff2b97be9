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
   The contact-network quantities of compute grflow/network, host-free:
   the sums over the contacts and particles of a sub-volume (Eq. 1 stress
   sum l (x) f, fabric sum n (x) n, particle and contact counts, histogram
   of contact numbers) and what is derived from their totals over all
   processors (stress, p, tau, q, r_u, z_g, P_c, fabric anisotropy a_c),
   in the layout of the compute's output vector.  The hosts find the
   contacts, decide which ends lie inside, and add up over processors.
   Header only, no host types.  Equations: doc/compute_grflow_network.rst.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_NETWORK_H
#define LMP_GRFLOW_NETWORK_H

#include "grflow_contact.h"
#include "grflow_host.h"
#include "grflow_wall.h"    // WallContacts

#include <mpi.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace GRFLOW {

  // the pore pressure ratio r_u = 1 - p/p0 of mean stress p against the
  // reference p0 (the compute's p0 keyword, fix grflow/shear's p0); 0
  // while there is no p0 > 0
  static inline double pore_pressure_ratio(double p, double p0)
  {
    return (p0 > 0.0) ? 1.0 - p / p0 : 0.0;
  }

  /* ----------------------------------------------------------------------
     the keywords of compute grflow/network, host-free: region ID, slab f,
     zlimits zlo zhi, volume V, shear ab, p0 value|first, cmax c.  The
     host reads numbers and reports errors (grflow_host.h; also
     host.integer(FLERR, const char *, const std::string &what) -> int).  Region
     IDs, variables (v_name) and volumes are checked by the host.
  ------------------------------------------------------------------------- */

  struct NetworkOptions {
    int cmax = 12;
    int tau_a = 0, tau_b = 2;    // tau = -(sigma_ab + sigma_ba)/2
    double slab = 0.8;           // central fraction of the height (no region)
    std::string region;          // empty: the slab of zlimits (or of the box)
    std::string zlo, zhi;        // sample bounds in z: number or v_name; empty: the box
    std::string volume;          // volume of a non-block region: number or v_name
    bool p0_keyword = false;     // p0 given: r_u = 1 - p/p0 (else r_u = 0)
    bool p0first = false;        // p0 first: the first positive pressure
    bool p0flag = false;         // p0 is set
    double p0 = 0.0;

    template <class Host> void parse(int narg, char **arg, int first, Host &host)
    {
      static const Keyword known[] = {{"region", 1}, {"slab", 1}, {"zlimits", 2}, {"volume", 1},
                                      {"shear", 1},  {"p0", 1},   {"cmax", 1}};
      parse_keywords(narg, arg, first, "compute grflow/network", known, host,
                     [&](const std::string &kw, char **values, const std::string &what) {
                       keyword(kw, values, what, host);
                     });
      if (!region.empty() && !zlo.empty())
        host.fail(FLERR, "Compute grflow/network: use either region or zlimits, not both");
      if (region.empty() && !volume.empty())
        host.fail(FLERR,
                  "Compute grflow/network volume goes with region (the slab volume is known)");
      // numbers now, variables when they are used
      const std::string *values[] = {&zlo, &zhi, &volume};
      const char *const what[] = {"zlimits", "zlimits", "volume"};
      for (int k = 0; k < 3; k++)
        if (!values[k]->empty() && values[k]->compare(0, 2, "v_") != 0)
          host.number(FLERR, values[k]->c_str(), std::string("compute grflow/network ") + what[k]);
    }

    // the values of one keyword of parse()
    template <class Host>
    void keyword(const std::string &kw, char **values, const std::string &what, Host &host)
    {
      const char *value = values[0];
      if (kw == "region") {
        region = value;
      } else if (kw == "slab") {
        slab = host.number(FLERR, value, what);
        if (slab <= 0.0 || slab > 1.0)
          host.fail(FLERR,
                    "Compute grflow/network slab must be in (0,1], got " + format_number(slab));
      } else if (kw == "zlimits") {
        zlo = value;
        zhi = values[1];
      } else if (kw == "volume") {
        volume = value;
      } else if (kw == "shear") {
        const std::string c = value;
        const int a = c.size() == 2 ? c[0] - 'x' : -1;
        const int b = c.size() == 2 ? c[1] - 'x' : -1;
        if (a < 0 || a > 2 || b < 0 || b > 2 || a == b)
          host.fail(FLERR,
                    "Compute grflow/network shear must be two different axes (xy, xz, yz, "
                    "...), got " +
                        c);
        tau_a = a;
        tau_b = b;
      } else if (kw == "p0") {
        p0_keyword = true;
        if (strcmp(value, "first") == 0) {
          p0first = true;
          p0flag = false;
        } else {
          p0 = host.number(FLERR, value, what);
          if (p0 <= 0.0)
            host.fail(FLERR, "Compute grflow/network p0 must be > 0, got " + format_number(p0));
          p0flag = true;
          p0first = false;
        }
      } else if (kw == "cmax") {
        cmax = host.integer(FLERR, value, what);
        if (cmax < 1 || cmax > 100)
          host.fail(FLERR,
                    "Compute grflow/network cmax must be in 1..100, got " + std::to_string(cmax));
      }
    }

    // the output vector from this processor's sums: the sums over all
    // processors of world, then derive_network() (below), or with network
    // false derive_stress(), its first NSTRESS entries only; r_u with
    // reference_p0(); with p0 first, the first positive pressure becomes
    // p0 (r_u = 1 - p/p0 needs p0 > 0)
    void reduce_and_derive(MPI_Comm world, const std::vector<double> &local, double volume,
                           double *vector, bool network);

    // p0 of r_u: that of the p0 keyword (its value, or the first positive
    // pressure once there is one), 0 for none (r_u = 0).  fix grflow/shear
    // has a p0 and an r_u of its own (ShearProtocol, grflow_shear_rule.h).
    double reference_p0() const { return (p0_keyword && p0flag) ? p0 : 0.0; }

    // the bounds of the slab of the sample between zlo and zhi
    void slab_bounds(double zlo_value, double zhi_value, double &lo, double &hi) const
    {
      const double half = 0.5 * slab * (zhi_value - zlo_value);
      const double zmid = 0.5 * (zlo_value + zhi_value);
      lo = zmid - half;
      hi = zmid + half;
    }
  };

  // positions of the entries of the compute's output vector (0-based):
  // stress, p, tau, q, |s|, r_u, particles, floaters, contacts, z_g, z
  // with floaters, a_c, sign, fabric anisotropy tensor, volume, then
  // P_c for c = 0..cmax.  The first NSTRESS entries (SXX..RU) come from
  // the stress sums alone: the stress path (derive_stress()) gives them
  // without the network quantities.
  struct NetworkLayout {
    // clang-format off
    enum {
      SXX, SYY, SZZ, SXY, SXZ, SYZ, PRESS, TAU, QDEV, SNORM, RU, NP, NFLOAT, NCONTACT, ZG,
      ZPLAIN, AC, SC, AXX, AYY, AZZ, AXY, AXZ, AYZ, VOLUME, PC0, NSTRESS = NP
    };
    // clang-format on
    static int size(int cmax) { return PC0 + cmax + 1; }
  };

  // the sums of one sub-volume, in one array of size(cmax) doubles
  struct NetworkSums {
    enum { STRESS = 0, FABRIC = 9, NP = 18, FLOAT, ENDS, HIST };
    static int size(int cmax) { return HIST + cmax + 1; }

    // a particle-particle contact with unit normal n (from j to i) and
    // force f on i: arm is the sum of the arms (a - delta/2) of the ends
    // inside, ends their number (1 or 2)
    static GRFLOW_FUNCTION void add_contact(double *sums, const double *n, const double *f,
                                            double arm, double ends)
    {
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
          sums[STRESS + 3 * a + b] += arm * n[a] * f[b];
          sums[FABRIC + 3 * a + b] += ends * n[a] * n[b];
        }
    }

    // the stress part of add_contact() alone (the same additions, so the
    // stress sums are the same to the bit with or without the fabric)
    static GRFLOW_FUNCTION void add_contact_stress(double *sums, const double *n, const double *f,
                                                   double arm)
    {
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) sums[STRESS + 3 * a + b] += arm * n[a] * f[b];
    }

    // the sum of the contact law's arms a - delta/2 (the kernel's
    // contact_arm) of the ends use_i, use_j of a contact with overlap delta
    static GRFLOW_FUNCTION double pair_arm(double delta, double radi, double radj, bool use_i,
                                           bool use_j)
    {
      double arm = 0.0;
      if (use_i) arm += contact_arm(radi, delta);
      if (use_j) arm += contact_arm(radj, delta);
      return arm;
    }

    // a particle-particle contact with overlap delta between particles of
    // radii radi, radj, counted at the ends use_i, use_j (the ends inside
    // that this processor counts, see count_ends()); with network false
    // its stress only
    static GRFLOW_FUNCTION void add_pair_contact(double *sums, const double *n, const double *f,
                                                 double delta, double radi, double radj, bool use_i,
                                                 bool use_j, bool network = true)
    {
      const double arm = pair_arm(delta, radi, radj, use_i, use_j);
      if (!network) {
        add_contact_stress(sums, n, f, arm);
        return;
      }
      const double ends = (use_i ? 1.0 : 0.0) + (use_j ? 1.0 : 0.0);
      add_contact(sums, n, f, arm, ends);
    }

    // which ends of a listed pair (i owned, j owned or ghost) this
    // processor counts: those inside; with newton off a pair with a ghost
    // is listed by both owners, and each counts only its own particle
    static GRFLOW_FUNCTION void count_ends(bool inside_i, bool inside_j, bool j_owned,
                                           bool newton_pair, bool &use_i, bool &use_j)
    {
      use_i = inside_i;
      use_j = inside_j && (j_owned || newton_pair);
    }

    // a contact of a particle inside with a flat wall normal to z (nz =
    // +1 below, -1 above): arm a - delta/2, force fw on the particle
    static GRFLOW_FUNCTION void add_wall_contact(double *sums, double nz, const double *fw,
                                                 double arm)
    {
      add_wall_stress(sums, nz, fw, arm);
      sums[FABRIC + 3 * 2 + 2] += 1.0;
    }
    static GRFLOW_FUNCTION void add_wall_stress(double *sums, double nz, const double *fw,
                                                double arm)
    {
      for (int b = 0; b < 3; b++) sums[STRESS + 3 * 2 + b] += arm * nz * fw[b];
    }

    // a particle inside with c force-bearing contacts
    static GRFLOW_FUNCTION void add_particle(double *sums, int c, int cmax)
    {
      sums[NP] += 1.0;
      if (c == 0) sums[FLOAT] += 1.0;
      sums[ENDS] += c;
      sums[HIST + (c < cmax ? c : cmax)] += 1.0;
    }
  };

  /* ----------------------------------------------------------------------
     the sub-volume and the per-particle sums, over a host's owned atoms
  ------------------------------------------------------------------------- */

  struct NetworkVolume {
    // the volume of a box [lo, hi] clipped to the simulation box
    static double clipped_box(const double *lo, const double *hi, const double *boxlo,
                              const double *boxhi)
    {
      double len[3];
      for (int d = 0; d < 3; d++) {
        const double a = lo[d] > boxlo[d] ? lo[d] : boxlo[d];
        const double b = hi[d] < boxhi[d] ? hi[d] : boxhi[d];
        len[d] = b - a > 0.0 ? b - a : 0.0;
      }
      return len[0] * len[1] * len[2];
    }

    // inside[i] = 1 for the owned atoms in the group whose centre lies in
    // the slab lo <= z < hi, else 0; between reneighborings an atom may be
    // up to half the skin outside a periodic box: the image of its centre
    // inside the box counts
    static void flag_slab(double **x, const int *mask, int groupbit, int nlocal, double lo,
                          double hi, bool zperiodic, double boxlo, double boxhi, double zprd,
                          double *inside)
    {
      for (int i = 0; i < nlocal; i++)
        inside[i] = in_slab(x[i][2], mask[i], groupbit, lo, hi, zperiodic, boxlo, boxhi, zprd);
    }

    // the flag of one atom at height z with mask bits mask, as above
    static GRFLOW_FUNCTION double in_slab(double z, int mask, int groupbit, double lo, double hi,
                                          bool zperiodic, double boxlo, double boxhi, double zprd)
    {
      if (zperiodic) {
        if (z < boxlo)
          z += zprd;
        else if (z >= boxhi)
          z -= zprd;
      }
      return ((mask & groupbit) && z >= lo && z < hi) ? 1.0 : 0.0;
    }
  };

  // the contacts of owned particles inside with flat walls, as a fix
  // with wall contacts recorded them on this step (WallContacts,
  // grflow_wall.h: the force-bearing ones; n is the wall's normal),
  // counted in ncontact[]; with ncontact null their stress only (the
  // stress path)
  static inline void add_wall_contacts(const WallContacts &walls, const double *inside, int nlocal,
                                       double *ncontact, double *sums)
  {
    typedef WallContacts C;
    for (int i = 0; i < nlocal; i++) {
      if (inside[i] <= 0.0) continue;
      const double *record = walls.record[i];
      for (int w = 0; w < walls.nwall; w++) {
        const double arm = record[C::REC_SIZE * w + C::REC_ARM];
        if (arm <= 0.0) continue;
        const double *force = &record[C::REC_SIZE * w + C::REC_FORCE];
        if (ncontact) {
          ncontact[i] += 1.0;
          NetworkSums::add_wall_contact(sums, walls.normal[w], force, arm);
        } else {
          NetworkSums::add_wall_stress(sums, walls.normal[w], force, arm);
        }
      }
    }
  }

  // every owned particle inside, with its ncontact[] contacts
  static inline void add_particles(const double *inside, const double *ncontact, int nlocal,
                                   int cmax, double *sums)
  {
    for (int i = 0; i < nlocal; i++)
      if (inside[i] > 0.0) NetworkSums::add_particle(sums, (int) ncontact[i], cmax);
  }

  /* ----------------------------------------------------------------------
     the output vector (NetworkLayout) from the sums over all processors
     and the volume of the sub-volume; tau = -(s_ab + s_ba)/2 of the axes
     tau_a, tau_b; r_u = 1 - p/p0 if p0 > 0, else 0.  derive_stress()
     gives the first NSTRESS entries from the stress sums alone,
     derive_network() all of them; the entries both give are the same to
     the bit.
  ------------------------------------------------------------------------- */

  // the stress sigma_ab = sum l_a f_b / V of the sums, its mean p and its
  // symmetric deviatoric part sym; returns sym:sym
  static inline double network_stress(const double *total, double volume, double s[3][3], double &p,
                                      double sym[3][3])
  {
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) s[a][b] = total[NetworkSums::STRESS + 3 * a + b] / volume;
    p = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
    double ss = 0.0;
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) {
        sym[a][b] = 0.5 * (s[a][b] + s[b][a]) - (a == b ? p : 0.0);    // deviatoric
        ss += sym[a][b] * sym[a][b];
      }
    return ss;
  }

  static inline void derive_stress(const double *total, double volume, int tau_a, int tau_b,
                                   double p0, double *vector)
  {
    typedef NetworkLayout L;
    double s[3][3], sym[3][3], p;
    const double ss = network_stress(total, volume, s, p, sym);

    // stress: LAMMPS order and convention (compression positive,
    // sigma_ab = sum l_a f_b / V); derived values use the symmetric part

    vector[L::SXX] = s[0][0];
    vector[L::SYY] = s[1][1];
    vector[L::SZZ] = s[2][2];
    vector[L::SXY] = s[0][1];
    vector[L::SXZ] = s[0][2];
    vector[L::SYZ] = s[1][2];
    vector[L::PRESS] = p;
    vector[L::TAU] = -0.5 * (s[tau_a][tau_b] + s[tau_b][tau_a]);
    vector[L::QDEV] = sqrt(1.5 * ss);
    vector[L::SNORM] = sqrt(ss);
    vector[L::RU] = pore_pressure_ratio(p, p0);
  }

  static inline void derive_network(const double *total, double volume, int tau_a, int tau_b,
                                    int cmax, double p0, double *vector)
  {
    typedef NetworkSums S;
    typedef NetworkLayout L;
    derive_stress(total, volume, tau_a, tau_b, p0, vector);
    double s[3][3], sym[3][3], p, fabric[3][3];
    const double ss = network_stress(total, volume, s, p, sym);
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) fabric[a][b] = total[S::FABRIC + 3 * a + b];
    const double np = total[S::NP], nfloat = total[S::FLOAT], csum = total[S::ENDS];

    // contacts

    vector[L::NP] = np;
    vector[L::NFLOAT] = nfloat;
    vector[L::NCONTACT] = 0.5 * csum;
    vector[L::ZG] = (np - nfloat > 0.0) ? csum / (np - nfloat) : 0.0;
    vector[L::ZPLAIN] = (np > 0.0) ? csum / np : 0.0;

    // fabric F = <n n> over contact ends, a = 15/2 dev F,
    // a_c = sign(a:s) sqrt(3/2 a:a)

    double an[3][3], aa = 0.0, as = 0.0;
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) {
        const double fn = (csum > 0.0) ? fabric[a][b] / csum : 0.0;
        an[a][b] = (csum > 0.0) ? 7.5 * (fn - (a == b ? 1.0 / 3.0 : 0.0)) : 0.0;
      }
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) {
        aa += an[a][b] * an[a][b];
        as += an[a][b] * sym[a][b];
      }
    const double sc = (aa > 0.0 && ss > 0.0) ? as / (sqrt(aa) * sqrt(ss)) : 0.0;
    vector[L::SC] = sc;
    vector[L::AC] = (sc < 0.0 ? -1.0 : 1.0) * sqrt(1.5 * aa);
    vector[L::AXX] = an[0][0];
    vector[L::AYY] = an[1][1];
    vector[L::AZZ] = an[2][2];
    vector[L::AXY] = an[0][1];
    vector[L::AXZ] = an[0][2];
    vector[L::AYZ] = an[1][2];
    vector[L::VOLUME] = volume;
    for (int c = 0; c <= cmax; c++) vector[L::PC0 + c] = (np > 0.0) ? total[S::HIST + c] / np : 0.0;
  }

  // the sums of all processors, then derive_network() or, with network
  // false, derive_stress() (vector then needs NSTRESS entries only).  Both
  // add up the whole array (the stress path's has zeros beyond the
  // stress), so that the stress sums are added in the same order.
  inline void NetworkOptions::reduce_and_derive(MPI_Comm world, const std::vector<double> &local,
                                                double volume, double *vector, bool network)
  {
    std::vector<double> total(local.size());
    MPI_Allreduce(local.data(), total.data(), (int) local.size(), MPI_DOUBLE, MPI_SUM, world);
    const double p0_ru = reference_p0();
    if (network)
      derive_network(total.data(), volume, tau_a, tau_b, cmax, p0_ru, vector);
    else
      derive_stress(total.data(), volume, tau_a, tau_b, p0_ru, vector);
    if (p0first && !p0flag && vector[NetworkLayout::PRESS] > 0.0) {
      p0 = vector[NetworkLayout::PRESS];
      p0flag = true;
      vector[NetworkLayout::RU] = pore_pressure_ratio(vector[NetworkLayout::PRESS], p0);
    }
  }

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
