// clang-format off
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
// clang-format on

/* ----------------------------------------------------------------------
   Contributing authors: GRFLOW developers

   grflow_host_api.h for LAMMPS: what GRFLOW's commands need from their
   host, the LAMMPS way.  (GRFLOW's LIGGGHTS build compiles its own
   definitions instead, src/LIGGGHTS/grflow_host_liggghts.cpp.)
------------------------------------------------------------------------- */

#include "grflow_host_api.h"

#include "grflow_contact_coeffs.h"
#include "grflow_host.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "input.h"
#include "modify.h"
#include "neigh_list.h"
#include "pair.h"
#include "timer.h"
#include "variable.h"

#include <cmath>

using namespace LAMMPS_NS;
using GRFLOW::FixHost;

/* ----------------------------------------------------------------------
   numbers and errors; a value that is not a number stops with the
   parameter's name, not only with the word that was found
------------------------------------------------------------------------- */

double FixHost::number(const char *file, int line, const char *str, const std::string &what) const
{
  if (!utils::is_double(str))
    lmp->error->all(file, line, what + " expects a number, got '" + std::string(str) + "'");
  return utils::numeric(file, line, str, false, lmp);
}

int FixHost::integer(const char *file, int line, const char *str, const std::string &what) const
{
  if (!utils::is_integer(str))
    lmp->error->all(file, line, what + " expects an integer, got '" + std::string(str) + "'");
  return utils::inumeric(file, line, str, false, lmp);
}

bool FixHost::logical(const char *file, int line, const char *str,
                      const std::string & /*what*/) const
{
  return utils::logical(file, line, str, false, lmp) != 0;
}

void FixHost::missing(const char *file, int line, const std::string &cmd) const
{
  utils::missing_cmd_args(file, line, cmd, lmp->error);
}

void FixHost::fail(const char *file, int line, const std::string &message) const
{
  lmp->error->all(file, line, message);
}

void FixHost::warning(const char *file, int line, const std::string &message) const
{
  if (lmp->comm->me == 0) lmp->error->warning(file, line, message);
}

std::string FixHost::text(double value) const
{
  return fmt::format("{}", value);
}

/* ---------------------------------------------------------------------- */

void GRFLOW::write_restart_values(LAMMPS *lmp, FILE *fp, int version, const double *values, int n)
{
  if (lmp->comm->me == 0) write_restart_block(fp, version, values, n);
}

const double *GRFLOW::read_restart_values(LAMMPS *lmp, const std::string &who, const char *buf,
                                          int current, int count, int &version)
{
  FixHost host{lmp};
  return read_restart_block(who, buf, current, count, version, host);
}

bool GRFLOW::restart_keeps_time()
{
  return true;
}

/* ---------------------------------------------------------------------- */

bool GRFLOW::can_end_run()
{
  return true;
}

void GRFLOW::end_run(LAMMPS *lmp)
{
  lmp->timer->force_timeout();
  // as fix halt, whose check clears the computes' invoked flags: a
  // variable evaluated after the run recomputes a compute on this last
  // step instead of taking the value of its last thermo output
  lmp->modify->clearstep_compute();
}

void GRFLOW::run_may_continue(LAMMPS *lmp)
{
  lmp->timer->reset_timeout();
}

/* ---------------------------------------------------------------------- */

Fix *GRFLOW::fix_by_id(LAMMPS *lmp, const std::string &id)
{
  return lmp->modify->get_fix_by_id(id);
}

Compute *GRFLOW::compute_by_id(LAMMPS *lmp, const std::string &id)
{
  return lmp->modify->get_compute_by_id(id);
}

Region *GRFLOW::region_by_id(LAMMPS *lmp, const std::string &id)
{
  return lmp->domain->get_region_by_id(id);
}

int GRFLOW::variable_index(LAMMPS *lmp, const std::string &name)
{
  return lmp->input->variable->find(name.c_str());
}

std::vector<Fix *> GRFLOW::all_fixes(LAMMPS *lmp)
{
  return lmp->modify->get_fix_list();
}

