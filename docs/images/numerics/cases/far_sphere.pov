#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 0 }
background { color rgb 0 }
camera { perspective location <0, 0, -100000000.0> look_at <0, 0, 0> right x*1.3333333333333333 up y angle 2.291831180523292e-06 }
light_source { <0, 0, -200000000.0> color rgb 1 }
sphere { <0,0,0>, 1 texture { pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.8 } } }
