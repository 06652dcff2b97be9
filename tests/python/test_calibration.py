"""-var calibrate yes: the decks find the preparation friction themselves
(inputs/calibrate.lmp).

1. The real decks on a small case (the quick preset, 300 spheres): the
   accepted trial is within e_tol of e_target; prep.json, calibration.txt
   and log.prep.lammps agree on every trial; the accepted friction given
   as a number reproduces the same preparation (the trials are plain
   preparations).
2. The search rule of calibrate.lmp with a stand-in prepare.lmp whose e is
   a given function of mu_prep (every other deck is the real one): each
   trial follows from the ones before it by the rule the deck documents,
   recomputed here; the two ways to fail (no trial within e_tol after
   calib_max trials; the next trial equal to the last one) stop with an
   error and remove prep.restart and prep.json.
3. Bad settings stop before any atom is made.

Environment: LMP (lmp binary), GRFLOW_INPUTS (the inputs/ directory).
"""

import json
import os
import shutil

import pytest

from lmprun import run_lmp

INPUTS = os.path.abspath(os.environ.get(
    "GRFLOW_INPUTS", os.path.join(os.path.dirname(__file__), "..", "..", "inputs")))


def deck(outdir, *vars_, inputs=INPUTS, check=True, timeout=900, nprocs=1):
    args = ["-in", os.path.join(inputs, "cyclic_shear.lmp"), "-var", "inputs", inputs,
            "-var", "outdir", str(outdir), "-var", "stage", "prep"]
    for i in range(0, len(vars_), 2):
        args += ["-var", vars_[i], str(vars_[i + 1])]
    return run_lmp(args, outdir.parent, nprocs=nprocs, check=check, timeout=timeout)


def trials(outdir):
    """calibration.txt as (trial, mu_prep, e) rows"""
    rows = []
    for line in (outdir / "calibration.txt").read_text().splitlines():
        if line.startswith("#"):
            continue
        k, mu, e = line.split()[:3]
        rows.append((int(k), float(mu), float(e)))
    return rows


# ---- 1. the real decks ---------------------------------------------------------

SMALL = ("preset", "quick", "N", 300)


@pytest.fixture(scope="module")
def calibrated(tmp_path_factory):
    out = tmp_path_factory.mktemp("calibrated") / "run"
    proc = deck(out, *SMALL, "calibrate", "yes")
    return out, proc


def test_accepts_a_trial_within_the_tolerance(calibrated):
    out, proc = calibrated
    rows = trials(out)
    prep = json.loads((out / "prep.json").read_text())
    assert rows and [k for k, _, _ in rows] == list(range(1, len(rows) + 1))
    k, mu, e = rows[-1]
    assert abs(e - 0.647) <= 0.005                   # the defaults e_target, e_tol
    assert all(abs(e - 0.647) > 0.005 for _, _, e in rows[:-1])    # it stops at the first
    assert prep["mu_prep"] == pytest.approx(mu, abs=0)
    assert prep["e"] == pytest.approx(e, abs=5e-9)   # the table's 8 decimals
    assert rows[0][1] == 0.15                        # mu_prep of the quick preset
    # every trial is in log.prep.lammps, appended in order
    log = (out / "log.prep.lammps").read_text()
    tried = [line.split("mu_prep = ")[1].strip() for line in log.splitlines()
             if line.startswith("GRFLOW prep:") and "compressing" in line]
    assert [float(m) for m in tried] == [m for _, m, _ in rows]
    assert f"mu_prep = {mu:.5f} gives e = {e:.5f}" in proc.stdout
    assert (out / "prep.restart").exists()


def test_accepted_friction_reproduces_the_preparation(calibrated, tmp_path):
    out, _ = calibrated
    mu = json.loads((out / "prep.json").read_text())["mu_prep"]
    again = tmp_path / "again"
    deck(again, *SMALL, "mu_prep", f"{mu:.5f}")
    a = json.loads((out / "prep.json").read_text())
    b = json.loads((again / "prep.json").read_text())
    for key in ("e", "z_g", "p", "Lx", "h", "step"):
        assert a[key] == b[key], key
    assert not (again / "calibration.txt").exists()


# ---- 2. the search rule, with a stand-in preparation ---------------------------

FAKE_PREP = """# stand-in for prepare.lmp: e is a given function of mu_prep
log             ${outdir}/log.prep.lammps ${prep_log_append}
print           "GRFLOW prep: 0 spheres, compressing with mu_prep = ${mu_prep}"
variable        mu equal ${mu_prep}
variable        e equal $(%s)
variable        net_zg equal 4.0
variable        net_p equal 1.0e5
variable        prep_steps equal 0
print           "{}" file ${outdir}/prep.json screen no
print           "" file ${outdir}/prep.restart screen no
"""


def fake(tmp_path, e_of_mu, *vars_, nprocs=1):
    """the decks with prepare.lmp replaced: e = e_of_mu (a LAMMPS formula in v_mu)"""
    inputs = tmp_path / "inputs"
    shutil.copytree(INPUTS, inputs)
    (inputs / "prepare.lmp").write_text(FAKE_PREP % e_of_mu)
    out = tmp_path / "out"
    proc = deck(out, "calibrate", "yes", *vars_, inputs=str(inputs), check=False, timeout=120,
                nprocs=nprocs)
    return out, proc


