//! Sampling the sky by its brightness (next-event estimation towards the environment): the sky's
//! radiance is tabulated once on a latitude–longitude grid, and directions are drawn from the
//! piecewise-constant density of its luminance (times the cells' solid angle), mixed with a
//! uniform share so that every direction the sky lights has a density however fine its detail.

use std::f64::consts::PI;

use glam::DVec3;

use crate::ir::Color;

/// Grid cells across (longitude) and down (latitude).
const WIDTH: usize = 256;
const HEIGHT: usize = 128;
/// The share of samples drawn uniformly over the sphere.
const UNIFORM: f64 = 0.1;

/// The luminance of a linear RGB colour (Rec. 709).
fn luminance(c: Color) -> f64 {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}

/// The direction of grid coordinates (u, v) in [0, 1]²: v = 0 at +Y, v = 1 at −Y.
fn direction(u: f64, v: f64) -> DVec3 {
    let theta = v * PI;
    let phi = u * 2.0 * PI;
    let s = libm::sin(theta);
    DVec3::new(s * libm::cos(phi), libm::cos(theta), s * libm::sin(phi))
}

/// The grid coordinates of unit direction `d` (the inverse of [`direction`]).
fn coordinates(d: DVec3) -> (f64, f64) {
    let v = libm::acos(d.y.clamp(-1.0, 1.0)) / PI;
    let u = libm::atan2(d.z, d.x).rem_euclid(2.0 * PI) / (2.0 * PI);
    (u, v)
}

/// A tabulated sky to draw directions from.
pub(super) struct Environment {
    /// Cumulative distribution over rows (HEIGHT + 1 entries, from 0 to 1).
    rows: Vec<f64>,
    /// Cumulative distribution within each row (HEIGHT × (WIDTH + 1) entries).
    cells: Vec<f64>,
    /// Each cell's probability (of the tabulated part).
    mass: Vec<f64>,
}

impl Environment {
    /// The sampler for a sky of radiance `radiance(dir)`; `None` when the sky is black.
    pub(super) fn new(radiance: impl Fn(DVec3) -> Color) -> Option<Environment> {
        let mut weight = vec![0.0; WIDTH * HEIGHT];
        for j in 0..HEIGHT {
            let v = (j as f64 + 0.5) / HEIGHT as f64;
            let sin = libm::sin(v * PI);
            for i in 0..WIDTH {
                let u = (i as f64 + 0.5) / WIDTH as f64;
                weight[j * WIDTH + i] = luminance(radiance(direction(u, v))).max(0.0) * sin;
            }
        }
        let total: f64 = weight.iter().sum();
        if !(total > 0.0 && total.is_finite()) {
            return None;
        }
        let mass: Vec<f64> = weight.iter().map(|w| w / total).collect();
        let mut rows = Vec::with_capacity(HEIGHT + 1);
        let mut cells = Vec::with_capacity(HEIGHT * (WIDTH + 1));
        let mut acc = 0.0;
        rows.push(0.0);
        for j in 0..HEIGHT {
            let row = &mass[j * WIDTH..(j + 1) * WIDTH];
            let row_sum: f64 = row.iter().sum();
            let mut within = 0.0;
            cells.push(0.0);
            for m in row {
                within += if row_sum > 0.0 { m / row_sum } else { 0.0 };
                cells.push(within);
            }
            acc += row_sum;
            rows.push(acc);
        }
        Some(Environment { rows, cells, mass })
    }

