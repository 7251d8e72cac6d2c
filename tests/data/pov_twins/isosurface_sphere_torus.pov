// POV-Ray twin `isosurface_sphere_torus`: isosurfaces of a sphere and a torus function in box containers, and a ball cut by a plane function, closed by its sphere container's wall
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is isosurface_sphere_torus.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// One unit per pixel, flat colours (a mask). POV-Ray's z is rtc's -z: rotations about x and y
// change sign in the rtc twin (these functions are even in z).
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.1, 0.1, 0.1> }
#declare F = finish { ambient 1 diffuse 0 specular 0 phong 0 }
isosurface { function { sqrt(x*x + y*y + z*z) - 25 } contained_by { box { <-28, -28, -28>, <28, 28, 28> } }
  max_gradient 1.2 accuracy 0.001
  translate <-45, 25, 0> pigment { rgb <0.9, 0.2, 0.1> } finish { F } }
isosurface { function { sqrt(pow(sqrt(x*x + z*z) - 22, 2) + y*y) - 8 } contained_by { box { <-31, -9, -31>, <31, 9, 31> } }
  max_gradient 1.2 accuracy 0.001
  rotate x*50 translate <35, 25, 0> pigment { rgb <0.1, 0.3, 0.9> } finish { F } }
isosurface { function { y - 0.4*x } threshold 3 contained_by { sphere { <0, 0, 0>, 22 } }
  max_gradient 1.2 accuracy 0.001
  rotate x*40 translate <0, -30, 0> pigment { rgb <0.2, 0.8, 0.3> } finish { F } }
