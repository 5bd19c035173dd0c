// The scene of two_spheres.toml for POV-Ray 3.7: the same camera (right-handed, as Glint),
// floor, spheres, point light with shadows and mirror reflection to depth 5.
#version 3.7;
#include "common.inc"

sphere { <-0.8, 0.7, 0>, 0.7
  pigment { rgb 0.1 }
  finish { ambient 0.1 diffuse 1 reflection 0.8 phong 0.5 phong_size 100 }
}
sphere { <0.8, 0.7, 0>, 0.7
  pigment { rgb <0.7, 0.1, 0.1> }
  finish { ambient 0.1 diffuse 1 phong 0.3 phong_size 40 }
}
