"""inputs/calibrate_mu_prep.py on a small case (the quick preset, 200 spheres).

1. From the bracket [0, 0.3] it finds a mu_prep whose preparation, as the
   deck wrote it to prep.json, has e within the tolerance of 0.647; it
   prints e against mu_prep and writes the same table to calibration.txt.
2. --try with the value found ends after that one run, with the same e
   (the preparation is deterministic).
3. A --try value above the target replaces --hi, which is not run.
4. Bad arguments stop with a message.
5. The search logic on a stand-in for lmp that writes prep.json with a
   given e(mu_prep): exact on a linear e, stops when the bracket shrinks
   below the 5 decimals, when tries are not monotonic, and when a
   preparation fails, each with its exit status.

Environment: LMP (lmp binary), GRFLOW_INPUTS (the inputs/ directory).
"""

import json
import os
import re
import stat
import subprocess
import sys

import pytest

from lmprun import LMP

INPUTS = os.environ.get("GRFLOW_INPUTS",
                        os.path.join(os.path.dirname(__file__), "..", "..", "inputs"))
SCRIPT = os.path.join(INPUTS, "calibrate_mu_prep.py")
SMALL = ["--N", "200", "--preset", "quick", "--lmp", LMP]
TARGET, TOL = 0.647, 0.005
LINE = re.compile(r"^mu_prep = ([0-9.]+)\s+e = ([0-9.]+)$")


def script(workdir, args, env=None, timeout=600):
    """Run the script; return the process and its printed (mu_prep, e) lines."""
    proc = subprocess.run([sys.executable, SCRIPT, "--workdir", str(workdir)] + list(args),
                          capture_output=True, text=True, timeout=timeout, env=env)
    printed = [tuple(float(v) for v in m.groups())
               for m in map(LINE.match, proc.stdout.splitlines()) if m]
    return proc, printed


def calibrate(workdir, *extra, check=True):
    proc, printed = script(workdir, SMALL + list(extra))
    if check:
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return proc, printed


def prep_e(workdir, mu):
    """e of a trial as the deck wrote it"""
    path = workdir / f"mu_{mu:.5f}" / "prep.json"
    return json.loads(path.read_text())["e"]


def found(proc):
    m = re.search(r"found mu_prep = ([0-9.]+) \(e = ([0-9.]+)\)", proc.stdout)
    assert m, proc.stdout
    return float(m.group(1))


@pytest.fixture(scope="module")
def search(tmp_path_factory):
    work = tmp_path_factory.mktemp("calibration")
    proc, printed = calibrate(work, "--lo", "0", "--hi", "0.3", "--max-runs", "8")
    return work, proc, printed


def test_finds_the_target_void_ratio(search):
    work, proc, printed = search
    print(f"[ measured ] N = 200 quick: {printed}")
    mu = found(proc)
    assert abs(prep_e(work, mu) - TARGET) <= TOL
    # the bracket ends come first and bracket the target
    assert printed[0][0] == 0.0 and printed[1][0] == 0.3
    assert prep_e(work, 0.0) < TARGET < prep_e(work, 0.3)
    # every printed e is the deck's, to the printed digits, and the table
    # holds the same runs
    for m, e in printed:
        assert e == pytest.approx(prep_e(work, m), abs=5.1e-5)
    rows = [tuple(map(float, l.split())) for l in
            (work / "calibration.txt").read_text().splitlines() if not l.startswith("#")]
    assert [r[0] for r in rows] == sorted(m for m, _ in printed)
    for m, e in rows:
        assert e == pytest.approx(prep_e(work, m), abs=1e-6)
    # a search, not a scan: fewer runs than the limit, only the last within
    # the tolerance
    assert len(printed) < 8
    assert all(abs(prep_e(work, m) - TARGET) > TOL for m, _ in printed[:-1])


def test_try_within_tolerance_ends_at_once(search, tmp_path):
    work, proc, _ = search
    mu = found(proc)
    again, printed = calibrate(tmp_path, "--try", repr(mu))
    assert found(again) == mu
    assert len(printed) == 1
    assert prep_e(tmp_path, mu) == prep_e(work, mu)


