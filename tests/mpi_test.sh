#!/usr/bin/env bash
# One frame across MPI ranks on loopback (app/mpi_session.h): `mpirun -np N glint render`
# writes the image one process writes, bit for bit; a rank that fails or dies ends the job
# with a message (never a hang: every run here is under a timeout) and no image.
# Usage: mpi_test.sh GLINT
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"
# Open MPI refuses root unless told (CI machines run as root); ranks share this machine's
# cores, so they are not pinned to one each.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi() { timeout 120 mpirun --oversubscribe --bind-to none "$@"; }

# 1. Three ranks, two and one give the single process's image: Whitted with glossy samples,
# and the path tracer with adaptive sampling and AOVs, whole and cropped.
for config in "whitted1980.toml --spp 4" "cornell_area.toml --integrator path --spp 16 --adaptive --aov albedo,depth"; do
  set -- $config
  name=$1
  scene="$scenes/$1"
  shift
  common=(--width 97 --height 73 "$@")
  "$glint" render "$scene" "${common[@]}" -o single.exr -q || fail "single process ($name)"
  mpi -np 3 "$glint" render "$scene" "${common[@]}" -o three.exr -q || fail "mpirun -np 3 ($name)"
  same single.exr three.exr "3 ranks against 1 process ($name)"
  mpi -np 2 "$glint" render "$scene" "${common[@]}" --threads 1 -o two.exr -q || fail "mpirun -np 2 ($name)"
  same single.exr two.exr "2 ranks of 1 thread against 1 process ($name)"
done
"$glint" render "$scene" "${common[@]}" --crop 10,20,60,50 -o crop_single.exr -q || fail "single crop"
mpi -np 3 "$glint" render "$scene" "${common[@]}" --crop 10,20,60,50 -o crop_three.exr -q || fail "crop on 3 ranks"
same crop_single.exr crop_three.exr "a crop on 3 ranks"
out=$(mpi -np 2 "$glint" render "$scenes/whitted1980.toml" --width 64 --height 48 -o summary.png 2>&1) ||
  fail "mpirun summary run"
[ "$(echo "$out" | grep -c ' -> summary.png')" -eq 1 ] || fail "expected one summary line, from rank 0: $out"

# 2. Failures end the job: exit status not 0, the reason on stderr, no image.
ended() {  # ended EXPECTED OUTPUT MPIRUN_ARGUMENTS...
  local expected=$1 output=$2
  shift 2
  mpi "$@" >/dev/null 2>err.txt
  local status=$?
  [ "$status" -ne 0 ] || fail "mpirun $* succeeded"
  [ "$status" -ne 124 ] || fail "mpirun $* hung"
  grep -q -- "$expected" err.txt || fail "mpirun $*: expected '$expected', got: $(cat err.txt)"
  [ -e "$output" ] && fail "mpirun $* left $output"
  ls -a | grep -q partial && fail "mpirun $* left a temporary file"
}
small=("$scenes/spheres.toml" --width 64 --height 48 -q)
ended "rank 1 of 2: this rank would render another image than rank 0 (spp: 4 on rank 0, 16 here)" other.exr \
  -np 1 "$glint" render "${small[@]}" -o other.exr : -np 1 "$glint" render "${small[@]}" --spp 16 -o other.exr
ended "rank 1 of 2: the command line above is refused" refused.exr \
  -np 1 "$glint" render "${small[@]}" -o refused.exr : -np 1 "$glint" render "${small[@]}" --no-such-option -o refused.exr
ended "a render across MPI ranks takes none of them" resume.exr -np 2 "$glint" render "${small[@]}" --resume -o resume.exr
ended "--frames under mpirun" frame_1.exr -np 2 "$glint" render "${small[@]}" --frames 1 -o frame_#.exr

# A rank killed mid-render (a node lost) ends the job.
long=("$scenes/whitted1980.toml" --width 1280 --height 960 --spp 64 --threads 1 -q -o killed.exr)
mpi -np 3 "$glint" render "${long[@]}" >/dev/null 2>err.txt & job=$!
for _ in $(seq 1 100); do [ "$(pgrep -f -c "glint render .*killed.exr")" -ge 3 ] && break; sleep 0.1; done
sleep 1
kill -9 "$(pgrep -f "glint render .*killed.exr" | tail -1)"
wait $job
status=$?
[ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "a killed rank: mpirun exited $status"
grep -q "exited on signal 9" err.txt || fail "a killed rank: no message saying so: $(cat err.txt)"
[ -e killed.exr ] && fail "a killed rank left an image"

finish
