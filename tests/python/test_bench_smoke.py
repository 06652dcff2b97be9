"""Smoke tests of bench/ (ctest bench.smoke, and bench.smoke_liggghts when
GRFLOW's LIGGGHTS build is there): every maintained bench script run with
tiny parameters (100 or 216 spheres, a few hundred to a few thousand
steps), each checked for exit status 0 and for the output it promises.
The numbers they print mean nothing at this size; what is tested is that
the scripts, their decks and their Python still fit together.

Which scripts run here and which do not, and why: bench/README.md, "Smoke
tests".

Environment (set by ctest): LMP; BUILD, the build tree whose
python/bin the scripts fall back to for grflow-figures and grflow-python
(bench/commands.sh); LIGGGHTS for the tests named *liggghts*.
"""
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

TOP = Path(__file__).resolve().parents[2]
BENCH = TOP / "bench"
LMP = os.environ.get("LMP", str(TOP / "build" / "lmp"))
LIGGGHTS = os.environ.get("LIGGGHTS", "")
# the quick preset at 100 spheres: a preparation of a few seconds
TINY = ["-var", "preset", "quick", "-var", "N", "100"]


def bench(script, *args, env=None, timeout=300):
    """Run bench/SCRIPT ARGS; assert status 0; return its stdout."""
    e = dict(os.environ, LMP=LMP, OMP_NUM_THREADS="1", MPLBACKEND="Agg")
    e.update(env or {})
    start = time.time()
    proc = subprocess.run(["bash", str(BENCH / script)] + [str(a) for a in args], env=e,
                          capture_output=True, text=True, timeout=timeout)
    print(f"[ measured ] bench/{script}: {time.time() - start:.1f} s")
    assert proc.returncode == 0, (f"bench/{script} exited with {proc.returncode}\n"
                                  f"{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")
    return proc.stdout


def lmp(*args, cwd):
    proc = subprocess.run([LMP, "-nocite", "-screen", "none"] + [str(a) for a in args],
                          cwd=cwd, capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, OMP_NUM_THREADS="1"))
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory):
    """A tiny run of the protocol: preparation, then 3000 shear steps with a
    restart file every 1000 (a run-out: no liquefaction at this size)."""
    out = tmp_path_factory.mktemp("run") / "r"
    deck = ["-log", "none", "-in", TOP / "inputs" / "cyclic_shear.lmp",
            "-var", "inputs", TOP / "inputs", "-var", "outdir", out] + TINY
    lmp(*deck, "-var", "stage", "prep", cwd=out.parent)
    lmp(*deck, "-var", "stage", "shear", "-var", "max_steps", 3000,
        "-var", "restart_every", 1000, cwd=out.parent)
    assert (out / "shear.restart.2000.cksum").is_file()
    return out


@pytest.fixture(scope="module")
def packing(tmp_path_factory):
    """The pair benchmark's packing at 216 spheres: bench/in.prep_packing
    with its 20^3 lattice cut to 6^3 and a short shear (2 segments)."""
    out = tmp_path_factory.mktemp("packing")
    text = (BENCH / "in.prep_packing").read_text()
    box = "region          box block 0 20 0 20 0 20"
    assert text.count(box) == 1, "in.prep_packing's lattice line moved: update this fixture"
    (out / "in.prep_packing").write_text(text.replace(box, box.replace("20", "6")))
    lmp("-in", "in.prep_packing", "-var", "outdir", out, "-var", "nseg", 2,
        "-var", "nstep", 1000, "-log", "log.prep", cwd=out)
    for f in ("packing.data", "packing.vars", "packing_compressed.data"):
        assert (out / f).is_file()
    return out


def with_packing(packing, dest):
    dest.mkdir()
    for f in ("packing.data", "packing.vars", "packing_compressed.data"):
        shutil.copy(packing / f, dest)
    return dest


def test_run_pair_bench(packing, tmp_path):
    out = with_packing(packing, tmp_path / "pair")
    text = bench("run_pair_bench.sh", LMP, out, env={"NSTEPS": "200", "NWARM": "50",
                                                      "ROUNDS": "1"})
    assert "reusing" in text
    result = json.loads((out / "pair_bench_results.json").read_text())
    assert sorted(result["runs"]) == ["gran_hooke_history", "granular", "grflow"]
    assert "| granular/grflow (4 modes)" in text


def test_compute_cost(packing, tmp_path):
    """bench/in.compute_cost (a deck, no driver): 7 timed runs."""
    out = with_packing(packing, tmp_path / "cost")
    lmp("-in", BENCH / "in.compute_cost", "-var", "outdir", out, "-var", "nsteps", 200,
        "-log", out / "log.cost", cwd=out)
    assert (out / "log.cost").read_text().count("\nLoop time of") == 7


