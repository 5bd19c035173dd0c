#!/usr/bin/env bash
# Animations, end to end: `glint render --frames` renders frame F at scene time F / fps
# (motion keys and glTF animations alike), names frames by a run of #, skips frames already
# written, resumes an interrupted one, and refuses malformed ranges and patterns with exit 1
# and no file. Usage: frames_test.sh GLINT
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"

# A camera that moves from (0, 1, 6) looking at (0, 1, 0) at time 0 to (4, 1, 6) looking at
# (2, 1, 0) at time 1, and the same scene held still half-way.
cat > moving.toml <<'TOML'
[render]
width = 64
height = 48
spp = 4

[camera]
position = [0, 1, 6]
look_at = [0, 1, 0]
position_end = [4, 1, 6]
look_at_end = [2, 1, 0]
fov = 40

[[materials]]
name = "red"
diffuse = [0.8, 0.1, 0.1]
specular = 0.5
shininess = 30

[[lights]]
type = "point"
position = [4, 6, 4]
intensity = 1

[[objects]]
type = "sphere"
center = [0, 1, 0]
radius = 1
material = "red"

[[objects]]
type = "plane"
size = 10
material = "red"
TOML
sed -e '/_end/d' -e 's/^position = \[0, 1, 6\]/position = [2, 1, 6]/' -e 's/^look_at = \[0, 1, 0\]/look_at = [1, 1, 0]/' \
  moving.toml > halfway.toml

