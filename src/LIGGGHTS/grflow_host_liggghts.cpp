/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: grflow_host_api.h (src/GRFLOW of GRFLOW) for
   LIGGGHTS, what GRFLOW's commands need from their host, the LIGGGHTS
   way.  The commands themselves (fix grflow/wall, fix grflow/shear, fix
   grflow/compress, compute grflow/network) are LAMMPS's classes,
   compiled here unchanged; the LAMMPS API they use that belongs to
   LIGGGHTS's base classes is added by liggghts/patches/0005.

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).
------------------------------------------------------------------------- */

#include "grflow_host_api.h"

#include "grflow_contact.h"
#include "grflow_host.h"
#include "grflow_liggghts.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "input.h"
#include "modify.h"
#include "neigh_list.h"
#include "pair_gran.h"
#include "update.h"
#include "variable.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <mpi.h>
#include <vector>

using namespace LAMMPS_NS;
using GRFLOW::FixHost;

/* ----------------------------------------------------------------------
   numbers as LAMMPS reads them: a decimal number, [+-]digits[.digits]
   [(e|E)[+-]digits]; an integer, [+-]digits; a boolean, yes/no, on/off,
   true/false, 1/0.  A wrong one stops with the parameter's name
   (LIGGGHTS's force->numeric() does not name it).
------------------------------------------------------------------------- */

static bool digit(char c)
{
  return c >= '0' && c <= '9';
}

double FixHost::number(const char *file, int line, const char *str, const std::string &what) const
{
  const char *c = str;
  if (*c == '+' || *c == '-') c++;
  int ndigit = 0;
  for (; digit(*c); c++) ndigit++;
  if (*c == '.') c++;
  for (; digit(*c); c++) ndigit++;
  if (ndigit > 0 && (*c == 'e' || *c == 'E')) {
    c++;
    if (*c == '+' || *c == '-') c++;
    if (!digit(*c)) ndigit = 0;
    while (digit(*c)) c++;
  }
  errno = 0;
  const double value = (ndigit > 0 && *c == '\0') ? strtod(str, NULL) : 0.0;
  if (ndigit == 0 || *c != '\0' || errno == ERANGE)
    fail(file, line, what + " expects a number, got '" + str + "'");
  return value;
}

int FixHost::integer(const char *file, int line, const char *str, const std::string &what) const
{
  const char *c = str;
  if (*c == '+' || *c == '-') c++;
  const bool some = digit(*c);
  while (digit(*c)) c++;
  errno = 0;
  const long value = (some && *c == '\0') ? strtol(str, NULL, 10) : 0;
  if (!some || *c != '\0' || errno == ERANGE || value < INT_MIN || value > INT_MAX)
    fail(file, line, what + " expects an integer, got '" + str + "'");
  return static_cast<int>(value);
}

bool FixHost::logical(const char *file, int line, const char *str, const std::string &what) const
{
  const std::string s = str;
  if (s == "yes" || s == "on" || s == "true" || s == "1") return true;
  if (s != "no" && s != "off" && s != "false" && s != "0")
    fail(file, line, what + " expects yes or no, got '" + s + "'");
  return false;
}

void FixHost::missing(const char *file, int line, const std::string &cmd) const
{
  fail(file, line, "Illegal " + cmd + " command: missing argument(s)");
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
  return format_number(value);
}

/* ---------------------------------------------------------------------- */

void GRFLOW::write_restart_values(LAMMPS *lmp, FILE *fp, int version, const double *values, int n)
{
  if (lmp->comm->me == 0) write_restart_block(fp, version, values, n);
}

const double *GRFLOW::read_restart_values(LAMMPS *lmp, const std::string &who, const char *buf,
                                          int current, int count, int &version)
{
  FixHost host = {lmp};
  return read_restart_block(who, buf, current, count, version, host);
}

bool GRFLOW::restart_keeps_time()
{
  return false;
}

/* ----------------------------------------------------------------------
   LIGGGHTS 3.8's run loop has no early end (its timer has no timeout):
   the LIGGGHTS decks run fixed segments instead
------------------------------------------------------------------------- */

bool GRFLOW::can_end_run()
{
  return false;
}

void GRFLOW::end_run(LAMMPS *) {}

void GRFLOW::run_may_continue(LAMMPS *) {}

/* ---------------------------------------------------------------------- */

Fix *GRFLOW::fix_by_id(LAMMPS *lmp, const std::string &id)
{
  const int ifix = lmp->modify->find_fix(id.c_str());
  return ifix < 0 ? NULL : lmp->modify->fix[ifix];
}

Compute *GRFLOW::compute_by_id(LAMMPS *lmp, const std::string &id)
{
  const int icompute = lmp->modify->find_compute(id.c_str());
  return icompute < 0 ? NULL : lmp->modify->compute[icompute];
}

Region *GRFLOW::region_by_id(LAMMPS *lmp, const std::string &id)
{
  const int iregion = lmp->domain->find_region(id.c_str());
  return iregion < 0 ? NULL : lmp->domain->regions[iregion];
}

int GRFLOW::variable_index(LAMMPS *lmp, const std::string &name)
{
  // Variable::find() takes a char * but only reads it
  return lmp->input->variable->find(const_cast<char *>(name.c_str()));
}

std::vector<Fix *> GRFLOW::all_fixes(LAMMPS *lmp)
{
  return std::vector<Fix *>(lmp->modify->fix, lmp->modify->fix + lmp->modify->nfix);
}

