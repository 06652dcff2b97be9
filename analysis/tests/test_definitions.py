# GRFLOW analysis tests: the summary's sampling and definitions options
# (issue 30, hypotheses 4 and 5), on synthetic data with known answers.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""Tests of grflow_analysis.definitions and the grflow-figures options
--sample-ms, --knee, --block-ms, --zg-percentile and --overlaps.

Each test builds a series or a snapshot whose answer follows from its
construction (stated beside it), not from the library."""

import json
import math
import os
import subprocess

import numpy as np
import pytest

import grflow_analysis as ga
from grflow_analysis import definitions as gd

from test_analysis import BIN, make_run


# ------------------------------------------------------------ decimation

def test_decimate_takes_the_row_nearest_each_multiple():
    # rows every 0.3 ms from 0 to 30 ms; the multiple k ms is nearest to
    # row round(10 k / 3) (10 k / 3 has a fraction 0, 1/3 or 2/3: no tie)
    t = 3e-4 * np.arange(101)
    s = {"time": t, "step": 30.0 * np.arange(101)}
    dec, idx = gd.decimate(s, 1e-3)
    assert list(idx) == [int(round(10 * k / 3)) for k in range(31)]
    assert np.array_equal(dec["step"], s["step"][idx])
    # a tie (0.75 between rows at 0.5 and 1.0; 2.25 between 2 and 2.5) takes
    # the earlier row
    # (binary-exact times, so that the tie is exact: 0 ... 3 s every 0.5 s,
    # multiples 0, 0.75, 1.5, 2.25, 3 s)
    t2 = 0.5 * np.arange(7)
    _, idx2 = gd.decimate({"time": t2}, 0.75)
    assert list(idx2) == [0, 1, 3, 4, 6]
    # a series not starting at a multiple: the multiples within its span only
    _, idx3 = gd.decimate({"time": 1e-3 * np.arange(3, 10) + 2e-4}, 2e-3)
    assert list(idx3) == [1, 3, 5]              # 4.2 ~ 4, 6.2 ~ 6, 8.2 ~ 8 ms
    with pytest.raises(ValueError):
        gd.decimate(s, 0.0)


def test_events_on_rows_go_to_the_first_kept_row_at_or_after():
    events = {"reversal_rows": [7, None], "crossing_rows": {0: 0, 1: 12},
              "rows": [0, 7, 12], "N": [0.0, 0.25, 0.5], "time": [0.0, 1.0, 2.0],
              "N_IL": 0.3, "step_IL": 90}
    ev = gd.events_on_rows(events, [0, 5, 10, 15])
    assert ev["reversal_rows"] == [2, None]
    assert ev["crossing_rows"] == {0: 0, 1: 3}
    assert ev["rows"] == [0, 2, 3]
    assert ev["N"] == events["N"] and ev["N_IL"] == 0.3 and ev["step_IL"] == 90
    assert gd.events_on_rows(events, [0, 5])["crossing_rows"][1] is None


def dip_series():
    """Rows every 0.1 ms over 100 ms (row i at t = i/10 ms, step 10 i).
    r_u 0.5 before row 50 (5 ms), where initial liquefaction is; then 0.995
    (liquefied) except three long dips below 0.99 over rows [105, 135),
    [305, 335), [505, 535) (3 ms each) and one short dip over rows
    [703, 706) (0.3 ms, between two multiples of 1 ms).  z_g: 4.5 before
    the onset, 3.7 on the first row of a long dip and 3.8 on its others,
    2.9 on the short dip, 1.0 on row 855 (85.5 ms) only, 1.5 elsewhere."""
    n = 1001
    i = np.arange(n)
    ru = np.where(i < 50, 0.5, 0.995)
    zg = np.where(i < 50, 4.5, 1.5)
    for a in (105, 305, 505):
        ru[a:a + 30] = 0.95
        zg[a:a + 30] = 3.8
        zg[a] = 3.7
    ru[703:706] = 0.95
    zg[703:706] = 2.9
    zg[855] = 1.0
    p = 1e5 * (1 - ru)
    s = {"step": 10.0 * i, "time": 1e-4 * i, "r_u": ru, "z_g": zg, "p": p,
         "inertial": 0.02 / np.sqrt(p)}
    events = {"reversal_rows": [], "crossing_rows": {0: 0}, "rows": [0], "N": [0.0],
              "time": [0.0], "N_IL": None, "step_IL": 500}
    return s, events


def test_decimated_exits_and_minimum_of_a_known_series():
    s, events = dip_series()
    full = gd.sampled_stats(s, events, 0.99, percentile=5)
    # every row: the exits are the first rows of the four dips
    assert full["n_exits"] == 4
    assert full["z_g_exit_mean"] == pytest.approx((3 * 3.7 + 2.9) / 4, abs=1e-12)
    assert full["z_g_post_IL_min"] == 1.0
    # 1 ms: rows 10 k; the long dips are first seen on rows 110, 310, 510
    # (z_g 3.8), the short dip and the row-855 minimum fall between samples
    dec, idx = gd.decimate(s, 1e-3)
    assert list(idx) == list(range(0, 1001, 10))
    st = gd.sampled_stats(dec, gd.events_on_rows(events, idx), 0.99, percentile=5)
    assert st["onset"] == 5
    assert st["n_exits"] == 3
    assert st["z_g_exit_mean"] == pytest.approx(3.8, abs=1e-12)
    assert st["z_g_exit_std"] == pytest.approx(0.0, abs=1e-12)
    assert st["z_g_post_IL_min"] == 1.5
    # 96 rows from the onset on, 9 of them in dips (3.8): 87 of 1.5 > 5%
    assert st["z_g_post_IL_pct"] == 1.5
    # 5 ms: rows 50 k miss every dip: no exit
    dec5, idx5 = gd.decimate(s, 5e-3)
    st5 = gd.sampled_stats(dec5, gd.events_on_rows(events, idx5), 0.99)
    assert st5["n_exits"] == ga.NOT_REACHED and st5["z_g_exit_mean"] == ga.NOT_REACHED


def test_percentile_of_z_g_after_il():
    # z_g after the onset row is 1, 1.01, ..., 2 (101 values): numpy's linear
    # percentile q is 1 + q/100 exactly, up to round-off
    z = np.r_[np.full(10, 4.0), np.linspace(1.0, 2.0, 101)]
    s = {"z_g": z}
    assert gd.zg_percentile_post_il(s, 10, 5) == pytest.approx(1.05, abs=1e-12)
    assert gd.zg_percentile_post_il(s, 10, 0) == 1.0
    assert gd.zg_percentile_post_il(s, None, 5) == ga.NOT_REACHED


# ------------------------------------------------------------ knee

def test_logistic_knee_is_at_ten_percent_of_the_jump():
    n0, w, a, b = 3.2, 0.004, 1.5, 2.0
    kn, kz = ga.logistic_knee(n0, w, a, b)
    assert kn == pytest.approx(n0 - w * math.log(9.0), abs=1e-15)
    assert kz == pytest.approx(a + 0.1 * b, abs=1e-15)
    # the logistic itself passes through the knee
    assert a + b / (1 + math.exp(-(kn - n0) / w)) == pytest.approx(kz, abs=1e-12)
    assert ga.logistic_knee(n0, w, a, b, 0.5) == pytest.approx((n0, a + 0.5 * b))
    with pytest.raises(ValueError):
        ga.logistic_knee(n0, w, a, b, 1.0)


def test_knee_of_an_exact_logistic_rise():
    """z_g an exact logistic in N (no scatter) in a quarter cycle, the exit
    0.005 cycles after N0: the fit of zg_inflections recovers its knee.
    Bounds from the fit's grid (_logistic_fit): after two refinements the
    centre step is about 4e-7 cycles and the width step exp(0.0053), so
    the width is known to about 0.3% and N0 - w ln 9 to about
    ln 9 x 0.3% = 0.7% of w; z at the knee then moves by at most the slope
    there (0.09 b / w) times that, 6e-4 b.  The bounds are 3x these."""
    rows = 2001
    N = np.linspace(12.5, 12.75, rows)
    N0, w, a, b = 12.6, 0.004, 1.4, 2.2
    zg = a + b / (1.0 + np.exp(-(N - N0) / w))
    exit_row = int(np.searchsorted(N, N0 + 0.005))
    events = {"reversal_rows": [None] * 25 + [rows - 1], "crossing_rows": {25: 0}}
    liq = {"onset": 0, "exits": [exit_row], "entries": []}
    found = ga.zg_inflections({"z_g": zg}, N, events, liq)
    assert len(found) == 1
    f = found[0]
    assert abs(f["knee_N"] - (N0 - w * math.log(9.0))) <= 0.02 * w
    assert abs(f["knee_z_g"] - (a + 0.1 * b)) <= 0.002 * b
    assert abs(f["z_g"] - (a + 0.5 * b)) <= 0.002 * b       # the inflection, as before


# ------------------------------------------------------------ block-averaged I

def const_p_series(p_rows, dt=1e-4, K=0.02):
    """Rows every dt; p as given; the written I = K / sqrt(p) where p > 0,
    -1 elsewhere (as the decks write it)."""
    p = np.asarray(p_rows, dtype=float)
    inert = np.where(p > 0, K / np.sqrt(np.where(p > 0, p, 1.0)), -1.0)
    n = len(p)
    return {"time": dt * np.arange(n), "step": 10.0 * np.arange(n), "p": p,
            "inertial": inert}


def test_block_inertial_of_a_constant_p():
    # 201 rows over 0 ... 20 ms: blocks of 1 ms are k = 0 ... 20 (the last
    # one row); constant p gives I = K / sqrt(p) in every block
    K, p = 0.02, 400.0
    s = const_p_series(np.full(201, p), K=K)
    b = gd.block_inertial(s, 1e-3, onset=100)
    assert b["blocks"] == 21 and b["undefined_blocks"] == 0
    assert b["K"] == pytest.approx(K, rel=1e-12)
    assert b["K_rel_spread"] <= 1e-12
    for key in ("max", "max_pre_IL", "median_post_IL"):
        assert b[key] == pytest.approx(K / math.sqrt(p), rel=1e-12)
    assert b["p_block_min_post_IL"] == pytest.approx(p, rel=1e-12)


def test_block_inertial_counts_blocks_without_positive_p():
    # block 3 (rows 30-39) has p = 0; block 5 (rows 50-59) alternates
    # +-100 Pa (mean 0); block 7 (rows 70-79) is -50 Pa: three blocks have
    # no I, counted and not clipped; block 6 holds 100 Pa, the rest 400 Pa
    p = np.full(101, 400.0)
    p[30:40] = 0.0
    p[50:60] = np.where(np.arange(10) % 2 == 0, 100.0, -100.0)
    p[60:70] = 100.0
    p[70:80] = -50.0
    s = const_p_series(p)
    b = gd.block_inertial(s, 1e-3, onset=20)
    assert b["blocks"] == 11 and b["undefined_blocks"] == 3
    assert b["undefined_blocks_post_IL"] == 3
    assert b["max"] == pytest.approx(0.02 / math.sqrt(100.0), rel=1e-12)
    assert b["p_block_min_post_IL"] == pytest.approx(-50.0, rel=1e-12)
    # blocks from the onset on: 2, 4, 6, 8, 9, 10 defined (5 of 400 Pa, 1 of 100)
    assert b["median_post_IL"] == pytest.approx(0.02 / 20.0, rel=1e-12)
    # a series without any row of defined I has no factor K
    none = gd.block_inertial(const_p_series(np.zeros(20)), 1e-3, onset=None)
    assert none["max"] == ga.NOT_AVAILABLE and none["undefined_blocks"] == 2


# ------------------------------------------------------------ counting rule

def snapshot():
    """A hand-made snapshot: box z in [0, 0.01) (zlo 0, zhi 0.01; the decks'
    slab 0.8 is z in [0.001, 0.009)).  Particles (id: glue, z, radius):
    1, 2, 3, 4, 7 free inside; 6 free at z = 0.0094 (outside the slab);
    5 glued to the bottom; 8 free at z = 0.0003 with radius 0.0005
    (crosses the bottom wall plane; outside the 0.8 slab).  Entries:
    1-2 f_n 0.5; 2-3 f_n 0 (overlapping, no force); 7-6 f_n 0.2; 5-6 f_n 1."""
    ids = np.array([1, 2, 3, 4, 5, 6, 7, 8])
    glue = np.array([0, 0, 0, 0, 1, 0, 0, 0])
    z = np.array([0.005, 0.005, 0.005, 0.005, 0.0005, 0.0094, 0.0085, 0.0003])
    atoms = {"columns": {"id": ids.astype(float), "glue": glue.astype(float), "z": z,
                         "radius": np.full(8, 0.0005)}}
    e = np.array([[1, 2, 0.5], [2, 3, 0.0], [7, 6, 0.2], [5, 6, 1.0]])
    cont = {"columns": {"id1": e[:, 0], "id2": e[:, 1], "fn": e[:, 2],
                        "dx": np.full(4, 0.00099), "dy": np.zeros(4), "dz": np.zeros(4)}}
    return atoms, cont


def test_zg_all_overlaps_of_a_hand_made_snapshot():
    atoms, cont = snapshot()
    # slab 0.8: inside 1, 2, 3, 4, 7.  f_n > 0: c = 1, 1, 0, 0, 1 -> 2
    # floaters, z_g = 3 / 3.  All overlaps: c = 1, 2, 1, 0, 1 -> 1 floater,
    # z_g = 5 / 4; the f_n = 0 pair adds one end to 2 and one to 3
    pos = gd.zg_overlaps(atoms, cont, 0.0, 0.01, rule="fn>0")
    assert (pos["N_p"], pos["floaters"], pos["N_c"], pos["z_g"]) == (5, 2, 1.5, 1.0)
    allo = gd.zg_overlaps(atoms, cont, 0.0, 0.01)
    assert (allo["N_p"], allo["floaters"], allo["N_c"], allo["z_g"]) == (5, 1, 2.5, 1.25)
    assert allo["ends_fn_nonpositive"] == 2 and pos["ends_fn_nonpositive"] == 0
    assert allo["entries"] == 4 and allo["entries_fn_nonpositive"] == 1
    # the branch vectors are 0.99 mm for radii summing to 1 mm: resolved overlaps
    assert allo["entries_unresolved"] == 0
    # slab 1.0: 6 and 8 are inside too (5 is glued); 6 has two pairs, 8
    # touches the bottom wall plane: all overlaps c = 1, 2, 1, 0, 2, 1, 1
    # -> z_g = 8 / 6; f_n > 0: c = 1, 1, 0, 0, 2, 1, 1 -> z_g = 6 / 5
    allo1 = gd.zg_overlaps(atoms, cont, 0.0, 0.01, slab=1.0)
    assert allo1["N_p"] == 7 and allo1["z_g"] == pytest.approx(8 / 6, abs=1e-15)
    pos1 = gd.zg_overlaps(atoms, cont, 0.0, 0.01, slab=1.0, rule="fn>0")
    assert pos1["z_g"] == pytest.approx(6 / 5, abs=1e-15)
    cont["columns"]["id2"][0] = 99
    with pytest.raises(ga.FormatError):
        gd.zg_overlaps(atoms, cont, 0.0, 0.01)


# ------------------------------------------------------------ the command

@pytest.fixture(scope="module")
def run_dir(tmp_path_factory):
    return make_run(str(tmp_path_factory.mktemp("defs") / "run"))[0]


def test_summary_without_options_has_no_definitions(run_dir):
    s = ga.read_series(os.path.join(run_dir, "series.txt"))
    summ = ga.summary(s, None, ga.run_events(run_dir, s))
    assert "definitions" not in summ
    assert "Sampling and definitions" not in ga.summary_markdown(summ)


def test_command_with_the_options(run_dir, tmp_path):
    out = tmp_path / "figs"
    res = subprocess.run([os.path.join(BIN, "grflow-figures"), run_dir, "--out", str(out),
                          "--sample-ms", "2,5", "--knee", "--block-ms", "3",
                          "--zg-percentile", "5", "--overlaps"],
                         capture_output=True, text=True, timeout=240)
    assert res.returncode == 0, res.stderr
    summ = json.loads((out / "summary.json").read_text())
    d = summ["definitions"]
    names = [e["name"] for e in d["entries"]]
    for n in ("z_g_knees", "z_g_knee_mean", "z_g_post_IL_p5", "inertial_block3ms_max",
              "inertial_block3ms_undefined_blocks", "n_exits@2ms", "z_g_exit_mean@5ms",
              "z_g_post_IL_min@2ms", "z_g_post_IL_p5@5ms", "inertial_max@2ms",
              "z_g_all_overlaps_C0", "z_g_all_overlaps_C2",
              "z_g_all_overlaps_minus_fn_positive_crossings",
              "z_g_whole_height_minus_slab_crossings", "z_g_whole_height_minus_slab_reversals"):
        assert n in names, n
    assert d["options"] == {"sample_ms": [2.0, 5.0], "knee": True, "block_ms": [3.0],
                            "percentile": 5.0, "overlaps": True}
    # the synthetic run has rows every 1 ms: at 2 ms the even rows are kept
    assert d["sampled"]["2ms"]["rows"] == (summ["rows"] + 1) // 2
    # the present entries are those of a run without the options
    s = ga.read_series(os.path.join(run_dir, "series.txt"))
    plain = ga.summary(s, None, ga.run_events(run_dir, s))
    assert [e["name"] for e in summ["entries"]] == [e["name"] for e in plain["entries"]]
    md = (out / "summary.md").read_text()
    assert "## Sampling and definitions" in md and "z_g_all_overlaps_C0" in md


@pytest.mark.parametrize("args", [["--sample-ms", "0"], ["--block-ms", "x"],
                                  ["--zg-percentile", "101"]])
def test_command_rejects_bad_options(run_dir, tmp_path, args):
    res = subprocess.run([os.path.join(BIN, "grflow-figures"), run_dir, "--out",
                          str(tmp_path / "o")] + args, capture_output=True, text=True,
                         timeout=120)
    assert res.returncode == 2 and "error" in res.stderr


def test_overlaps_over_snapshots_split_by_event_kind(tmp_path):
    """Two snapshots after initial liquefaction (step_IL 100), both the
    hand-made snapshot above (all overlaps z_g 5/4, f_n > 0 z_g 1): one on
    a zero-crossing (step 200, event 2) and one on a reversal (step 300,
    event 1); one before the onset (step 50), left out."""
    from test_analysis import write_atoms, write_contacts
    atoms, cont = snapshot()
    snap = tmp_path / "snapshots"
    snap.mkdir()
    a = atoms["columns"]
    xyz = np.column_stack([np.arange(8) * 2e-3, np.zeros(8), a["z"]])
    box = [(0.0, 0.02), (0.0, 0.02), (0.0, 0.01)]
    pairs = [(1, 2, 0.5), (2, 3, 0.0), (7, 6, 0.2), (5, 6, 1.0)]
    for st in (50, 200, 300):
        write_atoms(str(snap / ("atoms.%d.txt" % st)), st, a["id"].astype(int), a["radius"],
                    xyz, a["glue"].astype(int), box)
        write_contacts(str(snap / ("contacts.%d.txt" % st)), st, pairs, box)
    (tmp_path / "events.txt").write_text(
        "# step time event reversals N N_IL step_IL\n0 0 0 0 0 -1 -1\n"
        "150 1.5 1 1 0.25 -1 100\n200 2 2 1 0.5 0.3 100\n300 3 1 2 0.75 0.3 100\n")
    series = {"step": np.array([0.0, 100, 200, 300]), "zlo": np.zeros(4),
              "zhi": np.full(4, 0.01)}
    out = gd.overlaps_over_snapshots(str(tmp_path), series, 100)
    for kind in ("crossings", "reversals"):
        x = out[kind]
        assert x["snapshots"] == 1
        assert x["z_g_fn_positive_mean"] == 1.0 and x["z_g_all_overlaps_mean"] == 1.25
        assert x["difference_mean"] == pytest.approx(0.25, abs=1e-15)
        assert x["ends_fn_nonpositive_fraction"] == pytest.approx(2 / 5, abs=1e-15)
        # the whole height of the same snapshot: f_n > 0 z_g 6/5 (test above)
        assert x["z_g_whole_height_mean"] == pytest.approx(6 / 5, abs=1e-15)
    assert gd.overlaps_over_snapshots(str(tmp_path), series, None) == ga.NOT_REACHED
    # the whole height (slab 1.0): f_n > 0 z_g 6/5 (test above) on both kinds
    whole = gd.overlaps_over_snapshots(str(tmp_path), series, 100, slab=1.0)
    for kind in ("crossings", "reversals"):
        assert whole[kind]["z_g_fn_positive_mean"] == pytest.approx(6 / 5, abs=1e-15)


def test_options_on_a_run_that_never_liquefied(tmp_path):
    from fractions import Fraction as F
    root = make_run(str(tmp_path / "dry"), liquefy=False, quarters=13, last_fraction=F(1, 2))[0]
    s = ga.read_series(os.path.join(root, "series.txt"))
    summ = ga.summary(s, None, ga.run_events(root, s), sample_ms=(2,), knee=True,
                      block_ms=(3,), percentile=5, overlaps=True, run_dir=root)
    e = {x["name"]: x for x in summ["definitions"]["entries"]}
    for n in ("z_g_knee_mean", "z_g_post_IL_p5", "inertial_block3ms_median_post_IL",
              "n_exits@2ms", "z_g_post_IL_min@2ms", "z_g_all_overlaps_C0",
              "z_g_all_overlaps_minus_fn_positive_crossings",
              "z_g_whole_height_minus_slab_crossings", "z_g_whole_height_minus_slab_reversals"):
        assert e[n]["measured"] == ga.NOT_REACHED, n
        assert e[n]["match"] is False
    assert isinstance(e["inertial_block3ms_max"]["measured"], float)
    json.dumps(summ, allow_nan=False)
