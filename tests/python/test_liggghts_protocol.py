"""The LIGGGHTS decks (inputs/liggghts/cyclic_shear.liggghts) end to end, on
a small case, as tests/python/test_protocol.py checks the LAMMPS decks.

1. The whole protocol (quick preset, 300 spheres, tau_amp = 40 kPa so that
   it liquefies within a few cycles): it prepares the sample, shears it
   through initial liquefaction and one cycle more, and every output file
   parses in the format of inputs/README.md, through analysis/'s readers.
   The sample is the LAMMPS decks' (sizes from the same formula, IDs on
   the same sites); fix grflow/shear's events are in events.txt; the
   snapshots hold the series' network.
2. 2 MPI ranks: the same decks run and write the same files.
3. Kill and resume (-var resume yes): one series, every output step once,
   identical to an uninterrupted run (LIGGGHTS's decks write their restart
   files between run segments, so a resumed run starts as the uninterrupted
   one went on); a resume before the first restart file starts the stage
   again; resuming a finished run changes nothing.
4. -var calibrate yes finds mu_prep by inputs/calibrate.lmp's rule; stage
   2b (agitation) runs; the contact law's ratios reach particles and walls.
5. Bad parameters stop with params.lmp's messages (inputs/liggghts/params.sh
   gives params.lmp to LIGGGHTS), and with the LIGGGHTS decks' own.

Environment: LIGGGHTS (a liggghts built with GRFLOW,
scripts/build-liggghts.sh), MPIEXEC, GRFLOW_INPUTS (the inputs/ directory).
"""

import json
import math
import os
import re
import signal
import subprocess
import time

import pytest

import grflow_analysis as ga
from grflow_reference import network_from_snapshot, series_events
from runfiles import (COLUMNS, first_leg_wall_speed, last_complete_step, read_dump,
                      read_series, tail)

LIGGGHTS = os.environ.get("LIGGGHTS", "liggghts")
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
INPUTS = os.path.abspath(os.environ.get(
    "GRFLOW_INPUTS", os.path.join(os.path.dirname(__file__), "..", "..", "inputs")))
DECK = os.path.join(INPUTS, "liggghts", "cyclic_shear.liggghts")
# the quick preset with 300 spheres and a larger amplitude: initial
# liquefaction within a few cycles
SMALL = {"preset": "quick", "N": "300", "tau_amp": "40e3", "n_post": "1",
         "series_every": "50", "max_steps": "1000000"}


def liggghts_cmd(outdir, cache, screen=False, nprocs=1, **var):
    cmd = [LIGGGHTS, "-echo", "none", "-log", "none", "-in", DECK,
           "-var", "inputs", INPUTS, "-var", "outdir", str(outdir),
           "-var", "grflow_cache", str(cache)]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    if not screen:
        cmd += ["-screen", "none"]
    if nprocs > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    return cmd


def run(outdir, cache, timeout=900, nprocs=1, **var):
    proc = subprocess.run(liggghts_cmd(outdir, cache, nprocs=nprocs, **var),
                          capture_output=True, text=True, errors="replace", timeout=timeout)
    assert proc.returncode == 0, (proc.stdout[-3000:] + proc.stderr[-3000:]
                                  + tail(outdir / "log.shear.lammps")
                                  + tail(outdir / "log.prep.lammps"))
    return proc


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    """the decks' generated files (params.sh, is.sh) in a directory of the test"""
    return tmp_path_factory.mktemp("cache")


@pytest.fixture(scope="module")
def protocol(tmp_path_factory, cache):
    out = tmp_path_factory.mktemp("protocol") / "run"
    t0 = time.time()
    run(out, cache, **SMALL)
    return out, time.time() - t0


