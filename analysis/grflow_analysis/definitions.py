# GRFLOW analysis: the summary's optional sampling and definitions
# (issue 30, hypotheses 4 and 5).
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""Derived statistics of the written series and snapshots, beside the
summary's present definitions (:func:`grflow_analysis.summary`).

Nothing here decides an event, N_IL or a network quantity again: the
events and N_IL are the fix's (events.txt), z_g, p, r_u and I are the
series' columns as the decks wrote them.  What is computed here are
statistics of those columns under other choices of sampling and
definition, each documented where it is made:

* :func:`decimate`: the series at a coarser output interval (the rows
  nearest to the multiples of the interval in simulated time);
* the knee of the z_g rise at each exit (:func:`grflow_analysis.logistic_knee`
  of the logistic that :func:`grflow_analysis.zg_inflections` fits);
* :func:`block_inertial`: I from p averaged over blocks of simulated time;
* the q-th percentile of z_g after initial liquefaction;
* :func:`zg_overlaps`: z_g counting every overlap listed in a contacts
  snapshot (not only the pairs with f_n > 0 that compute grflow/network
  counts), at the states of cycle C that have snapshots.

:func:`definitions` gathers them into summary entries; ``grflow-figures``
exposes them as options (``--sample-ms``, ``--knee``, ``--block-ms``,
``--zg-percentile``, ``--overlaps``).  See analysis/README.md.
"""

import math
import os

import numpy as np

import grflow_analysis as ga

# The decks' sub-volume of compute net (inputs/shear.lmp: compute net free
# grflow/network zlimits v_zlo v_zhi slab 0.8): the free particles (glue 0)
# whose centre is in the central 80% of [zlo, zhi).
DECK_SLAB = 0.8


# ---------------------------------------------------------------- sampling

def decimate(series, interval):
    """The series at the output interval ``interval`` (s of simulated time).

    Rule: for every integer k with t_first <= k * interval <= t_last
    (t the ``time`` column), the row whose time is nearest to k * interval
    (the earlier row on a tie); a row chosen for two k is kept once.  The
    multiples are of the interval in the series' own time (the decks'
    time is 0 at the start of the run that wrote the first row).  Returns
    (decimated series: dict of arrays, as :func:`grflow_analysis.read_series`;
    idx: the indices of the chosen rows in the full series, increasing).
    """
    interval = float(interval)
    if not (interval > 0.0 and math.isfinite(interval)):
        raise ValueError("output interval %r is not a positive number" % (interval,))
    t = np.asarray(series["time"], dtype=float)
    if len(t) == 0:
        return {k: np.asarray(v)[:0] for k, v in series.items()}, np.zeros(0, dtype=np.int64)
    # the multiples of interval within [t0, t1]; the 1e-9 guards a time
    # written to 10 digits that lies a rounding error off a multiple
    k0 = math.ceil(t[0] / interval - 1e-9)
    k1 = math.floor(t[-1] / interval + 1e-9)
    targets = np.arange(k0, k1 + 1, dtype=float) * interval
    if len(t) == 1 or len(targets) == 0:
        idx = np.zeros(1 if len(targets) else 0, dtype=np.int64)
    else:
        j = np.clip(np.searchsorted(t, targets, side="left"), 1, len(t) - 1)
        left = j - 1
        take_left = (targets - t[left]) <= (t[j] - targets)
        idx = np.unique(np.where(take_left, left, j)).astype(np.int64)
    return {k: np.asarray(v)[idx].copy() for k, v in series.items()}, idx


def events_on_rows(events, idx):
    """The fix's events (:func:`grflow_analysis.run_events`) placed on the
    rows ``idx`` of the full series (a decimated series): an event on full
    row r goes to the first kept row at or after r, as
    :func:`grflow_analysis.fix_events` places an event on the first row
    at or after its step (None if no kept row is at or after it).  Their
    N, time, N_IL and step_IL are the fix's, unchanged."""
    idx = np.asarray(idx)

    def move(r):
        if r is None:
            return None
        k = int(np.searchsorted(idx, r, side="left"))
        return k if k < len(idx) else None

    return {"reversal_rows": [move(r) for r in events["reversal_rows"]],
            "crossing_rows": {k: move(r) for k, r in events["crossing_rows"].items()},
            "rows": [move(r) for r in events["rows"]],
            "N": list(events["N"]), "time": list(events["time"]),
            "N_IL": events["N_IL"], "step_IL": events["step_IL"]}


