// POV-Ray twin `sphere_sweep`: a linear, a cubic (Catmull-Rom) and a B-spline sphere sweep
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is sphere_sweep.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// One unit per pixel, flat colours (a mask). POV-Ray's z is rtc's -z: the points' z change
// sign in the rtc twin.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.1, 0.1, 0.1> }
#declare F = finish { ambient 1 diffuse 0 specular 0 phong 0 }
sphere_sweep { linear_spline 4, <-65, 30, 0>, 6, <-30, 48, 10>, 10, <10, 30, -10>, 4, <60, 40, 0>, 8
  pigment { rgb <0.9, 0.2, 0.1> } finish { F } }
sphere_sweep { cubic_spline 7, <-75, 0, 0>, 5, <-60, -5, 0>, 6, <-30, 10, 10>, 8, <0, -5, -10>, 5,
  <30, 12, 0>, 9, <60, 0, 10>, 6, <75, 5, 0>, 5
  pigment { rgb <0.1, 0.8, 0.2> } finish { F } }
sphere_sweep { b_spline 6, <-70, -40, 0>, 6, <-40, -20, 10>, 10, <-10, -55, -10>, 7, <20, -25, 0>, 9,
  <50, -50, 10>, 6, <70, -35, 0>, 8
  pigment { rgb <0.1, 0.3, 0.9> } finish { F } }
