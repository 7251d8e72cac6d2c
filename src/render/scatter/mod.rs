//! The scattering layer: what a surface does with the light that its local shading does not
//! account for — mirror reflection, refraction and their glossy lobes — behind one interface
//! the integrators call (pbrt-v4's BSDF boundary, in rtc's terms). A new surface effect is a
//! variant of [`Lobe`] (or of [`Ideal`]) and its tests here, not an edit of the integrators.
//!
//! rtc's Whitted lobes carry *weights*, not radiometric BSDFs: a lobe of weight `k` passes `k`
//! of the light arriving along its rays (the material's `reflect` or `refract`). For a lobe
//! with a density, `eval(wi) / pdf(wi) == k` wherever `pdf(wi) > 0`, so an integrator may
//! factor the constant weight out of the mean of its samples, as Whitted does. A delta lobe
//! (a perfect mirror or refraction) has no density: `sample` returns its one direction with
//! `pdf` 1 and `delta` set, and `eval` and `pdf` are 0 for any pair of directions.

mod fresnel;
mod glossy;
mod specular;

use glam::DVec3;

use crate::ir::{Color, Material};
use crate::opt::Effects;
pub(crate) use fresnel::beer_lambert;
pub use specular::refract;
pub(crate) use specular::{reflect, reflect_lanes};

/// The ideal direction a lobe scatters about.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Ideal {
    /// The mirror direction.
    Mirror,
    /// Snell's refraction from index `n1` (the near side) into `n2`.
    Refraction {
        /// Index of refraction on the side the light arrives from.
        n1: f64,
        /// Index of refraction on the far side.
        n2: f64,
    },
}

/// How a lobe's directions spread about its ideal direction.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Spread {
    /// Exactly the ideal direction (a delta lobe).
    Delta,
    /// Uniform over the cone of half-angle `gloss·90°`, folded back above the surface
    /// (Cook's glossy reflection and translucency).
    Cone {
        /// The material's `gloss`, in (0, 1].
        gloss: f64,
    },
}

/// One lobe of a surface's scattering: an ideal direction, a spread and a weight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Lobe {
    /// The direction it scatters about.
    ideal: Ideal,
    /// How its rays spread.
    spread: Spread,
    /// The share of the light arriving along its rays it passes on.
    weight: f64,
}

/// A direction drawn from a lobe (the path tracer weighs it by its density; Whitted's constant
/// weights need only [`Lobe::direction_about`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Sample {
    /// The unit direction the light arrives from (the ray to trace).
    pub(crate) dir: DVec3,
    /// `eval / pdf` for a lobe with a density; the lobe's weight for a delta.
    pub(crate) weight: f64,
    /// The density of `dir` per unit solid angle (1 for a delta).
    pub(crate) pdf: f64,
    /// Whether the lobe is a delta (its one direction has no density).
    pub(crate) delta: bool,
}

impl Lobe {
    /// The share of the light arriving along its rays it passes on.
    pub(crate) fn weight(&self) -> f64 {
        self.weight
    }

    /// The same lobe passing `weight` of its light.
    pub(crate) fn with_weight(self, weight: f64) -> Lobe {
        Lobe { weight, ..self }
    }

    /// Whether the lobe is a delta (one direction, no density).
    pub(crate) fn is_delta(&self) -> bool {
        self.spread == Spread::Delta
    }

    /// Whether its rays pass through the surface.
    pub(crate) fn transmits(&self) -> bool {
        matches!(self.ideal, Ideal::Refraction { .. })
    }

    /// The unit normal of the side the lobe's rays leave through, for the unit normal `n`
    /// facing the incoming ray.
    fn side(&self, n: DVec3) -> DVec3 {
        if self.transmits() { -n } else { n }
    }

    /// The ideal direction for unit incoming direction `d` at a surface whose unit normal `n`
    /// faces it; `None` under total internal reflection.
    #[inline(always)]
    pub(crate) fn axis(&self, d: DVec3, n: DVec3) -> Option<DVec3> {
        match self.ideal {
            Ideal::Mirror => Some(reflect(d, n)),
            Ideal::Refraction { n1, n2 } => refract(d, n, n1, n2),
        }
    }

