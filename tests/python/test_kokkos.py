"""pair_style granular/grflow/kk (the KOKKOS package) against granular/grflow
and against closed forms.

The KOKKOS style runs the same contact law (grflow_contact.h) on a Kokkos
device; its contact history lives in FixNeighHistoryGRFLOWKokkos, which
keeps the sliding spring's sign flip and the rolling and torsion springs'
sign when a pair changes owner.  Compared here, each with its threshold's
reason:

- forces, torques, energy, virial (global and per atom) and single() at a
  state with loaded springs (a restart file written by granular/grflow),
  for three settings (defaults; normal_force unclipped with velocity_arm
  full; two atom types with mixed coefficients and a mode switched off),
  and after one step, which advances the springs;
- trajectories of a sheared dense packing over 5000 steps (neighbor lists
  rebuilt, contacts that open and close, owners changed by atom sorting,
  by 2 MPI ranks, with threads, with the exchange and sorting on the
  Kokkos device), against granular/grflow;
- a restart in the middle of a run (kk -> kk, granular/grflow -> kk,
  kk -> granular/grflow);
- the owner swap of a pair crossing a periodic boundary (the rolling
  spring keeps its sign), a sphere that touches another again (new
  springs), coefficients changed between runs and by fix adapt;
- a packing sheared between fix grflow/wall walls (a host fix beside the
  KOKKOS pair style), and compute grflow/network refused with an error;
- the restitution coefficient of a head-on collision against its closed
  forms, under both normal force laws;
- the clear errors of unsupported settings (newton on, full neighbor
  lists) and of the plain style's checks;
- bench/kokkos_bench.sh, the benchmark of scripts/gpu-check.sh, at a
  small size.

Environment: LMP_KOKKOS (lmp with GRFLOW and KOKKOS), LMP (lmp with
granular/grflow; default LMP_KOKKOS, whose plain styles are those of the
default build), GRFLOW_KOKKOS_ARGS (the command-line switches of a KOKKOS
run; default: the OpenMP or Serial backend on one thread, "-k on t 1 -sf
kk -pk kokkos newton off neigh half"; a GPU: "-k on g 1 -sf kk -pk kokkos
newton off neigh half"), GRFLOW_KOKKOS_THREADS (threads of the threaded
runs, default 2; 0 leaves them out, e.g. on a GPU), MPIEXEC,
GRFLOW_TEST_DECKS.
"""
import json
import math
import os
import shlex
import subprocess
from pathlib import Path

import numpy as np
import pytest

from lmprun import DECKS, make_packing

LMP_KOKKOS = os.environ.get("LMP_KOKKOS", "")
LMP = os.environ.get("LMP", LMP_KOKKOS)
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
KK_ARGS = shlex.split(os.environ.get("GRFLOW_KOKKOS_ARGS",
                                     "-k on t 1 -sf kk -pk kokkos newton off neigh half"))
THREADS = int(os.environ.get("GRFLOW_KOKKOS_THREADS", "2"))

pytestmark = pytest.mark.skipif(not LMP_KOKKOS, reason="LMP_KOKKOS (a KOKKOS lmp) is not set")


def kk_args(threads=None, extra=""):
    """KK_ARGS with another thread count and more package kokkos options"""
    args = list(KK_ARGS)
    if threads is not None:
        k = args.index("t") if "t" in args else -1
        assert k > 0, "GRFLOW_KOKKOS_ARGS has no 't N' to change"
        args[k + 1] = str(threads)
    if extra:
        assert "-pk" in args, "GRFLOW_KOKKOS_ARGS has no -pk kokkos to add options to"
        args += shlex.split(extra)
    return args


def run(args, cwd, kokkos=False, nprocs=1, check=True, threads=None, extra="", timeout=900):
    """lmp (LMP, or LMP_KOKKOS with the KOKKOS switches if kokkos) on nprocs ranks"""
    exe = LMP_KOKKOS if kokkos else LMP
    cmd = [exe, "-log", "none", "-nocite", "-echo", "none"]
    if kokkos:
        cmd += kk_args(threads, extra)
    cmd += list(args)
    if nprocs > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    if check:
        assert proc.returncode == 0, " ".join(cmd) + "\n" + proc.stdout[-3000:] + proc.stderr[-3000:]
    if kokkos and check and "-h" not in args:
        # the suffix chose the KOKKOS style (LAMMPS lists its neighbor list)
        assert "pair granular/grflow/kk" in proc.stdout, proc.stdout[-3000:]
    return proc


