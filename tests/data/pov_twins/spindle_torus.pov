// POV-Ray twin `spindle_torus`: spindle tori (minor radius 11 > major 6, POV-Ray 3.7.0's only spindle mode, rtc's `spindle: "union"`): whole, and with the front half clipped away to show the spindle inside
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is spindle_torus.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Orthographic, one unit per pixel; POV-Ray's z is rtc's -z. Each torus lies in the xz-plane
// about +y, tilted towards the camera; the clip keeps its back half (z >= -2 here).
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <-60, 80, -120> color rgb 1 shadowless }
background { rgb <0.1, 0.1, 0.1> }
#declare Lit = finish { ambient 0.1 diffuse 0.9 specular 0 phong 0 };
// POV-Ray 3.7.0 shades the spindle with the apple's normal formula (3.7.1 fixed it), so the
// tori that show their spindle are flat-lit, coloured by the distance from their centre: white
// within the spindle's tips (the spindle's surface), their colour beyond (the apple's).
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 };
#declare Back = box { <-30, -30, -2>, <30, 30, 30> };
torus { 6, 11 rotate x*30 pigment { rgb <0.9, 0.3, 0.2> } finish { Lit } translate <-40, 0, 0> }
torus { 6, 11 clipped_by { object { Back rotate x*-30 } } rotate x*30
  pigment { spherical color_map { [0 rgb <0.3, 0.8, 0.3>] [0.02 rgb 1] [1 rgb 1] } scale 9.2195 } finish { Flat } translate <0, 0, 0> }
torus { 9, 14 clipped_by { box { <-30, -30, -2>, <30, 30, 30> } } rotate y*40 rotate x*20
  pigment { spherical color_map { [0 rgb <0.2, 0.4, 0.9>] [0.02 rgb 1] [1 rgb 1] } scale 10.7703 } finish { Flat } translate <46, 0, 0> }
