// POV-Ray twin `warp_spherical_latitude`: gradient y wrapped round a sphere: the latitude
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is warp_spherical_latitude.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
plane { z, 0
  pigment {
    gradient y color_map { [0 rgb <1, 0, 0>] [0.25 rgb <1, 1, 0>] [0.5 rgb <0, 1, 0>] [0.75 rgb <0, 0, 1>] [1 rgb <1, 0, 1>] }
    warp { spherical }
    rotate x*60 scale 50
  }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
