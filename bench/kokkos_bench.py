#!/usr/bin/env python3
"""Read the logs of bench/kokkos_bench.lmp and tabulate the speed of each
pair style at each size.

usage: kokkos_bench.py LOG... [--json FILE]

From each timed run (between GRFLOW_KK_BENCH_BEGIN <style> <n> and
GRFLOW_KK_BENCH_END <style> <n>): the loop time, steps, atoms, "Total # of
neighbors" (pairs in the half lists, newton off: a pair of an owned atom
and a ghost counts on both sides) and the Pair row of the timing table.
Reported per run: steps/s = steps / loop time, and ns per neighbor pair per
step = loop time / (steps * neighbors) * 1e9, the whole step (pair,
neighbor lists, integration, communication) per pair.  The Pair row is
printed too; on a GPU it holds only what the host waited for (LAMMPS does
not fence the device there), so the loop time is the measure.  For each
size the ratio of granular/grflow/kk to gran/hooke/history/kk is given.
Runs of granular/grflow also give the number of touching pairs at the end
of the timed run (GRFLOW_KK_BENCH_CONTACTS after its frame: N_c of compute
grflow/network by a run 0), and the Pair row
per touching pair and step; runs made with CUDA_LAUNCH_BLOCKING=1 (labelled
grflow_blocking by kokkos_bench.sh) make that row the pair kernels' time.
Standard library only (the GPU check runs it).
"""
import argparse
import json
import re
import sys


def parse(path):
    """the timed runs of one log: a list of dicts"""
    runs, cur = [], None
    with open(path) as f:
        for line in f:
            s = line.strip()
            m = re.match(r"GRFLOW_KK_BENCH_BEGIN (\S+) (\d+)", s)
            if m:
                cur = {"style": m.group(1), "n": int(m.group(2)), "log": path}
                continue
            m = re.match(r"GRFLOW_KK_BENCH_CONTACTS (\S+) (\d+) (\S+)", s)
            if m:
                # after the frame: the touching pairs at its end (run 0)
                for r in runs:
                    if (r["style"], r["n"]) == (m.group(1), int(m.group(2))):
                        r["contacts"] = float(m.group(3))
                continue
            if cur is None:
                continue
            if re.match(r"GRFLOW_KK_BENCH_END", s):
                need = ("loop_s", "steps", "atoms", "neighbors")
                if not all(k in cur for k in need):
                    raise SystemExit(f"kokkos_bench.py: {path}: incomplete timed run {cur}")
                runs.append(cur)
                cur = None
                continue
            m = re.match(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms", s)
            if m:
                cur.update(loop_s=float(m.group(1)), procs=int(m.group(2)),
                           steps=int(m.group(3)), atoms=int(m.group(4)))
                continue
            m = re.match(r"Pair\s*\|(.*)", s)
            if m:
                cur["pair_s"] = float(m.group(1).split("|")[1])
                continue
            m = re.match(r"Total # of neighbors = (\d+)", s)
            if m:
                cur["neighbors"] = int(m.group(1))
                continue
            m = re.search(r"(\d+) by (\d+) by (\d+) MPI processor grid", s)
            if m:
                cur["grid"] = s
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("logs", nargs="+")
    ap.add_argument("--json")
    args = ap.parse_args()
    runs = [r for p in args.logs for r in parse(p)]
    if not runs:
        raise SystemExit("kokkos_bench.py: no timed run in the logs")
    for r in runs:
        r["steps_per_s"] = r["steps"] / r["loop_s"]
        r["ns_per_pair_step"] = r["loop_s"] / (r["steps"] * r["neighbors"]) * 1e9
        if "pair_s" in r:
            r["pair_ns_per_pair_step"] = r["pair_s"] / (r["steps"] * r["neighbors"]) * 1e9
        if "pair_s" in r and r.get("contacts", 0) > 0:
            r["pair_ns_per_contact_step"] = r["pair_s"] / (r["steps"] * r["contacts"]) * 1e9
    print(f"{'style':16} {'atoms':>9} {'neighbors':>11} {'steps':>6} {'loop s':>9} "
          f"{'steps/s':>9} {'ns/pair/step':>13} {'(Pair row)':>11}")
    for r in sorted(runs, key=lambda r: (r["n"], r["style"])):
        pair = f"{r['pair_ns_per_pair_step']:11.3f}" if "pair_s" in r else f"{'-':>11}"
        print(f"{r['style']:16} {r['atoms']:9d} {r['neighbors']:11d} {r['steps']:6d} "
              f"{r['loop_s']:9.3f} {r['steps_per_s']:9.1f} {r['ns_per_pair_step']:13.3f} {pair}")
    contact_runs = [r for r in runs if "pair_ns_per_contact_step" in r]
    if contact_runs:
        print("\ngranular/grflow: the Pair row per touching pair (N_c of compute "
              "grflow/network after the timed run) and step; on a GPU only the\n"
              "runs labelled grflow_blocking (CUDA_LAUNCH_BLOCKING=1: every kernel waited "
              "for) time the pair kernels")
        print(f"{'label':16} {'atoms':>9} {'contacts':>10} {'Pair s':>9} {'ns/contact/step':>16}")
        for r in sorted(contact_runs, key=lambda r: (r["n"], r["style"])):
            print(f"{r['style']:16} {r['atoms']:9d} {r['contacts']:10.1f} {r['pair_s']:9.3f} "
                  f"{r['pair_ns_per_contact_step']:16.3f}")
    ratios = {}
    for n in sorted({r["n"] for r in runs}):
        best = {}
        for r in runs:
            if r["n"] == n and (r["style"] not in best or r["loop_s"] < best[r["style"]]["loop_s"]):
                best[r["style"]] = r
        if "grflow" in best and "hooke" in best:
            q = best["grflow"]["ns_per_pair_step"] / best["hooke"]["ns_per_pair_step"]
            ratios[str(best["grflow"]["atoms"])] = q
            print(f"{best['grflow']['atoms']} spheres: granular/grflow / gran/hooke/history, "
                  f"time per pair and step: {q:.2f}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"runs": runs, "grflow_over_hooke": ratios}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
