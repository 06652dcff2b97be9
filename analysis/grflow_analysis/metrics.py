# GRFLOW analysis: quantities measured on the series (connectivity, peak
# a_c, static redundancy, the fits of the z_g rise, the inertial number).
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""Quantities measured on the series: the connectivity P_c at a row, the
peak a_c of each cycle, the static redundancy, the logistic fit of the
z_g rise through each liquefaction exit (its inflection and its knee),
and statistics of the inertial number.

A quantity that cannot be measured is NOT_REACHED (an event that did not
happen) or NOT_AVAILABLE (missing input).
"""

import math

import numpy as np

from .readers import PC_COLUMNS

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