def zg_percentile_post_il(series, onset, q):
    """The q-th percentile (numpy's default, linear interpolation between
    the order statistics) of z_g over the finite rows from the onset row
    on; NOT_REACHED before initial liquefaction."""
    if onset is None:
        return ga.NOT_REACHED
    z = np.asarray(series["z_g"], dtype=float)[onset:]
    z = z[np.isfinite(z)]
    return float(np.percentile(z, q)) if len(z) else ga.NOT_AVAILABLE


def sampled_stats(series, events, ru_liq, percentile=None):
    """The summary's exit, inflection, knee, z_g and I statistics of one
    series (full or decimated), by the summary's own definitions
    (:func:`grflow_analysis.liquefaction`, :func:`grflow_analysis.zg_inflections`,
    :func:`grflow_analysis.inertial_stats`).  ``events`` must be placed
    on this series' rows (:func:`events_on_rows` for a decimated one)."""
    out = {"rows": int(len(series["time"]))}
    if out["rows"] == 0:
        return out
    N = ga.cycle_count(series, events)
    liq = ga.liquefaction(series, events, ru_liq)
    onset = liq["onset"]
    zg = np.asarray(series["z_g"], dtype=float)
    ex = liq["exits"]
    zex = [float(zg[i]) for i in ex]
    out["onset"] = onset
    out["n_exits"] = len(ex) if ex else ga.NOT_REACHED
    out["z_g_exit_mean"] = float(np.mean(zex)) if ex else ga.NOT_REACHED
    out["z_g_exit_std"] = float(np.std(zex)) if ex else ga.NOT_REACHED
    infl = ga.zg_inflections(series, N, events, liq)
    out["n_fits"] = len(infl)
    out["z_g_inflections"] = [d["z_g"] for d in infl]
    out["z_g_knees"] = [d["knee_z_g"] for d in infl]
    out["knee_N_before_inflection"] = [d["N"] - d["knee_N"] for d in infl]
    out["z_g_inflection_mean"] = (float(np.mean(out["z_g_inflections"])) if infl
                                  else (ga.NOT_REACHED if not ex else ga.NOT_AVAILABLE))
    out["z_g_knee_mean"] = (float(np.mean(out["z_g_knees"])) if infl
                            else (ga.NOT_REACHED if not ex else ga.NOT_AVAILABLE))
    if onset is None:
        out["z_g_post_IL_min"] = ga.NOT_REACHED
    else:
        post = zg[onset:][np.isfinite(zg[onset:])]
        out["z_g_post_IL_min"] = float(post.min()) if len(post) else ga.NOT_AVAILABLE
    if percentile is not None:
        out["z_g_post_IL_pct"] = zg_percentile_post_il(series, onset, percentile)
    out.update({"inertial_" + k if k != "p_min_post_IL" else k: v
                for k, v in ga.inertial_stats(series, onset).items()})
    return out


# ---------------------------------------------------------------- block-averaged I

