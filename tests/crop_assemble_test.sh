#!/usr/bin/env bash
# Crops for a render farm, end to end: `glint render --crop` writes EXR data windows that
# `glint assemble` (or oiiotool alone) joins into the image one render makes, bit for bit;
# every mistake exits 1 with a message and writes nothing. Usage: crop_assemble_test.sh GLINT
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"

# 1. Four quarters (fractions of an odd-sized image) and three unaligned pixel regions,
# assembled, equal the full render bit for bit: Whitted with glossy samples, and the path
# tracer with adaptive sampling (which looks at neighbours) and AOVs.
render() { "$glint" render "$@" -q || fail "glint render $*"; }
for config in "whitted1980.toml --spp 4" "cornell_area.toml --integrator path --spp 16 --adaptive --aov albedo,depth"; do
  set -- $config
  name=$1
  scene="$scenes/$1"
  shift
  common=(--width 83 --height 61 "$@")
  render "$scene" "${common[@]}" -o full.exr
  render "$scene" "${common[@]}" -o q1.exr --crop 0,0,0.5,0.5
  render "$scene" "${common[@]}" -o q2.exr --crop 0.5,0,1,0.5
  render "$scene" "${common[@]}" -o q3.exr --crop 0,0.5,0.5,1
  render "$scene" "${common[@]}" -o q4.exr --crop 0.5,0.5,1,1 --threads 1
  "$glint" assemble q1.exr q2.exr q3.exr q4.exr -o quarters.exr >/dev/null || fail "assemble quarters ($name)"
  same full.exr quarters.exr "quarters of $name"
  render "$scene" "${common[@]}" -o top.exr --crop 0,0,83,17
  render "$scene" "${common[@]}" -o left.exr --crop 0,17,29,61
  render "$scene" "${common[@]}" -o right.exr --crop 29,17,83,61
  "$glint" assemble right.exr top.exr left.exr -o pieces.exr >/dev/null || fail "assemble pieces ($name)"
  same full.exr pieces.exr "unaligned crops of $name"
done

# 2. The EXR windows: data window = the crop, display window = the frame.
info=$(oiiotool --info -v right.exr)
echo "$info" | grep -q "54 x   44" || fail "right.exr is not 54×44: $info"
echo "$info" | grep -q "pixel data origin: x=29, y=17" || fail "right.exr's data window is not at (29, 17): $info"
echo "$info" | grep -q "full/display size: 83 x 61" || fail "right.exr's display window is not 83×61: $info"
echo "$info" | grep -q 'glint:spp: "16"' || fail "right.exr does not say what rendered it: $info"

# 3. oiiotool alone joins them too (docs/scale-out.md): images add as zero outside their data windows.
oiiotool right.exr top.exr --add left.exr --add -o oiio.exr || fail "oiiotool --add"
same full.exr oiio.exr "oiiotool's assembly"

# 4. A crop to PNG holds the region's pixels alone.
render "$scenes/whitted1980.toml" --width 83 --height 61 --spp 1 -o region.png --crop 10,10,30,20
oiiotool --info region.png | grep -q "20 x   10" || fail "region.png is not 20×10: $(oiiotool --info region.png)"

# 5. Mistakes: exit 1, a message, no output.
refused() {  # refused OUTPUT EXPECTED_MESSAGE COMMAND...
  local output=$1 expected=$2
  shift 2
  "$@" >/dev/null 2>err.txt
  local status=$?
  [ "$status" -eq 1 ] || fail "$* exited $status, expected 1"
  grep -q -- "$expected" err.txt || fail "$*: expected '$expected', got: $(cat err.txt)"
  [ -e "$output" ] && fail "$* left $output"
  ls -A | grep -q partial && fail "$* left a temporary file"
}
refused bad.exr "expected X0,Y0,X1,Y1" "$glint" render --crop 0,0,10 -o bad.exr
refused bad.exr "expected X0,Y0,X1,Y1" "$glint" render --crop 0,0,ten,10 -o bad.exr
refused bad.exr "expected 0 ≤ X0 < X1" "$glint" render --crop 10,0,5,10 -o bad.exr
refused bad.exr "fractions of the image go from 0 to 1" "$glint" render --crop 0,0,1.5,1 -o bad.exr
refused bad.exr "reaches past the 40×30 image" "$glint" render --width 40 --height 30 --crop 0,0,41,30 -o bad.exr
refused bad.exr "uncovered, the first at (29, 17)" "$glint" assemble top.exr left.exr -o bad.exr
refused bad.exr "overlap" "$glint" assemble top.exr left.exr right.exr q1.exr -o bad.exr
"$glint" render "$scenes/cornell_area.toml" --width 83 --height 61 --integrator path --spp 4 --aov albedo,depth \
  --adaptive -o q1.exr --crop 0,0,0.5,0.5 -q
refused bad.exr "come from different renders (spp: 4 in q1.exr, 16 in q2.exr)" "$glint" assemble q1.exr q2.exr q3.exr \
  q4.exr -o bad.exr
refused bad.exr "is a whole frame, not a crop" "$glint" assemble full.exr q2.exr -o bad.exr
refused bad.exr "no such image file\|does not exist" "$glint" assemble missing.exr -o bad.exr

finish
