"""The GRFLOW contact law in LIGGGHTS ("pair_style gran model grflow")
against LAMMPS's pair_style granular/grflow: the same host-free kernel
(src/shared/grflow_contact.h) behind two hosts' bookkeeping.

- A dense packing (343 polydisperse spheres): equal forces and torques at
  step 0, and the same trajectory after 3000 steps of shear with neighbor
  list rebuilds, on 1 and 2 MPI ranks of LIGGGHTS (history carried through
  rebuilds, owner swaps and exchange between ranks).
- A sphere that bounces on another and touches it again: each touch starts
  with empty springs in both hosts (LIGGGHTS keeps a pair's history while
  the spheres are apart).
- Combinations GRFLOW does not support and bad coefficients: clear errors.

Environment: LMP (lmp), LIGGGHTS (a liggghts built with GRFLOW,
scripts/build-liggghts.sh), MPIEXEC, GRFLOW_TEST_DECKS.
"""
import os
import re
import subprocess

import numpy as np
import pytest

from lmprun import DECKS, MPIEXEC, make_packing, run_lmp

LIGGGHTS = os.environ.get("LIGGGHTS", "liggghts")
STEPS = 3000

# the coefficients in both hosts' syntax: pair_coeff arguments of LAMMPS,
# fix property/global of LIGGGHTS (only kn and cn: the others take the
# Table 1 ratios; "explicit": every coefficient given, none at its ratio)
COEFFS = {
    "table1": {"kn": 1.0e6, "cn": 1.15},
    "explicit": {"kn": 1.0e6, "cn": 1.15, "kt": 6.0e5, "ct": 0.3, "mut": 0.3, "kr": 2.0e5,
                 "cr": 0.1, "mur": 0.2, "ko": 3.0e4, "co": 0.02, "muo": 0.05},
}


def run_liggghts(args, cwd, nprocs=1, check=True, timeout=600):
    cmd = [LIGGGHTS, "-log", "none", "-echo", "none"] + list(args)
    if nprocs > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace",
                          timeout=timeout)
    if check:
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return proc


def lammps_coeffs(c):
    return f"{c['kn']} {c['cn']}" + "".join(f" {k} {v}" for k, v in c.items()
                                             if k not in ("kn", "cn"))


def liggghts_props(path, c):
    path.write_text("".join(f"fix coeff_{k} all property/global {k} peratomtypepair 1 {v}\n"
                            for k, v in c.items()))
    return path


def portable_data(src, dst):
    """The data file of LAMMPS's write_data in the form LIGGGHTS 3.8 reads
    too: section keywords without their '# style' comments, and only the
    sections both have (Atoms, Velocities)."""
    out, keep = [], True
    for line in src.read_text().splitlines():
        word = line.split("#")[0].strip()
        if word in ("Atoms", "Velocities"):
            keep = True
            out.append(word)
        elif re.fullmatch(r"[A-Z][A-Za-z ]+", word) and not word.endswith(("xhi", "zhi", "yhi")):
            keep = False    # a section LIGGGHTS does not need (Pair Coeffs, ...)
        elif keep:
            out.append(line.split("#")[0].rstrip() if out else "GRFLOW packing")
    dst.write_text("\n".join(out) + "\n")
    return dst


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
    return np.abs(a - b).max() / np.abs(b).max()


# compute grflow/network's vector with cmax 12 (GRFLOW::NetworkLayout):
# 25 values (SXX ... VOLUME), then P_c for c = 0..12
NET_SIZE = 25 + 13


def netprint(path, host):
    """Lines that print the vector of compute net with all digits: LAMMPS
    formats $() with 15 digits unless told, LIGGGHTS always with 20"""
    fmt = ":%.17g" if host == "lammps" else ""
    path.write_text("".join(f'print "NET {k} $(c_net[{k}]{fmt})"\n'
                            for k in range(1, NET_SIZE + 1)))
    return path