def block_inertial(series, window, onset):
    """I from p averaged over blocks of ``window`` s of simulated time.

    Blocks: the rows with floor(time / window) = k, for each k that has
    rows (aligned on the multiples of the window, as :func:`decimate`; the
    first and last block may be partial).  p_block is the arithmetic
    mean of the block's finite p (the rows are equally spaced in time
    within a run).  I_block = K / sqrt(p_block) where p_block > 0, with
    K = (v_x / h) d_mean sqrt(density) the decks' own factor of I
    (inputs/shear.lmp), taken from the series as the median of
    inertial * sqrt(p) over the rows where I is defined (p > 0), so that
    no parameter is read again.  A block with p_block <= 0 has no I: it is
    counted in ``undefined_blocks``, never clipped or floored.  Blocks
    after initial liquefaction: those whose first row is at or after the
    onset row; before it: those whose last row is before it (the block
    that holds the onset is in neither).

    Returns a dict: ``blocks``, ``undefined_blocks``,
    ``undefined_blocks_post_IL``, ``max``, ``max_pre_IL``,
    ``median_post_IL``, ``p_block_min_post_IL`` (Pa, as averaged: may be
    <= 0), ``K`` and ``K_rel_spread`` ((max - min)/median of
    inertial * sqrt(p) over the rows: the written I's 6 digits give about
    1e-6; more means h or the factor changed within the series).
    """
    window = float(window)
    if not (window > 0.0 and math.isfinite(window)):
        raise ValueError("block window %r is not a positive number" % (window,))
    t = np.asarray(series["time"], dtype=float)
    p = np.asarray(series["p"], dtype=float)
    out = {}
    if "inertial" in series:
        inert = np.asarray(series["inertial"], dtype=float)
        ok = np.isfinite(inert) & (inert > 0.0) & np.isfinite(p) & (p > 0.0)
        k_rows = inert[ok] * np.sqrt(p[ok])
    else:
        k_rows = np.zeros(0)
    if len(k_rows) == 0:
        na = ga.NOT_AVAILABLE
        out.update(K=na, K_rel_spread=na, max=na, max_pre_IL=na, median_post_IL=na)
        K = None
    else:
        K = float(np.median(k_rows))
        out["K"] = K
        out["K_rel_spread"] = float((k_rows.max() - k_rows.min()) / K)
    blk = np.floor(t / window + 1e-9).astype(np.int64)
    starts = np.flatnonzero(np.r_[True, blk[1:] != blk[:-1]])
    ends = np.r_[starts[1:], len(t)]
    pb = np.array([np.mean(p[a:b][np.isfinite(p[a:b])]) if np.isfinite(p[a:b]).any()
                   else np.nan for a, b in zip(starts, ends)])
    defined = np.isfinite(pb) & (pb > 0.0)
    out["blocks"] = int(len(pb))
    out["undefined_blocks"] = int(np.count_nonzero(~defined))
    if onset is None:
        post = np.zeros(len(pb), dtype=bool)
        pre = np.ones(len(pb), dtype=bool)
    else:
        post = starts >= onset
        pre = (ends - 1) < onset
    out["undefined_blocks_post_IL"] = (int(np.count_nonzero(post & ~defined))
                                       if onset is not None else ga.NOT_REACHED)
    finite_post = post & np.isfinite(pb)
    out["p_block_min_post_IL"] = (ga.NOT_REACHED if onset is None else
                                  float(pb[finite_post].min()) if finite_post.any()
                                  else ga.NOT_AVAILABLE)
    if K is not None:
        ib = np.full(len(pb), np.nan)
        ib[defined] = K / np.sqrt(pb[defined])
        out["max"] = float(ib[defined].max()) if defined.any() else ga.NOT_AVAILABLE
        out["max_pre_IL"] = (float(ib[pre & defined].max()) if (pre & defined).any()
                             else ga.NOT_AVAILABLE)
        if onset is None:
            out["median_post_IL"] = ga.NOT_REACHED
        else:
            sel = post & defined
            out["median_post_IL"] = float(np.median(ib[sel])) if sel.any() else ga.NOT_AVAILABLE
    return out


# ---------------------------------------------------------------- counting rule

