# GRFLOW analysis tests: synthetic run directories with known events.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""Tests of the package grflow_analysis (analysis/) and its command
grflow-figures.

A synthetic run directory is written in the format of inputs/README.md.
Its fractional cycle count N is built exactly (fractions) quarter by
quarter, with a different number of rows per quarter, tau = tau_amp sin(2 pi N)
(exactly 0 at the zero-crossings, exactly +-tau_amp at the reversals) and r_u
chosen so that initial liquefaction is at N = 4.4 and the system is liquefied
for N mod 1/2 in [0.4, 0.5) u [0, 0.1) afterwards, except that in cycle 5 it
stays liquefied from N = 5.4 to 5.8 (so cycle 5 has no C2' before its C3).
The run ends at N = 7.3.  Its events.txt holds the events of that design
(reversal k on the first row of N = k/2 - 1/4, the zero-crossing after it
on the first row of N = k/2) and N_IL = 4.4, as fix grflow/shear would
write them.  The expected values below follow from that design, not from
the library.

Run with the Python of the set-up (scripts/python-env.sh), in which the
package is installed.
"""

import json
import math
import os
import subprocess
import sys
from fractions import Fraction as F

import numpy as np
import pytest

import grflow_analysis as ga
from grflow_analysis import figures

# the package's commands, installed beside the interpreter running the tests
BIN = os.path.dirname(sys.executable)

TAU_AMP = 25.0e3
P0 = 1.0e5
DT_ROW = 1.0e-3          # simulated time between rows (s)
N_IL = F(22, 5)          # 4.4
EXITS = [F(23, 5), F(51, 10), F(29, 5), F(61, 10), F(33, 5), F(71, 10)]
EXIT_ZG = [3.5, 3.7, 3.62, 3.58, 3.66, 3.54]
ENTRIES = [F(49, 10), F(27, 5), F(59, 10), F(32, 5), F(69, 10)]
ZG_MIN_N, ZG_MIN = F(6), 1.7
FIGURES = ("fig1_snapshots.png", "fig2_macro.png", "fig3_zg.png", "fig4_pc.png",
           "fig5_ac_zg.png")


def rows_per_quarter(q):
    return 10 if q < 18 else (20 if q % 4 in (0, 1) else 15)


def build_series(liquefy=True, quarters=29, last_fraction=F(1, 5)):
    """Columns of a synthetic series and the exact N of each row (list of Fractions)."""
    Ns, qs, js = [], [], []
    for q in range(quarters + 1):
        Q = rows_per_quarter(q)
        jmax = Q - 1 if q < quarters else int(last_fraction * Q)
        for j in range(jmax + 1):
            Ns.append(F(q, 4) + F(j, 4 * Q))
            qs.append(q)
            js.append(j)
    n = len(Ns)
    Nf = np.array([float(x) for x in Ns])
    end = Ns[-1]
    col = {c: np.zeros(n) for c in ga.SERIES_COLUMNS}
    col["step"] = 100.0 * np.arange(n)
    col["time"] = DT_ROW * np.arange(n)
    gamma = 0.0
    for i, (N, q, j) in enumerate(zip(Ns, qs, js)):
        rev = (q + 1) // 2
        if j == 0 and q % 2 == 0:
            tau = 0.0
        elif j == 0:
            tau = TAU_AMP if q % 4 == 1 else -TAU_AMP
        else:
            tau = TAU_AMP * math.sin(2 * math.pi * float(N))
        half = N - F(math.floor(2 * N), 2)                 # N mod 1/2
        if not liquefy:
            ru = 0.5 * float(N / end)
            liq = False
        elif N < N_IL:
            ru, liq = 0.95 * float(N / N_IL), False
        else:
            liq = half >= F(2, 5) or half < F(1, 10) or F(27, 5) <= N < F(29, 5)
            ru = 0.995 if liq else 0.95
        if not liquefy or N < N_IL:
            zg = 4.76 - 0.6 * float(N) / 4.4
        elif N in EXITS:
            zg = EXIT_ZG[EXITS.index(N)]
        elif N == ZG_MIN_N:
            zg = ZG_MIN
        else:
            zg = 2.8 if liq else 3.9
        cyc = math.floor(N)
        ac = (0.1 + 0.05 * cyc) * (abs(tau) / TAU_AMP if j == 0 else
                                   abs(math.sin(2 * math.pi * float(N))))
        direction = 1.0 if rev % 2 == 0 else -1.0
        gamma += direction * (2e-5 if liq else 1e-5) if i else 0.0
        pc = np.zeros(13)
        pc[i % 13] += 0.5
        pc[(i + 5) % 13] += 0.5
        p = P0 * (1.0 - ru)
        vals = dict(reversals=rev, direction=direction, x_w=gamma * 0.02, gamma=gamma,
                    tau=tau, p=p, r_u=ru, z_g=zg, a_c=ac, N_p=6400.0,
                    floaters=round(pc[0] * 6400), sxx=p, syy=p, szz=p, sxz=-tau,
                    zlo=0.0, zhi=0.02, inertial=1e-4 / math.sqrt(max(1 - ru, 1e-6)))
        vals["N_c"] = zg * (6400 - vals["floaters"]) / 2
        for k, v in vals.items():
            col[k][i] = v
        for c in range(13):
            col["P%d" % c][i] = pc[c]
    return col, Ns, Nf


def write_series(path, col, names=ga.SERIES_COLUMNS):
    with open(path, "w") as f:
        f.write("# GRFLOW shear series (synthetic)\n")
        f.write("# " + " ".join(names) + "\n")
        for i in range(len(col["step"])):
            f.write(" ".join("%.17g" % col[c][i] for c in names) + "\n")


def write_atoms(path, step, ids, radius, xyz, glue, box, glue_name="glue"):
    with open(path, "w") as f:
        f.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\n" % (step, len(ids)))
        f.write("ITEM: BOX BOUNDS pp pp ff\n")
        for lo, hi in box:
            f.write("%.17g %.17g\n" % (lo, hi))
        f.write("ITEM: ATOMS id type radius x y z vx vy vz %s\n" % glue_name)
        for i in range(len(ids)):
            f.write("%d 1 %.17g %.17g %.17g %.17g 0 0 0 %d\n"
                    % (ids[i], radius[i], *xyz[i], glue[i]))


def write_contacts(path, step, pairs, box):
    with open(path, "w") as f:
        f.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ENTRIES\n%d\n" % (step, len(pairs)))
        f.write("ITEM: BOX BOUNDS pp pp ff\n")
        for lo, hi in box:
            f.write("%.17g %.17g\n" % (lo, hi))
        f.write("ITEM: ENTRIES id1 id2 dx dy dz fn ftx fty ftz\n")
        for a, b, fn in pairs:
            f.write("%d %d 1e-3 0 0 %.17g 0 0 0\n" % (a, b, fn))


BOX = [(0.0, 0.008), (0.0, 0.008), (0.0, 0.02)]


def event_lines(col, events, il_row=None):
    """The lines of events.txt (step time event reversals N N_IL step_IL)
    for the start on row 0 and ``events``, (row, kind) in time order with
    kind 1 a reversal and 2 the first zero-crossing after one, N by the
    rule of doc/fix_grflow_shear.rst; with initial liquefaction on row
    ``il_row``, N_IL linear in time between the events around it, written
    from the event after it on."""
    lines, k = [(0, 0)], 0
    for row, kind in events:
        lines.append((row, kind))
    out, n_il = [], -1.0
    marks = []
    for row, kind in lines:
        if kind == 1:
            k += 1
        n = 0.0 if kind == 0 else (k / 2 - 0.25 if kind == 1 else k / 2)
        marks.append((row, kind, k, n))
    for i, (row, kind, k, n) in enumerate(marks):
        if il_row is not None and n_il < 0 and row > il_row:
            ra, na = marks[i - 1][0], marks[i - 1][3]
            ta, tb, t = col["time"][ra], col["time"][row], col["time"][il_row]
            n_il = na + (n - na) * (t - ta) / (tb - ta)
        st_il = col["step"][il_row] if il_row is not None and row >= il_row else -1
        out.append((col["step"][row], col["time"][row], kind, k, n, n_il, st_il))
    return out


def events_table(lines):
    """``lines`` of events.txt as ga.read_events returns them."""
    return {c: np.array([l[i] for l in lines], dtype=float)
            for i, c in enumerate(ga.EVENT_COLUMNS)}


def write_events(path, lines):
    with open(path, "w") as f:
        f.write("# step time event reversals N N_IL step_IL\n")
        for l in lines:
            f.write(" ".join("%.17g" % v for v in l) + "\n")


def design_events(col, Ns, liquefy=True):
    """The events of the construction: reversal k on the first row of
    quarter 2k - 1, the crossing after it on the first row of quarter 2k."""
    events = [(i, 1 if int(4 * N) % 2 else 2) for i, N in enumerate(Ns)
              if i > 0 and (4 * N).denominator == 1]
    il_row = Ns.index(N_IL) if liquefy else None
    return event_lines(col, events, il_row)


def make_run(root, liquefy=True, snapshots=True, prep=True, events=True, **kw):
    """Write a synthetic run directory; return (dir, columns, exact N, float N)."""
    os.makedirs(root, exist_ok=True)
    col, Ns, Nf = build_series(liquefy, **kw)
    write_series(os.path.join(root, "series.txt"), col)
    if events:
        write_events(os.path.join(root, "events.txt"), design_events(col, Ns, liquefy))
    if prep:
        with open(os.path.join(root, "prep.json"), "w") as f:
            json.dump({"N": 8000, "seed": 1, "d_min": 1e-3, "d_max": 2e-3,
                       "d_mean": 1.26e-3, "density": 2650.0, "mu_prep": 0.1,
                       "mu_t": 0.5, "p_target": 1e5, "e": 0.650, "z_g": 4.80,
                       "p": 1.0e5, "sxx": 1e5, "syy": 1e5, "szz": 1e5, "Lx": 0.008,
                       "Ly": 0.008, "h": 0.02, "step": 50000, "time": 0.5,
                       "dt": 1e-5, "tau_amp": TAU_AMP, "v_x": 0.01, "ru_liq": 0.99}, f)
    if snapshots:
        snap = os.path.join(root, "snapshots")
        os.makedirs(snap, exist_ok=True)
        rng = np.random.default_rng(3)
        n = 300
        xyz = rng.uniform([0, 0, 0.0005], [0.008, 0.008, 0.0195], size=(n, 3))
        rad = rng.uniform(0.0005, 0.001, n)
        glue = np.where(xyz[:, 2] < 0.0015, 1, np.where(xyz[:, 2] > 0.0185, 2, 0))
        ids = np.arange(1, n + 1)
        write_atoms(os.path.join(snap, "atoms.prep.txt"), 0, ids, rad, xyz, glue, BOX)
        for step in (int(col["step"][50]), int(col["step"][-1])):
            moved = xyz.copy()
            moved[:, 0] = (moved[:, 0] + 0.2 * moved[:, 2]) % 0.008
            write_atoms(os.path.join(snap, "atoms.%d.txt" % step), step, ids, rad, moved,
                        glue, BOX, glue_name="v_glue")     # as the decks write it
            write_contacts(os.path.join(snap, "contacts.%d.txt" % step), step,
                           [(1, 2, 0.5), (2, 3, 1.5), (1, 3, 2.5)], BOX)
    return root, col, Ns, Nf


def row_at(Ns, value):
    return Ns.index(value)


@pytest.fixture(scope="module")
def liquefied_run(tmp_path_factory):
    return make_run(str(tmp_path_factory.mktemp("liq") / "run"))


@pytest.fixture(scope="module")
def dry_run(tmp_path_factory):
    return make_run(str(tmp_path_factory.mktemp("dry") / "run"), liquefy=False,
                    quarters=13, last_fraction=F(1, 2))


# ------------------------------------------------------------ reading

def test_read_series_columns(liquefied_run):
    root, col, Ns, _ = liquefied_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    assert list(s) == list(ga.SERIES_COLUMNS)
    assert len(s["step"]) == len(Ns)
    for c in ga.SERIES_COLUMNS:
        np.testing.assert_array_equal(s[c], col[c])


def test_read_series_without_header_and_with_repeated_steps(tmp_path):
    col, Ns, _ = build_series(quarters=3, last_fraction=F(0))
    path = str(tmp_path / "series.txt")
    with open(path, "w") as f:             # no header line: documented order assumed
        for i in range(len(Ns)):
            f.write(" ".join("%.17g" % col[c][i] for c in ga.SERIES_COLUMNS) + "\n")
        # a resumed run that repeated rows 20.. (the later rows win)
        for i in range(20, len(Ns)):
            f.write(" ".join("%.17g" % (col[c][i] + (0.5 if c == "tau" else 0))
                             for c in ga.SERIES_COLUMNS) + "\n")
    with pytest.warns(UserWarning):
        s = ga.read_series(path)
    assert len(s["step"]) == len(Ns)
    np.testing.assert_array_equal(s["tau"][:20], col["tau"][:20])
    np.testing.assert_array_equal(s["tau"][20:], col["tau"][20:] + 0.5)


def test_read_dumps(liquefied_run):
    root, col, _, _ = liquefied_run
    a = ga.read_dump_atoms(os.path.join(root, "snapshots", "atoms.prep.txt"))
    assert a["step"] == 0 and len(a["columns"]["id"]) == 300
    np.testing.assert_array_equal(a["box"], np.array(BOX))
    assert set(np.unique(a["columns"]["glue"])) == {0, 1, 2}
    step = int(col["step"][-1])
    c = ga.read_dump_local(os.path.join(root, "snapshots", "contacts.%d.txt" % step))
    assert c["step"] == step
    np.testing.assert_array_equal(c["columns"]["id1"], [1, 2, 1])
    np.testing.assert_array_equal(c["columns"]["fn"], [0.5, 1.5, 2.5])
    v = ga.read_dump_atoms(os.path.join(root, "snapshots", "atoms.%d.txt" % step))
    np.testing.assert_array_equal(v["columns"]["glue"], a["columns"]["glue"])
    np.testing.assert_array_equal(v["columns"]["v_glue"], a["columns"]["glue"])
    snaps = ga.list_snapshots(root)
    assert [s for s, _ in snaps] == [int(col["step"][50]), step]
    with pytest.raises(ga.FormatError):
        ga.read_dump_atoms(os.path.join(root, "snapshots", "contacts.%d.txt" % step))


# ------------------------------------------------------------ cycles

def test_cycle_count_matches_construction(liquefied_run):
    root, col, Ns, Nf = liquefied_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    ev = ga.run_events(root, s)
    N = ga.cycle_count(s, ev)
    # exact up to round-off everywhere, including the extrapolated last rows
    np.testing.assert_allclose(N, Nf, rtol=0, atol=1e-12)
    assert len(ev["reversal_rows"]) == 15
    for k, r in enumerate(ev["reversal_rows"], 1):
        assert Ns[r] == F(k, 2) - F(1, 4)
    for k in range(1, 15):
        assert Ns[ev["crossing_rows"][k]] == F(k, 2)
    assert ev["crossing_rows"][15] is None     # the run stops before it
    # before the first reversal no rate is known: N stays 0 (the start
    # only); after the last event, extrapolated at the last quarter's rate
    # and capped at a quarter cycle beyond it
    s3 = {"time": np.arange(3.0)}
    assert ga.cycle_count(s3, {"time": [0.0], "N": [0.0]}).tolist() == [0, 0, 0]
    s9 = {"time": np.arange(9.0)}
    np.testing.assert_allclose(ga.cycle_count(s9, {"time": [0.0, 2.0], "N": [0.0, 0.25]}),
                               [0, 0.125, 0.25, 0.375, 0.5, 0.5, 0.5, 0.5, 0.5], atol=1e-15)


# ------------------------------------------------------------ the fix's events

def events_between_rows(tmp_path, lines):
    """A 13-row series (step 100 i, time i, reversals as the events below
    say) and events.txt with the given lines, written to tmp_path."""
    steps = 100.0 * np.arange(13)
    rev = np.zeros(13)
    for st, kind, k in [(l[0], l[2], l[3]) for l in lines if l[2] == 1]:
        rev[steps >= st] = k
    col = {c: np.zeros(13) for c in ga.SERIES_COLUMNS}
    col.update(step=steps, time=np.arange(13.0), reversals=rev, r_u=np.full(13, 0.5),
               z_g=np.full(13, 4.0), p=np.full(13, 5.0e4))
    write_series(str(tmp_path / "series.txt"), col)
    with open(tmp_path / "events.txt", "w") as f:
        f.write("# step time event reversals N N_IL step_IL\n")
        for l in lines:
            f.write(" ".join("%.17g" % v for v in l) + "\n")
    return ga.read_series(str(tmp_path / "series.txt"))


# start; reversal 1 at t 2.5; crossing at 4.5; initial liquefaction at
# step 520 (t 5.2), its N_IL as the fix wrote it once the next event came;
# reversal 2 at 7.5; crossing at 9.5
EVENTS = [(0, 0.0, 0, 0, 0.0, -1, -1), (250, 2.5, 1, 1, 0.25, -1, -1),
          (450, 4.5, 2, 1, 0.5, -1, -1), (750, 7.5, 1, 2, 0.75, 0.5583333333333333, 520),
          (950, 9.5, 2, 2, 1.0, 0.5583333333333333, 520)]


def test_fix_events_are_used_as_written(tmp_path):
    s = events_between_rows(tmp_path, EVENTS)
    ev = ga.run_events(str(tmp_path), s)
    # an event's row: the first row at or after its step
    assert ev["reversal_rows"] == [3, 8]
    assert ev["crossing_rows"] == {0: 0, 1: 5, 2: 10}
    assert ev["N_IL"] == 0.5583333333333333 and ev["step_IL"] == 520
    # N between the events at their own times (not at the rows'): by hand
    N = ga.cycle_count(s, ev)
    assert N[2] == pytest.approx(0.25 * 2.0 / 2.5, abs=1e-15)
    assert N[3] == pytest.approx(0.25 + 0.25 * 0.5 / 2.0, abs=1e-15)
    assert N[9] == pytest.approx(0.75 + 0.25 * 1.5 / 2.0, abs=1e-15)
    assert N[10] == pytest.approx(1.0 + 0.25 * 0.5 / 2.0, abs=1e-15)   # extrapolated
    # initial liquefaction: the fix's step (row of step 600), its N_IL as written
    assert ga.liquefaction(s, ev, 0.99)["onset"] == 6
    summ = ga.summary(s, None, ev)
    n_il = next(e for e in summ["entries"] if e["name"] == "N_IL")
    assert n_il["measured"] == 0.5583333333333333 and "fix" in n_il["description"]


def test_fix_events_crossing_on_the_reversal_check(tmp_path):
    """A crossing seen on the same check as the next reversal has no line:
    its row is the reversal's."""
    s = events_between_rows(tmp_path, [EVENTS[0], EVENTS[1], (750, 7.5, 1, 2, 0.75, -1, -1)])
    ev = ga.run_events(str(tmp_path), s)
    assert ev["reversal_rows"] == [3, 8]
    assert ev["crossing_rows"] == {0: 0, 1: 8, 2: None}
    assert ev["N_IL"] is None and ev["step_IL"] is None
    assert ga.liquefaction(s, ev, 0.99)["onset"] is None


def test_events_txt_is_the_only_source_of_events(tmp_path):
    """A run directory without events.txt is an error that says so, not
    events found again in the series by another rule."""
    root = make_run(str(tmp_path / "run"), snapshots=False, events=False, quarters=21,
                    last_fraction=F(0))[0]
    s = ga.read_series(os.path.join(root, "series.txt"))
    with pytest.raises(ga.FormatError, match="no events.txt"):
        ga.run_events(root, s)
    # the library has no rule of its own for them
    assert not hasattr(ga, "cycle_events")
    with pytest.raises(TypeError):
        ga.summary(s, None)


@pytest.mark.parametrize("lines, message", [
    (["0 0 0 0 0 -1"], "rows have 6 fields"),
    (["0 0 1 1 0.25 -1 -1"], "not the start"),
    (["0 0 0 0 0 -1 -1", "500 1 1 1 0.25 -1 -1", "400 2 2 1 0.5 -1 -1"], "steps decrease"),
    (["0 0 0 0 0 -1 -1", "500 1 3 1 0.25 -1 -1"], "event kind"),
    (["0 0 0 0 0 -1 -1", "500 1 x 1 0.25 -1 -1"], "non-numeric"),
])
def test_read_events_rejects_bad_files(tmp_path, lines, message):
    path = tmp_path / "events.txt"
    path.write_text("# step time event reversals N N_IL step_IL\n" + "\n".join(lines) + "\n")
    with pytest.raises(ga.FormatError, match=message):
        ga.read_events(str(path))


def test_liquefaction_onset_and_exits(liquefied_run):
    root, col, Ns, Nf = liquefied_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    liq = ga.liquefaction(s, ga.run_events(root, s), 0.99)
    assert liq["onset"] == row_at(Ns, N_IL)
    assert [Ns[i] for i in liq["exits"]] == EXITS
    assert [Ns[i] for i in liq["entries"]] == ENTRIES


def test_cycle_states(liquefied_run):
    root, col, Ns, Nf = liquefied_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    ev = ga.run_events(root, s)
    assert ga.post_liquefaction_cycles(s, ev, 0.99) == [5, 6, 7]
    offsets = {"C0": F(0), "C0'": F(1, 10), "C1": F(1, 4), "C2": F(1, 2),
               "C2'": F(3, 5), "C3": F(3, 4)}
    n, st, note = ga.choose_cycle(s, ev, 0.99)       # cycle 5 lacks C2': cycle 6
    assert n == 6 and note == ""
    assert st == {k: row_at(Ns, 6 + v) for k, v in offsets.items()}
    n, st, _ = ga.choose_cycle(s, ev, 0.99, index=0)
    assert n == 5
    assert st["C2'"] is None
    assert {k: Ns[v] for k, v in st.items() if v is not None} == {
        k: 5 + v for k, v in offsets.items() if k != "C2'"}
    n, st, _ = ga.choose_cycle(s, ev, 0.99, index=2)
    assert n == 7
    assert [Ns[st[k]] if st[k] is not None else None for k in ga.STATES] == [
        F(7), F(71, 10), F(29, 4), None, None, None]
    assert ga.choose_cycle(s, ev, 0.99, index=3)[0] is None
    r = st["C1"]
    np.testing.assert_array_equal(ga.connectivity(s, r), [col["P%d" % c][r] for c in range(13)])
    # over the particles with contacts: P_c / (1 - P_0), P_0 entry 0, sums to 1
    pc = np.array([col["P%d" % c][r] for c in range(13)])
    nf = ga.connectivity_non_floaters(s, r)
    assert nf[0] == 0.0
    np.testing.assert_allclose(nf[1:], pc[1:] / (1.0 - pc[0]), rtol=1e-15)
    assert nf.sum() == pytest.approx(1.0, abs=1e-12)
    assert ga.cycle_rows(s, ev, 6) == (row_at(Ns, F(6)), row_at(Ns, F(7)))


def test_states_edge_rows():
    """Threshold reached exactly (the fix's initial liquefaction on row 6);
    exits on the C0 row (counts) and on the C1 row (does not)."""
    ru = np.array([.5] * 6 + [.99, .98, .995, .98, .98, .995, .98, .995, .995, .995,
                              .98, .98, .98, .98])
    s = {"step": 100.0 * np.arange(20), "time": np.arange(20.0), "r_u": ru}
    # reversals on rows 3, 7, 12, 17, the crossings after them on 5, 9, 14, 19
    ev = ga.fix_events(events_table(event_lines(
        s, [(3, 1), (5, 2), (7, 1), (9, 2), (12, 1), (14, 2), (17, 1), (19, 2)], il_row=6)), s)
    assert ev["N_IL"] == pytest.approx(0.625, abs=1e-15) and ev["step_IL"] == 600
    liq = ga.liquefaction(s, ev, 0.99)
    assert liq["onset"] == 6 and liq["exits"] == [7, 9, 12, 16]
    assert ga.find_cycle_states(s, ev, 1, 0.99) == {"C0": 9, "C0'": 9, "C1": 12, "C2": 14,
                                                    "C2'": 16, "C3": 17}
    assert ga.find_cycle_states(s, ev, 0, 0.99) == {"C0": 0, "C0'": None, "C1": 3, "C2": 5,
                                                    "C2'": None, "C3": 7}
    assert ga.post_liquefaction_cycles(s, ev, 0.99) == [1, 2]
    assert ga.choose_cycle(s, ev, 0.99)[:2] == (1, ga.find_cycle_states(s, ev, 1, 0.99))
    np.testing.assert_allclose(ga.cycle_count(s, ev)[[3, 5, 7, 9, 12, 14, 17, 19]],
                               [.25, .5, .75, 1, 1.25, 1.5, 1.75, 2], atol=1e-12)


def test_match_rules():
    assert ga._match(4.2, 4.0, 0.0, "max") is False
    assert ga._match(3.9, 4.0, 0.0, "max") is True
    assert ga._match(0.66, 0.647, 0.01, "abs") is False
    assert ga._match(0.655, 0.647, 0.01, "abs") is True
    assert ga._match([3.5, 3.9], 3.6, 0.2, "each") is False
    assert ga._match([3.5, 3.7], 3.6, 0.2, "each") is True
    assert ga._match("not reached", None, None, None) is False
    assert ga._match(2.0, None, None, None) is None
    # the paper's number without a tolerance: no match, the difference
    assert ga._match(3.545, 3.6, None, "diff") is None
    assert ga._match(3.6, 3.6, None, "diff") is None


def test_numbers_without_a_tolerance_show_the_difference():
    """Where the paper gives a number without a tolerance the summary calls
    nothing a match; it gives measured - paper (issue 30: no tolerance is
    chosen to make a result match)."""
    given = {"e_prep", "p_prep", "z_g_prep", "z_g_post_IL_min", "z_g_inflections",
             "z_g_inflection_mean", "z_g_at_exits", "z_g_exit_mean"}
    assert {k for k, v in ga.PAPER.items() if v[2] == "diff"} == given
    for k, (paper, tol, comparison, _) in ga.PAPER.items():
        # a tolerance is left only on the protocol's inputs, and it is 0
        assert comparison in (None, "diff", "max") or tol == 0, k
    e = ga._entry("z_g_exit_mean", "mean", "-", 3.545)
    assert e["match"] is None and e["difference"] == pytest.approx(-0.055, abs=1e-12)
    assert ga.tolerance_cell(e) == "no tolerance given"
    assert ga.match_cell(e).startswith("difference -0.05")
    e = ga._entry("z_g_at_exits", "each", "-", [3.5, 3.7])
    assert e["difference"] == pytest.approx([-0.1, 0.1], abs=1e-12)
    assert ga.match_cell(e).startswith("difference -0.1") and e["match"] is None
    e = ga._entry("z_g_exit_mean", "mean", "-", ga.NOT_REACHED)
    assert e["match"] is False and e["difference"] is None and ga.match_cell(e) == "-"


def test_peak_ac_per_cycle(liquefied_run):
    root, _, _, Nf = liquefied_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    peaks = ga.peak_ac_per_cycle(s, ga.cycle_count(s, ga.run_events(root, s)))
    np.testing.assert_allclose(peaks, [0.1 + 0.05 * n for n in range(8)], atol=1e-12)


# ------------------------------------------------------------ summary

def entries(summ):
    return {e["name"]: e for e in summ["entries"]}


def test_summary_liquefied(liquefied_run):
    root, col, Ns, Nf = liquefied_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    summ = ga.summary(s, ga.read_prep(os.path.join(root, "prep.json")), ga.run_events(root, s))
    e = entries(summ)
    assert e["e_prep"]["measured"] == 0.650 and e["e_prep"]["paper"] == 0.647
    assert e["e_prep"]["match"] is None
    assert e["e_prep"]["difference"] == pytest.approx(0.003, abs=1e-12)
    assert e["z_g_prep"]["measured"] == 4.80 and e["z_g_prep"]["match"] is None
    assert e["N_IL"]["measured"] == pytest.approx(4.4, abs=1e-12)
    assert e["N_IL"]["paper"] is None and e["N_IL"]["match"] is None
    assert e["z_g_post_IL_min"]["measured"] == ZG_MIN
    assert e["z_g_post_IL_min"]["difference"] == pytest.approx(ZG_MIN - 1.5, abs=1e-12)
    assert e["z_g_post_IL_max"]["measured"] == 3.9 and e["z_g_post_IL_max"]["match"]
    assert e["z_g_at_exits"]["measured"] == EXIT_ZG and e["z_g_at_exits"]["match"] is None
    assert e["z_g_exit_mean"]["measured"] == pytest.approx(3.6, abs=1e-12)
    assert e["z_g_exit_std"]["measured"] == pytest.approx(np.std(EXIT_ZG), abs=1e-12)
    assert e["n_exits"]["measured"] == 6
    assert summ["exit_N"] == pytest.approx([float(x) for x in EXITS], abs=1e-12)
    assert summ["cycle_C"]["cycle"] == 6
    assert summ["cycle_C"]["states"]["C2'"]["N"] == pytest.approx(6.6, abs=1e-12)
    assert summ["cycle_C"]["states"]["C2'"]["z_g"] == EXIT_ZG[4]


def test_connectivity_non_floaters_all_floaters():
    # every particle a floater: no distribution over particles with contacts
    series = {"P0": np.array([1.0])}
    for c in range(1, 13):
        series["P%d" % c] = np.array([0.0])
    assert np.all(np.isnan(ga.connectivity_non_floaters(series, 0)))


def test_inertial_stats_undefined_rows_and_split():
    # the deck writes I = -1 where p = 0: such rows are counted, never taken
    # as a value; the split is at the onset row
    series = {"inertial": np.array([1e-4, 5e-4, 2e-4, -1.0, 0.3, -1.0, 0.01]),
              "p": np.array([9e4, 5e4, 2e4, 0.0, 0.007, 0.0, 80.0])}
    st = ga.inertial_stats(series, onset=2)
    assert st["max"] == 0.3
    assert st["max_pre_IL"] == 5e-4
    assert st["median_post_IL"] == pytest.approx(np.median([2e-4, 0.3, 0.01]), abs=0)
    assert st["undefined_rows"] == 2
    assert st["p_min_post_IL"] == 0.0
    st = ga.inertial_stats(series, onset=None)
    assert st["max_pre_IL"] == 0.3 and st["median_post_IL"] == ga.NOT_REACHED
    assert st["p_min_post_IL"] == ga.NOT_REACHED
    st = ga.inertial_stats({"p": series["p"]}, onset=2)
    assert st["max"] == ga.NOT_AVAILABLE and st["p_min_post_IL"] == 0.0


def test_summary_a_c_changes_in_cycle_C(liquefied_run):
    # a_c at the states of cycle C, from the construction's rows
    root, col, Ns, Nf = liquefied_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    summ = ga.summary(s, ga.read_prep(os.path.join(root, "prep.json")), ga.run_events(root, s))
    e = entries(summ)
    st = {k: v["row"] for k, v in summ["cycle_C"]["states"].items()}
    for name, a, b in (("a_c_change_C0_C0p", "C0", "C0'"), ("a_c_change_C0p_C1", "C0'", "C1"),
                       ("a_c_change_C1_C2", "C1", "C2")):
        assert e[name]["measured"] == col["a_c"][st[b]] - col["a_c"][st[a]], name
        assert e[name]["match"] is None


def test_summary_splits_states_at_3_6(liquefied_run):
    # counted by hand from the construction: rows from the onset on, split
    # by r_u at 0.99
    root, col, Ns, Nf = liquefied_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    e = entries(ga.summary(s, ga.read_prep(os.path.join(root, "prep.json")), ga.run_events(root, s)))
    onset = next(k for k, ru in enumerate(col["r_u"]) if ru >= 0.99)
    nonliq = [zg for ru, zg in zip(col["r_u"][onset:], col["z_g"][onset:]) if ru < 0.99]
    liq = [zg for ru, zg in zip(col["r_u"][onset:], col["z_g"][onset:]) if ru >= 0.99]
    assert len(nonliq) > 0 and len(liq) > 0
    frac = sum(1 for zg in nonliq if zg >= 3.6) / len(nonliq)
    assert 0.0 < frac < 1.0    # the construction has both kinds
    assert e["nonliq_zg_at_least_3.6"]["measured"] == pytest.approx(frac, abs=1e-15)
    assert e["liq_zg_max"]["measured"] == max(liq)
    assert e["nonliq_zg_at_least_3.6"]["match"] is None


def test_summary_never_liquefied(dry_run):
    root, _, _, _ = dry_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    summ = ga.summary(s, ga.read_prep(os.path.join(root, "prep.json")), ga.run_events(root, s))
    e = entries(summ)
    for name in ("N_IL", "z_g_at_IL", "z_g_post_IL_min", "z_g_post_IL_max", "n_exits",
                 "z_g_at_exits", "z_g_exit_mean", "z_g_exit_std"):
        assert e[name]["measured"] == "not reached", name
        assert e[name]["match"] is False, name
    assert e["e_prep"]["difference"] is not None
    assert summ["cycle_C"]["cycle"] is None
    # without prep.json the preparation values are not available, never a match
    summ = ga.summary(s, None, ga.run_events(root, s))
    assert entries(summ)["e_prep"]["measured"] == "not available"
    assert entries(summ)["e_prep"]["match"] is False
    assert summ["tau_amp"] == 25e3 and summ["ru_liq"] == 0.99


def test_summary_takes_the_shear_stage_record(dry_run, tmp_path):
    # a shear stage run with another tau_amp and ru_liq than the
    # preparation's prep.json says (-var tau_amp at the shear stage, as the
    # resistance curve does): its record shear.json decides
    root, _, _, _ = dry_run
    s = ga.read_series(os.path.join(root, "series.txt"))
    prep = ga.read_prep(os.path.join(root, "prep.json"))
    assert ga.read_shear_record(root) is None
    (tmp_path / "shear.json").write_text('{"normal_force": "unclipped", "tau_amp": 3.0e4, '
                                         '"ru_liq": 0.95}')
    shear = ga.read_shear_record(str(tmp_path))
    summ = ga.summary(s, prep, ga.run_events(root, s), shear=shear)
    assert summ["tau_amp"] == 3.0e4 and summ["ru_liq"] == 0.95
    assert entries(summ)["tau_amp"]["measured"] == 3.0e4
    assert summ["shear_stage"]["normal_force"] == "unclipped"
    assert "(shear.json): normal_force unclipped" in ga.summary_markdown(summ)
    assert "not recorded" in ga.summary_markdown(ga.summary(s, prep, ga.run_events(root, s)))
    (tmp_path / "shear.json").write_text("[1, 2]")
    with pytest.raises(ga.FormatError):
        ga.read_shear_record(str(tmp_path))


# ------------------------------------------------------------ command

def test_command_liquefied(liquefied_run, tmp_path, capsys):
    root = liquefied_run[0]
    out = str(tmp_path / "figs")
    assert figures.main([root, "--out", out]) == 0
    for name in FIGURES + ("summary.json", "summary.md"):
        assert os.path.getsize(os.path.join(out, name)) > 1000 or name.startswith("summary")
    with open(os.path.join(out, "summary.json")) as f:
        summ = json.load(f)
    assert summ["cycle_C"]["cycle"] == 6
    printed = capsys.readouterr().out
    assert "| N_IL" in printed and "z_g_exit_mean" in printed
    md = open(os.path.join(out, "summary.md")).read()
    assert "| e_prep" in md and "0.647" in md
    # --cycle picks another post-liquefaction cycle, incomplete ones included
    out2 = str(tmp_path / "figs2")
    assert figures.main([root, "--out", out2, "--cycle", "2"]) == 0
    with open(os.path.join(out2, "summary.json")) as f:
        summ = json.load(f)
    assert summ["cycle_C"]["cycle"] == 7
    assert summ["cycle_C"]["states"]["C3"] == "not reached"
    assert os.path.isfile(os.path.join(out2, "fig4_pc.png"))


# ------------------------------------------------------------ what the figures show

def _run(root):
    s = ga.read_series(os.path.join(root, "series.txt"))
    prep = ga.read_prep(os.path.join(root, "prep.json"))
    return figures.Run(root, s, prep, ga.run_events(root, s))


def _hlines(ax):
    return sorted({float(l.get_ydata()[0]) for l in ax.get_lines()
                   if len(set(l.get_ydata())) == 1 and len(set(l.get_xdata())) == 2})


def _vlines(ax):
    return sorted({float(l.get_xdata()[0]) for l in ax.get_lines()
                   if len(set(l.get_xdata())) == 1 and len(set(l.get_ydata())) == 2})


def _state_marks(ax):
    """label -> (x, y) of the states' markers on an axes"""
    out = {}
    for c in ax.collections:
        if c.get_label() in figures.LABEL.values():
            out[c.get_label()] = tuple(c.get_offsets()[0])
    return out


def test_figures_show_what_they_claim(liquefied_run, tmp_path):
    """Each figure of the synthetic liquefied run (N_IL = 4.4, cycle C = 6,
    tau_amp = 25 kPa) draws the quantities its axes name, the reference
    lines, and the six states of cycle C where they are."""
    root = liquefied_run[0]
    run = _run(root)
    out = str(tmp_path)
    s = run.s
    rows = run.states
    assert run.n == 6 and all(r is not None for r in rows.values())
    labels = {figures.LABEL[st]: r for st, r in rows.items()}
    try:
        # Fig. 2: tau against p and gamma, the amplitude lines, cycle C and its states
        fig = figures.fig2(run, out, keep=True)
        for ax, x in zip(fig.axes[:2], (s["p"] / 1e3, 100 * s["gamma"])):
            names = [l.get_label() for l in ax.get_lines()]
            assert {"pre-liquefaction", "post-liquefaction", "cycle C (N = 6-7)"} <= set(names)
            assert _hlines(ax) == [-25.0, 25.0]
            marks = _state_marks(ax)
            assert set(marks) == set(labels)
            for lab, r in labels.items():
                assert marks[lab] == pytest.approx((x[r], s["tau"][r] / 1e3), abs=1e-12)
        assert fig.axes[0].get_xlabel() == "p (kPa)"
        assert fig.axes[1].get_xlabel() == r"$\gamma$ (%)"
        # Fig. 3: z_g(N), z_g = 3.6, N_IL = 4.4, the inset on cycle C with its states
        fig = figures.fig3(run, out, keep=True)
        ax = fig.axes[0]
        assert (ax.get_xlabel(), ax.get_ylabel()) == ("N (cycles)", "$z_g$")
        assert 3.6 in _hlines(ax)
        assert _vlines(ax) == [pytest.approx(4.4, abs=1e-12)]
        segs = ax.collections[0].get_segments()
        assert len(segs) > 0.9 * len(s["z_g"])            # the whole run, as a coloured line
        inset = ax.child_axes[0]
        marks = _state_marks(inset)
        assert set(marks) == set(labels)
        for lab, r in labels.items():
            assert marks[lab] == pytest.approx((run.N[r], s["z_g"][r]), abs=1e-12)
        # Fig. 4: P_c at the six states, over all particles and over those with contacts
        fig = figures.fig4(run, out, keep=True)
        for k, ax in enumerate(fig.axes[:2]):
            assert len(ax.containers) == 6
            for bars, st in zip(ax.containers, ga.STATES):
                pc = ga.connectivity(s, rows[st])
                # (b): among the particles with contacts, none has c = 0
                want = pc if k == 0 else np.concatenate([[0.0], pc[1:] / (1.0 - pc[0])])
                assert [b.get_height() for b in bars] == pytest.approx(list(want), abs=1e-12)
        # Fig. 5: a_c against z_g, z_g = 3.6, cycle C and its states
        fig = figures.fig5(run, out, keep=True)
        ax = fig.axes[0]
        assert (ax.get_xlabel(), ax.get_ylabel()) == ("$z_g$", "$a_c$")
        assert _vlines(ax) == [3.6]
        marks = _state_marks(ax)
        for lab, r in labels.items():
            assert marks[lab] == pytest.approx((s["z_g"][r], s["a_c"][r]), abs=1e-12)
        # Fig. 1: both side views, every particle of the snapshots drawn
        fig = figures.fig1(run, out, keep=True)
        for ax in fig.axes[:2]:
            assert (ax.get_xlabel(), ax.get_ylabel()) == ("x (mm)", "z (mm)")
            assert len(ax.collections[0].get_offsets()) == 300
    finally:
        figures.plt.close("all")


def test_figures_of_a_run_that_never_liquefied(dry_run, tmp_path):
    run = _run(dry_run[0])
    try:
        fig = figures.fig3(run, str(tmp_path), keep=True)
        ax = fig.axes[0]
        assert _vlines(ax) == []                      # no N_IL line
        assert any("not reached" in t.get_text() for t in ax.texts)
        fig = figures.fig4(run, str(tmp_path), keep=True)
        assert all(len(a.containers) == 0 for a in fig.axes[:2])
        assert any("cycle C not found" in t.get_text() for t in fig.axes[0].texts)
    finally:
        figures.plt.close("all")


def test_command_never_liquefied_default_out(dry_run, capsys):
    root = dry_run[0]
    assert figures.main([root]) == 0
    out = os.path.join(root, "figures")
    for name in FIGURES + ("summary.json", "summary.md"):
        assert os.path.isfile(os.path.join(out, name)), name
    with open(os.path.join(out, "summary.json")) as f:
        e = entries(json.load(f))
    assert e["N_IL"]["measured"] == "not reached" and e["N_IL"]["match"] is False
    assert "not reached" in capsys.readouterr().out


def test_command_without_snapshots_or_prep(tmp_path, capsys):
    root = make_run(str(tmp_path / "run"), snapshots=False, prep=False,
                    quarters=21, last_fraction=F(0))[0]
    assert figures.main([root]) == 0
    out = os.path.join(root, "figures")
    assert not os.path.exists(os.path.join(out, "fig1_snapshots.png"))
    for name in FIGURES[1:]:
        assert os.path.isfile(os.path.join(out, name)), name
    printed = capsys.readouterr().out
    assert "fig1 skipped" in printed and "prep.json unusable" in printed


def _series_lines():
    col, Ns, _ = build_series(quarters=2, last_fraction=F(0))
    head = "# " + " ".join(ga.SERIES_COLUMNS)
    rows = [" ".join("%.17g" % col[c][i] for c in ga.SERIES_COLUMNS) for i in range(len(Ns))]
    return head, rows


@pytest.mark.parametrize("case", ["ragged", "text", "no_tau", "header_only", "no_series",
                                  "no_dir", "no_events", "bad_events"])
def test_malformed_input_exit_2(tmp_path, capsys, case):
    root = tmp_path / "run"
    head, rows = _series_lines()
    if case != "no_dir":
        root.mkdir()
    if case == "ragged":
        rows[7] = rows[7].rsplit(" ", 1)[0]
    elif case == "text":
        rows[3] = rows[3].replace(rows[3].split()[6], "abc", 1)
    elif case == "no_tau":
        head = head.replace(" tau ", " shear ")
    elif case == "header_only":
        rows = []
    if case not in ("no_series", "no_dir"):
        (root / "series.txt").write_text(head + "\n" + "\n".join(rows) + "\n")
    if case == "bad_events":
        (root / "events.txt").write_text("0 0 1 1 0.25 -1 -1\n")
    assert figures.main([str(root)]) == 2
    err = capsys.readouterr().err
    assert "error" in err
    if case == "no_events":
        assert "no events.txt" in err
    assert not (root / "figures").exists()


def test_installed_command_from_any_directory(liquefied_run, tmp_path):
    """The set-up's commands and import work from a directory that is
    neither analysis/ nor the repository, with no PYTHONPATH: the package is
    installed, not found through the working directory."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["MPLBACKEND"] = "Agg"
    where = subprocess.run([sys.executable, "-c",
                            "import grflow_analysis, grflow_analysis.figures; "
                            "print(grflow_analysis.__file__)"],
                           cwd=tmp_path, env=env, capture_output=True, text=True)
    assert where.returncode == 0, where.stderr
    cmd = os.path.join(BIN, "grflow-figures")
    assert os.access(cmd, os.X_OK), "%s: not installed (scripts/python-env.sh)" % cmd
    bad = subprocess.run([cmd, str(tmp_path / "absent")], cwd=tmp_path, env=env,
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "does not exist" in bad.stderr
    good = subprocess.run([cmd, liquefied_run[0], "--out", str(tmp_path / "figs")],
                          cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600)
    assert good.returncode == 0, good.stdout[-2000:] + good.stderr[-2000:]
    assert (tmp_path / "figs" / "summary.json").is_file()
    for name in ("grflow-curve",):
        assert os.access(os.path.join(BIN, name), os.X_OK), name


def test_static_redundancy():
    # (3 N_c - 6 n) / (6 n) with z_g = 2 N_c / n
    n, Nc = 100, 180
    assert ga.static_redundancy(2 * Nc / n) == pytest.approx((3 * Nc - 6 * n) / (6 * n))
    assert ga.static_redundancy(4.0) == 0.0
    assert ga.static_redundancy(2.0) == -0.5


def test_zg_inflection_of_a_logistic_rise():
    """z_g climbs slowly and then rises as a sharp logistic in N (inflection
    at N0, z = 2.7, width 0.004 cycles, as the jumps through the exits of
    the paper-size runs), with deterministic uniform scatter of +-0.05, in
    a quarter cycle from a zero-crossing (row 0) to a reversal (the last
    row); the exit (r_u below ru_liq) comes 0.01 cycles after N0.  Over 20
    scatter seeds the fit finds N0 within a quarter of the width and z
    within 0.02: the scatter's rms (0.029) over the ~250 rows of the rise
    makes errors near 0.029/sqrt(250) ~ 0.002 in z; the bounds hold
    about ten such errors."""
    rows = 4001
    N = np.linspace(32.5, 32.75, rows)
    N0, w, zlo, dz = 32.61, 0.004, 1.5, 2.4
    exit_row = int(np.searchsorted(N, N0 + 0.01))
    events = {"reversal_rows": [None] * 65 + [rows - 1], "crossing_rows": {65: 0}}
    liq = {"onset": 0, "exits": [exit_row], "entries": []}
    for seed in range(20):
        rng = np.random.default_rng(seed)
        zg = (zlo + 2.0 * (N - N[0]) + dz / (1.0 + np.exp(-(N - N0) / w))
              + rng.uniform(-0.05, 0.05, rows))
        found = ga.zg_inflections({"z_g": zg}, N, events, liq)
        assert len(found) == 1 and found[0]["exit_row"] == exit_row
        assert abs(found[0]["N"] - N0) <= 0.25 * w, seed
        # the slow climb adds 2 (N - N[0]) = 0.22 at N0
        assert abs(found[0]["z_g"] - (zlo + 0.22 + dz / 2)) <= 0.02, seed
    # an exit whose quarter cycle has not ended in the series is skipped
    events_open = {"reversal_rows": [None] * 65, "crossing_rows": {65: 0}}
    assert ga.zg_inflections({"z_g": zg}, N, events_open, liq) == []
