#!/usr/bin/env bash
# Run one libFuzzer target for a short time, as CI does: replay its corpus and past
# findings, then mutate for SECONDS. New inputs go to a scratch folder, never into the
# repository; a finding is written to the current folder and fails the test. The seed is
# fixed so that a red CI run repeats on a developer's machine (the same mutations, as far as
# the time allows); open-ended random search is campaign.sh's job. Fork mode with timeouts
# recorded but not failed: with clang 14's ASan, an import child forked while another thread
# held the allocator's lock can wait forever (a sanitizer limitation, not a hang of Glint's;
# the bad-input corpus guards against real hangs). Crashes and sanitizer reports still fail.
#   smoke.sh TARGET_BINARY SECONDS CORPUS_DIR REGRESSIONS_DIR
set -euo pipefail
binary=$1 seconds=$2 corpus=$3 regressions=$4
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
seeds=()
for dir in "$corpus" "$regressions"; do
  [ -d "$dir" ] && seeds+=("$dir")
done
"$binary" -seed=1 -fork=1 -ignore_timeouts=1 -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 -print_final_stats=1 \
  -artifact_prefix="$PWD/$(basename "$binary")-" "$scratch" "${seeds[@]}"
