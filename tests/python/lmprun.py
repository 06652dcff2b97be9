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


def cell_from_restart(restart, newton="on", grid="1 1 1", wall="1.0e6 1.15"):
    """Deck lines that continue a packing between two GRFLOW walls from a
    restart file: newton, processor grid, the settings restart files do not
    keep, fix w (grflow/wall with coefficients `wall`; its positions come
    from the restart file), fix nve, and variables zlo, zhi of the walls."""
    return (f"newton          {newton}\n"
            f"processors      {grid}\n"
            f"read_restart    {restart}\n"
            "comm_modify     vel yes\n"
            "neighbor        0.2e-3 bin\n"
            "neigh_modify    delay 0 every 1 check yes\n"
            f"fix             w all grflow/wall {wall} zlo 0.0 zhi 8.0e-3\n"
            "fix             nve all nve/sphere\n"
            "variable        zlo equal f_w[4]\n"
            "variable        zhi equal f_w[10]\n")


def make_packing(work, nside=7, seed=99, dmin=1.0e-3, dmax=2.0e-3, phi=0.60, ncomp=30000):
    """A dense periodic packing of nside^3 spheres (tests/decks/dense_packing.lmp),
    written to work/packing.data; returns that path."""
    data = work / "packing.data"
    deck = work / "make_packing.lmp"
    deck.write_text(
        "units si\natom_style sphere\n"
        f"variable nside equal {nside}\nvariable seed equal {seed}\n"
        f"variable dmin equal {dmin}\nvariable dmax equal {dmax}\n"
        f"variable phi equal {phi}\nvariable ncomp equal {ncomp}\n"
        f"variable out string {data}\n"
        f"include {os.path.join(DECKS, 'dense_packing.lmp')}\n")
    run_lmp(["-in", str(deck)], work)
    return data
