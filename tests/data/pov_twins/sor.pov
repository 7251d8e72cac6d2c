// POV-Ray twin `sor`: a closed vase and an open, flaring tube (surfaces of revolution)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is sor.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// One unit per pixel, flat colours (a mask). POV-Ray's z is rtc's -z: rotations about x and y
// change sign in the rtc twin.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.1, 0.1, 0.1> }
#declare F = finish { ambient 1 diffuse 0 specular 0 phong 0 }
sor { 6, <10, -50>, <25, -35>, <12, -10>, <18, 10>, <28, 30>, <20, 45>
  rotate x*30 translate <-40, 0, 0> pigment { rgb <0.9, 0.2, 0.1> } finish { F } }
sor { 5, <5, -40>, <15, -30>, <8, 0>, <20, 30>, <25, 40> open
  rotate <-40, 20, 0> translate <40, 0, 0> pigment { rgb <0.1, 0.3, 0.9> } finish { F } }
