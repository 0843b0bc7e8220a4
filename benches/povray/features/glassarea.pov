// glassarea.toml in POV-Ray 3.7: glass.pov's camera, floor, glass ball and coloured balls
// under area.pov's disk light (a circular 4x4 area_light with jitter and area_illumination
// on, axes 1.5 R: 16 shadow rays and 16 shading terms per hit, as ours) in place of the point
// light. Right-handed with z up, as ../torus.pov; ka·ambient, kd, ks, q as in area.pov; the
// glass (filter 1, Fresnel reflection with conserve_energy, ior 1.5) and max_trace_level 9
// (= our max_depth 8) as in glass.pov; shadow rays pass the clear glass, as ours.
#version 3.7;
global_settings { max_trace_level 9 ambient_light rgb <1,1,1> assumed_gamma 1.0 }
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
sphere { <0,-2.5,0.4>, 1.4
  texture { pigment { rgbf 1 }
            finish { ambient 0 diffuse 0 specular 1 roughness 1/300
                     reflection { 0, 1 fresnel on } conserve_energy } }
  interior { ior 1.5 } }
sphere { <-1.4,2,0>, 1 M(<0.85,0.2,0.12>, 0.5, 50) }
sphere { <1.5,3,0>, 1 M(<0.15,0.3,0.85>, 0.5, 50) }
