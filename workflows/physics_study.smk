# A study of the shear stage's settings over seeds, as one Snakemake
# workflow: each seed is prepared once (stages 1-4, -var calibrate yes by
# default: every seed at the paper's e), then sheared from that same state
# in every setting, so that a setting and the baseline differ in the
# setting only (a paired design: the differences are taken seed by seed).
# grflow-study (analysis/) tabulates each setting over the seeds and
# against the baseline.
#
#   snakemake -s workflows/physics_study.smk --cores 2
#   snakemake -s workflows/physics_study.smk --cores 2 \
#     --config seeds="[1,2,3]" settings='{"base": "shear_rate 0.38", "slow": "shear_rate 0.19"}'
#
# Config (--config KEY=VALUE; defaults below):
#   seeds       seeds of the particle sizes (one preparation each)   [1, 2, 3]
#   N           spheres per sample                                        2000
#   preset      quick or paper (inputs/params.lmp)                       paper
#   settings    {NAME: "-var pairs of the shear stage"}, in the order of the
#               table; the first is the baseline          SETTINGS below
#   prep_vars   -var pairs of the preparation
#               "calibrate yes normal_force clipped"
#   vars        -var pairs of every run (preparation and shear)           ""
#   rate_settings  settings that differ in shear_rate only, whose quasi-static
#               limit (a straight line in the rate, taken to 0) the table adds
#               [base, rate0.19, rate0.095] with the default settings, else []
#   max_cycles  a run that has not liquefied after this many cycles is a
#               run-out                                                     60
#   out         study directory                           runs/study-N<N>
#   lmp         the LAMMPS binary                                          lmp
#   study       the table command (analysis/, scripts/setup.sh)   grflow-study
#   np          MPI ranks per run (1: no mpirun)                             1
#   gpus, jobs_per_gpu, kokkos   runs on GPUs (KOKKOS styles; common.smk)   0, 1
# A shear run killed (or a session ended) resumes from its newest restart
# file that verifies when the workflow is run again (the decks' -var
# resume yes); the preparations and finished runs are kept.  Every run is
# a normal run directory, OUT/seed<S>/<setting>/, which grflow-figures
# reads; OUT/study.{md,json} is the result.  workflows/README.md.

import json


include: "common.smk"

# the settings of issue 30 at N = 2000: the shear rate of the paper-size
# case (v_x = 0.01 m/s over its wall gap: 0.38 1/s) as the baseline, two
# slower rates for the quasi-static limit, the unclipped normal force,
# Cundall's local damping at four coefficients, and the unclipped force
# with Cundall's damping at 0.2.  The study was designed and run with the
# clipped normal force as the baseline (the decks' default until this
# study made the unclipped law the default), so every setting and the
# preparation name their law.
SETTINGS = {
    "base": "shear_rate 0.38 normal_force clipped",
    "rate0.19": "shear_rate 0.19 normal_force clipped",
    "rate0.095": "shear_rate 0.095 normal_force clipped",
    "unclipped": "shear_rate 0.38 normal_force unclipped",
    "cundall0.05": "shear_rate 0.38 normal_force clipped cundall_l 0.05",
    "cundall0.1": "shear_rate 0.38 normal_force clipped cundall_l 0.1",
    "cundall0.2": "shear_rate 0.38 normal_force clipped cundall_l 0.2",
    "cundall0.4": "shear_rate 0.38 normal_force clipped cundall_l 0.4",
    # the combination of the two model changes, at the paper's rate
    "unclipped_cundall0.2": "shear_rate 0.38 normal_force unclipped cundall_l 0.2",
}


SEEDS = [int(s) for s in config.get("seeds", [1, 2, 3])]
N = int(config.get("N", 2000))
PRESET = config.get("preset", "paper")
STUDY_SETTINGS = config.get("settings", SETTINGS)
if isinstance(STUDY_SETTINGS, str):
    STUDY_SETTINGS = json.loads(STUDY_SETTINGS)
PREP_VARS = var_pairs(config.get("prep_vars", "calibrate yes normal_force clipped"),
                      "prep_vars")
