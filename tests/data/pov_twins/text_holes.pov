// POV-Ray twin `text_holes`: "Bg%" in DejaVu Sans seen face on, the holes of B, g and % open, and "o" seen at a slant (its hole and its extruded side)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is text_holes.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Orthographic, one unit per pixel; POV-Ray's z is rtc's -z. text: 1 unit per em, baseline on
// y = 0, the first glyph's left edge at x = 0, extruded from z = 0 to the thickness.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.2, 0.1, 0.05> }
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 };
text { ttf "../../../stdlib/fonts/DejaVuSans.ttf" "Bg%" 0.2, 0
  scale 50 translate <-75, 5, 0> pigment { rgb <0.9, 0.8, 0.1> } finish { Flat } }
text { ttf "../../../stdlib/fonts/DejaVuSans.ttf" "o" 0.1, 0
  scale 55 rotate <-20, 35, 0> translate <40, -50, 0> pigment { rgb <0.1, 0.8, 0.1> } finish { Flat } }