def net_values(output):
    values = {}
    for line in output.splitlines():
        words = line.split()
        if len(words) == 3 and words[0] == "NET":
            values[int(words[1])] = float(words[2])
    assert sorted(values) == list(range(1, NET_SIZE + 1)), output[-2000:]
    return np.array([values[k] for k in sorted(values)])


@pytest.fixture(scope="module")
def packing(tmp_path_factory):
    work = tmp_path_factory.mktemp("liggghts")
    return work, portable_data(make_packing(work), work / "packing_portable.data")


def test_liggghts_has_grflow(tmp_path):
    deck = tmp_path / "in.style"
    deck.write_text("units si\natom_style granular\nregion b block 0 1 0 1 0 1 units box\n"
                    "create_box 1 b\nfix kn all property/global kn peratomtypepair 1 1e6\n"
                    "fix cn all property/global cn peratomtypepair 1 1.0\n"
                    "pair_style gran model grflow\npair_coeff * *\n")
    run_liggghts(["-in", str(deck)], tmp_path)


@pytest.mark.parametrize("coeffs", sorted(COEFFS))
@pytest.mark.parametrize("nprocs", [1, 2])
def test_same_forces_and_trajectory(packing, coeffs, nprocs):
    work, data = packing
    c = COEFFS[coeffs]
    ref = work / f"lammps_{coeffs}.dump"
    ref_net = work / f"lammps_{coeffs}.net"
    if not ref.exists():
        proc = run_lmp(["-in", os.path.join(DECKS, "equivalence.lmp"), "-var", "data", str(data),
                        "-var", "coeffs", lammps_coeffs(c), "-var", "steps", str(STEPS),
                        "-var", "dump", str(ref),
                        "-var", "netprint", str(netprint(work / "net.lmp", "lammps"))], work)
        np.savetxt(ref_net, net_values(proc.stdout))
    dump = work / f"liggghts_{coeffs}_np{nprocs}.dump"
    props = liggghts_props(work / f"props_{coeffs}.liggghts", c)
    proc = run_liggghts(["-in", os.path.join(DECKS, "liggghts", "equivalence.liggghts"),
                         "-var", "data", str(data), "-var", "props", str(props),
                         "-var", "steps", str(STEPS), "-var", "dump", str(dump),
                         "-var", "netprint", str(netprint(work / "net.liggghts", "liggghts"))],
                        work, nprocs)
    net, net_ref = net_values(proc.stdout), np.loadtxt(ref_net)
    (l0, l1), (g0, g1) = snapshots(ref), snapshots(dump)
    assert np.array_equal(l0[:, 0], g0[:, 0]) and np.array_equal(l1[:, 0], g1[:, 0])
    # columns: id x y z omega(3) f(3) torque(3)
    df0, dt0 = rel_diff(g0[:, 7:10], l0[:, 7:10]), rel_diff(g0[:, 10:13], l0[:, 10:13])
    dx, dw = rel_diff(g1[:, 1:4], l1[:, 1:4]), rel_diff(g1[:, 4:7], l1[:, 4:7])
    df1 = rel_diff(g1[:, 7:10], l1[:, 7:10])
    print(f"[ measured ] {coeffs}, LIGGGHTS on {nprocs} rank(s) against LAMMPS: step 0 "
          f"force {df0:.3e} torque {dt0:.3e}; step {STEPS}: x {dx:.3e} omega {dw:.3e} "
          f"force {df1:.3e}")
    # step 0: the same kernel on the same numbers; the hosts differ only in
    # the order in which a particle's contact forces are summed, a few
    # units of the last place (1e-16) per contact
    assert df0 < 1e-12 and dt0 < 1e-12
    # after the shear: round-off from the summation order grows chaotically
    # (with LAMMPS 4Jul2026 also from the masses, which differ from
    # LIGGGHTS's by an ulp, see test_liggghts_protocol_fixes.py: on 1 rank
    # up to 1.3e-11 in x and 2.3e-9 in omega, where 4Feb2025 gives 0);
    # the thresholds of the LAMMPS-only consistency test (another rank count:
    # up to 6.7e-10 in x and 1.1e-6 in omega; a wrongly carried spring
    # history: 6e-3 in x and 0.4 in omega)
    assert dx < 1e-6
    assert dw < 1e-4
    # compute grflow/network at the end: the same contacts (counts, z_g,
    # P_c exactly on one rank), stresses and fabric to round-off
    counts = [ComputeIndex.NP, ComputeIndex.NFLOAT, ComputeIndex.NCONTACT]
    dnet = np.abs(net - net_ref).max() / np.abs(net_ref).max()
    print(f"[ measured ] {coeffs}, compute grflow/network, LIGGGHTS on {nprocs} rank(s) "
          f"against LAMMPS: largest difference / largest value {dnet:.3e}; "
          f"z_g {net[ComputeIndex.ZG]:.6f} against {net_ref[ComputeIndex.ZG]:.6f}")
    if nprocs == 1:
        assert np.array_equal(net[counts], net_ref[counts])
    assert dnet < 1e-6


