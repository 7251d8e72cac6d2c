//! A Phong material as the path tracer sees it: a radiometric BSDF made of the material's
//! terms (docs/gi.md, "Materials under the path tracer").
//!
//! - diffuse: Lambert, albedo `kd·C` (`f = kd·C/π`);
//! - highlight: the energy-normalised Phong lobe of Lafortune and Willems,
//!   `f = ks·T·(n + 2)/(2π)·cos^n α` (α between `wi` and the mirror direction of `wo`,
//!   `T = (1 − metallic) + metallic·C`), whose albedo at normal incidence is `ks·T`;
//! - `reflect` and `refract`: the scattering layer's mirror and refraction lobes with the
//!   weights Whitted gives them (Fresnel, energy conservation and total internal reflection
//!   included), the refracted light tinted as Whitted tints it; glossy (`gloss > 0`) they have
//!   a density, otherwise they are deltas.
//!
//! One component is drawn with probability proportional to its weight; a direction with a
//! density is then weighed by the whole BSDF's `f·cos / pdf` over all components with a
//! density (one-sample MIS over the components), so light sampling can weigh the same
//! directions by the same `pdf`.

use std::f64::consts::PI;

use glam::DVec3;

use crate::ir::Color;
use crate::render::scatter::Lobe;

/// A scattering component with a density: Lambert or the Phong lobe.
#[derive(Clone, Copy, Debug)]
struct Smooth {
    /// Lambert albedo `kd·C` (per channel).
    diffuse: Color,
    /// The Phong lobe's albedo at normal incidence, `ks·T`.
    glossy: Color,
    /// The Phong exponent.
    exponent: f64,
}

/// A mirror or refraction lobe at this hit, with its ideal direction and the colour its light
/// takes.
#[derive(Clone, Copy, Debug)]
struct Specular {
    lobe: Lobe,
    axis: DVec3,
    tint: Color,
}

/// A direction the BSDF scatters into.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Scattered {
    /// The unit direction to trace.
    pub(crate) wi: DVec3,
    /// `f·cos / pdf` (a delta lobe's weight over its choice probability).
    pub(crate) throughput: Color,
    /// The density over all components with one (0 after a delta lobe).
    pub(crate) pdf: f64,
    /// Whether it went through the surface.
    pub(crate) transmits: bool,
}

/// The BSDF of one hit, for light leaving towards `wo`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Bsdf {
    /// Unit shading normal on `wo`'s side.
    n: DVec3,
    /// Unit geometric normal on `wo`'s side (no light leaks under it).
    facing: DVec3,
    /// Unit direction towards the viewer.
    wo: DVec3,
    /// The mirror direction of `wo` about `n` (the Phong lobe's axis).
    mirror: DVec3,
    smooth: Smooth,
    /// Mirror and refraction lobes (either may be absent).
    specular: [Option<Specular>; 2],
    /// Choice probabilities: diffuse, Phong, then the two specular lobes.
    choice: [f64; 4],
}

