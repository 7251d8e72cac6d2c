// POV-Ray twin `cylinder_light`: a tilted cylinder light: full within its radius, a smoothstep to its falloff, tightness 1, and a ball's shadow along its axis
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is cylinder_light.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel. POV-Ray's z is
// rtc's -z: the lights stand on the camera's side of the plane in both.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <0, 0, -40> color rgb 1 cylinder point_at <-20, 5, 0> radius 25 falloff 45 tightness 1 }
plane { z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
}
sphere { <30, -10, -8>, 6 pigment { rgb 1 } finish { ambient 0 diffuse 0 specular 0 phong 0 } }
