// POV-Ray twin `fog_ground`: ground fog (fog_type 2, offset 0.3, altitude 0.6) over a flat-lit floor and the background
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is fog_ground.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// The fog is full below y = 0.3 and thins as 1/(1 + h^2) above it: rays that climb out of it
// into the sky keep some of the background.
camera { perspective location <0, 2, 0> look_at <0, 1.4, 4> right x*4/3 up y angle 70 }
background { rgb <0.3, 0.5, 0.9> }
plane { y, 0
  pigment { rgb <0.5, 0.35, 0.2> }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
fog { fog_type 2 distance 3 color rgb <0.9, 0.9, 0.9> fog_offset 0.3 fog_alt 0.6 }