impl Bsdf {
    /// The BSDF of a hit with shading normal `n` and geometric normal `facing` (both on the
    /// viewer's side `wo`), colour `color`, Phong terms `kd`, `ks`, `exponent`, `metallic`, and
    /// the mirror and refraction lobes (with the tint of the refracted light).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        n: DVec3,
        facing: DVec3,
        wo: DVec3,
        color: Color,
        (kd, ks, exponent, metallic): (f64, f64, f64, f64),
        mirror: Option<(Lobe, DVec3)>,
        refraction: Option<(Lobe, DVec3, Color)>,
    ) -> Bsdf {
        let tint = (1.0 - metallic) * Color::ONE + metallic * color;
        let smooth = Smooth {
            diffuse: (kd * color).min(Color::ONE),
            glossy: (ks * tint).min(Color::ONE),
            exponent,
        };
        let specular = [
            mirror.map(|(lobe, axis)| Specular {
                lobe,
                axis,
                tint: Color::ONE,
            }),
            refraction.map(|(lobe, axis, tint)| Specular { lobe, axis, tint }),
        ];
        let weight =
            |s: &Option<Specular>| s.map_or(0.0, |s| s.lobe.weight() * s.tint.max_element());
        let mut choice = [
            smooth.diffuse.max_element(),
            smooth.glossy.max_element(),
            weight(&specular[0]),
            weight(&specular[1]),
        ];
        let total: f64 = choice.iter().sum();
        if total > 0.0 {
            choice.iter_mut().for_each(|c| *c /= total);
        }
        Bsdf {
            n,
            facing,
            wo,
            mirror: 2.0 * wo.dot(n) * n - wo,
            smooth,
            specular,
            choice,
        }
    }

    /// Whether it scatters any light at all.
    pub(crate) fn scatters(&self) -> bool {
        self.choice.iter().any(|c| *c > 0.0)
    }

    /// Whether light sampling can reach it (some component with a density).
    pub(crate) fn has_density(&self) -> bool {
        self.choice[0] > 0.0
            || self.choice[1] > 0.0
            || self.specular.iter().flatten().any(|s| !s.lobe.is_delta())
    }

    /// `f(wo, wi)·|cos θi|` summed over the components with a density, for unit `wi`.
    pub(crate) fn f_cos(&self, wi: DVec3) -> Color {
        let mut f = Color::ZERO;
        let cos = wi.dot(self.n);
        if cos > 0.0 && wi.dot(self.facing) > 0.0 {
            f += self.smooth.diffuse * (cos / PI);
            if self.choice[1] > 0.0 {
                let e = self.smooth.exponent;
                f += self.smooth.glossy
                    * ((e + 2.0) / (2.0 * PI) * lobe_cos(self.mirror, wi, e) * cos);
            }
        }
        for s in self.specular.iter().flatten() {
            if !s.lobe.is_delta() {
                f += s.tint * s.lobe.eval(-self.wo, self.facing, wi);
            }
        }
        f
    }

    /// The density over solid angle with which [`Bsdf::sample`] draws unit `wi` (its
    /// components with a density).
    pub(crate) fn pdf(&self, wi: DVec3) -> f64 {
        let mut p = 0.0;
        let cos = wi.dot(self.n);
        if cos > 0.0 && wi.dot(self.facing) > 0.0 {
            p += self.choice[0] * cos / PI;
            if self.choice[1] > 0.0 {
                let e = self.smooth.exponent;
                p += self.choice[1] * (e + 1.0) / (2.0 * PI) * lobe_cos(self.mirror, wi, e);
            }
        }
        for (s, c) in self.specular.iter().zip(&self.choice[2..]) {
            if let Some(s) = s.filter(|s| !s.lobe.is_delta()) {
                p += c * s.lobe.pdf(-self.wo, self.facing, wi);
            }
        }
        p
    }

    /// A scattered direction for the random numbers `pick` (which component) and `u` (where
    /// in it); `None` when the drawn direction carries no light (below the surface).
    pub(crate) fn sample(&self, pick: f64, u: (f64, f64)) -> Option<Scattered> {
        let mut k = 0;
        let mut acc = self.choice[0];
        while k < 3 && pick >= acc {
            k += 1;
            acc += self.choice[k];
        }
        if self.choice[k] <= 0.0 {
            return None;
        }
        let (wi, transmits) = match k {
            0 => (cosine_direction(self.n, u), false),
            1 => (phong_direction(self.mirror, self.smooth.exponent, u), false),
            _ => {
                let s = self.specular[k - 2]?;
                let drawn = s.lobe.sample_about(s.axis, self.facing, u);
                if drawn.delta {
                    let throughput = s.tint * (drawn.weight / self.choice[k]);
                    return Some(Scattered {
                        wi: drawn.dir,
                        throughput,
                        pdf: 0.0,
                        transmits: s.lobe.transmits(),
                    });
                }
                (drawn.dir, s.lobe.transmits())
            }
        };
        let pdf = self.pdf(wi);
        let f = self.f_cos(wi);
        if pdf <= 0.0 || f == Color::ZERO {
            return None;
        }
        Some(Scattered {
            wi,
            throughput: f / pdf,
            pdf,
            transmits,
        })
    }
}

/// `max(0, axis·wi)^e`.
fn lobe_cos(axis: DVec3, wi: DVec3, e: f64) -> f64 {
    let c = axis.dot(wi);
    if c > 0.0 { libm::pow(c, e) } else { 0.0 }
}

/// A cosine-weighted direction about unit `n` for the point `(a, b)` of the unit square.
fn cosine_direction(n: DVec3, (a, b): (f64, f64)) -> DVec3 {
    let r = a.sqrt();
    let phi = 2.0 * PI * b;
    let (t, bt) = n.any_orthonormal_pair();
    let z = (1.0 - a).max(0.0).sqrt();
    r * libm::cos(phi) * t + r * libm::sin(phi) * bt + z * n
}

