// lens.toml in POV-Ray 3.7: the same camera, floor, point light and five balls, with focal
// blur focused on the third ball. Right-handed with z up, as ../torus.pov; ka·ambient, kd,
// ks, q as in area.pov.
//
// What POV-Ray 3.7 does with it (source/backend/render/tracepixel.cpp of 3.7.0.10):
// - `aperture A` moves the eye by (A/2)·g for lens points g of a disk of radius 1/2 (a hex
//   grid of 7 and 9 sub-random points, each jittered): a lens of radius A/4. Ours is
//   `aperture = 0.3`, the lens's radius, so A = 4 x 0.3 = 1.2 (not 0.6).
// - `focal_point`: the plane of focus lies at its distance from the camera, along the view
//   axis, as our focus_distance (the look_at point here, 10.3078 away).
// - `blur_samples 16, 16`: at least and at most 16 rays a pixel; `variance 0` also keeps the
//   confidence test from ever stopping early, so every pixel takes all 16 (each from its own
//   jittered point of the pixel and of the lens), as our spp = 16 (stratified pixel and lens
//   points) does; one shadow ray per hit on both sides.
#version 3.7;
global_settings { max_trace_level 6 ambient_light rgb <1,1,1> assumed_gamma 1.0 }
camera { perspective location <-1.5,-9,1.5> sky <0,0,1> up <0,0,1> right <-1.3333333,0,0>
         look_at <0.5,1,0> angle 45
         focal_point <0.5,1,0> aperture 1.2 blur_samples 16, 16 confidence 0.9 variance 0 }
background { rgb <0.25,0.3,0.4> }
light_source { <-3,-4,8> color rgb 1 }
#macro M(C, KS, Q)
  texture { pigment { rgb C } finish { ambient 0.1 diffuse 1 specular KS roughness 1/Q } }
#end
plane { <0,0,1>, -1 texture { pigment { rgb 0.7 } finish { ambient 0.1 diffuse 1 specular 0 } } }
sphere { <-1.2,-5,0>, 1 M(<0.85,0.2,0.12>, 0.5, 50) }
sphere { <1.6,-2,0>, 1 M(<0.95,0.65,0.15>, 0.5, 50) }
sphere { <0.5,1,0>, 1 M(<0.3,0.75,0.3>, 0.5, 50) }
sphere { <-1,4.5,0>, 1 M(<0.15,0.3,0.85>, 0.5, 50) }
sphere { <2.2,8,0>, 1 M(<0.55,0.3,0.85>, 0.5, 50) }
