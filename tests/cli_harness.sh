# Sourced by the command-line tests (crop_assemble_test.sh, frames_test.sh) with the glint
# program as their first argument: they then run in a scratch folder removed at exit, with
# $glint, $scenes and $data set and these checks; each ends with `finish`.
set -u
glint=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scenes="$here/../scenes"
data="$here/data"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# Two images with the same pixels, bit for bit.
same() { idiff -fail 0 -warn 0 "$1" "$2" >/dev/null || fail "$3: $1 and $2 differ"; }
# Wait up to 30 s for a file to appear (a render under way on a loaded machine).
wait_for() { for _ in $(seq 1 300); do [ -e "$1" ] && return 0; sleep 0.1; done; fail "$1 never appeared"; }
finish() {
  echo "$failures failure(s)"
  [ "$failures" -eq 0 ]
}
