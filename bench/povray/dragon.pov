// The scene of dragon.toml for POV-Ray 3.7: dragon.inc holds the mesh (ply_to_pov.py).
#version 3.7;
#include "common.inc"
#include "dragon.inc"

object { Dragon
  scale 10
  translate <0.06, -0.527, 0>
  pigment { rgb <0.7, 0.1, 0.1> }
  finish { ambient 0.1 diffuse 1 phong 0.3 phong_size 40 }
}
