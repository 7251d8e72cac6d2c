// POV-Ray twin `fog_constant`: constant fog (fog_type 1) over a flat-lit floor and the background
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is fog_constant.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// The floor is one flat colour (ambient 1): every change across it is the fog's exp(-d/6).
// Rays that miss travel POV-Ray's BOUND_HUGE through the fog and show its colour.
camera { perspective location <0, 1, 0> look_at <0, 0.6, 4> right x*4/3 up y angle 60 }
background { rgb <0.1, 0.1, 0.1> }
plane { y, 0
  pigment { rgb <0.2, 0.5, 0.3> }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
fog { fog_type 1 distance 6 color rgb <0.75, 0.8, 0.85> }
