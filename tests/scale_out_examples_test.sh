#!/usr/bin/env bash
# The scheduler scripts of examples/scale-out/ run as a cluster would run them, with a
# stand-in sbatch (fake_sbatch.sh): the crops of slurm_tiles.sh assemble into the frame one
# render gives, and slurm_frames.sbatch renders, then skips, its chunks of frames.
# Usage: scale_out_examples_test.sh GLINT
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"
examples="$here/../examples/scale-out"
mkdir bin
cp "$here/fake_sbatch.sh" bin/sbatch
chmod +x bin/sbatch
export PATH="$work/bin:$PATH" GLINT="$glint"

# 1. A 3 × 2 grid of crops, then assembled.
options=(--width 83 --height 61 --spp 4)
bash "$examples/slurm_tiles.sh" "$scenes/whitted1980.toml" grid.exr 3 2 -- "${options[@]}" >/dev/null ||
  fail "slurm_tiles.sh"
[ "$(ls grid.parts | wc -l)" -eq 6 ] || fail "expected 6 crops: $(ls grid.parts)"
"$glint" render "$scenes/whitted1980.toml" "${options[@]}" -o whole.exr -q || fail "the whole frame"
same grid.exr whole.exr "slurm_tiles.sh's assembled grid"

# 2. Frames 0 to 24 in chunks of 10: three tasks; submitted again, every frame is skipped.
export SCENE="$scenes/motion_blur.toml" FIRST=0 LAST=24 CHUNK=10 OUT="frames/blur_###.png"
sbatch --array=0-2 "$examples/slurm_frames.sbatch" --width 32 --height 24 --spp 1 2>/dev/null ||
  fail "slurm_frames.sbatch"
[ "$(ls frames | wc -l)" -eq 25 ] || fail "expected 25 frames: $(ls frames)"
before=$(stat -c %Y frames/*)
sleep 1
sbatch --array=0-2 "$examples/slurm_frames.sbatch" 2>/dev/null || fail "slurm_frames.sbatch again"
[ "$(stat -c %Y frames/*)" = "$before" ] || fail "frames were rendered again"

finish
