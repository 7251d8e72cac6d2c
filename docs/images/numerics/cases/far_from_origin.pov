#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 0 }
background { color rgb 0 }
camera { perspective location <100000000.0, 100000002.0, -100000006.0> look_at <100000000.0, 100000000.5, -100000000.0> right x*1.3333333333333333 up y angle 51.77400875924256 }
light_source { <100000003.0, 100000005.0, -100000002.0> color rgb 1 }
plane { y, 100000000.0 texture { pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.8 } } }
sphere { <99999999.4, 100000000.5, -100000000.0>, 0.5 texture { pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.8 } } }
box { <100000000.4, 100000000.0, -99999999.0>, <100000001.2, 100000000.8, -99999999.8> texture { pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.8 } } }