def snapshots(dump):
    """The dump's snapshots: a list of arrays, one row per atom, sorted by id"""
    lines = dump.read_text().splitlines()
    snaps, k = [], 0
    while k < len(lines):
        n = int(lines[k + 3])
        snaps.append(np.array([[float(x) for x in l.split()] for l in lines[k + 9:k + 9 + n]]))
        k += 9 + n
    return snaps


def rel_diff(a, b):
    return np.abs(np.asarray(a) - np.asarray(b)).max() / np.abs(np.asarray(b)).max()


def values(output, tag):
    """the numbers of the last printed line that starts with tag"""
    lines = [l for l in output.splitlines() if l.startswith(tag + " ")]
    assert lines, f"no line {tag} in the output:\n{output[-2000:]}"
    return np.array([float(x) for x in lines[-1].split()[1:]])


@pytest.fixture(scope="module")
def packing(tmp_path_factory):
    work = tmp_path_factory.mktemp("kokkos")
    return work, make_packing(work)


def test_kokkos_lmp_has_the_style(tmp_path):
    out = run(["-h"], tmp_path, kokkos=False).stdout
    proc = subprocess.run([LMP_KOKKOS, "-h"], capture_output=True, text=True)
    assert "granular/grflow/kk" in proc.stdout
    assert "KOKKOS" in proc.stdout
    assert "granular/grflow" in out


# ---------------------------------------------------------------------------
# forces, torques, energy and virial at a state with loaded springs

# settings: pair style line, pair_coeff lines, and a command that gives half
# the atoms type 2
SETTINGS = {
    "default": ("granular/grflow", ["* * 1.0e6 1.15"], ""),
    "unclipped-full": ("granular/grflow normal_force unclipped velocity_arm full",
                       ["* * 1.0e6 1.15 kt 6.0e5 mur 0.2"], ""),
    "two-types": ("granular/grflow",
                  ["1 1 1.0e6 1.15 mut 0.3", "2 2 2.0e6 2.30 rolling off muo 0.2"],
                  "set group even type 2\n"),
}

LOAD_DECK = """units si
atom_style sphere
atom_modify map array sort 0 0.0
newton on
comm_modify vel yes
read_data {data} nocoeff extra/atom/types 1
group even id 2:100000:2
{types}pair_style {style}
{coeffs}
neighbor 0.2e-3 bin
neigh_modify delay 0 every 1 check yes
timestep 1.0e-7
fix nve all nve/sphere
fix shear all deform 1 x erate -40 y erate 20 z erate 20 remap x units box
run 400
write_restart {restart}
"""

# the state of the restart file: run 0, then one step (forces, torques,
# per-atom energy and stress, global energy and pressure, and compute
# pair/local through single())
STATE_DECK = """newton off
read_restart {restart}
comm_modify vel yes
neighbor 0.2e-3 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
compute pe all pe/atom pair
compute st all stress/atom NULL pair
compute pl all pair/local p1 p2 p3 p4 p5 p6 p7 p8 p9 p10 p11 dist
compute plsum all reduce sum c_pl[1] c_pl[2] c_pl[3] c_pl[4] c_pl[8] c_pl[9] c_pl[10] c_pl[11] inputs local
thermo_style custom step pe press pxx pyy pzz pxy pxz pyz
thermo_modify format float %.17g
dump d all custom 1 {dump} id fx fy fz tqx tqy tqz c_pe c_st[1] c_st[2] c_st[3] c_st[4] c_st[5] c_st[6]
dump_modify d sort id format float %.17g
run 0
variable pe equal pe
variable p equal press
variable pxy equal pxy
print "STATE0 $(v_pe:%.17g) $(v_p:%.17g) $(v_pxy:%.17g)"
print "SINGLE0 $(c_plsum[1]:%.17g) $(c_plsum[2]:%.17g) $(c_plsum[3]:%.17g) $(c_plsum[4]:%.17g) $(c_plsum[5]:%.17g) $(c_plsum[6]:%.17g) $(c_plsum[7]:%.17g) $(c_plsum[8]:%.17g)"
run 1
print "STATE1 $(v_pe:%.17g) $(v_p:%.17g) $(v_pxy:%.17g)"
"""