class ComputeIndex:
    """positions in compute grflow/network's vector (0-based, as
    GRFLOW::NetworkLayout in src/shared/grflow_network.h)"""
    NP, NFLOAT, NCONTACT, ZG = 11, 12, 13, 14


def test_touching_again_starts_with_empty_springs(tmp_path):
    steps = 300000
    ref, dump = tmp_path / "bounce_lammps.dump", tmp_path / "bounce_liggghts.dump"
    run_lmp(["-in", os.path.join(DECKS, "bounce.lmp"), "-var", "steps", str(steps),
             "-var", "dump", str(ref)], tmp_path)
    run_liggghts(["-in", os.path.join(DECKS, "liggghts", "bounce.liggghts"),
                  "-var", "steps", str(steps), "-var", "dump", str(dump)], tmp_path)
    lam, lig = snapshots(ref), snapshots(dump)
    assert len(lam) == len(lig) == steps // 20 + 1
    # the touches of the moving sphere (id 2, diameter 2 mm) with the one
    # at the origin, counted in the LAMMPS run (contacts last about 100
    # steps, the dump interval is 20)
    touching = np.array([np.linalg.norm(s[1, 1:4] - s[0, 1:4]) < 2.0e-3 for s in lam])
    starts = int(np.sum(touching[1:] & ~touching[:-1]))
    assert starts >= 3, f"the sphere touched {starts} times: the test needs separations"
    state = lambda snaps: np.array([s[1, 1:16] for s in snaps])
    d = rel_diff(state(lig), state(lam))
    print(f"[ measured ] bounce: {starts} touches; LIGGGHTS against LAMMPS, x v omega f "
          f"torque of the moving sphere: {d:.3e}")
    # two particles, one contact: no summation order differs, so the hosts
    # agree to round-off; a spring carried over from the previous touch
    # changes the tangential force at the next touch by O(1)
    assert d < 1e-9


BAD = [
    ("pair_style gran model grflow tangential history",
     "model grflow computes sliding, rolling and torsion itself: tangential must be off"),
    ("pair_style gran model grflow rolling_friction cdt",
     "rolling_friction must be off"),
    ("pair_style gran model grflow cohesion sjkr", "cohesion must be off"),
]


@pytest.mark.parametrize("line,message", BAD)
def test_unsupported_combination(tmp_path, line, message):
    deck = tmp_path / "in.bad"
    deck.write_text("units si\natom_style granular\nregion b block 0 1 0 1 0 1 units box\n"
                    "create_box 1 b\nfix kn all property/global kn peratomtypepair 1 1e6\n"
                    "fix cn all property/global cn peratomtypepair 1 1.0\n"
                    f"{line}\npair_coeff * *\n")
    proc = run_liggghts(["-in", str(deck)], tmp_path, check=False)
    assert proc.returncode != 0
    assert message in proc.stdout + proc.stderr


