"""workflows/resistance_curve.smk and grflow-curve (grflow_analysis.curve):
the cyclic resistance curve as one Snakemake workflow.

- the fit recovers a known power law (exactly from exact data, within its
  standard errors from noisy data);
- a tiny campaign (2 CSR values, 1 seed, 300 spheres) runs end to end: one
  CSR liquefies, the other is a run-out at max_cycles; the run directories
  are ones grflow-figures reads;
- stopped after one run, the campaign plans only the other run and the curve;
  killed during a run, it plans that run, the rest and the curve, not the
  preparation;
- the SLURM profile's dry run plans the job graph without a cluster.

Environment: LMP (lmp binary).  The commands grflow-curve, which the
workflow runs, and grflow-figures are the set-up's, beside the Python that
runs the tests (scripts/python-env.sh).
"""
import json
import os
import subprocess

import numpy as np
import pytest

from grflow_analysis import curve
import workflowrun
from workflowrun import ENV, SNAKEMAKE, needs_snakemake, planned

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SMK = os.path.join(ROOT, "workflows", "resistance_curve.smk")
PROFILE = os.path.join(ROOT, "workflows", "profiles", "slurm")

LMP = os.environ.get("LMP", "lmp")


def test_fit_exact_power_law():
    n = np.array([3.0, 7.0, 15.0, 40.0])
    fit = curve.fit_power_law(0.4 * n ** -0.2, n)
    assert fit["a"] == pytest.approx(0.4, rel=1e-12)
    assert fit["b"] == pytest.approx(0.2, rel=1e-12)
    assert fit["se_b"] == pytest.approx(0.0, abs=1e-12)


def test_fit_noisy_power_law_within_its_errors():
    # 3 seeds at 4 CSR values, lognormal scatter of N_IL (sd 0.3 in log N,
    # as seed scatter might be): the estimates lie within 3 standard errors
    # (a 99.7% band for normal errors) of the truth, for 200 campaigns in
    # all but a few
    rng = np.random.default_rng(20261124)
    a, b = 0.35, 0.18
    csr = np.repeat([0.15, 0.2, 0.25, 0.3], 3)
    misses = 0
    for _ in range(200):
        n = (csr / a) ** (-1 / b) * np.exp(rng.normal(0, 0.3, csr.size))
        fit = curve.fit_power_law(csr, n)
        if abs(fit["b"] - b) > 3 * fit["se_b"] or \
                abs(np.log(fit["a"]) - np.log(a)) > 3 * fit["se_log_a"]:
            misses += 1
    # expected about 0.6% each for b and log a with 10 degrees of freedom
    # (t distribution: 1.3%); 10 of 200 would be far outside
    assert misses <= 10


def test_fit_needs_three_points_and_two_n():
    assert curve.fit_power_law([0.2, 0.3], [10.0, 3.0]) is None
    assert curve.fit_power_law([0.2, 0.3, 0.25], [5.0, 5.0, 5.0]) is None


def test_curve_refuses_a_run_without_events(tmp_path):
    """N_IL is fix grflow/shear's, from events.txt: grflow-curve stops with
    exit status 2 and says so for a run directory without it, and writes
    no curve."""
    run = tmp_path / "seed1" / "csr0.2"
    run.mkdir(parents=True)
    (run / "run.json").write_text(json.dumps({"seed": 1, "csr": 0.2, "tau_amp": 2e4,
                                              "p_target": 1e5, "max_cycles": 5}))
    (run / "prep.json").write_text(json.dumps({"e": 0.65, "ru_liq": 0.99, "tau_amp": 2e4}))
    (run / "series.txt").write_text("# step time reversals gamma tau p r_u z_g a_c\n"
                                    "0 0 0 0 0 1e5 0 4.7 0\n100 1e-3 0 1e-4 5e3 1e5 0 4.7 0.1\n")
    proc = subprocess.run(["grflow-curve", str(tmp_path / "out"), str(run)],
                          capture_output=True, text=True, env=ENV, timeout=120)
    assert proc.returncode == 2 and "no events.txt" in proc.stderr, proc.stderr
    assert not (tmp_path / "out").exists()


def snakemake(args, cwd, check=True):
    return workflowrun.snakemake(SMK, args, cwd, check)


