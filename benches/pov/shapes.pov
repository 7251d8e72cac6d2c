// POV-Ray twin of scenes/bench/shapes.rtc (benches/shapes.sh): the same shapes, lights and
// camera. POV-Ray's z is rtc's -z, so points' z, and turns about x and y, change sign.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// rtc's fov 40deg is vertical; POV-Ray's angle is horizontal: 2·atan(4/3·tan 20deg).
camera { location <0, 1.5, -13> look_at <0, 0, 0> right x*4/3 up y angle 51.7757 }
light_source { <6, 10, -12> color rgb 1 }
#macro Shiny(C) texture { pigment { rgb C } finish { ambient 0.1 diffuse 0.7 phong 0.3 phong_size 30 } } #end
plane { y, -4.5 Shiny(<0.8, 0.8, 0.8>) }
text { ttf "stdlib/fonts/DejaVuSans.ttf" "rtc" 0.4, 0
  scale <1, 1, -1> translate <0, 0, 0.4>  // rtc extrudes towards +z from z = 0 (POV-Ray -z)
  scale 1.6 rotate y*20 translate <-5.4, 2.4, 0> Shiny(<0.9, 0.7, 0.1>) }
prism { conic_sweep linear_spline 0.3, 1, 11,
  <0, 1>, <0.25, 0.35>, <0.95, 0.3>, <0.4, -0.1>, <0.6, -0.8>,
  <0, -0.35>, <-0.6, -0.8>, <-0.4, -0.1>, <-0.95, 0.3>, <-0.25, 0.35>, <0, 1>
  rotate x*70 scale 1.6 translate <0, 2.2, 0> Shiny(<0.9, 0.15, 0.1>) }
lathe { cubic_spline 7, <0, -1>, <0.3, -1>, <0.8, -0.6>, <0.35, 0>, <0.6, 0.8>, <0.4, 1>, <0, 1.1>
  scale 1.3 rotate x*15 translate <4.5, 2.6, 0> Shiny(<0.2, 0.4, 0.9>) }
superellipsoid { <0.25, 0.25> scale 1.1 rotate <25, 35, 0> translate <-4.5, -0.3, 0> Shiny(<0.1, 0.8, 0.3>) }
superellipsoid { <2.5, 0.6> scale 1.2 rotate <30, -20, 0> translate <0, -0.3, 0> Shiny(<0.8, 0.3, 0.8>) }
sor { 6, <0.6, -1.4>, <0.8, -1.2>, <0.5, -0.5>, <0.7, 0.3>, <1, 1>, <0.8, 1.4>
  translate <4.5, -0.3, 0> Shiny(<0.9, 0.5, 0.2>) }
sphere_sweep { b_spline 6, <-1.6, -0.2, 0>, 0.2, <-1, 0.6, 0.5>, 0.35, <-0.3, -0.6, -0.5>, 0.25,
  <0.4, 0.5, 0>, 0.4, <1, -0.6, 0.5>, 0.3, <1.6, 0.3, 0>, 0.2
  translate <-4.5, -3.2, 0> Shiny(<0.2, 0.7, 0.8>) }
height_field { function 256, 256 { 0.5 + 0.3*cos(25.1327*(x - 0.5))*cos(25.1327*(y - 0.5)) } smooth
  translate <-0.5, 0, -0.5> scale <3, 1.2, 3> translate <0, -4.2, 0> Shiny(<0.6, 0.8, 0.4>) }
isosurface { function { sqrt(pow(sqrt(x*x + z*z) - 0.9, 2) + y*y) - 0.35 - 0.05*sin(8*x) }
  contained_by { box { <-1.4, -0.5, -1.4>, <1.4, 0.5, 1.4> } } max_gradient 1.5 accuracy 0.001
  rotate x*30 translate <4.5, -3.2, 0> Shiny(<0.9, 0.3, 0.4>) }
