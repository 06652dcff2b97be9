# GRFLOW analysis: the figures 1-5 and the summary of a run directory.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""Figures 1-5 of the isochoric cyclic shearing paper and a summary table.

usage: grflow-figures RUN_DIR [--out OUTDIR] [--cycle K] [--snapshot STEP]
                      [--sample-ms MS,...] [--knee] [--block-ms MS,...]
                      [--zg-percentile Q] [--overlaps]

Writes fig1_snapshots.png, fig2_macro.png, fig3_zg.png, fig4_pc.png,
fig5_ac_zg.png, summary.json and summary.md into OUTDIR (default
RUN_DIR/figures) and prints the summary table.  Exit status: 0 on success
(also when the run never liquefied), 1 if a figure failed unexpectedly,
2 if RUN_DIR, series.txt or events.txt is missing or malformed.  See
analysis/README.md.
"""

import argparse
import json
import math
import os
import sys
import traceback
import warnings

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection, LineCollection  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import grflow_analysis as ga  # noqa: E402

LABEL = {"C0": "$C_0$", "C0'": "$C_{0'}$", "C1": "$C_1$",
         "C2": "$C_2$", "C2'": "$C_{2'}$", "C3": "$C_3$"}
MARKER = {"C0": "o", "C0'": "s", "C1": "^", "C2": "D", "C2'": "P", "C3": "v"}
COLOR = {"C0": "tab:blue", "C0'": "tab:cyan", "C1": "tab:green",
         "C2": "tab:purple", "C2'": "tab:pink", "C3": "tab:olive"}
PRE, POST, CYC = "0.6", "tab:red", "black"
ZG_EXIT = 3.6
RU_CMAP = "turbo"
MAX_POINTS = 200000     # whole-run curves are thinned to about this many points


class Run:
    """Everything the figures need, computed once from the series."""

    def __init__(self, run_dir, series, prep, events, cycle_index=None, shear=None):
        self.dir = run_dir
        self.s = series
        self.prep = prep
        self.ru_liq, self.tau_amp = ga.protocol(prep, shear)
        self.events = events
        self.N = ga.cycle_count(series, self.events)
        self.liq = ga.liquefaction(series, self.events, self.ru_liq)
        self.onset = self.liq["onset"]
        self.n_il = ga.liquefaction_n(self.events, self.onset)
        self.n, self.states, self.note = ga.choose_cycle(
            series, self.events, self.ru_liq, cycle_index, self.liq)
        self.crange = (ga.cycle_rows(series, self.events, self.n)
                       if self.n is not None else None)
        self.stride = max(1, int(math.ceil(len(self.N) / MAX_POINTS)))

    def found_states(self):
        if self.states is None:
            return []
        return [(st, r) for st, r in self.states.items() if r is not None]

    def cycle_slice(self):
        a, b = self.crange
        return slice(a, b + 1)


def _note(msg):
    print("note: " + msg)


def _colored_line(ax, x, y, c, cmap, vmin, vmax, lw=1.0):
    pts = np.column_stack([x, y])
    ok = np.all(np.isfinite(pts), axis=1)
    seg = np.stack([pts[:-1], pts[1:]], axis=1)[ok[:-1] & ok[1:]]
    cval = 0.5 * (c[:-1] + c[1:])[ok[:-1] & ok[1:]]
    lc = LineCollection(seg, cmap=cmap, linewidths=lw)
    lc.set_array(cval)
    lc.set_clim(vmin, vmax)
    ax.add_collection(lc)
    return lc


def _limits(ax, x, y, pad=0.04):
    x, y = np.asarray(x), np.asarray(y)
    for v, setter in ((x, ax.set_xlim), (y, ax.set_ylim)):
        v = v[np.isfinite(v)]
        if len(v):
            lo, hi = v.min(), v.max()
            d = (hi - lo) * pad or max(abs(hi), 1.0) * pad
            setter(lo - d, hi + d)


def _mark_states(ax, run, x, y, size=50, annotate=True):
    for st, r in run.found_states():
        ax.scatter([x[r]], [y[r]], marker=MARKER[st], s=size, color=COLOR[st],
                   edgecolors="k", linewidths=0.6, zorder=5, label=LABEL[st])
        if annotate:
            ax.annotate(LABEL[st], (x[r], y[r]), textcoords="offset points",
                        xytext=(5, 5), fontsize=9, zorder=6)


def _finish(fig, path, keep, **save):
    """Save the figure; return its path, or with keep the Figure itself
    (left open, for tests that look at what it shows)."""
    fig.savefig(path, dpi=130, **save)
    if keep:
        return fig
    plt.close(fig)
    return path


def _not_reached(ax, text, y=0.5):
    ax.text(0.5, y, text, transform=ax.transAxes, ha="center", va="center",
            fontsize=11, color="tab:red",
            bbox=dict(boxstyle="round", fc="white", ec="tab:red", alpha=0.85))


# ---------------------------------------------------------------- Fig. 1

def _side_view(ax, snap, stripes, walls, title):
    c = snap["columns"]
    ids = c["id"].astype(np.int64)
    order = np.argsort(-c["y"])          # far (large y) first, near ones on top
    x, z, r = c["x"][order] * 1e3, c["z"][order] * 1e3, c["radius"][order] * 1e3
    glue = c["glue"][order]
    colors = np.empty((len(x), 4))
    stripe = np.array([stripes.get(i, 0) for i in ids[order]])
    colors[:] = matplotlib.colors.to_rgba("tab:orange")
    colors[stripe == 1] = matplotlib.colors.to_rgba("tab:blue")
    colors[glue > 0] = matplotlib.colors.to_rgba("0.65")
    ax.add_collection(EllipseCollection(
        2 * r, 2 * r, np.zeros_like(r), units="xy", offsets=np.column_stack([x, z]),
        offset_transform=ax.transData, facecolors=colors, edgecolors="0.15",
        linewidths=0.15))
    box = snap["box"]
    if box is not None:
        xlo, xhi = box[0] * 1e3
    else:
        xlo, xhi = (x - r).min(), (x + r).max()
    zlo, zhi = (z - r).min(), (z + r).max()
    for w in walls:
        ax.axhline(w * 1e3, color="k", lw=2.5)
        zlo, zhi = min(zlo, w * 1e3), max(zhi, w * 1e3)
    ax.set_xlim(xlo - 0.5, xhi + 0.5)
    ax.set_ylim(zlo - 0.5, zhi + 0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title(title, fontsize=10)


def fig1(run, out, snapshot_step=None, keep=False):
    """Side views (x-z) of the sample at the end of preparation and during shear."""
    prep_path = os.path.join(run.dir, "snapshots", "atoms.prep.txt")
    shear = ga.list_snapshots(run.dir, "atoms")
    if snapshot_step is not None:
        shear = [(st, p) for st, p in shear if st == snapshot_step]
        if not shear:
            _note("fig1: no snapshots/atoms.%d.txt" % snapshot_step)
    have_prep = os.path.isfile(prep_path)
    if not have_prep and not shear:
        _note("fig1 skipped: no snapshot files in %s"
              % os.path.join(run.dir, "snapshots"))
        return None
    prep = ga.read_dump_atoms(prep_path) if have_prep else None
    snap = ga.read_dump_atoms(shear[-1][1]) if shear else None
    # vertical stripes of the preparation state, to show the shear deformation
    stripes = {}
    if prep is not None:
        c = prep["columns"]
        if prep["box"] is not None:
            xlo, xhi = prep["box"][0]
        else:
            xlo, xhi = c["x"].min(), c["x"].max()
        band = np.floor((c["x"] - xlo) / max(xhi - xlo, 1e-300) * 8).astype(int) % 2
        stripes = dict(zip(c["id"].astype(np.int64).tolist(), band.tolist()))
    walls = []
    if "zlo" in run.s and "zhi" in run.s:
        walls = [run.s["zlo"][0], run.s["zhi"][0]]
    fig, axes = plt.subplots(1, 2, figsize=(12, 6))
    if prep is not None:
        _side_view(axes[0], prep, stripes, walls,
                   "(a) end of preparation (step %s)" % prep["step"])
    else:
        axes[0].set_axis_off()
        _not_reached(axes[0], "(a) snapshots/atoms.prep.txt not available")
    if snap is not None:
        step = snap["step"] if snap["step"] is not None else shear[-1][0]
        i = int(np.clip(np.searchsorted(run.s["step"], step), 0, len(run.N) - 1))
        n_at = np.interp(step, run.s["step"], run.N)
        _side_view(axes[1], snap, stripes, walls,
                   "(b) cyclic shearing, step %d: N = %.2f, $r_u$ = %.3f, "
                   r"$\gamma$ = %.2f%%" % (step, n_at, run.s["r_u"][i],
                                           100 * run.s["gamma"][i]))
    else:
        axes[1].set_axis_off()
        _not_reached(axes[1], "(b) no shear snapshot available")
    handles = [Patch(color="0.65", label="glued to a wall"),
               Patch(color="tab:orange", label="free, x band A"),
               Patch(color="tab:blue", label="free, x band B (bands: 8 vertical slices "
                     "of the cell at the end of preparation)")]
    fig.suptitle("Fig. 1: particle arrangement, side view (x-z projection), "
                 "gray = glued layers")
    fig.tight_layout()
    fig.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3,
               frameon=False, fontsize=9)
    return _finish(fig, os.path.join(out, "fig1_snapshots.png"), keep, bbox_inches="tight")


# ---------------------------------------------------------------- Fig. 2

def fig2(run, out, keep=False):
    """(a) stress path tau-p, (b) stress-strain tau-gamma."""
    s, k = run.s, run.stride
    tau, p, gam = s["tau"] / 1e3, s["p"] / 1e3, 100 * s["gamma"]
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
    on = run.onset if run.onset is not None else len(tau)
    for ax, x, xlabel in ((axes[0], p, "p (kPa)"), (axes[1], gam, r"$\gamma$ (%)")):
        ax.plot(x[:on + 1:k], tau[:on + 1:k], color=PRE, lw=0.8, label="pre-liquefaction")
        if run.onset is not None:
            ax.plot(x[on::k], tau[on::k], color=POST, lw=0.8, label="post-liquefaction")
        if run.crange is not None:
            sl = run.cycle_slice()
            ax.plot(x[sl], tau[sl], color=CYC, lw=2.0, label="cycle C (N = %d-%d)"
                    % (run.n, run.n + 1))
            _mark_states(ax, run, x, tau)
        for sign in (1, -1):
            ax.axhline(sign * run.tau_amp / 1e3, color="0.3", ls=":", lw=0.8)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(r"$\tau$ (kPa)")
        _limits(ax, x, tau)
        ax.legend(loc="best", fontsize=8)
        if run.onset is None:
            _not_reached(ax, "initial liquefaction ($r_u \\geq$ %g) not reached"
                         % run.ru_liq, 0.1)
        elif run.crange is None:
            _not_reached(ax, "cycle C: " + run.note, 0.1)
    axes[0].set_title("(a) stress path")
    axes[1].set_title("(b) stress-strain curve")
    fig.tight_layout()
    return _finish(fig, os.path.join(out, "fig2_macro.png"), keep)


# ---------------------------------------------------------------- Fig. 3

def fig3(run, out, keep=False):
    """z_g against N coloured by r_u, with N_IL, z_g = 3.6 and an inset on cycle C."""
    s, k, N = run.s, run.stride, run.N
    zg, ru = s["z_g"], s["r_u"]
    fig, ax = plt.subplots(figsize=(10, 6))
    lc = _colored_line(ax, N[::k], zg[::k], ru[::k], RU_CMAP, 0.0, 1.0)
    fig.colorbar(lc, ax=ax, label="$r_u$")
    _limits(ax, N, zg)
    if run.crange is not None:          # room above the data for the inset
        lo, hi = ax.get_ylim()
        ax.set_ylim(lo, hi + 0.75 * (hi - lo))
    ax.axhline(ZG_EXIT, color="k", ls="--", lw=1, label="$z_g$ = 3.6")
    if run.n_il is not None:
        ax.axvline(run.n_il, color="k", ls="--", lw=1, dashes=(6, 3),
                   label="$N_{IL}$ = %.2f" % run.n_il)
    elif run.onset is not None:
        _not_reached(ax, "$N_{IL}$ not known: no cycle event after initial liquefaction", 0.1)
    else:
        _not_reached(ax, "$N_{IL}$ not reached ($r_u$ < %g throughout)" % run.ru_liq, 0.1)
    ax.set_xlabel("N (cycles)")
    ax.set_ylabel("$z_g$")
    ax.set_title("Fig. 3: coordination number of non-floaters")
    if run.crange is not None:
        sl = run.cycle_slice()
        ins = ax.inset_axes([0.55, 0.6, 0.43, 0.33])
        _colored_line(ins, N[sl], zg[sl], ru[sl], RU_CMAP, 0.0, 1.0, lw=1.5)
        _limits(ins, N[sl], zg[sl], pad=0.12)
        ins.set_zorder(5)
        ins.axhline(ZG_EXIT, color="k", ls="--", lw=0.8)
        _mark_states(ins, run, N, zg, size=30)
        ins.set_title("cycle C (N = %d-%d)" % (run.n, run.n + 1), fontsize=9)
        ins.tick_params(labelsize=8)
        ins.set_xlabel("N", fontsize=8)
        ins.set_ylabel("$z_g$", fontsize=8)
        ax.indicate_inset_zoom(ins, edgecolor="0.3")
    elif run.onset is not None:
        _not_reached(ax, "cycle C: " + run.note, 0.9)
    ax.legend(loc="upper left", fontsize=9)
    fig.tight_layout()
    return _finish(fig, os.path.join(out, "fig3_zg.png"), keep)


# ---------------------------------------------------------------- Fig. 4

def fig4(run, out, keep=False):
    """P_c at the six states of cycle C, grouped bars: (a) over all the
    particles of the sub-volume, as the paper's Fig. 4, and (b) over the
    particles with at least one contact (P_c / (1 - P_0)), where the
    paper's reading ("a high proportion of particles with c < 4" at the
    liquefied states) can be seen when floaters dominate (a)."""
    fig, axes = plt.subplots(1, 2, figsize=(15, 5.5))
    c = np.arange(13)
    width = 0.13
    found = 0
    for k, ax in enumerate(axes):
        if run.states is None:
            continue
        for j, st in enumerate(ga.STATES):
            r = run.states[st]
            x = c + (j - 2.5) * width
            if r is None:
                ax.bar([], [], color=COLOR[st], label=LABEL[st] + " (not found)")
                continue
            pc = (ga.connectivity(run.s, r) if k == 0
                  else ga.connectivity_non_floaters(run.s, r))
            ax.bar(x, pc, width, color=COLOR[st], edgecolor="k", linewidth=0.3,
                   label="%s: N = %.3f, $z_g$ = %.2f, $r_u$ = %.3f, $P_0$ = %.2f"
                   % (LABEL[st], run.N[r], run.s["z_g"][r], run.s["r_u"][r],
                      ga.connectivity(run.s, r)[0]))
            found += k == 0
    for k, ax in enumerate(axes):
        ax.set_xticks(c)
        ax.set_xticklabels([str(i) for i in c[:-1]] + [r"$\geq$12"])
        ax.set_xlabel("number of contacts c")
        ax.set_ylabel("$P_c$ (fraction of all particles)" if k == 0
                      else "$P_c / (1 - P_0)$ (fraction of particles with contacts)")
        if run.n is None:
            ax.set_title("Fig. 4: connectivity in cycle C")
            ax.set_ylim(0, 1)
            _not_reached(ax, "cycle C not found: " + run.note)
            continue
        ax.set_title(("(a) all particles" if k == 0 else "(b) particles with contacts")
                     + ", cycle C (N = %d-%d)" % (run.n, run.n + 1))
        ax.set_ylim(bottom=0)
        ax.legend(fontsize=7, loc="upper right")
        if found < len(ga.STATES):
            _not_reached(ax, "%d of 6 states not found in this cycle"
                         % (len(ga.STATES) - found), 0.55)
    fig.tight_layout()
    return _finish(fig, os.path.join(out, "fig4_pc.png"), keep)


# ---------------------------------------------------------------- Fig. 5

def fig5(run, out, keep=False):
    """a_c against z_g over the whole run, cycle C highlighted."""
    s, k, N = run.s, run.stride, run.N
    zg, ac = s["z_g"], s["a_c"]
    fig, ax = plt.subplots(figsize=(9, 6))
    lc = _colored_line(ax, zg[::k], ac[::k], N[::k], "viridis",
                       0.0, max(float(np.nanmax(N)), 1e-9), lw=0.7)
    fig.colorbar(lc, ax=ax, label="N (cycles)")
    _limits(ax, zg, ac)
    ax.axvline(ZG_EXIT, color="k", ls="--", lw=1, label="$z_g$ = 3.6")
    if run.crange is not None:
        sl = run.cycle_slice()
        ax.plot(zg[sl], ac[sl], color=CYC, lw=2.0,
                label="cycle C (N = %d-%d)" % (run.n, run.n + 1))
        _mark_states(ax, run, zg, ac)
    else:
        _not_reached(ax, "cycle C not found: " + run.note, 0.9)
    ax.set_xlabel("$z_g$")
    ax.set_ylabel("$a_c$")
    ax.set_title("Fig. 5: fabric anisotropy against coordination number")
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    return _finish(fig, os.path.join(out, "fig5_ac_zg.png"), keep)


# ---------------------------------------------------------------- main

def _json_safe(v):
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, dict):
        return {k: _json_safe(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_json_safe(x) for x in v]
    if isinstance(v, np.generic):
        return _json_safe(v.item())
    return v


def _ms_list(text):
    """A comma-separated list of positive intervals in ms (argparse type)."""
    try:
        vals = [float(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError("%r: not a list of numbers" % text)
    if not vals or not all(math.isfinite(v) and v > 0.0 for v in vals):
        raise argparse.ArgumentTypeError("%r: intervals must be positive numbers (ms)" % text)
    return tuple(vals)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir", help="run directory (prep.json, series.txt, snapshots/)")
    ap.add_argument("--out", help="output directory (default RUN_DIR/figures)")
    ap.add_argument("--cycle", type=int, default=None, metavar="K",
                    help="cycle C = the K-th post-liquefaction cycle (0-based); default: "
                    "the first one with all six states")
    ap.add_argument("--snapshot", type=int, default=None, metavar="STEP",
                    help="shear snapshot of Fig. 1 (default: the last one)")
    opt = ap.add_argument_group(
        "sampling and definitions (issue 30; added to the summary beside the present "
        "definitions, which stay as they are)")
    opt.add_argument("--sample-ms", type=_ms_list, default=(), metavar="MS[,MS...]",
                     help="recompute exits, inflections, minima of z_g and I from the "
                     "series decimated to these output intervals (ms of simulated time; "
                     "the row nearest to each multiple)")
    opt.add_argument("--knee", action="store_true",
                     help="the knee of each exit's fitted logistic (lower asymptote + 10%% "
                     "of the jump), beside its inflection")
    opt.add_argument("--block-ms", type=_ms_list, default=(), metavar="MS[,MS...]",
                     help="I from p averaged over blocks of these durations (ms); a block "
                     "with mean p <= 0 has no I and is counted")
    opt.add_argument("--zg-percentile", type=float, default=None, metavar="Q",
                     help="the Q-th percentile of z_g after initial liquefaction, beside "
                     "its minimum (e.g. 5)")
    opt.add_argument("--overlaps", action="store_true",
                     help="z_g counting all overlaps (f_n <= 0 too) from the contact "
                     "snapshots at C0, C1, C2, C3 of cycle C")
    args = ap.parse_args(argv)
    if args.zg_percentile is not None and not 0.0 <= args.zg_percentile <= 100.0:
        ap.error("--zg-percentile %g: not in [0, 100]" % args.zg_percentile)

    run_dir = args.run_dir
    if not os.path.isdir(run_dir):
        print("error: run directory %s does not exist" % run_dir, file=sys.stderr)
        return 2
    series_path = os.path.join(run_dir, "series.txt")
    if not os.path.isfile(series_path):
        print("error: %s does not exist" % series_path, file=sys.stderr)
        return 2
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            series = ga.read_series(series_path)
        except (ga.FormatError, OSError) as err:
            print("error: malformed series: %s" % err, file=sys.stderr)
            return 2
    for w in caught:
        _note(str(w.message))
    try:
        events = ga.run_events(run_dir, series)
    except (ga.FormatError, OSError) as err:
        print("error: %s" % err, file=sys.stderr)
        return 2
    prep = None
    prep_path = os.path.join(run_dir, "prep.json")
    try:
        prep = ga.read_prep(prep_path)
    except (OSError, ga.FormatError) as err:
        _note("prep.json unusable (%s); ru_liq = %g and tau_amp = %g Pa assumed, "
              "preparation values not available" % (err, ga.DEFAULT_RU_LIQ,
                                                     ga.DEFAULT_TAU_AMP))
    try:
        shear = ga.read_shear_record(run_dir)
    except (OSError, ga.FormatError) as err:
        print("error: shear.json unusable: %s" % err, file=sys.stderr)
        return 2
    out = args.out or os.path.join(run_dir, "figures")
    os.makedirs(out, exist_ok=True)

    run = Run(run_dir, series, prep, events, args.cycle, shear)
    summ = ga.summary(series, prep, run.events, args.cycle, sample_ms=args.sample_ms,
                      knee=args.knee, block_ms=args.block_ms, percentile=args.zg_percentile,
                      overlaps=args.overlaps, run_dir=run_dir, shear=shear)
    # the run as named from the folder the command ran in (a summary kept in
    # a repository names no path of the machine it was made on); absolute
    # when the run lies outside that folder
    rel = os.path.relpath(os.path.abspath(run_dir))
    summ["run_dir"] = os.path.abspath(run_dir) if rel.startswith("..") else rel
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(_json_safe(summ), f, indent=1, allow_nan=False)
        f.write("\n")
    md = ga.summary_markdown(summ)
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("# GRFLOW run %s: measured against the paper\n\n" % summ["run_dir"])
        f.write(md)
    print(md)

    failed = False
    jobs = (("fig1", lambda: fig1(run, out, args.snapshot)), ("fig2", lambda: fig2(run, out)),
            ("fig3", lambda: fig3(run, out)), ("fig4", lambda: fig4(run, out)),
            ("fig5", lambda: fig5(run, out)))
    for name, job in jobs:
        try:
            path = job()
            if path:
                print("wrote %s" % path)
        except Exception:       # one figure failing must not lose the others
            failed = True
            plt.close("all")
            print("error: %s failed:\n%s" % (name, traceback.format_exc()), file=sys.stderr)
    print("wrote %s, %s" % (os.path.join(out, "summary.json"),
                            os.path.join(out, "summary.md")))
    return 1 if failed else 0


if __name__ == "__main__":     # python -m grflow_analysis.figures
    sys.exit(main())
