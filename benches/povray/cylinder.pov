// cga-trace/scenes/cylinder.toml in POV-Ray 3.7: the same camera, lights, floor, cylinders
// and cones (POV-Ray's `open` is our `caps = false`). Right-handed with z up, as torus.pov;
// the shading constants approximate ours.
#version 3.7;
global_settings { max_trace_level 5 ambient_light rgb <1,1,1> assumed_gamma 1.0 }
camera { perspective location <0,-14,5> sky <0,0,1> up <0,0,1> right <-1.3333333,0,0>
         look_at <0,0,0> angle 69.98432 }
background { rgb <0.05,0.06,0.09> }
light_source { <-6,-10,14> rgb <1,0.95,0.9> }
light_source { <8,-4,6> rgb <0.3,0.35,0.5> }
#macro M(C, KD, KS, KR)
  texture { pigment { rgb C } finish { ambient 0.2 diffuse KD specular KS roughness 0.02 reflection KR } }
#end
plane { <0,0,1>, -2 M(<0.55,0.55,0.6>, 0.8, 0.2, 0.35) }
cylinder { <-4.5,0,-2>, <-2,1.5,1.5>, 0.8 M(<0.9,0.35,0.1>, 1, 0.7, 0.15) }
cylinder { <-0.5,2,-1.5>, <1.5,3,-1.5>, 0.5 open M(<0.85,0.8,0.3>, 1, 0.9, 0.3) }
cone { <0,-2,-2>, 1, <0,-2,0.5>, 0 M(<0.2,0.5,0.9>, 1, 0.6, 0.1) }
cone { <3.5,0,-2>, 1.2, <3,0.5,0.5>, 0.4 M(<0.85,0.85,0.9>, 0.2, 1, 0.8) }
