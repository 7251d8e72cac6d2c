// POV-Ray twin `light_fade`: a point light fading with distance (fade_distance 15, fade_power 2)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is light_fade.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel. POV-Ray's z is
// rtc's -z: the lights stand on the camera's side of the plane in both.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <-4, 3, -10> color rgb 0.5 fade_distance 15 fade_power 2 }
plane { z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
}