    /// A direction of the lobe for the point `u` of the unit square (ignored by a delta);
    /// `None` under total internal reflection.
    #[cfg(test)]
    fn sample(&self, d: DVec3, n: DVec3, u: (f64, f64)) -> Option<Sample> {
        Some(self.sample_about(self.axis(d, n)?, n, u))
    }

    /// [`Lobe::sample`] for an integrator that already has the lobe's [`Lobe::axis`].
    pub(crate) fn sample_about(&self, axis: DVec3, n: DVec3, u: (f64, f64)) -> Sample {
        let dir = self.direction_about(axis, n, u);
        match self.spread {
            Spread::Delta => Sample {
                dir,
                weight: self.weight,
                pdf: 1.0,
                delta: true,
            },
            Spread::Cone { gloss } => Sample {
                dir,
                weight: self.weight,
                pdf: glossy::pdf(axis, self.side(n), gloss, dir),
                delta: false,
            },
        }
    }

    /// The direction of [`Lobe::sample_about`] alone, for an integrator that weighs every
    /// direction of the lobe alike (Whitted's constant weights need no density).
    #[inline(always)]
    pub(crate) fn direction_about(&self, axis: DVec3, n: DVec3, u: (f64, f64)) -> DVec3 {
        match self.spread {
            Spread::Delta => axis,
            Spread::Cone { gloss } => glossy::direction(axis, self.side(n), gloss, u),
        }
    }

    /// The density of the lobe's rays at unit `wi`, for incoming `d` at facing normal `n`
    /// (0 for a delta, and under total internal reflection).
    pub(crate) fn pdf(&self, d: DVec3, n: DVec3, wi: DVec3) -> f64 {
        match (self.spread, self.axis(d, n)) {
            (Spread::Cone { gloss }, Some(axis)) => glossy::pdf(axis, self.side(n), gloss, wi),
            _ => 0.0,
        }
    }

    /// The lobe's scattering density (weight per unit solid angle) for the pair (`d`, `wi`):
    /// `weight · pdf` (0 for a delta).
    pub(crate) fn eval(&self, d: DVec3, n: DVec3, wi: DVec3) -> f64 {
        self.weight * self.pdf(d, n, wi)
    }
}

/// A material's scattering as the scene's effects allow it: the weights of its mirror and
/// refraction lobes and how glossy they are. Built per hit; the lobes follow once the media on
/// both sides are known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Scattering {
    /// The mirror lobe's weight (0 without reflection).
    pub(crate) reflect: f64,
    /// The refraction lobe's weight (0 without refraction).
    pub(crate) refract: f64,
    /// The material's index of refraction.
    pub(crate) eta: f64,
    /// How the lobes spread.
    spread: Spread,
    /// The mirror weight follows the Fresnel reflectance (`fresnel`).
    fresnel: bool,
    /// The reflected share is taken from the refracted one (`conserve_energy`).
    conserve: bool,
}

impl Scattering {
    /// The scattering of `mat` in a scene with `effects`.
    #[inline(always)]
    pub(crate) fn of(mat: &Material, effects: &Effects) -> Scattering {
        Scattering {
            reflect: if effects.reflection { mat.reflect } else { 0.0 },
            refract: if effects.refraction { mat.refract } else { 0.0 },
            eta: mat.eta,
            spread: if effects.glossy && mat.gloss > 0.0 {
                Spread::Cone { gloss: mat.gloss }
            } else {
                Spread::Delta
            },
            fresnel: effects.fresnel && mat.fresnel,
            conserve: effects.conserve_energy && mat.conserve_energy,
        }
    }

    /// Whether the lobes' weights depend on the hit (Fresnel or energy conservation); when
    /// not, [`Scattering::shares`] is `(reflect, refract)` everywhere.
    #[inline(always)]
    pub(crate) fn varies(&self) -> bool {
        self.fresnel || self.conserve
    }

