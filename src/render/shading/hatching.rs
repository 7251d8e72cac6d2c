//! Pen-and-ink hatching: the Phong tone (ambient + diffuse, white material) picks how many layers
//! of ink lines cover the paper. Lines run along the surface coordinates, so they follow the
//! shape: one layer above 25 % darkness, cross-hatching above 50 %, a diagonal third layer above
//! 75 %. Paper shows the material colour, ink is black.

use glam::DVec2;

use super::{Ctx, Surface, light_sample, visible};
use crate::ir::Color;
use crate::opt::Prepared;

/// Lines per unit of surface coordinate.
const FREQUENCY: f64 = 80.0;
/// Share of each period covered by a line.
const WIDTH: f64 = 0.35;

/// The hatched colour of a surface point.
pub fn shade(scene: &Prepared, s: &Surface<'_>, ctx: &mut Ctx) -> Color {
    let mut tone = 0.0;
    for (i, light) in scene.lights().iter().enumerate() {
        let lum = (light.color.x + light.color.y + light.color.z) / 3.0;
        tone += s.mat.ka * lum;
        let (first, count) = ctx.lights.cells(light.samples);
        for j in 0..count {
            let k = (first + j) % light.samples;
            let ls = light_sample(light, i, k, count, s, &ctx.rng);
            let n_dot_l = s.n.dot(ls.l);
            if n_dot_l > 0.0 && visible(scene, s, &ls, &mut ctx.stats) {
                tone += s.mat.kd * n_dot_l * lum / f64::from(count);
            }
        }
    }
    if ink(s.uv, 1.0 - tone.clamp(0.0, 1.0)) {
        Color::ZERO
    } else {
        s.color
    }
}

/// True when a point with coordinates `uv` and darkness `dark` ∈ [0, 1] lies on an ink line.
fn ink(uv: DVec2, dark: f64) -> bool {
    let line = |x: f64| (x * FREQUENCY).rem_euclid(1.0) < WIDTH;
    (dark > 0.25 && line(uv.x)) || (dark > 0.5 && line(uv.y)) || (dark > 0.75 && line(uv.x + uv.y))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn darker_tones_cover_more_paper() {
        let count = |dark: f64| {
            (0..200)
                .flat_map(|i| (0..200).map(move |j| DVec2::new(f64::from(i), f64::from(j)) / 400.0))
                .filter(|uv| ink(*uv, dark))
                .count()
        };
        let (a, b, c, d) = (count(0.1), count(0.3), count(0.6), count(0.9));
        assert_eq!(a, 0);
        assert!(a < b && b < c && c < d, "{a} {b} {c} {d}");
    }
}
