"""examples/grflow: the LAMMPS-style examples of every GRFLOW command.

- Every command with a doc page (doc/*.rst) has its input
  examples/grflow/in.<page>; every command whose page has an "In LIGGGHTS"
  section, and the LIGGGHTS contact model, has its LIGGGHTS input in
  examples/grflow/liggghts/; the README there names every input.
- Every input runs to its end on 1 and 2 MPI ranks, alone in an empty
  directory (so it reads no file but itself): exit status 0, no "ERROR",
  the rank count in LAMMPS's "Loop time ... on N procs" lines, the text of
  its last print command, and for LAMMPS the "Total wall time" line.  The
  LIGGGHTS inputs run only when a LIGGGHTS build with GRFLOW is given
  (LIGGGHTS), as the other LIGGGHTS tests.
- Beside every input, its two logs as LAMMPS's examples have them,
  log.<DDMonYY>.<name>.g++.1 and .g++.2: written by the right program on 1
  and 2 ranks, run to the end without an error, and of this version of the
  input (its commands up to the first run, and its last one, are echoed in
  the log in order).

Environment: LMP (lmp), MPIEXEC (mpirun), LIGGGHTS (a liggghts built with
GRFLOW; the LIGGGHTS inputs are skipped without it), GRFLOW_EXAMPLES
(examples/grflow; default: the one of this source tree).
"""
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from lmprun import LMP, MPIEXEC

HERE = Path(__file__).resolve().parent
SOURCE = HERE.parents[1]
EXAMPLES = Path(os.environ.get("GRFLOW_EXAMPLES", SOURCE / "examples" / "grflow"))
DOC = SOURCE / "doc"
LIGGGHTS = os.environ.get("LIGGGHTS")

HOSTS = {"lammps": EXAMPLES, "liggghts": EXAMPLES / "liggghts"}
BANNER = {"lammps": "LAMMPS (", "liggghts": "LIGGGHTS ("}


def inputs(host):
    return sorted(p for p in HOSTS[host].glob("in.*") if p.is_file())


def name(path):
    return path.name[len("in."):]


def commands(path):
    """The input's lines with continuations ('&' at the end) joined, as
    LAMMPS echoes them, whitespace collapsed; empty lines left out"""
    out, pending = [], ""
    for line in path.read_text().splitlines():
        line = pending + line
        if line.rstrip().endswith("&"):
            pending = line.rstrip()[:-1]
            continue
        pending = ""
        if line.strip():
            out.append(" ".join(line.split()))
    return out


def is_command(line):
    return not line.startswith("#")


def last_print_text(path):
    """The literal start of the input's last command, a print: the text
    its output line begins with"""
    last = [c for c in commands(path) if is_command(c)][-1]
    m = re.match(r"""print\s+["'](.*)""", last)
    assert m, f"{path.name}: the last command is not a print: {last}"
    literal = re.split(r"[$\"']", m.group(1))[0]
    assert len(literal.strip()) >= 3, f"{path.name}: the last print starts with too little text: {last}"
    return literal


def printed(literal, text):
    """a line of the output begins with the literal (the echo of the print
    command itself begins with 'print')"""
    return re.search("^" + re.escape(literal), text, re.M) is not None


def setup_part(path):
    """The commands (and comments) up to and including the first run: run
    once, in order, whatever loops come later"""
    lines = commands(path)
    first_run = next(k for k, c in enumerate(lines) if re.match(r"run\s", c))
    return lines[:first_run + 1]


# ---- what must be there --------------------------------------------------

def doc_pages():
    return sorted(p.stem for p in DOC.glob("*.rst"))


def test_every_command_has_its_examples():
    pages = doc_pages()
    lammps_pages = [p for p in pages if not p.startswith("liggghts_")]
    assert len(lammps_pages) >= 6, pages     # the package's six commands at least
    lammps = {name(p) for p in inputs("lammps")}
    assert sorted(set(lammps_pages) - lammps) == []
    in_liggghts = [p for p in lammps_pages if "\nIn LIGGGHTS\n" in (DOC / f"{p}.rst").read_text()]
    assert in_liggghts, "no doc page has an 'In LIGGGHTS' section"
    wanted = set(in_liggghts) | {p[len("liggghts_"):] for p in pages if p.startswith("liggghts_")}
    liggghts = {name(p) for p in inputs("liggghts")}
    assert sorted(wanted - liggghts) == []
    # fix grflow/checksum is LAMMPS only: its page says so and there is no LIGGGHTS input
    assert "fix_grflow_checksum" not in in_liggghts


