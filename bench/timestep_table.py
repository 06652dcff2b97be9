#!/usr/bin/env python3
"""One table of the runs of bench/timestep_study.sh: per run directory
(named s<seed>_f<dt_factor>) the preparation's e, z_g and p, N_IL, the
liquefaction exits' z_g, the smallest and largest z_g after initial
liquefaction, z_g at the inflections of z_g(N) at the exits (all from
figures/summary.json, as grflow-figures wrote them), the
simulated time from initial liquefaction to the end of the series (at a
fixed wall speed a measure of the strains of the post-liquefaction
cycles; from series.txt), the shear stage's steps and the wall time;
then, per dt_factor, the mean and the spread (min-max) over the seeds.

    grflow-python bench/timestep_table.py RUNDIR ...

(grflow-python: the set-up's Python, in which grflow_analysis is
installed; build/python/bin/python is the tests' one.)
"""
import json
import os
import re
import sys
from collections import defaultdict

import grflow_analysis as ga

KEYS = [("e_prep", "e", "{:.4f}"), ("z_g_prep", "z_g0", "{:.3f}"), ("p_prep", "p0 (kPa)", "{:.1f}"),
        ("N_IL", "N_IL", "{:.2f}"), ("n_exits", "exits", "{:d}"),
        ("z_g_exit_mean", "z_g exits", "{:.3f}"), ("z_g_post_IL_min", "min z_g", "{:.3f}"),
        ("z_g_post_IL_max", "max z_g", "{:.3f}"), ("z_g_inflection_mean", "z_g infl.", "{:.3f}"),
        ("t_post_IL", "t after IL (s)", "{:.4f}")]


def post_il_time(run, ru_liq):
    """simulated time from the row of initial liquefaction (ga.liquefaction)
    to the last row"""
    try:
        series = ga.read_series(os.path.join(run, "series.txt"))
        events = ga.run_events(run, series)
    except (OSError, ga.FormatError):
        return None
    onset = ga.liquefaction(series, events, ru_liq)["onset"]
    return None if onset is None else float(series["time"][-1] - series["time"][onset])


def value(summary, key, run=None):
    if key == "t_post_IL":
        return post_il_time(run, summary.get("ru_liq", 0.99))
    v = next((e.get("measured") for e in summary.get("entries", []) if e.get("name") == key), None)
    if isinstance(v, str):
        return None    # "not reached" and the like
    if key == "p_prep" and v is not None:
        v = v / 1e3
    return v


def last_step(run):
    try:
        with open(os.path.join(run, "log.shear.lammps")) as f:
            steps = re.findall(r"GRFLOW shear: done at step (\d+)", f.read())
        return int(steps[-1]) if steps else None
    except OSError:
        return None


def main():
    rows = []
    for run in sys.argv[1:]:
        m = re.search(r"s([^_/]+)_f([0-9.]+)$", run.rstrip("/"))
        if not m:
            continue
        try:
            with open(os.path.join(run, "figures", "summary.json")) as f:
                summary = json.load(f)
        except OSError:
            print(f"# {run}: no figures/summary.json")
            continue
        wall = None
        try:
            wall = float(open(os.path.join(run, "wall_seconds.txt")).read())
        except OSError:
            pass
        rows.append((m.group(2), m.group(1), [value(summary, k, run) for k, _, _ in KEYS],
                     last_step(run), wall))
    rows.sort(key=lambda r: (float(r[0]), r[1]))
    head = ["dt_factor", "seed"] + [name for _, name, _ in KEYS] + ["shear steps", "wall (s)"]
    print("| " + " | ".join(head) + " |")
    print("|" + " --- |" * len(head))

    def fmt(fm, v):
        if v is None:
            return "-"
        return fm.format(int(v)) if "d" in fm else fm.format(v)

    for f, seed, vals, steps, wall in rows:
        cells = [f, seed] + [fmt(fm, v) for (_, _, fm), v in zip(KEYS, vals)]
        cells += [str(steps) if steps else "-", f"{wall:.0f}" if wall else "-"]
        print("| " + " | ".join(cells) + " |")
    groups = defaultdict(list)
    for f, seed, vals, steps, wall in rows:
        groups[f].append((vals, steps, wall))
    print()
    print("| dt_factor | runs | " + " | ".join(name for _, name, _ in KEYS) + " | wall (s) |")
    print("|" + " --- |" * (len(KEYS) + 3))
    for f in sorted(groups, key=float):
        g = groups[f]
        cells = [f, str(len(g))]
        for k, (_, _, fm) in enumerate(KEYS):
            vs = [r[0][k] for r in g if r[0][k] is not None]
            if not vs:
                cells.append("-")
                continue
            fm2 = "{:.2f}" if "d" in fm else fm
            cells.append(f"{fm2.format(sum(vs) / len(vs))} [{fm2.format(min(vs))}, {fm2.format(max(vs))}]")
        ws = [r[2] for r in g if r[2]]
        cells.append(f"{sum(ws) / len(ws):.0f}" if ws else "-")
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
