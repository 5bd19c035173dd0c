#!/usr/bin/env bash
# The totals of every campaign run logged in BUILD/fuzz-logs/ (campaign.sh), as the Markdown
# table of docs/robustness.md: per target the runs, minutes fuzzed, executions, coverage and
# corpus at the end of the last run, and the ooms / timeouts / crashes libFuzzer counted.
#   fuzz/campaign_totals.sh BUILD_DIR
set -euo pipefail
logs="$1/fuzz-logs"
echo "| target | runs | minutes | executions | coverage (edges) | corpus | ooms / timeouts / crashes |"
echo "|---|---|---|---|---|---|---|"
for log in "$logs"/fuzz_*.log; do
  awk -v name="$(basename "$log" .log)" '
    function close_run() { if (!open) return; seconds += last_time; executions += last_exec; ooms += o; timeouts += t; crashes += c; open = 0 }
    /^== /               { close_run(); runs++; open = 1; last_time = 0; last_exec = 0; o = t = c = 0; next }
    /^#[0-9]+: cov:/ {
      last_exec = substr($1, 2) + 0
      for (i = 1; i <= NF; i++) {
        if ($i == "cov:") cov = $(i + 1)
        if ($i == "corp:") corpus = $(i + 1)
        if ($i == "time:") last_time = $(i + 1) + 0
        if ($i == "oom/timeout/crash:") { split($(i + 1), n, "/"); o = n[1]; t = n[2]; c = n[3] }
      }
    }
    /^INFO: fuzzed for/  { last_time = $4 + 0 }
    END {
      close_run()
      printf "| `%s` | %d | %.0f | %d | %d | %d | %d / %d / %d |\n", name, runs, seconds / 60, executions, cov, corpus, ooms, timeouts, crashes
    }' "$log"
done
