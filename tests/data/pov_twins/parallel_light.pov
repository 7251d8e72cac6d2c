// POV-Ray twin `parallel_light`: a parallel light low in +x and the parallel shadow of a ball out of view (at x = 96)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is parallel_light.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Pixel (i, j) looks at (i + 0.5 - 80, 60 - j - 0.5, 0): one unit per pixel. POV-Ray's z is
// rtc's -z: the lights stand on the camera's side of the plane in both.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <600, 0, -100> color rgb 1 parallel point_at <0, 0, 0> }
plane { z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 1 specular 0 phong 0 }
}
sphere { <96, 0, -16>, 5 pigment { rgb 1 } }
