# GRFLOW analysis: a study of shear-stage settings over seeds.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""A study of shear-stage settings over seeds (workflows/physics_study.smk).

    grflow-study OUT --settings NAME [NAME ...] --seeds S [S ...]

OUT/seed<S>/<NAME>/ is the run of setting NAME from seed S's preparation
(series.txt, events.txt, prep.json, run.json).  For every run the
summary of grflow_analysis gives the quantities of QUANTITIES (the knee
and the 5th percentile of z_g as grflow-figures --knee --zg-percentile 5
gives them), and :func:`flickers` counts the exits that are flickers.
Per setting: the mean and the sample standard deviation over the seeds
(n - 1 in the denominator), and, against the first setting (the
baseline), the mean and standard deviation of the seed-by-seed
difference (setting minus baseline, over the seeds that have both): the
preparation is the same, so the difference is the setting's effect plus
the scatter of the shear stage alone.  A quantity a run did not reach
(no liquefaction, no exit) is left out of that setting's statistics
(a run-out's N_IL cell says "> N (run-out)", N its max_cycles),
and the table gives how many runs it has.  Writes OUT/study.json (every
run and every statistic) and OUT/study.md.  Exit status 2 if a run
directory or one of its files is missing; with --partial a run that is
not done (no run.json: a study in progress) is "not run" instead and left
out (a setting with no finished run is still an error).

    grflow-study OUT --settings ... --seeds ... --rate-settings NAME NAME [...]

adds the quasi-static limit: the named settings differ in -var shear_rate
only (an error otherwise); for each seed and quantity a straight line in
the shear rate through the settings' values (least squares; through both
points when there are two rates) is taken to rate 0, and the table gives
each seed's value at rate 0, their mean +- sample sd over the seeds, and
the mean slope.
"""
import argparse
import json
import math
import os
import sys

import numpy as np

import grflow_analysis as ga

# (key, heading, how it is made) -- the summary's entries, or this module's
QUANTITIES = [
    ("N_IL", "N_IL", "cycles to initial liquefaction (fix grflow/shear's)"),
    ("n_exits", "exits", "number of exits (r_u falls below ru_liq after initial liquefaction)"),
    ("n_flickers", "flickers", "exits whose sample is back at r_u >= ru_liq before the next "
     "reversal (flickers)"),
    ("z_g_exit_mean", "z_g at exits", "mean z_g at the exits of the run"),
    ("z_g_inflection_mean", "z_g at inflection",
     "mean z_g at the inflection of the logistic fitted to z_g(N) around each exit"),
    ("z_g_knee_mean", "z_g at knee", "mean z_g at the knee of the same logistic"),
    ("z_g_post_IL_min", "smallest z_g", "smallest z_g after initial liquefaction"),
    ("z_g_post_IL_p5", "z_g 5th pct", "5th percentile of z_g after initial liquefaction"),
    ("z_g_post_IL_max", "largest z_g", "largest z_g after initial liquefaction"),
    ("inertial_median_post_IL", "median I", "median inertial number after initial "
     "liquefaction (rows with p > 0)"),
    ("inertial_max", "largest I", "largest inertial number (rows with p > 0)"),
    ("p_min_post_IL", "smallest p (Pa)", "smallest p after initial liquefaction"),
]
PERCENTILE = 5.0


def flickers(series, events, ru_liq):
    """The exits after which the sample is back at r_u >= ru_liq before the
    fix's next reversal (the reversals column does not change between the
    exit row and the next entry row): the stress never built up to
    tau_amp, so the exit is a flicker of r_u about ru_liq, not a recovery
    of the sample.  Returns (number of exits, number of flickers)."""
    liq = ga.liquefaction(series, events, ru_liq)
    rev = series["reversals"]
    entries = np.asarray(liq["entries"], dtype=int)
    n = 0
    for e in liq["exits"]:
        later = entries[entries > e]
        if later.size and rev[later[0]] == rev[e]:
            n += 1
    return len(liq["exits"]), n


def run_values(run_dir):
    """The QUANTITIES of one run (floats; None where not reached)."""
    for name in ("series.txt", "events.txt", "prep.json", "run.json"):
        if not os.path.exists(os.path.join(run_dir, name)):
            raise FileNotFoundError("%s: no %s" % (run_dir, name))
    series = ga.read_series(os.path.join(run_dir, "series.txt"))
    prep = ga.read_prep(os.path.join(run_dir, "prep.json"))
    events = ga.run_events(run_dir, series)
    shear = ga.read_shear_record(run_dir)
    summ = ga.summary(series, prep, events, knee=True, percentile=PERCENTILE, shear=shear)
    entries = {e["name"]: e["measured"] for e in summ["entries"]}
    for e in summ["definitions"]["entries"]:
        entries[e["name"]] = e["measured"]
    ru_liq, _ = ga.protocol(prep, shear)
    entries["n_exits"], entries["n_flickers"] = flickers(series, events, ru_liq)
    if not isinstance(entries["N_IL"], float):
        entries["n_exits"] = entries["n_flickers"] = None
    out = {}
    for key, _, _ in QUANTITIES:
        v = entries.get(key)
        out[key] = float(v) if isinstance(v, (int, float)) and math.isfinite(v) else None
    with open(os.path.join(run_dir, "run.json")) as f:
        meta = json.load(f)
    out["e"] = float(prep["e"]) if ga._is_number(prep.get("e")) else None
    out["z_g_prep"] = float(prep["z_g"]) if ga._is_number(prep.get("z_g")) else None
    out["N_end"] = float(summ["N_end"]) if ga._is_number(summ.get("N_end")) else None
    out["shear_vars"] = meta.get("shear_vars")
    # a run-out (no liquefaction): N_IL is only known to exceed the cycles
    # it ran, max_cycles of the workflow (run.json), else the series' last N
    out["N_IL_above"] = None if out["N_IL"] is not None else \
        float(meta.get("max_cycles", out["N_end"]))
    return out


def stats(values):
    """(mean, sample sd or None, n) of the values that are not None."""
    v = [x for x in values if x is not None]
    if not v:
        return None, None, 0
    return (float(np.mean(v)), float(np.std(v, ddof=1)) if len(v) > 1 else None, len(v))


def not_run():
    """The values of a run that is not done (no run.json): every quantity
    None, marked so that the table says "not run"."""
    out = {k: None for k, _, _ in QUANTITIES}
    out.update({"e": None, "z_g_prep": None, "N_end": None, "shear_vars": None,
                "N_IL_above": None, "not_run": True})
    return out


def study(out, settings, seeds, partial=False):
    """``partial``: a run without run.json (not done yet) is "not run" and
    left out of the statistics, instead of an error."""
    def values(seed, s):
        d = os.path.join(out, "seed%d" % seed, s)
        if partial and not os.path.exists(os.path.join(d, "run.json")):
            return not_run()
        return run_values(d)
    runs = {s: {seed: values(seed, s) for seed in seeds} for s in settings}
    for s in settings:
        if all(runs[s][seed].get("not_run") for seed in seeds):
            raise FileNotFoundError("%s: no seed has a finished run (run.json)" % s)
    base = settings[0]
    table = {}
    for s in settings:
        row = {}
        for key, _, _ in QUANTITIES + [("e", "", ""), ("z_g_prep", "", "")]:
            mean, sd, n = stats([runs[s][seed][key] for seed in seeds])
            diffs = [runs[s][seed][key] - runs[base][seed][key] for seed in seeds
                     if runs[s][seed][key] is not None and runs[base][seed][key] is not None]
            dmean, dsd, dn = stats(diffs)
            row[key] = {"mean": mean, "sd": sd, "n": n, "diff_mean": dmean, "diff_sd": dsd,
                        "diff_n": dn}
        table[s] = row
    return {"out": out, "settings": settings, "baseline": base, "seeds": seeds,
            "shear_vars": {s: next(runs[s][seed]["shear_vars"] for seed in seeds
                                   if not runs[s][seed].get("not_run")) for s in settings},
            "runs": {s: {str(k): v for k, v in r.items()} for s, r in runs.items()},
            "table": table,
            "quantities": [{"key": k, "heading": h, "how": w} for k, h, w in QUANTITIES]}


def shear_rates(d, names):
    """{setting: its shear rate} for settings whose shear-stage -var pairs
    differ in shear_rate only; ValueError names the first that does not."""
    rates, rest = {}, {}
    for s in names:
        if s not in d["settings"]:
            raise ValueError("--rate-settings: %s is not one of --settings" % s)
        words = (d["shear_vars"][s] or "").split()
        pairs = dict(zip(words[0::2], words[1::2]))
        try:
            rates[s] = float(pairs.pop("shear_rate"))
        except (KeyError, ValueError):
            raise ValueError("--rate-settings: %s has no numeric shear_rate in its -var pairs "
                             "(%r)" % (s, d["shear_vars"][s])) from None
        rest[s] = pairs
    first = names[0]
    for s in names[1:]:
        if rest[s] != rest[first]:
            raise ValueError("--rate-settings: %s and %s differ in more than shear_rate "
                             "(%r, %r)" % (s, first, d["shear_vars"][s], d["shear_vars"][first]))
    if len(set(rates.values())) < 2:
        raise ValueError("--rate-settings: need two or more different shear rates, got %s"
                         % sorted(set(rates.values())))
    return rates


def line_to_zero(rates, values):
    """(value at rate 0, slope) of the least-squares line through the points
    (rate, value) that have a value, or (None, None) with fewer than two
    different rates."""
    pts = [(r, v) for r, v in zip(rates, values) if v is not None]
    if len(set(r for r, _ in pts)) < 2:
        return None, None
    slope, at0 = np.polyfit([r for r, _ in pts], [v for _, v in pts], 1)
    return float(at0), float(slope)


def quasistatic(d, names):
    """The quasi-static limit of every quantity over the settings NAMES
    (shear_rates): per seed the value at rate 0 and the slope; over the
    seeds the mean +- sd of the value at rate 0 and the mean slope."""
    rates = shear_rates(d, names)
    out = {"settings": names, "rates": [rates[s] for s in names], "table": {}}
    for key, _, _ in QUANTITIES:
        per = {}
        for seed in d["seeds"]:
            vals = [d["runs"][s][str(seed)][key] for s in names]
            per[str(seed)] = dict(zip(("at0", "slope"), line_to_zero(out["rates"], vals)))
        mean, sd, n = stats([per[str(seed)]["at0"] for seed in d["seeds"]])
        slope, _, _ = stats([per[str(seed)]["slope"] for seed in d["seeds"]])
        out["table"][key] = {"seeds": per, "mean": mean, "sd": sd, "n": n, "slope_mean": slope}
    return out


def _num(x, digits=3):
    if x is None:
        return "-"
    if float(x).is_integer() and abs(x) < 1e4:
        return "%d" % x
    if x != 0 and (abs(x) < 1e-2 or abs(x) >= 1e4):
        return "%.*e" % (digits - 1, x)
    return "%.*g" % (digits + 1, x) if abs(x) >= 1 else "%.*f" % (digits, x)


def _cell(mean, sd, n):
    if mean is None:
        return "- (0)"
    return "%s +- %s (%d)" % (_num(mean), _num(sd), n) if sd is not None else \
        "%s (%d)" % (_num(mean), n)


def markdown(d):
    lines = ["# Study: %s" % d["out"], "",
             "Seeds %s; baseline `%s`.  Each cell: mean +- sample sd over the seeds (runs "
             "counted); below it, the seed-by-seed difference from the baseline, "
             "mean +- sd (pairs counted)." % (", ".join(str(s) for s in d["seeds"]),
                                               d["baseline"]), "",
             "| setting | shear-stage -var | e | z_g after preparation |",
             "| --- | --- | --- | --- |"]
    for s in d["settings"]:
        t = d["table"][s]
        lines.append("| %s | `%s` | %s | %s |" % (s, d["shear_vars"][s] or "",
                                                  _cell(t["e"]["mean"], t["e"]["sd"], t["e"]["n"]),
                                                  _cell(t["z_g_prep"]["mean"], t["z_g_prep"]["sd"],
                                                        t["z_g_prep"]["n"])))
    for q in d["quantities"]:
        k = q["key"]
        lines += ["", "## %s" % q["heading"], "", q["how"] + ".", "",
                  "| setting | " + " | ".join("seed %d" % s for s in d["seeds"]) +
                  " | mean +- sd (n) | minus baseline |",
                  "| --- |" + " --- |" * (len(d["seeds"]) + 2)]
        for s in d["settings"]:
            t = d["table"][s][k]
            per = ["not run" if d["runs"][s][str(seed)].get("not_run") else
                   _num(d["runs"][s][str(seed)][k]) for seed in d["seeds"]]
            if k == "N_IL":
                per = ["> %s (run-out)" % _num(r["N_IL_above"]) if r.get("N_IL_above")
                       is not None else v for r, v in
                       zip((d["runs"][s][str(seed)] for seed in d["seeds"]), per)]
            diff = "-" if s == d["baseline"] else _cell(t["diff_mean"], t["diff_sd"],
                                                        t["diff_n"])
            lines.append("| %s | %s | %s | %s |" % (s, " | ".join(per),
                                                     _cell(t["mean"], t["sd"], t["n"]), diff))
    q = d.get("quasistatic")
    if q:
        lines += ["", "## Quasi-static limit", "",
                  "Settings %s at shear rates %s 1/s: per seed, the least-squares straight "
                  "line in the shear rate through the settings' values, taken to rate 0 "
                  "(through both points when there are two rates); then the mean +- sample "
                  "sd of the seeds' values at rate 0, and the mean slope (per 1/s)."
                  % (", ".join(q["settings"]), ", ".join(_num(r) for r in q["rates"])), "",
                  "| quantity | " + " | ".join("seed %d at 0" % s for s in d["seeds"]) +
                  " | mean +- sd (n) | mean slope |",
                  "| --- |" + " --- |" * (len(d["seeds"]) + 2)]
        for key, heading, _ in QUANTITIES:
            t = q["table"][key]
            lines.append("| %s | %s | %s | %s |" % (
                heading, " | ".join(_num(t["seeds"][str(seed)]["at0"]) for seed in d["seeds"]),
                _cell(t["mean"], t["sd"], t["n"]), _num(t["slope_mean"])))
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(prog="grflow-study", description=__doc__.split("\n\n")[0])
    ap.add_argument("out", help="study directory (OUT/seed<S>/<NAME>/ are the runs)")
    ap.add_argument("--settings", nargs="+", required=True,
                    help="setting names, the baseline first")
    ap.add_argument("--seeds", nargs="+", type=int, required=True)
    ap.add_argument("--partial", action="store_true",
                    help="a run without run.json (not done yet) is 'not run' and left out, "
                    "instead of an error")
    ap.add_argument("--rate-settings", nargs="+", metavar="NAME",
                    help="settings that differ in shear_rate only: add their quasi-static "
                    "limit (straight line in the rate, taken to 0)")
    args = ap.parse_args(argv)
    try:
        d = study(args.out, args.settings, args.seeds, partial=args.partial)
        if args.rate_settings:
            d["quasistatic"] = quasistatic(d, args.rate_settings)
    except (FileNotFoundError, ValueError) as e:
        print("grflow-study: %s" % e, file=sys.stderr)
        return 2
    with open(os.path.join(args.out, "study.json"), "w") as f:
        json.dump(d, f, indent=1)
    md = markdown(d)
    with open(os.path.join(args.out, "study.md"), "w") as f:
        f.write(md)
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
