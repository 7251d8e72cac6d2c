//! Phong shading exactly as COURSE.md §2.5 (reproduces the consensus renders):
//! `I = Σ_lights [ka·C·Lc + kd·max(0,N·L)·C·Lc + ks·max(0,R·V)^n·Lc]`; the highlight is not tinted
//! by C; a shadowed light keeps its ambient term. With [`AmbientConvention::Once`] the ambient term
//! is `ka·C` once, without light colour. POV-Ray's finish terms change it only where a material
//! asks ([`super::finish`]): the diffuse `N·L` becomes `(N·L)^brilliance` and a metallic
//! highlight takes the colour.

use super::{LightSample, Surface, finish, highlight, light_sample, occluder, transmission};
use crate::ir::{AmbientConvention, Color};
use crate::opt::Prepared;
use crate::render::context::Ctx;
use crate::render::record::{LightTerm, Recorder};

/// The Phong colour of a surface point; `rec` hears each light's terms.
pub(crate) fn shade<R: Recorder>(
    scene: &Prepared,
    s: &Surface<'_>,
    ctx: &mut Ctx,
    rec: &mut R,
) -> Color {
    let m = s.mat;
    let mut c = Color::ZERO;
    if scene.settings().ambient == AmbientConvention::Once {
        c += m.ka * s.color;
        if R::ON {
            rec.ambient(m.ka * s.color);
        }
    }
    for (i, light) in scene.lights().iter().enumerate() {
        let mut term = LightTerm::new(i);
        if scene.settings().ambient == AmbientConvention::PerLight {
            c += m.ka * s.color * light.color;
            if R::ON {
                term.ambient = m.ka * s.color * light.color;
            }
        }
        let (first, count) = ctx.lights.cells(light.samples);
        for j in 0..count {
            let k = (first + j) % light.samples;
            let w = ctx.lights.weight(light.samples, k);
            let ls = light_sample(light, i, k, w, s, &ctx.rng);
            let n_dot_l = s.n.dot(ls.l);
            if R::ON {
                term.samples += 1;
            }
            // Facing away: no diffuse, and the light is behind the surface, so no highlight either
            // (a closed surface would shadow it; this also skips the shadow ray).
            if n_dot_l <= 0.0 {
                if R::ON {
                    term.behind += 1;
                }
                continue;
            }
            let Some(pass) = transmission(scene, s, &ls, &mut ctx.stats) else {
                if R::ON {
                    term.blocked += 1;
                    term.occluder = term.occluder.or_else(|| occluder(scene, s, &ls));
                }
                continue;
            };
            let (diffuse, specular) = lit(s, &ls, n_dot_l, pass);
            c += diffuse + specular;
            if R::ON {
                term.tinted += u32::from(pass != Color::ONE);
                term.diffuse += diffuse;
                term.specular += specular;
            }
        }
        if R::ON {
            rec.light(term);
        }
    }
    c
}

/// The diffuse and specular light of sample `ls` at `s`, `pass` of it getting through.
#[inline]
fn lit(s: &Surface<'_>, ls: &LightSample, n_dot_l: f64, pass: Color) -> (Color, Color) {
    // `pass` is exactly ONE without glass in the way, so this is the plain sum then.
    let lc = ls.color * pass;
    let spec = highlight(s, ls.l, n_dot_l);
    let specular = if s.mat.metallic == 0.0 {
        spec * lc
    } else {
        spec * finish::metallic_tint(s.mat.metallic, s.color, n_dot_l) * lc
    };
    (
        (s.mat.kd * finish::falloff(s.mat, n_dot_l)) * s.color * lc,
        specular,
    )
}
