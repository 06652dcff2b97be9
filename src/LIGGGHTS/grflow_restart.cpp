/* ----------------------------------------------------------------------
   GRFLOW for LIGGGHTS 3.8: the LIGGGHTS side of the GRFLOW fixes'
   host-free code (grflow_restart.h).

   LIGGGHTS is open-source, distributed under the terms of the GNU Public
   License, version 2 or later; so is this file (GPL-2.0, as GRFLOW).
------------------------------------------------------------------------- */

#include "grflow_restart.h"

#include "grflow_network.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"

#include <cerrno>
#include <climits>
#include <cstdlib>

using namespace LAMMPS_NS;
using GRFLOW::FixHost;

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

void GRFLOW::log_text(LAMMPS *lmp, const std::string &text)
{
  if (lmp->comm->me != 0) return;
  if (lmp->screen) fputs(text.c_str(), lmp->screen);
  if (lmp->logfile) fputs(text.c_str(), lmp->logfile);
}

/* ----------------------------------------------------------------------
   numbers as LAMMPS reads them: a decimal number, [+-]digits[.digits]
   [(e|E)[+-]digits]; an integer, [+-]digits; a boolean, yes/no, on/off,
   true/false, 1/0.  A wrong one stops with the parameter's name.
------------------------------------------------------------------------- */

static bool digit(char c)
{
  return c >= '0' && c <= '9';
}

double FixHost::number(const char *str, const std::string &what) const
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
    fail(what + " expects a number, got '" + str + "'");
  return value;
}

int FixHost::integer(const char *str, const std::string &what) const
{
  const char *c = str;
  if (*c == '+' || *c == '-') c++;
  const bool some = digit(*c);
  while (digit(*c)) c++;
  errno = 0;
  const long value = (some && *c == '\0') ? strtol(str, NULL, 10) : 0;
  if (!some || *c != '\0' || errno == ERANGE || value < INT_MIN || value > INT_MAX)
    fail(what + " expects an integer, got '" + str + "'");
  return static_cast<int>(value);
}

bool FixHost::logical(const char *str, const std::string &what) const
{
  const std::string s = str;
  if (s == "yes" || s == "on" || s == "true" || s == "1") return true;
  if (s != "no" && s != "off" && s != "false" && s != "0")
    fail(what + " expects yes or no, got '" + s + "'");
  return false;
}

void FixHost::missing(const std::string &cmd) const
{
  fail("Illegal " + cmd + " command: missing argument(s)");
}

void FixHost::fail(const std::string &message) const
{
  lmp->error->all(FLERR, message.c_str());
}

void FixHost::warning(const std::string &message) const
{
  if (lmp->comm->me == 0) lmp->error->warning(FLERR, message.c_str());
}

std::string FixHost::text(double value) const
{
  return format_number(value);
}
