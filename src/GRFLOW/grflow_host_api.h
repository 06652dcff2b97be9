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
   What GRFLOW's commands need from their host that the two hosts do not
   spell the same way: LAMMPS (grflow_host_lammps.cpp, in this package)
   and LIGGGHTS 3.8 (src/LIGGGHTS/grflow_host_liggghts.cpp of the GRFLOW
   sources, compiled into GRFLOW's LIGGGHTS build).  The classes of the
   commands (fix grflow/wall, fix grflow/shear, fix grflow/compress,
   compute grflow/network) are written once, against LAMMPS's API, and
   compiled into both hosts; where LIGGGHTS 3.8 (a 2013 LAMMPS) lacks a
   piece of that API that belongs to a base class (Error with std::string
   messages, Fix::v_init(), Atom::GROW, the Compute constructor and
   communication of LAMMPS), GRFLOW's LIGGGHTS build adds it by a patch
   (liggghts/patches); the rest is declared here, with one definition per
   host.  No host type other than forward declarations appears here.
------------------------------------------------------------------------- */

#ifndef LMP_GRFLOW_HOST_API_H
#define LMP_GRFLOW_HOST_API_H

#include <cstdio>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class Compute;
class Fix;
class LAMMPS;
class Region;

namespace GRFLOW {

  /* ----------------------------------------------------------------------
     numbers read and errors reported the host's way, for the host-free
     rules of src/shared (the Host of grflow_host.h).  Every call takes
     the file and line of its call site (FLERR), which the error names.
     A value that is not a number stops with the parameter's name (what).
  ------------------------------------------------------------------------- */

  struct FixHost {
    LAMMPS *lmp;
    double number(const char *file, int line, const char *str, const std::string &what) const;
    int integer(const char *file, int line, const char *str, const std::string &what) const;
    bool logical(const char *file, int line, const char *str, const std::string &what) const;
    void missing(const char *file, int line, const std::string &cmd) const;
    void fail(const char *file, int line, const std::string &message) const;
    void warning(const char *file, int line, const std::string &message) const;    // rank 0
    std::string text(double value) const;    // a number as the host's messages print it
  };

  /* ----------------------------------------------------------------------
     global restart data of the fixes: the block of grflow_host.h (a tag,
     the format version, the number of values, then the values), written
     on rank 0; read back with its checks (an error naming who)
  ------------------------------------------------------------------------- */

  void write_restart_values(LAMMPS *lmp, FILE *fp, int version, const double *values, int n);
  const double *read_restart_values(LAMMPS *lmp, const std::string &who, const char *buf,
                                    int current, int count, int &version);

  // LAMMPS's restart files keep the simulated time, LIGGGHTS 3.8's do not
  // (a fix that needs it appends it to its restart values)
  bool restart_keeps_time();

  /* ----------------------------------------------------------------------
     ending a run early, as LAMMPS's fix halt ... error continue does: the
     run ends after the current step, and later runs go on (end_run() in
     end_of_step, run_may_continue() in post_run); computes used after the
     run are evaluated afresh on its last step.  LIGGGHTS 3.8 has no such
     means (can_end_run() false).
  ------------------------------------------------------------------------- */

  bool can_end_run();
  void end_run(LAMMPS *lmp);
  void run_may_continue(LAMMPS *lmp);

  /* ----------------------------------------------------------------------
     commands and settings by name
  ------------------------------------------------------------------------- */

  Fix *fix_by_id(LAMMPS *lmp, const std::string &id);            // nullptr if none
  Compute *compute_by_id(LAMMPS *lmp, const std::string &id);    // nullptr if none
  Region *region_by_id(LAMMPS *lmp, const std::string &id);      // nullptr if none
  int variable_index(LAMMPS *lmp, const std::string &name);      // -1 if none
  std::vector<Fix *> all_fixes(LAMMPS *lmp);                     // in definition order
  // define "ID group style args..." / delete the compute with ID id
  Compute *add_compute(LAMMPS *lmp, const std::string &command);
  void delete_compute(LAMMPS *lmp, const std::string &id);

  // the normal force law (NORMAL_CLIPPED, NORMAL_UNCLIPPED) of the
  // particles' GRFLOW contact law, -1 if the pair style is not GRFLOW's
  int pair_normal_law(LAMMPS *lmp);
  // whether the pair style tallies its potential energy (compute pe)
  bool pair_tallies_energy(LAMMPS *lmp);
  // whether a fix may change particle radii during a run
  bool radii_may_change(LAMMPS *lmp);

  /* ----------------------------------------------------------------------
     fix flags the hosts name differently
  ------------------------------------------------------------------------- */

  // the fix adds to the global and per-atom virial (fix_modify virial)
  void declare_virial(Fix *fix);
  // fix_modify keywords the host's Fix does not read itself (LIGGGHTS:
  // virial yes|no); the number of arguments used, 0 if none
  int host_modify_param(LAMMPS *lmp, Fix *fix, int narg, char **arg);
  // the fix changes the box size in x and y
  void declare_box_change_xy(Fix *fix);

  /* ----------------------------------------------------------------------
     output
  ------------------------------------------------------------------------- */

  void log_text(LAMMPS *lmp, const std::string &text);    // screen and log, rank 0
  double walltime();                                      // seconds

  /* ----------------------------------------------------------------------
     the particle-particle contacts of the pair style, for compute
     grflow/network: the force of a listed pair with the history the pair
     style keeps, without advancing it.  LAMMPS: Pair::single() of any
     granular pair style with the sliding force in svector[0-2];
     LIGGGHTS: the GRFLOW contact model of pair gran.
  ------------------------------------------------------------------------- */

  class PairContacts {
   public:
    // the pair style can give its contacts; an error naming caller if not
    static void check(LAMMPS *lmp, const std::string &caller);
    // its neighbor list and contact history exist; an error naming caller
    // (e.g. "Compute grflow/network") if not
    static void require_list(LAMMPS *lmp, const std::string &caller);

    explicit PairContacts(LAMMPS *lmp);
    // the special-bond factor of neighbor entry jentry (0: skip the pair)
    double factor(int jentry) const;
    // the contact of neighbor jj of atom i, atom j, with del = x_i - x_j
    // and rsq = |del|^2 < (a_i + a_j)^2 (factor: that of the pair):
    // false if it carries no normal force, else n (from j to i), the
    // force f on i and the overlap delta
    bool contact(int i, int j, int jj, const double *del, double rsq, double factor, double *n,
                 double *f, double &delta);

   private:
    LAMMPS *lmp;
    const void *law;    // the host's view of the contact law
  };

}    // namespace GRFLOW
}    // namespace LAMMPS_NS

#endif
