// POV-Ray twin `superellipsoid`: superellipsoids with exponents 0.05 (a sharp box) and 3 (a pinched star), turned
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is superellipsoid.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// One unit per pixel, flat colours (a mask). POV-Ray's z is rtc's -z: rotations about x and y
// change sign in the rtc twin, and odd powers of z in a polynomial change sign.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.1, 0.1, 0.1> }
#declare F = finish { ambient 1 diffuse 0 specular 0 phong 0 }
superellipsoid { <0.05, 0.05> scale 22 rotate <30, 40, 0> translate <-40, 0, 0>
  pigment { rgb <0.9, 0.6, 0.1> } finish { F } }
superellipsoid { <3, 3> scale 38 rotate <20, -30, 10> translate <40, 0, 0>
  pigment { rgb <0.2, 0.8, 0.3> } finish { F } }
