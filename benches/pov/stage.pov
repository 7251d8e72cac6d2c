// stage.pov: POV-Ray twin of scenes/bench/stage.rtc (benches/stage.sh): fog + a spot light +
// Fresnel glass. POV-Ray's z is rtc's -z; its camera `angle` is horizontal (rtc's fov 45deg
// vertical at 4:3). `Declare=NoFog=1`, `Declare=NoSpot=1`, `Declare=NoFresnel=1` take each
// feature away, as rtc's `--set fogged=false`, `--set spot=false`, `--set fresnel=false`.
#version 3.7;
#ifndef (NoFog) #declare NoFog = 0; #end
#ifndef (NoSpot) #declare NoSpot = 0; #end
#ifndef (NoFresnel) #declare NoFresnel = 0; #end
global_settings { assumed_gamma 1.0 ambient_light 1 max_trace_level 5 adc_bailout 0 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 2 * degrees(atan(tan(radians(22.5)) * 4 / 3)) right x*4/3 }
background { rgb <0.3, 0.4, 0.6> }
#if (!NoFog) fog { distance 15 color rgb <0.7, 0.7, 0.75> } #end
#if (NoSpot)
light_source { <3, 8, -5> color rgb 1 }
#else
light_source { <3, 8, -5> color rgb 1 spotlight point_at <0, 0, 0> radius 20 falloff 30 tightness 1 }
#end
#declare Matte = finish { ambient 0.1 diffuse 0.7 phong 0.3 phong_size 30 };
plane { y, 0 pigment { rgb <0.75, 0.75, 0.7> } finish { Matte } }
sphere { <0, 1, 0>, 1
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 phong 0.8 phong_size 200
    #if (NoFresnel) reflection 0.1 #else reflection { 0, 1 fresnel on } #end conserve_energy }
  interior { ior 1.5 }
}
#declare I = 0;
#while (I < 12)
  #declare A = radians(30 * I);
  sphere { <3.2 * cos(A), 0.5, -(3.2 * sin(A) - 1)>, 0.5 pigment { rgb <0.9, 0.5, 0.4> } finish { Matte } }
  #declare I = I + 1;
#end