def zg_overlaps(atoms, contacts, zlo, zhi, slab=DECK_SLAB, rule="all"):
    """z_g of a snapshot's sub-volume, counting the pairs of the contacts
    file by ``rule``: "all" counts every entry (every overlapping pair the
    dump lists, whatever its f_n: "z_g counting all overlaps"); "fn>0"
    only those with f_n > 0 (the rule of compute grflow/network; here only
    as a check that the sub-volume and floater rules below are the
    compute's, the series' z_g being the compute's number).

    The rest is compute grflow/network's definition as the decks use it
    (doc/compute_grflow_network.rst; compute net in inputs/shear.lmp):
    the particles inside are those with glue 0 (group free) whose centre z
    is in [zmid - slab h/2, zmid + slab h/2), h = zhi - zlo; c_i counts
    the pairs of particle i inside with any particle (inside, outside or
    glued); floaters are the particles inside with c_i = 0; N_c is half
    the sum of c_i over the particles inside; z_g = 2 N_c / (N_p - floaters).
    Wall contacts: the wall forces are not dumped, so a particle inside
    whose sphere crosses a wall plane (z - r < zlo or z + r > zhi) counts
    one wall contact under both rules (an overlap; whether its f_n > 0
    cannot be told).  In the decks' central slab no particle inside
    reaches a wall, so this does not arise there.

    Returns a dict: ``N_p``, ``floaters``, ``N_c``, ``z_g`` (0 when every
    particle inside is a floater), ``ends_fn_nonpositive`` (contact ends of
    particles inside, counted here, whose f_n <= 0; 0 for rule "fn>0"),
    ``entries``, ``entries_fn_nonpositive``, ``entries_unresolved`` (entries
    whose overlap recomputed from the dumped branch vector and radii is
    <= 1e-5 of the sum of the radii: the dump's 6-digit radii cannot tell
    whether these still overlap; they count as listed).
    """
    if rule not in ("all", "fn>0"):
        raise ValueError("rule %r: 'all' or 'fn>0'" % (rule,))
    ac, cc = atoms["columns"], contacts["columns"]
    ids = ac["id"].astype(np.int64)
    z, rad = ac["z"], ac["radius"]
    half = 0.5 * slab * (zhi - zlo)
    zmid = 0.5 * (zlo + zhi)
    inside = (ac["glue"] == 0) & (z >= zmid - half) & (z < zmid + half)
    order = np.argsort(ids)
    sids = ids[order]

    def rows_of(pid):
        k = np.searchsorted(sids, pid)
        if np.any(k >= len(sids)) or np.any(sids[np.minimum(k, len(sids) - 1)] != pid):
            raise ga.FormatError("a contact names an atom id that the atoms snapshot "
                                 "does not hold")
        return order[k]

    i1 = rows_of(cc["id1"].astype(np.int64))
    i2 = rows_of(cc["id2"].astype(np.int64))
    fn = np.asarray(cc["fn"], dtype=float)
    keep = np.ones(len(fn), dtype=bool) if rule == "all" else (fn > 0.0)
    ncont = np.zeros(len(ids), dtype=np.int64)
    np.add.at(ncont, i1[keep & inside[i1]], 1)
    np.add.at(ncont, i2[keep & inside[i2]], 1)
    nonpos = keep & (fn <= 0.0)
    ends_nonpos = int(np.count_nonzero(nonpos & inside[i1]) + np.count_nonzero(nonpos & inside[i2]))
    for wall in (inside & (z - rad < zlo), inside & (z + rad > zhi)):
        ncont[wall] += 1
    c = ncont[inside]
    n_p, floaters, csum = int(len(c)), int(np.count_nonzero(c == 0)), int(c.sum())
    rsum = rad[i1] + rad[i2]
    dist = np.sqrt(cc["dx"] ** 2 + cc["dy"] ** 2 + cc["dz"] ** 2)
    return {"N_p": n_p, "floaters": floaters, "N_c": 0.5 * csum,
            "z_g": csum / (n_p - floaters) if n_p > floaters else 0.0,
            "ends_fn_nonpositive": ends_nonpos, "entries": int(len(fn)),
            "entries_fn_nonpositive": int(np.count_nonzero(fn <= 0.0)),
            "entries_unresolved": int(np.count_nonzero(rsum - dist <= 1e-5 * rsum))}


OVERLAP_STATES = ("C0", "C1", "C2", "C3")    # the states of cycle C that have snapshots


def overlaps_at_states(run_dir, series, states, slab=DECK_SLAB):
    """z_g counting all overlaps at the states of cycle C that are events
    (C0, C1, C2, C3: the decks write snapshots at every reversal and first
    zero-crossing after it), beside the series' z_g of the state's row.

    The snapshot of a state is snapshots/{atoms,contacts}.<step>.txt with
    the largest step at or before the state's row's step (the fix's event
    is on a check, every 10 steps; its row is the first series row at or
    after it, up to one series interval later).  zlo/zhi are the row's.
    Returns a dict state -> dict (snapshot_step, row_step, z_g_series,
    z_g_all_overlaps and the rest of :func:`zg_overlaps` with rule "all",
    z_g_fn_positive_check: :func:`zg_overlaps` with rule "fn>0", floaters
    of both) or a string saying why there is none."""
    out = {}
    snaps = dict(ga.list_snapshots(run_dir, "atoms"))
    csnaps = dict(ga.list_snapshots(run_dir, "contacts"))
    steps = sorted(set(snaps) & set(csnaps))
    for st in OVERLAP_STATES:
        r = None if states is None else states.get(st)
        if r is None:
            out[st] = ga.NOT_REACHED
            continue
        row_step = int(series["step"][r])
        before = [s for s in steps if s <= row_step]
        if not before:
            out[st] = "no snapshot at or before step %d" % row_step
            continue
        snap = before[-1]
        # an event's row is at most one series interval after its step
        prev_step = int(series["step"][r - 1]) if r > 0 else None
        if prev_step is not None and snap <= prev_step:
            out[st] = "no snapshot between the previous row's step %d and step %d" % (
                prev_step, row_step)
            continue
        atoms = ga.read_dump_atoms(snaps[snap])
        cont = ga.read_dump_local(csnaps[snap])
        zlo, zhi = float(series["zlo"][r]), float(series["zhi"][r])
        allo = zg_overlaps(atoms, cont, zlo, zhi, slab, "all")
        pos = zg_overlaps(atoms, cont, zlo, zhi, slab, "fn>0")
        d = {"snapshot_step": snap, "row_step": row_step,
             "z_g_series": ga._num(series["z_g"][r]),
             "z_g_all_overlaps": allo["z_g"], "z_g_fn_positive_check": pos["z_g"],
             "floaters_all_overlaps": allo["floaters"], "floaters_fn_positive": pos["floaters"]}
        for k in ("N_p", "N_c", "ends_fn_nonpositive", "entries", "entries_fn_nonpositive",
                  "entries_unresolved"):
            d[k] = allo[k]
        d["N_c_fn_positive"] = pos["N_c"]
        out[st] = d
    return out


