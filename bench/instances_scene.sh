#!/bin/sh
# Writes a TOML scene that places one mesh file COUNT times with [[objects]] (the top-level
# benchmark of docs/performance.md): a square grid of copies, each scaled, turned about y
# and moved by its own transform, under one directional light, 320x240 at 1 spp.
#
#   bench/instances_scene.sh 100000 ../shared/data/meshes/stanford_bunny.ply > /tmp/bunnies.toml
#   /usr/bin/time -f "%e s %M KB" build/glint render /tmp/bunnies.toml -o /tmp/bunnies.png
#
# MESH is written as given: make it absolute, or relative to where the scene will be.
set -eu
if [ $# -ne 2 ]; then
  echo "usage: $0 COUNT MESH" >&2
  exit 2
fi
awk -v count="$1" -v mesh="$2" 'BEGIN {
  srand(1)
  side = int(sqrt(count)); if (side * side < count) side++
  print "[render]\nwidth = 320\nheight = 240\nspp = 1\n"
  print "[camera]\nposition = [0, 60, -60]\nlook_at = [0, 0, 40]\nfov = 60\n"
  print "[[lights]]\ntype = \"directional\"\ndirection = [-0.4, -1, 0.3]\nintensity = 1\n"
  print "[[materials]]\nname = \"clay\"\ndiffuse = 0.8\n"
  for (i = 0; i < count; i++) {
    x = (i % side - side / 2) * 0.6; z = (int(i / side) - side / 2) * 0.6
    printf "[[objects]]\ntype = \"mesh\"\nfile = \"%s\"\nmaterial = \"clay\"\n", mesh
    printf "transform = { scale = %.3f, rotate = { axis = [0, 1, 0], degrees = %.1f }, translate = [%.3f, 0, %.3f] }\n\n",
           3 + 2 * rand(), 360 * rand(), x, z
  }
}'
