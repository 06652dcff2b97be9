"""grflowplugin.so: the GRFLOW package as a LAMMPS plugin.

The plugin is built with hidden symbols, so loaded into this build's lmp
(which has GRFLOW built in) it still runs its own copy of the code.  It
must need no GRFLOW symbol from the host, so that a PLUGIN-enabled stock
LAMMPS 4Feb2025 without GRFLOW can load it.

Environment: LMP, GRFLOW_PLUGIN, GRFLOW_TEST_DECKS; for the plugin-only
build GRFLOW_STAGED_LAMMPS (the LAMMPS tree the default build staged) and
GRFLOW_INPUTS (the decks).
"""
import os
import shutil
import subprocess

import numpy as np
import pytest

from lmprun import DECKS, run_lmp

PLUGIN = os.environ.get("GRFLOW_PLUGIN", "grflowplugin.so")




@pytest.mark.skipif(shutil.which("nm") is None, reason="needs nm (binutils)")
def test_plugin_is_self_contained():
    out = subprocess.run(["nm", "-D", "-C", PLUGIN], capture_output=True, text=True,
                         check=True).stdout
    undefined = [l for l in out.splitlines() if l.split()[0] == "U" and "GRFLOW" in l]
    exported = [l.split()[-1] for l in out.splitlines() if " T " in l]
    assert undefined == []
    assert exported == ["lammpsplugin_init"]


def test_plugin_registers_style(tmp_path):
    out = run_lmp([], tmp_path, stdin=f"plugin load {PLUGIN}\nplugin list\n").stdout
    for style in ("pair style plugin granular/grflow", "compute style plugin grflow/network",
                  "fix style plugin grflow/wall", "fix style plugin grflow/shear",
                  "fix style plugin grflow/compress"):
        assert style in out


def test_plugin_gives_the_builtin_trajectory(tmp_path):
    """Two spheres rolling across a periodic boundary, newton off (which
    exercises transfer_history): plugin and built-in style agree bit for bit."""
    dumps = {}
    for name, prefix in (("builtin", ""), ("plugin", f"plugin load {PLUGIN}\n")):
        deck = tmp_path / f"{name}.lmp"
        deck.write_text(prefix + f"include {os.path.join(DECKS, 'boundary_crossing.lmp')}\n")
        dumps[name] = tmp_path / f"{name}.dump"
        out = run_lmp(["-in", str(deck), "-var", "newton", "off",
                       "-var", "pairstyle", "granular/grflow",
                       "-var", "paircoeff", "* * 1.0e6 1.15 mut 0.3",
                       "-var", "dump", str(dumps[name])], tmp_path).stdout
        if name == "plugin":
            assert "Overriding built-in pair style granular/grflow" in out
    a = np.loadtxt(dumps["builtin"], skiprows=9)
    b = np.loadtxt(dumps["plugin"], skiprows=9)
    assert np.abs(a[:, 2:]).max() > 0.0
    assert np.array_equal(a, b)


STAGED = os.environ.get("GRFLOW_STAGED_LAMMPS")
INPUTS = os.environ.get("GRFLOW_INPUTS")
PLUGIN_PROJECT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plugin")


@pytest.mark.skipif(not STAGED or not INPUTS or shutil.which("cmake") is None,
                    reason="needs cmake, GRFLOW_STAGED_LAMMPS and GRFLOW_INPUTS")
def test_plugin_only_build_runs_every_style(tmp_path):
    """The README's plugin-only build (plugin/CMakeLists.txt against a
    LAMMPS source tree, here the one the default build staged), loaded
    into that lmp with plugin load: a small paper protocol (preparation
    with fix grflow/compress, shear with fix grflow/shear, walls, pair
    style and compute) runs on the plugin's styles."""
    build = tmp_path / "build-plugin"
    subprocess.run(["cmake", "-S", PLUGIN_PROJECT, "-B", str(build),
                    "-D", f"LAMMPS_SOURCE_DIR={STAGED}"], check=True, capture_output=True,
                   text=True)
    subprocess.run(["cmake", "--build", str(build)], check=True, capture_output=True, text=True)
    plugin = build / "grflowplugin.so"
    assert plugin.exists()
    deck = tmp_path / "with_plugin.lmp"
    deck.write_text(f"plugin load {plugin}\n"
                    f"include {os.path.join(INPUTS, 'cyclic_shear.lmp')}\n")
    out_dir = tmp_path / "run"
    out = run_lmp(["-in", str(deck), "-var", "inputs", INPUTS, "-var", "outdir", str(out_dir),
                   "-var", "preset", "quick", "-var", "N", "500", "-var", "max_steps", "20000"],
                  tmp_path).stdout
    for style in ("pair style granular/grflow", "compute style grflow/network",
                  "fix style grflow/wall", "fix style grflow/shear",
                  "fix style grflow/compress"):
        assert f"Overriding built-in {style}" in out, style
    log = (out_dir / "log.shear.lammps").read_text()
    assert "GRFLOW shear: done at step 20000" in log