def overlaps_over_snapshots(run_dir, series, step_il, slab=DECK_SLAB):
    """The two counting rules on every shear snapshot from initial
    liquefaction on (snapshot step >= step_IL), each snapshot with
    itself, so that the difference is that of the rule alone.  The
    snapshots are split by the kind of the fix's event they belong to
    (events.txt: the event with the largest step at or before the
    snapshot's; kind 2, the first zero-crossing of tau after a reversal,
    as C0 and C2; kind 1, a reversal, as C1 and C3).  zlo/zhi: those of
    the first series row at or after the snapshot's step.

    Returns a dict kind name ("crossings", "reversals") -> dict with
    ``snapshots``, ``z_g_fn_positive_mean``, ``z_g_all_overlaps_mean``,
    ``difference_mean`` and ``difference_max`` (all overlaps minus f_n > 0),
    ``z_g_whole_height_mean`` (f_n > 0 over every free particle of the
    whole height, slab 1.0: the paper's "total number of particles"),
    ``ends_fn_nonpositive_fraction`` (of all the contact ends counted
    under "all", those of pairs with f_n <= 0); NOT_REACHED without
    initial liquefaction, and an empty dict without events.txt."""
    if step_il is None:
        return ga.NOT_REACHED
    try:
        table = ga.read_events(os.path.join(run_dir, "events.txt"))
    except (OSError, ga.FormatError):
        return {}
    snaps = dict(ga.list_snapshots(run_dir, "atoms"))
    csnaps = dict(ga.list_snapshots(run_dir, "contacts"))
    acc = {"crossings": [], "reversals": []}
    for st in sorted(set(snaps) & set(csnaps)):
        if st < step_il:
            continue
        k = int(np.searchsorted(table["step"], st, side="right")) - 1
        if k < 1:                      # the start line, not an event
            continue
        kind = "crossings" if int(table["event"][k]) == 2 else "reversals"
        r = min(int(np.searchsorted(series["step"], st, side="left")), len(series["step"]) - 1)
        atoms = ga.read_dump_atoms(snaps[st])
        cont = ga.read_dump_local(csnaps[st])
        zlo, zhi = float(series["zlo"][r]), float(series["zhi"][r])
        allo = zg_overlaps(atoms, cont, zlo, zhi, slab, "all")
        pos = zg_overlaps(atoms, cont, zlo, zhi, slab, "fn>0")
        whole = zg_overlaps(atoms, cont, zlo, zhi, 1.0, "fn>0")
        acc[kind].append((pos["z_g"], allo["z_g"], allo["ends_fn_nonpositive"],
                          2.0 * allo["N_c"], whole["z_g"]))
    out = {}
    for kind, v in acc.items():
        if not v:
            out[kind] = {"snapshots": 0}
            continue
        a = np.array(v, dtype=float)
        diff = a[:, 1] - a[:, 0]
        ends = a[:, 3].sum()
        out[kind] = {"snapshots": int(len(a)), "z_g_fn_positive_mean": float(a[:, 0].mean()),
                     "z_g_all_overlaps_mean": float(a[:, 1].mean()),
                     "difference_mean": float(diff.mean()), "difference_max": float(diff.max()),
                     "z_g_whole_height_mean": float(a[:, 4].mean()),
                     "ends_fn_nonpositive_fraction": float(a[:, 2].sum() / ends) if ends
                     else ga.NOT_AVAILABLE}
    return out


# ---------------------------------------------------------------- entries

