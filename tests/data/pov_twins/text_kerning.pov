// POV-Ray twin `text_kerning`: "AVAWAY" in DejaVu Sans with the pairs of the font's kern table (A-V, V-A, A-W, W-A, A-Y pulled together), and "Ta中o" whose 中 the font lacks: drawn as its .notdef box
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is text_kerning.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 charset utf8 }
// Orthographic, one unit per pixel; POV-Ray's z is rtc's -z.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.2, 0.1, 0.05> }
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 };
text { ttf "../../../stdlib/fonts/DejaVuSans.ttf" "AVAWAY" 0.2, 0
  scale 36 translate <-76, 15, 0> pigment { rgb <0.9, 0.8, 0.1> } finish { Flat } }
text { ttf "../../../stdlib/fonts/DejaVuSans.ttf" "Ta中o" 0.2, <0.05, 0, 0>
  scale 36 translate <-70, -45, 0> pigment { rgb <0.1, 0.8, 0.1> } finish { Flat } }
