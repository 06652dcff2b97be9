#!/usr/bin/env python3
# GRFLOW - one figure of the sensitivity runs (issue 16).
# Copyright the GRFLOW developers; GNU General Public License version 2.
"""What moves the liquefaction exits' z_g and N_IL: the wall speed v_x, the
shear stage's time step factor, the rolling/torsion arm, the
preparation route and N (1000 against 2000), each changed alone, from
the runs' figures/summary.json as grflow-figures wrote them
(this script only draws; every number is the summary's).

    grflow-python bench/plot_sensitivity.py [--out PNG] [--runs DIR]

(grflow-python: the set-up's Python, which has matplotlib.)

DIR (default runs/) holds the run directories of bench/variants_quick.sh
(vx/: the wall speed, its variants named v<v_x>; arm/, route/),
bench/timestep_study.sh (dtq10/, dtq10b/), and the paper-size runs
case03/ (v_x = 0.01 m/s) and vx005/ (0.005 m/s, same preparation and time
step); a missing run is left out of its panel.
"""

import argparse
import json
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PAPER_EXIT = 3.6
SEED_MARK = {"1": "o", "2": "s", "3": "^", "5827": "D"}


def summary(path):
    """the summary's measured values by name, None if the run has none"""
    f = os.path.join(path, "figures", "summary.json")
    if not os.path.isfile(f):
        return None
    with open(f) as fh:
        return {e["name"]: e["measured"] for e in json.load(fh)["entries"]}


def number(v):
    return v if isinstance(v, (int, float)) else None


def runs_matching(folder, pattern):
    """(groups, summary) of the run directories in folder whose names match"""
    out = []
    if not os.path.isdir(folder):
        return out
    for name in sorted(os.listdir(folder)):
        m = re.fullmatch(pattern, name)
        s = summary(os.path.join(folder, name)) if m else None
        if s is not None:
            out.append((m.groups(), s))
    return out


def variant_panel(ax, folder, variants, ticks, color):
    """the exits' z_g (colour) and N_IL (grey, right axis) of the runs
    s<seed>_<variant> in folder, one column per variant; "no IL" where the
    run reached max_cycles without initial liquefaction"""
    ax2 = ax.twinx()
    pos = {v: k for k, v in enumerate(variants)}
    pattern = r"s(\d+)_(%s)" % "|".join(variants)
    for (seed, var), s in runs_matching(folder, pattern):
        z, n = number(s.get("z_g_exit_mean")), number(s.get("N_IL"))
        x = pos[var] + 0.08 * (int(seed) - 2)
        if z is not None:
            ax.plot(x, z, SEED_MARK.get(seed, "x"), color=color, mfc="none", label="seed " + seed)
        if n is not None:
            ax2.plot(x, n, SEED_MARK.get(seed, "x"), color="0.5", ms=4)
        else:
            ax.annotate("no IL (seed %s)" % seed, (x, 0.2 + 0.06 * int(seed)),
                        xycoords=("data", "axes fraction"), ha="center", fontsize=7, color="0.3")
    ax.set_xticks(list(pos.values()))
    ax.set_xticklabels(ticks)
    ax2.set_ylabel("$N_{IL}$ (grey)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", default="runs")
    ap.add_argument("--out", default="doc/figures/sensitivity.png")
    a = ap.parse_args()
    fig, axes = plt.subplots(1, 4, figsize=(20, 4.6))

    # (a) wall speed
    ax = axes[0]
    for (seed, vx), s in runs_matching(os.path.join(a.runs, "vx"), r"s(\d+)_v([0-9.]+)"):
        z = number(s.get("z_g_exit_mean"))
        if z is not None:
            ax.plot(float(vx), z, SEED_MARK.get(seed, "x"), color="C0", mfc="none",
                    label="N = 1000, seed " + seed)
    for name, vx in (("case03", 0.01), ("vx005", 0.005)):
        s = summary(os.path.join(a.runs, name))
        if s is not None and number(s.get("z_g_exit_mean")) is not None:
            ax.errorbar(vx, s["z_g_exit_mean"], yerr=s.get("z_g_exit_std") or 0.0, fmt="*",
                        color="C3", ms=11, capsize=3,
                        label="N = 8000, seed 5827 (%d exits)" % s["n_exits"])
    ax.set_xscale("log")
    ax.set_xlabel("wall speed $v_x$ (m/s)")
    ax.set_title("(a) wall speed")

    # (b) time step factor of the shear stage (N = 1000)
    ax = axes[1]
    for folder in ("dtq10", "dtq10b"):
        for (seed, f), s in runs_matching(os.path.join(a.runs, folder), r"s(\d+)_f([0-9.]+)"):
            z = number(s.get("z_g_exit_mean"))
            if z is not None:
                ax.plot(float(f), z, SEED_MARK.get(seed, "x"), color="C1", mfc="none",
                        label="seed " + seed)
    ax.set_xlabel("dt_factor_shear")
    ax.set_title("(b) time step, N = 1000, v_x = 0.05 m/s")

    # (c) rolling and torsion arm (N = 1000), exits and N_IL
    variant_panel(axes[2], os.path.join(a.runs, "arm"), ["base", "arm2", "arm2e"],
                  ["arm a'\n(default)", "arm 2a'", "arm 2a',\nsame e"], "C2")
    axes[2].set_title("(c) rolling/torsion arm, N = 1000")

    # (d) preparation route: compression alone against the agitated route,
    # both calibrated to the same e (0.714 and 0.70), v_x = 0.01 m/s
    # and, last column, compression alone at N = 2000 (e = 0.714)
    variant_panel(axes[3], os.path.join(a.runs, "route"),
                  ["plain", "agit", "plain70", "agit70", "n2000"],
                  ["compression\nalone", "agitated", "compression\nalone", "agitated",
                   "compression\nalone,\nN = 2000"], "C4")
    axes[3].set_xlabel("e = 0.714             e = 0.70            e = 0.714")
    axes[3].set_title("(d) preparation route (N = 1000) and N, v_x = 0.01 m/s")

    for ax, loc in zip(axes, ("lower left", "lower left", "center", "upper center")):
        ax.axhline(PAPER_EXIT, color="k", ls="--", lw=0.8)
        ax.set_ylabel("$z_g$ at the liquefaction exits (mean)")
        handles, labels = ax.get_legend_handles_labels()
        seen = {}
        for h, lab in zip(handles, labels):
            seen.setdefault(lab, h)
        if seen:
            ax.legend(seen.values(), seen.keys(), fontsize=7, loc=loc)
    axes[0].text(0.005, PAPER_EXIT + 0.01, "paper: 3.6", fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    fig.savefig(a.out, dpi=110)
    print("wrote " + a.out)


if __name__ == "__main__":
    main()
