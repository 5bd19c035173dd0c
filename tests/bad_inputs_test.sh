#!/usr/bin/env bash
# Runs every file of the bad-input corpus (tests/bad_inputs/, listed in expected.txt) through
# `glint render FILE -o OUT.png` and `glint info FILE` and checks what a user sees: exit status
# exactly 1, the first line of stderr naming the file and saying what expected.txt says, no
# image and no temporary .OUT.partial-* left, no signal, no hang, no sanitizer report.
# Usage: bad_inputs_test.sh GLINT_BINARY
set -u
glint=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
corpus=$(cd "$(dirname "${BASH_SOURCE[0]}")/bad_inputs" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export LC_ALL=C  # byte-wise matching: some file names are not UTF-8
# Under LeakSanitizer (the CI's sanitizer build), leaks inside assimp's error paths are not ours.
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lsan_third_party.supp"
failures=0
checks=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The corpus is copied so that nothing a run writes can land in the source tree, and the
# files git cannot hold portably (directories named like files, non-UTF-8 names) are made here.
cp -R "$corpus" "$work/corpus"
cd "$work/corpus"
mkdir -p generated/dir_named.toml generated/dir_named.glb generated/dir_named.ply
cp toml/syntax_missing_value.toml "generated/latin1_$(printf '\351')_name.toml"
cp obj/bad_index.obj "generated/bytes_$(printf '\377\376')_name.obj"
mkdir "generated/folder_$(printf '\377')"
cp toml/missing_texture_file.toml "generated/folder_$(printf '\377')/scene.toml"
cat > generated/ok.toml <<'TOML'
[[materials]]
name = "grey"
[[objects]]
type = "sphere"
radius = 1
material = "grey"
TOML
before=$(find . -print | sort)

# One run: check_run LABEL EXPECTED MODE NAMED -- COMMAND... in the folder $out (the image,
# if any, is $out/OUT.png); prints RUN, and FAIL: lines.
check_run() {
  local label=$1 expected=$2 mode=$3 named=$4
  shift 5
  rm -rf "$out" && mkdir -p "$out"
  timeout 60 "$@" >"$log.stdout" 2>"$log.stderr"
  local status=$?
  echo RUN
  local first
  first=$(head -n 1 "$log.stderr")
  if grep -Eq 'Sanitizer|runtime error:' "$log.stderr"; then
    fail "$label: sanitizer report: $(grep -E -m 3 'Sanitizer|runtime error:|#[0-9] ' "$log.stderr" | tr '\n' ' ')"
  fi
  if [ $status -eq 124 ]; then fail "$label: no answer within 60 s (a hang)"; return; fi
  if [ $status -gt 128 ]; then fail "$label: killed by signal $((status - 128))"; fi
  if [ "$mode" = accepted ]; then
    [ $status -eq 0 ] || fail "$label: exit status $status, expected 0 (accepted with a warning): $first"
    if [ "$expected" = "-" ]; then
      [ -s "$log.stderr" ] && fail "$label: expected no message, got: $first"
    else
      case "$first" in *"$expected"*) ;; *) fail "$label: first line of stderr lacks '$expected': $first" ;; esac
    fi
  else
    [ $status -eq 1 ] || fail "$label: exit status $status, expected 1: $first"
    case "$first" in *"$expected"*) ;; *) fail "$label: first line of stderr lacks '$expected': $first" ;; esac
    case "$first" in *"$named"*) ;; *) fail "$label: first line of stderr does not name $named: $first" ;; esac
    [ -e "$out/OUT.png" ] && fail "$label: an image was written"
  fi
  ls -A "$out" | grep -q 'partial' && fail "$label: a temporary file was left: $(ls -A "$out")"
}

# Both runs of one entry of expected.txt. Entries run in parallel: most of a run is the
# program's start-up.
check_entry() {
  local file=$1 expected=$2 mode=$3 size=(--width 16 --height 16)
  if [ ! -e "$file" ]; then fail "$file: listed in expected.txt but missing"; return; fi
  case "$mode" in
    env)
      check_run "render --env $file" "$expected" error "$file" -- "$glint" render --env "$file" -o "$out/OUT.png" "${size[@]}"
      check_run "info --env $file" "$expected" error "$file" -- "$glint" info generated/ok.toml --env "$file"
      ;;
    env-*)
      local kind=${mode#env-}
      check_run "render --env $file --env-kind $kind" "$expected" error "$file" -- "$glint" render --env "$file" --env-kind "$kind" -o "$out/OUT.png" "${size[@]}"
      check_run "info --env $file --env-kind $kind" "$expected" error "$file" -- "$glint" info generated/ok.toml --env "$file" --env-kind "$kind"
      ;;
    time)
      check_run "render $file --time 0" "$expected" error "$file" -- "$glint" render "$file" --time 0 -o "$out/OUT.png" "${size[@]}"
      check_run "info $file --time 0" "$expected" error "$file" -- "$glint" info "$file" --time 0
      ;;
    accepted | "")
      check_run "render $file" "$expected" "${mode:-error}" "$file" -- "$glint" render "$file" -o "$out/OUT.png" "${size[@]}"
      [ "$mode" = accepted ] && [ ! -s "$out/OUT.png" ] && fail "render $file: accepted, but no image was written"
      check_run "info $file" "$( [ "$mode" = accepted ] && echo - || echo "$expected")" "${mode:-error}" "$file" -- \
        "$glint" info "$file"
      ;;
    *) fail "$file: unknown mode '$mode' in expected.txt" ;;
  esac
}

entries=0
listed=$'\n'
jobs_max=$(nproc)
while IFS=$'\t' read -r file expected mode || [ -n "$file" ]; do
  case "$file" in '' | '#'*) continue ;; esac
  file=$(printf '%b' "$file")
  expected=$(printf '%b' "$expected")
  entries=$((entries + 1))
  listed+="./$file"$'\n'
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n; done
  out="$work/out/$entries" log="$work/log.$entries" check_entry "$file" "$expected" "${mode:-}" >"$work/result.$entries" &
done <expected.txt
wait
for ((i = 1; i <= entries; i++)); do
  checks=$((checks + $(grep -c '^RUN$' "$work/result.$i")))
  failures=$((failures + $(grep -c '^FAIL' "$work/result.$i")))
  grep '^FAIL' "$work/result.$i"
done

# Every input in the corpus is listed (a file nobody runs tests nothing), and nothing was
# written beside the inputs.
while IFS= read -r f; do
  case "$f" in
    ./expected.txt | ./README.md | ./make_binary_inputs.py | ./generated/ok.toml) continue ;;
    ./image/* | ./obj/*.mtl) continue ;;  # read through the scenes and --env entries that name them
  esac
  [ -f "$f" ] || continue
  case "$listed" in *$'\n'"$f"$'\n'*) ;; *) fail "$f is in the corpus but not in expected.txt" ;; esac
done < <(find . -type f -print)
after=$(find . -print | sort)
[ "$before" = "$after" ] || fail "files appeared or vanished beside the inputs: $(diff <(echo "$before") <(echo "$after") | tr '\n' ' ')"

# The loop must have done its work: two runs per entry.
[ "$entries" -ge 60 ] || fail "only $entries entries in expected.txt (expected at least 60)"
[ "$checks" -eq $((2 * entries)) ] || fail "$checks runs for $entries entries (expected two each)"
echo "$entries inputs, $checks runs: $failures failed"
[ "$failures" -eq 0 ]
