# GRFLOW analysis: read the files of a run directory written by the GRFLOW
# decks.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""The readers of a GRFLOW run directory.

The run directory format is that of ``inputs/README.md``: ``prep.json``,
``series.txt`` (36 named columns), ``events.txt`` (the cycle events of fix
grflow/shear), ``snapshots/atoms.*.txt`` (dump custom) and
``snapshots/contacts.*.txt`` (dump local); ``shear.json`` is the shear
stage's record (inputs/shear_record.sh).  A file that does not follow it
raises :class:`FormatError`.  Also here: the column names of the series
(SERIES_COLUMNS) and the settings the shear stage ran with
(:func:`stage_values`, :func:`protocol`).
"""

import json
import math
import os
import re
import warnings

import numpy as np

SERIES_COLUMNS = tuple(
    "step time reversals direction x_w gamma tau p r_u z_g a_c N_c N_p "
    "floaters sxx syy szz sxy sxz syz zlo zhi inertial".split()
    + ["P%d" % c for c in range(13)])
REQUIRED_COLUMNS = ("step", "time", "reversals", "gamma", "tau", "p", "r_u",
                    "z_g", "a_c")
PC_COLUMNS = tuple("P%d" % c for c in range(13))
DEFAULT_RU_LIQ = 0.99
DEFAULT_TAU_AMP = 25.0e3


class FormatError(ValueError):
    """A run-directory file that does not follow inputs/README.md."""


def _canonical(name):
    """Column name as in SERIES_COLUMNS (tolerates TimeStep, v_/c_/f_ prefixes)."""
    if name.lower() == "timestep":
        return "step"
    for prefix in ("v_", "c_", "f_"):
        if name.startswith(prefix) and name[2:] in SERIES_COLUMNS:
            return name[2:]
    return name


def read_series(path):
    """Read ``series.txt``; return a dict of float arrays keyed by column name.

    The column names are those of the last ``#`` comment line before the
    first data row; if there is none (or it does not have as many names as
    the rows have fields) and the rows have 36 fields, the documented order
    SERIES_COLUMNS is assumed.  Comment lines later in the file are skipped.
    Should the steps not increase strictly (a resumed run that repeated
    rows), a repeated step replaces the rows it overlaps, with a warning.
    Raises FileNotFoundError, or FormatError when the file is malformed
    (no data, ragged or non-numeric rows, missing required columns).
    """
    header = None
    nfields = None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                header = s.lstrip("#").split()
                continue
            nfields = len(s.split())
            break
    if nfields is None:
        raise FormatError("%s: no data rows" % path)
    if header is None or len(header) != nfields:
        if nfields == len(SERIES_COLUMNS):
            header = list(SERIES_COLUMNS)
        else:
            raise FormatError("%s: the column names (last '#' line before the data) "
                              "do not match the %d fields of the first row"
                              % (path, nfields))
    names = [_canonical(h) for h in header]
    if len(set(names)) != len(names):
        raise FormatError("%s: repeated column names in %s" % (path, " ".join(header)))
    missing = [c for c in REQUIRED_COLUMNS if c not in names]
    if missing:
        raise FormatError("%s: missing column(s) %s" % (path, ", ".join(missing)))
    data = _load_rows(path, len(names))
    if data.shape[1] != len(names):
        raise FormatError("%s: rows have %d fields, %d columns are named"
                          % (path, data.shape[1], len(names)))
    data = _drop_repeated_steps(data, names.index("step"), path)
    return {n: data[:, i].copy() for i, n in enumerate(names)}


EVENT_COLUMNS = ("step", "time", "event", "reversals", "N", "N_IL", "step_IL")


def read_events(path):
    """Read ``events.txt`` (inputs/README.md): a dict of arrays keyed by
    EVENT_COLUMNS.  Raises FileNotFoundError, or FormatError for a file that
    does not have those 7 columns, a first line other than the start (event
    0, N = 0), or steps that decrease."""
    data = _load_rows(path, len(EVENT_COLUMNS))
    if data.shape[0] == 0:
        raise FormatError("%s: no data rows" % path)
    if data.shape[1] != len(EVENT_COLUMNS):
        raise FormatError("%s: rows have %d fields, expected %d (%s)"
                          % (path, data.shape[1], len(EVENT_COLUMNS), " ".join(EVENT_COLUMNS)))
    ev = {n: data[:, i].copy() for i, n in enumerate(EVENT_COLUMNS)}
    if ev["event"][0] != 0 or ev["N"][0] != 0:
        raise FormatError("%s: the first line is not the start of shearing (event 0, N 0)" % path)
    if np.any(np.diff(ev["step"]) < 0) or not np.all(np.isin(ev["event"][1:], (1, 2))):
        raise FormatError("%s: steps decrease, or an event kind other than 1 or 2" % path)
    return ev


def _load_rows(path, ncol):
    """The numeric rows of a whitespace table with '#' comments, as a 2-d
    array; FormatError naming the first bad line (ncol fields expected)."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return np.loadtxt(path, comments="#", ndmin=2, dtype=float)
    except ValueError:
        _locate_bad_row(path, ncol)
        raise FormatError("%s: unreadable data rows" % path)


