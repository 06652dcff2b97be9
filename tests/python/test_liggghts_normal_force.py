"""The unclipped normal force in LIGGGHTS ("model grflow limitForce off",
fix grflow/wall "normal_force unclipped") against the closed forms and
against LAMMPS (granular/grflow and fix grflow/wall "normal_force
unclipped"): a head-on collision of two of the sample's smallest spheres
(d = 1 mm, damping ratio 0.69 with Table 1's kn, cn) and of one such
sphere with a wall.

Closed forms (doc/pair_granular_grflow.rst): unclipped
e = exp(-pi zeta/sqrt(1 - zeta^2)); clipped e = exp(-eta t_f), t_f the
zero of kn delta - cn v_n.  20000 steps per contact: the first-order
error of velocity Verlet with a velocity-dependent force is below 3e-4
of e there (tests/test_contact_kernel.cpp), so 1e-3 of e.  The two hosts
run the same kernel on one contact with no summation order to differ:
1e-9.

Environment: LMP, LIGGGHTS (a liggghts built with GRFLOW).
"""
import math
import os
import re
import subprocess

import pytest

from lmprun import run_lmp

LIGGGHTS = os.environ.get("LIGGGHTS", "liggghts")
D, RHO, KN, CN, V0 = 1.0e-3, 2650.0, 1.0e6, 1.15, 0.1


def closed_forms(meff):
    w0 = math.sqrt(KN / meff)
    eta = CN / (2.0 * meff)
    w = math.sqrt(w0 * w0 - eta * eta)
    zeta = eta / w0
    t_f = (math.pi - math.atan2(2.0 * eta * w, w * w - eta * eta)) / w
    return math.pi / w, math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta * zeta)), \
        math.exp(-eta * t_f)


def result(out):
    m = re.search(r"^RESULT (\S+) (\S+)", out, re.M)
    assert m, out[-3000:]
    return float(m.group(1)), float(m.group(2))


def run_liggghts(deck, cwd):
    path = cwd / "deck.liggghts"
    path.write_text(deck)
    proc = subprocess.run([LIGGGHTS, "-log", "none", "-echo", "none", "-in", str(path)],
                          cwd=cwd, capture_output=True, text=True, errors="replace", timeout=600)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return proc.stdout


def run_lammps(deck, cwd):
    path = cwd / "deck.lmp"
    path.write_text(deck)
    return run_lmp(["-in", str(path)], cwd).stdout


# two spheres 0.1 um apart closing at V0 along x (LIGGGHTS: atom_style
# granular; LAMMPS: sphere); contact is the pair style and its coefficients
def pair_deck(liggghts, contact, dt, steps):
    style = ("atom_style granular\ncommunicate single vel yes\nnewton off\n" if liggghts
             else "atom_style sphere\ncomm_modify vel yes\n")
    return (f"units si\n{style}atom_modify map array\nboundary f f f\n"
            "region box block -0.005 0.005 -0.005 0.005 -0.005 0.005 units box\n"
            "create_box 1 box\n"
            "create_atoms 1 single 0.0 0.0 0.0 units box\n"
            f"create_atoms 1 single {1.0001 * D!r} 0.0 0.0 units box\n"
            f"set group all diameter {D!r}\nset group all density {RHO!r}\n"
            "group a id 1\ngroup b id 2\n"
            f"velocity a set {0.5 * V0!r} 0.0 0.0 units box\n"
            f"velocity b set {-0.5 * V0!r} 0.0 0.0 units box\n"
            f"{contact}\n"
            "neighbor 0.5e-3 bin\nneigh_modify delay 0 every 1 check yes\n"
            f"timestep {dt!r}\nfix nve all nve/sphere\nrun {steps}\n"
            "variable v1 equal vx[1]\nvariable v2 equal vx[2]\n"
            'print "RESULT ${v1} ${v2}"\n')