@pytest.mark.parametrize("prop,value,message", [
    ("kn", "0.0", "model grflow: kn of types 1 1 must be > 0, got 0"),
    ("mut", "-0.5", "model grflow: mut of types 1 1 must be >= 0, got -0.5"),
    ("cr", "-1", "model grflow: cr of types 1 1 must be >= 0, got -1"),
])
def test_bad_coefficient(tmp_path, prop, value, message):
    deck = tmp_path / "in.bad"
    props = {"kn": "1e6", "cn": "1.0"}
    props[prop] = value
    deck.write_text("units si\nnewton off\natom_style granular\n"
                    "region b block 0 1e-2 0 1e-2 0 1e-2 units box\n"
                    "create_box 1 b\ncreate_atoms 1 single 5e-3 5e-3 5e-3 units box\n"
                    "set group all diameter 1e-3\nset group all density 2650\n"
                    + "".join(f"fix c{k} all property/global {k} peratomtypepair 1 {v}\n"
                              for k, v in props.items())
                    + "pair_style gran model grflow\npair_coeff * *\ntimestep 1e-7\n"
                      "communicate single vel yes\nrun 1\n")
    proc = run_liggghts(["-in", str(deck)], tmp_path, check=False)
    assert proc.returncode != 0
    assert message in proc.stdout + proc.stderr


RESTART_DECK = """units si
atom_style granular
atom_modify map array sort 0 0.0
newton off
communicate single vel yes
{read}
include {props}
pair_style gran model grflow
pair_coeff * *
neighbor 0.2e-3 bin
neigh_modify delay 0 every 1 check yes
timestep 1.0e-7
fix nve all nve/sphere
fix shear all deform 1 x erate -40 y erate 20 z erate 20 remap x units box
{first}
dump d all custom 1 {dump} id fx fy fz tqx tqy tqz
dump_modify d sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g"
run 20
"""


def test_resume_from_a_restart_file_keeps_the_springs(packing):
    """LIGGGHTS's restart command writes the contact history of the last
    neighbor list build, stamped with that step: read back, a touching
    contact continues its springs (as in stock LIGGGHTS), it does not
    start from empty ones"""
    work, data = packing
    props = liggghts_props(work / "props_restart.liggghts", COEFFS["table1"])
    ref, resumed = work / "restart_ref.dump", work / "restart_resumed.dump"
    (work / "in.restart_a").write_text(RESTART_DECK.format(
        read=f"read_data {data}", props=props, dump=ref,
        first=f"restart 1000 {work}/r.*\nrun 1000"))
    run_liggghts(["-in", str(work / "in.restart_a")], work)
    (work / "in.restart_b").write_text(RESTART_DECK.format(
        read=f"read_restart {work}/r.1000", props=props, dump=resumed, first=""))
    run_liggghts(["-in", str(work / "in.restart_b")], work)
    a, b = snapshots(ref), snapshots(resumed)
    assert len(a) == len(b) == 21
    d = max(rel_diff(b[k][:, 1:7], a[k][:, 1:7]) for k in range(21))
    print(f"[ measured ] resumed from the restart file written at step 1000 against the run "
          f"that wrote it, steps 1000-1020, forces and torques: {d:.3e}")
    # measured: 2.2e-2 with the springs of the last list build (what
    # LIGGGHTS's restart files hold); 51 with every spring dropped, as the
    # step stamp did before the setup continued touching contacts.  The
    # threshold sits 9x above the one and 250x below the other.
    assert d < 0.2


COMPUTE_DECK = """units si
newton off
atom_style granular
communicate single vel yes
region b block 0 1e-2 0 1e-2 0 1e-2 units box
create_box 1 b
create_atoms 1 single 5e-3 5e-3 5e-3 units box
set group all diameter 1e-3
set group all density 2650
fix kn all property/global kn peratomtypepair 1 1e6
fix cn all property/global cn peratomtypepair 1 1.0
{pair}
timestep 1e-7
{compute}
thermo_style custom step c_n[7]
run 0
"""


