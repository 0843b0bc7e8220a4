// area.toml in POV-Ray 3.7: the same camera, floor, balls and ONE disk of light of radius
// R = 1.5 facing down, as a circular 4x4 area_light (16 lights of 1/16 of its colour).
// Right-handed with z up, as ../torus.pov; a material's ka·ambient, kd, ks and q become
// POV-Ray's ambient, diffuse, specular and roughness 1/q.
//
// What POV-Ray 3.7 does with it (source/backend/render/trace.cpp of 3.7.0.10):
// - No `adaptive` keyword: the level defaults to 100 (lighting/point.cpp), so the recursive
//   corner test always subdivides and every one of the 16 grid points gets its own shadow
//   ray, once each (`adaptive 0` would test the 4 corners and stop where they agree: still
//   adaptive). `adaptive 1` would do the same as the default for a 4x4 grid.
// - `area_illumination on`: the diffuse and specular terms are summed over the 16 points,
//   each 1/16 of the colour, as ours are (without it POV-Ray shades from the centre only and
//   uses the grid for the shadow alone). POV-Ray multiplies that sum by the fraction of the
//   16 shadow rays that got through; ours weights each point's term by its own ray.
// - `jitter`: each grid point moves at random within its cell, the analogue of our stratified
//   points. The cells' centres run from -1/2 to +1/2 of each axis, so the jittered points
//   cover -2/3 .. +2/3 of it; axes of 1.5 R (not 2 R) make that the square of side 2 R, which
//   `circular` maps onto the disk of radius R. The axes x and y span the disk's plane (its
//   normal is -z); no `orient` (that turns the light to face each hit, as our sphere lights).
#version 3.7;
global_settings { max_trace_level 6 ambient_light rgb <1,1,1> assumed_gamma 1.0 }
camera { perspective location <0,-10,4> sky <0,0,1> up <0,0,1> right <-1.3333333,0,0>
         look_at <0,0,0> angle 45 }
background { rgb <0.25,0.3,0.4> }
#declare R = 1.5;
light_source { <-1,-2,7> color rgb 1
  area_light 1.5*R*x, 1.5*R*y, 4, 4 circular jitter area_illumination on }
#macro M(C, KS, Q)
  texture { pigment { rgb C } finish { ambient 0.1 diffuse 1 specular KS roughness 1/Q } }
#end
plane { <0,0,1>, -1 texture { pigment { rgb 0.7 } finish { ambient 0.1 diffuse 1 specular 0 } } }
sphere { <-2.3,0.5,0>, 1 M(<0.85,0.2,0.12>, 0.5, 50) }
sphere { <0.2,-1.2,0>, 1 M(<0.3,0.75,0.3>, 0.5, 50) }
sphere { <2.5,1.2,0>, 1 M(<0.15,0.3,0.85>, 0.5, 50) }
