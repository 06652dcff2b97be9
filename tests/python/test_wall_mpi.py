"""fix grflow/wall gives the same trajectory and the same wall forces with 1
and 2 MPI ranks and with newton on or off (up to round-off).

A packing of 144 spheres is compressed between a bottom wall and a top wall
(once, one rank, written to a restart file); then the top wall shears it and
presses on.  The ranks split the box along z (processors 1 1 2: each wall
belongs to another rank, so the wall forces are summed across ranks) or
along x (processors 2 1 1: spheres touching the sheared top wall move to the
other rank, and their wall history must go with them).  A lost or zeroed
history changes the spins by ~1e-2 (measured in test_fix_wall.cpp), far
above the round-off tolerance here.

A sphere that goes through a wall on one of two ranks stops the run with
the error message, it does not hang.

Environment: LMP (lmp binary), MPIEXEC (mpirun).
"""

import os

import numpy as np
import pytest

from lmprun import DECKS, cell_from_restart, run_lmp

STEPS = 2000


SHEAR = """
{cell}
velocity        all set 15.0 NULL NULL sum yes
fix_modify      w wall lo vel 15.0 0 0 wall hi vel 16.0 -0.3 -0.01
thermo          1000
run             {steps}
write_dump      all custom {dump} id x y z omegax omegay omegaz modify sort id format float %.17g
print           "NEWTON $(is_active(newton,pair))"
print           "WALL $(f_w[1]:%.17g) $(f_w[2]:%.17g) $(f_w[3]:%.17g) $(f_w[4]:%.17g) $(f_w[5]:%.17g) $(f_w[6]:%.17g) $(f_w[7]:%.17g) $(f_w[8]:%.17g) $(f_w[9]:%.17g) $(f_w[10]:%.17g) $(f_w[11]:%.17g) $(f_w[12]:%.17g)"
"""

CROSSING = """
units           si
atom_style      sphere
atom_modify     map array
boundary        p p f
processors      1 1 2
region          box block 0 0.01 0 0.01 0 0.01
create_box      1 box
create_atoms    1 single 0.005 0.005 0.003
create_atoms    1 single 0.005 0.005 0.007
set             group all diameter 1.0e-3 density 2650
set             atom 1 vz -100.0
timestep        1.0e-7
fix             w all grflow/wall 1.0 0.0 zlo 0.001 zhi 0.009
fix             nve all nve/sphere
run             100000
"""




@pytest.fixture(scope="module")
def packing(tmp_path_factory):
    work = tmp_path_factory.mktemp("wall_mpi")
    restart = work / "packing.restart"
    dump = work / "packing.dump"
    run_lmp(["-in", os.path.join(DECKS, "wall_packing.lmp"), "-var", "restart", str(restart),
             "-var", "dump", str(dump)], work)
    return work, restart, np.loadtxt(dump, skiprows=9)


def sheared(packing, nprocs, newton, grid):
    work, restart, _ = packing
    tag = f"np{nprocs}_{newton}_{grid.replace(' ', '')}"
    dump = work / f"final_{tag}.dump"
    deck = work / f"shear_{tag}.lmp"
    deck.write_text(SHEAR.format(cell=cell_from_restart(restart, newton, grid), steps=STEPS,
                                 dump=dump))
    out = run_lmp(["-in", str(deck)], work, nprocs).stdout
    # the settings really were those asked for
    flags = next(line for line in out.splitlines() if line.startswith("NEWTON")).split()
    assert float(flags[1]) == (1.0 if newton == "on" else 0.0)
    assert f"{grid.replace(' ', ' by ')} MPI processor grid" in out
    wall = next(line for line in out.splitlines() if line.startswith("WALL"))
    table = np.loadtxt(dump, skiprows=9)
    return table, np.array([float(v) for v in wall.split()[1:]])


@pytest.fixture(scope="module")
def reference(packing):
    return sheared(packing, 1, "on", "1 1 1")


def rel_diff(a, b):
    return np.abs(a - b).max() / np.abs(b).max()


VARIANTS = [(1, "off", "1 1 1"), (2, "on", "1 1 2"), (2, "off", "1 1 2"),
            (2, "on", "2 1 1"), (2, "off", "2 1 1")]


@pytest.mark.parametrize("nprocs,newton,grid", VARIANTS)
def test_same_trajectory_and_wall_forces(packing, reference, nprocs, newton, grid):
    ref, ref_wall = reference
    got, wall = sheared(packing, nprocs, newton, grid)
    assert np.array_equal(got[:, 0], ref[:, 0])
    dx = rel_diff(got[:, 1:4], ref[:, 1:4])
    dw = rel_diff(got[:, 4:7], ref[:, 4:7])
    forces = [0, 1, 2, 6, 7, 8]
    df = np.abs(wall[forces] - ref_wall[forces]).max() / np.abs(ref_wall[forces]).max()
    dpos = np.abs(np.delete(wall, forces) - np.delete(ref_wall, forces)).max()
    print(f"[ measured ] np={nprocs} newton={newton} grid={grid}: "
          f"x {dx:.3e}  omega {dw:.3e}  wall forces {df:.3e}  wall positions {dpos:.3e}")
    # round-off from summation order grows along the run: measured 2e-13 in
    # omega after 200 steps, 1e-10 after 2000 and 1.5e-7 after 5000 (in x
    # 4e-16, 8e-13, 6e-10); wall histories zeroed on migration give 8e-2 in
    # omega (measured by breaking unpack_exchange)
    assert dx < 1e-10
    assert dw < 1e-9
    assert df < 1e-10
    assert dpos == 0.0


