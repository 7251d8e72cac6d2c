// POV-Ray twin `spot_light`: a spot light: full inside its radius, a smoothstep to its falloff, tightness 2
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is spot_light.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel. POV-Ray's z is
// rtc's -z: the lights stand on the camera's side of the plane in both.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <3, -2, -40> color rgb 1 spotlight point_at <5, 1, 0> radius 20 falloff 35 tightness 2 }
plane { z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
}