/// A direction about unit `axis` with density `(e + 1)/(2π)·cos^e α`.
fn phong_direction(axis: DVec3, e: f64, (a, b): (f64, f64)) -> DVec3 {
    let cos = libm::pow(1.0 - a, 1.0 / (e + 1.0));
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    let phi = 2.0 * PI * b;
    let (t, bt) = axis.any_orthonormal_pair();
    sin * libm::cos(phi) * t + sin * libm::sin(phi) * bt + cos * axis
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Norm;
    use crate::render::scatter::Scattering;

    /// A stratified point set over the unit square, n × n.
    fn grid(n: u32) -> impl Iterator<Item = (f64, f64)> {
        (0..n * n).map(move |k| {
            let (i, j) = (k % n, k / n);
            (
                (f64::from(i) + 0.5) / f64::from(n),
                (f64::from(j) + 0.5) / f64::from(n),
            )
        })
    }

    fn phong(kd: f64, ks: f64, e: f64, wo: DVec3) -> Bsdf {
        Bsdf::new(
            DVec3::Z,
            DVec3::Z,
            wo,
            Color::new(0.9, 0.6, 0.3),
            (kd, ks, e, 0.0),
            None,
            None,
        )
    }

    fn glossy_glass(gloss: f64, wo: DVec3) -> Bsdf {
        let mat = crate::ir::Material {
            reflect: 0.2,
            refract: 0.7,
            eta: 1.5,
            gloss,
            ..crate::ir::Material::default()
        };
        let effects = crate::opt::Effects {
            glossy: true,
            ..crate::opt::Effects::default()
        };
        let s = Scattering::of(&mat, &effects);
        let d = -wo;
        let mirror = s.mirror(0.2);
        let refraction = Scattering::of(
            &crate::ir::Material {
                refract: 0.7,
                ..mat
            },
            &crate::opt::Effects {
                refraction: true,
                ..effects
            },
        )
        .refraction(1.0, 1.5);
        Bsdf::new(
            DVec3::Z,
            DVec3::Z,
            wo,
            Color::ONE,
            (0.1, 0.0, 1.0, 0.0),
            Some((mirror, crate::render::scatter::reflect(d, DVec3::Z))),
            refraction
                .axis(d, DVec3::Z)
                .map(|axis| (refraction.with_weight(0.7), axis, Color::ONE)),
        )
    }

    #[test]
    fn a_sample_is_weighed_by_the_whole_bsdf_over_the_whole_density() {
        let wo = DVec3::new(0.4, -0.2, 0.9).unit();
        for b in [phong(0.6, 0.3, 20.0, wo), glossy_glass(0.3, wo)] {
            for (k, u) in grid(16).enumerate() {
                let pick = (k as f64 + 0.5) / 256.0;
                let Some(s) = b.sample(pick, u) else { continue };
                if s.pdf == 0.0 {
                    continue; // a delta lobe
                }
                assert!((s.pdf - b.pdf(s.wi)).abs() <= 1e-12 * s.pdf);
                let want = b.f_cos(s.wi) / s.pdf;
                assert!((s.throughput - want).abs().max_element() < 1e-12);
            }
        }
    }

    /// The directional albedo `∫ f·cos dω` for light leaving towards `wo`, by importance
    /// sampling the BSDF on a fine stratified grid (the mean of `f·cos / pdf`).
    fn albedo(b: &Bsdf) -> Color {
        let n = 256;
        let mut sum = Color::ZERO;
        for (k, u) in grid(n).enumerate() {
            let pick = (k as f64 + 0.5) / f64::from(n * n);
            if let Some(s) = b.sample(pick, u) {
                sum += s.throughput;
            }
        }
        sum / f64::from(n * n)
    }

    #[test]
    fn the_albedo_never_exceeds_one_and_lambert_keeps_kd_c() {
        for cos in [1.0f64, 0.7, 0.3, 0.05] {
            let wo = DVec3::new((1.0 - cos * cos).sqrt(), 0.0, cos);
            // kd + ks = 1 with a white-ish colour: at most 1 in every channel.
            for e in [1.0, 10.0, 200.0] {
                let a = albedo(&phong(0.5, 0.5, e, wo));
                assert!(a.max_element() <= 1.0 + 1e-3, "cos {cos}, n {e}: {a}");
            }
            // Lambert alone: exactly kd·C.
            let a = albedo(&phong(1.0, 0.0, 1.0, wo));
            let want = Color::new(0.9, 0.6, 0.3);
            assert!((a - want).abs().max_element() < 2e-3, "cos {cos}: {a}");
        }
    }

    #[test]
    fn the_phong_lobe_at_normal_incidence_has_albedo_ks_up_to_its_horizon_loss() {
        // Seen head on, a sharp lobe lies wholly above the horizon and returns ks; the
        // normalisation (n + 2)/2π makes ∫ cos^n α · cos θ dω = 2π/(n + 2) exactly there.
        let a = albedo(&phong(0.0, 0.4, 100.0, DVec3::Z));
        assert!((a.x - 0.4).abs() < 2e-3, "{a}");
    }

    #[test]
    fn diffuse_and_phong_are_reciprocal() {
        let b_of = |wo: DVec3| phong(0.5, 0.4, 12.0, wo);
        let dirs = [
            DVec3::new(0.3, 0.1, 0.9).unit(),
            DVec3::new(-0.5, 0.4, 0.5).unit(),
            DVec3::new(0.1, -0.8, 0.3).unit(),
        ];
        for a in dirs {
            for b in dirs {
                // f(a → b) = f(b → a): compare f·cos divided by each side's own cosine.
                let f_ab = b_of(a).f_cos(b) / b.z;
                let f_ba = b_of(b).f_cos(a) / a.z;
                assert!((f_ab - f_ba).abs().max_element() < 1e-12, "{a} {b}");
            }
        }
    }

    #[test]
    fn a_glossy_glass_spends_its_weights_on_its_lobes() {
        // Mirror 0.2 + refraction 0.7 + Lambert 0.1: every sampled direction carries weight,
        // and the albedo is their sum (0.2 + 0.7 + 0.1 = 1) less what the lobes lose below the
        // surface they fold back.
        let wo = DVec3::new(0.2, 0.0, 1.0).unit();
        let a = albedo(&glossy_glass(0.2, wo));
        assert!(
            a.max_element() <= 1.0 + 1e-3 && a.min_element() > 0.9,
            "{a}"
        );
    }

    #[test]
    fn sampled_directions_follow_the_stated_pdf_chi_squared() {
        // pbrt-v4's BSDF test: bin 200,000 sampled directions over (cos θ, φ) and compare
        // with the pdf integrated over each bin; χ² must stay below the 0.1% critical value.
        let wo = DVec3::new(0.5, 0.2, 0.8).unit();
        let b = phong(0.5, 0.5, 8.0, wo);
        let (nz, nphi) = (10usize, 20usize);
        let mut observed = vec![0f64; nz * nphi];
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let samples = 200_000;
        for _ in 0..samples {
            let pick = next();
            let u = (next(), next());
            if let Some(s) = b.sample(pick, u) {
                let phi = s.wi.y.atan2(s.wi.x).rem_euclid(2.0 * PI);
                let iz = ((s.wi.z * nz as f64) as usize).min(nz - 1);
                let ip = ((phi / (2.0 * PI) * nphi as f64) as usize).min(nphi - 1);
                observed[iz * nphi + ip] += 1.0;
            }
        }
        // The pdf over each bin by the midpoint rule on 16 × 16 cells (dω = dz dφ).
        let mut expected = vec![0f64; nz * nphi];
        let fine = 16;
        for (k, e) in expected.iter_mut().enumerate() {
            let (iz, ip) = (k / nphi, k % nphi);
            let (dz, dphi) = (1.0 / nz as f64, 2.0 * PI / nphi as f64);
            for a in 0..fine {
                for c in 0..fine {
                    let z = (iz as f64 + (a as f64 + 0.5) / fine as f64) * dz;
                    let phi = (ip as f64 + (c as f64 + 0.5) / fine as f64) * dphi;
                    let r = (1.0 - z * z).max(0.0).sqrt();
                    let wi = DVec3::new(r * phi.cos(), r * phi.sin(), z);
                    *e += b.pdf(wi) * dz * dphi / (fine * fine) as f64;
                }
            }
            *e *= f64::from(samples);
        }
        // Pool the bins expected to hold fewer than 5 samples, as the test requires.
        let (mut chi2, mut dof, mut pool_o, mut pool_e) = (0.0, 0usize, 0.0, 0.0);
        for (o, e) in observed.iter().zip(&expected) {
            if *e < 5.0 {
                pool_o += o;
                pool_e += e;
            } else {
                chi2 += (o - e).powi(2) / e;
                dof += 1;
            }
        }
        if pool_e > 0.0 {
            chi2 += (pool_o - pool_e).powi(2) / pool_e;
            dof += 1;
        }
        // Wilson–Hilferty: the χ² critical value at p = 0.001 for `dof − 1` degrees of freedom.
        let k = (dof - 1) as f64;
        let critical = k * (1.0 - 2.0 / (9.0 * k) + 3.09 * (2.0 / (9.0 * k)).sqrt()).powi(3);
        assert!(
            chi2 < critical,
            "χ² {chi2} over {dof} bins, critical {critical}"
        );
    }
}
