"""workflows/physics_study.smk and grflow-study (grflow_analysis.study): a
study of shear-stage settings over seeds, from one preparation per seed.

- flickers: an exit counts as one when the sample is back at
  r_u >= ru_liq before the next reversal (a series made by hand);
- the paired statistics against the baseline (values made by hand);
- a tiny study (300 spheres, 2 seeds, 2 settings) runs end to end: each
  setting is sheared from the seed's one preparation, and the table has
  every run; a run not done is an error, or "not run" with --partial;
- killed during a shear run, the workflow run again resumes that run from
  its restart file (the decks' -var resume yes) and ends with one series,
  every step once;
- a bad config is refused before anything runs;
- the quasi-static limit (--rate-settings): values on a straight line in
  the shear rate give its value at rate 0 and its slope; settings that
  differ in more than the rate are refused.

Environment: LMP (lmp binary).  grflow-study, which the workflow runs, is
the set-up's, beside the Python that runs the tests (scripts/python-env.sh).
"""
import json
import os
import signal
import subprocess
import time

import numpy as np
import pytest

from grflow_analysis import study
from runfiles import read_series
import workflowrun
from workflowrun import ENV, SNAKEMAKE, needs_snakemake, planned

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SMK = os.path.join(ROOT, "workflows", "physics_study.smk")
LMP = os.environ.get("LMP", "lmp")


def test_flickers_are_exits_without_a_reversal():
    # liquefied from row 1 (step_IL 100); exit at row 3, back at row 4
    # with no reversal between (a flicker); exit at row 6, a reversal at
    # row 7, back at row 8 (a recovery)
    ru = np.array([0.5, 0.995, 0.995, 0.98, 0.995, 0.995, 0.9, 0.5, 0.995, 0.995])
    rev = np.array([0, 0, 0, 0, 0, 0, 0, 1, 1, 1])
    series = {"step": np.arange(10) * 100.0, "r_u": ru, "reversals": rev}
    events = {"step_IL": 100}
    assert study.flickers(series, events, 0.99) == (2, 1)
    # an exit that has not come back by the end of the series is no flicker
    series["r_u"] = ru[:8]
    series["step"] = series["step"][:8]
    series["reversals"] = rev[:8]
    assert study.flickers(series, events, 0.99) == (2, 1)
    series["reversals"] = np.zeros(8)
    assert study.flickers(series, events, 0.99) == (2, 1)


def test_statistics_by_hand():
    assert study.stats([1.0, None, 3.0]) == (2.0, pytest.approx(2 ** 0.5), 2)
    assert study.stats([None]) == (None, None, 0)
    assert study.stats([4.0]) == (4.0, None, 1)


def _rate_study(values, shear_vars):
    """A study dict as study() makes it, with QUANTITIES' values given per
    setting and seed ({setting: {seed: value}}; every quantity the same)."""
    runs = {s: {str(seed): {k: v for k, _, _ in study.QUANTITIES} for seed, v in per.items()}
            for s, per in values.items()}
    return {"settings": list(values), "seeds": [1, 2], "runs": runs, "shear_vars": shear_vars}


def test_quasistatic_limit_of_a_line():
    # seed 1 on 3.0 + 0.5 rate, seed 2 on 3.2 - 0.1 rate: exact at rate 0
    rates = {"base": 0.4, "half": 0.2, "quarter": 0.1}
    values = {s: {1: 3.0 + 0.5 * r, 2: 3.2 - 0.1 * r} for s, r in rates.items()}
    d = _rate_study(values, {s: "shear_rate %g cundall_l 0.1" % r for s, r in rates.items()})
    q = study.quasistatic(d, list(rates))
    t = q["table"]["z_g_exit_mean"]
    assert t["seeds"]["1"]["at0"] == pytest.approx(3.0)
    assert t["seeds"]["2"]["at0"] == pytest.approx(3.2)
    assert t["seeds"]["1"]["slope"] == pytest.approx(0.5)
    assert (t["mean"], t["n"]) == (pytest.approx(3.1), 2)
    assert t["sd"] == pytest.approx(0.2 / 2 ** 0.5)
    assert t["slope_mean"] == pytest.approx(0.2)
    # a seed with a value at one rate only has no line: left out, counted
    d["runs"]["half"]["2"]["z_g_exit_mean"] = None
    d["runs"]["quarter"]["2"]["z_g_exit_mean"] = None
    t = study.quasistatic(d, list(rates))["table"]["z_g_exit_mean"]
    assert t["seeds"]["2"]["at0"] is None and t["n"] == 1 and t["mean"] == pytest.approx(3.0)
    # least squares through 3 points off a line: value at 0 by hand
    assert study.line_to_zero([1.0, 2.0, 3.0], [1.0, 2.0, 4.0])[0] == pytest.approx(-2.0 / 3.0)


