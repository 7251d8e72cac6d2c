// POV-Ray twin `brick_end_face`: brick turned about y: the wall's end face (z-y), where the joints run the other way
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is brick_end_face.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
plane { z, 0
  pigment {
    brick color rgb <0.85, 0.85, 0.8> color rgb <0.5, 0.2, 0.12>
    brick_size <20, 8, 12> mortar 1.2
    rotate y*90 translate <2.5, 0.5, 0>
  }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
