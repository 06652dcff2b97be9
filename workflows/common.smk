# Helpers shared by the workflows (resistance_curve.smk, physics_study.smk),
# included by them: the lmp command of the decks, -var pairs from config
# text, and the shell that makes a shear run's directory from a seed's
# preparation.
#
# Runs on GPUs (config, both workflows): gpus=G (default 0: the CPU) runs
# every job with the KOKKOS styles on one of G GPUs, with at most
# jobs_per_gpu=R jobs on each at once (default 1; several 8000-sphere jobs
# fill one GPU better than one: doc/kokkos-design.md), through
# workflows/gpu_slot.sh; kokkos="..." the KOKKOS switches (default "-k on g
# 1 -sf kk -pk kokkos newton off neigh half"); lmp must then be an lmp with
# GRFLOW and KOKKOS (scripts/setup-kokkos.sh cuda).  Give snakemake
# --cores G*R (a job takes one core and one slot).

import os

GRFLOW = os.path.abspath(os.path.join(workflow.basedir, ".."))
INPUTS = os.path.join(GRFLOW, "inputs")
GPUS = int(config.get("gpus", 0))
JOBS_PER_GPU = int(config.get("jobs_per_gpu", 1))
KOKKOS = str(config.get("kokkos", "-k on g 1 -sf kk -pk kokkos newton off neigh half"))
if GPUS < 0 or JOBS_PER_GPU < 1:
    raise ValueError(f"gpus {GPUS}, jobs_per_gpu {JOBS_PER_GPU}: need gpus >= 0, jobs_per_gpu >= 1")


def var_pairs(text, what):
    """'-var NAME VALUE ...' from config text "NAME VALUE ..." (an empty
    --config value reads as None)"""
    words = str(text or "").split()
    if len(words) % 2:
        raise ValueError(f"{what} {text!r}: need NAME VALUE pairs")
    return " ".join(f"-var {words[k]} {words[k + 1]}" for k in range(0, len(words), 2))


def lmp_command(lmp, np, args):
    """the decks' lmp command on np ranks (mpirun for np > 1; as root with
    --allow-run-as-root), with -in cyclic_shear.lmp -var inputs and args;
    with gpus > 0 one rank on a GPU slot with the KOKKOS switches (and
    newton_pair off, which the KOKKOS pair style needs)"""
    if GPUS > 0:
        if np != 1:
            raise ValueError(f"np {np} with gpus {GPUS}: a GPU job runs on one rank (np=1)")
        newton = "" if "newton_pair" in args else " -var newton_pair off"
        return (f"{GRFLOW}/workflows/gpu_slot.sh {GPUS} {JOBS_PER_GPU} {lmp} -nocite -log none "
                f"-screen none {KOKKOS} -in {INPUTS}/cyclic_shear.lmp -var inputs {INPUTS} "
                f"{args}{newton}")
    mpi = ""
    if np > 1:
        root = "--allow-run-as-root " if os.geteuid() == 0 else ""
        mpi = f"mpirun {root}--oversubscribe -np {np} "
    return (f"{mpi}{lmp} -nocite -log none -screen none -in {INPUTS}/cyclic_shear.lmp "
            f"-var inputs {INPUTS} {args}")


# a shear run's directory DIR from the preparation's prep.restart (linked,
# with its checksum file, which the decks verify), prep.json (copied) and
# its snapshot of the prepared sample, if any (for Fig. 1)
LINK_PREP = (
    "mkdir -p {params.dir}/snapshots && "
    "ln -sf $(realpath {input.restart}) {params.dir}/prep.restart && "
    "ln -sf $(realpath {input.restart}).cksum {params.dir}/prep.restart.cksum && "
    "cp {input.json} {params.dir}/prep.json && "
    "(cp $(dirname {input.restart})/snapshots/atoms.prep.txt {params.dir}/snapshots/ "
    "2>/dev/null || true) && "
)
