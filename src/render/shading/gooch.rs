//! Gooch cool-to-warm shading (COURSE.md §2.5): per light
//! `kCool·(1−N·L)/2 + kWarm·(1+N·L)/2 + ks·max(0,R·V)^n·Lc` with `kCool = (0,0,b) + alpha·kd·C`,
//! `kWarm = (y,y,0) + beta·kd·C`, no ambient term. The tone is not multiplied by the light colour
//! (the course data cannot tell; the official light is white). A shadowed light sample shows the
//! full cool tone and no highlight.

use glam::DVec3;

use super::{Surface, highlight, light_sample, occluder, transmission};
use crate::ir::{Color, GoochParams};
use crate::opt::Prepared;
use crate::render::context::Ctx;
use crate::render::record::{LightTerm, Recorder};

/// The Gooch colour of a surface point; `rec` hears each light's tone and highlight.
pub(crate) fn shade<R: Recorder>(
    scene: &Prepared,
    s: &Surface<'_>,
    g: &GoochParams,
    ctx: &mut Ctx,
    rec: &mut R,
) -> Color {
    let kd_c = s.mat.kd * s.color;
    let cool = DVec3::new(0.0, 0.0, g.b) + g.alpha * kd_c;
    let warm = DVec3::new(g.y, g.y, 0.0) + g.beta * kd_c;
    let mut c = Color::ZERO;
    for (i, light) in scene.lights().iter().enumerate() {
        let mut term = LightTerm::new(i);
        let (first, count) = ctx.lights.cells(light.samples);
        for j in 0..count {
            let k = (first + j) % light.samples;
            let w = ctx.lights.weight(light.samples, k);
            let share = w.value();
            let ls = light_sample(light, i, k, w, s, &ctx.rng);
            let n_dot_l = s.n.dot(ls.l);
            let tone = cool * (1.0 - n_dot_l) / 2.0 + warm * (1.0 + n_dot_l) / 2.0;
            if R::ON {
                term.samples += 1;
            }
            if n_dot_l <= 0.0 {
                if R::ON {
                    term.behind += 1;
                    term.diffuse += share * tone;
                }
                // Facing away: the blend already leans cool; no highlight from behind.
                c += share * tone;
            } else {
                match transmission(scene, s, &ls, &mut ctx.stats) {
                    Some(pass) if pass == Color::ONE => {
                        c += share * tone + highlight(s, ls.l, n_dot_l) * ls.color;
                        if R::ON {
                            term.diffuse += share * tone;
                            term.specular += highlight(s, ls.l, n_dot_l) * ls.color;
                        }
                    }
                    // Through glass: the warm side of the blend in proportion to the light
                    // that comes through, the highlight tinted by it.
                    Some(pass) => {
                        let f = pass.element_sum() / 3.0;
                        c += share * (cool + f * (tone - cool))
                            + highlight(s, ls.l, n_dot_l) * ls.color * pass;
                        if R::ON {
                            term.tinted += 1;
                            term.diffuse += share * (cool + f * (tone - cool));
                            term.specular += highlight(s, ls.l, n_dot_l) * ls.color * pass;
                        }
                    }
                    None => {
                        c += share * cool;
                        if R::ON {
                            term.blocked += 1;
                            term.diffuse += share * cool;
                            term.occluder = term.occluder.or_else(|| occluder(scene, s, &ls));
                        }
                    }
                }
            }
        }
        if R::ON {
            rec.light(term);
        }
    }
    c
}