@pytest.fixture(scope="module")
def loaded(packing):
    """a restart file of the sheared packing with loaded springs, for each
    setting, written by granular/grflow"""
    work, data = packing
    files = {}
    for name, (style, coeffs, types) in SETTINGS.items():
        restart = work / f"loaded_{name}.restart"
        deck = work / f"in.load_{name}"
        deck.write_text(LOAD_DECK.format(
            data=data, types=types, style=style, restart=restart,
            coeffs="\n".join("pair_coeff " + c for c in coeffs)))
        run(["-in", str(deck)], work)
        files[name] = restart
    return work, files


@pytest.mark.parametrize("setting", list(SETTINGS))
def test_state_forces_energy_virial(loaded, setting):
    work, files = loaded
    out, snaps = {}, {}
    for kk in (False, True):
        dump = work / f"state_{setting}_{'kk' if kk else 'cpu'}.dump"
        deck = work / f"in.state_{setting}_{'kk' if kk else 'cpu'}"
        deck.write_text(STATE_DECK.format(restart=files[setting], dump=dump))
        proc = run(["-in", str(deck)], work, kokkos=kk)
        if kk:
            # the springs came from the plain style's restart file
            assert "Resetting peratom fix info from restart file" in proc.stdout
        out[kk], snaps[kk] = proc.stdout, snapshots(dump)
    cpu0, kk0 = snaps[False][0], snaps[True][0]
    assert cpu0.shape == kk0.shape and np.array_equal(cpu0[:, 0], kk0[:, 0])

    # step 0: the same state, the springs read from the file.  Another
    # summation order (the KOKKOS loop sums a particle's contacts first,
    # then adds them) changes the last bits: up to about 1e-15 of the
    # largest value, times the contacts of a particle.  A wrong spring
    # (sign, arm, a missing mode) gives O(1e-2) and more.
    df = rel_diff(kk0[:, 1:4], cpu0[:, 1:4])
    dt = rel_diff(kk0[:, 4:7], cpu0[:, 4:7])
    de = rel_diff(kk0[:, 7], cpu0[:, 7])
    ds = rel_diff(kk0[:, 8:14], cpu0[:, 8:14])
    g_cpu, g_kk = values(out[False], "STATE0"), values(out[True], "STATE0")
    dg = rel_diff(g_kk, g_cpu)
    s_cpu, s_kk = values(out[False], "SINGLE0"), values(out[True], "SINGLE0")
    dsingle = np.abs(s_kk - s_cpu).max() / np.abs(s_cpu).max()
    print(f"[ measured ] {setting}, step 0: force {df:.2e} torque {dt:.2e} pe/atom {de:.2e} "
          f"stress/atom {ds:.2e} pe,press,pxy {dg:.2e} pair/local sums {dsingle:.2e}")
    assert np.abs(cpu0[:, 4:7]).max() > 0.0
    for d in (df, dt, de, ds, dg):
        assert d < 1e-12
    # single() reads the same springs: the sums over the contacts of p1..p11
    assert dsingle < 1e-12

    # after one step the springs have been advanced (rotation, increment,
    # caps) by each style from states equal to round-off
    cpu1, kk1 = snaps[False][1], snaps[True][1]
    d1 = max(rel_diff(kk1[:, 1:4], cpu1[:, 1:4]), rel_diff(kk1[:, 4:7], cpu1[:, 4:7]))
    dg1 = rel_diff(values(out[True], "STATE1"), values(out[False], "STATE1"))
    print(f"[ measured ] {setting}, step 1: force, torque {d1:.2e}; pe,press,pxy {dg1:.2e}")
    assert d1 < 1e-10
    assert dg1 < 1e-10


# ---------------------------------------------------------------------------
# trajectories

STEPS = 5000


