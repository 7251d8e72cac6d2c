#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 9 adc_bailout 0 }
background { color rgb 0 }
camera { perspective location <0.0, 0.0, -5.0> look_at <0.0, 0.0, -0.0> right x*1.3333333333333333 up y angle 51.77400875924256 }
light_source { <2, 3, -6> color rgb 1 }
plane { z, 3 texture { pigment { checker color rgb 1 color rgb 0 scale 0.5 } finish { ambient 0.2 diffuse 0.8 } } }
difference { sphere { <0,0,0>, 1 } sphere { <0,0,0>, 0.999999 } texture { pigment { color rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } } interior { ior 1.5 } }
