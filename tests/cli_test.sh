#!/usr/bin/env bash
# End-to-end checks of the glint command line: what a user sees, exit codes, and that a
# failed run leaves no output file. Usage: cli_test.sh GLINT_BINARY
set -u
glint=$1
scenes=$(cd "$(dirname "${BASH_SOURCE[0]}")/../scenes" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# 1. The built-in scene renders, and the last line reports times and rays per second.
out=$("$glint" render -o default.png --width 40 --height 30) || fail "default render exited non-zero"
[ -s default.png ] || fail "default render wrote no image"
echo "$out" | grep -Eq 'load [0-9.]+ s, build [0-9.]+ s, render [0-9.]+ s on [0-9]+ threads?, [0-9.]+ M rays \([0-9.]+ M rays/s\)' ||
  fail "final line lacks times, threads and rays per second: $out"
# It says how many threads the process ran on: every core, or what --threads bounds it to
# (the build and the image's encoding included, not only the render).
cores=$(nproc)
[ "$cores" = 1 ] && all="on 1 thread," || all="on $cores threads,"
echo "$out" | grep -q "$all" || fail "final line should say '$all' on this machine: $out"
out=$("$glint" render -o one_thread.png --width 40 --height 30 --threads 1) || fail "--threads 1 exited non-zero"
echo "$out" | grep -q "on 1 thread," || fail "--threads 1: final line should say 'on 1 thread,': $out"

# 2. The same image for any thread count (byte-identical float output).
"$glint" render -o one.pfm --width 40 --height 30 --spp 4 --threads 1 -q >/dev/null || fail "1-thread render failed"
"$glint" render -o two.pfm --width 40 --height 30 --spp 4 --threads 2 -q >/dev/null || fail "2-thread render failed"
cmp -s one.pfm two.pfm || fail "1 and 2 threads gave different images"
# Filters whose weights are not 1 too: a fused multiply-add in some compiled copies of the
# pixel loop and not in others once made these depend on the thread count.
for filter in mitchell gaussian; do
  "$glint" render "$scenes/whitted1980.toml" -o one.pfm --width 64 --height 48 --spp 4 --threads 1 --filter $filter -q ||
    fail "$filter 1 thread"
  "$glint" render "$scenes/whitted1980.toml" -o two.pfm --width 64 --height 48 --spp 4 --threads 2 --filter $filter -q ||
    fail "$filter 2 threads"
  cmp -s one.pfm two.pfm || fail "1 and 2 threads gave different images with the $filter filter"
done

# 3. Bad arguments: non-zero exit, a message, and no file.
if "$glint" render -o bad.xyz -q 2>err.txt; then fail "unknown extension accepted"; fi
[ -e bad.xyz ] && fail "unknown extension left a file"
grep -q "bad.xyz" err.txt || fail "extension error does not name the file: $(cat err.txt)"
if "$glint" render -o spp.png --spp 8 -q 2>err.txt; then fail "--spp 8 accepted"; fi
grep -q "square" err.txt || fail "--spp error does not explain: $(cat err.txt)"
[ -e spp.png ] && fail "--spp error left a file"
if "$glint" render does_not_exist.toml -o missing.png -q 2>/dev/null; then fail "missing scene accepted"; fi
[ -e missing.png ] && fail "missing scene left a file"

# 4. A scene-file mistake: file:line:column, exit status 1, no output file.
cat > typo.toml <<'TOML'
[camera]
position = [0, 1, 5]
look_at = [0, 0, 0]
feild_of_view = 40
TOML
"$glint" render typo.toml -o typo.png -q 2>err.txt
status=$?
[ "$status" -eq 1 ] || fail "scene error exit status $status, expected 1"
grep -Eq 'typo\.toml:[0-9]+:[0-9]+: ' err.txt || fail "scene error lacks file:line:column: $(cat err.txt)"
[ -e typo.png ] && fail "scene error left an output file"
ls -A | grep -q partial && fail "a temporary file was left behind"

# 5. Integrators by name: both render, an unknown one is refused with the known names, and
# the path tracer says once that it ignores the ambient term of a Whitted scene (and with
# -q says nothing at all: -q prints errors only).
cat > lit.toml <<'TOML'
[world]
ambient_light = 0.1
[[materials]]
name = "white"
[[lights]]
type = "sphere"
center = [0, 3, 0]
radius = 0.5
radiance = 5
[[objects]]
type = "plane"
size = 4
material = "white"
TOML
"$glint" render lit.toml -o whitted.png --width 16 --height 12 --light-samples 4 -q >/dev/null ||
  fail "whitted with an area light failed"
"$glint" render lit.toml -o path.png --width 16 --height 12 --integrator path >/dev/null 2>err.txt ||
  fail "path render failed: $(cat err.txt)"
[ -s path.png ] || fail "path render wrote no image"
[ "$(grep -c 'ignores \[world\] ambient_light' err.txt)" -eq 1 ] || fail "path: no single ambient warning: $(cat err.txt)"
"$glint" render lit.toml -o quiet.png --width 16 --height 12 --integrator path -q >out.txt 2>err.txt ||
  fail "quiet path render failed: $(cat err.txt)"
[ -s quiet.png ] || fail "quiet path render wrote no image"
[ -s out.txt ] && fail "-q printed on stdout: $(cat out.txt)"
[ -s err.txt ] && fail "-q printed on stderr: $(cat err.txt)"
"$glint" info lit.toml | grep -q "lights: *1: 1 area" || fail "info does not count the area light: $("$glint" info lit.toml)"
if "$glint" render lit.toml -o unknown.png --integrator pathtracer -q 2>err.txt; then fail "unknown integrator accepted"; fi
grep -q "whitted" err.txt || fail "unknown integrator error does not list the known ones: $(cat err.txt)"
[ -e unknown.png ] && fail "unknown integrator left a file"
if "$glint" render lit.toml -o f.png --filter lanczos -q 2>err.txt; then fail "unknown filter accepted"; fi
grep -q "mitchell" err.txt || fail "unknown filter error does not list the known ones: $(cat err.txt)"

# 6. info counts the triangles of every shape that has them: pool.toml's water is a
# heightfield of 61 × 101 vertices, 2 × 60 × 100 triangles, and the scene holds no mesh.
out=$("$glint" info "$scenes/pool.toml") || fail "info pool.toml failed"
echo "$out" | grep -q "triangles: *12000 unique, 12000 instanced" || fail "info miscounts heightfield triangles: $out"
# pool.toml declares three [[textures]], two of them with uv_scale (a view, not a texture).
echo "$out" | grep -q "textures: *3$" || fail "info miscounts declared textures: $out"

# 7. Every numeric option has its scene-file range and says so in words, before loading;
# exit 1, no file. (issue: "--spp -4" printed a 300-digit range, "--seed -3" passed.)
check_refused() {  # expected-words option...
  local words=$1; shift
  if "$glint" render -o refused.png -q "$@" 2>err.txt; then fail "$* accepted"; return; fi
  [ -e refused.png ] && fail "$* left a file"
  grep -q -- "$words" err.txt || fail "$*: message lacks '$words': $(cat err.txt)"
}
check_refused "--spp: expected a square number 1, 4, 9, ... up to 4096" --spp -4
check_refused "got 8" --spp 8
check_refused "--width: expected an integer from 1 to 16384; got 100000" --width 100000
check_refused "--height: expected an integer from 1 to 16384; got 0" --height 0
check_refused "--seed: expected a non-negative integer; got -3" --seed -3
check_refused "--depth: expected an integer from 0 to 64; got 5000" --depth 5000
check_refused "--light-samples: expected an integer from 1 to 1024" --light-samples 0
check_refused "--glossy-samples: expected an integer from 1 to 1024; got 0" --glossy-samples 0
check_refused "--filter-radius: expected a radius in pixels above 0 and at most 16" --filter-radius 0
check_refused "--threads: expected 0 (all cores) or a thread count up to 1024" --threads -1
check_refused "--aperture: expected a lens radius ≥ 0 in world units (0: a pinhole); got -0.5" --aperture -0.5
check_refused "--focus: expected a positive distance in world units; got 0" --focus 0
check_refused "--aov: expected a comma-separated list of albedo, normal, depth, position, spp, variance; got 'zdepth'" \
  --aov albedo,zdepth
check_refused "refused.png: AOVs (depth) are written as extra channels of an EXR image" --aov depth
check_refused "--spp: expected a power of 4 (1, 4, 16, 64, ...) with adaptive sampling" --adaptive --spp 9
check_refused "--adaptive-threshold: expected a positive relative error" --adaptive-threshold -1
check_refused "--shutter: expected finite times with CLOSE at or after OPEN; got '1,0'" --shutter 1,0
check_refused "--shutter: expected OPEN,CLOSE (two times, e.g. 0,0.5); got '0.5'" --shutter 0.5
check_refused "--time and --shutter: expected one of them, not both" --time 0 --shutter 0,1
check_refused "--up orients the automatic camera of a mesh or glTF file" --up z
check_refused "--up: w not in {x,y,z}" --up w
check_refused "--exposure: expected a number of stops or 'auto'; got 'bright'" --exposure bright
check_refused "--tonemap: expected none, clamp, aces, agx or pbr-neutral; got 'filmic'" --tonemap filmic
# --up z turns a mesh's automatic camera for z-up files; a TOML scene places its own camera.
"$glint" render "$scenes/../tests/data/icosphere.ply" --up z --width 32 --height 24 -o up.png -q || fail "--up z failed"
if "$glint" render "$scenes/spheres.toml" --up z -o up_toml.png -q 2>err.txt; then fail "--up on a TOML scene accepted"; fi
grep -q "a TOML scene places its own camera" err.txt || fail "--up on TOML: $(cat err.txt)"
# glint info says when a mesh's vertex colours tint its material.
"$glint" info "$scenes/../tests/data/vertex_colored_triangle.ply" | grep -q "colours:     vertex colours on 1 mesh" ||
  fail "glint info does not report vertex colours"
# Display transforms: a glTF file is tone mapped with PBR Neutral unless told otherwise, a
# TOML scene is not; --exposure auto says the stops it chose; EXR output keeps radiance.
out=$("$glint" render "$scenes/../tests/data/animated_quads.gltf" --width 32 --height 24 -o quads.png 2>/dev/null) ||
  fail "animated_quads.gltf failed"
grep -q -- "-> quads.png (pbr-neutral, exposure +0.00)" <<<"$out" || fail "glTF display transform: $out"
out=$("$glint" render --width 32 --height 24 --exposure auto --tonemap agx -o auto.png) || fail "--exposure auto failed"
grep -Eq -- "-> auto.png \(agx, exposure auto [+-][0-9.]+\)" <<<"$out" || fail "--exposure auto summary: $out"
"$glint" render --width 32 --height 24 --tonemap aces -o aces.pfm -q || fail "--tonemap with a PFM failed"
"$glint" render --width 32 --height 24 -o plain.pfm -q || fail "plain PFM failed"
cmp -s aces.pfm plain.pfm || fail "--tonemap changed a float image"
out=$("$glint" render --width 32 --height 24 -o plain.png) || fail "plain PNG failed"
grep -q "exposure" <<<"$out" && fail "a TOML scene without [display] reported a display transform: $out"
# The last line of an adaptive render says how many samples it spent, not only the most.
out=$("$glint" render "$scenes/adaptive.toml" --width 64 --height 48 --threads 1 -o adaptive.png 2>&1) ||
  fail "adaptive.toml failed: $out"
grep -Eq "adaptive 4 to 64 spp \([0-9.]+ on average\)" <<<"$out" || fail "adaptive summary line: $out"
# --time T is the instant [T, T]: the moving balls are sharp, and the same as --shutter T,T.
mb=("$scenes/motion_blur.toml" --width 48 --height 36 --spp 4 --threads 1 -q)
"$glint" render "${mb[@]}" --time 0.5 -o instant.pfm || fail "--time 0.5 failed"
"$glint" render "${mb[@]}" --shutter 0.5,0.5 -o same_instant.pfm || fail "--shutter 0.5,0.5 failed"
"$glint" render "${mb[@]}" -o blurred.pfm || fail "motion_blur.toml failed"
cmp -s instant.pfm same_instant.pfm || fail "--time 0.5 and --shutter 0.5,0.5 differ"
cmp -s instant.pfm blurred.pfm && fail "--time 0.5 rendered the same image as the whole shutter"
# glTF node animations: --time poses the sliding, turning quad of animated_quads.gltf at that
# instant, --shutter blurs it over the interval, and without either it rests (and says so).
anim=("$scenes/../tests/data/animated_quads.gltf" --width 64 --height 48 --spp 4 --threads 1 -q)
"$glint" render "${anim[@]}" --time 0 -o anim0.pfm || fail "glTF --time 0 failed"
"$glint" render "${anim[@]}" --time 1 -o anim1.pfm || fail "glTF --time 1 failed"
"$glint" render "${anim[@]}" --shutter 0,1 -o anim01.pfm || fail "glTF --shutter 0,1 failed"
cmp -s anim0.pfm anim1.pfm && fail "glTF animation: --time 0 and --time 1 gave the same image"
cmp -s anim0.pfm anim01.pfm && fail "glTF animation: --shutter 0,1 gave the image of --time 0"
cmp -s anim1.pfm anim01.pfm && fail "glTF animation: --shutter 0,1 gave the image of --time 1"
"$glint" info "$scenes/../tests/data/animated_quads.gltf" --shutter 0,1 | grep -q "1 animation(s) sampled over the shutter \[0, 1\]" ||
  fail "glint info --shutter does not say the animation was sampled"
"$glint" info "$scenes/../tests/data/animated_quads.gltf" 2>&1 | grep -q "animation(s) (nodes drawn at their rest transforms)" ||
  fail "glint info without a shutter does not say the animation was ignored"
if "$glint" render -o refused.png --spp abc 2>/dev/null; then fail "--spp abc accepted"; else
  [ $? -eq 1 ] || fail "a malformed number does not exit with 1"; fi

# 8. The output location is checked before the scene is loaded and rendered.
mkdir -p folder.png
if "$glint" render -o folder.png -q 2>err.txt; then fail "a folder as output accepted"; fi
grep -q "folder.png: is a folder" err.txt || fail "folder output: $(cat err.txt)"
if "$glint" render -o no/such/dir/x.png -q 2>err.txt; then fail "a missing folder accepted"; fi
grep -q "the folder no/such/dir does not exist" err.txt || fail "missing folder: $(cat err.txt)"
grep -q "partial" err.txt && fail "the message names a temporary file: $(cat err.txt)"

# 9. More threads than the machine runs: our note, not the thread library's.
"$glint" render -o threads.png --width 16 --height 8 --threads 1000 >out.txt 2>err.txt || fail "--threads 1000 failed"
grep -q "TBB" err.txt && fail "a raw TBB warning: $(cat err.txt)"

# 10. The deepest accepted recursion cannot overflow a stack: two facing mirrors send every
# ray back and forth until --depth 64 stops it.
cat > mirrors.toml <<'TOML'
[camera]
position = [0, 0, 0.5]
look_at = [0, 0, -1]
fov = 30
[[materials]]
name = "mirror"
diffuse = 0
reflectivity = 0.99
[[lights]]
type = "point"
position = [0, 0.5, 0]
[[objects]]
type = "quad"
corner = [-5, -5, -1]
edge_u = [10, 0, 0]
edge_v = [0, 10, 0]
material = "mirror"
[[objects]]
type = "quad"
corner = [-5, -5, 1]
edge_u = [0, 10, 0]
edge_v = [10, 0, 0]
material = "mirror"
TOML
"$glint" render mirrors.toml -o mirrors.png --width 32 --height 32 --spp 4 --depth 64 -q ||
  fail "--depth 64 between two mirrors failed"

# 11. Ctrl-C keeps the work: the first SIGINT finishes the tiles in flight, writes what is
# rendered (EXR: with a per-pixel sample count) and exits 130; SIGTERM exits 143; a second
# signal ends the render at once and leaves no image and no temporary file.
# The renders save a checkpoint every 0.1 s: its appearance says the render is under way,
# however slowly a loaded machine starts the process.
wait_for() { for _ in $(seq 1 300); do [ -e "$1" ] && return 0; sleep 0.1; done; fail "$1 never appeared"; }
long=("$scenes/whitted1980.toml" --width 1920 --height 1440 --spp 64 --threads 1 -q --checkpoint-every 0.1)
"$glint" render "${long[@]}" -o partial.exr 2>err.txt & pid=$!
wait_for partial.exr.checkpoint; kill -INT $pid; wait $pid; status=$?
[ $status -eq 130 ] || fail "SIGINT: exit status $status, expected 130"
[ -s partial.exr ] || fail "SIGINT left no partial image"
grep -q "interrupted: wrote the [0-9]* of 10800 tiles rendered to partial.exr" err.txt ||
  fail "SIGINT message: $(cat err.txt)"
if command -v oiiotool >/dev/null; then
  info=$(oiiotool --info -v partial.exr)
  echo "$info" | grep -q "channel list: R, G, B, samples" || fail "partial EXR lacks the samples channel: $info"
  stats=$(oiiotool partial.exr --ch samples --printstats)
  echo "$stats" | grep -q "Max: 64.0" || fail "no pixel of the partial EXR has all 64 samples: $stats"
  echo "$stats" | grep -q "Min: 0.0" || fail "the partial EXR claims every pixel: $stats"
else
  echo "skipped: oiiotool (openimageio-tools) is not installed; the partial EXR's channels are unchecked"
fi
"$glint" render "${long[@]}" -o partial.png 2>/dev/null & pid=$!
wait_for partial.png.checkpoint; kill -TERM $pid; wait $pid; status=$?
[ $status -eq 143 ] || fail "SIGTERM: exit status $status, expected 143"
[ -s partial.png ] || fail "SIGTERM left no partial image"
"$glint" render "${long[@]}" -o twice.exr 2>/dev/null & pid=$!
wait_for twice.exr.checkpoint; kill -INT $pid; kill -INT $pid; wait $pid; status=$?
[ $status -eq 130 ] || fail "second SIGINT: exit status $status, expected 130"
ls -a | grep -q "partial-" && fail "a temporary image was left: $(ls -a)"

# 12. Exact resume: an interrupted render continues from its checkpoint and ends in the
# image an uninterrupted render gives, bit for bit; a killed render resumes from its last
# periodic checkpoint; another render's checkpoint is refused, saying what differs.
res=("$scenes/whitted1980.toml" --width 640 --height 480 --spp 16 --threads 1 -q)
"$glint" render "${res[@]}" -o whole.pfm || fail "uninterrupted render failed"
# (The periodic checkpoint only starts the interruption; the one written on SIGINT is named.)
"$glint" render "${res[@]}" -o resumed.pfm --checkpoint-every 0.1 2>err.txt & pid=$!
wait_for resumed.pfm.checkpoint; kill -INT $pid; wait $pid
[ -s resumed.pfm.checkpoint ] && grep -q "; checkpoint resumed.pfm.checkpoint (continue with --resume)" err.txt ||
  fail "an interrupted render left no checkpoint: $(cat err.txt)"
"$glint" render "${res[@]}" -o resumed.pfm --resume 2>err.txt || fail "--resume failed: $(cat err.txt)"
cmp -s whole.pfm resumed.pfm || fail "the resumed image differs from the uninterrupted one"
[ -e resumed.pfm.checkpoint ] && fail "a finished render left its checkpoint"
# With AOVs the checkpoint keeps their sums too: the resumed EXR equals the whole one in
# every channel.
if command -v idiff >/dev/null; then
  aov=("${res[@]}" --aov albedo,depth,spp,variance)
  "$glint" render "${aov[@]}" -o whole_aov.exr || fail "render with AOVs failed"
  "$glint" render "${aov[@]}" -o resumed_aov.exr --checkpoint-every 0.1 2>/dev/null & pid=$!
  wait_for resumed_aov.exr.checkpoint; kill -INT $pid; wait $pid
  "$glint" render "${aov[@]}" -o resumed_aov.exr --resume 2>err.txt || fail "--resume with AOVs: $(cat err.txt)"
  idiff -fail 0 -warn 0 whole_aov.exr resumed_aov.exr >idiff.txt ||
    fail "the resumed AOVs differ from the uninterrupted ones: $(cat idiff.txt)"
else
  echo "skipped: idiff (openimageio-tools) is not installed; resuming with AOVs is unchecked"
fi
"$glint" render "${res[@]}" -o killed.pfm --checkpoint-every 0.1 & pid=$!
wait_for killed.pfm.checkpoint; kill -KILL $pid; wait $pid 2>/dev/null
[ -s killed.pfm.checkpoint ] || fail "--checkpoint-every left no checkpoint behind a killed render"
"$glint" render "${res[@]}" -o killed.pfm --resume 2>err.txt || fail "resume after kill failed: $(cat err.txt)"
cmp -s whole.pfm killed.pfm || fail "the image resumed after a kill differs from the uninterrupted one"
"$glint" render "${res[@]}" -o other.pfm --checkpoint-every 0.1 & pid=$!
wait_for other.pfm.checkpoint; kill -INT $pid; wait $pid
if "$glint" render "$scenes/whitted1980.toml" --width 640 --height 480 --spp 4 -q -o other.pfm --resume 2>err.txt; then
  fail "a checkpoint of another render was resumed"; fi
grep -q "spp: the checkpoint has 16, this render 4" err.txt || fail "mismatch message: $(cat err.txt)"
# Options that change the camera, not the file, change the render too: a checkpoint made
# without a lens is not resumed with one.
if "$glint" render "${res[@]}" --aperture 0.05 -o other.pfm --resume 2>err.txt; then
  fail "a checkpoint was resumed through another lens"; fi
grep -q "lens: the checkpoint has aperture 0, " err.txt || fail "lens mismatch message: $(cat err.txt)"
printf 'not a checkpoint' > other.pfm.checkpoint
if "$glint" render "${res[@]}" -o other.pfm --resume 2>err.txt; then fail "a corrupt checkpoint was resumed"; fi
grep -q "not a Glint checkpoint" err.txt || fail "corrupt checkpoint message: $(cat err.txt)"
if "$glint" render "${res[@]}" -o none.pfm --resume 2>err.txt; then fail "--resume without a checkpoint passed"; fi
grep -q "no checkpoint to resume" err.txt || fail "missing checkpoint message: $(cat err.txt)"

# Start-up: OpenImageIO (255 shared libraries, 350 ms; src/image/image_codec.h) is loaded only
# by a run that reads or writes an image it needs for; PNG output is written over zlib, EXR
# output through OpenEXR's own module.
loads() { local library=$1; shift; LD_DEBUG=libs "$glint" "$@" 2>&1 >/dev/null | grep -q "$library"; }
loads libOpenImageIO.so --help && fail "glint --help loaded OpenImageIO"
loads libOpenImageIO.so info "$scenes/spheres.toml" && fail "glint info loaded OpenImageIO"
loads libOpenImageIO.so render -o start.png --width 1 --height 1 -q && fail "a render to PNG loaded OpenImageIO"
loads libOpenImageIO.so render -o start.exr --width 1 --height 1 -q && fail "a render to EXR loaded OpenImageIO"
loads libOpenEXR render -o start.png --width 1 --height 1 -q && fail "a render to PNG loaded OpenEXR"
loads libOpenEXR render -o start.exr --width 1 --height 1 -q || fail "a render to EXR did not load OpenEXR (is the check blind?)"
# EXR input too goes through OpenEXR's module alone (src/image/exr_reader.h): an EXR sky.
"$glint" render -o sky.exr --width 8 --height 4 -q || fail "a render to EXR failed"
loads libOpenImageIO.so render --env sky.exr -o start.png --width 1 --height 1 -q &&
  fail "a render under an EXR environment map loaded OpenImageIO"
loads libOpenImageIO.so render -o start.tif --width 1 --height 1 -q ||
  fail "a render to TIFF did not load OpenImageIO (is the check blind?)"
# Open MPI is glint-mpi's alone (app/program_beside.h): no command of glint loads it.
loads libmpi.so render -o start.png --width 1 --height 1 -q && fail "a render loaded Open MPI"
# assimp is loaded by a run that reads a mesh file other than a plain binary PLY, and only by
# one (src/assets/assimp_module.h, src/assets/ply_triangles.h).
loads libassimp.so --help && fail "glint --help loaded assimp"
loads libassimp.so render -o start.png --width 1 --height 1 -q && fail "a render without meshes loaded assimp"
loads libassimp.so render "$scenes/bunny_glass.toml" -o start.png --width 1 --height 1 -q &&
  fail "a render of the glass bunny (a binary PLY of triangles) loaded assimp"
loads libassimp.so render "$scenes/../tests/data/vertex_colored_triangle.ply" -o start.png --width 1 --height 1 -q ||
  fail "a render of an ASCII PLY did not load assimp (is the check blind?)"

echo "$(( failures == 0 ? 1 : 0 )) passed, $failures failed"
[ "$failures" -eq 0 ]
