// POV-Ray twin `brick`: brick with mortar on the wall's face z = 0
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is brick.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
plane { z, 0
  pigment {
    brick color rgb <0.8, 0.78, 0.72> color rgb <0.6, 0.22, 0.15>
    brick_size <20, 8, 10> mortar 1.5
    translate <3, 1, 0>
  }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
