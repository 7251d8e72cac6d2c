// POV-Ray twin `finish_emission`: a glowing sphere (emission, no light on it needed) over a lit floor; the emitter does not light the floor
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is finish_emission.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <200, 300, -400> color rgb 0.7 }
sphere { <-40, 10, 0>, 28 pigment { rgb <1, 0.5, 0.2> } finish { ambient 0 diffuse 0 emission rgb <1, 0.8, 0.6> } }
sphere { <40, 10, 0>, 28 pigment { rgb <0.3, 0.6, 1> } finish { ambient 0.1 diffuse 0.6 emission 0.3 } }
plane { z, 30 pigment { rgb 0.6 } finish { ambient 0.1 diffuse 0.6 } }
