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
