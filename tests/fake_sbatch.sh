#!/usr/bin/env bash
# A stand-in for Slurm's sbatch (tests/scale_out_examples_test.sh): runs the job here and
# now, an array's tasks one after another with SLURM_ARRAY_TASK_ID set, and prints a job id.
# A failing task fails the submission, as afterok would hold back what depends on it.
set -u
array="" wrap="" parsable=0
while [ $# -gt 0 ]; do
  case "$1" in
    --array=*) array=${1#--array=} ;;
    --wrap) wrap=$2; shift ;;
    --wrap=*) wrap=${1#--wrap=} ;;
    --parsable) parsable=1 ;;
    --*) ;;  # job names, --export=ALL, dependencies: the jobs run in order here anyway
    *) break ;;
  esac
  shift
done
export SLURM_CPUS_PER_TASK=1
if [ -n "$wrap" ]; then
  bash -c "$wrap" >&2 || exit 1
elif [ -n "$array" ]; then
  for range in ${array//,/ }; do
    for i in $(seq "${range%-*}" "${range#*-}"); do
      SLURM_ARRAY_TASK_ID=$i bash "$@" >&2 || exit 1
    done
  done
else
  bash "$@" >&2 || exit 1
fi
[ "$parsable" -eq 1 ] && echo "$$;local" || echo "Submitted batch job $$"
