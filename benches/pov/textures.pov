// textures.pov: POV-Ray 3.7 twin of scenes/bench/textures.rtc (benches/textures.sh), the
// pattern-heavy benchmark of issue 36. A floor of granite with a wrinkles bump and 49 spheres on
// a 7 x 7 grid (50 objects), the spheres in turn marble, granite, wood, crackle and marble with a
// wrinkles bump; marble, wood and crackle carry 6 octaves of turbulence, as in the rtc scene.
// 640 x 480 with 2 x 2 supersampling from the command line (+A0.0 +AM1 +R2 -J), one light with
// shadows. `Declare=Plain=1` gives every object a plain colour instead; `Declare=NoBump=1`
// keeps the colour patterns and drops the wrinkles normals.
// The world's coordinates are rtc's (right-handed: the camera's `right -x*4/3` makes the
// picture the same, not mirrored); each sphere is made at the origin with its texture and then
// moved, so its patterns move with it as rtc's do.
#version 3.7;

#ifndef (Plain) #declare Plain = 0; #end
#ifndef (NoBump) #declare NoBump = 0; #end

global_settings { assumed_gamma 1.0 ambient_light 1 }

// rtc: eye [0, 7, 12], center [0, 0.5, 0], vertical fov 40deg, 640 x 480.
// |direction| = 0.5 / tan(20deg) for an up vector of length 1.
camera {
  perspective
  location <0, 7, 12>
  up y
  right -x*640/480
  direction z*0.5/tan(radians(20))
  sky y
  look_at <0, 0.5, 0>
}

light_source { <-8, 14, 10> color rgb 1 }

#declare Fin = finish { ambient 0.1 diffuse 0.7 phong 0.3 phong_size 40 };

#declare MarbleP = pigment {
  marble turbulence 0.8 octaves 6
  color_map { [0 rgb <0.9, 0.88, 0.82>] [0.6 rgb <0.6, 0.6, 0.62>] [1 rgb <0.15, 0.15, 0.2>] }
  scale 0.5
}
#declare GraniteP = pigment {
  granite
  color_map { [0 rgb <0.55, 0.4, 0.35>] [0.5 rgb <0.8, 0.7, 0.65>] [1 rgb <0.2, 0.15, 0.15>] }
  scale 0.8
}
#declare WoodP = pigment {
  wood turbulence 0.1 octaves 6
  color_map { [0 rgb <0.75, 0.5, 0.25>] [1 rgb <0.45, 0.25, 0.1>] }
  scale 0.15
}
#declare CrackleP = pigment {
  crackle turbulence 0.3 octaves 6
  color_map { [0 rgb <0.1, 0.1, 0.12>] [0.15 rgb <0.7, 0.65, 0.55>] [1 rgb <0.85, 0.8, 0.7>] }
  scale 0.3
}
// A pigment with the finish, and the wrinkles normal when `Bump` (and bumps are on).
#macro Tex(P, Bump)
  texture {
    pigment { P }
    #if (Bump & !NoBump) normal { wrinkles 0.5 scale 0.2 } #end
    finish { Fin }
  }
#end

#if (Plain)
  #declare Kinds = array[5] {
    texture { pigment { rgb <0.8, 0.78, 0.74> } finish { Fin } },
    texture { pigment { rgb <0.6, 0.48, 0.43> } finish { Fin } },
    texture { pigment { rgb <0.6, 0.38, 0.18> } finish { Fin } },
    texture { pigment { rgb <0.7, 0.65, 0.55> } finish { Fin } },
    texture { pigment { rgb <0.8, 0.78, 0.74> } finish { Fin } }
  }
  #declare Floor = texture { pigment { rgb <0.5, 0.45, 0.4> } finish { Fin } };
#else
  #declare K0 = Tex(MarbleP, 0)
  #declare K1 = Tex(GraniteP, 0)
  #declare K2 = Tex(WoodP, 0)
  #declare K3 = Tex(CrackleP, 0)
  #declare K4 = Tex(MarbleP, 1)
  #declare Kinds = array[5] { K0, K1, K2, K3, K4 }
  #declare Floor = Tex(pigment { GraniteP scale 2 }, 1);
#end

plane { y, 0 texture { Floor } }

#declare I = 0;
#while (I < 49)
  sphere { 0, 0.8 texture { Kinds[mod(I, 5)] } translate <2*mod(I, 7) - 6, 0.8, 2*div(I, 7) - 6> }
  #declare I = I + 1;
#end
