"""Independent re-derivations, in Python and for the tests only, of what
the C++ decides in a run: the contact network of compute grflow/network
from a snapshot's dumps, and the cycle events of fix grflow/shear from the
series.  The analysis (grflow_analysis) takes both from the run's own
output (series.txt, events.txt) and has no second rule for them; the
protocol tests compare the run's output with these.
"""

import math

import numpy as np


def network_from_snapshot(atoms, contacts, zlo, zhi, slab=0.8, cmax=12, stress=None):
    """Contact network of a snapshot, recomputed offline as compute grflow/network does.

    ``atoms`` and ``contacts`` are the dicts of grflow_analysis's
    read_dump_atoms and read_dump_local of one step; ``zlo``/``zhi`` the
    wall positions (series columns of that step).  The sub-volume is the
    decks' (compute ``net``: ``zlimits v_zlo v_zhi slab 0.8``, group
    ``free``): particles with glue 0 whose centre z is in
    [zmid - slab h/2, zmid + slab h/2).  A contact is an entry with fn > 0;
    entries with fn <= 0 (overlapping but separating,
    doc/compute_grflow_network.rst) are left out.  Each end of a contact
    that belongs to a particle inside counts for that particle and adds n n
    to the fabric.  A particle inside that overlaps a wall plane is counted
    as touching that wall: the wall forces are not dumped, so an overlap
    with a zero force (which the compute does not count) cannot be told
    apart; in the decks' central slab no particle inside can reach a wall.

    Returns a dict: ``N_p``, ``floaters``, ``N_c``, ``z_g``, ``z``, ``P``
    (P_0 .. P_cmax, the last for cmax or more contacts), ``a`` (the 3x3
    fabric anisotropy tensor 15/2 (F - I/3)), ``a_abs`` (sqrt(3/2 a:a)) and,
    if ``stress`` (sxx syy szz sxy sxz syz, the series columns) is given,
    ``a_c`` with the sign of a:s, s the deviator of the stress made
    symmetric from those columns.  The compute uses (s_ab + s_ba)/2 of its
    full tensor, and the series does not hold s_yx, s_zx, s_zy: where a:s
    is near 0 the two signs can differ.
    """
    ac, cc = atoms["columns"], contacts["columns"]
    ids = ac["id"].astype(np.int64)
    z, rad = ac["z"], ac["radius"]
    half = 0.5 * slab * (zhi - zlo)
    zmid = 0.5 * (zlo + zhi)
    inside = (ac["glue"] == 0) & (z >= zmid - half) & (z < zmid + half)
    index = {int(i): k for k, i in enumerate(ids)}
    ncont = np.zeros(len(ids), dtype=np.int64)
    fab = np.zeros((3, 3))
    keep = cc["fn"] > 0.0
    for i1, i2, dx, dy, dz in zip(cc["id1"][keep], cc["id2"][keep], cc["dx"][keep],
                                  cc["dy"][keep], cc["dz"][keep]):
        ends = 0
        for i in (index[int(i1)], index[int(i2)]):
            if inside[i]:
                ncont[i] += 1
                ends += 1
        if ends:
            n = np.array([dx, dy, dz]) / math.sqrt(dx * dx + dy * dy + dz * dz)
            fab += ends * np.outer(n, n)
    for wall in (inside & (z - rad < zlo), inside & (z + rad > zhi)):
        ncont[wall] += 1
        fab[2, 2] += np.count_nonzero(wall)
    c = ncont[inside]
    n_p, floaters, csum = len(c), int(np.count_nonzero(c == 0)), int(c.sum())
    P = np.bincount(np.minimum(c, cmax), minlength=cmax + 1)[:cmax + 1] / max(n_p, 1)
    a = 7.5 * (fab / csum - np.eye(3) / 3.0) if csum else np.zeros((3, 3))
    out = {"N_p": n_p, "floaters": floaters, "N_c": 0.5 * csum,
           "z_g": csum / (n_p - floaters) if n_p > floaters else 0.0,
           "z": csum / n_p if n_p else 0.0, "P": P, "a": a,
           "a_abs": math.sqrt(1.5 * float(np.sum(a * a)))}
    if stress is not None:
        sxx, syy, szz, sxy, sxz, syz = stress
        sig = np.array([[sxx, sxy, sxz], [sxy, syy, syz], [sxz, syz, szz]])
        dev = sig - np.trace(sig) / 3.0 * np.eye(3)
        out["a_c"] = out["a_abs"] if np.sum(a * dev) >= 0.0 else -out["a_abs"]
    return out


def series_events(series, ru_liq):
    """The cycle events and initial liquefaction found in the series' rows
    (their ``reversals``, ``tau`` and ``r_u``), at the series' resolution,
    in the form of grflow_analysis.fix_events (so that cycle_count and the
    rest take them): ``reversal_rows`` (entry k-1 is the first row whose
    ``reversals`` >= k), ``crossing_rows`` (k -> the first row after
    reversal k, before reversal k+1, where tau has the sign of the new
    direction: tau <= 0 after an odd reversal, made at +tau_amp, tau >= 0
    after an even one; k = 0 is the shear start, row 0 when no reversal
    precedes the series; None if not seen), ``rows``, ``N``, ``time`` (the
    events in time order, N = k/2 - 1/4 at reversal k, k/2 at the crossing
    after it, at the time of their row; two events on one row: the later
    one), ``onset`` (the first row with r_u >= ru_liq, None if none),
    ``step_IL`` (its step) and ``N_IL`` (N of that row, linear in time
    between the events around it).
    """
    rev = np.maximum.accumulate(np.rint(series["reversals"]).astype(np.int64))
    tau, t = series["tau"], series["time"]
    nrow = len(rev)
    k0, kmax = int(rev[0]), int(rev[-1])
    reversal_rows = [None] * kmax
    for k in range(k0 + 1, kmax + 1):
        reversal_rows[k - 1] = int(np.searchsorted(rev, k, side="left"))
    crossing_rows = {}
    if k0 == 0:
        crossing_rows[0] = 0
    for k in range(max(k0, 1), kmax + 1):
        start = reversal_rows[k - 1]
        if start is None:       # reversal before the first row: unknown
            crossing_rows[k] = None
            continue
        stop = reversal_rows[k] if k < kmax else nrow
        sign = -1.0 if k % 2 else 1.0
        hit = np.nonzero(sign * tau[start + 1:stop] >= 0.0)[0]
        crossing_rows[k] = int(start + 1 + hit[0]) if len(hit) else None
    events = []
    if k0 == 0:
        events.append((0, 0.0))
    for k in range(k0 + 1, kmax + 1):
        events.append((reversal_rows[k - 1], k / 2.0 - 0.25))
    for k, row in crossing_rows.items():
        if k > 0 and row is not None:
            events.append((row, k / 2.0))
    events.sort()
    rows, Ns = [], []
    for row, n in events:
        if rows and row == rows[-1]:      # two events on one row: keep the later one
            rows.pop()
            Ns.pop()
        rows.append(row)
        Ns.append(n)
    times = [0.0 if (row == 0 and n == 0.0) else float(t[row]) for row, n in zip(rows, Ns)]
    hit = np.nonzero(np.asarray(series["r_u"]) >= ru_liq)[0] if "r_u" in series else []
    onset = int(hit[0]) if len(hit) else None
    n_il = float(np.interp(t[onset], times, Ns)) if onset is not None and times else None
    return {"reversal_rows": reversal_rows, "crossing_rows": crossing_rows,
            "rows": rows, "N": Ns, "time": times, "onset": onset,
            "step_IL": int(series["step"][onset]) if onset is not None else None,
            "N_IL": n_il}
