// POV-Ray camera twin `cylindrical_150`: cylindrical 150deg panorama
// size 180 120
// Rendered by render.sh (POV-Ray 3.7.0.10, no anti-aliasing); its rtc twin is cylindrical_150.rtc.
// The scene is rtc's mirrored in z (POV-Ray is left-handed): rtc's (x, y, z) is <x, y, -z> here.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
background { rgb <0.3, 0.4, 0.6> }
camera { cylinder 1 angle 150 location <0, 2, -1> look_at <1, 2, 3> right x up y*1.7453292519943295 }
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 }
plane { y, -1 pigment { checker rgb <0.8, 0.8, 0.8> rgb <0.25, 0.2, 0.15> scale 2 scale <1, 1, -1> } finish { Flat } }
sphere { <0, 1, 6>, 1.5 pigment { rgb <0.9, 0.1, 0.1> } finish { Flat } }
sphere { <6, 1, 0>, 1.5 pigment { rgb <0.1, 0.8, 0.1> } finish { Flat } }
sphere { <-6, 1, 0>, 1.5 pigment { rgb <0.1, 0.2, 0.9> } finish { Flat } }
sphere { <0, 1, -6>, 1.5 pigment { rgb <0.9, 0.8, 0.1> } finish { Flat } }
sphere { <0, 7, 0>, 1.5 pigment { rgb <0.8, 0.1, 0.8> } finish { Flat } }
sphere { <4, 0.5, 4>, 1 pigment { rgb <0.1, 0.8, 0.8> } finish { Flat } }