def test_the_readme_names_every_input():
    readme = (EXAMPLES / "README.md").read_text()
    for host in HOSTS:
        for path in inputs(host):
            rel = path.relative_to(EXAMPLES).as_posix()
            assert rel in readme, f"examples/grflow/README.md does not name {rel}"


# ---- the logs beside the inputs -------------------------------------------

ALL_INPUTS = [(host, p) for host in HOSTS for p in inputs(host)]


def log_files(path, nprocs):
    pattern = re.compile(r"log\.\d{1,2}[A-Z][a-z]{2}\d{2}\." + re.escape(name(path))
                         + r"\.g\+\+\." + str(nprocs) + "$")
    return sorted(p for p in path.parent.iterdir() if pattern.match(p.name))


def in_order(needles, lines):
    """the first needle not found in lines after the previous one; None if all are"""
    k = 0
    for needle in needles:
        while k < len(lines) and lines[k] != needle:
            k += 1
        if k == len(lines):
            return needle
        k += 1
    return None


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("host,path", ALL_INPUTS, ids=[f"{h}-{name(p)}" for h, p in ALL_INPUTS])
def test_the_logs_are_beside_the_input(host, path, nprocs):
    logs = log_files(path, nprocs)
    assert len(logs) == 1, f"{path.name}: logs for {nprocs} rank(s): {[p.name for p in logs]}"
    text = logs[0].read_text(errors="replace")
    assert text.startswith(BANNER[host]), f"{logs[0].name} is not a {host} log"
    assert "ERROR" not in text, f"{logs[0].name} has an error"
    loops = re.findall(r"Loop time of \S+ on (\d+) procs", text)
    assert loops and set(loops) == {str(nprocs)}, f"{logs[0].name}: runs on {set(loops)} procs"
    if host == "lammps":
        assert "Total wall time" in text, f"{logs[0].name} did not run to its end"
    lines = [" ".join(line.split()) for line in text.splitlines()]
    missing = in_order(setup_part(path), lines)
    assert missing is None, f"{logs[0].name} is not of this {path.name}: no '{missing}'"
    last = [c for c in commands(path) if is_command(c)][-1]
    assert last in lines, f"{logs[0].name} does not reach the last command of {path.name}"
    assert printed(last_print_text(path), text), f"{logs[0].name} does not print the last line"


# ---- running every input -----------------------------------------------------

def run_input(host, path, nprocs, work):
    shutil.copy(path, work / path.name)    # alone: an input that reads another file fails
    exe = LMP if host == "lammps" else LIGGGHTS
    cmd = [exe, "-in", path.name, "-log", "none", "-echo", "none"]
    if host == "lammps":
        cmd.append("-nocite")
    if nprocs > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    env = dict(os.environ, OMP_NUM_THREADS="1")
    return subprocess.run(cmd, cwd=work, capture_output=True, text=True, errors="replace",
                          timeout=600, env=env)


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("host,path", ALL_INPUTS, ids=[f"{h}-{name(p)}" for h, p in ALL_INPUTS])
def test_the_input_runs_to_its_end(host, path, nprocs, tmp_path):
    if host == "liggghts" and not LIGGGHTS:
        pytest.skip("no LIGGGHTS build given (LIGGGHTS)")
    proc = run_input(host, path, nprocs, tmp_path)
    out = proc.stdout + proc.stderr
    tail = out[-3000:]
    assert proc.returncode == 0, tail
    assert "ERROR" not in out, tail
    loops = re.findall(r"Loop time of \S+ on (\d+) procs", proc.stdout)
    assert loops and set(loops) == {str(nprocs)}, tail
    assert printed(last_print_text(path), proc.stdout), tail
    if host == "lammps":
        assert "Total wall time" in proc.stdout, tail
    seconds = [float(t) for t in re.findall(r"Loop time of (\S+) on", proc.stdout)]
    print(f"[ measured ] {host} {path.name} on {nprocs} rank(s): {len(seconds)} runs, "
          f"loop time {sum(seconds):.2f} s")
