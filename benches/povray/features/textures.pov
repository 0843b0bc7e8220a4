// textures.toml in POV-Ray 3.7: the same camera, point light, checker floor and ball wrapped
// in cga-trace/scenes/maps/grid.png. Right-handed with z up, as ../torus.pov; ka·ambient, kd,
// ks, q as in area.pov.
//
// What POV-Ray 3.7 does with it (source/backend/pattern/pattern.cpp and
// source/backend/support/imageutil.cpp of 3.7.0.10):
// - `checker`: the first colour where ⌊x⌋ + ⌊y⌋ + ⌊z⌋ is even, the second where it is odd
//   (each coordinate nudged up by a small tolerance first), cells of 1 unit: on the plane
//   z = 0 that is our checker of cells ⌊u⌋ + ⌊v⌋, u = x and v = y from the plane's point,
//   the origin.
// - `image_map { png … map_type 1 }`: spherical, about the pigment's y axis, u = 0 at +x and
//   growing towards +z, v from the bottom. Ours is about z, u = 0 at -x and growing towards
//   +y, v from the top: the matrix takes the pigment's x, y, z to -x, z, -y (a mirror, as
//   POV-Ray's angle turns the other way about its axis). `interpolate 2`: bilinear, as ours.
//   The PNG is decoded from sRGB to linear (assumed_gamma 1.0), as ours. Its path is
//   relative to this folder: render with `+L` this folder, as time.sh does.
#version 3.7;
global_settings { max_trace_level 6 ambient_light rgb <1,1,1> assumed_gamma 1.0 }
camera { perspective location <-7,-7,6> sky <0,0,1> up <0,0,1> right <-1.3333333,0,0>
         look_at <0,0,1.2> angle 45 }
background { rgb <0.25,0.3,0.4> }
light_source { <-2,-6,9> color rgb 1 }
plane { <0,0,1>, 0
  texture { pigment { checker color rgb 0.8 color rgb <0.2,0.25,0.35> }
            finish { ambient 0.1 diffuse 1 specular 0 } } }
sphere { <0,0,0>, 1.5
  texture { pigment { image_map { png "../../../cga-trace/scenes/maps/grid.png" map_type 1 interpolate 2 }
                      matrix <-1,0,0, 0,0,1, 0,-1,0, 0,0,0> }
            finish { ambient 0.1 diffuse 1 specular 0.5 roughness 1/50 } }
  translate <0,0,1.5> }
