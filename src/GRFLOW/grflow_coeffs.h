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
   Parsing of GRFLOW contact coefficients, shared by pair_coeff of
   pair granular/grflow and by fix grflow/wall:
     kn cn [kt v] [ct v] [mut v] [kr v] [cr v] [mur v] [ko v] [co v] [muo v]
           [rolling off] [torsion off]
   Unset keywords take the ratios of the paper's Table 1.  The names,
   defaults and rules are the host-free ones of grflow_coeff_rules.h;
   this file reads them from LAMMPS arguments and reports LAMMPS errors.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_COEFFS_H
#define LMP_GRFLOW_COEFFS_H

#include "grflow_contact_coeffs.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
namespace GRFLOW {

  // parse coefficients from arg[first]; returns the index after the last
  // one used.  An unknown keyword is an error unless stop_at_unknown.
  int parse_coeffs(LAMMPS *lmp, const std::string &cmd, int narg, char **arg, int first,
                   bool stop_at_unknown, double *value);

  // stop with an error naming the coefficient unless kn > 0 and every
  // other coefficient >= 0, all finite; where: the command or the source
  void check_coeffs(LAMMPS *lmp, const std::string &where, const double *value);

  // the value of a velocity_arm keyword: 0 for reduced (a - delta/2), 1
  // for full (the radii); an error naming cmd otherwise
  int parse_velocity_arm(LAMMPS *lmp, const std::string &cmd, const char *value);

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