Compute *GRFLOW::add_compute(LAMMPS *lmp, const std::string &command)
{
  // LIGGGHTS's add_compute() takes the words
  std::vector<std::string> words;
  std::string word;
  for (char c : command + " ") {
    if (c != ' ') {
      word += c;
    } else if (!word.empty()) {
      words.push_back(word);
      word.clear();
    }
  }
  std::vector<char *> argv;
  for (std::string &w : words) argv.push_back(&w[0]);
  lmp->modify->add_compute((int) argv.size(), argv.data());
  return compute_by_id(lmp, words[0]);
}

void GRFLOW::delete_compute(LAMMPS *lmp, const std::string &id)
{
  lmp->modify->delete_compute(id.c_str());
}

/* ---------------------------------------------------------------------- */

// the law of pair_style gran model grflow, as the model published it
int GRFLOW::pair_normal_law(LAMMPS *lmp)
{
  std::map<const LAMMPS *, LiggghtsPairLaw> &laws = liggghts_pair_laws();
  if (!lmp->force->pair || !laws.count(lmp) || laws[lmp].coeff->empty()) return -1;
  const LiggghtsPairLaw &law = laws[lmp];
  return (*law.coeff)[law.ntypes + 2].normal_law;    // types 1 1
}

// pair_style gran tallies no potential energy
bool GRFLOW::pair_tallies_energy(LAMMPS *lmp)
{
  return !(lmp->force->pair_style && strcmp(lmp->force->pair_style, "gran") == 0);
}

bool GRFLOW::radii_may_change(LAMMPS *lmp)
{
  for (int k = 0; k < lmp->modify->nfix; k++)
    if (lmp->modify->fix[k]->rad_mass_vary_flag) return true;
  return false;
}

/* ---------------------------------------------------------------------- */

void GRFLOW::declare_virial(Fix *fix)
{
  fix->virial_flag = 1;
}

// fix_modify virial yes|no: LIGGGHTS's Fix::modify_params() does not read it
int GRFLOW::host_modify_param(LAMMPS *lmp, Fix *fix, int narg, char **arg)
{
  if (strcmp(arg[0], "virial") != 0) return 0;
  FixHost host = {lmp};
  const std::string what = std::string("fix_modify ") + fix->id + " virial";
  if (narg < 2) host.missing(FLERR, what);
  if (strcmp(arg[1], "yes") == 0)
    fix->virial_flag = 1;
  else if (strcmp(arg[1], "no") == 0)
    fix->virial_flag = 0;
  else
    host.fail(FLERR, what + ": expected yes or no, got " + arg[1]);
  return 2;
}

void GRFLOW::declare_box_change_xy(Fix *fix)
{
  fix->box_change_size = 1;
}

/* ---------------------------------------------------------------------- */

void GRFLOW::log_text(LAMMPS *lmp, const std::string &text)
{
  if (lmp->comm->me != 0) return;
  if (lmp->screen) fputs(text.c_str(), lmp->screen);
  if (lmp->logfile) fputs(text.c_str(), lmp->logfile);
}

double GRFLOW::walltime()
{
  return MPI_Wtime();
}

/* ----------------------------------------------------------------------
   the contacts of pair_style gran model grflow: the force of each
   touching pair from the kernel and the springs stored in the pair's
   contact history (not advanced, as LAMMPS's Pair::single() does), with
   the coefficients the model published (grflow_liggghts.h)
------------------------------------------------------------------------- */

void GRFLOW::PairContacts::check(LAMMPS *lmp, const std::string &caller)
{
  if (!lmp->force->pair || !liggghts_pair_laws().count(lmp) ||
      !dynamic_cast<PairGran *>(lmp->force->pair))
    lmp->error->all(FLERR,
                    caller +
                        " requires pair_style gran model grflow (its contact forces come from "
                        "GRFLOW's contact law)");
}

void GRFLOW::PairContacts::require_list(LAMMPS *lmp, const std::string &caller)
{
  NeighList *list = lmp->force->pair->list;
  if (!list || !list->numneigh || !lmp->force->pair->listgranhistory)
    lmp->error->all(FLERR,
                    caller +
                        " needs the pair style's neighbor list: use it after a run (run 0 will "
                        "do)");
}

GRFLOW::PairContacts::PairContacts(LAMMPS *lmp) : lmp(lmp), law(&liggghts_pair_laws()[lmp]) {}

// granular particles carry no special bonds
double GRFLOW::PairContacts::factor(int /*jentry*/) const
{
  return 1.0;
}

bool GRFLOW::PairContacts::contact(int i, int j, int jj, const double *del, double rsq,
                                   double /*factor*/, double *n, double *f, double &delta)
{
  const LiggghtsPairLaw &pair_law = *static_cast<const LiggghtsPairLaw *>(law);
  PairGran *pair = static_cast<PairGran *>(lmp->force->pair);
  double **v = lmp->atom->v, **omega = lmp->atom->omega;
  const double *radius = lmp->atom->radius;
  const int *type = lmp->atom->type;

  ContactGeometry g;
  pair_geometry(del, sqrt(rsq), radius[i], radius[j], false, g);
  const double vrel[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
  double hist[HIST_SIZE];
  double *stored =
      &pair->listgranhistory->firstdouble[i][pair->dnum() * jj + pair_law.history_offset];
  current_springs(stored, static_cast<double>(lmp->update->ntimestep), false, hist);
  ContactForces out;
  contact_forces((*pair_law.coeff)[type[i] * (pair_law.ntypes + 1) + type[j]], g, vrel, omega[i],
                 omega[j], lmp->update->dt, false, hist, out);
  if (out.fn <= 0.0) return false;
  for (int k = 0; k < 3; k++) {
    n[k] = g.n[k];
    f[k] = out.f[k];
  }
  delta = g.delta;
  return true;
}