@needs_snakemake
def test_tiny_campaign_end_to_end(tmp_path):
    out = tmp_path / "curve"
    config = ["--config", "csr=[0.6,0.05]", "seeds=[1]", f"out={out}", f"lmp={LMP}",
              "vars=N 300", "max_cycles=5"]
    # a campaign stopped after its first run (here: asked for that run
    # only), then run again: only the missing run and the curve are
    # planned, the preparation and the finished run are kept
    snakemake(["--cores", "2", str(out / "seed1" / "csr0.6" / "run.json")] + config, tmp_path)
    proc = snakemake(["-n", "--cores", "2"] + config, tmp_path)
    assert planned(proc) == {"all": 1, "curve": 1, "shear": 1, "total": 3}, proc.stdout
    snakemake(["--cores", "2"] + config, tmp_path)

    c = json.loads((out / "curve.json").read_text())
    runs = {r["csr"]: r for r in c["runs"]}
    assert set(runs) == {0.6, 0.05}
    assert runs[0.6]["liquefied"] and runs[0.6]["N_IL"] > 0
    assert runs[0.6]["tau_amp"] == pytest.approx(60.0e3)
    # the run-out: stopped by max_cycles, not liquefied
    assert not runs[0.05]["liquefied"] and runs[0.05]["N_IL"] is None
    log = (out / "seed1" / "csr0.05" / "log.shear.lammps").read_text()
    assert "N = 5, initial liquefaction not reached (run-out)" in log
    # the run ends on the event where the fix's N reached 5 (the crossing
    # after reversal 10); the series' last row is on or before it, after
    # reversal 10 (N = 4.75): a quarter cycle is far longer than series_every
    assert 4.75 <= runs[0.05]["N_end"] <= 5.0
    assert c["fit"] is None and "no fit" in c["fit_note"]
    assert (out / "curve.png").stat().st_size > 0
    assert "run-out" in (out / "curve.md").read_text()
    # one preparation for both CSR values
    assert (out / "seed1" / "csr0.6" / "prep.restart").resolve() == \
        (out / "seed1" / "prep" / "prep.restart").resolve()

    # a run directory is one grflow-figures reads
    proc = subprocess.run(["grflow-figures", str(out / "seed1" / "csr0.6")],
                          capture_output=True, text=True, env=ENV, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]


@needs_snakemake
def test_killed_campaign_reruns_only_the_missing_work(tmp_path):
    """snakemake killed (SIGKILL, with its lmp) while a shear run is under
    way; after --unlock, the same command with --rerun-incomplete plans that run,
    the runs never started and the curve, but not the finished
    preparation."""
    import signal
    import time
    out = tmp_path / "curve"
    config = ["--config", "csr=[0.45,0.3]", "seeds=[1]", f"out={out}", f"lmp={LMP}",
              "vars=N 300", "max_cycles=20"]
    proc = subprocess.Popen([SNAKEMAKE, "-s", SMK, "--cores", "1"] + config, cwd=tmp_path,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True, env=ENV)
    deadline = time.time() + 600
    # a shear run has written its first series rows
    while not any(p.stat().st_size > 2000 for p in out.glob("seed1/csr*/series.txt")):
        assert proc.poll() is None, "the campaign ended before it was killed"
        assert time.time() < deadline
        time.sleep(0.1)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    assert (out / "seed1" / "prep" / "prep.restart").exists()
    assert not (out / "curve.json").exists()
    # a kill leaves Snakemake's lock: --unlock, as its message says
    snakemake(["--unlock"] + config, tmp_path)
    plan = snakemake(["-n", "--rerun-incomplete", "--cores", "1"] + config, tmp_path)
    assert planned(plan) == {"all": 1, "curve": 1, "shear": 2, "total": 4}, plan.stdout
    snakemake(["--rerun-incomplete", "--cores", "2"] + config, tmp_path)
    c = json.loads((out / "curve.json").read_text())
    assert sorted(r["csr"] for r in c["runs"]) == [0.3, 0.45]


@needs_snakemake
def test_slurm_profile_dry_run(tmp_path):
    proc = snakemake(["-n", "--profile", PROFILE, "--config", "csr=[0.2,0.3]",
                      "seeds=[1,2,3]", f"out={tmp_path / 'c'}", "preset=paper", "np=4"],
                     tmp_path)
    assert planned(proc) == {"all": 1, "curve": 1, "prep": 3, "shear": 6, "total": 11}, \
        proc.stdout


@needs_snakemake
@pytest.mark.parametrize("bad,expect", [
    ("csr=[0.2,-0.1]", "csr"), ("preset=fast", "preset fast"), ("vars=N", "NAME VALUE"),
])
def test_bad_config_is_refused(tmp_path, bad, expect):
    proc = snakemake(["-n", "--cores", "1", "--config", bad, f"out={tmp_path}"], tmp_path,
                     check=False)
    assert proc.returncode != 0
    assert expect in proc.stdout + proc.stderr