Compute *GRFLOW::add_compute(LAMMPS *lmp, const std::string &command)
{
  return lmp->modify->add_compute(command);
}

void GRFLOW::delete_compute(LAMMPS *lmp, const std::string &id)
{
  lmp->modify->delete_compute(id);
}

/* ---------------------------------------------------------------------- */

int GRFLOW::pair_normal_law(LAMMPS *lmp)
{
  Pair *pair = lmp->force->pair_match("^granular/grflow", 0);
  if (!pair) return -1;
  int dim = -1;
  const int *law = static_cast<const int *>(pair->extract("normal_force", dim));
  return (law && dim == 0) ? *law : -1;
}

bool GRFLOW::pair_tallies_energy(LAMMPS * /*lmp*/)
{
  return true;
}

bool GRFLOW::radii_may_change(LAMMPS *lmp)
{
  return !lmp->modify->get_fix_by_style("^adapt").empty();
}

/* ---------------------------------------------------------------------- */

void GRFLOW::declare_virial(Fix *fix)
{
  fix->energy_global_flag = 0;
  fix->virial_global_flag = fix->virial_peratom_flag = 1;
  fix->thermo_virial = 1;
}

int GRFLOW::host_modify_param(LAMMPS * /*lmp*/, Fix * /*fix*/, int /*narg*/, char ** /*arg*/)
{
  return 0;    // fix_modify virial: Fix::modify_params() reads it
}

void GRFLOW::declare_box_change_xy(Fix *fix)
{
  fix->box_change |= Fix::BOX_CHANGE_X | Fix::BOX_CHANGE_Y;
}

/* ---------------------------------------------------------------------- */

void GRFLOW::log_text(LAMMPS *lmp, const std::string &text)
{
  if (lmp->comm->me == 0) utils::logmesg(lmp, text);
}

double GRFLOW::walltime()
{
  return platform::walltime();
}

/* ----------------------------------------------------------------------
   the pair style's contacts: Pair::single() of any granular pair style
   that gives the sliding force in svector[0-2] (granular/grflow,
   granular, gran/*); F_n/r in fforce
------------------------------------------------------------------------- */

void GRFLOW::PairContacts::check(LAMMPS *lmp, const std::string &caller)
{
  Pair *pair = lmp->force->pair;
  if (!pair) lmp->error->all(FLERR, caller + " requires a pair style");
  if (!pair->single_enable || !pair->finitecutflag || !pair->svector || pair->single_extra < 3)
    lmp->error->all(FLERR,
                    caller +
                        " requires a granular pair style with single() giving the sliding force "
                        "in svector[0-2] (granular/grflow, granular, gran/*), not " +
                        std::string(lmp->force->pair_style));
}

void GRFLOW::PairContacts::require_list(LAMMPS *lmp, const std::string &caller)
{
  NeighList *list = lmp->force->pair->list;
  if (!list || !list->numneigh)
    lmp->error->all(FLERR,
                    caller +
                        " needs the pair style's neighbor list: use it after a run (run 0 will "
                        "do)");
}

GRFLOW::PairContacts::PairContacts(LAMMPS *lmp) : lmp(lmp), law(nullptr) {}

double GRFLOW::PairContacts::factor(int jentry) const
{
  return lmp->force->special_lj[(jentry >> SBBITS) & 3];    // Pair::sbmask()
}

bool GRFLOW::PairContacts::contact(int i, int j, int /*jj*/, const double *del, double rsq,
                                   double factor, double *n, double *f, double &delta)
{
  Pair *pair = lmp->force->pair;
  const int *type = lmp->atom->type;
  double fpair = 0.0;
  pair->single(i, j, type[i], type[j], rsq, 1.0, factor, fpair);
  if (fpair <= 0.0) return false;

  const double r = sqrt(rsq);
  const double *svector = pair->svector;
  for (int k = 0; k < 3; k++) {
    n[k] = del[k] / r;
    f[k] = fpair * del[k] + svector[k];
  }
  delta = lmp->atom->radius[i] + lmp->atom->radius[j] - r;
  return true;
}
