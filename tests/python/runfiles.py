"""Reading a run directory of the decks (inputs/README.md formats) in the
tests of the LAMMPS and the LIGGGHTS decks (test_protocol.py,
test_liggghts_protocol.py): one copy of the series columns, which
test_layouts.py checks against the compiled output layouts, and of the
readers, which go through grflow_analysis (one parser of each format)."""
import warnings

import grflow_analysis as ga

COLUMNS = ("step time reversals direction x_w gamma tau p r_u z_g a_c N_c N_p floaters "
           "sxx syy szz sxy sxz syz zlo zhi inertial " +
           " ".join(f"P{c}" for c in range(13))).split()


def tail(path, n=3000):
    return path.read_text(errors="replace")[-n:] if path.exists() else ""


def read_series(path):
    """series.txt through analysis/'s reader (one parser of the format), as
    a list of rows: the columns must be the documented ones, and a repeated
    step, which that reader drops with a warning, fails the test."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        series = ga.read_series(str(path))
    assert list(series) == COLUMNS
    return [list(row) for row in zip(*(series[c].tolist() for c in COLUMNS))]


def last_complete_step(path):
    """the step of the last complete data line of a series being written
    (-1 if none yet)"""
    try:
        lines = path.read_text().splitlines(keepends=True)
    except FileNotFoundError:
        return -1
    for line in reversed(lines):
        if line.endswith("\n") and line.strip() and not line.startswith("#"):
            return float(line.split()[0])
    return -1


def read_dump(path, kind):
    """a snapshot through analysis/'s reader: (column names, rows)"""
    dump = ga.read_dump(str(path))
    assert dump["item"] == kind
    cols = list(dump["columns"])
    return cols, [list(row) for row in zip(*(dump["columns"][c].tolist() for c in cols))]


def first_leg_wall_speed(rows):
    """(h, speed): the wall gap zhi - zlo, which must be the same in every
    row (the shear stage keeps the height), and the top wall's speed
    |dx_w/dt| between the first and the last row of the first leg after
    the start (no reversal between them).  x_w and time are written with 10
    digits, so the speed is good to about 1e-8."""
    c = {k: COLUMNS.index(k) for k in ("time", "reversals", "direction", "x_w", "zlo", "zhi")}
    h = rows[0][c["zhi"]] - rows[0][c["zlo"]]
    assert all(r[c["zhi"]] - r[c["zlo"]] == h for r in rows), "the wall gap changed"
    leg = [r for r in rows[1:] if r[c["reversals"]] == rows[1][c["reversals"]]]
    a, b = leg[0], leg[-1]
    assert len(leg) >= 5 and a[c["direction"]] == b[c["direction"]], "too short a first leg"
    return h, abs(b[c["x_w"]] - a[c["x_w"]]) / (b[c["time"]] - a[c["time"]])