# one sphere 0.05 um above a wall at z = 0, moving down at V0; wall: the fix
def wall_deck(liggghts, wall, dt, steps):
    style = ("atom_style granular\ncommunicate single vel yes\nnewton off\n" if liggghts
             else "atom_style sphere\ncomm_modify vel yes\n")
    # (no pair style: LIGGGHTS's atom sorting would have no bin size)
    return (f"units si\n{style}atom_modify map array sort 0 0.0\nboundary p p f\n"
            "region box block -0.002 0.002 -0.002 0.002 -0.001 0.003 units box\n"
            "create_box 1 box\n"
            f"create_atoms 1 single 0.0 0.0 {1.0001 * 0.5 * D!r} units box\n"
            f"set group all diameter {D!r}\nset group all density {RHO!r}\n"
            f"velocity all set 0.0 0.0 {-V0!r} units box\n"
            f"{wall}\n"
            "neighbor 0.5e-3 bin\nneigh_modify delay 0 every 1 check yes\n"
            f"timestep {dt!r}\nfix nve all nve/sphere\nrun {steps}\n"
            "variable v1 equal vz[1]\nvariable v2 equal vz[1]\n"
            'print "RESULT ${v1} ${v2}"\n')


LIG_COEFFS = ("fix kn all property/global kn peratomtypepair 1 1.0e6\n"
              "fix cn all property/global cn peratomtypepair 1 1.15\n")


@pytest.mark.parametrize("law", ["unclipped", "clipped"])
def test_pair_restitution(tmp_path, law):
    m = RHO * math.pi * D ** 3 / 6.0
    t_c, e_u, e_c = closed_forms(0.5 * m)
    dt, steps = t_c / 20000, 60000
    opt = " limitForce off" if law == "unclipped" else ""
    lig = result(run_liggghts(pair_deck(True, f"{LIG_COEFFS}pair_style gran model grflow{opt}\n"
                                        "pair_coeff * *", dt, steps), tmp_path))
    kw = " normal_force unclipped" if law == "unclipped" else ""
    lam = result(run_lammps(pair_deck(False, f"pair_style granular/grflow{kw}\n"
                                      "pair_coeff * * 1.0e6 1.15", dt, steps), tmp_path))
    e_lig, e_lam = (lig[1] - lig[0]) / V0, (lam[1] - lam[0]) / V0
    e_ana = e_u if law == "unclipped" else e_c
    print(f"[ measured ] pair {law}: e closed form {e_ana:.5f}, LIGGGHTS {e_lig:.5f}, "
          f"LAMMPS {e_lam:.5f}")
    assert abs(e_lig - e_ana) < 1e-3 * e_ana
    assert abs(e_lig - e_lam) < 1e-9 * e_ana
    assert e_c - e_u > 0.1    # the laws are far apart


@pytest.mark.parametrize("fix", ["wall/gran", "grflow/wall"])
def test_wall_restitution_unclipped(tmp_path, fix):
    m = RHO * math.pi * D ** 3 / 6.0
    t_c, e_u, e_c = closed_forms(m)    # the wall: a body of infinite mass
    dt, steps = t_c / 20000, 60000
    if fix == "wall/gran":
        # (LIGGGHTS reads the model's keywords after the wall's definition)
        wall = (f"{LIG_COEFFS}fix w all wall/gran model grflow primitive type 1 zplane 0.0 "
                "limitForce off")
    else:
        wall = "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 normal_force unclipped"
    lig = result(run_liggghts(wall_deck(True, wall, dt, steps), tmp_path))
    lam = result(run_lammps(wall_deck(False, "fix w all grflow/wall 1.0e6 1.15 zlo 0.0 "
                                      "normal_force unclipped", dt, steps), tmp_path))
    e_lig, e_lam = lig[0] / V0, lam[0] / V0
    print(f"[ measured ] wall ({fix}) unclipped: e closed form {e_u:.5f}, LIGGGHTS "
          f"{e_lig:.5f}, LAMMPS fix grflow/wall {e_lam:.5f} (clipped closed form {e_c:.5f})")
    assert abs(e_lig - e_u) < 1e-3 * e_u
    assert abs(e_lig - e_lam) < 1e-9 * e_u


def test_bad_limit_force(tmp_path):
    deck = pair_deck(True, f"{LIG_COEFFS}pair_style gran model grflow limitForce maybe\n"
                     "pair_coeff * *", 1e-9, 1)
    path = tmp_path / "bad.liggghts"
    path.write_text(deck)
    proc = subprocess.run([LIGGGHTS, "-log", "none", "-echo", "none", "-in", str(path)],
                          cwd=tmp_path, capture_output=True, text=True, errors="replace",
                          timeout=600)
    assert proc.returncode != 0 or "ERROR" in proc.stdout
    assert "limitForce" in proc.stdout + proc.stderr, proc.stdout[-2000:]
