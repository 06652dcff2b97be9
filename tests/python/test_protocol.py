"""The protocol decks (inputs/cyclic_shear.lmp) end to end, on a small case.

1. The whole protocol with the quick preset and fewer particles: it
   prepares the sample (compression, friction, glue), shears it through
   initial liquefaction (r_u >= 0.99) and one post-liquefaction cycle, and
   every output file parses in the format of inputs/README.md.
2. Kill and resume: a shear stage killed (SIGKILL) after its first
   restart file, then resumed with -var resume yes, leaves one series with
   every output step exactly once, identical to an uninterrupted run up to
   the restart step.
3. Bad deck parameters stop with a clear message.

Environment: LMP (lmp binary), GRFLOW_INPUTS (the inputs/ directory).
"""

import json
import re
import math
import os
import signal
import subprocess
import time

import numpy as np
import pytest

import grflow_analysis as ga
from grflow_reference import network_from_snapshot, series_events
from runfiles import (COLUMNS, first_leg_wall_speed, last_complete_step, read_dump,
                      read_series, tail)
from lmprun import LMP

INPUTS = os.environ.get("GRFLOW_INPUTS",
                        os.path.join(os.path.dirname(__file__), "..", "..", "inputs"))
DECK = os.path.join(INPUTS, "cyclic_shear.lmp")
STOCK_DECK = os.path.join(INPUTS, "cyclic_shear_stock.lmp")
SMALL = {"preset": "quick", "N": "500", "n_post": "1", "series_every": "50"}
# the protocol fixture's run: a series row at every check of fix
# grflow/shear (check_every 10), so that every snapshot (taken at an
# event, on a check) has its row
PROTOCOL = dict(SMALL, series_every="10")


def lmp_cmd(outdir, screen=False, deck=DECK, **var):
    cmd = [LMP, "-nocite", "-echo", "none", "-log", "none", "-in", deck,
           "-var", "inputs", INPUTS, "-var", "outdir", str(outdir)]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    if not screen:
        cmd += ["-screen", "none"]
    return cmd


def run(outdir, timeout=900, deck=DECK, **var):
    proc = subprocess.run(lmp_cmd(outdir, deck=deck, **var), capture_output=True, text=True,
                          timeout=timeout)
    assert proc.returncode == 0, (proc.stdout[-3000:] + proc.stderr[-3000:]
                                  + tail(outdir / "log.shear.lammps")
                                  + tail(outdir / "log.prep.lammps"))
    return proc


@pytest.fixture(scope="module")
def protocol(tmp_path_factory):
    out = tmp_path_factory.mktemp("protocol") / "run"
    t0 = time.time()
    run(out, **PROTOCOL)
    return out, time.time() - t0


