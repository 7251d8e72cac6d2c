// POV-Ray twin `triangular_edge`: triangular on the wall z = 0, along the edge between two rows of tiles
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is triangular_edge.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
plane { z, 0
  pigment {
    triangular color rgb <0.8, 0.2, 0.15> color rgb <0.95, 0.85, 0.3> color rgb <0.2, 0.45, 0.8> color rgb <0.25, 0.65, 0.3> color rgb <0.6, 0.3, 0.7> color rgb <0.9, 0.9, 0.9>
    scale 18 translate <3, 0, 0>
  }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