def _row(name, description, unit, measured, base=None):
    """A summary entry (the fields of grflow_analysis.summary's entries);
    with ``base``, the paper's value, tolerance and comparison of that
    present entry, so a number under another definition is held to the
    same paper value; without, no paper value."""
    if base is not None:
        paper, tol, comparison, source = ga.PAPER[base]
        source = "as %s: %s" % (base, source)
    else:
        paper, tol, comparison, source = None, None, None, "no number given"
    return {"name": name, "description": description, "unit": unit, "measured": measured,
            "paper": paper, "tolerance": tol, "comparison": comparison,
            "match": ga._match(measured, paper, tol, comparison), "paper_source": source}


def _ms(x):
    return "%gms" % x


def definitions(series, events, ru_liq, sample_ms=(), knee=False, block_ms=(),
                percentile=None, overlaps=False, run_dir=None, states=None):
    """Summary entries for the options of issue 30, beside the present ones.

    ``sample_ms``: output intervals (ms) to decimate the series to
    (:func:`decimate`); for each, the exits, their z_g, the inflections
    (and knees with ``knee``), the smallest z_g after IL (and its
    ``percentile``-th percentile) and the I statistics are recomputed from
    the decimated rows.  ``knee``: the knee of each exit's fitted logistic
    at the written sampling.  ``block_ms``: windows (ms) of block-averaged
    p for I (:func:`block_inertial`).  ``percentile``: q of the q-th
    percentile of z_g after IL.  ``overlaps``: z_g counting all overlaps
    at the snapshot states of cycle C (``states``: its rows, from
    :func:`grflow_analysis.choose_cycle`), read from ``run_dir``.

    Returns a dict: ``entries`` (list, the fields of the summary's),
    ``options`` (as given), ``overlaps`` (per state, if asked) and
    ``sampled`` (the raw statistics per sampling, for the JSON).
    """
    entries = []
    sampled = {}
    opts = {"sample_ms": [float(x) for x in sample_ms], "knee": bool(knee),
            "block_ms": [float(x) for x in block_ms], "percentile": percentile,
            "overlaps": bool(overlaps)}
    if percentile is not None and not 0.0 <= float(percentile) <= 100.0:
        raise ValueError("percentile %r not in [0, 100]" % (percentile,))
    full = sampled_stats(series, events, ru_liq, percentile)
    sampled["written"] = full
    qname = None if percentile is None else "z_g_post_IL_p%g" % percentile
    if knee:
        entries += [
            _row("z_g_knees",
                 "per exit: z_g at the knee of the same logistic as z_g_inflections, "
                 "where it reaches its lower asymptote + %g of its jump (a + %g b, at "
                 "N0 - w ln %g)" % (ga.KNEE_FRACTION, ga.KNEE_FRACTION,
                                    (1 - ga.KNEE_FRACTION) / ga.KNEE_FRACTION),
                 "-", full["z_g_knees"] if full["z_g_knees"] else full["z_g_knee_mean"]),
            _row("z_g_knee_mean", "mean of z_g_knees", "-", full["z_g_knee_mean"]),
            _row("knee_N_before_inflection_mean",
                 "mean of N0 - N_knee (cycles) over the fits: how far the knee comes "
                 "before the inflection", "-",
                 float(np.mean(full["knee_N_before_inflection"]))
                 if full["knee_N_before_inflection"] else full["z_g_knee_mean"]),
        ]
    if percentile is not None:
        entries.append(_row(qname, "percentile q = %g of z_g over the rows from initial "
                            "liquefaction on (numpy percentile, linear interpolation between "
                            "order statistics), beside z_g_post_IL_min" % percentile, "-",
                            full["z_g_post_IL_pct"]))
    for w in opts["block_ms"]:
        b = block_inertial(series, w * 1e-3, full.get("onset"))
        sampled["block_%s" % _ms(w)] = b
        how = ("I = K / sqrt(p_block), p_block the mean p over blocks of %g ms of "
               "simulated time (aligned on multiples of %g ms), K the decks' factor "
               "(v_x/h) d_mean sqrt(density) from the series" % (w, w))
        tag = "inertial_block%s" % _ms(w)
        entries += [
            _row(tag + "_max", "largest block I; " + how, "-", b["max"], "inertial_max"),
            _row(tag + "_max_pre_IL", "largest block I of the blocks before initial "
                 "liquefaction", "-", b["max_pre_IL"], "inertial_max_pre_IL"),
            _row(tag + "_median_post_IL", "median block I of the blocks from initial "
                 "liquefaction on, where p_block > 0", "-", b["median_post_IL"]),
            _row(tag + "_undefined_blocks", "blocks with p_block <= 0 (no I; not clipped), "
                 "of %d blocks; %s after initial liquefaction"
                 % (b["blocks"], b["undefined_blocks_post_IL"]), "-", b["undefined_blocks"]),
            _row("p_block%s_min_post_IL" % _ms(w), "smallest block-mean p from initial "
                 "liquefaction on", "Pa", b["p_block_min_post_IL"]),
        ]
    for ms in opts["sample_ms"]:
        dec, idx = decimate(series, ms * 1e-3)
        ev = events_on_rows(events, idx)
        st = sampled_stats(dec, ev, ru_liq, percentile)
        sampled[_ms(ms)] = st
        sfx = "@" + _ms(ms)
        how = ("series decimated to %g ms (the row nearest to each multiple of %g ms of "
               "simulated time: %d of %d rows)" % (ms, ms, st["rows"], len(series["time"])))
        if st["rows"] == 0:
            entries.append(_row("rows" + sfx, how, "-", ga.NOT_AVAILABLE))
            continue
        entries += [
            _row("n_exits" + sfx, "number of exits; " + how, "-", st["n_exits"]),
            _row("z_g_exit_mean" + sfx, "mean z_g at the exits, " + how, "-",
                 st["z_g_exit_mean"], "z_g_exit_mean"),
            _row("z_g_exit_std" + sfx, "population standard deviation of z_g at the exits, "
                 + how, "-", st["z_g_exit_std"]),
            _row("z_g_inflection_mean" + sfx, "mean z_g at the logistic inflections "
                 "(%d fits: an exit needs 5 rows within %g cycles), %s"
                 % (st["n_fits"], ga.INFLECTION_HALF_WINDOW_N, how), "-",
                 st["z_g_inflection_mean"], "z_g_inflection_mean"),
        ]
        if knee:
            entries.append(_row("z_g_knee_mean" + sfx, "mean z_g at the knees of the same "
                                "fits, " + how, "-", st["z_g_knee_mean"]))
        entries.append(_row("z_g_post_IL_min" + sfx, "smallest z_g after initial "
                            "liquefaction, " + how, "-", st["z_g_post_IL_min"],
                            "z_g_post_IL_min"))
        if percentile is not None:
            entries.append(_row(qname + sfx, "percentile q = %g of z_g after initial "
                                "liquefaction, %s" % (percentile, how), "-",
                                st["z_g_post_IL_pct"]))
        entries += [
            _row("inertial_max" + sfx, "largest written I where p > 0, " + how, "-",
                 st["inertial_max"], "inertial_max"),
            _row("inertial_median_post_IL" + sfx, "median written I after initial "
                 "liquefaction, " + how, "-", st["inertial_median_post_IL"]),
            _row("p_min_post_IL" + sfx, "smallest p after initial liquefaction, " + how,
                 "Pa", st["p_min_post_IL"]),
        ]
    out = {"options": opts, "entries": entries, "sampled": sampled}
    if overlaps:
        ov = overlaps_at_states(run_dir, series, states) if run_dir else {}
        out["overlaps"] = ov
        allsnap = (overlaps_over_snapshots(run_dir, series, events["step_IL"])
                   if run_dir else {})
        out["overlaps_post_IL"] = allsnap
        for kind, label in (("crossings", "the first zero-crossings of tau after a "
                             "reversal (as C0, C2)"),
                            ("reversals", "the reversals (as C1, C3)")):
            x = allsnap.get(kind) if isinstance(allsnap, dict) else None
            if isinstance(allsnap, str):
                meas = allsnap
            elif not x or not x["snapshots"]:
                meas = ga.NOT_AVAILABLE
            else:
                meas = x["difference_mean"]
            desc = ("mean over the snapshots at %s from initial liquefaction on of z_g "
                    "counting all overlaps minus z_g counting f_n > 0, both from the same "
                    "snapshot" % label)
            if x and x.get("snapshots"):
                desc += ("; %d snapshots, means %s (f_n > 0) and %s (all overlaps), largest "
                         "difference %s, %s of the counted contact ends have f_n <= 0"
                         % (x["snapshots"], ga._fmt(x["z_g_fn_positive_mean"]),
                            ga._fmt(x["z_g_all_overlaps_mean"]),
                            ga._fmt(x["difference_max"]),
                            ga._fmt(x["ends_fn_nonpositive_fraction"])))
            entries.append(_row("z_g_all_overlaps_minus_fn_positive_%s" % kind, desc,
                                "-", meas))
        # the paper's z_g takes N_p as "the total number of particles": the
        # same snapshots with the sub-volume the whole height (every free
        # particle; the glued ones stay out, as in compute net)
        for kind, label in (("crossings", "the first zero-crossings of tau after a reversal"),
                            ("reversals", "the reversals")):
            x = allsnap.get(kind) if isinstance(allsnap, dict) else None
            if isinstance(allsnap, str):
                meas, desc_more = allsnap, ""
            elif not x or not x["snapshots"]:
                meas, desc_more = ga.NOT_AVAILABLE, ""
            else:
                meas = x["z_g_whole_height_mean"] - x["z_g_fn_positive_mean"]
                desc_more = "; %d snapshots, means %s (whole height) and %s (slab %g)" % (
                    x["snapshots"], ga._fmt(x["z_g_whole_height_mean"]),
                    ga._fmt(x["z_g_fn_positive_mean"]), DECK_SLAB)
            entries.append(_row(
                "z_g_whole_height_minus_slab_%s" % kind,
                "mean over the snapshots at %s from initial liquefaction on of z_g (f_n > 0) "
                "over every free particle of the whole height minus z_g of the decks' "
                "central slab, both from the same snapshot%s" % (label, desc_more), "-", meas))
        for stn in OVERLAP_STATES:
            d = ov.get(stn, ga.NOT_AVAILABLE)
            meas = d["z_g_all_overlaps"] if isinstance(d, dict) else d
            if isinstance(d, dict):
                beside = ("snapshot step %d: z_g of the same snapshot with f_n > 0 only "
                          "(the compute's rule) %s; series z_g at the state's row, step "
                          "%d: %s" % (d["snapshot_step"], ga._fmt(d["z_g_fn_positive_check"]),
                                      d["row_step"], ga._fmt(d["z_g_series"])))
            else:
                beside = "no snapshot"
            entries.append(_row(
                "z_g_all_overlaps_%s" % stn,
                "z_g counting all overlaps (every pair of the contacts snapshot, f_n <= 0 "
                "too; the sub-volume, floaters and wall rule of compute grflow/network) at "
                "%s of cycle C; %s" % (stn, beside), "-", meas))
    return out


