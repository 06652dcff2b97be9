# GRFLOW analysis: the cycles of a run from fix grflow/shear's events:
# fractional cycle count, initial liquefaction and its exits, cycle states.
# Part of GRFLOW, distributed under the GNU General Public License v2
# (see LICENSE at the top of the repository).
"""The cycles of a run: fix grflow/shear's events placed on the series,
the fractional cycle count, initial liquefaction and its exits, and the
states of a cycle.

Definitions (section numbers of the paper, paper/isochoric-cyclic-shearing.md):

* fractional cycle count N (inputs/README.md; decided by fix grflow/shear,
  src/shared/grflow_cycle_count.h): shear starts at N = 0; reversal k is at
  N = k/2 - 1/4, the first zero-crossing of tau after it at N = k/2; linear
  in time in between (see :func:`cycle_count`).  The events and N_IL are
  the fix's, read from events.txt (:func:`run_events`), and nothing here
  finds them again in the series: a run without events.txt is an error;
* initial liquefaction: the fix's step of the first r_u >= ru_liq, N_IL
  its N (sec. 3);
* liquefaction exit: a row after the onset with r_u < ru_liq whose previous
  row had r_u >= ru_liq (sec. 3: "exits liquefaction state when r_u < 0.99");
* cycle n runs from N = n to N = n + 1; its states (sec. 3, Fig. 2) are
  C0 (N = n), C0' (first exit at or after C0, before C1), C1 (N = n + 1/4),
  C2 (N = n + 1/2), C2' (first exit at or after C2, before C3),
  C3 (N = n + 3/4) (see :func:`find_cycle_states`).
"""

import os

import numpy as np

from .readers import DEFAULT_RU_LIQ, FormatError, read_events

STATES = ("C0", "C0'", "C1", "C2", "C2'", "C3")


def fix_events(table, series):
    """The events of fix grflow/shear (:func:`read_events`) placed on the
    series: a dict with ``reversal_rows`` (list; entry k-1 is the row of
    reversal k, None if unknown), ``crossing_rows`` (dict k -> row or None:
    the first zero-crossing of tau after reversal k; k = 0 is the shear
    start), ``rows``, ``N`` and ``time`` (every event in time order, with
    its N and time, for :func:`cycle_count`), ``N_IL`` (the fix's N at
    initial liquefaction, None if not known) and ``step_IL`` (None before
    it).  An event's row is the first series row at or after its step.  A
    zero-crossing seen on the same check as the next reversal is flagged as
    the reversal only; its row is that reversal's.
    """
    step = series["step"]
    nrow = len(step)

    def row_of(st):
        r = int(np.searchsorted(step, st, side="left"))
        return r if r < nrow else None

    kinds, revs = table["event"].astype(int), np.rint(table["reversals"]).astype(int)
    reversal_rows, crossing_rows = [], {0: row_of(table["step"][0])}
    for i in range(1, len(kinds)):
        k = revs[i]
        if kinds[i] == 1:
            # a reversal on the setup of the first run (tau >= tau_amp at
            # once) has no line: its row is unknown
            while len(reversal_rows) < k - 1:
                reversal_rows.append(None)
            reversal_rows.append(row_of(table["step"][i]))
            if k - 1 >= 1 and k - 1 not in crossing_rows:
                crossing_rows[k - 1] = reversal_rows[-1]
        else:
            crossing_rows[k] = row_of(table["step"][i])
    kmax = len(reversal_rows)
    for k in range(1, kmax + 1):
        crossing_rows.setdefault(k, None)
    rows = [row_of(st) for st in table["step"]]
    known = table["N_IL"][table["N_IL"] >= 0]
    st_il = table["step_IL"][table["step_IL"] >= 0]
    return {"reversal_rows": reversal_rows, "crossing_rows": crossing_rows,
            "rows": rows, "N": [float(n) for n in table["N"]],
            "time": [float(t) for t in table["time"]],
            "N_IL": float(known[-1]) if len(known) else None,
            "step_IL": int(st_il[-1]) if len(st_il) else None}


def run_events(run_dir, series):
    """The cycle events of a run: fix grflow/shear's, from ``events.txt``
    (:func:`read_events`, :func:`fix_events`).  They are the only source of
    the events and of N_IL: a run directory without ``events.txt`` (written
    before the fix wrote it, or incomplete) raises FormatError."""
    path = os.path.join(run_dir, "events.txt")
    if not os.path.isfile(path):
        raise FormatError("%s: no events.txt.  The cycle events and N_IL are fix "
                          "grflow/shear's, which the decks write there (inputs/README.md); "
                          "this directory was written before events.txt existed, or by "
                          "a run that did not reach the shear stage" % run_dir)
    return fix_events(read_events(path), series)


def liquefaction_n(events, onset):
    """N_IL: fix grflow/shear's (events["N_IL"]); None if initial
    liquefaction was not reached (``onset`` None) or no event came after
    it yet (the fix knows N_IL from the event after it on)."""
    if onset is None:
        return None
    return events["N_IL"]


