// POV-Ray 3.7 julia_fractal reference scene -- binary silhouette MASK (white = hit, black = miss)
// case bicomplex01_sqr_A: the commutative "hypercomplex" algebra (bicomplex numbers), 4-D c
//   c = <-0.2, 0.6, 0.2, 0.2>   hypercomplex   function = sqr   max_iteration = 20   precision = 20
//   slice = <0, 0, 0, 1>, 0.0
// POV-Ray's hypercomplex set: a point escapes when x^2 + y^2 + z^2 + w^2 > 16 (bailout 4,
// whatever c is), bounding sphere of radius 4 (tests/data/reference/bicomplex/ORIGIN.md).
// Render:  povray +Ibicomplex01_sqr_A_mask.pov +O<out>.png +W320 +H240 -A -D +WT2 Display=off
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb 0 }
camera {
  perspective
  location <1, 1.5, -4>
  sky      <0, 1, 0>
  up       y
  right    x*image_width/image_height
  angle    45            // HORIZONTAL field of view in degrees
  look_at  <0, 0, 0>
}
// no light sources: the object emits exactly 1.0, everything else is 0.0
julia_fractal {
  <-0.2, 0.6, 0.2, 0.2>
  hypercomplex
  sqr
  max_iteration 20
  precision 20
  slice <0, 0, 0, 1>, 0.0
  pigment { rgb 1 }
  finish  { ambient 0 emission 1 diffuse 0 specular 0 phong 0 reflection 0 }
}
