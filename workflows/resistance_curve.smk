# The cyclic resistance curve (CSR against N_IL) as one Snakemake workflow:
# each seed is prepared once, then sheared from that state at every CSR;
# grflow-curve (analysis/, installed by scripts/setup.sh) fits
# CSR = a N_IL^(-b) and draws the curve.
#
#   snakemake -s workflows/resistance_curve.smk --cores 2 \
#     --config csr="[0.15,0.2,0.25,0.3]" seeds="[1,2,3]" preset=quick
#
# Config (--config KEY=VALUE; defaults below):
#   csr         CSR values, tau_amp = csr * p_target            [0.15, 0.2, 0.25, 0.3]
#   seeds       seeds of the particle sizes (one preparation each)      [1, 2, 3]
#   preset      quick or paper (inputs/params.lmp)                         quick
#   max_cycles  a run that has not liquefied after this many cycles is
#               a run-out (drawn with an arrow, not fitted)                   60
#   n_post      cycles after initial liquefaction (N_IL needs none; >= 1)      1
#   p_target    confining stress of the preparation (Pa)                   1.0e5
#   out         campaign directory                        runs/curve-<preset>
#   lmp         the LAMMPS binary                                             lmp
#   curve       the curve command (analysis/, scripts/setup.sh)      grflow-curve
#   np          MPI ranks per run (1: no mpirun)                               1
#   vars        more -var settings for every run, e.g. "N 500 v_x 0.02"       ""
#   gpus, jobs_per_gpu, kokkos   runs on GPUs (KOKKOS styles; common.smk)   0, 1
# Every run is a normal run directory (OUT/seed<S>/csr<C>/) that
# grflow-figures understands; OUT/curve.{png,json,md} is the
# result.  snakemake reruns only what is missing or failed; --summary lists
# what is done; on a SLURM cluster add --profile workflows/profiles/slurm.

include: "common.smk"

CSR = [float(c) for c in config.get("csr", [0.15, 0.2, 0.25, 0.3])]
SEEDS = [int(s) for s in config.get("seeds", [1, 2, 3])]
PRESET = config.get("preset", "quick")
MAX_CYCLES = int(config.get("max_cycles", 60))
N_POST = int(config.get("n_post", 1))
P_TARGET = float(config.get("p_target", 1.0e5))
OUT = config.get("out", "runs/curve-" + PRESET)
LMP = config.get("lmp", "lmp")
CURVE = config.get("curve", "grflow-curve")
NP = int(config.get("np", 1))
EXTRA = var_pairs(config.get("vars", ""), "vars")

if PRESET not in ("quick", "paper"):
    raise ValueError(f"preset {PRESET}: use quick or paper")
if not CSR or any(not (c > 0) for c in CSR):
    raise ValueError(f"csr {CSR}: need one or more values > 0")
if not SEEDS:
    raise ValueError("seeds: need one or more")
if MAX_CYCLES < 1 or N_POST < 1 or NP < 1 or not (P_TARGET > 0):
    raise ValueError("max_cycles, n_post and np must be >= 1 and p_target > 0")
RUN = lmp_command(LMP, NP, f"-var preset {PRESET} -var p_target {P_TARGET} {EXTRA}")


def csr_tag(c):
    return f"{c:g}"


rule all:
    input:
        f"{OUT}/curve.png",
        f"{OUT}/curve.json",
        f"{OUT}/curve.md",


# stages 1-4 of the protocol, once per seed
rule prep:
    output:
        restart=f"{OUT}/seed{{seed}}/prep/prep.restart",
        json=f"{OUT}/seed{{seed}}/prep/prep.json",
    log:
        f"{OUT}/seed{{seed}}/prep/log.driver.lammps",
    threads: NP
    resources:
        mpi=NP,
    shell:
        "{RUN} -var stage prep -var seed {wildcards.seed} "
        "-var outdir {OUT}/seed{wildcards.seed}/prep > {log} 2>&1"


# stage 5 at one CSR from the seed's prepared state; run.json records the
# settings (tau_amp = csr * p_target) for grflow-curve
rule shear:
    input:
        restart=rules.prep.output.restart,
        json=rules.prep.output.json,
    output:
        series=f"{OUT}/seed{{seed}}/csr{{csr}}/series.txt",
        meta=f"{OUT}/seed{{seed}}/csr{{csr}}/run.json",
    log:
        f"{OUT}/seed{{seed}}/csr{{csr}}/log.driver.lammps",
    params:
        dir=f"{OUT}/seed{{seed}}/csr{{csr}}",
        tau=lambda w: float(w.csr) * P_TARGET,
    threads: NP
    resources:
        mpi=NP,
    shell:
        LINK_PREP +
        "{RUN} -var stage shear -var outdir {params.dir} -var tau_amp {params.tau} "
        "-var max_cycles {MAX_CYCLES} -var n_post {N_POST} > {log} 2>&1 && "
        "grep -q 'GRFLOW shear: done' {params.dir}/log.shear.lammps && "
        "printf '{{\"seed\": {wildcards.seed}, \"csr\": {wildcards.csr}, \"tau_amp\": {params.tau}, "
        "\"p_target\": {P_TARGET}, \"max_cycles\": {MAX_CYCLES}, \"preset\": \"{PRESET}\"}}\\n' "
        "> {output.meta}"


rule curve:
    input:
        expand(f"{OUT}/seed{{seed}}/csr{{csr}}/run.json", seed=SEEDS,
               csr=[csr_tag(c) for c in CSR]),
    output:
        f"{OUT}/curve.png",
        f"{OUT}/curve.json",
        f"{OUT}/curve.md",
    params:
        dirs=lambda w, input: " ".join(os.path.dirname(p) for p in input),
    shell:
        "{CURVE} {OUT} {params.dirs}"
