// POV-Ray twin `modifiers`: a box with a ball-shaped cavity made with `inverse`, a ball opened by `clipped_by`, and a blob with a cylinder component
// Rendered by render.sh (POV-Ray 3.7.0.10, 160x120, no anti-aliasing); its rtc twin is modifiers.rtc.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
// Orthographic, one unit per pixel; POV-Ray's z is rtc's -z (the camera and light stand at
// negative z here, at positive z in rtc).
camera { orthographic location <0, 0, -100> look_at <0, 0, 0> right x*160 up y*120 }
light_source { <-60, 80, -120> color rgb 1 shadowless }
background { rgb <0.1, 0.1, 0.1> }
#declare Lit = finish { ambient 0.1 diffuse 0.9 specular 0 phong 0 };
// Left: the box minus a ball centred on its front face, as box ∩ inverse(ball); the cavity's
// wall is the ball's (blue).
intersection {
  box { <-22, -22, -22>, <22, 22, 22> pigment { rgb <0.9, 0.2, 0.1> } finish { Lit } }
  sphere { <0, 0, -22>, 17 inverse pigment { rgb <0.1, 0.3, 0.9> } finish { Lit } }
  translate <-52, 10, 0>
}
// Middle: a ball with its front and its top clipped away: its inside shows.
sphere { <0, 0, 0>, 24
  clipped_by { box { <-30, -30, -6>, <30, 14, 30> } }
  pigment { rgb <0.2, 0.8, 0.2> } finish { Lit }
  translate <0, -10, 0>
}
// Right: a blob of a slanted cylinder component (round ends) and a ball.
blob { threshold 0.5
  cylinder { <38, -35, 0>, <62, 30, 0>, 12, 1 }
  sphere { <64, -30, 0>, 16, 1 }
  pigment { rgb <0.9, 0.8, 0.1> } finish { Lit }
}
