#!/usr/bin/env bash
# One crop of slurm_tiles.sh's grid: task i renders column i mod COLUMNS, row i div COLUMNS,
# as fractions of the image (crops that share an edge in fractions share it in pixels).
#SBATCH --cpus-per-task=8
set -euo pipefail
i=$SLURM_ARRAY_TASK_ID
column=$((i % COLUMNS))
row=$((i / COLUMNS))
crop=$(awk -v c="$column" -v r="$row" -v C="$COLUMNS" -v R="$ROWS" \
  'BEGIN { printf "%.9f,%.9f,%.9f,%.9f", c / C, r / R, (c + 1) / C, (r + 1) / R }')
# shellcheck disable=SC2086  # GLINT_OPTIONS holds several options
exec "${GLINT:-glint}" render "$SCENE" ${GLINT_OPTIONS:-} --crop "$crop" --threads "${SLURM_CPUS_PER_TASK:-0}" -q \
  -o "$PARTS/tile_$(printf %04d "$i").exr"
