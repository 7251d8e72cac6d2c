// POV-Ray twin `no_shadow`: two balls over a lit plane; the left one casts no shadow (no_shadow)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is no_shadow.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel. POV-Ray's z is
// rtc's -z: the lights stand on the camera's side of the plane in both.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <150, 60, -100> color rgb 1 }
plane { z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
}
sphere { <-40, 0, -20>, 12 pigment { rgb <0.9, 0.1, 0.1> } finish { ambient 1 diffuse 0 specular 0 phong 0 } no_shadow }
sphere { <20, 0, -20>, 12 pigment { rgb <0.1, 0.2, 0.9> } finish { ambient 1 diffuse 0 specular 0 phong 0 } }