def test_a_try_replaces_a_bracket_end(search, tmp_path):
    """--hi 1 but --try 0.3 (above the target): 1 is never run, and the
    search goes on from [0, 0.3] as the first one did."""
    work, proc, printed = search
    assert prep_e(work, 0.3) > TARGET + TOL    # so 0.3 does not end it
    again, runs = calibrate(tmp_path, "--lo", "0", "--hi", "1", "--try", "0.3",
                            "--max-runs", "8")
    assert runs[0][0] == 0.3 and all(m != 1.0 for m, _ in runs)
    assert sorted(runs) == sorted(printed)
    assert found(again) == found(proc)


@pytest.mark.parametrize("args,expect", [
    (["--lo", "0.3", "--hi", "0.1"], "need 0 <= --lo < --hi"),
    (["--tol", "0"], "--tol must be > 0"),
    (["--try", "0.5", "--hi", "0.3"], "--try values must lie in"),
])
def test_bad_arguments(tmp_path, args, expect):
    proc, printed = calibrate(tmp_path, *args, check=False)
    assert proc.returncode != 0 and not printed
    assert expect in proc.stderr


FAKE = """#!/usr/bin/python3
import json, os, sys
a = sys.argv
var = {a[i + 1]: a[i + 2] for i in range(len(a) - 2) if a[i] == "-var"}
mu = float(var["mu_prep"])
if mu == float(os.environ.get("FAKE_FAIL", "-1")):
    sys.exit(1)
os.makedirs(var["outdir"], exist_ok=True)
with open(os.path.join(var["outdir"], "prep.json"), "w") as f:
    json.dump({"e": eval(os.environ["FAKE_E"])}, f)
"""


def fake(tmp_path, e_of_mu, *args, fail=None):
    """calibrate_mu_prep.py with a stand-in lmp whose e is e_of_mu (a Python
    expression in mu)"""
    exe = tmp_path / "fake_lmp"
    exe.write_text(FAKE)
    exe.chmod(exe.stat().st_mode | stat.S_IXUSR)
    env = dict(os.environ, FAKE_E=e_of_mu, FAKE_FAIL=str(-1 if fail is None else fail))
    return script(tmp_path / "w", ["--lmp", str(exe)] + list(args), env=env, timeout=120)


def test_search_logic_linear(tmp_path):
    # e = 0.6 + 0.5 mu: regula falsi lands on mu = 0.094 at once
    proc, printed = fake(tmp_path, "0.6 + 0.5 * mu")
    assert proc.returncode == 0
    assert [m for m, _ in printed] == [0.0, 0.3, 0.094]
    assert "found mu_prep = 0.09400" in proc.stdout


def test_search_logic_step_shrinks_bracket(tmp_path):
    # a jump across the tolerance band at 0.1234567: bisection down to 1e-5
    proc, printed = fake(tmp_path, "0.6 if mu < 0.1234567 else 0.7", "--max-runs", "40")
    assert proc.returncode == 1
    assert "narrower than the 5 decimals" in proc.stdout
    lo = max(m for m, e in printed if e < 0.647)
    hi = min(m for m, e in printed if e > 0.647)
    assert lo < 0.1234567 <= hi and round(hi - lo, 5) <= 1e-5
    assert len(printed) == len(set(printed)) < 40


def test_search_logic_tries_not_monotonic(tmp_path):
    # e falls with mu: the try below the target lies above the one above it
    proc, printed = fake(tmp_path, "0.75 - mu", "--try", "0.2", "0.01")
    assert proc.returncode == 2
    assert "not bracketed" in proc.stdout
    assert [m for m, _ in printed] == [0.2, 0.01]


def test_search_logic_failed_preparation(tmp_path):
    proc, printed = fake(tmp_path, "0.6 + 0.5 * mu", fail=0.3)
    assert proc.returncode == 3
    assert "preparation failed for mu_prep = 0.3" in proc.stderr
    assert [m for m, _ in printed] == [0.0]


def test_max_runs_must_hold_the_tries(tmp_path):
    proc, printed = fake(tmp_path, "0.6 + 0.5 * mu", "--try", "0.1", "0.2", "--max-runs", "3")
    assert proc.returncode == 2 and not printed
    assert "leaves no room for 2 tries" in proc.stderr