def test_whole_protocol_reaches_liquefaction(protocol):
    out, seconds = protocol
    prep = json.loads((out / "prep.json").read_text())
    for key in ("N", "seed", "d_min", "d_max", "d_mean", "density", "mu_prep", "mu_t",
                "pair_stock", "p_target", "e", "z_g", "p", "sxx", "syy", "szz", "Lx", "Ly",
                "h", "step", "time", "dt", "tau_amp", "v_x", "ru_liq"):
        assert key in prep, key
    assert prep["N"] == 500
    # the whole-cell stresses were within 1% of 100 kPa; the central slab is near
    assert abs(prep["p"] - 1.0e5) < 0.15e5
    assert 0.5 < prep["e"] < 1.0
    # timestep rule: dt = 0.1 sqrt(m_min / kn)
    m_min = 2650 * 3.141592653589793 / 6 * 1.0e-9
    assert prep["dt"] == pytest.approx(0.1 * (m_min / 1.0e6) ** 0.5, rel=1e-9)

    rows = read_series(out / "series.txt")
    col = {name: [r[k] for r in rows] for k, name in enumerate(COLUMNS)}
    steps = col["step"]
    assert steps == sorted(set(steps))
    assert all(b - a == int(PROTOCOL["series_every"]) for a, b in zip(steps, steps[1:]))
    ru_max = max(col["r_u"])
    reversals = col["reversals"][-1]
    log = (out / "log.shear.lammps").read_text()
    il = [l for l in log.splitlines() if l.startswith("GRFLOW shear: done")]
    print(f"[ measured ] small protocol: {seconds:.0f} s, e = {prep['e']:.4f}, "
          f"z_g = {prep['z_g']:.3f}, max r_u = {ru_max:.4f}, reversals = {reversals:g}; {il}")
    assert ru_max >= 0.99
    assert il, "the shear stage did not finish"
    # the fix's stop: one cycle after initial liquefaction
    assert "(liquefied)" in log
    # P_c sums to one, the columns are the compute's
    for r in rows[:: max(1, len(rows) // 50)]:
        assert sum(r[COLUMNS.index("P0"):]) == pytest.approx(1.0, abs=1e-4)
    # the inertial number I = (v_x/h) d_mean sqrt(density/p) from p as it is,
    # -1 where p = 0 (undefined); the series' columns hold %.6g and %.10g
    for k in range(len(rows)):
        p, inert = col["p"][k], col["inertial"][k]
        if p > 0.0:
            h = col["zhi"][k] - col["zlo"][k]
            expect = prep["v_x"] / h * prep["d_mean"] * (prep["density"] / p) ** 0.5
            assert inert == pytest.approx(expect, rel=1e-5), (steps[k], p, inert)
        else:
            assert inert == -1.0, (steps[k], p, inert)
    # constant volume: walls and box do not move in z
    assert max(col["zhi"]) - min(col["zhi"]) == 0.0
    assert max(col["zlo"]) - min(col["zlo"]) == 0.0

    # snapshots at every reversal (and zero-crossing), atoms and contacts
    snaps = sorted(out.glob("snapshots/contacts.*.txt"))
    assert len(snaps) >= reversals
    cols, data = read_dump(snaps[-1], "ENTRIES")
    assert cols == ["id1", "id2", "dx", "dy", "dz", "fn", "ftx", "fty", "ftz"]
    assert len(data) > 0
    cols, atoms = read_dump(out / "snapshots/atoms.prep.txt", "ATOMS")
    assert cols == ["id", "type", "radius", "x", "y", "z", "vx", "vy", "vz", "glue"]
    glue = [a[-1] for a in atoms]
    assert glue.count(1.0) == prep["glued_bottom"] > 0
    assert glue.count(2.0) == prep["glued_top"] > 0


def test_fix_events_agree_with_the_series(protocol):
    """N has one owner, fix grflow/shear: events.txt holds its events and
    N_IL, analysis/ takes them from there, and the deck's last message
    prints the same N_IL.  A detection from the series' rows, in the tests
    (grflow_reference), is the independent check: the series
    is sampled every series_every steps at steps where the fix also checks,
    so a reversal is first seen on the first row at or after the fix's
    step, and a zero-crossing or initial liquefaction never on a row before
    the fix's step."""
    out, _ = protocol
    series = ga.read_series(str(out / "series.txt"))
    table = ga.read_events(str(out / "events.txt"))
    fix = ga.run_events(str(out), series)
    ru_liq = json.loads((out / "prep.json").read_text())["ru_liq"]
    own = series_events(series, ru_liq)
    n_rev = int(series["reversals"][-1])
    # the stage ends on the step of its last event and the series' last row
    # may come before it (series_every): an event after the last row has
    # no row, and the series does not show it
    assert all(r is None for r in fix["reversal_rows"][n_rev:])
    assert n_rev >= 4 and len(own["reversal_rows"]) == n_rev
    assert fix["reversal_rows"][:n_rev] == own["reversal_rows"]
    crossings = 0
    for k, row in own["crossing_rows"].items():
        if k > 0 and row is not None:
            assert fix["crossing_rows"][k] is not None and fix["crossing_rows"][k] <= row, k
            crossings += 1
    assert crossings >= 3
    # the counts of the rule: k/2 - 1/4 at reversal k, k/2 at the crossing after it
    for kind, k, n in zip(table["event"][1:], table["reversals"][1:], table["N"][1:]):
        assert n == (0.5 * k - 0.25 if kind == 1 else 0.5 * k)
    # initial liquefaction: the fix's step, N_IL between the events around it
    onset_series = own["onset"]
    assert fix["step_IL"] is not None and fix["step_IL"] <= series["step"][onset_series]
    before = table["step"] <= fix["step_IL"]
    n_a, n_b = table["N"][before][-1], table["N"][~before][0]
    assert n_a <= fix["N_IL"] <= n_b
    # done at the first event with N - N_IL >= n_post (1 here)
    assert table["N"][-1] - fix["N_IL"] >= 1.0 > table["N"][-2] - fix["N_IL"]
    # one number, written out by the fix, read by the summary and the deck
    summ = ga.summary(series, json.loads((out / "prep.json").read_text()), events=fix)
    n_il = next(e["measured"] for e in summ["entries"] if e["name"] == "N_IL")
    assert n_il == fix["N_IL"]
    log = (out / "log.shear.lammps").read_text()
    assert "(N_IL = %.4f)" % n_il in log
    print(f"[ measured ] N_IL: fix {fix['N_IL']:.4f}, from the series' rows "
          f"{ga.cycle_count(series, own)[onset_series]:.4f}")


def check_snapshots_against_series(out):
    """A step's atoms and contacts snapshots are enough to recompute the
    contact network offline: on every snapshot step that has a series row,
    grflow_reference.network_from_snapshot (Python, from the dumps) gives the
    compute's N_p, floaters, N_c, z_g, P_c and a_c (C++, in the run).
    Returns the number of steps compared and of fn = 0 entries left out."""
    series = ga.read_series(str(out / "series.txt"))
    row_of = {int(s): k for k, s in enumerate(series["step"])}
    compared = dropped = 0
    for step, path in ga.list_snapshots(str(out), "contacts"):
        k = row_of.get(step)
        if k is None:
            continue
        atoms = ga.read_dump_atoms(str(out / "snapshots" / f"atoms.{step}.txt"))
        contacts = ga.read_dump_local(path)
        assert atoms["step"] == contacts["step"] == step
        stress = [series[c][k] for c in ("sxx", "syy", "szz", "sxy", "sxz", "syz")]
        net = network_from_snapshot(atoms, contacts, series["zlo"][k], series["zhi"][k],
                                    stress=stress)
        where = f"{out.name} step {step}"
        # counts exactly; the rest to the digits of series.txt (z_g and a_c
        # %.8g, P_c %.6g) and of the dumps (%g: branch vectors to 6 digits)
        assert net["N_p"] == series["N_p"][k], where
        assert net["floaters"] == series["floaters"][k], where
        assert net["N_c"] == series["N_c"][k], where
        assert net["z_g"] == pytest.approx(series["z_g"][k], rel=1e-7), where
        for c in range(13):
            assert net["P"][c] == pytest.approx(series[f"P{c}"][k], abs=1e-6), (where, c)
        assert net["a_c"] == pytest.approx(series["a_c"][k], abs=1e-5), where
        dropped += int((contacts["columns"]["fn"] <= 0.0).sum())
        compared += 1
    print(f"[ measured ] {out.name}: offline network = series on {compared} snapshot steps "
          f"({dropped} overlapping entries with fn = 0 left out)")
    return compared, dropped


def test_snapshots_hold_the_series_network(protocol):
    compared, _ = check_snapshots_against_series(protocol[0])
    # every snapshot step (the fixture writes a row at every check), and
    # enough of them for the comparison to mean something
    assert compared == len(ga.list_snapshots(str(protocol[0]), "contacts"))
    assert compared >= 3


def test_reference_network_by_hand():
    """grflow_reference.network_from_snapshot on a hand-made snapshot: six
    particles between walls at z = 0 and 10 (slab 0.8: z in [1, 9)):
    1-4 free and inside, 5 glued, 6 free but outside the slab.  Contacts:
    1-2 along z, 2-3 along x, 1-5 along z (glued: only 1's end), 3-6 along
    y (only 3's end), 3-4 with fn = 0 (not a contact), so c = 2, 2, 2, 0:
    N_p 4, one floater, N_c = 6/2, z_g = 6/3, and the ends in the fabric
    are 3 along z, 2 along x, 1 along y."""
    atoms = {"columns": {"id": np.array([1, 2, 3, 4, 5, 6.0]),
                         "radius": np.full(6, 0.5),
                         "z": np.array([5.0, 6.0, 6.0, 3.0, 4.0, 9.5]),
                         "glue": np.array([0, 0, 0, 0, 1, 0.0])}}
    pairs = [(1, 2, 0, 0, -1, 5.0), (2, 3, 1, 0, 0, 2.0), (5, 1, 0, 0, -1, 1.0),
             (6, 3, 0, -1, 0, 0.5), (3, 4, 0.9, 0, 0, 0.0)]
    names = ("id1", "id2", "dx", "dy", "dz", "fn")
    contacts = {"columns": {n: np.array([p[k] for p in pairs], dtype=float)
                            for k, n in enumerate(names)}}
    net = network_from_snapshot(atoms, contacts, 0.0, 10.0, slab=0.8, cmax=4,
                                stress=[1.0, 1.0, 4.0, 0.0, 0.0, 0.0])
    assert (net["N_p"], net["floaters"], net["N_c"]) == (4, 1, 3.0)
    assert net["z_g"] == pytest.approx(2.0)
    assert net["z"] == pytest.approx(1.5)
    assert list(net["P"]) == pytest.approx([0.25, 0.0, 0.75, 0.0, 0.0])
    a = 7.5 * (np.diag([2.0, 1.0, 3.0]) / 6.0 - np.eye(3) / 3.0)
    assert net["a"] == pytest.approx(a)
    assert net["a_c"] == pytest.approx(math.sqrt(1.5 * np.sum(a * a)))   # along z, as s
    net = network_from_snapshot(atoms, contacts, 0.0, 10.0, slab=0.8, cmax=4,
                                stress=[4.0, 4.0, 1.0, 0.0, 0.0, 0.0])
    assert net["a_c"] < 0.0
    # a particle inside that overlaps a wall touches it: 4 at z 0.4 -> slab
    # 1.0 makes it inside and in contact with the bottom wall (along z)
    atoms["columns"]["z"][3] = 0.4
    net = network_from_snapshot(atoms, contacts, 0.0, 10.0, slab=1.0, cmax=4)
    assert (net["N_p"], net["floaters"], net["N_c"]) == (5, 0, 4.0)


def test_reference_series_events_between_samples():
    """grflow_reference.series_events: a crossing between samples is on the
    first row with the new sign (N = k/2 there); initial liquefaction on the
    first row with r_u >= ru_liq; the analysis draws N between them."""
    tau = np.array([0, 10, 20, 25, 12, -3, -20, -25, -5, 4, 15, 20, 24]) * 1e3
    rev = np.array([0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2])
    ru = np.array([0.5] * 6 + [0.99] * 7)
    s = {"step": 10.0 * np.arange(13), "time": np.arange(13.0), "reversals": rev,
         "tau": tau, "r_u": ru}
    ev = series_events(s, 0.99)
    assert ev["reversal_rows"] == [3, 7] and ev["crossing_rows"] == {0: 0, 1: 5, 2: 9}
    assert (ev["onset"], ev["step_IL"]) == (6, 60)
    assert ev["N_IL"] == pytest.approx(0.5 + 0.25 / 2, abs=1e-15)
    expect = [0, 1 / 12, 2 / 12, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0,
              1.125, 1.25, 1.25]               # extrapolated, then capped at +1/4
    np.testing.assert_allclose(ga.cycle_count(s, ev), expect, atol=1e-12)


def test_sizes_follow_the_papers_distribution(protocol):
    # number ~ d^-3 on [d_min, d_max] = [1, 2] mm: cumulative distribution
    # F(d) = (1 - d^-2) / (1 - 1/4) (d in mm), number-mean 4/3 mm, median
    # 1/sqrt(0.625) = 1.2649 mm.  (A draw with d^3 uniform instead, number
    # ~ d^2, has mean 1.61 mm and 20% of the spheres below that median.)
    out, _ = protocol
    cols, atoms = read_dump(out / "snapshots/atoms.prep.txt", "ATOMS")
    d = sorted(2e3 * a[cols.index("radius")] for a in atoms)    # mm
    n = len(d)
    assert n == 500
    assert 1.0 - 1e-9 <= d[0] and d[-1] <= 2.0 + 1e-9
    mean = sum(d) / n
    below = sum(1 for x in d if x < 1.0 / 0.625 ** 0.5) / n
    # Kolmogorov-Smirnov distance to F
    ks = max(max(abs((k + 1) / n - F), abs(k / n - F))
             for k, F in ((k, (1.0 - x ** -2) / 0.75) for k, x in enumerate(d)))
    print(f"[ measured ] {n} diameters: mean {mean:.4f} mm (4/3), "
          f"fraction below the median {below:.3f} (0.5), KS distance {ks:.4f}")
    # standard error of the mean: 0.266 mm / sqrt(500) = 0.012 mm
    assert mean == pytest.approx(4.0 / 3.0, abs=0.05)
    assert below == pytest.approx(0.5, abs=0.08)
    # KS critical value at the 0.1% level for n = 500: 1.95 / sqrt(n) = 0.087
    assert ks < 0.087
    prep = json.loads((out / "prep.json").read_text())
    assert prep["d_mean"] == pytest.approx(4.0 / 3.0 * 1e-3, rel=1e-9)


def shear_dir(out, src):
    """A run directory for the shear stage alone, from src's prep.restart."""
    (out / "snapshots").mkdir(parents=True)
    (out / "prep.restart").symlink_to(src / "prep.restart")
    return out


def test_kill_and_resume_gives_one_series(protocol, tmp_path):
    src, _ = protocol
    # shear stage only, from the prepared sample, over a fixed horizon
    common = dict(SMALL, stage="shear", restart_every=4000, max_steps=20000,
                  n_post=1000)

    ref = shear_dir(tmp_path / "ref", src)
    run(ref, **common)
    ref_rows = read_series(ref / "series.txt")

    killed = shear_dir(tmp_path / "killed", src)
    proc = subprocess.Popen(lmp_cmd(killed, **common), stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    deadline = time.time() + 600
    # killed once the restart file exists and the series has a row past it
    # (rows the resumed run must trim), whatever the machine's speed
    while not ((killed / "shear.restart.4000").exists()
               and last_complete_step(killed / "series.txt") > 4000):
        assert proc.poll() is None, "the run ended before its first restart file"
        assert time.time() < deadline
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    before = read_series(killed / "series.txt")
    last_before = before[-1][0]
    restarts = sorted(int(p.name.split(".")[-1]) for p in killed.glob("shear.restart.*[0-9]"))
    print(f"[ measured ] killed at series step {last_before:g}, restart files {restarts}")
    assert last_before < 20000, "killed too late: the run had finished"

    run(killed, resume="yes", **common)
    rows = read_series(killed / "series.txt")
    steps = [r[0] for r in rows]
    ref_steps = [r[0] for r in ref_rows]
    missing = sorted(set(ref_steps) - set(steps))[:10]
    extra = sorted(set(steps) - set(ref_steps))[:10]
    dup = len(steps) - len(set(steps))
    assert steps == ref_steps, f"missing {missing} extra {extra} duplicates {dup}"    # every step once, none lost
    resumed_at = restarts[-1]
    n_same = sum(1 for s in ref_steps if s < resumed_at)
    assert rows[:n_same] == ref_rows[:n_same]
    # at the restart step the state is the restart file's: the same to
    # round-off (the neighbor lists are rebuilt, sums run in another order)
    k = steps.index(resumed_at)
    for name in ("tau", "p", "z_g"):
        c = COLUMNS.index(name)
        assert rows[k][c] == pytest.approx(ref_rows[k][c], rel=1e-9, abs=1e-9), name
    # the elapsed time goes on from the restart file's (a restart file
    # written during a run used to lose the steps since that run's start)
    t = COLUMNS.index("time")
    for r, rr in zip(rows, ref_rows):
        assert r[t] == pytest.approx(rr[t], rel=1e-9), f"time at step {r[0]:g}"
    # later on the round-off grows (a dense packing is chaotic); the protocol
    # state is the same and the stresses are close
    p = COLUMNS.index("p")
    dp = abs(rows[-1][p] / ref_rows[-1][p] - 1.0)
    print(f"[ measured ] resumed at {resumed_at}: relative difference of p at step "
          f"{steps[-1]:g}: {dp:.1e}")
    assert rows[-1][2:4] == ref_rows[-1][2:4]
    assert dp < 0.02
    assert "GRFLOW shear: resuming at step" in (killed / "log.shear.lammps").read_text()

    # resuming the finished run changes nothing (it used to trim the series
    # at the last restart file's step and run on from there)
    series = (killed / "series.txt").read_text()
    files = sorted(p.name for p in killed.glob("shear.restart.*[0-9]"))
    run(killed, resume="yes", **common)
    assert (killed / "series.txt").read_text() == series
    assert sorted(p.name for p in killed.glob("shear.restart.*[0-9]")) == files
    assert ("had finished at step 20000; nothing to resume"
            in (killed / "log.shear.lammps").read_text())


def test_normal_force_reaches_pair_and_walls(protocol, tmp_path):
    """-var normal_force unclipped in a shear stage from a clipped
    preparation: the pair style and the walls take the unclipped law (the
    walls warn when their law is not the pair style's: no warning), and
    the run differs from the clipped one (the unclipped law pulls where
    the dashpot outweighs the spring)."""
    src, _ = protocol
    common = dict(SMALL, stage="shear", max_steps=2000, n_post=1000)
    rows = {}
    for law in ("clipped", "unclipped"):
        out = shear_dir(tmp_path / law, src)
        proc = run(out, normal_force=law, **common)
        text = proc.stdout + proc.stderr + (out / "log.shear.lammps").read_text()
        assert "is not the pair style's normal_force" not in text
        rows[law] = read_series(out / "series.txt")
    assert rows["clipped"][-1] != rows["unclipped"][-1]


def test_resume_keeps_the_stage_settings(protocol, tmp_path):
    """The shear stage records its settings in shear.json when it starts;
    a resume that gives another contact law, wall speed or damping stops
    with an error naming each, and leaves the run as it was; a resume with
    the same values (here written otherwise: 1e-2 for 0.01) goes on."""
    src, _ = protocol
    common = dict(SMALL, stage="shear", restart_every=1000, max_steps=2000, n_post=1000)
    out = shear_dir(tmp_path / "run", src)
    run(out, v_x=0.01, normal_force="clipped", **common)
    record = json.loads((out / "shear.json").read_text())
    assert record["normal_force"] == "clipped" and record["v_x"] == 0.01
    assert record["pair"] == "grflow" and record["cundall_l"] == 0.0
    series = (out / "series.txt").read_text()

    proc = subprocess.run(lmp_cmd(out, resume="yes", v_x=0.02, normal_force="unclipped",
                                  **common), capture_output=True, text=True, timeout=300)
    text = proc.stdout + proc.stderr + (out / "log.shear.lammps").read_text()
    assert proc.returncode != 0
    assert "normal_force unclipped (the stage has clipped)" in text
    assert "v_x 0.02 (the stage has 0.01)" in text
    assert (out / "series.txt").read_text() == series
    assert json.loads((out / "shear.json").read_text()) == record

    run(out, resume="yes", v_x="1e-2", normal_force="clipped", **common)
    assert "nothing to resume" in (out / "log.shear.lammps").read_text()
    assert (out / "series.txt").read_text() == series

    # a restart file copied into a directory without shear.json (as
    # bench/shear_ab.sh does): the resume writes it, says so, and goes on
    copy = tmp_path / "copy"
    (copy / "snapshots").mkdir(parents=True)
    (copy / "prep.json").write_bytes((src / "prep.json").read_bytes())
    for name in ("shear.restart.1000", "shear.restart.1000.cksum"):
        (copy / name).write_bytes((out / name).read_bytes())
    run(copy, resume="yes", normal_force="unclipped", **dict(common, max_steps=1500))
    assert "shear.json was missing" in (copy / "log.shear.lammps").read_text()
    assert json.loads((copy / "shear.json").read_text())["normal_force"] == "unclipped"


def test_shear_rate_sets_the_wall_speed(protocol, tmp_path):
    """-var shear_rate G: the top wall moves at v_x = G h, h the wall gap
    (zhi - zlo, constant in the shear stage), whatever v_x says.  Checked
    on the wall's own path in the series."""
    src, _ = protocol
    G = 3.7
    out = shear_dir(tmp_path / "rate", src)
    run(out, shear_rate=G, v_x=123.0, **dict(SMALL, stage="shear", max_steps=2000,
                                                 n_post=1000))
    h, speed = first_leg_wall_speed(read_series(out / "series.txt"))
    assert speed == pytest.approx(G * h, rel=1e-7)
    said = re.search(r"GRFLOW shear: v_x = (\S+) m/s", (out / "log.shear.lammps").read_text())
    # the log's v_x is G times the gap read from the series' 12-digit zlo, zhi
    assert float(said.group(1)) == pytest.approx(G * h, rel=1e-9)


def test_resume_before_the_first_restart_file(protocol, tmp_path):
    """A shear stage killed before its first periodic restart file resumes
    from shear.restart.0 (the copy of prep.restart the stage makes when it
    starts): the stage starts again, says so, and writes series.txt anew.
    The commands after read_restart are the same as a fresh start's, so
    the series equals an uninterrupted run's to the last digit."""
    src, _ = protocol
    common = dict(SMALL, stage="shear", restart_every=1000000, max_steps=40000,
                  n_post=1000)

    ref = shear_dir(tmp_path / "ref", src)
    run(ref, **common)
    ref_text = (ref / "series.txt").read_text()
    assert (ref / "shear.restart.0").read_bytes() == (src / "prep.restart").read_bytes()

    killed = shear_dir(tmp_path / "killed", src)
    proc = subprocess.Popen(lmp_cmd(killed, **common), stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    deadline = time.time() + 600
    series = killed / "series.txt"
    # (lines, not parsed rows: the last line may be half written)
    while not (series.exists() and series.read_text().count("\n") >= 20):
        assert proc.poll() is None, "the run ended before it was killed"
        assert time.time() < deadline
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    restarts = sorted(p.name for p in killed.glob("shear.restart.*[0-9]"))
    assert restarts == ["shear.restart.0"], restarts
    assert read_series(series)[-1][0] < 40000, "killed too late: the run had finished"

    run(killed, resume="yes", **common)
    assert read_series(series) == read_series(ref / "series.txt")
    assert series.read_text().count("# step") == ref_text.count("# step")
    assert ("starting it again from prep.restart"
            in (killed / "log.shear.lammps").read_text())


def test_stock_deck_runs_the_protocol(protocol, tmp_path):
    """inputs/cyclic_shear_stock.lmp: the same small protocol with stock
    pair granular (the same law) prepares a packing like granular/grflow's
    at the same stress and liquefies.  (Its servo reads the elastic energy
    from a variable.  With mu_prep 0.0407 instead of the preset's 0.15, a
    stock preparation of 500 spheres sat in a servo overshoot cycle for
    millions of steps before fix grflow/compress damped them.)"""
    out = tmp_path / "stock"
    t0 = time.time()
    run(out, deck=STOCK_DECK, **SMALL)
    seconds = time.time() - t0
    prep = json.loads((out / "prep.json").read_text())
    ref = json.loads((protocol[0] / "prep.json").read_text())
    assert prep["pair_stock"] == 1 and ref["pair_stock"] == 0
    assert "(1) pair granular, perpetual" in (out / "log.prep.lammps").read_text()
    rows = read_series(out / "series.txt")
    ru_max = max(r[COLUMNS.index("r_u")] for r in rows)
    print(f"[ measured ] stock deck: {seconds:.0f} s, e = {prep['e']:.4f} "
          f"(granular/grflow {ref['e']:.4f}), z_g = {prep['z_g']:.3f} ({ref['z_g']:.3f}), "
          f"p = {prep['p']:.0f} Pa, max r_u = {ru_max:.4f}")
    assert abs(prep["p"] - 1.0e5) < 0.15e5
    # one sample each of a chaotic process: alike, not equal.  Bounds: 4
    # standard deviations of the difference of two samples, from the
    # scatter over 6 seeds of this preparation (doc/studies/prep-scatter.md, "Scatter
    # of the small preparation": e sd 0.0176, z_g sd 0.050, so 4 sqrt(2) sd)
    assert abs(prep["e"] - ref["e"]) < 4 * 2 ** 0.5 * 0.0176
    assert abs(prep["z_g"] - ref["z_g"]) < 4 * 2 ** 0.5 * 0.050
    assert ru_max >= 0.99
    assert "GRFLOW shear: done" in (out / "log.shear.lammps").read_text()
    # its contacts snapshots carry the normal force too (pair/local's
    # "force" is f_n for both styles; p15 is GRFLOW's alone)
    assert check_snapshots_against_series(out)[0] >= 3


def test_agitation_keeps_density_lowers_coordination(tmp_path):
    """Stage 2b (inputs/agitate.lmp): after the mu_prep compression, a
    dilation, agitation and recompression with mu_rec give about the same
    void ratio with clearly fewer contacts; without it (agitate_dilation 1)
    the mu_prep packing is kept."""
    common = dict(preset="quick", N=500, mu_prep=0.0407, stage="prep")
    states = {}
    for name, dil in (("plain", 1.0), ("agitated", 1.003)):
        out = tmp_path / name
        run(out, agitate_dilation=dil, mu_rec=0.25, **common)
        prep = json.loads((out / "prep.json").read_text())
        assert prep["agitate_dilation"] == dil and prep["mu_rec"] == 0.25
        log = (out / "log.prep.lammps").read_text()
        assert ("recompressed with mu_rec" in log) == (dil > 1.0)
        states[name] = prep
    plain, agitated = states["plain"], states["agitated"]
    print(f"[ measured ] N = 500: plain e = {plain['e']:.4f}, z_g = {plain['z_g']:.3f}; "
          f"agitated (1.003, mu_rec 0.25) e = {agitated['e']:.4f}, z_g = {agitated['z_g']:.3f}")
    # bounds: the mean plus or minus 4 standard deviations of the
    # differences agitated - plain of 6 seeds (doc/studies/prep-scatter.md, "Scatter of
    # the small preparation": e +0.0079 sd 0.0007, z_g -1.262 sd 0.109)
    assert abs(agitated["e"] - plain["e"]) < 0.0079 + 4 * 0.0007
    assert agitated["z_g"] < plain["z_g"] - (1.262 - 4 * 0.109)
    assert abs(agitated["p"] - 1.0e5) < 0.15e5


# Table 1's other coefficients as -var ratios, chosen off their defaults
RATIOS = {"kt_kn": 0.5, "ct_cn": 0.25, "kr_kn": 0.2, "cr_cn": 0.125, "mu_r": 0.3,
          "ko_kn": 0.25, "co_cn": 0.0625, "mu_o": 0.2}


def echoed(log, start):
    """The commands in the log (echoed after variable substitution) that
    start with start, each as a list of words."""
    found = [l.split() for l in log.splitlines() if l.startswith(start) and "$" not in l]
    assert found, f"no '{start}' command in the log"
    return found


def keywords(words):
    """keyword -> value of the 'keyword number' pairs in a command"""
    out = {}
    for k, v in zip(words, words[1:]):
        try:
            out.setdefault(k, float(v))
        except ValueError:
            pass
    return out


def check_coefficients(pair, wall, want, stock, a):
    """pair_coeff and fix grflow/wall commands (word lists) against the
    coefficients want (grflow keyword names); a = reduced radius a'"""
    for k, v in want.items():
        assert keywords(wall)[k] == pytest.approx(v, rel=1e-12), k
    if not stock:
        for k, v in want.items():
            assert keywords(pair)[k] == pytest.approx(v, rel=1e-12), k
        return
    # hooke kn cn ... linear_history kt ct/cn mu rolling sds kr cr mur
    # twisting sds ko a'^2 co a'^2 muo a'
    i = pair.index("linear_history")
    assert [float(v) for v in pair[i + 1:i + 4]] == pytest.approx(
        [want["kt"], want["ct"] / 1.15, want["mut"]], rel=1e-12)
    i = pair.index("rolling")
    assert [float(v) for v in pair[i + 2:i + 5]] == pytest.approx(
        [want["kr"], want["cr"], want["mur"]], rel=1e-12)
    i = pair.index("twisting")
    assert [float(v) for v in pair[i + 2:i + 5]] == pytest.approx(
        [want["ko"] * a * a, want["co"] * a * a, want["muo"] * a], rel=1e-9)


@pytest.mark.parametrize("deck", [DECK, STOCK_DECK], ids=["grflow", "stock"])
def test_contact_ratios_reach_particles_and_walls(tmp_path, deck):
    """-var kt_kn ... mu_o set the pair coefficients and the walls' alike
    (kn = 1e6 N/m, cn = 1.15 kg/s by default), in every stage: every
    coefficient in the commands the deck ran, as LAMMPS echoed them, first
    with mu_prep, then after the switch to mu_t, then in the shear stage
    (a new pair style and walls after read_restart); prep.json records
    them."""
    out = tmp_path / "run"
    cmd = lmp_cmd(out, deck=deck, preset="quick", N=200, max_steps=500, **RATIOS)
    cmd[cmd.index("-echo") + 1] = "log"
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, (proc.stdout[-2000:] + proc.stderr[-2000:]
                                  + tail(out / "log.prep.lammps") + tail(out / "log.shear.lammps"))
    prep = json.loads((out / "prep.json").read_text())
    for k, v in RATIOS.items():
        assert prep[k] == v, k
    assert prep["kn"] == 1.0e6 and prep["cn"] == 1.15
    kn, cn = 1.0e6, 1.15
    want = {"kt": 0.5 * kn, "ct": 0.25 * cn, "kr": 0.2 * kn, "cr": 0.125 * cn, "mur": 0.3,
            "ko": 0.25 * kn, "co": 0.0625 * cn, "muo": 0.2}
    stock, a = deck == STOCK_DECK, prep["d_mean"] / 4
    wall_cmd, pair_cmd = "fix             walls all grflow/wall", "pair_coeff * *"
    log = (out / "log.prep.lammps").read_text()
    pairs = echoed(log, pair_cmd)
    check_coefficients(pairs[0], echoed(log, wall_cmd)[0], dict(want, mut=0.15), stock, a)
    # the switch to mu_t (prepare.lmp, stage 3)
    last = pairs[-1]
    mut = float(last[last.index("linear_history") + 3]) if stock else keywords(last)["mut"]
    assert mut == 0.5
    assert echoed(log, "fix_modify      walls mut")[-1][-1] == "0.5"
    # the shear stage's walls act on the free particles (shear.lmp)
    log = (out / "log.shear.lammps").read_text()
    check_coefficients(echoed(log, pair_cmd)[0],
                       echoed(log, "fix             walls free grflow/wall")[0],
                       dict(want, mut=0.5), stock, a)


@pytest.mark.parametrize("var,expect", [
    ({"preset": "fast"}, "unknown preset fast"),
    ({"stage": "both"}, "unknown stage both"),
    ({"pair": "hertz"}, "unknown pair hertz"),
    ({"resume": "yes", "stage": "prep"}, "cannot go with stage prep"),
    ({"agitate_dilation": "0.99"}, "agitate_dilation 0.99 must be >= 1"),
    ({"kt_kn": "-0.5"}, "kt must be >= 0, got -500000"),
    ({"N": "0"}, "N 0 must be a whole number >= 1"),
    ({"N": "100.5"}, "N 100.5 must be a whole number >= 1"),
    ({"N": "many"}, "ERROR: not a number: N 'many'"),
    ({"v_x": "1e-2x", "tau_amp": "25k"}, "not a number: v_x '1e-2x', tau_amp '25k'"),
    ({"d_min": "2e-3", "d_max": "1e-3"}, "need 0 < d_min <= d_max"),
    ({"dt_factor": "0"}, "dt_factor 0 must be > 0"),
    ({"dt_factor_shear": "-0.1"}, "dt_factor_shear -0.1 must be > 0"),
    ({"glue_gap": "-1e-4"}, "glue_gap -1e-4 must be >= 0"),
    ({"tau_amp": "0"}, "tau_amp 0 must be > 0"),
    ({"v_x": "0"}, "v_x 0 must be > 0"),
    ({"shear_rate": "-0.38"}, "shear_rate -0.38 must be >= 0"),
    ({"shear_rate": "fast"}, "ERROR: not a number: shear_rate 'fast'"),
    ({"skin_factor": "0"}, "skin_factor 0 must be > 0"),
    ({"check_every": "0"}, "each must be >= 1"),
    ({"max_cycles": "-1"}, "max_cycles -1 must be >= 0"),
    ({"newton_pair": "maybe"}, "newton_pair maybe: use on or off"),
    ({"normal_force": "maybe"}, "normal_force maybe: use clipped or unclipped"),
])
def test_bad_parameters(tmp_path, var, expect):
    proc = subprocess.run(lmp_cmd(tmp_path / "bad", screen=True, **var), capture_output=True,
                          text=True,
                          timeout=120)
    text = proc.stdout + proc.stderr + tail(tmp_path / "bad" / "log.prep.lammps")
    assert proc.returncode != 0
    assert expect in text


def test_every_numeric_parameter_is_checked():
    """params.lmp hands every index variable with a numeric default to
    check_numbers.sh (which names a -var value that is no number): a new
    numeric parameter left out of that list fails here."""
    text = open(os.path.join(INPUTS, "params.lmp")).read()
    number = re.compile(r"^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$")
    numeric = {m.group(1) for m in re.finditer(r"^variable\s+(\S+)\s+index\s+(\S+)", text, re.M)
               if number.match(m.group(2))}
    numeric.add("cundall_a")    # its default is ${cundall_l}
    call = text[text.index("check_numbers.sh"):text.index("include         ${outdir}/numbers.lmp")]
    words = call.replace("&", " ").split()[2:]
    checked = dict(zip(words[0::2], words[1::2]))
    assert set(checked) == numeric
    assert all(v == "${" + k + "}" for k, v in checked.items())


def test_outdir_with_whitespace(tmp_path):
    """A space would split outdir into two words in the decks' file names and
    shell commands (mkdir would make two directories): an error first."""
    for name in ("two words", "tab\there"):
        outdir = tmp_path / name
        proc = subprocess.run(lmp_cmd(outdir, screen=True, preset="quick"), capture_output=True,
                              text=True, timeout=120, cwd=tmp_path)
        assert proc.returncode != 0
        assert f"outdir {outdir} contains whitespace" in proc.stdout + proc.stderr
        # nothing was made: neither the directory nor pieces of its name
        assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_sample_too_small(tmp_path):
    """20 spheres compress into a cell narrower than 2 d_max (two spheres
    would touch through two periodic images at once): the preparation stops
    with the sizes, before prep.restart; 30 spheres make a cell wide enough."""
    proc = subprocess.run(lmp_cmd(tmp_path / "n20", screen=True, preset="quick", N=20),
                          capture_output=True, text=True, timeout=120)
    text = proc.stdout + proc.stderr
    assert proc.returncode != 0
    assert "the sample of N = 20 spheres is too small" in text
    assert "each must be >= 2 d_max = 0.004" in text
    assert not (tmp_path / "n20" / "prep.restart").exists()
    run(tmp_path / "n30", preset="quick", N=30, stage="prep", timeout=120)
    assert (tmp_path / "n30" / "prep.restart").exists()