def test_run_protocol_step(run_dir, tmp_path):
    text = bench("run_protocol_step.sh", 500,
                 env={"PREP": str(run_dir / "prep.restart"), "OUT": str(tmp_path),
                      "VARS": "-var preset quick"})
    assert "grflow, 1 rank(s): 500 steps" in text
    assert "grflow, 2 rank(s): 500 steps" in text


def test_shear_ab(run_dir, tmp_path):
    """From a shear restart file (resumed, so its checksum file must come
    along), two variants in one round, with profile_shear.py's lines."""
    text = bench("shear_ab.sh", run_dir / "shear.restart.1000", 500, 1, "one|1|", "two|2|",
                 env={"OUT": str(tmp_path), "VARS": "-var preset quick"})
    assert "round 1 one: # all: 500 steps" in text
    assert "round 1 two: # all: 500 steps" in text
    assert "round 1 one | Pair |" in text


def test_vec2_gain(run_dir, tmp_path):
    """Two states (a prep.restart and a shear restart file), two rounds,
    the same binary as both variants: 8 runs, the table and the ratios."""
    quick = "-var preset quick"
    text = bench("vec2_gain.sh", LMP, LMP, 2,
                 f"jam|{run_dir / 'prep.restart'}|300|{quick}",
                 f"sheared|{run_dir / 'shear.restart.1000'}|300|{quick}",
                 env={"OUT": str(tmp_path)})
    rows = (tmp_path / "rounds.tsv").read_text().splitlines()[1:]
    assert len(rows) == 8
    assert all(r.split("\t")[3] == "300" for r in rows)
    # even rounds run the scalar binary first
    assert [r.split("\t")[2] for r in rows[4:6]] == ["scalar", "vec2"]
    for state in ("jam", "sheared"):
        assert f"{state}: per round" in text
    assert text.count("loop ratio scalar/vec2: median") == 2


def test_sample_shear_speed(run_dir, tmp_path):
    """Samples at steps 0 (prep.restart) and 2000 (EVERY=2), 1 core and 2
    ranks each, and the predicted time of the 3000-step stage."""
    text = bench("sample_shear_speed.sh", run_dir, 300,
                 env={"OUT": str(tmp_path), "EVERY": "2", "VARS": "preset quick"})
    assert "3000 (finished: yes), 2 samples of 300 steps" in text
    assert "stage of 3000 steps:" in text


def test_seed_scatter_and_timed_case(tmp_path):
    """seed_scatter.sh (through timed_case.sh init and run) with calibrate
    yes accepting the first preparation (e_tol 1), then timed_case.sh total;
    the same command again finds the seed done."""
    args = [tmp_path / "seeds", "1", 1, 0] + TINY + ["-var", "e_tol", 1, "-var", "max_steps", 500]
    bench("seed_scatter.sh", *args)
    d = tmp_path / "seeds" / "s1"
    assert (d / "bin" / "lmp").is_file() and (d / "prep.json").is_file()
    assert "GRFLOW shear: done at step 500" in (d / "log.shear.lammps").read_text()
    assert "seed 1: done" in bench("seed_scatter.sh", *args)
    total = bench("timed_case.sh", "total", d)
    assert "in 2 segments" in total and "still running" not in total


def test_timestep_study(tmp_path):
    """One seed, one factor: the run, its figures, timestep_table.py's table."""
    out = tmp_path / "dt"
    text = bench("timestep_study.sh", out, "1", "0.2", *TINY, "-var", "max_steps", 500,
                 env={"CPU": "0"})
    assert (out / "s1_f0.2" / "figures" / "summary.json").is_file()
    assert "| 0.2 | 1 |" in text


def test_variants_quick_and_plot_sensitivity(tmp_path):
    """A wall-speed variant as plot_sensitivity.py reads them (runs/vx,
    s<seed>_v<v_x>), its row in the table, then the figure from it."""
    runs = tmp_path / "runs"
    text = bench("variants_quick.sh", runs / "vx", "1", "v0.05|-var N 100 -var max_steps 500",
                 env={"JOBS": "1"})
    assert (runs / "vx" / "s1_v0.05" / "figures" / "summary.json").is_file()
    assert "| s1_v0.05 | " in text and "failed or unfinished" not in text
    proc = subprocess.run([sys.executable, str(BENCH / "plot_sensitivity.py"), "--runs",
                           str(runs), "--out", str(tmp_path / "sensitivity.png")],
                          capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, MPLBACKEND="Agg"))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert (tmp_path / "sensitivity.png").stat().st_size > 0


