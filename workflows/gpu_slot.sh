#!/usr/bin/env bash
# Run one job of a workflow on a GPU shared by several jobs: with GPUS GPUs
# and at most PER jobs on each, take a free slot (a lock file per GPU and
# slot, held while the job runs; the slots fill the GPUs in turn), set
# CUDA_VISIBLE_DEVICES to that slot's GPU and run the command.  Waits while
# every slot is taken.  A CUDA_VISIBLE_DEVICES set already (e.g. by a
# batch system) is the list the GPUs are taken from.
#
#   workflows/gpu_slot.sh GPUS PER COMMAND ...
#
# GRFLOW_GPU_SLOTS: the folder of the lock files (default
# /tmp/grflow-gpu-slots-<uid>); one folder per machine and user.
set -uo pipefail
gpus=${1:?usage: gpu_slot.sh GPUS PER COMMAND ...}
per=${2:?usage: gpu_slot.sh GPUS PER COMMAND ...}
shift 2
[ $# -gt 0 ] || { echo "gpu_slot.sh: no command" >&2; exit 2; }
for n in "$gpus" "$per"; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "gpu_slot.sh: GPUS and PER must be integers >= 1, got $gpus $per" >&2; exit 2; }
done
IFS=',' read -r -a visible <<< "${CUDA_VISIBLE_DEVICES:-}"
if [ ${#visible[@]} -gt 0 ] && [ ${#visible[@]} -lt "$gpus" ]; then
  echo "gpu_slot.sh: $gpus GPUs asked for, CUDA_VISIBLE_DEVICES lists ${#visible[@]}" >&2
  exit 2
fi
dir=${GRFLOW_GPU_SLOTS:-/tmp/grflow-gpu-slots-$(id -u)}
mkdir -p "$dir"
while true; do
  for ((s = 0; s < per; s++)); do
    for ((g = 0; g < gpus; g++)); do
      exec {fd}> "$dir/gpu$g.slot$s"
      if flock -n "$fd"; then
        if [ ${#visible[@]} -gt 0 ]; then
          export CUDA_VISIBLE_DEVICES=${visible[$g]}
        else
          export CUDA_VISIBLE_DEVICES=$g
        fi
        # the job keeps the lock (the open file) until it ends, and gets
        # the workflow's signals itself
        exec "$@"
      fi
      exec {fd}>&-
    done
  done
  sleep 1
done
