"""How far round-off carries the dense stage of the compression tests: the
measurement behind the thresholds of tests/python/test_compress_mpi.py and
test_liggghts_protocol_fixes.py's test_compress_dense_packing_same
(doc/studies/dense-roundoff.md).

Packings: the sparse cell of tests/decks/compress_cell.lmp compressed from
the gas to 100 kPa (GAS_STEPS steps at rate 200, as the LIGGGHTS test does,
with tests/decks/liggghts/compress_equivalence.lmp), the gas stage run with
round-off changed (newton, atom sorting, 2 MPI ranks; with LMP2 also by a
second LAMMPS): through jamming round-off grows to 1e-3 of the box, so each
gives another packing.  On each, the dense stage (DENSE_STEPS steps to
130 kPa at rate 20) is run by LMP with the deck's own settings (the
reference) and with changes that only change round-off:

  newton   newton on          sort  atom_modify sort 100
  x2, z2   2 MPI ranks (processors 2 1 1, 1 1 2)
  ulp      the x of atom 1 in the data file one ulp larger
  lmp2     LMP2 (another LAMMPS build) with the deck's settings
  liggghts LIGGGHTS's half of the test (compress_equivalence.liggghts)

and, on the packings named in KN_ON, with kn (pair and walls) times
1 + delta for each delta of KN_DELTAS: how the difference grows with the
size of a perturbation, from round-off's size to a systematic one.

Output: OUTDIR/table.txt, one line per packing and run: packing, run, the
relative differences to the reference at the last step of lx, ly, h, e,
sxx, syy, szz, and over all steps the largest difference of the servo's
error over its tolerance (0.01) and of the kinetic energy ratio over its
bound (1e-3), what the convergence flag compares; on stdout the same
lines, then the largest differences of each kind.  Runs whose record
exists are not run again.  2 runs at a time.

    grflow-python bench/dense_roundoff.py OUTDIR
    (or build/python/bin/python bench/dense_roundoff.py OUTDIR)

Environment: LMP (default build/lmp), LMP2 (optional), LIGGGHTS (optional),
GAS_STEPS (40000), DENSE_STEPS (20000), PACKINGS (how many of the gas
variants, default all: 10, and 6 more with LMP2), KN_ON ("lmp lmp_sort200
lmp2 lmp2_sort1000": a quiet packing and three loud ones of the record),
KN_DELTAS ("1e-15 1e-13 1e-11 1e-9 1e-7 1e-5 1e-3"), MPIEXEC (mpirun).
"""
import math
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

TOP = Path(__file__).resolve().parents[1]
DECKS = TOP / "tests" / "decks"
LMP = os.environ.get("LMP", str(TOP / "build" / "lmp"))
LMP2 = os.environ.get("LMP2", "")
LIGGGHTS = os.environ.get("LIGGGHTS", "")
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
GAS_STEPS = int(os.environ.get("GAS_STEPS", "40000"))
DENSE_STEPS = int(os.environ.get("DENSE_STEPS", "20000"))
KN_ON = os.environ.get("KN_ON", "lmp lmp_sort200 lmp2 lmp2_sort1000").split()
KN_DELTAS = os.environ.get("KN_DELTAS", "1e-15 1e-13 1e-11 1e-9 1e-7 1e-5 1e-3").split()
NAMES = ["converged", "sxx", "syy", "szz", "errmax", "ke", "eel", "ratio", "rate_x", "rate_y",
         "rate_z", "volume", "e", "lx", "ly", "h", "factor_x", "factor_y", "factor_z"]
BOX, STRESS = ("lx", "ly", "h", "e"), ("sxx", "syy", "szz")
TOL, KE_RATIO = 0.01, 1.0e-3    # fix grflow/compress's defaults, which the deck keeps

# the gas stage's variants: name -> (which LAMMPS, deck variables, ranks);
# each gives a different packing (atom_modify sort 10, 20 or 50 gave the
# packing of sort 100 and are left out)
NEWTON, SORT = ["-var", "newton", "on"], ["-var", "sort"]
GAS = {"lmp": ("lmp", [], 1), "lmp_newton": ("lmp", NEWTON, 1),
       "lmp_sort100": ("lmp", SORT + ["100"], 1), "lmp_x2": ("lmp", ["-var", "procs", "2 1 1"], 2),
       "lmp_z2": ("lmp", ["-var", "procs", "1 1 2"], 2),
       "lmp_sort1000": ("lmp", SORT + ["1000"], 1), "lmp_sort200": ("lmp", SORT + ["200"], 1),
       "lmp_sort500": ("lmp", SORT + ["500"], 1),
       "lmp_newton_sort100": ("lmp", NEWTON + SORT + ["100"], 1),
       "lmp_x2_newton": ("lmp", ["-var", "procs", "2 1 1"] + NEWTON, 2),
       "lmp2": ("lmp2", [], 1), "lmp2_newton": ("lmp2", NEWTON, 1),
       "lmp2_sort100": ("lmp2", SORT + ["100"], 1),
       "lmp2_x2": ("lmp2", ["-var", "procs", "2 1 1"], 2),
       "lmp2_z2": ("lmp2", ["-var", "procs", "1 1 2"], 2),
       "lmp2_sort1000": ("lmp2", SORT + ["1000"], 1)}
