// POV-Ray twin `sky_gradient`: a sky_sphere with a gradient y colour map, seen by a perspective camera looking up
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is sky_gradient.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Nothing but sky: every pixel is the sky's colour along its ray. POV-Ray's z is rtc's -z; the
// gradient along y does not see the difference. Below the horizon the gradient wraps (frac(y)).
camera { perspective location <0, 0, 0> look_at <0, 0.3, 1> right x*4/3 up y angle 90 }
sky_sphere {
  pigment {
    gradient y
    color_map { [0 rgb <0.9, 0.85, 0.7>] [0.4 rgb <0.4, 0.6, 0.9>] [1 rgb <0.05, 0.15, 0.5>] }
  }
}
