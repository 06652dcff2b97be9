# GRFLOW analysis: the cyclic resistance curve of a campaign.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""The cyclic resistance curve of a campaign: CSR = tau_amp / p0 against
the number of cycles to initial liquefaction N_IL.

    grflow-curve OUT RUN_DIR [RUN_DIR ...]

Each RUN_DIR is a shear run (series.txt, events.txt, prep.json, and
run.json from workflows/resistance_curve.smk).  N_IL is fix
grflow/shear's, read from events.txt by the summary of grflow_analysis:
linear in time between the events around the first check with
r_u >= ru_liq (doc/fix_grflow_shear.rst); a run that did not liquefy is
a run-out at the cycle count it reached.  Writes OUT/curve.json,
OUT/curve.md and OUT/curve.png.

The fit: CSR = a N_IL^(-b), by least squares of log CSR on log N_IL over
the liquefied runs, with the standard errors of a and b from the
regression (a is reported with the interval exp(log a +- se)).  Run-outs
are drawn, not fitted.  Fewer than 3 liquefied runs with at least 2
distinct CSR values: no fit (said so in the outputs).
"""
import json
import math
import os
import sys

import numpy as np

import grflow_analysis as ga


def run_result(run_dir):
    """One run of the campaign as a dict (csr, seed, tau_amp, p0 from the
    series' first row, N_IL or None, N_end, liquefied, ...)."""
    with open(os.path.join(run_dir, "run.json")) as f:
        meta = json.load(f)
    series = ga.read_series(os.path.join(run_dir, "series.txt"))
    prep = ga.read_prep(os.path.join(run_dir, "prep.json"))
    summ = ga.summary(series, prep, ga.run_events(run_dir, series),
                      shear=ga.read_shear_record(run_dir))
    entries = {e["name"]: e["measured"] for e in summ["entries"]}
    n_il = entries["N_IL"]
    liquefied = isinstance(n_il, float)
    p0 = float(series["p"][0])
    return {
        "run": os.path.relpath(run_dir),
        "seed": meta["seed"],
        "csr": meta["csr"],
        "tau_amp": meta["tau_amp"],
        "p_target": meta["p_target"],
        "p0": p0,
        "csr_measured": meta["tau_amp"] / p0 if p0 > 0 else None,
        "e": prep.get("e"),
        "liquefied": liquefied,
        "N_IL": n_il if liquefied else None,
        "N_end": float(summ["N_end"]),
        "max_cycles": meta.get("max_cycles"),
        "steps": int(summ["last_step"]),
    }


def fit_power_law(csr, n_il):
    """CSR = a N^(-b) by least squares of log CSR on log N.
    Returns dict a, b, se_log_a, se_b, a_range, n, r2; None if fewer than 3
    points or fewer than 2 distinct N."""
    csr = np.asarray(csr, float)
    n = np.asarray(n_il, float)
    if len(n) < 3 or len(np.unique(n)) < 2:
        return None
    x, y = np.log(n), np.log(csr)
    A = np.vstack([np.ones_like(x), x]).T
    coef, res, _, _ = np.linalg.lstsq(A, y, rcond=None)
    resid = y - A @ coef
    dof = len(x) - 2
    s2 = float(resid @ resid) / dof if dof > 0 else float("nan")
    cov = s2 * np.linalg.inv(A.T @ A)
    log_a, slope = float(coef[0]), float(coef[1])
    se_log_a, se_b = float(math.sqrt(cov[0, 0])), float(math.sqrt(cov[1, 1]))
    ss_tot = float(((y - y.mean()) ** 2).sum())
    return {"a": math.exp(log_a), "b": -slope, "se_log_a": se_log_a, "se_b": se_b,
            "a_range": [math.exp(log_a - se_log_a), math.exp(log_a + se_log_a)],
            "n": int(len(x)), "r2": 1.0 - float(resid @ resid) / ss_tot if ss_tot > 0 else None}


def campaign(runs):
    liq = [r for r in runs if r["liquefied"]]
    fit = fit_power_law([r["csr"] for r in liq], [r["N_IL"] for r in liq])
    if fit is not None and len({r["csr"] for r in liq}) < 2:
        fit = None
    return {"runs": runs, "fit": fit,
            "fit_note": ("least squares of log CSR on log N_IL over the liquefied runs; "
                         "run-outs not fitted; se: standard errors of the regression"
                         if fit else "no fit: needs 3 liquefied runs at 2 or more CSR values")}


def markdown(c):
    lines = ["| seed | CSR (tau_amp/p_target) | tau_amp (kPa) | p0 (kPa) | tau_amp/p0 | e | N_IL | "
             "cycles run | steps |", "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in sorted(c["runs"], key=lambda r: (-r["csr"], r["seed"])):
        nil = "%.2f" % r["N_IL"] if r["liquefied"] else "run-out (> %.1f)" % r["N_end"]
        lines.append("| %s | %.3g | %.4g | %.4g | %.3f | %s | %s | %.2f | %d |" % (
            r["seed"], r["csr"], r["tau_amp"] / 1e3, r["p0"] / 1e3,
            r["csr_measured"] if r["csr_measured"] else float("nan"),
            "%.4f" % r["e"] if isinstance(r["e"], (int, float)) else "-", nil, r["N_end"],
            r["steps"]))
    f = c["fit"]
    lines.append("")
    if f:
        lines.append("Fit CSR = a N_IL^(-b): a = %.4g (%.4g to %.4g), b = %.4g +- %.2g, "
                     "%d runs, r^2 = %.3f (%s)." % (f["a"], f["a_range"][0], f["a_range"][1],
                                                    f["b"], f["se_b"], f["n"], f["r2"],
                                                    c["fit_note"]))
    else:
        lines.append(c["fit_note"] + ".")
    return "\n".join(lines) + "\n"


def figure(c, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    seeds = sorted({r["seed"] for r in c["runs"]}, key=str)
    markers = "osD^v<>ph*"
    for k, s in enumerate(seeds):
        rs = [r for r in c["runs"] if r["seed"] == s]
        liq = [r for r in rs if r["liquefied"]]
        out = [r for r in rs if not r["liquefied"]]
        m = markers[k % len(markers)]
        ax.plot([r["N_IL"] for r in liq], [r["csr"] for r in liq], m, ls="none",
                color="C%d" % k, label="seed %s" % s)
        for r in out:
            ax.plot(r["N_end"], r["csr"], m, mfc="none", color="C%d" % k)
            ax.annotate("", xy=(r["N_end"] * 1.6, r["csr"]), xytext=(r["N_end"], r["csr"]),
                        arrowprops=dict(arrowstyle="->", color="C%d" % k))
    f = c["fit"]
    if f:
        ns = [r["N_IL"] for r in c["runs"] if r["liquefied"]]
        x = np.geomspace(min(ns) / 1.5, max(ns) * 1.5, 50)
        ax.plot(x, f["a"] * x ** (-f["b"]), "k-", lw=1,
                label="CSR = %.3g N$^{-%.3g \\pm %.2g}$" % (f["a"], f["b"], f["se_b"]))
    ax.set_xscale("log")
    ax.set_xlabel("cycles to initial liquefaction N$_{IL}$ (open: run-out)")
    ax.set_ylabel("CSR = tau_amp / p_target")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) < 2:
        print(__doc__)
        return 2
    out, dirs = argv[0], argv[1:]
    try:
        runs = [run_result(d) for d in dirs]
    except (OSError, ValueError, KeyError) as err:   # ga.FormatError is a ValueError
        print("error: %s" % err, file=sys.stderr)
        return 2
    os.makedirs(out, exist_ok=True)
    c = campaign(runs)
    with open(os.path.join(out, "curve.json"), "w") as f:
        json.dump(c, f, indent=1)
    with open(os.path.join(out, "curve.md"), "w") as f:
        f.write(markdown(c))
    figure(c, os.path.join(out, "curve.png"))
    print(markdown(c), end="")
    return 0


if __name__ == "__main__":     # python -m grflow_analysis.curve
    sys.exit(main())