# the dense stage's runs: name -> (deck variables, ranks); ulp, lmp2 and
# liggghts are made apart
DENSE = {"newton": (NEWTON, 1), "sort": (SORT + ["100"], 1),
         "x2": (["-var", "procs", "2 1 1"], 2), "z2": (["-var", "procs", "1 1 2"], 2)}


def variant_deck(out):
    """tests/decks/liggghts/compress_equivalence.lmp with newton, atom
    sorting, the processor grid and kn as variables whose defaults are the
    deck's own settings (the reference run is the deck's run, bit for bit)"""
    text = (DECKS / "liggghts" / "compress_equivalence.lmp").read_text()
    subs = [(r"\natom_modify     map array sort 0 0.0\n",
             "\nvariable sort index 0\nvariable newton index off\n"
             "variable procs index \"1 1 1\"\nvariable kn index 1.0e6\nprocessors ${procs}\n"
             "atom_modify map array sort ${sort} 0.0\n"),
            (r"\nnewton          off\n", "\nnewton ${newton}\n"),
            (r"\* \* 1\.0e6 1\.15 ", "* * ${kn} 1.15 "),
            (r"grflow/wall 1\.0e6 1\.15 ", "grflow/wall ${kn} 1.15 ")]
    for pattern, new in subs:
        text, n = re.subn(pattern, lambda m: new, text)
        if n != 1:
            sys.exit(f"dense_roundoff.py: {pattern!r} not found once in compress_equivalence.lmp")
    out.write_text(text)
    return out


def run(cmd, cwd, nprocs=1):
    if nprocs > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(nprocs)] + cmd
    proc = subprocess.run([str(c) for c in cmd], cwd=cwd, capture_output=True, text=True,
                          errors="replace", env=dict(os.environ, OMP_NUM_THREADS="1"))
    if proc.returncode:
        sys.exit(f"failed: {' '.join(map(str, cmd))}\n{proc.stdout[-2000:]}{proc.stderr[-2000:]}")
    return proc.stdout


def lmp(binary, deck, args, cwd, nprocs=1):
    return run([binary, "-log", "none", "-nocite", "-echo", "none", "-in", deck] + args, cwd,
               nprocs)


def walls_line(out):
    return next(l for l in out.splitlines() if l.startswith("WALLS")).split()[1:]


def portable_data(src, dst):
    """LAMMPS's data file as LIGGGHTS 3.8 reads it: the function of
    tests/python/test_liggghts.py, which the LIGGGHTS tests use"""
    sys.path.insert(0, str(TOP / "tests" / "python"))
    from test_liggghts import portable_data as convert
    return convert(src, dst)


def records(path):
    out = {}
    for line in path.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            v = [float(x) for x in line.split()]
            out[int(v[0])] = dict(zip(NAMES, v[1:]))
    return out


