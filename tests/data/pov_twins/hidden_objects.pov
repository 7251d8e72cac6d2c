// POV-Ray twin `hidden_objects`: a mirror seen face on shows a ball the camera cannot see (no_image), a ball behind the camera, and not one hidden from reflections (no_reflection)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is hidden_objects.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Orthographic, one unit per pixel; POV-Ray's z is rtc's -z. Rays start on the camera's
// plane (z = -100), so balls beyond it are seen in the mirror only.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.2, 0.1, 0.05> }
plane { z, 0
  pigment { rgb 1 }
  finish { ambient 0 diffuse 0 specular 0 phong 0 reflection 1 }
}
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 };
sphere { <-45, 10, -50>, 15 pigment { rgb <0.9, 0.1, 0.1> } finish { Flat } no_image }
sphere { <0, -10, -200>, 15 pigment { rgb <0.1, 0.8, 0.1> } finish { Flat } }
sphere { <45, 10, -200>, 15 pigment { rgb <0.9, 0.8, 0.1> } finish { Flat } no_reflection }
sphere { <45, -35, -50>, 12 pigment { rgb <0.1, 0.2, 0.9> } finish { Flat } no_reflection }
