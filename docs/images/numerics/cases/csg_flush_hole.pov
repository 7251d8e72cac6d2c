#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 0 }
background { color rgb 0 }
camera { perspective location <0.3, 0.2, -6.0> look_at <0.0, 0.0, -0.0> right x*1.3333333333333333 up y angle 39.320120804165086 }
light_source { <3, 4, -8> color rgb 1 }
difference { box { <-1,-1,-1>, <1,1,1> } box { <-0.4,-0.4,-1>, <0.4,0.4,1> } texture { pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.8 } } }
