#!/usr/bin/python3
# GRFLOW - calibration of the preparation friction mu_prep.
# Copyright the GRFLOW developers; GNU General Public License version 2.
"""Find the preparation friction mu_prep that gives the void ratio
e = 0.647 +- 0.005 at 100 kPa (the paper's sample) for a given N and seed.

Each evaluation runs the preparation stage of inputs/cyclic_shear.lmp
(-var stage prep: sample, compression with mu_prep, the agitation stage
with its recompression at mu_rec unless agitate_dilation is 1, mu_t = 0.5
and re-equilibration) and reads e from prep.json.  e grows with mu_prep, so
the search brackets the target between --lo and --hi and then narrows the
bracket by regula falsi (with bisection steps when one end stalls).  It
prints e against mu_prep as it goes and writes the table to
WORKDIR/calibration.txt.  --try evaluates candidates first (a value known
from an earlier search, to check it still holds): one within the tolerance
ends the search, the others narrow the bracket in place of --lo or --hi.

    /usr/bin/python3 inputs/calibrate_mu_prep.py                 # N = 8000, default seed
    /usr/bin/python3 inputs/calibrate_mu_prep.py --N 400 --np 2
    /usr/bin/python3 inputs/calibrate_mu_prep.py --var rate_max 5   # any other -var
    /usr/bin/python3 inputs/calibrate_mu_prep.py --try 0.095         # check a candidate first

Every run counts towards --max-runs (the tries and both bracket ends
included).  Exit status 0 when a value within the tolerance was found; 1
if none was within --max-runs, or the bracket shrank below the 5 decimals
of the trial values; 2 for bad arguments, or a target not bracketed (by
--lo and --hi, or tries whose e does not grow with mu_prep); 3 if a
preparation failed.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run_prep(args, mu):
    out = os.path.join(args.workdir, f"mu_{mu:.5f}")
    cmd = [] if args.np <= 1 else [args.mpirun, "--allow-run-as-root", "--oversubscribe",
                                   "-np", str(args.np)]
    cmd += [args.lmp, "-in", os.path.join(HERE, "cyclic_shear.lmp"), "-log", "none",
            "-screen", "none", "-var", "inputs", HERE, "-var", "stage", "prep",
            "-var", "preset", args.preset, "-var", "N", str(args.N),
            "-var", "seed", str(args.seed), "-var", "mu_prep", repr(mu), "-var", "outdir", out]
    for name, value in args.var:
        cmd += ["-var", name, value]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    prep = os.path.join(out, "prep.json")
    if proc.returncode != 0 or not os.path.exists(prep):
        log = os.path.join(out, "log.prep.lammps")
        print(f"preparation failed for mu_prep = {mu} (exit {proc.returncode}); see {log}\n"
              + proc.stdout[-2000:] + proc.stderr[-2000:], file=sys.stderr)
        sys.exit(3)
    with open(prep) as f:
        e = json.load(f)["e"]
    return e


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--N", type=int, default=8000)
    ap.add_argument("--seed", type=int, default=5827)
    ap.add_argument("--target", type=float, default=0.647)
    ap.add_argument("--tol", type=float, default=0.005)
    ap.add_argument("--lo", type=float, default=0.0, help="lowest mu_prep tried")
    ap.add_argument("--hi", type=float, default=0.3, help="highest mu_prep tried")
    ap.add_argument("--try", dest="tries", type=float, nargs="+", default=[], metavar="MU",
                    help="candidates evaluated before the bracket")
    ap.add_argument("--max-runs", type=int, default=10)
    ap.add_argument("--preset", default="paper")
    ap.add_argument("--np", type=int, default=1, help="MPI ranks per run")
    ap.add_argument("--lmp", default=shutil.which("lmp") or "lmp")
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--workdir", default="runs/calibration")
    ap.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                    help="extra -var for the deck")
    args = ap.parse_args()
    if not 0 <= args.lo < args.hi:
        ap.error(f"need 0 <= --lo < --hi, got --lo {args.lo} --hi {args.hi}")
    if args.tol <= 0 or args.max_runs < 1:
        ap.error("--tol must be > 0 and --max-runs >= 1")
    if any(not args.lo <= mu <= args.hi for mu in args.tries):
        ap.error(f"--try values must lie in [--lo, --hi] = [{args.lo}, {args.hi}]")
    tries = list(dict.fromkeys(round(mu, 5) for mu in args.tries))
    if args.max_runs < len(tries) + 2:
        ap.error(f"--max-runs {args.max_runs} leaves no room for {len(tries)} tries "
                 "and the two bracket ends")
    os.makedirs(args.workdir, exist_ok=True)

    table = []

    # trial values have 5 decimals: the value run is the one printed, named
    # in WORKDIR and given back to --try
    def evaluate(mu):
        assert mu == round(mu, 5)
        e = run_prep(args, mu)
        table.append((mu, e))
        print(f"mu_prep = {mu:.5f}   e = {e:.4f}", flush=True)
        with open(os.path.join(args.workdir, "calibration.txt"), "w") as f:
            f.write(f"# N = {args.N}, seed = {args.seed}, target e = {args.target} +- {args.tol}\n")
            f.write("# mu_prep e\n")
            for m, v in sorted(table):
                f.write(f"{m:.5f} {v:.6f}\n")
        return e

    print(f"calibrating mu_prep for e = {args.target} +- {args.tol}, N = {args.N}, "
          f"seed = {args.seed}")

    def within(entry):
        return abs(entry[1] - args.target) <= args.tol

    for mu in tries:
        if within((mu, evaluate(mu))):
            print(f"found mu_prep = {mu:.5f} (e = {table[-1][1]:.4f})")
            return 0
    # the tries below / above the target replace the bracket's ends
    below = [t for t in table if t[1] < args.target]
    above = [t for t in table if t[1] > args.target]
    lo, elo = max(below) if below else (round(args.lo, 5), None)
    hi, ehi = min(above) if above else (round(args.hi, 5), None)
    if lo >= hi:
        runs = ", ".join(f"e({m:.5f}) = {v:.4f}" for m, v in sorted(table))
        print(f"target e = {args.target} not bracketed: e is below it at mu_prep = {lo:.5f}, "
              f"not below the bracket's upper end {hi:.5f} ({runs})")
        return 2
    if elo is None:
        elo = evaluate(lo)
    if ehi is None:
        ehi = evaluate(hi)
    best = min(table, key=lambda t: abs(t[1] - args.target))
    if not (elo <= args.target <= ehi):
        if within(best):
            print(f"found mu_prep = {best[0]:.5f} (e = {best[1]:.4f})")
            return 0
        print(f"target e = {args.target} not between e({lo}) = {elo:.4f} and e({hi}) = {ehi:.4f}")
        return 2
    side = 0
    while not within(best) and len(table) < args.max_runs:
        # regula falsi, with a bisection step after two moves of the same end
        mu = lo + (args.target - elo) * (hi - lo) / (ehi - elo) if ehi > elo else 0.5 * (lo + hi)
        if abs(side) >= 2:
            mu = 0.5 * (lo + hi)
            side = 0
        mu = round(mu, 5)
        if mu in (lo, hi):
            mu = round(0.5 * (lo + hi), 5)
        if mu in (lo, hi):
            print(f"the bracket [{lo:.5f}, {hi:.5f}] is narrower than the 5 decimals of mu_prep")
            break
        e = evaluate(mu)
        if e < args.target:
            lo, elo = mu, e
            side = side + 1 if side >= 0 else 1
        else:
            hi, ehi = mu, e
            side = side - 1 if side <= 0 else -1
        best = min(table, key=lambda t: abs(t[1] - args.target))
    if within(best):
        print(f"found mu_prep = {best[0]:.5f} (e = {best[1]:.4f})")
        return 0
    print(f"not within tolerance after {len(table)} runs; closest: mu_prep = {best[0]:.5f} "
          f"(e = {best[1]:.4f})")
    return 1


if __name__ == "__main__":
    sys.exit(main())