def test_reference_is_not_trivial(packing, reference):
    """the top wall shears and loads the packing; the packing and both walls
    travel half a box length along x, so that every sphere touching a wall
    ends on the other rank of processors 2 1 1 (boundaries at x = L/2 and
    the periodic boundary), with its wall history"""
    _, _, start = packing
    final, wall = reference
    print(f"[ measured ] reference wall vector: {' '.join(f'{v:.4g}' for v in wall)}")
    assert wall[8] > 5.0 and abs(wall[6]) > 0.5            # top wall: loaded and sheared
    assert abs(wall[2] + wall[8]) < 0.2 * wall[8]          # carried to the bottom wall
    assert wall[9] < 8.0e-3 and wall[10] > 3.0e-3          # moved down and along x
    lx = 6.0e-3
    side0 = np.floor(start[:, 1] / (lx / 2))
    side1 = np.floor(final[:, 1] / (lx / 2))
    top = final[:, 3] + 0.7e-3 > wall[9]
    bottom = final[:, 3] - 0.7e-3 < wall[3]
    moved = [np.count_nonzero(near & (side0 != side1)) for near in (top, bottom)]
    print(f"[ measured ] spheres near the top / bottom wall that changed rank "
          f"(grid 2 1 1): {moved[0]} / {moved[1]}")
    assert min(moved) >= 5


def test_crossing_is_an_error_not_a_hang(tmp_path):
    deck = tmp_path / "crossing.lmp"
    deck.write_text(CROSSING)
    proc = run_lmp(["-in", str(deck)], tmp_path, 2, check=False, timeout=120)
    assert proc.returncode != 0
    assert "Fix grflow/wall w: atom 1 crossed the zlo wall" in proc.stdout + proc.stderr


def test_crossing_at_the_box_face_is_the_walls_error(tmp_path):
    """With the walls on the fixed box faces (as the decks put them) the
    crossing atom leaves the box: the wall reports it before LAMMPS's
    exchange would drop it as a lost atom.  With pair and skin the crossing
    comes on a step with a neighbor list build: at 1000 m/s the atom moves a
    skin (1e-4 m) per step, so every step has one."""
    deck = tmp_path / "crossing_face.lmp"
    deck.write_text(CROSSING.replace("1 1 2", "1 1 *").replace("vz -100.0", "vz -1000.0")
                    .replace("zlo 0.001 zhi 0.009", "zlo 0.0 zhi 0.01").replace(
        "fix             nve", "pair_style      granular/grflow\n"
        "pair_coeff      * * 1.0e6 1.15\n"
        "neighbor        1.0e-4 bin\n"
        "neigh_modify    delay 0 every 1 check yes\n"
        "comm_modify     vel yes\n"
        "fix             nve"))
    for nprocs in (1, 2):
        proc = run_lmp(["-in", str(deck)], tmp_path, nprocs, check=False, timeout=120)
        text = proc.stdout + proc.stderr
        assert proc.returncode != 0
        assert "Fix grflow/wall w: atom 1 crossed the zlo wall" in text
        assert "Lost atoms" not in text


WALL_OUTSIDE = """
units           si
atom_style      sphere
boundary        p p {bz}
region          box block 0 0.01 0 0.01 0 0.01
create_box      1 box
create_atoms    1 single 0.005 0.005 0.005
set             type 1 diameter 0.001 density 2650
comm_modify     vel yes
fix             w all grflow/wall 1.0e6 1.15 {walls}
fix             g all gravity 9.81 vector 0 0 -1
fix             nve all nve/sphere
timestep        1.0e-6
run             100000
"""


@pytest.mark.parametrize("bz,walls,expect", [
    ("f", "zlo -0.002", "the zlo wall (z = -0.002) is outside the box's fixed lower face (z = 0)"),
    ("f", "zlo 0.0 zhi 0.011", "the zhi wall (z = 0.011) is outside the box's fixed upper face "
                               "(z = 0.01)"),
])
def test_wall_outside_a_fixed_face_is_named(tmp_path, bz, walls, expect):
    """A wall beyond a fixed face of the box: an atom falling towards it
    leaves the box first, which LAMMPS reports as "Lost atoms: original 1
    current 0" with nothing that names the wall; the fix names it at the
    start of the run, on 1 and 2 ranks."""
    deck = tmp_path / "outside.lmp"
    deck.write_text(WALL_OUTSIDE.format(bz=bz, walls=walls))
    for nprocs in (1, 2):
        proc = run_lmp(["-in", str(deck)], tmp_path, nprocs, check=False, timeout=120)
        text = proc.stdout + proc.stderr
        assert proc.returncode != 0
        assert "Fix grflow/wall w: " + expect in text
        assert "Lost atoms" not in text


def test_wall_outside_a_shrink_wrapped_face_is_fine(tmp_path):
    """with boundary s the box grows with the atoms: the same wall below
    the initial box is reached, no error"""
    deck = tmp_path / "outside_s.lmp"
    deck.write_text(WALL_OUTSIDE.format(bz="s", walls="zlo -0.002").replace("100000", "30000"))
    run_lmp(["-in", str(deck)], tmp_path, 1, timeout=120)


def test_minimize_warns_that_walls_do_not_act(tmp_path):
    deck = tmp_path / "minimize.lmp"
    deck.write_text(CROSSING.replace("1 1 2", "1 1 *").replace("run             100000",
                                                               "minimize 0 0 10 100\nrun 0"))
    proc = run_lmp(["-in", str(deck)], tmp_path, 1, check=False, timeout=120)
    text = proc.stdout + proc.stderr
    assert ("Fix grflow/wall w: the walls do not act during a minimization; atoms can "
            "cross them") in text
    # a run after it does not repeat the warning
    assert text.count("walls do not act") == 1
