// POV-Ray twin `bicubic_patch`: a bulging patch, one with a row collapsed to a point (an apex)
// and one that folds back over itself (a silhouette inside the patch), as flat-colour masks.
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is bicubic_patch.rtc.
// POV-Ray tessellates (type 1, flatness 0, 2^5 steps each way: 32 x 32 cells); rtc traces the
// patches exactly, so pixels on a silhouette may differ.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// One unit per pixel, flat colours (a mask). POV-Ray's z is rtc's -z: the points' z change
// sign in the rtc twin.
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
background { rgb <0.1, 0.1, 0.1> }
#declare F = finish { ambient 1 diffuse 0 specular 0 phong 0 }
bicubic_patch { type 1 flatness 0 u_steps 5 v_steps 5
  <-75, 15, 0>, <-62, 10, 20>, <-48, 12, 20>, <-35, 18, 0>,
  <-78, 28, 15>, <-62, 28, -40>, <-48, 30, -40>, <-32, 30, 15>,
  <-74, 42, 15>, <-60, 44, -40>, <-46, 44, -40>, <-30, 46, 15>,
  <-72, 55, 0>, <-60, 62, 20>, <-46, 60, 20>, <-34, 54, 0>
  pigment { rgb <0.9, 0.2, 0.1> } finish { F } }
bicubic_patch { type 1 flatness 0 u_steps 5 v_steps 5
  <45, 55, 0>, <45, 55, 0>, <45, 55, 0>, <45, 55, 0>,
  <15, 35, 10>, <35, 40, -30>, <55, 42, -30>, <75, 35, 10>,
  <12, 20, 10>, <32, 22, -30>, <58, 24, -30>, <78, 18, 10>,
  <20, 5, 0>, <35, 0, 20>, <55, 0, 20>, <70, 5, 0>
  pigment { rgb <0.1, 0.3, 0.9> } finish { F } }
bicubic_patch { type 1 flatness 0 u_steps 5 v_steps 5
  <-60, -52, 0>, <-30, -56, 10>, <0, -56, 10>, <30, -52, 0>,
  <-62, -20, -20>, <-30, -22, -30>, <0, -22, -30>, <32, -20, -20>,
  <-58, 10, -50>, <-30, 8, -60>, <0, 8, -60>, <28, 10, -50>,
  <-55, -35, -80>, <-28, -38, -90>, <2, -38, -90>, <25, -35, -80>
  pigment { rgb <0.1, 0.8, 0.2> } finish { F } }
