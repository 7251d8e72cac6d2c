#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 9 adc_bailout 0 }
background { color rgb 0 }
camera { perspective location <1.5, 1.2, -5.0> look_at <0.0, 0.0, -0.0> right x*1.3333333333333333 up y angle 51.77400875924256 }
light_source { <3, 4, -5> color rgb 1 }
plane { z, 3 texture { pigment { checker color rgb 1 color rgb 0 scale 0.4 } finish { ambient 0.2 diffuse 0.8 } } }
merge { box { <-1,-1,-1>, <0,1,1> } box { <0,-1,-1>, <1,1,1> } texture { pigment { color rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } } interior { ior 1.5 } }
