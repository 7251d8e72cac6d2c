//! Pen-and-ink hatching after Leister's computer-generated copper plates: strokes follow the
//! surface's coordinate lines, keep a steady spacing on screen, grow wider with the tone and
//! cross in the darks, and are anti-aliased.
//!
//! - Tone: the Phong tone (ambient + diffuse, white material) gives a darkness `d` ∈ [0, 1].
//! - Layers: the first family of strokes runs along u (level lines of v), the second along v
//!   (level lines of u), the third diagonally (level lines of u + v). The first alone covers up
//!   to [`FIRST_LAYER`] of the paper; the second then joins and the third past [`SECOND_LAYER`],
//!   each covering what keeps the combined coverage `1 − Π(1 − cᵢ)` equal to `d`, so the tone
//!   is continuous and the crossings only appear in the darks.
//! - Spacing: a family's lines are the integers of `φ = 2^k·F·(its coordinate)`; the level `k`
//!   is chosen per point from the coordinate's screen gradient (measured with two footprint
//!   rays one pixel apart) so that lines are [`SPACING_PX`] apart on screen. Between two levels
//!   (fraction `t` ∈ [0, 1) of the way) a share `2^t − 1` of the next level's in-between lines
//!   is drawn (spread evenly by a golden-ratio sequence), so the density is one line per
//!   `SPACING_PX` at every `t`, and at `t → 1` all are present: the levels join without a jump.
//! - Width: a stroke of a layer covering `c` is `c·SPACING_PX` pixels wide, and each pixel
//!   takes the exact box-filtered coverage of the strokes across its footprint.
//!
//! Paper shows the material colour, ink is black. The two footprint rays per shaded point are
//! counted as secondary rays.

use crate::num::Norm;
use glam::{DVec2, DVec3};

use super::{Surface, light_sample, occluder, transmission};
use crate::geometry::Ray;
use crate::ir::{Color, Visibility};
use crate::opt::Prepared;
use crate::render::context::Ctx;
use crate::render::footprint;
use crate::render::record::{LightTerm, Recorder};

/// Distance between neighbouring strokes of one family on screen, in pixels.
const SPACING_PX: f64 = 6.0;
/// Darkness the first layer covers alone.
const FIRST_LAYER: f64 = 0.4;
/// Darkness the first two layers cover before the third joins.
const SECOND_LAYER: f64 = 0.7;
/// Lines per unit of surface coordinate at level 0 (a power of two, so that the levels down
/// to −log2(F) keep whole lines per unit and u's seam on closed surfaces stays seamless).
const BASE_FREQUENCY: f64 = 64.0;
/// The coarsest and finest levels.
const LEVELS: (f64, f64) = (-6.0, 30.0);

/// The hatched colour of a surface point; `rec` hears each light's tone inputs (grey).
pub(crate) fn shade<R: Recorder>(
    scene: &Prepared,
    s: &Surface<'_>,
    ctx: &mut Ctx,
    rec: &mut R,
) -> Color {
    let mut tone = 0.0;
    for (i, light) in scene.lights().iter().enumerate() {
        let mut term = LightTerm::new(i);
        let lum = (light.color.x + light.color.y + light.color.z) / 3.0;
        tone += s.mat.ka * lum;
        if R::ON {
            term.ambient = Color::splat(s.mat.ka * lum);
        }
        let (first, count) = ctx.lights.cells(light.samples);
        for j in 0..count {
            let k = (first + j) % light.samples;
            let w = ctx.lights.weight(light.samples, k);
            let ls = light_sample(light, i, k, w, s, &ctx.rng);
            let n_dot_l = s.n.dot(ls.l);
            if R::ON {
                term.samples += 1;
                term.behind += u32::from(n_dot_l <= 0.0);
            }
            if n_dot_l > 0.0 {
                match transmission(scene, s, &ls, &mut ctx.stats) {
                    Some(pass) => {
                        let through = pass.element_sum() / 3.0;
                        tone += w.of(s.mat.kd * n_dot_l * lum) * through;
                        if R::ON {
                            term.tinted += u32::from(pass != Color::ONE);
                            term.diffuse += Color::splat(w.of(s.mat.kd * n_dot_l * lum) * through);
                        }
                    }
                    None if R::ON => {
                        term.blocked += 1;
                        term.occluder = term.occluder.or_else(|| occluder(scene, s, &ls));
                    }
                    None => {}
                }
            }
        }
        if R::ON {
            rec.light(term);
        }
    }
    let dark = 1.0 - tone.clamp(0.0, 1.0);
    let layers = layer_coverages(dark);
    if layers[0] <= 0.0 {
        return s.color;
    }
    ctx.stats.secondary_rays += 2;
    let paper = match screen_gradient(scene, s) {
        Some(g) => {
            let families = [g.col(1), g.col(0), g.col(0) + g.col(1)];
            let coords = [s.uv.y, s.uv.x, s.uv.x + s.uv.y];
            layers
                .iter()
                .zip(families.iter().zip(coords))
                .enumerate()
                .map(|(i, (&c, (&grad, x)))| 1.0 - stroke_coverage(i as u64, x, grad.norm(), c))
                .product::<f64>()
        }
        // No footprint (a silhouette pixel): the flat tone.
        None => 1.0 - dark,
    };
    s.color * paper
}

