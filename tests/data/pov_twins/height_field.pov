// POV-Ray twin `height_field`: a 16-bit greyscale height map (height_field_map.png, made by height_field_map.py) with a water level, two spheres half hidden by its peak and ridge
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is height_field.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// One unit per pixel, flat colours (a mask), seen at a slant. POV-Ray's z is rtc's -z: the rtc
// twin mirrors the field's own z (`.scale([1, 1, -1])`), negates z in translations and the
// angles of turns about x and y.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.1, 0.1, 0.1> }
#declare F = finish { ambient 1 diffuse 0 specular 0 phong 0 }
union {
  height_field { png "height_field_map.png" water_level 0.12 pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
  // Behind the peak (image pixel (5, 5), so x = 0.15, z = 0.8): only its top shows.
  sphere { <0.15, 0.45, 0.92>, 0.12 pigment { rgb <0.9, 0.2, 0.1> } finish { F } }
  // In the ridge's flank.
  sphere { <0.5, 0.25, 0.3>, 0.1 pigment { rgb <0.1, 0.3, 0.9> } finish { F } }
  translate <-0.5, 0, -0.5> scale <120, 50, 90> rotate x*-40 rotate y*25 translate <0, -20, 0>
}
