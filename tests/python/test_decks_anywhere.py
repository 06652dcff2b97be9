"""The protocol decks (inputs/cyclic_shear.lmp, cyclic_shear_stock.lmp) from
any working directory (issue 40).

1. Without -var inputs they find their files from the repository root
   (inputs), from inputs/ (.) and from inputs/liggghts/ (..); the output
   goes to runs/<preset> of the working directory, and the run is the same
   wherever it starts.
2. A deck copied into a project of its own runs with -var inputs.
3. Where the decks are not found, or -var inputs names a folder without
   them, the run stops with one message that says what to do.

Each run is the quick preset's preparation of 30 spheres (-var stage prep,
a few seconds), from a copy of inputs/ in a temporary folder, so that the
default outdir lands beside it and not in the source tree.

Environment: LMP (lmp binary), GRFLOW_INPUTS (the inputs/ directory).
"""

import json
import os
import shutil
import subprocess

import pytest

from lmprun import LMP
from runfiles import tail

INPUTS = os.environ.get("GRFLOW_INPUTS",
                        os.path.join(os.path.dirname(__file__), "..", "..", "inputs"))

# the smallest sample that prepares (test_protocol.py, test_sample_too_small),
# stages 1-4 only
TINY = {"preset": "quick", "N": "30", "stage": "prep"}
NOT_FOUND = ("ERROR: no GRFLOW decks (params.lmp, check_numbers.sh) in inputs, . or .. of the "
             "working directory: give their folder, -var inputs /path/to/grflow/inputs")


@pytest.fixture
def checkout(tmp_path):
    """the decks where a clone has them, tmp/grflow/inputs, copied so that
    the runs' default outdir (runs/<preset>, relative to the working
    directory) may land beside them"""
    root = tmp_path / "grflow"
    shutil.copytree(INPUTS, root / "inputs", ignore=shutil.ignore_patterns("runs", "-p", "log.*"))
    return root


def run_in(cwd, deck, **var):
    """lmp -in deck, from the working directory cwd, without -var inputs
    unless given; the screen output is in stdout"""
    cmd = [LMP, "-nocite", "-echo", "none", "-log", "none", "-in", str(deck)]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=300)


def assert_ran(proc, out):
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:] + tail(
        out / "log.prep.lammps")
    assert (out / "prep.json").exists()


def test_decks_run_from_the_root_inputs_and_liggghts_folders(checkout):
    """Without -var inputs the deck finds its files from the repository
    root (inputs), from inputs/ (.) and from inputs/liggghts/ (..); the
    output goes to runs/<preset> of the working directory, and the run is
    the same wherever it starts.  No folder named -p is left behind."""
    prep = {}
    for where, deck in ((".", "inputs/cyclic_shear.lmp"), ("inputs", "cyclic_shear.lmp"),
                        ("inputs/liggghts", "../cyclic_shear.lmp")):
        cwd = checkout / where
        out = cwd / "runs" / "quick"
        assert_ran(run_in(cwd, deck, **TINY), out)
        prep[where] = (out / "prep.json").read_bytes()
        assert not (cwd / "-p").exists(), where
    assert prep["inputs"] == prep["."] and prep["inputs/liggghts"] == prep["."]
    # the stock deck, which finds cyclic_shear.lmp the same way
    cwd = checkout / "inputs"
    assert_ran(run_in(cwd, "cyclic_shear_stock.lmp", **TINY), cwd / "runs" / "quick-stock")
    assert json.loads((cwd / "runs/quick-stock/prep.json").read_text())["pair_stock"] == 1


def test_copied_deck_runs_with_var_inputs(checkout, tmp_path):
    """A deck copied into a project of its own runs with -var inputs, an
    absolute path or one relative to the working directory; its outdir
    stays relative to the working directory."""
    project = tmp_path / "project"
    project.mkdir()
    shutil.copy(checkout / "inputs" / "cyclic_shear.lmp", project / "my_shear.lmp")
    assert_ran(run_in(project, "my_shear.lmp", inputs=checkout / "inputs", **TINY),
               project / "runs" / "quick")
    assert_ran(run_in(project, "my_shear.lmp", inputs="../grflow/inputs", outdir="rel", **TINY),
               project / "rel")
    assert ((project / "rel/prep.json").read_bytes()
            == (project / "runs/quick/prep.json").read_bytes())


@pytest.mark.parametrize("deck", ["cyclic_shear.lmp", "cyclic_shear_stock.lmp"])
def test_decks_not_found_say_what_to_do(checkout, tmp_path, deck):
    """A copied deck without -var inputs, or with a folder that holds no
    decks, stops before anything is written with one message that says
    to give -var inputs."""
    project = tmp_path / "project"
    project.mkdir()
    shutil.copy(checkout / "inputs" / deck, project / deck)
    nowhere = tmp_path / "nowhere"
    for var, message in (({}, NOT_FOUND),
                         ({"inputs": nowhere},
                          f"ERROR: inputs {nowhere}: no GRFLOW decks there (params.lmp, "
                          "check_numbers.sh; a relative path is taken from the working "
                          "directory): give their folder, -var inputs /path/to/grflow/inputs")):
        proc = run_in(project, deck, preset="quick", **var)
        text = proc.stdout + proc.stderr
        assert proc.returncode != 0, text
        assert [l for l in text.splitlines() if "ERROR" in l] == [message], text
        assert sorted(p.name for p in project.iterdir()) == [deck]
        assert not nowhere.exists()


def test_stock_deck_searches_as_the_deck():
    """cyclic_shear_stock.lmp repeats cyclic_shear.lmp's search (it has to
    find that deck): the two copies are the same lines."""
    def search(name):
        text = open(os.path.join(INPUTS, name)).read()
        start = text.index("variable        grflow_inputs_given equal")
        last = text.index('elif "${grflow_decks_value} == 0"', start)
        return text[start:text.index('  "quit 1"\n', last)]
    assert search("cyclic_shear.lmp") == search("cyclic_shear_stock.lmp")
