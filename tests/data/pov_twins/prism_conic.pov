// POV-Ray twin `prism_conic`: conic-sweep prisms (the outline scaled by the height, apex at the origin) seen at a slant: a linear star frustum and a cubic oval cut off at both heights
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is prism_conic.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Orthographic, one unit per pixel; POV-Ray's z is rtc's -z.
camera { orthographic location <0, 60, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.2, 0.1, 0.05> }
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 };
prism { conic_sweep linear_spline 0.3, 1, 11,
  <0, 1>, <0.25, 0.35>, <0.95, 0.3>, <0.4, -0.1>, <0.6, -0.8>,
  <0, -0.35>, <-0.6, -0.8>, <-0.4, -0.1>, <-0.95, 0.3>, <-0.25, 0.35>, <0, 1>
  rotate 180*x scale 45 translate <-38, 25, 0> pigment { rgb <0.9, 0.1, 0.1> } finish { Flat } }
prism { conic_sweep cubic_spline 0.5, 1, 7,
  <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1>
  scale <40, 50, 30> translate <38, -30, 0> pigment { rgb <0.1, 0.2, 0.9> } finish { Flat } }