VARS = var_pairs(config.get("vars", ""), "vars")
MAX_CYCLES = int(config.get("max_cycles", 60))
OUT = config.get("out", f"runs/study-N{N}")
LMP = config.get("lmp", "lmp")
STUDY = config.get("study", "grflow-study")
NP = int(config.get("np", 1))

if PRESET not in ("quick", "paper"):
    raise ValueError(f"preset {PRESET}: use quick or paper")
if not SEEDS or N < 1 or MAX_CYCLES < 1 or NP < 1:
    raise ValueError("seeds: need one or more; N, max_cycles and np must be >= 1")
if not isinstance(STUDY_SETTINGS, dict) or not STUDY_SETTINGS:
    raise ValueError("settings: need a dict {NAME: \"-var pairs\"} with one or more entries")
SHEAR_VARS = {}
for name, text in STUDY_SETTINGS.items():
    if not name or "/" in name or name == "prep" or name.split() != [name]:
        raise ValueError(f"settings: {name!r} cannot name a directory (one word, no '/', "
                         "not 'prep')")
    SHEAR_VARS[name] = var_pairs(text, f"settings {name}:")
NAMES = list(STUDY_SETTINGS)
RATE_SETTINGS = config.get("rate_settings",
                           ["base", "rate0.19", "rate0.095"] if STUDY_SETTINGS is SETTINGS else [])
if isinstance(RATE_SETTINGS, str):
    RATE_SETTINGS = RATE_SETTINGS.split()
for name in RATE_SETTINGS:
    if name not in NAMES:
        raise ValueError(f"rate_settings: {name} is not one of the settings ({', '.join(NAMES)})")

RUN = lmp_command(LMP, NP, f"-var preset {PRESET} -var N {N} {VARS}")


rule all:
    input:
        f"{OUT}/study.md",
        f"{OUT}/study.json",


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
        "{RUN} {PREP_VARS} -var stage prep -var seed {wildcards.seed} "
        "-var outdir {OUT}/seed{wildcards.seed}/prep > {log} 2>&1"


# stage 5 in one setting from the seed's prepared state; a directory with
# restart files of an earlier, killed attempt is resumed (resume yes picks
# the newest file that verifies); run.json records the setting
rule shear:
    input:
        restart=rules.prep.output.restart,
        json=rules.prep.output.json,
    output:
        meta=f"{OUT}/seed{{seed}}/{{setting}}/run.json",
    log:
        f"{OUT}/seed{{seed}}/{{setting}}/log.driver.lammps",
    wildcard_constraints:
        setting="[^/]+",
    params:
        dir=f"{OUT}/seed{{seed}}/{{setting}}",
        vars=lambda w: SHEAR_VARS[w.setting],
        meta=lambda w: json.dumps({"seed": int(w.seed), "setting": w.setting,
                                   "shear_vars": STUDY_SETTINGS[w.setting], "N": N,
                                   "preset": PRESET, "max_cycles": MAX_CYCLES}),
    threads: NP
    resources:
        mpi=NP,
    shell:
        LINK_PREP +
        "resume=no && if ls {params.dir}/shear.restart.*[0-9] > /dev/null 2>&1; then resume=yes; fi && "
        "{RUN} {params.vars} -var stage shear -var resume $resume -var outdir {params.dir} "
        "-var max_cycles {MAX_CYCLES} > {log} 2>&1 && "
        "grep -q -e 'GRFLOW shear: done' -e 'nothing to resume' {params.dir}/log.shear.lammps && "
        "printf '%s\\n' '{params.meta}' > {output.meta}"


rule study:
    input:
        expand(f"{OUT}/seed{{seed}}/{{setting}}/run.json", seed=SEEDS, setting=NAMES),
    output:
        f"{OUT}/study.md",
        f"{OUT}/study.json",
    params:
        settings=" ".join(NAMES),
        seeds=" ".join(str(s) for s in SEEDS),
        rates=" ".join(["--rate-settings"] + RATE_SETTINGS) if RATE_SETTINGS else "",
    shell:
        "{STUDY} {OUT} --settings {params.settings} --seeds {params.seeds} {params.rates}"