def definitions_markdown(d):
    """The options' entries as a markdown section (for summary.md)."""
    lines = ["", "## Sampling and definitions (issue 30; options of grflow-figures)", "",
             "| quantity | measured | paper | tolerance | match |",
             "| --- | --- | --- | --- | --- |"]
    for e in d["entries"]:
        u = e["unit"]
        lines.append("| %s (%s) | %s | %s | %s | %s |" % (
            e["name"], e["description"], ga._fmt(e["measured"], u), ga._fmt(e["paper"], u),
            ga.tolerance_cell(e), ga.match_cell(e)))
    ov = d.get("overlaps")
    if ov:
        lines += ["", "z_g counting all overlaps at the snapshot states of cycle C "
                  "(zg_overlaps(); the series' z_g is compute grflow/network's, f_n > 0; "
                  "the check applies that rule to the snapshot: equal to the series' z_g "
                  "when the snapshot and the row are on the same step):", "",
                  "| state | snapshot step | row step | z_g series | z_g f_n > 0 (snapshot, "
                  "check) | z_g all overlaps | ends with f_n <= 0 | floaters f_n > 0 / all "
                  "| entries / f_n <= 0 / unresolved |",
                  "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
        for st, x in ov.items():
            if not isinstance(x, dict):
                lines.append("| %s | %s |  |  |  |  |  |  |  |" % (st, x))
                continue
            lines.append("| %s | %d | %d | %s | %s | %s | %d | %d / %d | %d / %d / %d |" % (
                st, x["snapshot_step"], x["row_step"], ga._fmt(x["z_g_series"]),
                ga._fmt(x["z_g_fn_positive_check"]), ga._fmt(x["z_g_all_overlaps"]),
                x["ends_fn_nonpositive"], x["floaters_fn_positive"],
                x["floaters_all_overlaps"], x["entries"], x["entries_fn_nonpositive"],
                x["entries_unresolved"]))
    return "\n".join(lines) + "\n"