def _locate_bad_row(path, ncol):
    """Raise FormatError naming the first ragged or non-numeric data line."""
    with open(path) as f:
        for lineno, line in enumerate(f, 1):
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            fields = s.split()
            if len(fields) != ncol:
                raise FormatError("%s:%d: %d fields, expected %d"
                                  % (path, lineno, len(fields), ncol))
            try:
                [float(x) for x in fields]
            except ValueError:
                raise FormatError("%s:%d: non-numeric field" % (path, lineno))


def _drop_repeated_steps(data, col, path):
    steps = data[:, col]
    if len(steps) < 2 or np.all(np.diff(steps) > 0):
        return data
    warnings.warn("%s: steps do not increase strictly; later rows replace "
                  "earlier rows from the same step on" % path)
    keep = []
    for i, s in enumerate(steps):
        while keep and steps[keep[-1]] >= s:
            keep.pop()
        keep.append(i)
    return data[keep]


def read_prep(path):
    """Read ``prep.json`` into a dict (FileNotFoundError, or FormatError if not a JSON object)."""
    with open(path) as f:
        try:
            prep = json.load(f)
        except ValueError as err:
            raise FormatError("%s: %s" % (path, err))
    if not isinstance(prep, dict):
        raise FormatError("%s: not a JSON object" % path)
    return prep


def read_shear_record(run_dir):
    """The shear stage's settings, ``shear.json`` of run_dir, as a dict
    (written by the decks when the stage starts: inputs/shear_record.sh);
    None when the run has none (a run from before the decks wrote it);
    FormatError if it is not a JSON object."""
    path = os.path.join(run_dir, "shear.json")
    if not os.path.exists(path):
        return None
    return read_prep(path)


def stage_values(prep, shear=None):
    """prep.json's values (``prep``, None if unavailable) with the shear
    stage's own ru_liq and tau_amp from its record shear.json (``shear``)
    where it has them: the values the shear stage ran with."""
    out = dict(prep or {})
    out.update({k: v for k, v in (shear or {}).items() if k in ("ru_liq", "tau_amp")})
    return out


def protocol(prep, shear=None):
    """(ru_liq, tau_amp) of the shear stage (:func:`stage_values`),
    defaulting to 0.99 and 25e3 Pa."""
    values = stage_values(prep, shear)
    ru_liq = values.get("ru_liq")
    tau_amp = values.get("tau_amp")
    ru_liq = float(ru_liq) if _is_number(ru_liq) and ru_liq > 0 else DEFAULT_RU_LIQ
    tau_amp = float(tau_amp) if _is_number(tau_amp) and tau_amp > 0 else DEFAULT_TAU_AMP
    return ru_liq, tau_amp


