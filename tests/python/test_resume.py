"""Restart files of the decks (inputs/) and the resume of a killed shear
stage, on 1 and 2 MPI ranks.

Every restart file the decks write has a checksum file FILE.cksum in the
format of POSIX cksum (fix grflow/checksum for the restart command,
inputs/restart_files.sh for write_restart); -var resume yes reads the
newest shear.restart.<step> that verifies, names the ones it skipped, and
never gives a damaged file to read_restart.

1. fix grflow/checksum writes, for every restart file, exactly what
   `cksum` prints for it (an independent implementation of the CRC).
2. A kill while a restart file is written leaves the file cut short and no
   checksum file: the resume skips it, starts from the file before, and the
   run ends with one series, every output step once, the rows before the
   file it used unchanged.
3. A file with garbage in its middle (its checksum file intact) is skipped.
4. No file verifies: a clear error, no read_restart.
5. A damaged prep.restart stops a fresh shear stage with a clear error.
6. fix grflow/checksum's own errors.
"""
import os
import shutil
import subprocess

import pytest

from lmprun import LMP, MPIEXEC

INPUTS = os.environ.get("GRFLOW_INPUTS",
                        os.path.join(os.path.dirname(__file__), "..", "..", "inputs"))
DECK = os.path.join(INPUTS, "cyclic_shear.lmp")
SMALL = {"preset": "quick", "N": "500", "series_every": "50"}
# the shear stage over a fixed horizon: restart files at 4000 ... 20000
SHEAR = dict(SMALL, stage="shear", restart_every=4000, max_steps=20000, n_post=1000)


def lmp(outdir, nprocs=1, **var):
    cmd = [LMP, "-nocite", "-echo", "none", "-log", "none", "-in", DECK,
           "-var", "inputs", INPUTS, "-var", "outdir", str(outdir)]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    if nprocs > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    return proc, proc.stdout + proc.stderr


def run_ok(outdir, nprocs=1, **var):
    proc, text = lmp(outdir, nprocs, **var)
    assert proc.returncode == 0, text[-3000:]
    return text


def cksum(path):
    """CRC and size as POSIX cksum (coreutils) prints them"""
    out = subprocess.run(["cksum", str(path)], capture_output=True, text=True, check=True)
    return out.stdout.split()[:2]


def rows(path):
    return [line.split() for line in path.read_text().splitlines()
            if line.strip() and not line.startswith("#")]


def restart_steps(outdir):
    return sorted(int(p.name.split(".")[-1]) for p in outdir.glob("shear.restart.*")
                  if p.name.split(".")[-1].isdigit())


@pytest.fixture(scope="module")
def prep(tmp_path_factory):
    out = tmp_path_factory.mktemp("prep") / "run"
    run_ok(out, stage="prep", **SMALL)
    return out


@pytest.fixture(scope="module", params=[1, 2], ids=["1rank", "2ranks"])
def reference(request, prep, tmp_path_factory):
    """an uninterrupted shear stage from prep, on 1 or 2 ranks"""
    out = tmp_path_factory.mktemp(f"ref{request.param}") / "run"
    shutil.copytree(prep, out)
    run_ok(out, request.param, **SHEAR)
    return out, request.param


def test_checksum_files_are_cksum(prep, reference):
    out, _ = reference
    assert restart_steps(out) == [0, 4000, 8000, 12000, 16000, 20000]
    names = [p for p in out.iterdir() if p.name.startswith(("prep.restart", "shear.restart."))
             and not p.name.endswith(".cksum")]
    for f in names:
        line = (out / (f.name + ".cksum")).read_text().split()
        assert line == cksum(f) + [f.name], f.name
    assert not list(out.glob("*.tmp"))