@pytest.mark.parametrize("shear_vars,names,expect", [
    ({"a": "shear_rate 0.4", "b": "shear_rate 0.2 cundall_l 0.1"}, ["a", "b"],
     "differ in more than shear_rate"),
    ({"a": "shear_rate 0.4", "b": "cundall_l 0.1"}, ["a", "b"], "no numeric shear_rate"),
    ({"a": "shear_rate 0.4", "b": "shear_rate 0.4"}, ["a", "b"], "two or more different"),
    ({"a": "shear_rate 0.4", "b": "shear_rate 0.2"}, ["a", "c"], "c is not one of --settings"),
])
def test_quasistatic_refuses_settings_that_are_not_a_rate_series(shear_vars, names, expect):
    d = _rate_study({s: {1: 1.0, 2: 2.0} for s in shear_vars}, shear_vars)
    with pytest.raises(ValueError, match=expect):
        study.quasistatic(d, names)


def snakemake(args, cwd, check=True):
    return workflowrun.snakemake(SMK, args, cwd, check)


def config(out, **more):
    settings = {"base": "tau_amp 45e3", "lower": "tau_amp 40e3"}
    c = {"seeds": "[1,2]", "N": "300", "preset": "quick", "prep_vars": "",
         "settings": json.dumps(settings), "out": str(out), "lmp": LMP,
         "vars": "n_post 1 series_every 50", "max_cycles": "20"}
    c.update(more)
    return ["--config"] + [f"{k}={v}" for k, v in c.items()]