def test_whole_protocol_reaches_liquefaction(protocol):
    out, seconds = protocol
    prep = json.loads((out / "prep.json").read_text())
    for key in ("N", "seed", "d_min", "d_max", "d_mean", "density", "kn", "cn", "mu_prep",
                "agitate_dilation", "mu_rec", "mu_t", "pair_stock", "p_target", "e", "z_g",
                "p", "sxx", "syy", "szz", "Lx", "Ly", "h", "glued_bottom", "glued_top",
                "step", "time", "dt", "tau_amp", "v_x", "ru_liq", "n_post"):
        assert key in prep, key
    assert prep["N"] == 300 and prep["pair_stock"] == 0 and prep["tau_amp"] == 40e3
    assert abs(prep["p"] - 1.0e5) < 0.15e5
    assert 0.5 < prep["e"] < 1.0
    m_min = 2650 * math.pi / 6 * 1.0e-9
    assert prep["dt"] == pytest.approx(0.1 * (m_min / 1.0e6) ** 0.5, rel=1e-9)
    # the time since the start of the preparation: step * dt (one timestep)
    assert prep["time"] == pytest.approx(prep["step"] * prep["dt"], rel=1e-9)

    rows = read_series(out / "series.txt")
    col = {name: [r[k] for r in rows] for k, name in enumerate(COLUMNS)}
    steps = col["step"]
    assert steps[0] == 0.0 and steps == sorted(set(steps))
    assert all(b - a == 50 for a, b in zip(steps, steps[1:]))
    # the time since shearing started (LIGGGHTS's restart files keep no
    # time: the decks' time is step * dt, with the shear stage's dt, the
    # preparation's times dt_factor_shear / dt_factor of params.lmp)
    params = open(os.path.join(INPUTS, "params.lmp")).read()
    factor = {k: float(re.search(rf"^variable\s+{k}\s+index\s+(\S+)", params, re.M).group(1))
              for k in ("dt_factor", "dt_factor_shear")}
    dt_shear = prep["dt"] * factor["dt_factor_shear"] / factor["dt_factor"]
    assert all(t == pytest.approx(s * dt_shear, rel=1e-9, abs=1e-15)
               for s, t in zip(steps, col["time"]))
    ru_max = max(col["r_u"])
    log = (out / "log.shear.lammps").read_text()
    done = [l for l in log.splitlines() if l.startswith("GRFLOW shear: done")]
    print(f"[ measured ] LIGGGHTS small protocol: {seconds:.0f} s, e = {prep['e']:.4f}, "
          f"z_g = {prep['z_g']:.3f}, max r_u = {ru_max:.4f}, "
          f"reversals = {col['reversals'][-1]:g}; {done}")
    assert ru_max >= 0.99
    assert done and "N_IL = " in done[0], "the shear stage did not finish after liquefaction"
    # the fix's progress lines reach the log (from the segments' log)
    assert "(liquefied)" in log
    assert not (out / "log.shear.segments").exists()
    assert not (out / "events.pending").exists()
    for r in rows[:: max(1, len(rows) // 50)]:
        assert sum(r[COLUMNS.index("P0"):]) == pytest.approx(1.0, abs=1e-9)
    # the inertial number from p as it is, -1 where p = 0
    for k in range(len(rows)):
        p, inert = col["p"][k], col["inertial"][k]
        if p > 0.0:
            h = col["zhi"][k] - col["zlo"][k]
            expect = prep["v_x"] / h * prep["d_mean"] * (prep["density"] / p) ** 0.5
            assert inert == pytest.approx(expect, rel=1e-9), (steps[k], p, inert)
        else:
            assert inert == -1.0, (steps[k], p, inert)
    assert max(col["zhi"]) - min(col["zhi"]) == 0.0
    assert max(col["zlo"]) - min(col["zlo"]) == 0.0

    # snapshots at every event, atoms and contacts, in the LAMMPS decks' columns
    snaps = sorted(out.glob("snapshots/contacts.*.txt"))
    assert len(snaps) >= col["reversals"][-1]
    cols, data = read_dump(snaps[-1], "ENTRIES")
    assert cols == ["id1", "id2", "dx", "dy", "dz", "fn", "ftx", "fty", "ftz"]
    assert len(data) > 0
    assert not list(out.glob("snapshots/contacts.raw.*"))
    cols, atoms = read_dump(out / "snapshots/atoms.prep.txt", "ATOMS")
    assert cols == ["id", "type", "radius", "x", "y", "z", "vx", "vy", "vz", "glue"]
    glue = [a[-1] for a in atoms]
    assert glue.count(1.0) == prep["glued_bottom"] > 0
    assert glue.count(2.0) == prep["glued_top"] > 0


def test_the_sample_is_the_lammps_decks(protocol):
    """IDs 1..N, and each sphere's diameter the formula of prepare.lmp of
    its ID and the seed (the dump's 6 digits)."""
    out, _ = protocol
    prep = json.loads((out / "prep.json").read_text())
    cols, atoms = read_dump(out / "snapshots/atoms.prep.txt", "ATOMS")
    ids = [int(a[0]) for a in atoms]
    assert ids == list(range(1, prep["N"] + 1))
    dmin, dmax, seed = prep["d_min"], prep["d_max"], prep["seed"]
    for a in atoms:
        u = abs(math.sin(a[0] * 12.9898 + seed * 78.233)) * 43758.5453
        d = (dmin ** -2 - (u - math.floor(u)) * (dmin ** -2 - dmax ** -2)) ** -0.5
        assert 2.0 * a[cols.index("radius")] == pytest.approx(d, rel=2e-6), a[0]


def test_fix_events_agree_with_the_series(protocol):
    """events.txt holds fix grflow/shear's events at their own steps (from
    the checks, not the run segments) and N_IL; the analysis's detection
    from the series agrees; the deck's last message has the same N_IL."""
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
    for k, row in own["crossing_rows"].items():
        if k > 0 and row is not None:
            assert fix["crossing_rows"][k] is not None and fix["crossing_rows"][k] <= row, k
    assert all(s % 10 == 0 for s in table["step"])    # on the checks (check_every 10)
    for kind, k, n in zip(table["event"][1:], table["reversals"][1:], table["N"][1:]):
        assert n == (0.5 * k - 0.25 if kind == 1 else 0.5 * k)
    onset_series = own["onset"]
    assert fix["step_IL"] is not None and fix["step_IL"] <= series["step"][onset_series]
    before = table["step"] <= fix["step_IL"]
    assert table["N"][before][-1] <= fix["N_IL"] <= table["N"][~before][0]
    # done at the first event with N - N_IL >= n_post (1 here), and the
    # stage ended on that event's step (segments of check_every steps): its
    # last restart file is of that step, its last series row at most
    # series_every (50) steps before
    assert table["N"][-1] - fix["N_IL"] >= 1.0 > table["N"][-2] - fix["N_IL"]
    last = int(table["step"][-1])
    assert (out / f"shear.restart.{last}").exists()
    assert last - 50 < series["step"][-1] <= last
    summ = ga.summary(series, json.loads((out / "prep.json").read_text()), events=fix)
    n_il = next(e["measured"] for e in summ["entries"] if e["name"] == "N_IL")
    assert n_il == fix["N_IL"]
    log = (out / "log.shear.lammps").read_text()
    done = next(l for l in log.splitlines() if l.startswith("GRFLOW shear: done"))
    assert float(done.split("N_IL = ")[1].rstrip(")")) == pytest.approx(n_il, rel=1e-12)


def check_snapshots_against_series(out):
    """On every snapshot step with a series row, grflow_reference.network_from_snapshot
    gives the compute's counts exactly and z_g, P_c, a_c to round-off (the
    LIGGGHTS contacts files have 10 digits)."""
    series = ga.read_series(str(out / "series.txt"))
    row_of = {int(s): k for k, s in enumerate(series["step"])}
    table = ga.read_events(str(out / "events.txt"))
    events = set(int(s) for s in table["step"][1:])
    compared = 0
    snaps = ga.list_snapshots(str(out), "contacts")
    # one pair of snapshots per event, on the event's step
    assert set(s for s, _ in snaps) == events
    assert set(s for s, _ in ga.list_snapshots(str(out), "atoms")) == events
    for step, path in snaps:
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
        assert net["N_p"] == series["N_p"][k], where
        assert net["floaters"] == series["floaters"][k], where
        assert net["N_c"] == series["N_c"][k], where
        assert net["z_g"] == pytest.approx(series["z_g"][k], rel=1e-12), where
        for c in range(13):
            assert net["P"][c] == pytest.approx(series[f"P{c}"][k], abs=1e-12), (where, c)
        assert net["a_c"] == pytest.approx(series["a_c"][k], abs=1e-8), where
        compared += 1
    print(f"[ measured ] {out.name}: offline network = series on {compared} snapshot steps")
    return compared


def test_snapshots_hold_the_series_network(protocol):
    assert check_snapshots_against_series(protocol[0]) >= 3


def test_two_ranks(tmp_path, cache):
    """The decks on 2 MPI ranks: the preparation and a shear stage of 20000
    steps write the same files (the run differs from the 1-rank one in
    round-off only, which the packing amplifies)."""
    out = tmp_path / "np2"
    run(out, cache, nprocs=2, **dict(SMALL, max_steps=20000))
    prep = json.loads((out / "prep.json").read_text())
    assert prep["N"] == 300 and abs(prep["p"] - 1.0e5) < 0.15e5
    rows = read_series(out / "series.txt")
    assert [r[0] for r in rows] == [50.0 * k for k in range(401)]
    assert check_snapshots_against_series(out) >= 1
    assert "done at step 20000" in (out / "log.shear.lammps").read_text()


def without_time(rows):
    """the rows without the time column: LIGGGHTS sums the time of each run
    segment (update_time), and a restart file keeps none (the time is then
    step * dt): the same to the last digits only"""
    t = COLUMNS.index("time")
    return [r[:t] + r[t + 1:] for r in rows]


def shear_dir(out, src):
    (out / "snapshots").mkdir(parents=True)
    (out / "prep.restart").symlink_to(src / "prep.restart")
    return out


def kill_when(proc, ready, deadline_s=600):
    deadline = time.time() + deadline_s
    while not ready():
        assert proc.poll() is None, "the run ended before it was killed"
        assert time.time() < deadline
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()


def test_kill_and_resume_gives_one_series(protocol, tmp_path, cache):
    src, _ = protocol
    common = dict(SMALL, stage="shear", restart_every=4000, max_steps=20000, n_post=1000)
    ref = shear_dir(tmp_path / "ref", src)
    run(ref, cache, **common)
    ref_rows = read_series(ref / "series.txt")

    killed = shear_dir(tmp_path / "killed", src)
    proc = subprocess.Popen(liggghts_cmd(killed, cache, **common), stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    kill_when(proc, lambda: (killed / "shear.restart.4000").exists()
              and last_complete_step(killed / "series.txt") > 4000)
    assert read_series(killed / "series.txt")[-1][0] < 20000, "killed too late"
    restarts = sorted(int(p.name.split(".")[-1]) for p in killed.glob("shear.restart.*[0-9]"))
    print(f"[ measured ] killed after restart files {restarts}")

    run(killed, cache, resume="yes", **common)
    rows = read_series(killed / "series.txt")
    # every step once, and the very rows of the uninterrupted run: the
    # decks write their restart files between segments and start the next
    # segment with a setup, as the resumed run does
    assert [r[0] for r in rows] == [r[0] for r in ref_rows]
    assert without_time(rows) == without_time(ref_rows)
    t = COLUMNS.index("time")
    for r, rr in zip(rows, ref_rows):
        assert r[t] == pytest.approx(rr[t], rel=1e-12), r[0]
    events, ref_events = (ga.read_events(str(d / "events.txt")) for d in (killed, ref))
    for name in ("step", "event", "reversals", "N", "N_IL", "step_IL"):
        assert list(events[name]) == list(ref_events[name]), name
    assert list(events["time"]) == pytest.approx(list(ref_events["time"]), rel=1e-12)
    assert "GRFLOW shear: resuming at step" in (killed / "log.shear.lammps").read_text()

    # resuming the finished run changes nothing
    series = (killed / "series.txt").read_text()
    files = sorted(p.name for p in killed.glob("shear.restart.*[0-9]"))
    run(killed, cache, resume="yes", **common)
    assert (killed / "series.txt").read_text() == series
    assert sorted(p.name for p in killed.glob("shear.restart.*[0-9]")) == files
    assert ("had finished at step 20000; nothing to resume"
            in (killed / "log.shear.lammps").read_text())


def test_shear_rate_sets_the_wall_speed(protocol, tmp_path, cache):
    """-var shear_rate G: the top wall moves at v_x = G h (h the wall gap),
    whatever v_x says, as in the LAMMPS decks."""
    src, _ = protocol
    G = 3.7
    out = shear_dir(tmp_path / "rate", src)
    run(out, cache, shear_rate=G, v_x=123.0, **dict(SMALL, stage="shear", max_steps=2000,
                                                        n_post=1000))
    h, speed = first_leg_wall_speed(read_series(out / "series.txt"))
    assert speed == pytest.approx(G * h, rel=1e-7)


def test_resume_before_the_first_restart_file(protocol, tmp_path, cache):
    src, _ = protocol
    common = dict(SMALL, stage="shear", restart_every=1000000, max_steps=20000, n_post=1000)
    ref = shear_dir(tmp_path / "ref", src)
    run(ref, cache, **common)
    assert (ref / "shear.restart.0").read_bytes() == (src / "prep.restart").read_bytes()

    killed = shear_dir(tmp_path / "killed", src)
    proc = subprocess.Popen(liggghts_cmd(killed, cache, **common), stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    series = killed / "series.txt"
    kill_when(proc, lambda: series.exists() and series.read_text().count("\n") >= 20)
    assert sorted(p.name for p in killed.glob("shear.restart.*[0-9]")) == ["shear.restart.0"]
    run(killed, cache, resume="yes", **common)
    assert without_time(read_series(series)) == without_time(read_series(ref / "series.txt"))
    assert series.read_text().count("# step") == 1
    assert "starting it again from prep.restart" in (killed / "log.shear.lammps").read_text()


def test_resume_keeps_the_stage_settings(protocol, tmp_path, cache):
    """As in LAMMPS (inputs/shear_record.sh, shared): shear.json records
    the stage's settings; a resume with another contact law or wall speed
    stops with an error naming them and leaves the run as it was; one with
    the same values goes on."""
    src, _ = protocol
    common = dict(SMALL, stage="shear", restart_every=1000, max_steps=2000, n_post=1000)
    out = shear_dir(tmp_path / "run", src)
    run(out, cache, v_x=0.01, normal_force="clipped", **common)
    record = json.loads((out / "shear.json").read_text())
    assert record["normal_force"] == "clipped" and record["v_x"] == 0.01
    series = (out / "series.txt").read_text()
    proc = subprocess.run(liggghts_cmd(out, cache, resume="yes", v_x=0.02,
                                       normal_force="unclipped", **common),
                          capture_output=True, text=True, errors="replace", timeout=300)
    text = proc.stdout + proc.stderr + (out / "log.shear.lammps").read_text()
    assert proc.returncode != 0
    assert "normal_force unclipped (the stage has clipped)" in text
    assert "v_x 0.02 (the stage has 0.01)" in text
    assert (out / "series.txt").read_text() == series
    run(out, cache, resume="yes", v_x="1e-2", normal_force="clipped", **common)
    assert "nothing to resume" in (out / "log.shear.lammps").read_text()
    assert (out / "series.txt").read_text() == series


def test_agitation_stage(tmp_path, cache):
    """Stage 2b (agitate.liggghts: dilation, agitation with velocities drawn
    in LIGGGHTS, recompression with mu_rec) runs and keeps the density; it
    lowers the coordination."""
    common = dict(preset="quick", N=300, mu_prep=0.0407, stage="prep", dilate_steps=5000,
                  agitate_steps=20000, mu_rec=0.25)
    states = {}
    for name, dil in (("plain", 1.0), ("agitated", 1.003)):
        out = tmp_path / name
        run(out, cache, agitate_dilation=dil, **common)
        states[name] = json.loads((out / "prep.json").read_text())
        log = (out / "log.prep.lammps").read_text()
        assert ("recompressed with mu_rec" in log) == (dil > 1.0)
    plain, agitated = states["plain"], states["agitated"]
    print(f"[ measured ] N = 300: plain e = {plain['e']:.4f}, z_g = {plain['z_g']:.3f}; "
          f"agitated e = {agitated['e']:.4f}, z_g = {agitated['z_g']:.3f}")
    assert abs(agitated["e"] - plain["e"]) < 0.03
    assert agitated["z_g"] < plain["z_g"]
    assert abs(agitated["p"] - 1.0e5) < 0.15e5


def test_calibration(tmp_path, cache):
    """-var calibrate yes (calibrate.liggghts): trials until e is within
    e_tol of e_target, each a line of calibration.txt, the next friction by
    inputs/calibrate.lmp's rule (here the slope e_slope after the first
    trial); prep.json is the accepted trial's."""
    out = tmp_path / "cal"
    run(out, cache, preset="quick", N=300, stage="prep", calibrate="yes", e_target=0.725,
        e_tol=0.005)
    lines = [l.split() for l in (out / "calibration.txt").read_text().splitlines()
             if not l.startswith("#")]
    trials = [(int(l[0]), float(l[1]), float(l[2])) for l in lines]
    print(f"[ measured ] calibration trials (trial, mu_prep, e): {trials}")
    assert len(trials) >= 2 and [t[0] for t in trials] == list(range(1, len(trials) + 1))
    assert trials[0][1] == 0.15
    assert all(abs(e - 0.725) > 0.005 for _, _, e in trials[:-1])
    assert abs(trials[-1][2] - 0.725) <= 0.005
    # the second trial: mu_prep + (e_target - e) / e_slope, to 5 decimals
    mu, e = trials[0][1], trials[0][2]
    assert trials[1][1] == pytest.approx(round(mu + (0.725 - e) / 0.6, 5), abs=1e-12)
    prep = json.loads((out / "prep.json").read_text())
    assert prep["mu_prep"] == trials[-1][1] and prep["e"] == pytest.approx(trials[-1][2])
    log = (out / "log.prep.lammps").read_text()
    assert log.count("GRFLOW prep: done") == len(trials)
    assert "GRFLOW calibration: mu_prep = " in log


def echoed(log, start):
    found = [l.split() for l in log.splitlines() if l.startswith(start) and "$" not in l]
    assert found, f"no '{start}' command in the log"
    return found


def test_contact_ratios_reach_particles_and_walls(tmp_path, cache):
    """-var kt_kn ... mu_o set the coefficients of model grflow (fix
    property/global) and of the walls, in the preparation and the shear
    stage; prep.json records them."""
    ratios = {"kt_kn": 0.5, "ct_cn": 0.25, "kr_kn": 0.2, "cr_cn": 0.125, "mu_r": 0.3,
              "ko_kn": 0.25, "co_cn": 0.0625, "mu_o": 0.2}
    out = tmp_path / "run"
    cmd = liggghts_cmd(out, cache, preset="quick", N=200, max_steps=500, **ratios)
    cmd[cmd.index("-echo") + 1] = "log"
    proc = subprocess.run(cmd, capture_output=True, text=True, errors="replace", timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:] + tail(out / "log.prep.lammps")
    prep = json.loads((out / "prep.json").read_text())
    for k, v in ratios.items():
        assert prep[k] == v, k
    want = {"kt": 0.5e6, "ct": 0.25 * 1.15, "kr": 0.2e6, "cr": 0.125 * 1.15, "mur": 0.3,
            "ko": 0.25e6, "co": 0.0625 * 1.15, "muo": 0.2}
    for logname, mut in (("log.prep.lammps", 0.15), ("log.shear.lammps", 0.5)):
        log = (out / logname).read_text()
        for name, value in dict(want, mut=mut).items():
            line = echoed(log, f"fix             grflow_{name} all property/global {name} ")[0]
            assert float(line[-1]) == pytest.approx(value, rel=1e-12), (logname, name)
        wall = echoed(log, "fix             walls ")[0]
        kw = dict(zip(wall, wall[1:]))
        for name, value in dict(want, mut=mut).items():
            assert float(kw[name]) == pytest.approx(value, rel=1e-12), (logname, name)
    # the switch to mu_t in the preparation (stage 3)
    log = (out / "log.prep.lammps").read_text()
    assert echoed(log, "fix             grflow_mut all property/global mut ")[-1][-1] == "0.5"
    assert echoed(log, "fix_modify      walls mut")[-1][-1] == "0.5"


@pytest.mark.parametrize("var,expect", [
    # params.lmp's checks, as LIGGGHTS runs them (params.sh)
    ({"preset": "fast"}, "unknown preset fast"),
    ({"agitate_dilation": "0.99"}, "agitate_dilation 0.99 must be >= 1"),
    ({"N": "0"}, "N 0 must be a whole number >= 1"),
    ({"N": "100.5"}, "N 100.5 must be a whole number >= 1"),
    ({"d_min": "2e-3", "d_max": "1e-3"}, "need 0 < d_min <= d_max"),
    ({"dt_factor": "0"}, "dt_factor 0 must be > 0"),
    ({"dt_factor_shear": "-0.1"}, "dt_factor_shear -0.1 must be > 0"),
    ({"glue_gap": "-1e-4"}, "glue_gap -1e-4 must be >= 0"),
    ({"tau_amp": "0"}, "tau_amp 0 must be > 0"),
    ({"v_x": "0"}, "v_x 0 must be > 0"),
    ({"shear_rate": "-0.38"}, "shear_rate -0.38 must be >= 0"),
    ({"skin_factor": "0"}, "skin_factor 0 must be > 0"),
    ({"check_every": "0"}, "each must be >= 1"),
    ({"max_cycles": "-1"}, "max_cycles -1 must be >= 0"),
    ({"newton_pair": "maybe"}, "newton_pair maybe: use on or off"),
    ({"normal_force": "maybe"}, "normal_force maybe: use clipped or unclipped"),
    ({"timing": "maybe"}, "timing maybe: use yes or no"),
    ({"calibrate": "maybe"}, "calibrate maybe: use yes or no"),
    # a value that is no number: named by params.lmp's check, as in LAMMPS
    ({"N": "many"}, "ERROR: not a number: N 'many'"),
    # the LIGGGHTS decks' own
    ({"stage": "both"}, "unknown stage both"),
    ({"resume": "yes", "stage": "prep"}, "cannot go with stage prep"),
    ({"pair": "hertz"}, "unknown pair hertz"),
    ({"pair": "stock"}, "pair stock (stock pair granular) is LAMMPS only"),
    ({"shear_segment": "15"}, "shear_segment 15 must be a multiple of check_every 10"),
    ({"prep_segment": "1005"}, "prep_segment 1005 must be a multiple of servo_every 10"),
    ({"kt_kn": "-0.5"}, "fix grflow/wall: kt must be >= 0, got -5e+05"),
])
def test_bad_parameters(tmp_path, cache, var, expect):
    outdir = tmp_path / "bad"
    proc = subprocess.run(liggghts_cmd(outdir, cache, screen=True, **var), capture_output=True,
                          text=True, errors="replace", timeout=120)
    text = proc.stdout + proc.stderr + tail(outdir / "log.prep.lammps")
    assert proc.returncode != 0
    assert expect in text


def test_outdir_with_whitespace(tmp_path, cache):
    for name in ("two words", "tab\there"):
        outdir = tmp_path / name
        proc = subprocess.run(liggghts_cmd(outdir, cache, screen=True, preset="quick"),
                              capture_output=True, text=True, errors="replace", timeout=120,
                              cwd=tmp_path)
        assert proc.returncode != 0
        assert f"outdir {outdir} contains whitespace" in proc.stdout + proc.stderr
        assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_sample_too_small(tmp_path, cache):
    proc = subprocess.run(liggghts_cmd(tmp_path / "n20", cache, screen=True, preset="quick",
                                       N=20), capture_output=True, text=True, errors="replace",
                          timeout=300)
    text = proc.stdout + proc.stderr
    assert proc.returncode != 0
    assert "the sample of N = 20 spheres is too small" in text
    assert "each must be >= 2 d_max = 0.004" in text
    assert not (tmp_path / "n20" / "prep.restart").exists()
    run(tmp_path / "n30", cache, preset="quick", N=30, stage="prep", timeout=300)
    assert (tmp_path / "n30" / "prep.restart").exists()


def test_params_sh_rewrites_only_what_liggghts_cannot_read(tmp_path):
    """params.sh leaves every line of params.lmp as it is except the string
    comparisons in "if" and "quit N"; its output does not depend on the
    parameters (one file per params.lmp)."""
    out = tmp_path / "params.liggghts"
    subprocess.run(["sh", os.path.join(INPUTS, "liggghts", "params.sh"),
                    os.path.join(INPUTS, "params.lmp"), str(out)], check=True)
    src = open(os.path.join(INPUTS, "params.lmp")).read().replace("&\n", "")
    kept = [l for l in out.read_text().splitlines() if not l.startswith("#")]
    changed = [l for l in kept if l not in src.splitlines()]
    for line in changed:
        assert (line.startswith(("if ", "shell           sh ${inputs}/liggghts/is.sh",
                                 "include         ${grflow_cache}/is."))
                or line == "quit"), line
    assert any("grflow_is_preset_quick" in l for l in changed)
    assert not any("== paper" in l or "!= paper" in l for l in kept)
