//! Gradients of patterns for bump mapping, analytic where the pattern has one here: the noise
//! patterns (bozo, dents, granite, wrinkles) from improved noise's exact gradient, and gradient,
//! onion and leopard from their formulas, carried through transform and repeat warps and the
//! wave by the chain rule. Other patterns and warps return `None`, and the caller takes central
//! differences instead.
//!
//! **The step.** A bump reads the pattern at a scale, its `accuracy` step (POV-Ray's default
//! 0.02). A noise octave of frequency `s` has about `s` cycles per unit, and central
//! differences of step `d` see a sinusoid of angular frequency `ω` at `sin(ωd)/(ωd)` of its
//! slope: in full while `ωd < 1`, and within the envelope `1/(ωd)` beyond (the two samples fall
//! ever further apart on the octave's bumps). The analytic sums weight each octave's gradient by that
//! same envelope, [`octave_weight`], so finer octaves do not turn the surface to glitter that
//! no pixel could resolve, and a bump looks as it did when it was measured by differences.

use std::f64::consts::TAU;

use glam::{DMat3, DVec3};

use crate::num::Norm;

use super::fbm::octave_seed;
use super::noise;
use super::{Field, Pattern, Warp, geometric};

/// The weight of a noise octave of frequency `frequency` in a gradient taken at `step`:
/// `min(1, 1 / (2π·frequency·step))` (the module's envelope).
#[inline]
pub fn octave_weight(frequency: f64, step: f64) -> f64 {
    let reach = TAU * frequency * step;
    if reach <= 1.0 { 1.0 } else { 1.0 / reach }
}

impl Field {
    /// The gradient of [`Field::eval`] at `p` (the field's own space) for a bump of `step`
    /// (the module's rules); `None` where no analytic form is known here: a discrete pattern,
    /// a warp other than a transform or repeat, a pattern without one, or a non-finite slope.
    pub fn gradient(&self, p: DVec3, step: f64) -> Option<DVec3> {
        if self.pattern.entries().is_some() {
            return None;
        }
        // ∇ₚ f(w(p)) = J_wᵀ ∇f: the product of the warps' transposed Jacobians, in order.
        let mut q = p;
        let mut to_p = DMat3::IDENTITY;
        for warp in &self.warps {
            match warp {
                Warp::Transform(m) => to_p *= m.matrix3.transpose(),
                Warp::Placement(m) => to_p *= m.inverse().matrix3.transpose(),
                Warp::Repeat(r) => to_p *= DMat3::from_diagonal(r.scale_at(q)),
                _ => return None,
            }
            q = warp.apply(q);
        }
        let (v, g) = value_and_gradient(&self.pattern, q, step)?;
        let slope = self.wave.slope(v);
        let gradient = slope * (to_p * g);
        gradient.is_finite().then_some(gradient)
    }
}

/// The pattern's value and gradient at `q` for a bump of `step`, where known.
fn value_and_gradient(pattern: &Pattern, q: DVec3, step: f64) -> Option<(f64, DVec3)> {
    Some(match *pattern {
        Pattern::Gradient { axis } => (geometric::gradient(q, axis), axis),
        Pattern::Onion => {
            let r = q.norm();
            let direction = if r > 0.0 { q / r } else { DVec3::ZERO };
            (geometric::onion(q), direction)
        }
        Pattern::Leopard => {
            let (sx, sy, sz) = (libm::sin(q.x), libm::sin(q.y), libm::sin(q.z));
            let s = (sx + sy + sz) / 3.0;
            let c = DVec3::new(libm::cos(q.x), libm::cos(q.y), libm::cos(q.z));
            (s * s, (2.0 * s / 3.0) * c)
        }
        Pattern::Bozo { seed } => faded(noise::unit_and_gradient(q, seed), 1.0, step),
        Pattern::Dents { seed } => {
            let (n, g) = faded(noise::unit_and_gradient(q, seed), 1.0, step);
            (n * n * n, 3.0 * n * n * g)
        }
        Pattern::Granite { seed } => granite(q, seed, step),
        Pattern::Wrinkles { seed } => wrinkles(q, seed, step),
        _ => return None,
    })
}

/// A noise value and gradient at frequency `frequency` with the gradient weighted by
/// [`octave_weight`].
#[inline]
fn faded((v, g): (f64, DVec3), frequency: f64, step: f64) -> (f64, DVec3) {
    (v, octave_weight(frequency, step) * g)
}

/// [`super::noisy::granite`] and its faded gradient.
fn granite(p: DVec3, seed: u32, step: f64) -> (f64, DVec3) {
    let (mut sum, mut gradient) = (0.0, DVec3::ZERO);
    let mut scale = 1.0;
    for i in 0..6 {
        let frequency = 4.0 * scale;
        let (n, g) = noise::unit_and_gradient(p * frequency, octave_seed(seed, i));
        let crease = 1.0 - 2.0 * n;
        sum += crease.abs().min(0.5) / scale;
        if crease.abs() < 0.5 {
            // d|1 − 2n|/dp = −2·sign(1 − 2n)·frequency·∇n, over the octave's scale.
            let sign = if crease < 0.0 { -1.0 } else { 1.0 };
            gradient += (-2.0 * sign * frequency / scale * octave_weight(frequency, step)) * g;
        }
        scale *= 2.0;
    }
    (sum, gradient)
}

/// [`super::noisy::wrinkles`] and its faded gradient.
fn wrinkles(p: DVec3, seed: u32, step: f64) -> (f64, DVec3) {
    let (mut sum, mut gradient) = (0.0, DVec3::ZERO);
    let mut scale = 1.0;
    for i in 0..10 {
        let (n, g) = noise::unit_and_gradient(p * scale, octave_seed(seed, i));
        let raised = 2.0 * n - 0.5;
        sum += raised.clamp(0.0, 1.0) / scale;
        if raised > 0.0 && raised < 1.0 {
            // ½ · d(2n)/dp / scale = ∇n at the octave's point (the chain rule's scale cancels).
            gradient += octave_weight(scale, step) * g;
        }
        scale *= 2.0;
    }
    (0.5 * sum, gradient)
}