def sheared(packing, tag, kokkos=False, nprocs=1, newton="off", sort=1000, threads=None,
            extra=""):
    """the final x and omega of tests/decks/consistency.lmp (5000 steps of
    anisotropic deformation at constant volume)"""
    work, data = packing
    dump = work / f"sheared_{tag}.dump"
    run(["-in", os.path.join(DECKS, "consistency.lmp"), "-var", "data", str(data),
         "-var", "newton", newton, "-var", "sort", str(sort), "-var", "steps", str(STEPS),
         "-var", "dump", str(dump)], work, kokkos=kokkos, nprocs=nprocs, threads=threads,
        extra=extra)
    table = np.loadtxt(dump, skiprows=9)
    return table[:, 1:4], table[:, 4:7]


@pytest.fixture(scope="module")
def reference(packing):
    """granular/grflow, 1 rank, newton on: the reference of
    test_parallel_consistency.py"""
    return sheared(packing, "cpu", newton="on")


# (ranks, sort interval, threads, package kokkos options): owners change by
# sorting (on the host, or on the device with sort device), by ranks (the
# exchange on the host, or on the device with comm device), with threads
# the forces on j are added atomically.  Measured on the OpenMP backend:
# up to 6.9e-10 in x and 1.2e-6 in omega.
VARIANTS = [(1, 1000, None, ""), (1, 10, None, ""), (1, 10, None, "sort device"),
            (2, 1000, None, ""), (2, 10, None, "comm device sort device"),
            # 3 ranks in a row: a rank receives from both sides in one
            # exchange, the second message of unpack_exchange_kokkos()
            (3, 10, None, "comm device sort device")]
if THREADS > 1:
    VARIANTS += [(1, 10, THREADS, ""), (2, 1000, THREADS, "comm device")]


@pytest.mark.parametrize("nprocs,sort,threads,extra", VARIANTS)
def test_sheared_trajectory(packing, reference, nprocs, sort, threads, extra):
    x_ref, w_ref = reference
    tag = f"kk_np{nprocs}_sort{sort}_t{threads}_{extra.replace(' ', '_')}"
    x, w = sheared(packing, tag, kokkos=True, nprocs=nprocs, sort=sort, threads=threads,
                   extra=extra)
    dx, dw = rel_diff(x, x_ref), rel_diff(w, w_ref)
    print(f"[ measured ] kk np={nprocs} sort={sort} threads={threads} {extra or '-'}: "
          f"x {dx:.3e}  omega {dw:.3e}")
    # the thresholds of test_parallel_consistency.py: round-off from another
    # summation order grows chaotically over the run (up to 6.7e-10 in x and
    # 1.1e-6 in omega measured there), a wrongly transferred spring history
    # gives 6e-3 in x and 0.4 in omega; each threshold lies halfway between
    # on a log scale
    assert dx < 1e-6
    assert dw < 1e-4


# ---------------------------------------------------------------------------
# a restart in the middle

HALF_DECK = """units si
atom_style sphere
atom_modify map array sort 0 0.0
newton {newton}
comm_modify vel yes
{read}
pair_style granular/grflow
pair_coeff * * 1.0e6 1.15
neighbor 0.2e-3 bin
neigh_modify delay 0 every 1 check yes
timestep 1.0e-7
fix nve all nve/sphere
fix shear all deform 1 x trate -40 y trate 20 z trate 20 remap x units box
run {steps}
{after}
"""

RESUME_DECK = """newton {newton}
read_restart {restart}
comm_modify vel yes
neighbor 0.2e-3 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
fix shear all deform 1 x trate -40 y trate 20 z trate 20 remap x units box
run {steps}
write_dump all custom {dump} id x y z omegax omegay omegaz modify sort id format float %.17g
"""


