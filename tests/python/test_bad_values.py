"""Values that reach granular/grflow by roads other than pair_coeff get the
same checks, and stop LAMMPS with an error that names them: fix adapt
(through Pair::reinit() and init_one()) with equal-style variables that
evaluate to a negative, zero or infinite coefficient (LAMMPS's variables
themselves refuse to make a NaN), and a timestep that is not > 0.  (Through lmp, not the library API: an error
raised while a run sets up leaves LAMMPS 4Feb2025's fix NEIGH_HISTORY in a
state its destructor cannot free, so a library instance could not be
closed after it.)

Environment: LMP (lmp binary).
"""
import struct

import pytest

from lmprun import run_lmp

SETUP = """units si
atom_style sphere
region box block 0 0.01 0 0.01 0 0.01
create_box 1 box
create_atoms 1 single 0.005 0.005 0.005
create_atoms 1 single 0.0059 0.005 0.005
set group all diameter 1.0e-3 density 2650
pair_style granular/grflow
pair_coeff * * 1.0e6 1.15
comm_modify vel yes
fix nve all nve/sphere
"""


def error_of(tmp_path, lines):
    deck = tmp_path / "in.bad"
    deck.write_text(SETUP + lines)
    proc = run_lmp(["-in", str(deck)], tmp_path, check=False)
    assert proc.returncode != 0, proc.stdout[-2000:]
    return proc.stdout + proc.stderr


@pytest.mark.parametrize("value,coeff,expect", [
    ("-0.5", "mut", "mut must be >= 0, got -0.5"),
    ("0.0", "kn", "kn must be > 0, got 0"),
    ("1.0e300*1.0e300", "kn", "kn must be finite, got inf"),
    ("-1.0e300*1.0e300", "co", "co must be finite, got -inf"),
])
def test_fix_adapt_value_is_checked(tmp_path, value, coeff, expect):
    text = error_of(tmp_path, f"variable v equal {value}\n"
                              f"fix a all adapt 1 pair granular/grflow {coeff} * * v_v reset no\n"
                              "run 1\n")
    assert "Pair granular/grflow coefficients of types 1 1" in text
    assert expect in text


@pytest.mark.parametrize("dt", ["0.0", "-1.0e-7"])
def test_timestep_must_be_positive(tmp_path, dt):
    text = error_of(tmp_path, f"timestep {dt}\nrun 1\n")
    assert "needs a timestep > 0" in text


def test_same_centre_is_an_error(tmp_path):
    # a second sphere exactly on the first: no contact normal
    text = error_of(tmp_path, "create_atoms 1 single 0.005 0.005 0.005\n"
                              "set atom 3 diameter 1.0e-3 density 2650\nrun 1\n")
    assert "atoms 1 and 3 are at the same position" in text or \
        "atoms 3 and 1 are at the same position" in text


@pytest.mark.parametrize("diameter", ["-1.0e-3", "0.0"])
def test_bad_diameter_from_a_data_file(tmp_path, diameter):
    # a data file is one road a diameter takes that set and create_atoms
    # do not check
    data = tmp_path / "bad.data"
    data.write_text(f"""# two spheres, one with a bad diameter

2 atoms
1 atom types
0 0.01 xlo xhi
0 0.01 ylo yhi
0 0.01 zlo zhi

Atoms # sphere

1 1 1.0e-3 2650 0.005 0.005 0.005
2 1 {diameter} 2650 0.0059 0.005 0.005
""")
    deck = tmp_path / "in.data"
    deck.write_text(f"""units si
atom_style sphere
read_data {data}
pair_style granular/grflow
pair_coeff * * 1.0e6 1.15
comm_modify vel yes
fix nve all nve/sphere
run 1
""")
    proc = run_lmp(["-in", str(deck)], tmp_path, check=False)
    text = proc.stdout + proc.stderr
    assert proc.returncode != 0, text[-2000:]
    assert "atom 2 has diameter" in text and "finite diameter > 0" in text, text[-2000:]


@pytest.mark.parametrize("args,expect", [
    ("zlimits v_lo v_inf", "variable inf is inf, not a finite number"),
    ("zlimits v_hi v_lo", "must have zlo < zhi"),
    # the volume of a region sub-volume, by the same road
    ("region box volume v_inf", "volume: variable inf is inf, not a finite number"),
])
def test_network_zlimits_and_volume_must_be_finite(tmp_path, args, expect):
    # an equal-style variable can be infinite (1e300*1e300); LAMMPS refuses
    # to use it in another formula, so a NaN cannot be made this way (the
    # same check catches one)
    text = error_of(tmp_path, "variable lo equal 0.0\nvariable hi equal 0.01\n"
                              "variable inf equal 1.0e300*1.0e300\n"
                              f"compute net all grflow/network {args}\n"
                              "thermo_style custom step c_net[1]\nrun 0\n")
    assert expect in text, text[-2000:]


RESTART_PAIR = """
units           si
atom_style      sphere
region          box block 0 0.01 0 0.01 0 0.01
create_box      1 box
create_atoms    1 single 0.005 0.005 0.005
set             type 1 diameter 0.001 density 2650
pair_style      granular/grflow
pair_coeff      * * 1.0e6 1.15
comm_modify     vel yes
write_restart   pair.restart
"""


@pytest.mark.parametrize("value,expect", [
    (float("nan"), "kn must be finite, got nan"),
    (-1.0, "kn must be > 0, got -1"),
])
def test_damaged_pair_coefficients_in_a_restart_file(tmp_path, value, expect):
    """A restart file whose pair coefficients were damaged (the bytes of kn
    overwritten): read_restart stops with the pair style's rule for kn,
    naming the types, instead of running with them."""
    (tmp_path / "write.lmp").write_text(RESTART_PAIR)
    run_lmp(["-in", "write.lmp"], tmp_path)
    path = tmp_path / "pair.restart"
    data = path.read_bytes()
    coeffs = struct.pack("=dd", 1.0e6, 1.15)
    assert data.count(coeffs) == 1
    path.write_bytes(data.replace(coeffs, struct.pack("=dd", value, 1.15)))
    (tmp_path / "read.lmp").write_text("read_restart pair.restart\nrun 0\n")
    proc = run_lmp(["-in", "read.lmp"], tmp_path, check=False)
    assert proc.returncode != 0
    assert ("Pair granular/grflow: damaged restart file: types 1 1: " + expect
            in proc.stdout + proc.stderr)
