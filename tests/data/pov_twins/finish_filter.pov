// POV-Ray twin `finish_filter`: glass slabs seen head on over a checker: rgbf (left: filter 0.6), rgbft (middle: filter 0.3, transmit 0.4), rgbt (right: transmit 0.7)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is finish_filter.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 max_trace_level 10 }
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <0, 0, -500> color rgb 1 }
plane { z, 0 pigment { checker rgb 1, rgb 0.2 scale 10 translate <0.3, 0.3, 0> } finish { ambient 1 diffuse 0 } }
#declare G = finish { ambient 0 diffuse 0 specular 0 phong 0 }
box { <-75, -50, -20>, <-27, 50, -10> pigment { rgbf <1, 0.3, 0.2, 0.6> } finish { G } interior { ior 1.5 } }
box { <-24, -50, -20>, <24, 50, -10> pigment { rgbft <1, 0.3, 0.2, 0.3, 0.4> } finish { G } interior { ior 1.5 } }
box { <27, -50, -20>, <75, 50, -10> pigment { rgbt <1, 0.3, 0.2, 0.7> } finish { G } interior { ior 1.5 } }