/// Each layer's coverage for darkness `dark`, so that `1 − Π(1 − cᵢ) = dark` (up to 0.99).
fn layer_coverages(dark: f64) -> [f64; 3] {
    let d = dark.clamp(0.0, 0.99);
    let first = d.min(FIRST_LAYER);
    let second = if d > FIRST_LAYER {
        1.0 - (1.0 - d.min(SECOND_LAYER)) / (1.0 - FIRST_LAYER)
    } else {
        0.0
    };
    let third = if d > SECOND_LAYER {
        1.0 - (1.0 - d) / (1.0 - SECOND_LAYER)
    } else {
        0.0
    };
    [first, second, third]
}

/// The share of a pixel that strokes of family `family` cover, where its coordinate is `x`,
/// changing by `per_px` per pixel on screen, for a layer covering `c` of the paper.
fn stroke_coverage(family: u64, x: f64, per_px: f64, c: f64) -> f64 {
    if c <= 0.0 || !per_px.is_finite() || per_px <= 0.0 || !x.is_finite() {
        return c.max(0.0);
    }
    let per_px = per_px * BASE_FREQUENCY;
    // The level whose lines are SPACING_PX apart: 2^k·per_px = 1/SPACING_PX.
    let k = libm::log2(1.0 / (SPACING_PX * per_px));
    // Past the coarsest level the lines are closer than SPACING_PX: each covers `c` of its
    // period, with no in-between lines.
    let (level, t) = if k < LEVELS.0 {
        (LEVELS.0, 0.0)
    } else {
        let k = k.min(LEVELS.1);
        (k.floor(), k - k.floor())
    };
    let scale = libm::exp2(level);
    let phi = x * BASE_FREQUENCY * scale;
    // The pixel's footprint and a stroke's half-width, in units of φ.
    let footprint = per_px * scale;
    if footprint >= 0.5 {
        // Two or more lines per pixel: the box filter's average is the layer's share.
        return c.min(1.0);
    }
    let half = 0.5 * c * (SPACING_PX * footprint).min(1.0);
    let midline_density = libm::exp2(t) - 1.0;
    let mut covered = 0.0;
    let nearest = phi.round();
    for j in [nearest - 1.0, nearest, nearest + 1.0] {
        covered += box_overlap(phi - j, footprint, half);
        // The in-between line j + ½, present on its share of the lines.
        if midline_present(family, j, midline_density) {
            covered += box_overlap(phi - (j + 0.5), footprint, half);
        }
    }
    covered.min(1.0)
}

/// The share of a box of width `w` centred at `a` that the interval [−h, h] covers.
fn box_overlap(a: f64, w: f64, h: f64) -> f64 {
    let lo = (a - 0.5 * w).max(-h);
    let hi = (a + 0.5 * w).min(h);
    ((hi - lo) / w).max(0.0)
}