def halves(packing, tag, first_kk, second_kk, nprocs=1):
    """2500 steps, write_restart, then 2500 more steps read from the file"""
    work, data = packing
    restart, dump = work / f"half_{tag}.restart", work / f"half_{tag}.dump"
    deck = work / f"in.half_{tag}"
    deck.write_text(HALF_DECK.format(newton="off" if first_kk else "on",
                                     read=f"read_data {data} nocoeff", steps=STEPS // 2,
                                     after=f"write_restart {restart}"))
    run(["-in", str(deck)], work, kokkos=first_kk, nprocs=nprocs)
    deck = work / f"in.resume_{tag}"
    deck.write_text(RESUME_DECK.format(newton="off" if second_kk else "on", restart=restart,
                                       steps=STEPS // 2, dump=dump))
    proc = run(["-in", str(deck)], work, kokkos=second_kk, nprocs=nprocs)
    assert "Resetting peratom fix info from restart file" in proc.stdout
    table = np.loadtxt(dump, skiprows=9)
    return table[:, 1:4], table[:, 4:7]


@pytest.fixture(scope="module")
def unbroken(packing):
    """granular/grflow, the same 5000 steps in two runs without a restart
    file (trate: the deformation of two runs is that of one)"""
    work, data = packing
    dump = work / "unbroken.dump"
    deck = work / "in.unbroken"
    deck.write_text(HALF_DECK.format(
        newton="on", read=f"read_data {data} nocoeff", steps=STEPS // 2,
        after=f"run {STEPS // 2}\nwrite_dump all custom {dump} id x y z omegax omegay omegaz "
              "modify sort id format float %.17g"))
    run(["-in", str(deck)], work)
    table = np.loadtxt(dump, skiprows=9)
    return table[:, 1:4], table[:, 4:7]


@pytest.mark.parametrize("first_kk,second_kk,nprocs", [
    (True, True, 1), (False, True, 1), (True, False, 1), (True, True, 2)])
def test_restart_in_the_middle(packing, unbroken, first_kk, second_kk, nprocs):
    x_ref, w_ref = unbroken
    names = {True: "kk", False: "cpu"}
    tag = f"{names[first_kk]}_{names[second_kk]}_np{nprocs}"
    x, w = halves(packing, tag, first_kk, second_kk, nprocs)
    dx, dw = rel_diff(x, x_ref), rel_diff(w, w_ref)
    print(f"[ measured ] restart {names[first_kk]} -> {names[second_kk]}, np={nprocs}: "
          f"x {dx:.3e}  omega {dw:.3e}")
    # as test_sheared_trajectory: round-off grows chaotically; springs lost
    # or wrongly read at the restart give O(1e-2) in omega
    assert dx < 1e-6
    assert dw < 1e-4


# ---------------------------------------------------------------------------
# the owner swap of one pair, a pair that touches again

def crossing(tmp_path, newton, kokkos):
    dump = tmp_path / f"crossing_{newton}_{kokkos}.dump"
    run(["-in", os.path.join(DECKS, "boundary_crossing.lmp"), "-var", "newton", newton,
         "-var", "pairstyle", "granular/grflow",
         "-var", "paircoeff", "* * 1.0e6 1.15 torsion off mut 0.0",
         "-var", "dump", str(dump)], tmp_path, kokkos=kokkos)
    return np.loadtxt(dump, skiprows=9)[:, 2:5]


def test_rolling_history_across_periodic_boundary(tmp_path):
    """Two spheres in rolling contact drift across a periodic boundary: the
    pair goes from owned-owned to two pairs of an owned atom and an image,
    and one of them gets its spring through the owner swap.  Rolling only
    (mut 0, torsion off): a negated rolling spring flips the torques."""
    ref = crossing(tmp_path, "on", False)
    kk = crossing(tmp_path, "off", True)
    d = rel_diff(kk, ref)
    print(f"[ measured ] crossing, granular/grflow/kk (newton off) vs granular/grflow "
          f"(newton on): torque {d:.3e}")
    # two particles, one contact: the styles agree to round-off (measured
    # 0 between newton on and off of the plain style); a negated rolling
    # spring gives O(1)
    assert d < 1e-10
    assert np.abs(kk[0] + kk[1]).max() < 1e-12 * np.abs(kk).max()


def test_touching_again_starts_with_empty_springs(tmp_path):
    """tests/decks/bounce.lmp: a sphere falls on another, bounces and touches
    it again, each touch with new springs.  The KOKKOS run takes the KOKKOS
    pair style but the plain fix nve/sphere and fix gravity (suffix off
    after pair_coeff): fix nve/sphere/kk rounds the free flight differently
    (8e-10 after 13000 steps, before the first touch), which the bounces
    amplify to 1e-2 over the run and would hide what is compared here."""
    steps = 300000
    deck = (Path(DECKS) / "bounce.lmp").read_text()
    at = deck.index("\nneighbor ")
    (tmp_path / "bounce_pair_kk.lmp").write_text(deck[:at] + "\nsuffix off" + deck[at:])
    dumps = {kk: tmp_path / f"bounce_{kk}.dump" for kk in (False, True)}
    for kk, dump in dumps.items():
        deckfile = tmp_path / "bounce_pair_kk.lmp" if kk else Path(DECKS) / "bounce.lmp"
        run(["-in", str(deckfile), "-var", "steps", str(steps), "-var", "dump", str(dump)],
            tmp_path, kokkos=kk)
    cpu, kk = snapshots(dumps[False]), snapshots(dumps[True])
    assert len(cpu) == len(kk) == steps // 20 + 1
    touching = np.array([np.linalg.norm(s[1, 1:4] - s[0, 1:4]) < 2.0e-3 for s in cpu])
    starts = int(np.sum(touching[1:] & ~touching[:-1]))
    assert starts >= 3, f"the sphere touched {starts} times: the test needs separations"
    state = lambda snaps: np.array([s[1, 1:16] for s in snaps])
    d = rel_diff(state(kk), state(cpu))
    print(f"[ measured ] bounce: {starts} touches; kk against granular/grflow, x v omega f "
          f"torque of the moving sphere: {d:.3e}")
    # one contact, the same integrator, no summation order differs: equal to
    # round-off (measured: equal); a spring carried over from the previous
    # touch changes the next touch's tangential force by O(1)
    assert d < 1e-9


COEFF_DECK = """units si
atom_style sphere
atom_modify map array sort 0 0.0
newton {newton}
comm_modify vel yes
read_data {data} nocoeff
pair_style granular/grflow
pair_coeff * * 1.0e6 1.15 mut 0.1
neighbor 0.2e-3 bin
neigh_modify delay 0 every 1 check yes
timestep 1.0e-7
fix nve all nve/sphere
fix shear all deform 1 x trate -40 y trate 20 z trate 20 remap x units box
run 500
pair_coeff * * 1.0e6 1.15 mut 0.5 kr 2.0e5
run 500
variable mu equal 0.2+0.1*step/1000
fix a all adapt 1 pair granular/grflow mur * * v_mu reset no
run 500
write_dump all custom {dump} id x y z omegax omegay omegaz modify sort id format float %.17g
"""


def test_coefficients_change_between_runs_and_by_fix_adapt(packing):
    work, data = packing
    res = {}
    for kk in (False, True):
        dump = work / f"coeff_{kk}.dump"
        deck = work / f"in.coeff_{kk}"
        deck.write_text(COEFF_DECK.format(newton="off" if kk else "on", data=data, dump=dump))
        run(["-in", str(deck)], work, kokkos=kk)
        res[kk] = np.loadtxt(dump, skiprows=9)
    dx = rel_diff(res[True][:, 1:4], res[False][:, 1:4])
    dw = rel_diff(res[True][:, 4:7], res[False][:, 4:7])
    print(f"[ measured ] coefficients changed by pair_coeff and fix adapt, 1500 steps: "
          f"x {dx:.3e} omega {dw:.3e}")
    # 1500 steps: less chaotic growth than 5000; coefficients the kk style
    # did not see would change omega by O(1e-2)
    assert dx < 1e-6
    assert dw < 1e-4


WALL_DECK = """newton {newton}
processors 1 1 1
read_restart {restart}
comm_modify vel yes
neighbor 0.2e-3 bin
neigh_modify delay 0 every 1 check yes
fix w all grflow/wall 1.0e6 1.15 zlo 0.0 zhi 8.0e-3
fix nve all nve/sphere
fix_modify w wall hi vel 0.05 0.0 0.0
run 3000
print "WALL $(f_w[1]:%.17g) $(f_w[3]:%.17g) $(f_w[7]:%.17g) $(f_w[9]:%.17g)"
write_dump all custom {dump} id x y z omegax omegay omegaz modify sort id format float %.17g
"""


def test_with_fix_grflow_wall(tmp_path):
    """the packing of tests/decks/wall_packing.lmp between two GRFLOW walls,
    sheared by the top wall: fix grflow/wall (no KOKKOS variant: it runs on
    the host, LAMMPS copies the data each step) beside granular/grflow/kk"""
    restart = tmp_path / "wall.restart"
    run(["-in", os.path.join(DECKS, "wall_packing.lmp"), "-var", "restart", str(restart),
         "-var", "dump", str(tmp_path / "wall_prep.dump")], tmp_path)
    res, walls = {}, {}
    for kk in (False, True):
        dump = tmp_path / f"wall_{kk}.dump"
        deck = tmp_path / f"in.wall_{kk}"
        deck.write_text(WALL_DECK.format(newton="off" if kk else "on", restart=restart, dump=dump))
        walls[kk] = values(run(["-in", str(deck)], tmp_path, kokkos=kk).stdout, "WALL")
        res[kk] = np.loadtxt(dump, skiprows=9)
    dx = rel_diff(res[True][:, 1:4], res[False][:, 1:4])
    dw = rel_diff(res[True][:, 4:7], res[False][:, 4:7])
    dwall = rel_diff(walls[True], walls[False])
    print(f"[ measured ] with fix grflow/wall, 3000 sheared steps: x {dx:.3e} omega {dw:.3e} "
          f"wall forces {dwall:.3e}")
    assert np.abs(walls[False]).max() > 0.0
    # round-off grown over 3000 steps (as test_sheared_trajectory); a wall
    # or pair force lost between host and device would change omega by O(1)
    assert dx < 1e-6
    assert dw < 1e-4
    assert dwall < 1e-4


def test_compute_grflow_network_is_refused(loaded):
    """compute grflow/network reads the pair style's neighbor list on the host;
    with the KOKKOS list it would count nothing: an error, not zeros"""
    work, files = loaded
    deck = work / "in.network"
    deck.write_text(f"newton off\nread_restart {files['default']}\ncomm_modify vel yes\n"
                    "fix nve all nve/sphere\ncompute net all grflow/network\n"
                    "thermo_style custom step c_net[14]\nrun 0\n")
    proc = run(["-in", str(deck)], work, kokkos=True, check=False)
    text = proc.stdout + proc.stderr
    assert proc.returncode != 0, text[-2000:]
    assert "does not work with pair style granular/grflow/kk" in text, text[-2000:]


# ---------------------------------------------------------------------------
# closed forms

D, RHO, V0 = 1.0e-3, 2650.0, 0.1


def collide(tmp_path, law, dt, steps):
    """head-on collision of two spheres of 1 mm (the most damped pair of the
    sample); returns the restitution coefficient"""
    kw = " normal_force unclipped" if law == "unclipped" else ""
    deck = tmp_path / f"in.collide_{law}"
    deck.write_text(
        "units si\natom_style sphere\natom_modify map array\nboundary f f f\nnewton off\n"
        "comm_modify vel yes\nregion box block -0.005 0.005 -0.005 0.005 -0.005 0.005\n"
        "create_box 1 box\nneighbor 0.5e-3 bin\nneigh_modify delay 0 every 1 check yes\n"
        f"create_atoms 1 single 0 0 0 units box\n"
        f"create_atoms 1 single {1.0001 * D!r} 0 0 units box\n"
        f"set type 1 diameter {D!r} density {RHO!r}\n"
        f"set atom 1 vx {0.5 * V0!r}\nset atom 2 vx {-0.5 * V0!r}\n"
        f"pair_style granular/grflow{kw}\npair_coeff * * 1.0e6 1.15\n"
        f"timestep {dt!r}\nfix nve all nve/sphere\nrun {steps}\n"
        'print "VX $(vx[1]:%.17g) $(vx[2]:%.17g)"\n')
    v = values(run(["-in", str(deck)], tmp_path, kokkos=True).stdout, "VX")
    return (v[1] - v[0]) / V0


@pytest.mark.parametrize("law", ["unclipped", "clipped"])
def test_head_on_restitution(tmp_path, law):
    m = RHO * math.pi * D ** 3 / 6.0
    meff = 0.5 * m
    w0, eta = math.sqrt(1.0e6 / meff), 1.15 / (2.0 * meff)
    w = math.sqrt(w0 * w0 - eta * eta)
    zeta = eta / w0
    e_u = math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta * zeta))
    t_f = (math.pi - math.atan2(2.0 * eta * w, w * w - eta * eta)) / w
    e_c = math.exp(-eta * t_f)
    t_c = math.pi / w
    e = collide(tmp_path, law, t_c / 20000, 60000)
    e_ana = e_u if law == "unclipped" else e_c
    print(f"[ measured ] head-on, {law}: e closed form {e_ana:.5f}, granular/grflow/kk {e:.5f}")
    # 20000 steps per contact: velocity Verlet's first-order error with a
    # velocity-dependent force stays below 3e-4 of e (tests/test_contact_kernel.cpp);
    # the two laws differ by 0.16
    assert abs(e - e_ana) < 1e-3 * e_ana
    assert e_c - e_u > 0.1


