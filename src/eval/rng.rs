//! Keyed, counter-based randomness. A stream is `random(seed: s)`; every draw is a pure function
//! of (seed, key, index, lane), so adding a draw never moves another object.
//!
//! The algorithm (language version 1, pinned by tests; never change it silently):
//! * `mix(z)` is the SplitMix64 finaliser:
//!   `z ^= z >> 30; z *= 0xBF58476D1CE4E5B9; z ^= z >> 27; z *= 0x94D049BB133111EB; z ^= z >> 31`
//!   (wrapping multiplication on u64).
//! * `fnv(key)` is 64-bit FNV-1a over the key's UTF-8 bytes
//!   (offset 0xCBF29CE484222325, prime 0x100000001B3).
//! * `bits(seed, key, i, lane) = mix(mix(mix(seed) ^ fnv(key)) ^ (4·i + lane))`, with `i` taken
//!   as two's-complement u64 and wrapping arithmetic.
//! * `u(seed, key, i, lane) = (bits >> 11) · 2⁻⁵³`, uniform in [0, 1).
//! * `uniform(key, i) = u(.., 0)`; `normal(key, i)` is Box–Muller
//!   `sqrt(-2 ln(1 - u0)) · cos(2π u1)`; `in_sphere(key, i)` is `r·(x, y, z)` with
//!   `z = 1 - 2 u0`, `φ = 2π u1`, `r = cbrt(u2)`, `x = sqrt(1 - z²) cos φ`, `y = sqrt(1 - z²) sin φ`;
//!   `on_sphere` is the same with r = 1.

use glam::DVec3;

use super::args::Params;
use super::args::{ArgVal, CallSite};
use super::error::R;
use super::host::BuiltinFn;
use super::host::Host;
use super::schema::{Group, Lit, Param, Sig, Ty};
use super::value::Value;

/// `random(seed:)` with its schema.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&RANDOM, random)];

/// SplitMix64's finaliser.
pub fn mix(mut z: u64) -> u64 {
    z ^= z >> 30;
    z = z.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z ^= z >> 27;
    z = z.wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// 64-bit FNV-1a.
pub fn fnv(key: &str) -> u64 {
    let mut h: u64 = 0xCBF2_9CE4_8422_2325;
    for b in key.bytes() {
        h ^= b as u64;
        h = h.wrapping_mul(0x0000_0100_0000_01B3);
    }
    h
}

/// The raw 64 bits for (seed, key, index, lane).
pub fn bits(seed: u64, key: &str, i: i64, lane: u64) -> u64 {
    mix(mix(mix(seed) ^ fnv(key)) ^ (i as u64).wrapping_mul(4).wrapping_add(lane))
}

/// Uniform in [0, 1).
pub fn unit(seed: u64, key: &str, i: i64, lane: u64) -> f64 {
    (bits(seed, key, i, lane) >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// A standard normal deviate.
fn normal(seed: u64, key: &str, i: i64) -> f64 {
    let u0 = unit(seed, key, i, 0);
    let u1 = unit(seed, key, i, 1);
    (-2.0 * libm::log(1.0 - u0)).sqrt() * libm::cos(std::f64::consts::TAU * u1)
}

/// A point on (`solid = false`) or in the unit sphere.
pub fn sphere_point(seed: u64, key: &str, i: i64, solid: bool) -> DVec3 {
    let z = 1.0 - 2.0 * unit(seed, key, i, 0);
    let phi = std::f64::consts::TAU * unit(seed, key, i, 1);
    let r = if solid {
        libm::cbrt(unit(seed, key, i, 2))
    } else {
        1.0
    };
    let s = (1.0 - z * z).max(0.0).sqrt();
    r * DVec3::new(s * libm::cos(phi), s * libm::sin(phi), z)
}

/// `random(seed)`.
static RANDOM: Sig = Sig::new(
    "random",
    Group::Random,
    "A keyed, counter-based random stream: every draw a pure function of (seed, key, index).",
    &[Param::new("seed", Ty::Int, "the stream's seed")],
    "Rng",
)
.examples(&["random(seed: 7)"]);
fn random(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &RANDOM, a)?;
    let (seed, _) = p.int(it, "seed")?;
    Ok(Value::Rng(seed as u64))
}

/// `rng.uniform(key, i)`, `rng.normal(key, i)`, `rng.in_sphere(key, i)`, `rng.on_sphere(key, i)`,
/// `rng.range(key, i, lo, hi)`.
pub(crate) fn method(
    it: &mut dyn Host,
    seed: u64,
    name: &'static str,
    site: CallSite,
    args: Vec<ArgVal>,
) -> R<Value> {
    let sig = METHODS
        .iter()
        .find(|m| m.name == name)
        .expect("an `Rng` method");
    let mut p = Params::new(site, sig, args)?;
    let (key, _) = p.string(it, "key")?;
    let (i, _) = p.int(it, "index")?;
    Ok(match name {
        "uniform" => Value::Float(unit(seed, &key, i, 0)),
        "normal" => Value::Float(normal(seed, &key, i)),
        "in_sphere" => Value::Vec3(sphere_point(seed, &key, i, true)),
        "on_sphere" => Value::Vec3(sphere_point(seed, &key, i, false)),
        _ => {
            let (lo, _) = p.float(it, "lo")?;
            let (hi, _) = p.float(it, "hi")?;
            Value::Float(lo + (hi - lo) * unit(seed, &key, i, 0))
        }
    })
}

/// The methods of `Rng` values with their schemas.
pub(crate) static METHODS: &[&Sig] = &[&UNIFORM, &NORMAL, &IN_SPHERE, &ON_SPHERE, &RANGE];

/// What a draw is keyed by: a purpose and an index.
const KEY: [Param; 2] = [
    Param::new(
        "key",
        Ty::String,
        "the purpose of the draw (\"size\", \"place\")",
    ),
    Param::new(
        "index",
        Ty::Int,
        "which draw of that purpose (the loop counter)",
    )
    .or(Lit::Int(0)),
];

/// `rng.uniform(key, index)`.
static UNIFORM: Sig = Sig::new(
    "uniform",
    Group::Method,
    "A `Float` in [0, 1).",
    &KEY,
    "Float",
)
.examples(&["random(seed: 7).uniform(key: \"x\", index: 3)"]);
/// `rng.normal(key, index)`.
static NORMAL: Sig = Sig::new(
    "normal",
    Group::Method,
    "A standard normal `Float`.",
    &KEY,
    "Float",
)
.examples(&["random(seed: 7).normal(\"x\", 3)"]);
/// `rng.in_sphere(key, index)`.
static IN_SPHERE: Sig = Sig::new(
    "in_sphere",
    Group::Method,
    "A point uniformly inside the unit ball.",
    &KEY,
    "Vec3",
)
.examples(&["random(seed: 7).in_sphere(\"place\", 3) * 2"]);
/// `rng.on_sphere(key, index)`.
static ON_SPHERE: Sig = Sig::new(
    "on_sphere",
    Group::Method,
    "A point uniformly on the unit sphere.",
    &KEY,
    "Vec3",
)
.examples(&["random(seed: 7).on_sphere(\"dir\")"]);
/// `rng.range(key, index, lo, hi)`.
static RANGE: Sig = Sig::new(
    "range",
    Group::Method,
    "A `Float` in [lo, hi).",
    &[
        KEY[0],
        KEY[1],
        Param::new("lo", Ty::Float, "the lowest value"),
        Param::new("hi", Ty::Float, "the bound above the values"),
    ],
    "Float",
)
.examples(&["random(seed: 7).range(key: \"size\", index: 3, lo: 0.1, hi: 0.3)"]);
