// POV-Ray twin `marble_plain`: marble without turbulence (x through its default triangle wave), turned
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is marble_plain.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
plane { z, 0
  pigment {
    marble color_map { [0 rgb <0.05, 0.07, 0.12>] [0.35 rgb <0.8, 0.3, 0.1>] [0.7 rgb <0.95, 0.85, 0.3>] [1 rgb <0.95, 0.95, 0.9>] }
    scale 25 rotate z*30
  }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