@needs_snakemake
def test_tiny_study_end_to_end(tmp_path):
    out = tmp_path / "study"
    snakemake(["--cores", "2"] + config(out), tmp_path)
    d = json.loads((out / "study.json").read_text())
    assert d["settings"] == ["base", "lower"] and d["baseline"] == "base"
    for s in ("base", "lower"):
        # one preparation per seed, shared by the settings
        for seed in (1, 2):
            assert (out / f"seed{seed}" / s / "prep.restart").resolve() == \
                (out / f"seed{seed}" / "prep" / "prep.restart").resolve()
        # a run-out (no liquefaction by max_cycles) has no N_IL and is left
        # out of the statistics, which count the runs they have
        n_il = [d["runs"][s][str(seed)]["N_IL"] for seed in (1, 2)]
        for seed, n in zip((1, 2), n_il):
            log = (out / f"seed{seed}" / s / "log.shear.lammps").read_text()
            done = [x for x in log.splitlines() if x.startswith("GRFLOW shear: done at step")]
            assert len(done) == 1
            assert (n is None) == done[0].endswith("initial liquefaction not reached (run-out)")
            # its N_IL cell says it exceeds max_cycles
            assert (d["runs"][s][str(seed)]["N_IL_above"] == 20.0) == (n is None)
        liquefied = [n for n in n_il if n is not None]
        assert liquefied, "no run liquefied: raise tau_amp"
        assert d["table"][s]["N_IL"]["n"] == len(liquefied)
        assert d["table"][s]["N_IL"]["mean"] == pytest.approx(np.mean(liquefied))
    # the baseline's difference from itself is 0
    assert d["table"]["base"]["z_g_prep"]["diff_mean"] == 0.0
    # the settings reached the runs: tau_amp in the shear log
    log = (out / "seed1" / "lower" / "log.shear.lammps").read_text()
    assert "tau_amp = 40e3 Pa" in log
    md = (out / "study.md").read_text()
    assert "## N_IL" in md and "| lower |" in md
    n_runouts = sum(d["runs"][s][str(seed)]["N_IL"] is None for s in ("base", "lower")
                    for seed in (1, 2))
    assert md.count("> 20 (run-out)") == n_runouts
    # a run directory is one grflow-figures reads
    proc = subprocess.run(["grflow-figures", str(out / "seed2" / "lower")],
                          capture_output=True, text=True, env=ENV, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    # a study in progress: a run without run.json is an error, or with
    # --partial "not run" and left out
    (out / "seed2" / "lower" / "run.json").unlink()
    with pytest.raises(FileNotFoundError):
        study.study(str(out), ["base", "lower"], [1, 2])
    p = study.study(str(out), ["base", "lower"], [1, 2], partial=True)
    assert p["runs"]["lower"]["2"]["not_run"] and p["runs"]["lower"]["2"]["N_IL"] is None
    assert p["table"]["lower"]["z_g_prep"]["n"] == 1
    assert "| lower | " in study.markdown(p) and "not run" in study.markdown(p)
    (out / "seed1" / "lower" / "run.json").unlink()
    with pytest.raises(FileNotFoundError, match="lower: no seed has a finished run"):
        study.study(str(out), ["base", "lower"], [1, 2], partial=True)


@needs_snakemake
def test_killed_study_resumes_the_shear_run(tmp_path):
    """snakemake killed (SIGKILL, with its lmp) after a shear run wrote a
    restart file; the same command (after --unlock) resumes that run from
    the file rather than starting it again, and the series has every step
    once."""
    out = tmp_path / "study"
    cfg = config(out, seeds="[1]", settings=json.dumps({"base": "tau_amp 30e3"}),
                 vars="n_post 1 series_every 50 restart_every 2000")
    proc = subprocess.Popen([SNAKEMAKE, "-s", SMK, "--cores", "1"] + cfg, cwd=tmp_path,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True, env=ENV)
    run = out / "seed1" / "base"
    deadline = time.time() + 600
    while not ((run / "shear.restart.4000.cksum").exists()):
        assert proc.poll() is None, "the study ended before it was killed"
        assert time.time() < deadline
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    assert not (run / "run.json").exists()
    snakemake(["--unlock"] + cfg, tmp_path)
    plan = snakemake(["-n", "--cores", "1"] + cfg, tmp_path)
    assert planned(plan) == {"all": 1, "shear": 1, "study": 1, "total": 3}, plan.stdout
    snakemake(["--cores", "1"] + cfg, tmp_path)
    log = (run / "log.shear.lammps").read_text()
    assert "GRFLOW shear: resuming at step" in log
    assert "GRFLOW shear: done" in log
    steps = [r[0] for r in read_series(run / "series.txt")]
    assert steps == sorted(set(steps))
    assert steps[0] == 0 and all(b - a == 50 for a, b in zip(steps, steps[1:]))
    assert json.loads((out / "study.json").read_text())["runs"]["base"]["1"]["N_IL"] > 0


@needs_snakemake
@pytest.mark.parametrize("bad,expect", [
    ("settings={\"a/b\": \"\"}", "cannot name a directory"),
    ("settings={\"x\": \"cundall_l\"}", "NAME VALUE"),
    ("preset=fast", "preset fast"),
    ("prep_vars=calibrate", "NAME VALUE"),
    ("rate_settings=base nope", "rate_settings: nope is not one of the settings"),
])
def test_bad_config_is_refused(tmp_path, bad, expect):
    proc = snakemake(["-n", "--cores", "1", "--config", bad, f"out={tmp_path}"], tmp_path,
                     check=False)
    assert proc.returncode != 0
    assert expect in proc.stdout + proc.stderr