def test_prep_scatter(tmp_path):
    text = bench("prep_scatter.sh", tmp_path, env={"SEEDS": "1", "N": "60"})
    names = sorted(line.split()[0] for line in text.splitlines())
    assert names == ["agitated", "plain", "small"]


# ---- LIGGGHTS (bench.smoke_liggghts) ----------------------------------------

needs_liggghts = pytest.mark.skipif(not LIGGGHTS, reason="no LIGGGHTS build (LIGGGHTS unset)")


@needs_liggghts
def test_host_speed_liggghts(packing, tmp_path):
    out = with_packing(packing, tmp_path / "hosts")
    text = bench("host_speed.sh", out, env={"LIGGGHTS": LIGGGHTS, "ROUNDS": "1",
                                            "NSTEPS": "200", "NWARM": "50",
                                            "HOME": str(tmp_path)})
    lines = [line for line in text.splitlines() if line.split()[:1] == ["1"]]
    assert len(lines) == 1 and len(lines[0].split()) >= 4, text


@needs_liggghts
def test_host_agreement_and_steprate_liggghts(tmp_path):
    """Seed 1 in both hosts (2000 shear steps, a restart file every 1000),
    the table of both summaries, then host_steprate.sh from steps 0 and 1000
    of both runs."""
    out = tmp_path / "hosts"
    vars_ = TINY + ["-var", "max_steps", 2000, "-var", "restart_every", 1000]
    # HOME: the LIGGGHTS decks' generated files in a cache of this test's
    # own ($HOME/.cache/grflow/liggghts), not one that other runs share
    env = {"LIGGGHTS": LIGGGHTS, "TMPDIR": str(tmp_path), "HOME": str(tmp_path)}
    text = bench("host_agreement.sh", out, "1", *vars_, env=env)
    for host in ("lammps", "liggghts"):
        assert (out / f"{host}_s1" / "figures" / "summary.json").is_file(), text
    assert "| 1 | LAMMPS |" in text and "| 1 | LIGGGHTS |" in text
    text = bench("host_steprate.sh", out, 1, 0, 1000, 1, *TINY, env=dict(env, STEPS="500"))
    rows = [line.split() for line in text.splitlines()[1:]]
    assert sorted((r[0], r[1]) for r in rows) == [("lammps", "jammed"), ("lammps", "liquefied"),
                                                  ("liggghts", "jammed"),
                                                  ("liggghts", "liquefied")], text


@needs_liggghts
def test_dense_roundoff_liggghts(tmp_path):
    """One packing (3000 gas steps), 500 dense steps: the round-off runs,
    LIGGGHTS and one kn change against the reference, and the summary."""
    env = dict(os.environ, LMP=LMP, LIGGGHTS=LIGGGHTS, OMP_NUM_THREADS="1", PACKINGS="1",
               GAS_STEPS="3000", DENSE_STEPS="500", KN_DELTAS="1e-3", KN_ON="lmp")
    env.pop("LMP2", None)
    start = time.time()
    proc = subprocess.run([sys.executable, str(BENCH / "dense_roundoff.py"), str(tmp_path)],
                          env=env, capture_output=True, text=True, timeout=300)
    print(f"[ measured ] bench/dense_roundoff.py: {time.time() - start:.1f} s")
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    runs = [line.split()[1] for line in (tmp_path / "table.txt").read_text().splitlines()
            if not line.startswith("#")]
    assert runs == ["newton", "sort", "x2", "z2", "ulp", "liggghts", "kn*(1+1e-3)"]
    assert "largest relative differences at step 500, 1 packing(s):" in proc.stdout


def test_source_lines():
    """bench/source_lines.py (the line counts of issue 40's note): its
    comment and blank-line rule on a known text, and the totals of a folder
    at HEAD as the sum of its files"""
    sys.path.insert(0, str(BENCH))
    try:
        import source_lines
    finally:
        sys.path.pop(0)
    text = "int a;\n/* one\n   two */\n// three\n\n  b(); // four\nc /* five */ ;\n"
    assert source_lines.code_lines(text) == 3
    proc = subprocess.run([sys.executable, str(BENCH / "source_lines.py"), "src/OPENMP"],
                          cwd=TOP, capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    rows = [line.split(None, 1) for line in proc.stdout.splitlines()]
    files = {name: int(n) for n, name in rows if not name.endswith("(total)")}
    totals = {name: int(n) for n, name in rows if name.endswith("(total)")}
    assert set(files) == {"src/OPENMP/pair_granular_grflow_omp.cpp",
                          "src/OPENMP/pair_granular_grflow_omp.h"}
    assert all(n > 0 for n in files.values())
    assert totals == {"src/OPENMP/ (total)": sum(files.values())}
