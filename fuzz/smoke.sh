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
mkdir "$scratch/corpus"
trap 'rm -rf "$scratch"' EXIT
seeds=()
for dir in "$corpus" "$regressions"; do
  [ -d "$dir" ] && seeds+=("$dir")
done
# The whole log goes to a file; what is printed leaves out the progress lines, new-function
# lists and the libraries' complaints about broken inputs, so that a finding's report is not
# cut off by CTest's limit on a failed test's output (a red CI run once showed only those).
log="$scratch/fuzz.log"
status=0
"$binary" -seed=1 -fork=1 -ignore_timeouts=1 -timeout_exitcode=70 -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 -print_final_stats=1 \
  -artifact_prefix="$PWD/$(basename "$binary")-" "$scratch/corpus" "${seeds[@]}" >"$log" 2>&1 || status=$?
grep -v -E '^#[0-9]+|NEW_FUNC|^libpng |^INFO: (Running|Seed|Loaded|seed corpus|-max_len|log from)' "$log" | head -c 200000 || true
# Fork mode exits with the code of the last job it collected, even an ignored timeout's
# (libFuzzer's FuzzerFork.cpp, "Use the exit code from the last child process"): CI once
# failed with "INFO: exiting: 70" and no report when the job running at the time limit was
# the one that timed out. A crash stops the run at once with its own code (77, or a
# signal's), so 70, the timeout code, is only ever an ignored timeout.
if [ "$status" -eq 70 ]; then
  echo "smoke.sh: the last fork job timed out (ignored, as -ignore_timeouts=1 asks)"
  status=0
fi
exit "$status"
