// POV-Ray twin `wave_cubic_frequency`: gradient y through a cubic wave at frequency 3
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is wave_cubic_frequency.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
plane { z, 0
  pigment {
    gradient y color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] }
    cubic_wave frequency 3
    scale 60
  }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
