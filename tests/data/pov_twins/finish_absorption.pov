// POV-Ray twin `finish_absorption`: clear slabs 4, 12 and 24 units thick over a checker, absorbing by fade_power 1001 (exponential): fade_distance 20, fade_color <0.9, 0.5, 0.2>
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is finish_absorption.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 max_trace_level 10 }
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <0, 0, -500> color rgb 1 }
plane { z, 0 pigment { checker rgb 1, rgb 0.5 scale 10 translate <0.3, 0.3, 0> } finish { ambient 1 diffuse 0 } }
#declare G = material {
  texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 specular 0 phong 0 } }
  interior { ior 1.33 fade_distance 20 fade_power 1001 fade_color <0.9, 0.5, 0.2> }
}
box { <-75, -50, -8>, <-27, 50, -4> material { G } }
box { <-24, -50, -16>, <24, 50, -4> material { G } }
box { <27, -50, -28>, <75, 50, -4> material { G } }
