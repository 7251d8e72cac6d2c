// POV-Ray twin `finish_metallic`: Phong highlights tinted by the surface colour, metallic 0 (left), 0.5 (middle), 1 (right)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is finish_metallic.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <-200, 300, -500> color rgb 1 }
light_source { <400, -100, -300> color rgb 0.6 }
#declare F = finish { ambient 0.05 diffuse 0.3 specular 0 phong 0.7 phong_size 12 }
sphere { <-52, 0, 0>, 25 pigment { rgb <1, 0.7, 0.15> } finish { F metallic 0 } }
sphere { <0, 0, 0>, 25 pigment { rgb <1, 0.7, 0.15> } finish { F metallic 0.5 } }
sphere { <52, 0, 0>, 25 pigment { rgb <0.2, 0.5, 1> } finish { F metallic 1 } }