def cycle_count(series, events):
    """Fractional number of cycles N at every row (inputs/README.md).

    N is that of the fix's events (``events`` of :func:`run_events`) at
    their own times, and linear in time between events.  After the last
    event N is extrapolated linearly with the rate of the last interval
    between events (a quarter cycle), capped at a quarter cycle beyond the
    last event (the next event has not happened).  Before any reversal no
    rate is known and N stays 0.  Rows before the first event (a series
    not starting at the shear start) take the first event's N.
    """
    t = series["time"]
    et, en = list(events["time"]), list(events["N"])
    if not et:
        return np.zeros_like(t)
    N = np.interp(t, et, en)
    if len(et) >= 2 and et[-1] > et[-2]:
        rate = (en[-1] - en[-2]) / (et[-1] - et[-2])
        after = t > et[-1]
        N[after] = en[-1] + np.minimum(rate * (t[after] - et[-1]), 0.25)
    return N


def liquefaction(series, events, ru_liq=DEFAULT_RU_LIQ):
    """Initial liquefaction and exits.

    Returns a dict: ``onset`` (the first row at or after the fix's step of
    initial liquefaction, events["step_IL"]; None if not reached, or not
    within the series), ``exits`` (rows after the onset with r_u < ru_liq
    whose previous row has r_u >= ru_liq) and ``entries`` (rows after the
    onset with r_u >= ru_liq whose previous row has r_u < ru_liq).
    """
    ru = series["r_u"]
    st = events["step_IL"]
    onset = None if st is None else int(np.searchsorted(series["step"], st, side="left"))
    if onset is None or onset >= len(ru):
        return {"onset": None, "exits": [], "entries": []}
    liq = ru >= ru_liq
    below = ru < ru_liq
    idx = np.arange(onset + 1, len(ru))
    exits = idx[below[idx] & liq[idx - 1]]
    entries = idx[liq[idx] & below[idx - 1]]
    return {"onset": onset, "exits": [int(i) for i in exits],
            "entries": [int(i) for i in entries]}


def find_cycle_states(series, events, cycle, ru_liq=DEFAULT_RU_LIQ, liq=None):
    """Rows of the six states of cycle ``cycle`` (n >= 0); None where not found.

    C0: the first zero-crossing of tau after reversal 2n (the start of
    loading towards +tau_amp; for n = 0 the shear start); C1: reversal 2n+1
    (tau reached +tau_amp); C2: the first zero-crossing after reversal
    2n+1; C3: reversal 2n+2 (tau reached -tau_amp), all as the fix's
    ``events``; C0': first liquefaction exit at or after C0 and before C1
    (before the end of the series if C1 is not reached); C2': the same
    between C2 and C3.
    """
    if liq is None:
        liq = liquefaction(series, events, ru_liq)
    rr, cr = events["reversal_rows"], events["crossing_rows"]

    def reversal(k):
        return rr[k - 1] if 1 <= k <= len(rr) else None

    def first_exit(lo, hi):
        if lo is None:
            return None
        for e in liq["exits"]:
            if e >= lo and (hi is None or e < hi):
                return e
            if hi is not None and e >= hi:
                break
        return None

    n = int(cycle)
    st = {"C0": cr.get(2 * n), "C1": reversal(2 * n + 1),
          "C2": cr.get(2 * n + 1), "C3": reversal(2 * n + 2)}
    st["C0'"] = first_exit(st["C0"], st["C1"])
    st["C2'"] = first_exit(st["C2"], st["C3"])
    return {s: st[s] for s in STATES}


def post_liquefaction_cycles(series, events, ru_liq=DEFAULT_RU_LIQ, liq=None):
    """Cycles n whose C0 is at or after the onset of liquefaction, in order."""
    if liq is None:
        liq = liquefaction(series, events, ru_liq)
    if liq["onset"] is None:
        return []
    return [k // 2 for k, row in sorted(events["crossing_rows"].items())
            if k % 2 == 0 and row is not None and row >= liq["onset"]]


def choose_cycle(series, events, ru_liq=DEFAULT_RU_LIQ, index=None, liq=None):
    """Pick cycle C.

    With ``index`` None: the first post-liquefaction cycle with all six
    states found; otherwise the ``index``-th (0-based) post-liquefaction
    cycle.  Returns (n, states, note): n and states None when there is no
    such cycle, note a short reason (or "").
    """
    if liq is None:
        liq = liquefaction(series, events, ru_liq)
    if liq["onset"] is None:
        return None, None, "initial liquefaction not reached"
    cycles = post_liquefaction_cycles(series, events, ru_liq, liq)
    if index is not None:
        if not 0 <= index < len(cycles):
            return None, None, ("post-liquefaction cycle %d not reached (%d found)"
                                % (index, len(cycles)))
        n = cycles[index]
        return n, find_cycle_states(series, events, n, ru_liq, liq), ""
    for n in cycles:
        st = find_cycle_states(series, events, n, ru_liq, liq)
        if all(v is not None for v in st.values()):
            return n, st, ""
    return None, None, "no post-liquefaction cycle with all six states"


def cycle_rows(series, events, n):
    """Row range [first, last] of cycle n: from its C0 to the next C0 (or the end)."""
    first = events["crossing_rows"].get(2 * n)
    if first is None:
        return None
    last = events["crossing_rows"].get(2 * n + 2)
    return first, (last if last is not None else len(series["time"]) - 1)