def killed_at(reference, tmp_path, step):
    """the run directory as a kill during the write of shear.restart.<step>
    leaves it: the series and events up to that step, the later restart
    files not yet written, that one cut to half its size, no checksum file"""
    ref, _ = reference
    out = tmp_path / "killed"
    shutil.copytree(ref, out)
    for s in restart_steps(out):
        if s > step:
            (out / f"shear.restart.{s}").unlink()
            (out / f"shear.restart.{s}.cksum").unlink()
    for name in ("series.txt", "events.txt"):
        keep = [line for line in (out / name).read_text().splitlines(keepends=True)
                if line.startswith("#") or float(line.split()[0]) <= step]
        (out / name).write_text("".join(keep))
    f = out / f"shear.restart.{step}"
    f.write_bytes(f.read_bytes()[: f.stat().st_size // 2])
    (out / f"shear.restart.{step}.cksum").unlink()
    return out


def test_kill_during_write_resumes_from_the_file_before(reference, tmp_path):
    ref, nprocs = reference
    out = killed_at(reference, tmp_path, 12000)
    text = run_ok(out, nprocs, resume="yes", **SHEAR)
    assert (f"skipped restart file {out}/shear.restart.12000: no checksum file"
            in text)
    assert f"resuming at step 8000 from {out}/shear.restart.8000" in text
    # one series to the end: every output step once, in order; the rows
    # before the file used are the uninterrupted run's, unchanged
    got, want = rows(out / "series.txt"), rows(ref / "series.txt")
    assert [r[0] for r in got] == [r[0] for r in want]
    n = sum(1 for r in want if int(r[0]) < 8000)
    assert got[:n] == want[:n]
    # the file cut short was written again, complete, with its checksum
    f = out / "shear.restart.12000"
    assert (out / "shear.restart.12000.cksum").read_text().split()[:2] == cksum(f)
    assert "GRFLOW shear: done at step 20000" in text


def test_garbage_in_a_file_is_skipped(reference, tmp_path):
    ref, nprocs = reference
    out = tmp_path / "garbage"
    shutil.copytree(ref, out)
    # the run killed after shear.restart.16000 (its checksum written), and
    # then 4 KiB in the middle of that file overwritten
    for name in ("shear.restart.20000", "shear.restart.20000.cksum"):
        (out / name).unlink()
    f = out / "shear.restart.16000"
    data = bytearray(f.read_bytes())
    mid = len(data) // 2
    data[mid:mid + 4096] = os.urandom(4096)
    f.write_bytes(bytes(data))
    text = run_ok(out, nprocs, resume="yes", **SHEAR)
    assert f"skipped restart file {out}/shear.restart.16000: damaged" in text
    assert f"resuming at step 12000 from {out}/shear.restart.12000" in text
    assert [r[0] for r in rows(out / "series.txt")] == [r[0] for r in rows(ref / "series.txt")]


def test_no_file_verifies_is_an_error(reference, tmp_path):
    ref, nprocs = reference
    out = tmp_path / "none"
    shutil.copytree(ref, out)
    for s in restart_steps(out):
        f = out / f"shear.restart.{s}"
        f.write_bytes(f.read_bytes()[:1000])
    series = (out / "series.txt").read_text()
    proc, text = lmp(out, nprocs, resume="yes", **SHEAR)
    assert proc.returncode != 0
    assert f"ERROR: GRFLOW resume: none of the restart files in {out} verifies" in text
    assert "shear.restart.20000 shear.restart.16000" in text
    assert "read_restart" not in (out / "log.shear.lammps").read_text().split("ERROR")[-1]
    # nothing was changed
    assert (out / "series.txt").read_text() == series
    # no restart file at all
    empty = tmp_path / "empty"
    shutil.copytree(ref, empty)
    for p in empty.glob("shear.restart.*"):
        p.unlink()
    proc, text = lmp(empty, nprocs, resume="yes", **SHEAR)
    assert proc.returncode != 0
    assert f"no restart file {empty}/shear.restart.<step> to resume from" in text


def test_damaged_prep_restart_stops_the_shear_stage(prep, tmp_path):
    out = tmp_path / "badprep"
    shutil.copytree(prep, out)
    f = out / "prep.restart"
    f.write_bytes(f.read_bytes()[:5000])
    proc, text = lmp(out, **SHEAR)
    assert proc.returncode != 0
    assert f"ERROR: GRFLOW: restart file {f} is not usable (damaged" in text
    assert not (out / "shear.restart.0").exists()


CHECKSUM_DECK = """
units           si
atom_style      sphere
region          box block 0 1 0 1 0 1
create_box      1 box
create_atoms    1 single 0.5 0.5 0.5
set             type 1 diameter 0.1 density 1000
{lines}
run             {steps}
"""


@pytest.mark.parametrize("lines,expect", [
    ("fix c all grflow/checksum extra", "unexpected argument 'extra'"),
    ("variable n equal 10*(floor(step/10)+1)\nrestart v_n r.*\nfix c all grflow/checksum",
     "restart files at steps set by a variable are not supported"),
    ("restart 5 r.%.*\nfix c all grflow/checksum",
     "written by several processors ('%' in the restart file name) are not supported"),
    ("fix c all grflow/checksum", "no restart command, no restart file to check"),
])
def test_fix_checksum_messages(tmp_path, lines, expect):
    deck = tmp_path / "in.lmp"
    deck.write_text(CHECKSUM_DECK.format(lines=lines, steps=10))
    proc = subprocess.run([LMP, "-nocite", "-log", "none", "-in", str(deck)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=60)
    assert expect in proc.stdout + proc.stderr


def test_fix_checksum_restart_pair_and_last_step(tmp_path):
    """the two files restart N a b alternates between, and a file written on
    the last step of a run (summed at the end of the run)"""
    deck = tmp_path / "in.lmp"
    deck.write_text(CHECKSUM_DECK.format(
        lines="fix nve all nve/sphere\nrestart 5 a.rst b.rst\nfix c all grflow/checksum",
        steps=15))
    subprocess.run([LMP, "-nocite", "-log", "none", "-in", str(deck)], cwd=tmp_path,
                   capture_output=True, text=True, timeout=60, check=True)
    for name in ("a.rst", "b.rst"):
        assert (tmp_path / f"{name}.cksum").read_text().split() == cksum(tmp_path / name) + [name]
