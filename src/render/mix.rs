//! Mixed materials resolved at a hit: a material map's pattern picks or blends its stops'
//! materials, layers lie over one another through their colour maps' filter and transmit. The
//! result is one plain material (its colour read from the parts' textures at the hit, so it has
//! no texture of its own) that the shading code takes like any other.

use crate::geometry::{MappingFrame, SurfaceHit};
use crate::ir::{Material, Mix};
use crate::opt::{Prepared, TextureMap};
use crate::pattern::Rgbft;

use super::texture;

/// How deep mixes of mixes are resolved; a deeper part counts as its stored fields. Values are
/// immutable, so a mix cannot contain itself; the bound keeps a long chain from costing more
/// than a few resolutions per hit.
const MAX_DEPTH: u32 = 8;

/// The plain material that `mat` (which has a mix) is at `hit`, in mapping `frame`.
pub(crate) fn resolve(
    scene: &Prepared,
    hit: &SurfaceHit,
    frame: MappingFrame,
    mat: &Material,
) -> Material {
    resolve_at(scene, hit, frame, mat, 0).0
}

/// `mat` at `hit` as a plain material, with its colour's filter and transmit (what a layer
/// above lets through to it).
fn resolve_at(
    scene: &Prepared,
    hit: &SurfaceHit,
    frame: MappingFrame,
    mat: &Material,
    depth: u32,
) -> (Material, Rgbft) {
    let textures = scene.textures();
    let Some(mix) = mat.mix.as_deref().filter(|_| depth < MAX_DEPTH) else {
        let color = match mat.texture {
            Some(t) => texture::rgbft(&textures[t.0 as usize], hit, frame),
            None => Rgbft::opaque(mat.color),
        };
        let plain = Material {
            color: color.rgb,
            texture: None,
            mix: None,
            ..mat.clone()
        };
        return (plain, color);
    };
    let part =
        |id: crate::ir::MaterialId| resolve_at(scene, hit, frame, scene.material(id), depth + 1);
    match mix {
        Mix::Map {
            texture: t,
            stops,
            blend,
        } => {
            let TextureMap::Pattern(pt) = &textures[t.0 as usize] else {
                return part(stops[0].1);
            };
            let v = texture::pattern_value(pt, hit, hit.local_point);
            let upper = stops.partition_point(|(at, _)| *at <= v);
            if upper == 0 {
                return part(stops[0].1);
            }
            let (lo_at, lo) = stops[upper - 1];
            let Some(&(hi_at, hi)) = stops.get(upper).filter(|_| *blend) else {
                return part(lo);
            };
            let w = (v - lo_at) / (hi_at - lo_at);
            let (a, ca) = part(lo);
            let (b, cb) = part(hi);
            (blended(&a, &b, w), ca.lerp(cb, w))
        }
        Mix::Layers(layers) => {
            let parts: Vec<(Material, Rgbft)> = layers.iter().map(|id| part(*id)).collect();
            // The colour: from the bottom layer up, each over what lies below.
            let color = parts
                .iter()
                .rev()
                .map(|(_, c)| *c)
                .reduce(|below, above| above.over(below))
                .unwrap_or(Rgbft::opaque(mat.color));
            // The finish: each layer weighted by how much of it shows, the rest to the bottom.
            let mut reach = 1.0;
            let mut acc: Option<Material> = None;
            let mut shown = 0.0;
            let last = parts.len() - 1;
            for (i, (m, c)) in parts.iter().enumerate() {
                let share = if i == last {
                    reach
                } else {
                    reach * c.coverage()
                };
                reach -= share;
                if share > 0.0 {
                    let total = shown + share;
                    acc = Some(match acc {
                        None => m.clone(),
                        Some(a) => blended(&a, m, share / total),
                    });
                    shown = total;
                }
            }
            let mut m = acc.unwrap_or_else(|| parts[0].0.clone());
            m.color = color.rgb;
            (m, color)
        }
    }
}

/// `a` and `b` mixed: `b`'s share `w` of every number, the larger share's model and bump.
fn blended(a: &Material, b: &Material, w: f64) -> Material {
    let lerp = |x: f64, y: f64| x + (y - x) * w;
    let major = if w < 0.5 { a } else { b };
    Material {
        color: a.color + (b.color - a.color) * w,
        ka: lerp(a.ka, b.ka),
        kd: lerp(a.kd, b.kd),
        ks: lerp(a.ks, b.ks),
        n: lerp(a.n, b.n),
        reflect: lerp(a.reflect, b.reflect),
        refract: lerp(a.refract, b.refract),
        eta: lerp(a.eta, b.eta),
        gloss: lerp(a.gloss, b.gloss),
        gloss_samples: a.gloss_samples.max(b.gloss_samples),
        filter: lerp(a.filter, b.filter),
        absorption: a.absorption + (b.absorption - a.absorption) * w,
        metallic: lerp(a.metallic, b.metallic),
        brilliance: lerp(a.brilliance, b.brilliance),
        emission: a.emission + (b.emission - a.emission) * w,
        // `fresnel` and `conserve_energy` are the larger share's, like the shading model.
        ..major.clone()
    }
}