def _is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def read_dump(path):
    """Read the first frame of a LAMMPS text dump (custom or local).

    Returns a dict: ``step`` (int), ``box`` (3x2 array of lo/hi; for a
    triclinic box the first two numbers of each line), ``item`` ("ATOMS" or
    "ENTRIES") and ``columns`` (dict of float arrays by column name; a column
    named with a LAMMPS prefix, e.g. ``v_glue``, is also under its bare
    name, ``glue``).
    Raises FormatError if the file does not follow the dump format.
    """
    with open(path) as f:
        lines = f.read().splitlines()
    step = count = box = None
    i = 0
    while i < len(lines):
        line = lines[i].strip()
        i += 1
        if not line.startswith("ITEM:"):
            if line:
                raise FormatError("%s:%d: expected an ITEM line" % (path, i))
            continue
        item = line[5:].strip()
        try:
            if item == "TIMESTEP":
                step = int(lines[i].split()[0])
                i += 1
            elif item.startswith("NUMBER OF"):
                count = int(lines[i].split()[0])
                i += 1
            elif item.startswith("BOX BOUNDS"):
                box = np.array([[float(v) for v in lines[i + k].split()[:2]]
                                for k in range(3)])
                i += 3
            elif item.split()[0] in ("ATOMS", "ENTRIES"):
                kind, names = item.split()[0], item.split()[1:]
                if count is None:
                    raise FormatError("%s: no NUMBER OF %s before the data" % (path, kind))
                rows = lines[i:i + count]
                if len(rows) < count:
                    raise FormatError("%s: %d %s announced, %d present"
                                      % (path, count, kind.lower(), len(rows)))
                if count:
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        data = np.loadtxt(rows, ndmin=2, dtype=float)
                else:
                    data = np.zeros((0, len(names)))
                if data.shape[1] != len(names):
                    raise FormatError("%s: %d fields per %s line, %d named"
                                      % (path, data.shape[1], kind.lower(), len(names)))
                cols = {n: data[:, k].copy() for k, n in enumerate(names)}
                for n in names:         # v_glue, c_id etc. also under their bare name
                    if n[:2] in ("v_", "c_", "f_", "i_", "d_") and n[2:] not in cols:
                        cols[n[2:]] = cols[n]
                return {"step": step, "box": box, "item": kind, "columns": cols}
        except (IndexError, ValueError) as err:
            if isinstance(err, FormatError):
                raise
            raise FormatError("%s:%d: malformed %s section (%s)" % (path, i, item, err))
    raise FormatError("%s: no ATOMS or ENTRIES section" % path)


def read_dump_atoms(path):
    """Read ``snapshots/atoms.*.txt``; columns id, radius, x, y, z, glue required."""
    d = read_dump(path)
    need = ("id", "radius", "x", "y", "z", "glue")
    if d["item"] != "ATOMS" or any(n not in d["columns"] for n in need):
        raise FormatError("%s: expected ITEM: ATOMS with %s" % (path, " ".join(need)))
    return d


def read_dump_local(path):
    """Read ``snapshots/contacts.*.txt``; columns id1, id2, dx, dy, dz, fn required."""
    d = read_dump(path)
    need = ("id1", "id2", "dx", "dy", "dz", "fn")
    if d["item"] != "ENTRIES" or any(n not in d["columns"] for n in need):
        raise FormatError("%s: expected ITEM: ENTRIES with %s" % (path, " ".join(need)))
    return d


def list_snapshots(run_dir, kind="atoms"):
    """Shear-stage snapshot files of a run, as a sorted list of (step, path)."""
    snapdir = os.path.join(run_dir, "snapshots")
    out = []
    if os.path.isdir(snapdir):
        pat = re.compile(r"^%s\.(\d+)\.txt$" % kind)
        for name in os.listdir(snapdir):
            m = pat.match(name)
            if m:
                out.append((int(m.group(1)), os.path.join(snapdir, name)))
    return sorted(out)