def expected_next(rows, target, slope0):
    """the rule of calibrate.lmp: the next friction after the trials rows"""
    lo = [(m, e) for _, m, e in rows if e < target]
    hi = [(m, e) for _, m, e in rows if e > target]
    mu, e = rows[-1][1], rows[-1][2]
    if lo and hi:
        # the latest trial on each side is the bracket's end
        (ml, el), (mh, eh) = lo[-1], hi[-1]
        a, b = min(ml, mh) + 0.1 * abs(mh - ml), max(ml, mh) - 0.1 * abs(mh - ml)
        x = ml + (target - el) * (mh - ml) / (eh - el)
        return min(max(x, a), b)
    slope = slope0
    if len(rows) >= 2:
        secant = (e - rows[-2][2]) / (mu - rows[-2][1])
        if secant > 0:
            slope = secant
    return min(1.0, max(0.0, mu + (target - e) / slope))


def check_rule(rows, target=0.647, slope0=0.6):
    for n in range(1, len(rows)):
        assert rows[n][1] == pytest.approx(expected_next(rows[:n], target, slope0), abs=5e-6), n


@pytest.mark.parametrize("nprocs", [1, 2])
def test_rule_linear(tmp_path, nprocs):
    # e = 0.6 + 0.5 mu, first trial 0.3, first slope 0.6 (wrong on purpose):
    # 0.3 -> 0.12833 by the slope, then the secant is exact: 0.094; the
    # loop (clear, jump, variables kept) the same on 2 MPI ranks
    out, proc = fake(tmp_path, "0.6+0.5*v_mu", "mu_prep", 0.3, nprocs=nprocs)
    assert proc.returncode == 0, proc.stdout[-3000:]
    rows = trials(out)
    assert [m for _, m, _ in rows] == [0.3, 0.12833, 0.094]
    check_rule(rows)


def test_rule_bracket_never_reaches(tmp_path):
    # e jumps across the band 0.647 +- 0.005 at mu = 0.1234: no trial can be
    # accepted; after the bracket forms, regula falsi stays in its middle 80%
    out, proc = fake(tmp_path, "ternary(v_mu<0.1234,0.6,0.7)+0.01*v_mu",
                     "calib_max", 7)
    assert proc.returncode != 0
    assert "no trial within e_tol = 0.005 of e_target = 0.647 in calib_max = 7 trials" \
        in proc.stdout
    rows = trials(out)
    assert len(rows) == 7
    check_rule(rows)
    assert not (out / "prep.restart").exists() and not (out / "prep.json").exists()


@pytest.mark.parametrize("nprocs", [1, 2])
def test_rule_target_out_of_reach(tmp_path, nprocs):
    # e >= 0.7 at any friction: the slope leads to mu = 0, then 0 again
    # (on 2 ranks too: rank 0 removes the files, every rank stops)
    out, proc = fake(tmp_path, "0.7+0.1*v_mu", nprocs=nprocs)
    assert proc.returncode != 0
    assert "the next trial would be the same friction" in proc.stdout
    assert "e_target 0.647 cannot be reached" in proc.stdout
    rows = trials(out)
    assert [m for _, m, _ in rows] == [0.095, 0.0]
    check_rule(rows)
    assert not (out / "prep.restart").exists() and not (out / "prep.json").exists()


def test_rule_noisy_secant_falls_back_to_the_slope(tmp_path):
    # e rises as the friction falls between the first two trials (noise):
    # the secant is negative, so the third trial uses e_slope (from -var) again
    out, proc = fake(tmp_path, "ternary(v_mu>0.09,0.70,ternary(v_mu>0.01,0.72,0.645))",
                     "e_slope", 0.8)
    assert proc.returncode == 0, proc.stdout[-3000:]
    rows = trials(out)
    assert [m for _, m, _ in rows] == [0.095, 0.02875, 0.0]
    check_rule(rows, slope0=0.8)


# ---- 3. bad settings ----------------------------------------------------------------

@pytest.mark.parametrize("name,value,expect", [
    ("mu_prep", -0.1, "ERROR: mu_prep -0.1 must be >= 0"),
    ("calibrate", "maybe", "ERROR: calibrate maybe: use yes or no"),
    ("mu_prep", 1.5, "ERROR: calibrate yes: mu_prep 1.5, the first trial, must be between 0 and 1"),
    ("e_tol", 0, "ERROR: e_target 0.647, e_tol 0, e_slope 0.6: each must be > 0"),
    ("e_slope", -1, "e_slope -1: each must be > 0"),
    ("calib_max", 2.5, "ERROR: calib_max 2.5 must be a whole number >= 1"),
    ("calib_max", 0, "ERROR: calib_max 0 must be a whole number >= 1"),
])
def test_bad_settings(tmp_path, name, value, expect):
    # the first two without calibrate yes
    extra = () if "calibrate yes" not in expect and name in ("mu_prep", "calibrate") \
        else ("calibrate", "yes")
    out = tmp_path / "out"
    proc = deck(out, *SMALL, *extra, name, value, check=False)
    assert proc.returncode != 0
    assert expect in proc.stdout
    assert not (out / "calibration.txt").exists() and not (out / "prep.json").exists()
