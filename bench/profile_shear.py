#!/usr/bin/env python3
"""Where the shear stage's time goes, from its own log: the LAMMPS timing
breakdown (Pair, Neigh, Comm, Output, Modify, Other) of every run segment
of a log.shear.lammps (the deck splits the stage at every event), summed
separately before and after initial liquefaction.

    python3 bench/profile_shear.py RUNDIR/log.shear.lammps [--whole]

--whole: one sum over all segments (no split at initial liquefaction).

A segment counts as "after" when it starts at or after the step of initial
liquefaction (from the log's last line, or from the first progress line
marked "(liquefied)" -- that one is a reversal, so up to one half cycle
after it is then counted as "before").  Times are the "avg time" column
(the mean over MPI ranks); "max" is the slowest rank's, whose excess over
the mean is load imbalance.
"""
import re
import sys

SECTIONS = ["Pair", "Neigh", "Comm", "Output", "Modify", "Other"]


def parse(path):
    """[(first step, steps, atoms, procs, loop time, {section: (avg, max)})]
    per run segment, and the step of initial liquefaction (or None)."""
    segments = []
    step = 0    # the shear stage starts at step 0 (prepare.lmp resets it)
    step_il = None
    with open(path) as f:
        for line in f:
            m = re.match(r"GRFLOW shear: resuming at step (\d+)", line)
            if m:
                step = int(m.group(1))
            m = re.match(r"Loop time of ([\d.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms",
                         line)
            if m:
                loop, procs, n, atoms = float(m.group(1)), int(m.group(2)), int(m.group(3)), int(m.group(4))
                segments.append([step, n, atoms, procs, loop, {}])
                step += n
                continue
            m = re.match(r"(Pair|Neigh|Comm|Output|Modify|Other)\s*\|(.*)", line)
            if m and segments:
                cols = [c.strip() for c in m.group(2).split("|")]
                if m.group(1) == "Other":
                    avg, mx = float(cols[1]), float(cols[1])
                else:
                    avg, mx = float(cols[1]), float(cols[2])
                segments[-1][5][m.group(1)] = (avg, mx)
            m = re.search(r"initial liquefaction at step (\d+)", line)
            if m:
                step_il = int(m.group(1))
            m = re.search(r"step (\d+) gamma .* \(liquefied\)", line)
            if m and step_il is None:
                step_il = int(m.group(1))
    return segments, step_il


def summarize(segments, step_il, split=True):
    """sums per phase: "before" and "after" initial liquefaction, or with
    split False (or no liquefaction in the log) one phase, "all"."""
    if not split or step_il is None:
        phases = {"all": list(segments)}
    else:
        phases = {"before": [], "after": []}
        for seg in segments:
            phases["after" if seg[0] >= step_il else "before"].append(seg)
    out = {}
    for name, segs in phases.items():
        steps = sum(s[1] for s in segs)
        loop = sum(s[4] for s in segs)
        sec = {k: sum(s[5].get(k, (0.0, 0.0))[0] for s in segs) for k in SECTIONS}
        secmax = {k: sum(s[5].get(k, (0.0, 0.0))[1] for s in segs) for k in SECTIONS}
        atoms = segs[0][2] if segs else 0
        procs = segs[0][3] if segs else 0
        out[name] = dict(steps=steps, loop=loop, sections=sec, sections_max=secmax,
                         atoms=atoms, procs=procs, segments=len(segs))
    return out


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    segments, step_il = parse(sys.argv[1])
    if not segments:
        sys.exit(f"no run segments in {sys.argv[1]}")
    res = summarize(segments, step_il, "--whole" not in sys.argv[2:])
    print(f"# {sys.argv[1]}: {len(segments)} segments, initial liquefaction at step {step_il}")
    print("| section | " + " | ".join(f"{ph}: s | % | us/step" for ph in res) + " |")
    print("| --- |" + " --: | --: | --: |" * len(res))
    for k in SECTIONS + ["total"]:
        row = [k]
        for ph in res:
            r = res[ph]
            t = r["loop"] if k == "total" else r["sections"][k]
            pct = 100.0 * t / r["loop"] if r["loop"] > 0 else 0.0
            us = 1e6 * t / r["steps"] if r["steps"] else 0.0
            row += [f"{t:.1f}", f"{pct:.1f}", f"{us:.1f}"]
        print("| " + " | ".join(row) + " |")
    for ph in res:
        r = res[ph]
        if r["steps"]:
            imb = {k: r["sections_max"][k] - r["sections"][k] for k in SECTIONS if k != "Other"}
            print(f"# {ph}: {r['steps']} steps in {r['segments']} segments, {r['loop']:.1f} s, "
                  f"{r['steps'] / r['loop']:.0f} steps/s, {r['procs']} procs, "
                  f"{1e9 * r['loop'] * r['procs'] / (r['steps'] * r['atoms']):.1f} ns per atom-step "
                  f"(x procs); slowest rank minus mean: "
                  + ", ".join(f"{k} {v:.1f} s" for k, v in imb.items()))


if __name__ == "__main__":
    main()