    /// The weights of the mirror and refraction lobes for light arriving at cosine `cos_i`
    /// to the normal, from index `n1` into `n2`. With `fresnel` the mirror weighs
    /// `reflect · F(cos_i, n2/n1)` (the exact dielectric reflectance); with `fresnel` or
    /// `conserve_energy` the refraction lobe loses what the mirror takes, `refract · (1 − kr)`
    /// (POV-Ray's `conserve_energy`). Otherwise `(reflect, refract)`.
    pub(crate) fn shares(&self, cos_i: f64, n1: f64, n2: f64) -> (f64, f64) {
        if !self.varies() {
            return (self.reflect, self.refract);
        }
        let kr = if self.fresnel {
            self.reflect * fresnel::reflectance(cos_i, n2 / n1)
        } else {
            self.reflect
        };
        (kr, self.refract * (1.0 - kr).max(0.0))
    }

    /// Whether light passes through the surface (a refraction lobe of positive weight).
    pub(crate) fn transmits(&self) -> bool {
        self.refract > 0.0
    }

    /// The mirror lobe, weighing `weight` (the reflectance, plus the refracted share under
    /// total internal reflection).
    pub(crate) fn mirror(&self, weight: f64) -> Lobe {
        Lobe {
            ideal: Ideal::Mirror,
            spread: self.spread,
            weight,
        }
    }

    /// The refraction lobe from index `n1` into `n2`.
    pub(crate) fn refraction(&self, n1: f64, n2: f64) -> Lobe {
        Lobe {
            ideal: Ideal::Refraction { n1, n2 },
            spread: self.spread,
            weight: self.refract,
        }
    }
}

/// The tint of the light a surface of colour `color` transmits, per channel: the `filter`
/// share of it passes through the colour, the rest untinted, `filter·C + (1 − filter)`
/// (POV-Ray's `filter·C + transmit` over `filter + transmit`). `None` for `filter: 0`, which
/// passes light untinted (the course rule). The one rule for what is seen through glass and
/// for its shadow.
#[inline(always)]
pub(crate) fn tint(mat: &Material, color: Color) -> Option<Color> {
    (mat.filter > 0.0).then(|| mat.filter * color + (1.0 - mat.filter))
}

