"""inputs/calibrate_mu_prep.py on a small case (the quick preset, 200 spheres).

1. From the bracket [0, 0.3] it finds a mu_prep whose preparation, as the
   deck wrote it to prep.json, has e within the tolerance of 0.647; it
   prints e against mu_prep and writes the same table to calibration.txt.
2. --try with the value found ends after that one run, with the same e
   (the preparation is deterministic).
3. A --try value above the target replaces --hi, which is not run.
4. Bad arguments stop with a message.

Environment: LMP (lmp binary), GRFLOW_INPUTS (the inputs/ directory).
"""

import json
import os
import re
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


def calibrate(workdir, *extra, check=True):
    proc = subprocess.run([sys.executable, SCRIPT, "--workdir", str(workdir)] + SMALL
                          + list(extra), capture_output=True, text=True, timeout=600)
    if check:
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    printed = [tuple(float(v) for v in m.groups())
               for m in map(LINE.match, proc.stdout.splitlines()) if m]
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
    assert all(abs(e - TARGET) > TOL for _, e in printed[:-1])


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
    _, proc, printed = search
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
