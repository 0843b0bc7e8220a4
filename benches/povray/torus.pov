// cga-trace/scenes/torus.toml in POV-Ray 3.7: the same camera, lights, floor, sphere and
// tori (POV-Ray's torus lies in its xz-plane about the y axis: turned onto each normal by
// Reorient_Trans, then moved to its centre). Right-handed with z up, as ../../shared/anchors/
// povray/primitives.pov; the shading constants approximate ours, the geometry is the same.
#version 3.7;
#include "transforms.inc"
global_settings { max_trace_level 5 ambient_light rgb <1,1,1> assumed_gamma 1.0 }
// x_max = 1.4 at focal length 1: a horizontal field of view of 2 atan(0.7) = 69.984°.
camera { perspective location <0,-14,5> sky <0,0,1> up <0,0,1> right <-1.3333333,0,0>
         look_at <0,0,0> angle 69.98432 }
background { rgb <0.05,0.06,0.09> }
light_source { <-6,-10,14> rgb <1,0.95,0.9> }
light_source { <8,-4,6> rgb <0.3,0.35,0.5> }
#macro M(C, KD, KS, KR)
  texture { pigment { rgb C } finish { ambient 0.2 diffuse KD specular KS roughness 0.02 reflection KR } }
#end
plane { <0,0,1>, -2 M(<0.55,0.55,0.6>, 0.8, 0.2, 0.35) }
torus { 2.0, 0.45 Reorient_Trans(y, <1,-0.5,1.5>) translate <-2.5,1,0.5> M(<0.9,0.35,0.1>, 1, 0.7, 0.15) }
torus { 2.2, 0.08 Reorient_Trans(y, <0,0,1>) translate <2.8,2,-1.2> M(<0.85,0.8,0.3>, 1, 0.9, 0.3) }
torus { 1.0, 0.95 Reorient_Trans(y, <0.2,0,1>) translate <2.6,-2,-1> M(<0.2,0.5,0.9>, 1, 0.6, 0.1) }
sphere { <-2.5,1,0.5>, 1 M(<0.85,0.85,0.9>, 0.2, 1, 0.8) }
