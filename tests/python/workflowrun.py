"""Running the Snakemake workflows of workflows/ in the tests
(test_workflow.py, test_study.py): one copy of the command and of the
reader of a dry run's job table."""
import os
import shutil
import subprocess
import sys

import pytest

SNAKEMAKE = shutil.which("snakemake")
needs_snakemake = pytest.mark.skipif(SNAKEMAKE is None, reason="needs snakemake (Debian)")
BIN = os.path.dirname(sys.executable)       # grflow-curve, grflow-study, grflow-figures
# the set-up's commands beside the Python that runs the tests (scripts/python-env.sh)
ENV = dict(os.environ, PATH=BIN + os.pathsep + os.environ.get("PATH", ""), MPLBACKEND="Agg")


def planned(proc):
    """{rule: job count} from the "Job stats" table of a dry run."""
    jobs = {}
    for line in (proc.stdout + proc.stderr).splitlines():
        parts = line.split()
        if len(parts) == 4 and all(p.isdigit() for p in parts[1:]):
            jobs[parts[0]] = int(parts[1])
    return jobs


def snakemake(smk, args, cwd, check=True):
    """snakemake -s SMK ARGS in cwd; with check, it must succeed"""
    proc = subprocess.run([SNAKEMAKE, "-s", smk] + args, cwd=cwd, capture_output=True,
                          text=True, timeout=900, env=ENV)
    if check:
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return proc
