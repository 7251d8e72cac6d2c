// POV-Ray twin `poly`: the tangle cube as a quartic and a sextic poly with odd powers of z, turned
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is poly.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// One unit per pixel, flat colours (a mask). POV-Ray's z is rtc's -z: rotations about x and y
// change sign in the rtc twin, and odd powers of z in a polynomial change sign.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.1, 0.1, 0.1> }
#declare F = finish { ambient 1 diffuse 0 specular 0 phong 0 }
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, -5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, -5, 0, 0, 0, 0, 1, 0, -5, 0, 11.8>
  sturm scale 12 rotate <25, 30, 0> translate <-40, 0, 0> pigment { rgb <0.8, 0.2, 0.7> } finish { F } }
poly { 6, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0.6, 0, 0, -1>
  sturm scale 30 rotate <-20, 35, 0> translate <40, 0, 0> pigment { rgb <0.2, 0.7, 0.9> } finish { F } }
