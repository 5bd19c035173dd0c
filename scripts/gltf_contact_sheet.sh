#!/usr/bin/env bash
# Render every glTF sample in a folder (by default ../shared/data/gltf beside the checkout)
# with no display, camera or environment flags, only a small size, and join the images into
# one labelled contact sheet: what a user sees from `glint render FILE` for each of them.
# Usage: scripts/gltf_contact_sheet.sh [GLINT] [SAMPLES_DIR] [OUTPUT]
#   defaults: build/glint, ../shared/data/gltf, docs/images/gltf_contact_sheet.png
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
glint=${1:-$here/build/glint}
samples=${2:-$here/../shared/data/gltf}
output=${3:-$here/docs/images/gltf_contact_sheet.png}
width=320
height=240
columns=4
[ -x "$glint" ] || { echo "no glint at $glint: build first (README)" >&2; exit 1; }
[ -d "$samples" ] || { echo "no glTF samples at $samples" >&2; exit 1; }
command -v oiiotool >/dev/null || { echo "oiiotool is needed (Debian: openimageio-tools)" >&2; exit 1; }
font=$(fc-match -f '%{file}' 'DejaVu Sans' 2>/dev/null || true)

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tiles=()
for dir in "$samples"/*/; do
  name=$(basename "$dir")
  # The Khronos layout: glTF-Binary/NAME.glb or glTF/NAME.gltf (the first one found).
  file=$(find "$dir" -maxdepth 2 \( -name '*.glb' -o -name '*.gltf' \) | sort | head -n 1)
  [ -n "$file" ] || continue
  tile="$work/$name.png"
  if ! "$glint" render "$file" -o "$tile" --width $width --height $height -q 2>"$work/$name.err"; then
    echo "$name: render failed: $(head -n 1 "$work/$name.err")" >&2
    oiiotool --create ${width}x${height} 3 -o "$tile"
  fi
  # A cropped camera (the file's aspect) still fills the same cell.
  oiiotool "$tile" --fit:pad=1 ${width}x${height} -o "$tile"
  if [ -n "$font" ]; then
    oiiotool "$tile" --text:x=6:y=18:size=15:color=1,1,1:font="$font" "$name" -o "$tile"
  fi
  tiles+=("$tile")
  echo "$name"
done
[ ${#tiles[@]} -gt 0 ] || { echo "no .gltf or .glb files under $samples" >&2; exit 1; }
rows=$(( (${#tiles[@]} + columns - 1) / columns ))
mkdir -p "$(dirname "$output")"
oiiotool "${tiles[@]}" --mosaic:pad=2 ${columns}x${rows} -o "$work/sheet.png"
mv "$work/sheet.png" "$output"
echo "wrote $output (${#tiles[@]} samples)"
