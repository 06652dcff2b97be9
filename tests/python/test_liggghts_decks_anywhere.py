"""The LIGGGHTS deck (inputs/liggghts/cyclic_shear.liggghts) from any
working directory (issue 40), as tests/python/test_decks_anywhere.py checks
the LAMMPS decks.

1. Without -var inputs it finds its files from the repository root
   (inputs), from inputs/ (.) and from inputs/liggghts/ (..), on 1 and 2
   MPI ranks; the output goes to runs/<preset> of the working directory
   (made with its parents), and the run is the same wherever it starts.
2. A deck copied into a project of its own runs with -var inputs.
3. Where the decks are not found, or -var inputs names a folder without
   them, the run stops with one message that says what to do, and no
   shell error before it.

Each run is the quick preset's preparation of 30 spheres (-var stage prep,
a few seconds), from a copy of inputs/ in a temporary folder, so that the
default outdir lands beside it and not in the source tree; the generated
files go to a grflow_cache of the test.

Environment: LIGGGHTS (a liggghts built with GRFLOW,
scripts/build-liggghts.sh), MPIEXEC, GRFLOW_INPUTS (the inputs/ directory).
"""

import json
import os
import shutil
import subprocess

import pytest

from runfiles import tail

LIGGGHTS = os.environ.get("LIGGGHTS", "liggghts")
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
INPUTS = os.path.abspath(os.environ.get(
    "GRFLOW_INPUTS", os.path.join(os.path.dirname(__file__), "..", "..", "inputs")))

# the smallest sample that prepares (test_liggghts_protocol.py,
# test_sample_too_small), stages 1-4 only
TINY = {"preset": "quick", "N": "30", "stage": "prep"}
NOT_FOUND = ("ERROR: no GRFLOW decks (params.lmp, liggghts/params.sh) in inputs, . or .. of the "
             "working directory: give their folder, -var inputs /path/to/grflow/inputs")


@pytest.fixture
def checkout(tmp_path):
    """the decks where a clone has them, tmp/grflow/inputs, copied so that
    the runs' default outdir (runs/<preset>, relative to the working
    directory) may land beside them"""
    root = tmp_path / "grflow"
    shutil.copytree(INPUTS, root / "inputs",
                    ignore=shutil.ignore_patterns("runs", "-p", "log.*"))
    return root


def run_in(cwd, deck, cache, nprocs=1, **var):
    """liggghts -in deck from the working directory cwd, without -var
    inputs unless given; the screen output is in stdout"""
    cmd = [LIGGGHTS, "-echo", "none", "-log", "none", "-in", str(deck),
           "-var", "grflow_cache", str(cache)]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    if nprocs > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace",
                          timeout=300)


def assert_ran(proc, out):
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:] + tail(
        out / "log.prep.lammps")
    assert (out / "prep.json").exists()
    # the search's shell command prints nothing (the old deck's "sh: cannot open")
    assert "sh: " not in proc.stdout + proc.stderr


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    """the deck's generated files (the search's, params.sh's, is.sh's)"""
    return tmp_path_factory.mktemp("cache")


def test_deck_runs_from_the_root_inputs_and_liggghts_folders(checkout, cache):
    """Without -var inputs the deck finds its files from the repository
    root (inputs), from inputs/ (.) and from inputs/liggghts/ (..); the
    output goes to runs/<preset> of the working directory (made with its
    parents), and the run is the same wherever it starts.  No folder named
    -p is left behind.  From inputs/liggghts/ on 2 ranks too."""
    prep = {}
    for where, deck in ((".", "inputs/liggghts/cyclic_shear.liggghts"),
                        ("inputs", "liggghts/cyclic_shear.liggghts"),
                        ("inputs/liggghts", "cyclic_shear.liggghts")):
        cwd = checkout / where
        out = cwd / "runs" / "quick"
        assert_ran(run_in(cwd, deck, cache, **TINY), out)
        prep[where] = (out / "prep.json").read_bytes()
        assert not (cwd / "-p").exists(), where
    assert prep["inputs"] == prep["."] and prep["inputs/liggghts"] == prep["."]
    cwd = checkout / "inputs" / "liggghts"
    assert_ran(run_in(cwd, "cyclic_shear.liggghts", cache, nprocs=2, outdir="np2", **TINY),
               cwd / "np2")
    assert json.loads((cwd / "np2/prep.json").read_text())["N"] == 30


def test_copied_deck_runs_with_var_inputs(checkout, tmp_path, cache):
    """A deck copied into a project of its own runs with -var inputs, an
    absolute path or one relative to the working directory; its outdir
    stays relative to the working directory."""
    project = tmp_path / "project"
    project.mkdir()
    shutil.copy(checkout / "inputs/liggghts/cyclic_shear.liggghts", project / "my_shear.liggghts")
    assert_ran(run_in(project, "my_shear.liggghts", cache, inputs=checkout / "inputs", **TINY),
               project / "runs" / "quick")
    assert_ran(run_in(project, "my_shear.liggghts", cache, inputs="../grflow/inputs",
                      outdir="rel", **TINY), project / "rel")
    assert ((project / "rel/prep.json").read_bytes()
            == (project / "runs/quick/prep.json").read_bytes())


def test_deck_not_found_says_what_to_do(checkout, tmp_path, cache):
    """A copied deck without -var inputs, or with a folder that holds no
    decks, stops before anything is written with one message that says
    to give -var inputs."""
    project = tmp_path / "project"
    project.mkdir()
    shutil.copy(checkout / "inputs/liggghts/cyclic_shear.liggghts", project / "my_shear.liggghts")
    nowhere = tmp_path / "nowhere"
    for var, message in (({}, NOT_FOUND),
                         ({"inputs": nowhere},
                          f"ERROR: inputs {nowhere}: no GRFLOW decks there (params.lmp, "
                          "liggghts/params.sh; a relative path is taken from the working "
                          "directory): give their folder, -var inputs /path/to/grflow/inputs")):
        proc = run_in(project, "my_shear.liggghts", cache, preset="quick", **var)
        text = proc.stdout + proc.stderr
        assert proc.returncode != 0, text
        assert [l for l in text.splitlines() if "ERROR" in l] == [message], text
        assert "sh: " not in text
        assert sorted(p.name for p in project.iterdir()) == ["my_shear.liggghts"]
        assert not nowhere.exists()
