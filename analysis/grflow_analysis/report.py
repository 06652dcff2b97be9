# GRFLOW analysis: the paper's values and the summary of a run beside them.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""The summary of a run: its measured values beside the paper's (PAPER),
as a JSON-ready dict (:func:`summary`) and a markdown table
(:func:`summary_markdown`).
"""

import math

import numpy as np

from .cycles import STATES, choose_cycle, cycle_count, liquefaction, liquefaction_n
from .metrics import (INFLECTION_HALF_WINDOW_N, NOT_AVAILABLE, NOT_REACHED, connectivity,
                      connectivity_non_floaters, inertial_stats, peak_ac_per_cycle,
                      static_redundancy, zg_inflections)
from .readers import _is_number, protocol, stage_values

# The paper's values (paper/isochoric-cyclic-shearing.md) and how a
# measured value is compared with them.  comparison "abs": |measured -
# paper| <= tolerance, for the protocol's inputs (tolerance 0); "max":
# measured <= paper, for the paper's bounds; "diff": the paper gives the
# number without a tolerance, so there is no match, only the difference
# measured - paper (of each element, for a list).  paper None: the paper
# gives no number.
PAPER = {
    "N_particles": (8000, 0, "abs",
                    "Sec. 2 / Fig. 1: 'a sample composed of 8000 particles'"),
    "e_prep": (0.647, None, "diff",
               "Sec. 2: 'an isotropically compressed sample of 8000 spheres with void "
               "ratio e = 0.647 (medium dense) under a mean pressure of 100 kPa'"),
    "p_prep": (100.0e3, None, "diff",
               "Sec. 2: '... under a mean pressure of 100 kPa'; Sec. 3: 'moves "
               "cyclically leftward from p = 100 kPa'"),
    "z_g_prep": (4.76, None, "diff",
                 "Sec. 4: 'z_g decreases from its initial value z_g ~ 4.76'"),
    "tau_amp": (25.0e3, 0.0, "abs", "Sec. 3: 'with tau^amp = 25 kPa'"),
    "N_IL": (None, None, None, "Sec. 3 defines N_IL; no value is given"),
    "z_g_at_IL": (4.0, 0.0, "max",
                  "Sec. 4: z_g 'drops below 4.0 when the system approaches initial "
                  "liquefaction'"),
    "z_g_post_IL_max": (4.0, 0.0, "max",
                        "Sec. 4: 'In the post-liquefaction period, z_g stays below 4.0'"),
    "nonliq_zg_at_least_3.6": (None, None, None,
                               "Sec. 4 (Fig. 5): 'The non-liquefaction states belong to the "
                               "region of z_g >= 3.6'; no fraction given"),
    "liq_zg_max": (None, None, None,
                   "Sec. 4: the liquefied states lie below z_g = 3.6 by the same reading; "
                   "no number given"),
    "a_c_change_C0_C0p": (None, None, None,
                          "Sec. 4: from C0 to C0' z_g and a_c 'vary significantly' "
                          "(anisotropic gain of contacts); no number given"),
    "a_c_change_C0p_C1": (None, None, None,
                          "Sec. 4: between C0' and C1 'a_c is nearly constant' (isotropic "
                          "gain of contacts); no number given"),
    "a_c_change_C1_C2": (None, None, None,
                         "Sec. 4: between C1 and C2 'a_c is nearly constant' (isotropic "
                         "loss of contacts); no number given"),
    "z_g_post_IL_min": (1.5, None, "diff",
                        "Sec. 4: z_g 'fluctuates significantly down to values as low "
                        "as 1.5'"),
    "z_g_inflections": (3.6, None, "diff",
                        "Sec. 4: 'The horizontal dashed line for z_g = 3.6 corresponds to "
                        "the inflection point of z_g as a function of N, coinciding with the "
                        "exit of liquefaction state (C0' and C2')'"),
    "z_g_inflection_mean": (3.6, None, "diff", "as z_g_inflections"),
    "static_redundancy_post_IL_max": (0.0, 0.0, "max",
                                      "Sec. 4: after initial liquefaction z_g 'stays below "
                                      "4.0 and fluctuates ... with a negative static "
                                      "redundancy'"),
    "n_exits": (None, None, None, "no number given"),
    "z_g_at_exits": (3.6, None, "diff",
                     "Sec. 4: 'z_g = 3.6 ... coinciding with the exit of liquefaction "
                     "state (C0' and C2')'; Sec. 5: 'exiting the liquefaction state at "
                     "the coordination number of 3.6'"),
    "z_g_exit_mean": (3.6, None, "diff", "as z_g_at_exits"),
    "z_g_exit_std": (None, None, None, "no number given"),
    "inertial_max": (0.025, 0.0, "max",
                     "Sec. 2: 'Even in the liquefaction state, I does not increase "
                     "beyond 0.025'"),
    "inertial_max_pre_IL": (1e-3, 0.0, "max",
                            "Sec. 2: 'The shear is nearly quasistatic if I < 10^-3' and "
                            "'nearly quasistatic in the non-liquefaction states'"),
    "inertial_median_post_IL": (None, None, None, "no number given"),
    "inertial_undefined_rows": (None, None, None,
                                "no number given (the paper's I <= 0.025 implies p > 0)"),
    "p_min_post_IL": (None, None, None,
                      "no number given (I <= 0.025 at v_x = 0.01 m/s implies p above "
                      "about 1 Pa)"),
    "a_c_peak_per_cycle": (None, None, None,
                           "Sec. 4: the maximum of a_c 'increases gradually with N'; "
                           "no number given"),
}


def _match(measured, paper, tol, comparison):
    if isinstance(measured, str):
        return False
    if paper is None or measured is None or comparison == "diff":
        return None
    if comparison == "each":
        return bool(len(measured) > 0 and all(abs(m - paper) <= tol + 1e-12 for m in measured))
    if comparison == "max":
        return bool(measured <= paper)
    return bool(abs(measured - paper) <= tol + 1e-12 * max(1.0, abs(paper)))


def _difference(measured, paper):
    """measured - paper (a list for a list), None where either is no number"""
    if paper is None or isinstance(measured, str) or measured is None:
        return None
    if isinstance(measured, (list, tuple, np.ndarray)):
        return [float(m) - paper for m in measured]
    return float(measured) - paper


def _entry(name, description, unit, measured):
    paper, tol, comparison, source = PAPER[name]
    return {"name": name, "description": description, "unit": unit,
            "measured": measured, "paper": paper, "tolerance": tol,
            "comparison": comparison, "match": _match(measured, paper, tol, comparison),
            "difference": _difference(measured, paper), "paper_source": source}


def tolerance_cell(e):
    """The tolerance column of a summary table for entry e."""
    if e["comparison"] == "diff":
        return "no tolerance given"
    if e["tolerance"] is None:
        return "-"
    if e["comparison"] == "max":
        return "measured <= paper"
    return ("each within %s" if e["comparison"] == "each" else "+-%s") % _fmt(
        e["tolerance"], e["unit"])


def match_cell(e):
    """The match column: yes/no, or the difference where the paper gives no
    tolerance (the range of the differences for a list)."""
    if e["comparison"] == "diff":
        d = e.get("difference")
        if d is None:
            return "-"
        if isinstance(d, list):
            return "difference %s to %s" % (_fmt(min(d), e["unit"]), _fmt(max(d), e["unit"])) \
                if d else "-"
        return "difference %s" % _fmt(d, e["unit"])
    return {True: "yes", False: "no", None: "-"}[e["match"]]


def _num(x):
    """float for JSON, or None for missing/non-finite values."""
    if x is None:
        return None
    x = float(x)
    return x if math.isfinite(x) else None


def summary(series, prep, events, cycle_index=None, sample_ms=(), knee=False,
            block_ms=(), percentile=None, overlaps=False, run_dir=None, shear=None):
    """Measured values beside the paper's, plus cycle C, as a JSON-ready dict.

    ``prep`` is the prep.json dict (None if unavailable); ``shear`` the
    shear stage's record, shear.json (:func:`read_shear_record`; None for a
    run without one): its tau_amp and ru_liq are the stage's, and the dict
    keeps it as ``shear_stage``; ``events`` the
    fix's, of :func:`run_events` (the only source of the events and of
    N_IL); ``cycle_index`` selects cycle C among the post-liquefaction
    cycles (default: the first with all six states).  Entries measured as
    "not reached" (an event that did not happen) or "not available"
    (missing input) never match.

    The options of issue 30 (:func:`grflow_analysis.definitions.definitions`):
    ``sample_ms`` (output intervals in ms to decimate the series to),
    ``knee``, ``block_ms`` (windows in ms of block-averaged p for I),
    ``percentile`` (q of a percentile of z_g after IL), ``overlaps`` (z_g
    counting all overlaps at the snapshot states of cycle C, from the
    snapshots of ``run_dir``).  With any of them the dict has the key
    ``definitions``; without, it is as before them.
    """
    ru_liq, tau_amp = protocol(prep, shear)
    N = cycle_count(series, events)
    liq = liquefaction(series, events, ru_liq)
    zg = series["z_g"]
    prep = stage_values(prep, shear)

    def prep_value(key):
        v = prep.get(key)
        return float(v) if _is_number(v) else NOT_AVAILABLE

    entries = [
        _entry("N_particles", "particles in the sample (prep.json N)", "-",
               prep_value("N")),
        _entry("e_prep", "void ratio at the end of preparation", "-", prep_value("e")),
        _entry("p_prep", "mean stress at the end of preparation", "Pa", prep_value("p")),
        _entry("z_g_prep", "z_g at the end of preparation", "-", prep_value("z_g")),
        _entry("tau_amp", "shear stress amplitude used", "Pa", prep_value("tau_amp")),
    ]
    onset = liq["onset"]
    if onset is None:
        entries += [
            _entry("N_IL", "cycles to initial liquefaction (r_u >= ru_liq)", "-", NOT_REACHED),
            _entry("z_g_at_IL", "z_g at initial liquefaction", "-", NOT_REACHED),
            _entry("z_g_post_IL_max", "largest z_g after initial liquefaction", "-",
                   NOT_REACHED),
            _entry("z_g_post_IL_min", "smallest z_g after initial liquefaction", "-",
                   NOT_REACHED),
            _entry("nonliq_zg_at_least_3.6",
                   "fraction of the rows after initial liquefaction with r_u < ru_liq that "
                   "have z_g >= 3.6", "-", NOT_REACHED),
            _entry("liq_zg_max", "largest z_g of the rows with r_u >= ru_liq", "-",
                   NOT_REACHED),
        ]
    else:
        post = zg[onset:][np.isfinite(zg[onset:])]
        n_il = liquefaction_n(events, onset)
        entries += [
            _entry("N_IL", "cycles to initial liquefaction (r_u >= ru_liq; fix grflow/shear's "
                   "N_IL)", "-",
                   n_il if n_il is not None else NOT_AVAILABLE),
            _entry("z_g_at_IL", "z_g at initial liquefaction", "-", _num(zg[onset])),
            _entry("z_g_post_IL_max", "largest z_g after initial liquefaction", "-",
                   float(post.max()) if len(post) else NOT_REACHED),
            _entry("z_g_post_IL_min", "smallest z_g after initial liquefaction", "-",
                   float(post.min()) if len(post) else NOT_REACHED),
        ]
        # the paper's division of the states at z_g = 3.6, from initial
        # liquefaction on: rows not liquefied (r_u < ru_liq) with z_g >= 3.6,
        # and the largest z_g of the liquefied rows
        ru_post = series["r_u"][onset:]
        zg_post = zg[onset:]
        ok = np.isfinite(ru_post) & np.isfinite(zg_post)
        nonliq = ok & (ru_post < ru_liq)
        liqrows = ok & (ru_post >= ru_liq)
        entries += [
            _entry("nonliq_zg_at_least_3.6",
                   "fraction of the rows after initial liquefaction with r_u < ru_liq that "
                   "have z_g >= 3.6", "-",
                   float(np.mean(zg_post[nonliq] >= 3.6)) if nonliq.any() else NOT_REACHED),
            _entry("liq_zg_max", "largest z_g of the rows with r_u >= ru_liq", "-",
                   float(zg_post[liqrows].max()) if liqrows.any() else NOT_REACHED),
        ]
    ex = liq["exits"]
    zex = [float(zg[i]) for i in ex]
    entries += [
        _entry("n_exits", "number of liquefaction exits (r_u falls below ru_liq)", "-",
               len(ex) if ex else NOT_REACHED),
        _entry("z_g_at_exits", "z_g at each liquefaction exit", "-",
               zex if ex else NOT_REACHED),
        _entry("z_g_exit_mean", "mean z_g at the liquefaction exits", "-",
               float(np.mean(zex)) if ex else NOT_REACHED),
        _entry("z_g_exit_std", "standard deviation (population) of z_g at the exits",
               "-", float(np.std(zex)) if ex else NOT_REACHED),
    ]
    infl = zg_inflections(series, N, events, liq)
    zin = [d["z_g"] for d in infl]
    if onset is None:
        red_max = NOT_REACHED
    else:
        post = zg[onset:][np.isfinite(zg[onset:])]
        red_max = float(static_redundancy(post.max())) if len(post) else NOT_REACHED
    entries += [
        _entry("z_g_inflections",
               "z_g at the inflection of a logistic fitted to z_g(N) within %g cycles of "
               "each exit" % INFLECTION_HALF_WINDOW_N, "-",
               zin if zin else NOT_REACHED),
        _entry("z_g_inflection_mean", "mean of z_g_inflections", "-",
               float(np.mean(zin)) if zin else NOT_REACHED),
        _entry("static_redundancy_post_IL_max",
               "largest static redundancy z_g/4 - 1 after initial liquefaction (3 force "
               "unknowns per contact, 6 equations per particle)", "-", red_max),
    ]
    ist = inertial_stats(series, onset)
    entries += [
        _entry("inertial_max", "largest inertial number I where p > 0", "-", ist["max"]),
        _entry("inertial_max_pre_IL", "largest I before initial liquefaction", "-",
               ist["max_pre_IL"]),
        _entry("inertial_median_post_IL", "median I after initial liquefaction, p > 0",
               "-", ist["median_post_IL"]),
        _entry("inertial_undefined_rows",
               "rows with p = 0, where I is undefined (series value -1)", "-",
               ist["undefined_rows"]),
        _entry("p_min_post_IL", "smallest p after initial liquefaction", "Pa",
               ist["p_min_post_IL"]),
    ]
    entries.append(_entry("a_c_peak_per_cycle",
                          "maximum a_c in each cycle n <= N < n+1 (last may be partial)",
                          "-", peak_ac_per_cycle(series, N)))

    n, states, note = choose_cycle(series, events, ru_liq, cycle_index, liq)

    # the paper's reading of Fig. 5 on cycle C: a_c changes much from C0 to
    # C0', little from C0' to C1 and from C1 to C2 (a_c at the later state
    # minus a_c at the earlier, with the change of z_g beside it in the
    # description)
    def change(a, b):
        if n is None or states.get(a) is None or states.get(b) is None:
            return NOT_REACHED
        return float(series["a_c"][states[b]] - series["a_c"][states[a]])

    def zg_change(a, b):
        if n is None or states.get(a) is None or states.get(b) is None:
            return ""
        return ", z_g %+.3g" % float(zg[states[b]] - zg[states[a]])

    entries += [
        _entry("a_c_change_C0_C0p", "change of a_c from C0 to C0' in cycle C" +
               zg_change("C0", "C0'"), "-", change("C0", "C0'")),
        _entry("a_c_change_C0p_C1", "change of a_c from C0' to C1 in cycle C" +
               zg_change("C0'", "C1"), "-", change("C0'", "C1")),
        _entry("a_c_change_C1_C2", "change of a_c from C1 to C2 in cycle C" +
               zg_change("C1", "C2"), "-", change("C1", "C2")),
    ]
    cyc = {"cycle": n, "index_among_post_IL": cycle_index, "note": note, "states": {}}
    if n is not None:
        for s in STATES:
            r = states[s]
            if r is None:
                cyc["states"][s] = NOT_REACHED
                continue
            cyc["states"][s] = {
                "row": int(r), "step": int(series["step"][r]), "N": float(N[r]),
                "tau": _num(series["tau"][r]), "p": _num(series["p"][r]),
                "r_u": _num(series["r_u"][r]), "gamma": _num(series["gamma"][r]),
                "z_g": _num(zg[r]), "a_c": _num(series["a_c"][r]),
                "P_c": [_num(v) for v in connectivity(series, r)],
                "P_c_non_floaters": [_num(v) for v in connectivity_non_floaters(series, r)]}
    out = {
        "ru_liq": ru_liq, "tau_amp": tau_amp, "shear_stage": shear,
        "rows": int(len(N)), "last_step": int(series["step"][-1]),
        "N_end": float(N[-1]), "reversals": int(np.max(series["reversals"])),
        "onset_row": onset,
        "exit_N": [float(N[i]) for i in ex],
        "entries": entries, "cycle_C": cyc,
    }
    if sample_ms or knee or block_ms or percentile is not None or overlaps:
        from grflow_analysis import definitions as _defs
        out["definitions"] = _defs.definitions(
            series, events, ru_liq, sample_ms=sample_ms, knee=knee, block_ms=block_ms,
            percentile=percentile, overlaps=overlaps, run_dir=run_dir, states=states)
    return out


def _fmt(v, unit=""):
    if isinstance(v, str):
        return v
    if v is None:
        return "-"
    if isinstance(v, list):
        if not v:
            return "[]"
        shown = ", ".join(_fmt(x, unit) for x in v[:8])
        return "[" + shown + (", ... (%d)" % len(v) if len(v) > 8 else "") + "]"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if unit == "Pa":
        return "%.4g kPa" % (v / 1e3)
    if isinstance(v, int):
        return str(v)
    return "%.4g" % v


def summary_markdown(s):
    """The summary as a markdown table (stresses in kPa)."""
    lines = ["| quantity | measured | paper | tolerance | match |",
             "| --- | --- | --- | --- | --- |"]
    for e in s["entries"]:
        u = e["unit"]
        lines.append("| %s (%s) | %s | %s | %s | %s |" % (
            e["name"], e["description"], _fmt(e["measured"], u), _fmt(e["paper"], u),
            tolerance_cell(e), match_cell(e)))
    c = s["cycle_C"]
    lines.append("")
    if c["cycle"] is None:
        lines.append("Cycle C: %s." % c["note"])
    else:
        lines.append("Cycle C: cycle %d (N = %d to %d)." % (c["cycle"], c["cycle"],
                                                           c["cycle"] + 1))
        lines.append("")
        lines.append("| state | step | N | tau | p | r_u | gamma | z_g | a_c | P_0 | "
                     "c < 4 among particles with contacts |")
        lines.append("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        for st, d in c["states"].items():
            if isinstance(d, str):
                lines.append("| %s | %s |  |  |  |  |  |  |  |  |  |" % (st, d))
            else:
                gam = None if d["gamma"] is None else 100 * d["gamma"]
                nf = d.get("P_c_non_floaters") or []
                low = (sum(v for v in nf[1:4] if v is not None)
                       if len(nf) >= 4 and all(v is not None for v in nf[1:4]) else None)
                p0 = d["P_c"][0] if d.get("P_c") else None
                lines.append("| %s | %d | %.4g | %s | %s | %s | %s%% | %s | %s | %s | %s |" % (
                    st, d["step"], d["N"], _fmt(d["tau"], "Pa"), _fmt(d["p"], "Pa"),
                    _fmt(d["r_u"]), _fmt(gam), _fmt(d["z_g"]), _fmt(d["a_c"]), _fmt(p0),
                    _fmt(low)))
        lines.append("")
        lines.append("P_0: floaters among the sub-volume's particles.  The last column is "
                     "P_1 + P_2 + P_3 over the particles with contacts (P_c / (1 - P_0)); "
                     "the paper reads its Fig. 4 as \"a high proportion of particles with "
                     "c < 4\" at C0 and C2, a fragile network that \"disappears\" at C0' "
                     "and C2'.")
    lines.append("")
    lines.append("ru_liq = %g, tau_amp = %g kPa, %d rows, last step %d, N_end = %.4g."
                 % (s["ru_liq"], s["tau_amp"] / 1e3, s["rows"], s["last_step"], s["N_end"]))
    lines.append("")
    if s.get("shear_stage"):
        lines.append("The shear stage's settings (shear.json): %s."
                     % ", ".join("%s %s" % kv for kv in s["shear_stage"].items()))
    else:
        lines.append("The shear stage's settings: not recorded (no shear.json: a run "
                     "from before the decks wrote it; its log.shear.lammps has them).")
    text = "\n".join(lines) + "\n"
    if "definitions" in s:
        from grflow_analysis import definitions as _defs
        text += _defs.definitions_markdown(s["definitions"])
    return text
