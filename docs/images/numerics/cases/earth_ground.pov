#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 0 }
background { color rgb 0 }
camera { perspective location <0.0, 0.12, -0.35> look_at <0.0, 0.03, -0.0> right x*1.3333333333333333 up y angle 51.77400875924256 }
light_source { <0.3, 0.5, -0.4> color rgb 1 }
sphere { <0,-6.371e6,0>, 6.371e6 texture { pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.8 } } }
sphere { <-0.06, 0.025, 0>, 0.025 texture { pigment { color rgb <0.9,0.2,0.1> } finish { ambient 0.2 diffuse 0.8 } } }
box { <0.01, 0, 0.04>, <0.05, 0.04, 0> texture { pigment { color rgb <0.2,0.5,0.9> } finish { ambient 0.2 diffuse 0.8 } } }
