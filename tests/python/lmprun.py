"""Running lmp from the GRFLOW pytest tests.

Environment (set by ctest): LMP (lmp binary), MPIEXEC (mpirun),
GRFLOW_TEST_DECKS (tests/decks).
"""
import os
import subprocess

LMP = os.environ.get("LMP", "lmp")
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
DECKS = os.environ.get("GRFLOW_TEST_DECKS",
                       os.path.join(os.path.dirname(__file__), "..", "decks"))


def run_lmp(args, cwd, nprocs=1, stdin=None, check=True, timeout=600):
    """Run lmp quietly (on nprocs MPI ranks); return the CompletedProcess.
    With check, a non-zero exit fails the test with LAMMPS's last output."""
    cmd = [LMP, "-log", "none", "-nocite", "-echo", "none"] + list(args)
    if nprocs > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    proc = subprocess.run(cmd, cwd=cwd, input=stdin, capture_output=True, text=True,
                          timeout=timeout)
    if check:
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return proc
