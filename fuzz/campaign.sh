#!/usr/bin/env bash
# A long fuzzing run, for developers (docs/robustness.md): each target in turn for MINUTES,
# continuing after findings (libFuzzer fork mode). Corpora grow in BUILD/fuzz-corpus/TARGET
# across runs, findings land in BUILD/fuzz-findings/, logs in BUILD/fuzz-logs/TARGET.log.
#   fuzz/campaign.sh BUILD_DIR MINUTES [TARGET...]     (BUILD_DIR configured with GLINT_FUZZ=ON)
set -euo pipefail
build=$(cd "$1" && pwd) minutes=$2
shift 2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_toml_scene fuzz_gltf fuzz_glb fuzz_obj_mtl fuzz_ply fuzz_stl fuzz_image)
export LSAN_OPTIONS="suppressions=$here/../tests/lsan_third_party.supp"
mkdir -p "$build/fuzz-findings" "$build/fuzz-logs"
for target in "${targets[@]}"; do
  corpus="$build/fuzz-corpus/$target"
  mkdir -p "$corpus"
  extra=()
  for dir in "$build/seeds/$target" "$here/corpus/$target" "$here/regressions/$target"; do
    [ -d "$dir" ] && extra+=("$dir")
  done
  echo "== $target: $minutes min from $(date -u +%H:%M:%S)" | tee -a "$build/fuzz-logs/$target.log"
  "$build/fuzz/$target" -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
    -max_total_time=$((minutes * 60)) -timeout=20 -rss_limit_mb=4096 \
    -artifact_prefix="$build/fuzz-findings/$target-" "$corpus" "${extra[@]}" >>"$build/fuzz-logs/$target.log" 2>&1 || true
  grep -E '^#[0-9]+: cov' "$build/fuzz-logs/$target.log" | tail -1
done
