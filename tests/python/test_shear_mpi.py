"""fix grflow/shear takes the same decisions with 1 and 2 MPI ranks and with
newton on or off: the same reversal steps, the same final reversal count,
direction and wall displacement.

A packing of 144 spheres is compressed without friction between two walls
(once, one rank, written to a restart file), then sheared with friction at
constant height, reversing at tau = +-0.3 p0 (checked every 20 steps) for
6000 steps: four reversals.  The ranks split the box along z (processors
1 1 2: the walls and the sheared layer on different ranks, tau and p summed
across ranks) or along x (processors 2 1 1).  tau is a global sum, so its
round-off depends on the rank count; the reversals stay on the same steps as
long as no check falls within round-off of the threshold (the closest check
is printed).

Environment: LMP (lmp binary), MPIEXEC (mpirun).
"""

import os

import pytest

from lmprun import DECKS, cell_from_restart, run_lmp

STEPS = 6000
EVERY = 20


SHEAR = """
{cell}
compute         net all grflow/network zlimits v_zlo v_zhi
run             0 post no
variable        amp equal 0.3*c_net[7]
fix             sh all grflow/shear w net 0.02 $(v_amp:%.17g) every {every}
variable        rev equal f_sh[2]
variable        dir equal f_sh[1]
variable        tau equal f_sh[5]
fix             rec all print {every} "$(step) ${{rev}} ${{dir}} $(v_tau:%.17g)" file {record} screen no
thermo          1000
run             {steps}
print           "NEWTON $(is_active(newton,pair))"
print           "SHEAR $(f_sh[1]:%.17g) $(f_sh[2]:%.17g) $(f_sh[3]:%.17g) $(f_sh[8]:%.17g) $(f_sh[5]:%.17g)"
print           "AMP $(v_amp:%.17g)"
"""


@pytest.fixture(scope="module")
def packing(tmp_path_factory):
    work = tmp_path_factory.mktemp("shear_mpi")
    restart = work / "packing.restart"
    # frictionless preparation: a frictional one liquefies at the first unloading
    run_lmp(["-in", os.path.join(DECKS, "wall_packing.lmp"), "-var", "restart", str(restart),
             "-var", "mut_prep", "0.0"], work)
    return work, restart


def sheared(packing, nprocs, newton, grid):
    work, restart = packing
    tag = f"np{nprocs}_{newton}_{grid.replace(' ', '')}"
    record = work / f"record_{tag}.txt"
    deck = work / f"shear_{tag}.lmp"
    deck.write_text(SHEAR.format(cell=cell_from_restart(restart, newton, grid), steps=STEPS,
                                 every=EVERY, record=record))
    out = run_lmp(["-in", str(deck)], work, nprocs).stdout
    lines = out.splitlines()
    flags = next(line for line in lines if line.startswith("NEWTON")).split()
    assert float(flags[1]) == (1.0 if newton == "on" else 0.0)
    assert f"{grid.replace(' ', ' by ')} MPI processor grid" in out
    final = [float(v) for v in next(l for l in lines if l.startswith("SHEAR")).split()[1:]]
    amp = float(next(l for l in lines if l.startswith("AMP")).split()[1])
    steps, taus, last = [], [], 0.0
    for line in record.read_text().splitlines():
        if not line or line.startswith("#"):
            continue
        step, rev, _, tau = line.split()
        taus.append(float(tau))
        if float(rev) != last:
            steps.append(int(step))
        last = float(rev)
    return {"steps": steps, "final": final, "amp": amp, "taus": taus}


@pytest.fixture(scope="module")
def reference(packing):
    return sheared(packing, 1, "on", "1 1 1")


def test_reference_is_not_trivial(reference):
    steps, final, amp = reference["steps"], reference["final"], reference["amp"]
    margin = min(abs(abs(t) - amp) for t in reference["taus"]) / amp
    print(f"[ measured ] 1 rank newton on: reversal steps {steps}, final direction "
          f"{final[0]:g} reversals {final[1]:g} x_w {final[2]:.6g} p0 {final[3]:.6g}; "
          f"closest check to the threshold: |tau|/tau_amp - 1 = {margin:.2e}")
    assert len(steps) >= 4
    assert all(s % EVERY == 0 for s in steps)
    assert final[1] == len(steps)
    assert margin > 1e-9


VARIANTS = [(1, "off", "1 1 1"), (2, "on", "1 1 2"), (2, "off", "1 1 2"),
            (2, "on", "2 1 1"), (2, "off", "2 1 1")]


@pytest.mark.parametrize("nprocs,newton,grid", VARIANTS)
def test_same_reversal_steps(packing, reference, nprocs, newton, grid):
    got = sheared(packing, nprocs, newton, grid)
    ref = reference
    dp0 = abs(got["final"][3] - ref["final"][3]) / ref["final"][3]
    dtau = max(abs(a - b) for a, b in zip(got["taus"], ref["taus"])) / ref["amp"]
    print(f"[ measured ] np={nprocs} newton={newton} grid={grid}: reversal steps "
          f"{got['steps']}, p0 rel diff {dp0:.2e}, max |dtau|/tau_amp {dtau:.2e}")
    assert got["steps"] == ref["steps"]
    assert got["final"][:3] == ref["final"][:3]    # direction, reversals, x_w: exact
    assert dp0 < 1e-12
    assert dtau < 1e-6