/// What a surface of `mat` lets through along a straight line, per channel (glass shadows):
/// `refract` times its [`tint`], or `None` for an opaque surface.
#[inline(always)]
pub(crate) fn straight_through(mat: &Material) -> Option<Color> {
    (mat.refract > 0.0).then(|| match tint(mat, mat.color) {
        Some(t) => mat.refract * t,
        None => Color::splat(mat.refract),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Norm;

    fn glossy_mirror(gloss: f64) -> Lobe {
        Lobe {
            ideal: Ideal::Mirror,
            spread: Spread::Cone { gloss },
            weight: 0.7,
        }
    }

    #[test]
    fn a_delta_lobe_has_one_direction_and_no_density() {
        let lobe = Lobe {
            ideal: Ideal::Refraction { n1: 1.0, n2: 1.5 },
            spread: Spread::Delta,
            weight: 0.9,
        };
        let d = DVec3::new(0.3, -1.0, 0.0).unit();
        let s = lobe.sample(d, DVec3::Y, (0.2, 0.8)).unwrap();
        assert!(s.delta && s.pdf == 1.0 && s.weight == 0.9);
        assert_eq!(Some(s.dir), refract(d, DVec3::Y, 1.0, 1.5));
        assert_eq!(lobe.pdf(d, DVec3::Y, s.dir), 0.0);
        assert_eq!(lobe.eval(d, DVec3::Y, s.dir), 0.0);
    }

    #[test]
    fn eval_over_pdf_is_the_weight_wherever_a_glossy_lobe_has_density() {
        let lobe = glossy_mirror(0.4);
        let d = DVec3::new(0.5, -1.0, 0.2).unit();
        for i in 0..8 {
            for j in 0..8 {
                let u = ((f64::from(i) + 0.5) / 8.0, (f64::from(j) + 0.5) / 8.0);
                let s = lobe.sample(d, DVec3::Y, u).unwrap();
                assert!(!s.delta && s.pdf > 0.0);
                assert_eq!(s.pdf, lobe.pdf(d, DVec3::Y, s.dir));
                let ratio = lobe.eval(d, DVec3::Y, s.dir) / s.pdf;
                assert!((ratio - s.weight).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn total_internal_reflection_has_no_refracted_sample() {
        let lobe = Scattering {
            reflect: 0.0,
            refract: 1.0,
            eta: 1.5,
            spread: Spread::Delta,
            fresnel: false,
            conserve: false,
        }
        .refraction(1.5, 1.0);
        let grazing = DVec3::new(1.0, -0.2, 0.0).unit();
        assert!(lobe.sample(grazing, DVec3::Y, (0.5, 0.5)).is_none());
        assert_eq!(lobe.pdf(grazing, DVec3::Y, DVec3::Y), 0.0);
    }

    #[test]
    fn the_scene_effects_switch_lobes_off() {
        let mat = Material {
            reflect: 0.5,
            refract: 0.4,
            gloss: 0.3,
            ..Material::default()
        };
        let all = Effects {
            reflection: true,
            refraction: true,
            glossy: true,
            ..Effects::default()
        };
        let s = Scattering::of(&mat, &all);
        assert_eq!((s.reflect, s.refract), (0.5, 0.4));
        assert_eq!(s.spread, Spread::Cone { gloss: 0.3 });
        let none = Scattering::of(&mat, &Effects::default());
        assert_eq!((none.reflect, none.refract), (0.0, 0.0));
        assert_eq!(none.spread, Spread::Delta);
        // The IR's default filter (the course rule) passes light untinted; the language's
        // (filter 1) through the colour.
        assert_eq!(straight_through(&mat), Some(Color::splat(0.4)));
        let tinted = Material {
            filter: crate::ir::LANGUAGE_FILTER,
            ..mat.clone()
        };
        assert_eq!(straight_through(&tinted), Some(0.4 * mat.color));
        assert_eq!(straight_through(&Material::default()), None);
    }

    #[test]
    fn filter_mixes_the_tinted_and_untinted_shares() {
        let red = Color::new(1.0, 0.2, 0.1);
        let half = Material {
            filter: 0.25,
            refract: 0.8,
            color: red,
            ..Material::default()
        };
        // POV-Ray's rgbft <1, 0.2, 0.1, 0.2, 0.6>: filter·C + transmit = <0.8, 0.64, 0.62>.
        let t = straight_through(&half).unwrap();
        let pov = 0.2 * red + Color::splat(0.6);
        assert!((t - pov).abs().max_element() < 1e-15, "{t} vs {pov}");
        assert_eq!(tint(&Material::default(), red), None);
    }

    #[test]
    fn fresnel_shares_reflect_f_and_refract_the_rest() {
        let glass = Material {
            reflect: 1.0,
            refract: 1.0,
            eta: 1.5,
            fresnel: true,
            ..Material::default()
        };
        let all = Effects {
            reflection: true,
            refraction: true,
            fresnel: true,
            conserve_energy: true,
            ..Effects::default()
        };
        let s = Scattering::of(&glass, &all);
        let (kr, kt) = s.shares(1.0, 1.0, 1.5);
        assert!((kr - 0.04).abs() < 1e-15 && (kt - 0.96).abs() < 1e-15);
        let (kr, kt) = s.shares(0.0, 1.0, 1.5);
        assert!((kr - 1.0).abs() < 1e-12 && kt.abs() < 1e-12);
        // Half the mirror: half of F, and the refraction keeps the rest.
        let half = Scattering::of(
            &Material {
                reflect: 0.5,
                ..glass.clone()
            },
            &all,
        );
        let (kr, kt) = half.shares(1.0, 1.0, 1.5);
        assert!((kr - 0.02).abs() < 1e-15 && (kt - 0.98).abs() < 1e-15);
        // conserve_energy alone: the constant mirror weight comes out of the refraction.
        let conserve = Material {
            fresnel: false,
            conserve_energy: true,
            reflect: 0.3,
            refract: 0.9,
            ..glass.clone()
        };
        let (kr, kt) = Scattering::of(&conserve, &all).shares(0.7, 1.0, 1.5);
        assert_eq!(kr, 0.3);
        assert!((kt - 0.9 * 0.7).abs() < 1e-15);
        // Neither: today's constant weights.
        let plain = Material {
            fresnel: false,
            ..glass
        };
        assert_eq!(
            Scattering::of(&plain, &all).shares(0.1, 1.0, 1.5),
            (1.0, 1.0)
        );
    }
}
