//! Numeric helpers every stage shares: lengths and unit vectors with the standard library's
//! square root.
//!
//! glam is built with its `libm` feature so that its trigonometry gives the same bits on every
//! machine, and so its `length`, `normalize` and friends take their square root from libm,
//! whose x86 `sqrt` is inline assembly: opaque to the optimiser (never paired into `sqrtpd`,
//! never scheduled across), and in the legacy SSE encoding, which stalls on the upper halves of
//! the AVX registers around it in a build for x86-64-v3 (scene A took 2.2× as long). `f64::sqrt`
//! is the same correctly rounded operation (IEEE 754 requires it), so every result here is
//! glam's to the bit; `clippy.toml` forbids glam's own versions.

use glam::{DVec2, DVec3, Vec3, Vec3A};

/// The length of a vector and the unit vector along it, computed as glam computes them.
pub trait Norm: Sized + Copy {
    /// The scalar type.
    type Scalar;
    /// `√(v·v)` (glam's `length`).
    fn norm(self) -> Self::Scalar;
    /// `v · (1 / |v|)` (glam's `normalize`).
    fn unit(self) -> Self;
    /// The unit vector, or `None` when `1 / |v|` is not finite and positive (glam's
    /// `try_normalize`).
    fn try_unit(self) -> Option<Self>;
    /// The unit vector, or `fallback` when there is none (glam's `normalize_or`).
    fn unit_or(self, fallback: Self) -> Self {
        self.try_unit().unwrap_or(fallback)
    }
    /// `|self − other|` (glam's `distance`).
    fn distance_to(self, other: Self) -> Self::Scalar;
}

macro_rules! norm_by_dot {
    ($v:ty, $s:ty) => {
        impl Norm for $v {
            type Scalar = $s;
            #[inline(always)]
            fn norm(self) -> $s {
                self.dot(self).sqrt()
            }
            #[inline(always)]
            fn unit(self) -> $v {
                self * (1.0 / self.norm())
            }
            #[inline(always)]
            fn try_unit(self) -> Option<$v> {
                let rcp = 1.0 / self.norm();
                (rcp.is_finite() && rcp > 0.0).then(|| self * rcp)
            }
            #[inline(always)]
            fn distance_to(self, other: $v) -> $s {
                (self - other).norm()
            }
        }
    };
}

norm_by_dot!(DVec3, f64);
norm_by_dot!(DVec2, f64);
norm_by_dot!(Vec3, f32);

/// `Vec3A` takes its square roots from SSE intrinsics already (no libm): glam's own methods.
impl Norm for Vec3A {
    type Scalar = f32;
    #[inline(always)]
    #[allow(clippy::disallowed_methods)]
    fn norm(self) -> f32 {
        self.length()
    }
    #[inline(always)]
    #[allow(clippy::disallowed_methods)]
    fn unit(self) -> Vec3A {
        self.normalize()
    }
    #[inline(always)]
    #[allow(clippy::disallowed_methods)]
    fn try_unit(self) -> Option<Vec3A> {
        self.try_normalize()
    }
    #[inline(always)]
    #[allow(clippy::disallowed_methods)]
    fn distance_to(self, other: Vec3A) -> f32 {
        self.distance(other)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bit for bit glam's results, zero and non-finite vectors included.
    #[test]
    #[allow(clippy::disallowed_methods)]
    fn norms_are_glams() {
        // A 64-bit LCG (Knuth's MMIX constants): reproducible inputs.
        let mut seed = 41u64;
        let mut rnd = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64) / (1u64 << 53) as f64
        };
        let mut vs: Vec<DVec3> = (0..500)
            .map(|i| (DVec3::new(rnd(), rnd(), rnd()) - 0.5) * 10f64.powi(i % 40 - 20))
            .collect();
        vs.extend([
            DVec3::ZERO,
            DVec3::splat(f64::NAN),
            DVec3::new(f64::INFINITY, 0.0, 1.0),
        ]);
        let bits = |v: DVec3| v.to_array().map(f64::to_bits);
        for v in vs {
            assert_eq!(v.norm().to_bits(), v.length().to_bits());
            assert_eq!(bits(v.unit()), bits(v.normalize()));
            assert_eq!(v.try_unit().map(bits), v.try_normalize().map(bits));
            assert_eq!(bits(v.unit_or(DVec3::Y)), bits(v.normalize_or(DVec3::Y)));
            assert_eq!(
                v.distance_to(DVec3::ONE).to_bits(),
                v.distance(DVec3::ONE).to_bits()
            );
            let w = DVec2::new(v.x, v.y);
            assert_eq!(w.norm().to_bits(), w.length().to_bits());
            assert_eq!(
                w.unit().to_array().map(f64::to_bits),
                w.normalize().to_array().map(f64::to_bits)
            );
            let f = v.as_vec3();
            assert_eq!(f.norm().to_bits(), f.length().to_bits());
            assert_eq!(
                f.try_unit().map(|u| u.to_array().map(f32::to_bits)),
                f.try_normalize().map(|u| u.to_array().map(f32::to_bits))
            );
        }
    }
}
