// POV-Ray twin `finish_brilliance`: the diffuse falloff (N.L)^brilliance, brilliance 1 (left), 3 (middle), 0.4 (right)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is finish_brilliance.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Orthographic, one unit per pixel. POV-Ray's z is rtc's -z.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <-300, 400, -500> color rgb 1 }
#declare F = finish { ambient 0.1 diffuse 0.9 specular 0 phong 0 }
sphere { <-52, 0, 0>, 25 pigment { rgb <0.9, 0.6, 0.3> } finish { F brilliance 1 } }
sphere { <0, 0, 0>, 25 pigment { rgb <0.9, 0.6, 0.3> } finish { F brilliance 3 } }
sphere { <52, 0, 0>, 25 pigment { rgb <0.9, 0.6, 0.3> } finish { F brilliance 0.4 } }
