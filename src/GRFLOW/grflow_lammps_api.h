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
   The differences of the LAMMPS API that GRFLOW meets, in one place.

   Pair::atom2cut() and Pair::radii2cut(): virtual in LAMMPS 4Feb2025
   (the per-atom cutoffs of finite-size particles for "neighbor multi"),
   gone in 4Jul2026 (the neighbor code uses the radii itself).
   GRFLOW_PAIR_HAS_ATOM2CUT is 1 where they exist.  The GRFLOW builds set
   it from the LAMMPS tree's pair.h (cmake/GRFLOWCompileSettings.cmake); otherwise it is inferred from a header that 4Jul2026 has and
   4Feb2025 does not (nbin_manual.h), which is right for those two
   versions.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_LAMMPS_API_H
#define LMP_GRFLOW_LAMMPS_API_H

#ifndef GRFLOW_PAIR_HAS_ATOM2CUT
#if defined(__has_include)
#if __has_include("nbin_manual.h")
#define GRFLOW_PAIR_HAS_ATOM2CUT 0
#else
#define GRFLOW_PAIR_HAS_ATOM2CUT 1
#endif
#else
#define GRFLOW_PAIR_HAS_ATOM2CUT 1
#endif
#endif

#endif