# ---------------------------------------------------------------------------
# the benchmark of the GPU check, at a small size on this backend

def test_benchmark_script(packing, tmp_path):
    """bench/kokkos_bench.sh (scripts/gpu-check.sh bench runs it on a GPU):
    both styles at 1 and 2 tiles of the packing; its table and json"""
    work, data = packing
    bench = Path(__file__).resolve().parents[2] / "bench" / "kokkos_bench.sh"
    env = dict(os.environ, TILES="1 2", NSTEPS="100", NWARM="20", KK=" ".join(KK_ARGS))
    proc = subprocess.run(["bash", str(bench), LMP_KOKKOS, str(data), str(tmp_path / "b")],
                          capture_output=True, text=True, env=env, timeout=900)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    res = json.loads((tmp_path / "b" / "results.json").read_text())
    runs = {(r["style"], r["n"]): r for r in res["runs"]}
    assert set(runs) == {("grflow", 1), ("hooke", 1), ("grflow", 2), ("hooke", 2)}
    for (style, n), r in runs.items():
        assert r["atoms"] == 343 * n ** 3 and r["steps"] == 100 and r["neighbors"] > 0
        assert r["ns_per_pair_step"] > 0.0
    assert set(res["grflow_over_hooke"]) == {"343", "2744"}
    print("[ measured ] benchmark at 343 and 2744 spheres (timings mean nothing here): "
          + ", ".join(f"{k}: {v:.2f}" for k, v in res["grflow_over_hooke"].items()))


