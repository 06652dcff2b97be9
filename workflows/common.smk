# Helpers shared by the workflows (resistance_curve.smk, physics_study.smk),
# included by them: the lmp command of the decks, -var pairs from config
# text, and the shell that makes a shear run's directory from a seed's
# preparation.

import os

GRFLOW = os.path.abspath(os.path.join(workflow.basedir, ".."))
INPUTS = os.path.join(GRFLOW, "inputs")


def var_pairs(text, what):
    """'-var NAME VALUE ...' from config text "NAME VALUE ..." (an empty
    --config value reads as None)"""
    words = str(text or "").split()
    if len(words) % 2:
        raise ValueError(f"{what} {text!r}: need NAME VALUE pairs")
    return " ".join(f"-var {words[k]} {words[k + 1]}" for k in range(0, len(words), 2))


def lmp_command(lmp, np, args):
    """the decks' lmp command on np ranks (mpirun for np > 1; as root with
    --allow-run-as-root), with -in cyclic_shear.lmp -var inputs and args"""
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
