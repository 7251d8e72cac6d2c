// POV-Ray twin `finish_fresnel`: an opaque black sphere of index 1.5 reflecting by the Fresnel equations, `reflection { 0, 1 fresnel on }`: 4 % head on rising to all at its rim, of a coloured background and a checker
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is finish_fresnel.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 max_trace_level 10 adc_bailout 0 }
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.9, 0.6, 0.2> }
light_source { <0, 0, -500> color rgb 1 }
plane { y, -40 pigment { checker rgb <0.2, 0.3, 0.8>, rgb 0.9 scale 10 translate <0.3, 0.3, 0.3> } finish { ambient 1 diffuse 0 } }
sphere { <0, 5, 0>, 42
  pigment { rgb 0 }
  finish { ambient 0 diffuse 0 specular 0 phong 0 reflection { 0, 1 fresnel on } }
  interior { ior 1.5 }
}
