// POV-Ray twin `lathe_cusp`: a linear lathe whose profile meets the axis mid-way (a cusp), and a cubic-spline vase
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is lathe_cusp.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// One unit per pixel, flat colours (a mask). POV-Ray's z is rtc's -z: rotations about x and y
// change sign in the rtc twin, and odd powers of z in a polynomial change sign.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.1, 0.1, 0.1> }
#declare F = finish { ambient 1 diffuse 0 specular 0 phong 0 }
lathe { linear_spline 5, <0, -40>, <30, -20>, <0, 0>, <30, 20>, <0, 40>
  rotate x*35 translate <-40, 0, 0> pigment { rgb <0.9, 0.2, 0.1> } finish { F } }
lathe { cubic_spline 7, <0, -40>, <10, -40>, <28, -25>, <12, 0>, <22, 30>, <14, 40>, <0, 45>
  rotate <-25, 20, 0> translate <40, 0, 0> pigment { rgb <0.1, 0.3, 0.9> } finish { F } }
