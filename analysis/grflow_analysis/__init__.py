# GRFLOW analysis: read a run directory written by the GRFLOW decks and
# extract the quantities of the isochoric cyclic shearing paper.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""The analysis of a GRFLOW run directory; ``grflow-figures``
(:mod:`grflow_analysis.figures`) draws the paper's figures with it.

Everything here is a pure function of its arguments (no plotting, no
printing); rows of the series are referred to by their index in the
arrays returned by :func:`read_series`.  Its names
are also those of its modules, imported here:

* :mod:`grflow_analysis.readers`: the readers of the run directory
  (inputs/README.md), :class:`FormatError`, the column names of the
  series and the settings the shear stage ran with;
* :mod:`grflow_analysis.cycles`: fix grflow/shear's events on the series,
  the fractional cycle count N, initial liquefaction and its exits, the
  states of a cycle (its docstring holds these definitions);
"""

import math

import numpy as np

# the package's names, one source each
from .readers import (DEFAULT_RU_LIQ, DEFAULT_TAU_AMP, EVENT_COLUMNS, PC_COLUMNS,
                      REQUIRED_COLUMNS, SERIES_COLUMNS, FormatError, _canonical,
                      _drop_repeated_steps, _is_number, _load_rows, _locate_bad_row,
                      list_snapshots, protocol, read_dump, read_dump_atoms,
                      read_dump_local, read_events, read_prep, read_series,
                      read_shear_record, stage_values)
from .cycles import (STATES, choose_cycle, cycle_count, cycle_rows, find_cycle_states,
                     fix_events, liquefaction, liquefaction_n, post_liquefaction_cycles,
                     run_events)

NOT_REACHED = "not reached"
NOT_AVAILABLE = "not available"


def connectivity(series, row):
    """P_c, c = 0..12 (P12: 12 or more), at a row (NaN where a column is absent)."""
    return np.array([series[c][row] if c in series else np.nan for c in PC_COLUMNS])


def connectivity_non_floaters(series, row):
    """P_c over the particles with at least one contact, c = 1..12: the
    written P_c divided by 1 - P_0 (NaN where every particle is a
    floater).  Index 0 is 0 by construction, so that the array lines up
    with connectivity()."""
    pc = connectivity(series, row)
    rest = 1.0 - pc[0]
    out = np.full_like(pc, np.nan)
    if rest > 0.0:
        out = pc / rest
        out[0] = 0.0
    return out


def peak_ac_per_cycle(series, N):
    """Maximum a_c in each cycle n (rows with floor(N) == n), n = 0 .. floor(max N)."""
    cyc = np.floor(N + 1e-12).astype(np.int64)
    out = []
    for n in range(int(cyc.max()) + 1 if len(cyc) else 0):
        sel = (cyc == n) & np.isfinite(series["a_c"])
        out.append(float(series["a_c"][sel].max()) if sel.any() else None)
    return out


# Isostatic coordination number of frictional spheres counted as the paper
# does: 3 force components per contact against 6 equilibrium equations per
# particle.  (Counting the rolling and twisting moments of the contact law
# as unknowns too, 6 per contact, would put it at 2.)
Z_ISOSTATIC = 4.0


def static_redundancy(z_g, z_iso=Z_ISOSTATIC):
    """Degree of static redundancy per equation, (3 N_c - 6 n) / (6 n) with
    n = N_p - N_p^0 the particles that carry contacts: z_g / z_iso - 1.
    Negative: fewer contact force unknowns than equilibrium equations."""
    return np.asarray(z_g, dtype=float) / z_iso - 1.0


def _logistic_fit(n, z, n_centres=121, n_widths=25):
    """Least-squares fit of z = a + b / (1 + exp(-(n - n0) / w)) by a grid
    over n0 (within the data) and w (1/200 to 1/2 of the span, log-spaced),
    a and b by linear regression at each grid point, then the grid refined
    twice around the best point.  Returns (n0, w, a, b, rms residual)."""
    span = n[-1] - n[0]
    c_lo, c_hi = n[0], n[-1]
    w_lo, w_hi = np.log(span / 200.0), np.log(span / 2.0)
    best = None
    zc = z - z.mean()
    szz = float(zc @ zc)
    for _ in range(3):
        centres = np.linspace(c_lo, c_hi, n_centres)
        for w in np.exp(np.linspace(w_lo, w_hi, n_widths)):
            # one row per centre: the logistic, overflow-free via tanh
            x = 0.5 * (1.0 + np.tanh(0.5 * (n[None, :] - centres[:, None]) / w))
            xc = x - x.mean(axis=1, keepdims=True)
            sxx = np.einsum("ij,ij->i", xc, xc)
            sxz = xc @ zc
            good = sxx > 1e-12 * len(n)
            b = np.where(good, sxz / np.where(good, sxx, 1.0), 0.0)
            r = np.where(good, szz - b * sxz, np.inf)     # residual sum of squares
            m = int(np.argmin(r))
            if best is None or r[m] < best[4]:
                a = float(z.mean() - b[m] * x[m].mean())
                best = (float(centres[m]), float(w), a, float(b[m]), float(r[m]))
        # refine: a finer grid around the best point
        dc = (c_hi - c_lo) / (n_centres - 1)
        c_lo, c_hi = best[0] - 2 * dc, best[0] + 2 * dc
        dw = (w_hi - w_lo) / (n_widths - 1)
        w_lo, w_hi = np.log(best[1]) - 2 * dw, np.log(best[1]) + 2 * dw
    n0, w, a, b, r = best
    return n0, w, a, b, math.sqrt(max(r, 0.0) / len(n))


# Half-width, in cycles, of the window around each exit over which the
# logistic is fitted.  In the paper-size runs z_g climbs slowly through the
# liquefied quarter cycle (about 1.5 to 2.8 over 0.1 cycles) and then jumps
# to about 3.6 within about 0.005 cycles as the sample leaves liquefaction,
# before the reversal; the window holds that jump several times over and
# leaves out most of the slow climb, whose many rows would otherwise set
# the fit.  (Chosen from the shape of z_g(N) in runs/sc/serial, before any
# inflection value was computed with it.)
INFLECTION_HALF_WINDOW_N = 0.02


def zg_inflections(series, N, events, liq, max_rows=2000,
                   half_window=INFLECTION_HALF_WINDOW_N):
    """The inflection point of z_g(N) in the rise through each liquefaction
    exit.  Over the rows within half_window cycles of the exit, inside the
    quarter cycle that holds it (from the first zero-crossing of tau after
    a reversal to the next reversal), z_g(N) is fitted with a logistic step
    z = a + b / (1 + exp(-(N - N0)/w)) (least squares; at most max_rows
    rows, evenly taken); its inflection is N0, where z = a + b/2.  A fit
    rather than the steepest point of the data: z_g is a fluctuating
    count, and the slope of an S-shaped rise is flat near its inflection,
    so the steepest sampled point wanders.  Returns a
    list of dicts (exit row, N0, z_g = a + b/2, w, rms residual, a, b, and
    the knee of the fitted logistic, :func:`logistic_knee`: knee_N,
    knee_z_g), one per exit whose quarter cycle is complete in the series
    and rises (b > 0)."""
    zg = np.asarray(series["z_g"], dtype=float)
    rr = events["reversal_rows"]
    cr = events["crossing_rows"]
    starts = sorted((row, k) for k, row in cr.items() if row is not None)
    out = []
    for e in liq["exits"]:
        before = [(row, k) for row, k in starts if row <= e]
        if not before:
            continue
        start, k = before[-1]
        stop = rr[k] if k < len(rr) else None      # reversal k + 1
        if stop is None or stop <= e:
            continue
        n = np.asarray(N[start:stop + 1], dtype=float)
        z = zg[start:stop + 1]
        ok = np.isfinite(z) & np.isfinite(n) & (np.abs(n - N[e]) <= half_window)
        n, z = n[ok], z[ok]
        if len(n) < 5 or not n[-1] > n[0]:
            continue
        if len(n) > max_rows:
            take = np.linspace(0, len(n) - 1, max_rows).round().astype(int)
            n, z = n[take], z[take]
        n0, w, a, b, rms = _logistic_fit(n, z)
        if b <= 0.0:
            continue
        knee_n, knee_z = logistic_knee(n0, w, a, b)
        out.append({"exit_row": int(e), "N": float(n0), "z_g": float(a + 0.5 * b),
                    "width": float(w), "rms": float(rms), "a": float(a), "b": float(b),
                    "knee_N": float(knee_n), "knee_z_g": float(knee_z)})
    return out


# The knee of a logistic rise z = a + b / (1 + exp(-(N - N0)/w)), b > 0:
# where it has risen by this fraction of its jump b above its lower
# asymptote a (issue 30, "the knee of the rise").  Not the point of
# largest curvature, which moves with the scale chosen for z against N
# (z_g is a count, N cycles: there is no natural ratio between the two).
KNEE_FRACTION = 0.1


def logistic_knee(n0, w, a, b, fraction=KNEE_FRACTION):
    """The knee of the logistic z = a + b / (1 + exp(-(N - n0)/w)): the
    point where z = a + fraction * b, at N = n0 - w ln((1 - fraction) /
    fraction) (n0 - w ln 9 = n0 - 2.197 w for the default 0.1).  Returns
    (N, z)."""
    if not 0.0 < fraction < 1.0:
        raise ValueError("knee fraction %r not in (0, 1)" % (fraction,))
    return n0 - w * math.log((1.0 - fraction) / fraction), a + fraction * b


# ---------------------------------------------------------------- summary

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


def inertial_stats(series, onset):
    """The inertial number as the deck wrote it (column ``inertial``: I from
    the unfloored p, -1 where p = 0 and I is undefined), split at the onset
    row of initial liquefaction (None: not reached).

    Returns a dict: ``max`` (largest defined I), ``max_pre_IL``,
    ``median_post_IL``, ``undefined_rows`` (rows with I = -1) and
    ``p_min_post_IL`` (smallest p from the onset on, Pa).  A value that
    cannot be measured is NOT_AVAILABLE or NOT_REACHED.  Series written
    before the deck stopped flooring p at 1 Pa in I give that floored I.
    """
    out = {}
    if "inertial" not in series:
        out.update(max=NOT_AVAILABLE, max_pre_IL=NOT_AVAILABLE,
                   median_post_IL=NOT_AVAILABLE, undefined_rows=NOT_AVAILABLE)
    else:
        inert = np.asarray(series["inertial"], dtype=float)
        defined = np.isfinite(inert) & (inert >= 0.0)
        out["undefined_rows"] = int(np.count_nonzero(~defined))
        out["max"] = float(inert[defined].max()) if defined.any() else NOT_AVAILABLE
        end = len(inert) if onset is None else onset
        pre = inert[:end][defined[:end]]
        out["max_pre_IL"] = float(pre.max()) if len(pre) else NOT_AVAILABLE
        if onset is None:
            out["median_post_IL"] = NOT_REACHED
        else:
            post = inert[onset:][defined[onset:]]
            out["median_post_IL"] = float(np.median(post)) if len(post) else NOT_AVAILABLE
    if onset is None:
        out["p_min_post_IL"] = NOT_REACHED
    else:
        p = np.asarray(series["p"], dtype=float)[onset:]
        p = p[np.isfinite(p)]
        out["p_min_post_IL"] = float(p.min()) if len(p) else NOT_AVAILABLE
    return out


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
