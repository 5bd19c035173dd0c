#!/usr/bin/env bash
# One large frame on a Slurm cluster as crops, then joined: a job array renders a grid of
# COLUMNS × ROWS crops, and a job that starts once every one of them succeeded
# (--dependency=afterok) assembles them into the image one `glint render` would write.
#
#   examples/scale-out/slurm_tiles.sh SCENE OUTPUT.exr [COLUMNS ROWS] [-- glint render options]
#
# The crops go to OUTPUT.parts/ (tile_0000.exr, ...); `glint assemble` refuses a set with
# a missing, overlapping or foreign crop, so a failed task shows rather than leaving a hole.
set -euo pipefail
scene=$1
output=$2
columns=${3:-4}
rows=${4:-4}
shift $(($# < 4 ? $# : 4))
[ "${1:-}" = "--" ] && shift
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
parts="${output%.exr}.parts"
mkdir -p "$parts"
# The tasks take their settings from the environment they are submitted from (--export=ALL).
crops=$(SCENE=$scene PARTS=$parts COLUMNS=$columns ROWS=$rows GLINT_OPTIONS="$*" \
  sbatch --parsable --export=ALL --job-name=glint-crops --array="0-$((columns * rows - 1))" "$here/slurm_crop_task.sh")
sbatch --parsable --job-name=glint-assemble --dependency="afterok:${crops%%;*}" \
  --wrap "${GLINT:-glint} assemble $parts/tile_*.exr -o $output"