@pytest.mark.parametrize("compute,message", [
    ("compute n all grflow/network foo 1", "Unknown compute grflow/network keyword: foo"),
    ("compute n all grflow/network slab 0", "slab must be in (0,1], got 0"),
    ("compute n all grflow/network slab abc", "compute grflow/network slab expects a number, got 'abc'"),
    ("compute n all grflow/network cmax 2.5", "compute grflow/network cmax expects an integer, got '2.5'"),
    ("compute n all grflow/network p0 -1", "p0 must be > 0"),
    ("compute n all grflow/network region nope", "Region nope for compute grflow/network does not exist"),
    ("compute n all grflow/network shear xx", "shear must be two different axes"),
    ("compute n all grflow/network zlimits 0", "Illegal compute grflow/network zlimits command: missing"),
])
def test_compute_bad_input(tmp_path, compute, message):
    deck = tmp_path / "in.compute"
    deck.write_text(COMPUTE_DECK.format(pair="pair_style gran model grflow\npair_coeff * *",
                                        compute=compute))
    proc = run_liggghts(["-in", str(deck)], tmp_path, check=False)
    assert proc.returncode != 0
    assert message in proc.stdout + proc.stderr


def test_shear_halt_is_refused(tmp_path):
    """fix grflow/shear halt yes ends runs early, which LIGGGHTS 3.8 cannot:
    an error that says so, not a run that ignores the keyword"""
    deck = tmp_path / "in.halt"
    deck.write_text(COMPUTE_DECK.format(
        pair="pair_style gran model grflow\npair_coeff * *",
        compute="compute n all grflow/network\nfix sh all grflow/shear w n 0.02 1000 halt yes"))
    proc = run_liggghts(["-in", str(deck)], tmp_path, check=False)
    assert proc.returncode != 0
    assert "halt yes: this program cannot end a run early" in proc.stdout + proc.stderr


def test_compress_halt_is_refused(tmp_path):
    """fix grflow/compress halt (a keyword or fix_modify) ends runs early,
    which LIGGGHTS 3.8 cannot: an error that says so"""
    walls = ("fix w all grflow/wall 1e6 1.0 zlo 0 zhi 1e-2\ncompute n all grflow/network slab 1.0\n"
             "fix c all grflow/compress w n 1e5 10")
    for extra in (" halt stress", "\nfix_modify c halt ready"):
        deck = tmp_path / "in.halt"
        deck.write_text(COMPUTE_DECK.replace("units si\n", "units si\nboundary p p f\n").format(
            pair="pair_style gran model grflow\npair_coeff * *", compute=walls + extra))
        proc = run_liggghts(["-in", str(deck)], tmp_path, check=False)
        assert proc.returncode != 0, extra
        assert "Fix grflow/compress halt: this program cannot end a run early" in \
            proc.stdout + proc.stderr, extra


def test_compute_needs_model_grflow(tmp_path):
    """the compute's forces come from GRFLOW's law: another model is refused"""
    deck = tmp_path / "in.compute"
    deck.write_text(COMPUTE_DECK.format(
        pair="fix cv all property/global characteristicVelocity scalar 1.0\n"
             "fix ym all property/global youngsModulus peratomtype 1e7\n"
             "fix pr all property/global poissonsRatio peratomtype 0.3\n"
             "fix cr all property/global coefficientRestitution peratomtypepair 1 0.5\n"
             "fix cf all property/global coefficientFriction peratomtypepair 1 0.5\n"
             "pair_style gran model hooke tangential history\npair_coeff * *",
        compute="compute n all grflow/network"))
    proc = run_liggghts(["-in", str(deck)], tmp_path, check=False)
    assert proc.returncode != 0
    assert "Compute grflow/network requires pair_style gran model grflow" in proc.stdout + proc.stderr