    /// A direction for the random numbers `pick` (tabulated or uniform) and `(a, b)`, with its
    /// density per unit solid angle.
    pub(super) fn sample(&self, pick: f64, (a, b): (f64, f64)) -> (DVec3, f64) {
        let dir = if pick < UNIFORM {
            let z = 1.0 - 2.0 * a;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let phi = 2.0 * PI * b;
            DVec3::new(r * libm::cos(phi), z, r * libm::sin(phi))
        } else {
            let last = *self.rows.last().unwrap_or(&1.0);
            let j = self
                .rows
                .partition_point(|c| *c <= a * last)
                .clamp(1, HEIGHT)
                - 1;
            let row = &self.cells[j * (WIDTH + 1)..(j + 1) * (WIDTH + 1)];
            let i = row.partition_point(|c| *c <= b).clamp(1, WIDTH) - 1;
            // Uniform within the cell, by the two numbers' remainders in their strata.
            let span_a = (self.rows[j + 1] - self.rows[j]).max(f64::MIN_POSITIVE);
            let fa = ((a * last - self.rows[j]) / span_a).clamp(0.0, 1.0);
            let span_b = (row[i + 1] - row[i]).max(f64::MIN_POSITIVE);
            let fb = ((b - row[i]) / span_b).clamp(0.0, 1.0);
            direction(
                (i as f64 + fb) / WIDTH as f64,
                (j as f64 + fa) / HEIGHT as f64,
            )
        };
        (dir, self.pdf(dir))
    }

    /// The density per unit solid angle with which [`Environment::sample`] draws unit `dir`.
    pub(super) fn pdf(&self, dir: DVec3) -> f64 {
        let (u, v) = coordinates(dir);
        let i = ((u * WIDTH as f64) as usize).min(WIDTH - 1);
        let j = ((v * HEIGHT as f64) as usize).min(HEIGHT - 1);
        let sin = libm::sin(v * PI);
        let cell_area = (2.0 * PI / WIDTH as f64) * (PI / HEIGHT as f64);
        let tabulated = if sin > 0.0 {
            self.mass[j * WIDTH + i] / (cell_area * sin)
        } else {
            0.0
        };
        UNIFORM / (4.0 * PI) + (1.0 - UNIFORM) * tabulated
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Norm;

    fn sky(d: DVec3) -> Color {
        // A bright sun near +X+Y over a dim gradient.
        let sun = DVec3::new(1.0, 1.0, 0.3).unit();
        let glow = if d.dot(sun) > 0.99 { 500.0 } else { 0.0 };
        Color::splat(0.2 + 0.5 * d.y.max(0.0) + glow)
    }

    #[test]
    fn the_density_integrates_to_one_and_matches_the_samples() {
        let env = Environment::new(sky).unwrap();
        // ∫ pdf dω by the midpoint rule on a grid finer than the table.
        let (n, m) = (1024, 512);
        let mut total = 0.0;
        for j in 0..m {
            let v = (j as f64 + 0.5) / m as f64;
            for i in 0..n {
                let u = (i as f64 + 0.5) / n as f64;
                let dw = (2.0 * PI / n as f64) * (PI / m as f64) * libm::sin(v * PI);
                total += env.pdf(direction(u, v)) * dw;
            }
        }
        assert!((total - 1.0).abs() < 1e-3, "{total}");
        // A sample's density is the density of its direction, and the sun draws most samples.
        let mut toward_sun = 0;
        let sun = DVec3::new(1.0, 1.0, 0.3).unit();
        for k in 0..1000 {
            let x = (k as f64 + 0.5) / 1000.0;
            let (d, p) = env.sample(x, (x, (x * 7.31).fract()));
            assert!((d.norm() - 1.0).abs() < 1e-12);
            assert!((p - env.pdf(d)).abs() <= 1e-9 * p, "{p} vs {}", env.pdf(d));
            toward_sun += usize::from(d.dot(sun) > 0.98);
        }
        assert!(toward_sun > 700, "{toward_sun} of 1000 towards the sun");
    }

    #[test]
    fn a_black_sky_has_nothing_to_sample() {
        assert!(Environment::new(|_| Color::ZERO).is_none());
    }

    #[test]
    fn coordinates_invert_directions() {
        for (u, v) in [(0.1, 0.2), (0.7, 0.9), (0.5, 0.5), (0.99, 0.01)] {
            let (u2, v2) = coordinates(direction(u, v));
            assert!((u - u2).abs() < 1e-12 && (v - v2).abs() < 1e-12);
        }
    }
}
