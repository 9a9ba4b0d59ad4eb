#!/usr/bin/env bash
# A Slurm job array that splits a `flapwright sweep` into shards (issue 39).
#
#   sbatch --array=1-8 examples/slurm/sweep-array.sh my-wing.toml
#   # when every task has ended:
#   python3 examples/slurm/merge.py sweep-shards/*/sweep.csv > sweep.csv
#
# Each task designs every N-th variant (N the array's task count) into its own folder,
# using the cores Slurm gives it (rayon reads RAYON_NUM_THREADS). A task that is
# requeued or run again keeps the rows already in its table. The shards' tables,
# merged, are the table one `flapwright sweep` without --shard writes.
#SBATCH --job-name=flapwright-sweep
#SBATCH --cpus-per-task=4
#SBATCH --mem-per-cpu=1G
#SBATCH --time=02:00:00
set -euo pipefail
scene=${1:?usage: sbatch --array=1-N sweep-array.sh SCENE}
export RAYON_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}
flapwright sweep "$scene" \
  --vary 'flap[*].settings.landing_gap_percent=1.5:2.5:0.005' \
  --shard "${SLURM_ARRAY_TASK_ID}/${SLURM_ARRAY_TASK_COUNT}" \
  --out "sweep-shards/${SLURM_ARRAY_TASK_ID}" --quiet
