// POV-Ray twin `sky_pattern`: a sky_sphere with an onion pattern, scaled and moved, read at the ray's direction
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is sky_pattern.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Nothing but sky. The pattern is symmetric under z -> -z (POV-Ray's z is rtc's -z), so both
// read the same number along a ray.
camera { perspective location <0, 0, 0> look_at <0, 0.3, 1> right x*4/3 up y angle 90 }
sky_sphere {
  pigment {
    onion
    color_map { [0 rgb <0.1, 0.2, 0.5>] [0.5 rgb <0.95, 0.9, 0.8>] [1 rgb <0.1, 0.2, 0.5>] }
    scale 0.3
    translate <0.2, 0, 0>
  }
}