def rel(a, b):
    """|a - b| / |b| (a loose cell of a short run may have no stress yet)"""
    return abs(a - b) / abs(b) if b else (0.0 if a == b else math.inf)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: dense_roundoff.py OUTDIR")
    out = Path(sys.argv[1]).resolve()
    out.mkdir(parents=True, exist_ok=True)
    deck = variant_deck(out / "compress_variants.lmp")
    binaries = {"lmp": LMP, "lmp2": LMP2}

    cell = out / "cell"
    if not (cell / "walls.txt").exists():
        cell.mkdir(exist_ok=True)
        (cell / "prep.lmp").write_text(f"include {DECKS / 'compress_cell.lmp'}\n"
                                       f"write_data {cell / 'cell.data'}\n"
                                       'print "WALLS $(f_w[4]:%.17g) $(f_w[10]:%.17g)"\n')
        walls = walls_line(run([LMP, "-log", "none", "-nocite", "-echo", "none", "-in",
                                "prep.lmp"], cell))
        portable_data(cell / "cell.data", cell / "cell_portable.data")
        (cell / "walls.txt").write_text(" ".join(walls))
    cell_walls = (cell / "walls.txt").read_text().split()

    def gas(name):
        d = out / name
        if not (d / "walls.txt").exists():
            d.mkdir(exist_ok=True)
            which, extra, nprocs = GAS[name]
            o = lmp(binaries[which], deck,
                    ["-var", "data", cell / "cell_portable.data", "-var", "wlo", cell_walls[0],
                     "-var", "whi", cell_walls[1], "-var", "p", "1.0e5", "-var", "rate", "200",
                     "-var", "steps", GAS_STEPS, "-var", "record", d / "gas.txt",
                     "-var", "out", d / "dense.data"] + extra, d, nprocs)
            portable_data(d / "dense.data", d / "dense_portable.data")
            lines = (d / "dense_portable.data").read_text().splitlines()
            for k, l in enumerate(lines):     # atom 1's x one ulp larger
                w = l.split()
                if len(w) == 10 and w[0] == "1":
                    w[4] = repr(math.nextafter(float(w[4]), math.inf))
                    lines[k] = " ".join(w)
            (d / "dense_ulp.data").write_text("\n".join(lines) + "\n")
            (d / "walls.txt").write_text(" ".join(walls_line(o)))
        return d

    def dense(d, tag, extra=(), nprocs=1, binary=LMP, data="dense_portable.data"):
        rec = d / f"dense_{tag}.txt"
        if not rec.exists():
            wlo, whi = (d / "walls.txt").read_text().split()
            args = ["-var", "data", d / data, "-var", "wlo", wlo, "-var", "whi", whi,
                    "-var", "p", "1.3e5", "-var", "rate", "20", "-var", "steps", DENSE_STEPS,
                    "-var", "record", rec]
            if binary == LIGGGHTS:
                run([binary, "-log", "none", "-echo", "none", "-in",
                     DECKS / "liggghts" / "compress_equivalence.liggghts"] + args, d)
            else:
                lmp(binary, deck, args + ["-var", "out", d / f"dense_{tag}.data"] + list(extra),
                    d, nprocs)
        return tag, records(rec)

    names = [n for n in GAS if LMP2 or not n.startswith("lmp2")]
    names = names[:int(os.environ.get("PACKINGS", len(names)))]
    with ThreadPoolExecutor(2) as ex:
        dirs = list(ex.map(gas, names))
    table, kinds = [], {}
    for name, d in zip(names, dirs):
        jobs = [(d, "reference")] + [(d, t, x, n) for t, (x, n) in DENSE.items()]
        jobs.append((d, "ulp", (), 1, LMP, "dense_ulp.data"))
        if LMP2:
            jobs.append((d, "lmp2", (), 1, LMP2))
        if LIGGGHTS:
            jobs.append((d, "liggghts", (), 1, LIGGGHTS))
        if name in KN_ON:
            jobs += [(d, f"kn*(1+{x})", ["-var", "kn", repr(1.0e6 * (1.0 + float(x)))])
                     for x in KN_DELTAS]
        with ThreadPoolExecutor(2) as ex:
            recs = dict(ex.map(lambda j: dense(*j), jobs))
        ref = recs.pop("reference")
        end = max(ref)
        for tag, r in recs.items():
            diff = {q: rel(r[end][q], ref[end][q]) for q in BOX + STRESS}
            steps = sorted(set(r) & set(ref))
            flag = (max(abs(r[s]["errmax"] - ref[s]["errmax"]) for s in steps) / TOL,
                    max(abs(r[s]["ratio"] - ref[s]["ratio"]) for s in steps) / KE_RATIO)
            line = (f"{name} {tag} " + " ".join(f"{diff[q]:.2e}" for q in BOX + STRESS)
                    + f" {flag[0]:.2e} {flag[1]:.2e}")
            print(line, flush=True)
            table.append(line)
            kind = ("kn " + tag if tag.startswith("kn") else
                    tag if tag in ("lmp2", "liggghts") else "round-off in LMP")
            new = (max(diff[q] for q in BOX), max(diff[q] for q in STRESS)) + flag
            old = kinds.get(kind, [(0.0, "")] * 4)
            kinds[kind] = [o if o[0] >= v else (v, f"{name} {tag}") for o, v in zip(old, new)]
    (out / "table.txt").write_text(
        "# packing run d_lx d_ly d_h d_e d_sxx d_syy d_szz (relative, at step "
        f"{DENSE_STEPS} of the dense stage) d_errmax/tol d_ratio/ke_ratio (largest over "
        "the steps)\n" + "\n".join(table) + "\n")
    print(f"largest relative differences at step {DENSE_STEPS}, {len(names)} packing(s):")
    for kind, worst in kinds.items():
        print(f"  {kind}: " + ", ".join(
            f"{what} {v:.1e} ({where})" for what, (v, where) in
            zip(("box (lx, ly, h, e)", "stresses", "errmax/tol (all steps)",
                 "ratio/ke_ratio (all steps)"), worst)))


if __name__ == "__main__":
    main()