# 1. Frame 12 at 24 fps is scene time 0.5: the camera half-way, bit for bit; frames 0 and 24
# are the two keys.
out=$("$glint" render moving.toml --frames 0-24:12 -o f_##.exr) || fail "--frames 0-24:12 failed"
echo "$out" | grep -q "3 frames: 3 rendered, 0 already there" || fail "frames summary: $out"
[ -s f_00.exr ] && [ -s f_12.exr ] && [ -s f_24.exr ] || fail "frames missing: $(ls)"
"$glint" render halfway.toml -o halfway.exr -q || fail "halfway render"
same f_12.exr halfway.exr "frame 12 of the moving camera against the camera held half-way"
"$glint" render moving.toml --time 0 -o t0.exr -q && "$glint" render moving.toml --time 1 -o t1.exr -q
same f_00.exr t0.exr "frame 0 against --time 0"
same f_24.exr t1.exr "frame 24 against --time 1"
idiff -fail 0 -warn 0 f_00.exr f_24.exr >/dev/null && fail "the camera did not move between frames 0 and 24"

# A camera moved by keys at any times: at 1 fps, frame 2 is half-way between the keys at
# times 1 and 3.
sed -e '/_end/d' -e '/^position = \[0, 1, 6\]/d' -e 's/^look_at = .*/motion = [\
  { time = 0, position = [0, 1, 6], look_at = [0, 1, 0] },\
  { time = 1, position = [4, 1, 6], look_at = [2, 1, 0] },\
  { time = 3, position = [0, 3, 6], look_at = [0, 1, 0] },\
]/' moving.toml > keyed.toml
sed -e '/_end/d' -e 's/^position = \[0, 1, 6\]/position = [2, 2, 6]/' -e 's/^look_at = \[0, 1, 0\]/look_at = [1, 1, 0]/' \
  moving.toml > keyed_halfway.toml
"$glint" render keyed.toml --frames 2 --fps 1 -o keyed_#.exr -q || fail "camera keys: $(cat keyed.toml)"
"$glint" render keyed_halfway.toml -o keyed_halfway.exr -q || fail "keyed halfway render"
same keyed_2.exr keyed_halfway.exr "frame 2 of a keyed camera against the camera held between its keys"

# 2. Frames already there are skipped (a retried farm task redoes only what is missing);
# --overwrite renders them again.
cp f_00.exr f_12.exr
out=$("$glint" render moving.toml --frames 0-24x12 -o f_##.exr) || fail "second run failed"
echo "$out" | grep -q "frame 12: f_12.exr is there; skipped" || fail "no skip message: $out"
echo "$out" | grep -q "3 frames: 0 rendered, 3 already there" || fail "second summary: $out"
same f_12.exr f_00.exr "a skipped frame"
"$glint" render moving.toml --frames 12 -o f_##.exr --overwrite -q || fail "--overwrite failed"
same f_12.exr halfway.exr "an overwritten frame"

# 3. --fps and --motion-blur: frame 30 at 60 fps with the shutter open for half a frame is
# the shutter [0.5, 0.508333333].
"$glint" render moving.toml --frames 30 --fps 60 --motion-blur 0.5 -o blur_####.exr -q || fail "motion blur frame"
"$glint" render moving.toml --shutter 0.5,0.508333333 -o blur.exr -q || fail "--shutter render"
same blur_0030.exr blur.exr "a motion-blurred frame against its shutter"

# 4. glTF node animations play: frame F is the file posed at F / fps seconds.
anim=("$data/animated_quads.gltf" --width 48 --height 36 --spp 1 -q)
"$glint" render "${anim[@]}" --frames 0-48x24 -o quads_#.exr || fail "glTF frames"
for t in 0 1 2; do
  "$glint" render "${anim[@]}" --time $t -o quads_time_$t.exr || fail "glTF --time $t"
  same quads_$((t * 24)).exr quads_time_$t.exr "glTF frame $((t * 24)) against --time $t"
done
idiff -fail 0 -warn 0 quads_0.exr quads_24.exr >/dev/null && fail "the glTF's quad did not move"

# 5. An interrupted frame keeps its checkpoint, and the next run resumes it to the image an
# uninterrupted render gives.
long=(moving.toml --width 480 --height 360 --spp 64 --threads 1 --frames 7)
"$glint" render "${long[@]}" -q -o long_#.exr --checkpoint-every 0.1 2>/dev/null & pid=$!
wait_for long_7.exr.checkpoint; kill -INT $pid; wait $pid; status=$?
[ $status -eq 130 ] || fail "interrupted frame: exit status $status, expected 130"
[ -e long_7.exr.checkpoint ] || fail "the interrupted frame left no checkpoint"
err=$("$glint" render "${long[@]}" -o long_#.exr 2>&1 >/dev/null) || fail "resuming the frame failed"
echo "$err" | grep -q "resuming long_7.exr.checkpoint" || fail "the frame was not resumed: $err"
[ -e long_7.exr.checkpoint ] && fail "the resumed frame's checkpoint was left"
"$glint" render "${long[@]}" -q -o whole_#.exr || fail "uninterrupted frame"
same long_7.exr whole_7.exr "a resumed frame"

# 6. The default names: the scene's name and four digits.
"$glint" render moving.toml --frames 1-2 --width 8 --height 6 -q || fail "default frame names"
[ -s moving_0001.png ] && [ -s moving_0002.png ] || fail "no moving_0001.png, moving_0002.png: $(ls)"

# 7. Mistakes: exit 1, a message, no file.
refused() {  # refused EXPECTED_MESSAGE ARGUMENTS...
  local expected=$1
  shift
  "$glint" render moving.toml -o bad_##.exr "$@" >/dev/null 2>err.txt
  local status=$?
  [ "$status" -eq 1 ] || fail "$* exited $status, expected 1"
  grep -q -- "$expected" err.txt || fail "$*: expected '$expected', got: $(cat err.txt)"
  ls | grep -q '^bad' && fail "$* left $(ls | grep '^bad')"
}
refused "--frames: expected frame numbers" --frames 1-
refused "--frames: expected frame numbers" --frames a-b
refused "--frames: expected frame numbers" --frames 1-10,
refused "--frames: expected frame numbers" --frames -3
refused "expected FIRST ≤ LAST and a step of 1 or more in '5-1'" --frames 5-1
refused "expected FIRST ≤ LAST and a step of 1 or more in '1-10x0'" --frames 1-10x0
refused "expected FIRST ≤ LAST and a step of 1 or more in '1-10:0'" --frames 1,1-10:0
refused "--fps: expected a positive number" --frames 1 --fps 0
refused "--motion-blur: expected the fraction of a frame" --frames 1 --motion-blur 2
refused "expected no --time or --shutter" --frames 1 --time 0.5
refused "expected no --resume" --frames 1 --resume
refused "requires --frames\|--frames is required\|requires" --fps 30
"$glint" render moving.toml --frames 1 -o bad.exr 2>err.txt && fail "a pattern without # was accepted"
grep -q "expected one run of # in the file name" err.txt || fail "pattern message: $(cat err.txt)"
"$glint" render moving.toml --frames 1 -o bad_#_#.exr 2>err.txt && fail "a pattern with two runs of # was accepted"
ls | grep -q '^bad' && fail "a bad pattern left $(ls | grep '^bad')"

finish
