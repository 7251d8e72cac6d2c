// POV-Ray twin `prism_splines`: four linear-sweep prisms seen from above at a slant: a square with a square hole (linear spline), a rounded diamond (quadratic), a Catmull-Rom oval (cubic) and a Bezier blob with a hole (bezier)
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is prism_splines.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Orthographic, one unit per pixel, looking down at a slant; POV-Ray's z is rtc's -z.
camera { orthographic location <0, 100, -50> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.2, 0.1, 0.05> }
#declare Flat = finish { ambient 1 diffuse 0 specular 0 phong 0 };
prism { linear_sweep linear_spline 0, 12, 10,
  <-20, -20>, <20, -20>, <20, 20>, <-20, 20>, <-20, -20>,
  <-8, -8>, <8, -8>, <8, 8>, <-8, 8>, <-8, -8>
  translate <-40, 0, 25> pigment { rgb <0.9, 0.1, 0.1> } finish { Flat } }
prism { linear_sweep quadratic_spline 0, 20, 6,
  <-1, 0>, <0, 1>, <1, 0>, <0, -1>, <-1, 0>, <0, 1>
  scale <30, 1, 24> translate <30, 0, 25> pigment { rgb <0.1, 0.8, 0.1> } finish { Flat } }
prism { linear_sweep cubic_spline -5, 8, 7,
  <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1>
  scale <32, 1, 18> translate <-40, 0, -30> pigment { rgb <0.1, 0.2, 0.9> } finish { Flat } }
prism { linear_sweep bezier_spline 0, 16, 32,
  <-1, 0>, <-1, 0.8>, <-0.5, 1.2>, <0, 1>,
  <0, 1>, <0.6, 0.8>, <1.3, 0.6>, <1, 0>,
  <1, 0>, <0.8, -0.7>, <0.4, -1.1>, <0, -1>,
  <0, -1>, <-0.6, -1.2>, <-1.1, -0.6>, <-1, 0>,
  <-0.4, -0.3>, <-0.4, 0.0>, <-0.4, 0.1>, <-0.4, 0.4>,
  <-0.4, 0.4>, <0.0, 0.4>, <0.2, 0.4>, <0.4, 0.4>,
  <0.4, 0.4>, <0.4, 0.1>, <0.4, 0.0>, <0.4, -0.3>,
  <0.4, -0.3>, <0.1, -0.3>, <-0.1, -0.3>, <-0.4, -0.3>
  scale <28, 1, 24> translate <35, 0, -30> pigment { rgb <0.9, 0.8, 0.1> } finish { Flat } }
