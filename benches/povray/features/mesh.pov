// mesh.toml in POV-Ray 3.7: the same camera, point light, floor, ball and two vases. Each vase
// is cga-trace/scenes/meshes/vase.obj as a mesh2 with its vertex normals (smooth, as ours),
// which vase_mesh.py writes as vase_mesh.inc (time.sh, adaptive.py: into their work folder,
// passed with +L); the mesh2 has no texture of its own, so each copy wears its own.
// ka·ambient, kd, ks, q as in area.pov.
#version 3.7;
global_settings { max_trace_level 6 ambient_light rgb <1,1,1> assumed_gamma 1.0 }
camera { perspective location <0,-10,4> sky <0,0,1> up <0,0,1> right <-1.3333333,0,0>
         look_at <0,0,1.2> angle 45 }
background { rgb <0.25,0.3,0.4> }
light_source { <-3,-6,8> color rgb 1 }
#macro M(C, KS, Q)
  texture { pigment { rgb C } finish { ambient 0.1 diffuse 1 specular KS roughness 1/Q } }
#end
#include "vase_mesh.inc"
plane { <0,0,1>, 0 texture { pigment { rgb 0.7 } finish { ambient 0.1 diffuse 1 specular 0 } } }
object { Vase M(<0.95,0.7,0.25>, 0.7, 60) scale 0.6 translate <-1.8,0,0> }
object { Vase M(<0.15,0.3,0.85>, 0.5, 50) scale 0.6 translate <1.6,1.5,0> }
sphere { <0.2,-1.6,0.8>, 0.8 M(<0.85,0.2,0.12>, 0.5, 50) }