/// Whether the in-between line after line `j` of `family` is drawn where a share `density` of
/// them is: a golden-ratio (Weyl) sequence over the line index, so any run of n neighbouring
/// lines holds n·density ± 1 of them (a hash would clump them), shifted per family.
fn midline_present(family: u64, j: f64, density: f64) -> bool {
    const GOLDEN: f64 = 0.618_033_988_749_894_9;
    let x = (j * GOLDEN + 0.3 * family as f64).rem_euclid(1.0);
    x < density
}

/// The surface coordinates' change per pixel on screen at `s` (columns: d(u,v)/dx, d(u,v)/dy),
/// from two rays from the eye through the points one pixel to the side and one up, which must
/// land on the same surface; `None` when neither side of either does (a silhouette).
fn screen_gradient(scene: &Prepared, s: &Surface<'_>) -> Option<glam::DMat2> {
    let cam = scene.camera();
    let forward = (cam.center - cam.eye).unit();
    let (right, up) = footprint::screen_axes(cam);
    let pixel_angle = footprint::pixel_angle(cam);
    // A sixteenth of a pixel: close enough that periodic coordinates (a plane's repeat every
    // unit, a sphere's seam) wrap only where a pixel spans 8 periods, where the strokes are
    // far finer than a pixel and their box filter gives the flat tone anyway.
    const FRACTION: f64 = 1.0 / 16.0;
    let step = FRACTION * pixel_angle * (s.p - cam.eye).dot(forward).abs();
    let along = |axis: DVec3| -> Option<DVec2> {
        [1.0, -1.0].into_iter().find_map(|sign| {
            let target = s.p + sign * step * axis;
            let uv = uv_at(scene, s, cam.eye, target)?;
            let d = uv - s.uv;
            Some(sign * (d - d.round()) / FRACTION)
        })
    };
    // Screen y grows downwards, world `up` upwards.
    Some(glam::DMat2::from_cols(along(right)?, -along(up)?).transpose())
}

/// The surface coordinates where the ray from `eye` towards `target` meets the surface of `s`
/// (the same material, facing the same way, near its tangent plane).
fn uv_at(scene: &Prepared, s: &Surface<'_>, eye: DVec3, target: DVec3) -> Option<DVec2> {
    let d = target - eye;
    let ray = Ray::new(eye, d.unit());
    let hit = scene.seen_hit(&ray, 0.0, f64::INFINITY, Visibility::NO_IMAGE)?;
    let same = std::ptr::eq(scene.material(hit.material), s.mat)
        && hit.normal.dot(s.n).abs() > 0.5
        && (hit.point - s.p).dot(s.n).abs() < 4.0 * (target - s.p).norm() + s.spawn.error.norm();
    same.then_some(hit.uv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layers_add_up_to_the_darkness_and_cross_only_in_the_darks() {
        for i in 0..=100 {
            let d = f64::from(i) / 100.0;
            let c = layer_coverages(d);
            let total = 1.0 - c.iter().map(|x| 1.0 - x).product::<f64>();
            assert!((total - d.min(0.99)).abs() < 1e-12, "{d}: {c:?}");
            assert_eq!(c[1] > 0.0, d > FIRST_LAYER);
            assert_eq!(c[2] > 0.0, d > SECOND_LAYER);
        }
    }

    #[test]
    fn mean_coverage_is_the_layer_share_at_every_scale() {
        // Across many pixels the strokes cover `c` of the paper whatever the coordinate's rate.
        for per_px in [0.0004, 0.001, 0.0017, 0.003, 0.011] {
            for c in [0.1, 0.3] {
                let n = 20_000;
                let mean = (0..n)
                    .map(|i| stroke_coverage(0, f64::from(i) * per_px, per_px, c))
                    .sum::<f64>()
                    / f64::from(n);
                assert!((mean - c).abs() < 0.03, "{per_px} {c}: {mean}");
            }
        }
    }

    #[test]
    fn coverage_is_anti_aliased() {
        // Some pixels are partly covered, none more than fully.
        let per_px = 0.0013;
        let values: Vec<f64> = (0..600)
            .map(|i| stroke_coverage(1, 0.37 + f64::from(i) * per_px, per_px, 0.25))
            .collect();
        assert!(values.iter().any(|&v| v > 0.05 && v < 0.95));
        assert!(values.iter().all(|&v| (0.0..=1.0).contains(&v)));
    }
}