# ---------------------------------------------------------------------------
# settings the KOKKOS style refuses, with errors that name the problem

SMALL = """units si
atom_style sphere
{newton}
region box block 0 0.01 0 0.01 0 0.01
create_box 1 box
create_atoms 1 single 0.005 0.005 0.005
create_atoms 1 single 0.0059 0.005 0.005
set group all diameter 1.0e-3 density 2650
pair_style granular/grflow
pair_coeff * * 1.0e6 1.15
{comm}
fix nve all nve/sphere
run 1
"""


@pytest.mark.parametrize("newton,comm,extra,message", [
    ("newton on", "comm_modify vel yes", "", "requires newton pair off"),
    ("newton off", "comm_modify vel yes", "neigh full", "needs a half neighbor list"),
    ("newton off", "", "", "use comm_modify vel yes"),
])
def test_unsupported_settings_are_errors(tmp_path, newton, comm, extra, message):
    deck = tmp_path / "in.bad"
    deck.write_text(SMALL.format(newton=newton, comm=comm))
    proc = run(["-in", str(deck)], tmp_path, kokkos=True, check=False, extra=extra)
    text = proc.stdout + proc.stderr
    assert proc.returncode != 0, text[-2000:]
    assert message in text, text[-2000:]


def test_same_position_is_an_error(tmp_path):
    """a third sphere exactly on the first: no contact normal; the KOKKOS
    loop skips the pair and the host names the atoms"""
    deck = tmp_path / "in.same"
    deck.write_text(SMALL.format(newton="newton off", comm="comm_modify vel yes").replace(
        "pair_style", "create_atoms 1 single 0.005 0.005 0.005\n"
        "set atom 3 diameter 1.0e-3 density 2650\npair_style", 1))
    proc = run(["-in", str(deck)], tmp_path, kokkos=True, check=False)
    text = proc.stdout + proc.stderr
    assert proc.returncode != 0, text[-2000:]
    assert ("atoms 1 and 3 are at the same position" in text
            or "atoms 3 and 1 are at the same position" in text), text[-2000:]
