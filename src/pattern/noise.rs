//! Gradient noise: Ken Perlin's improved noise (SIGGRAPH 2002) in three dimensions.
//!
//! **Algorithm.** The point's unit lattice cell has eight corners; each corner `c` gets one of
//! the twelve gradients `g` pointing from a cube's centre to its edge midpoints, `(±1, ±1, 0)`,
//! `(±1, 0, ±1)`, `(0, ±1, ±1)`, chosen by the integer hash of the corner and the seed
//! ([`super::hash`]: `⌊12·h / 2³²⌋`, so the twelve are equally likely, without Perlin's four
//! repeated entries that pad his table to sixteen). The corner contributes `g · (p − c)`; the
//! eight contributions are blended trilinearly with the quintic fade `6t⁵ − 15t⁴ + 10t³`,
//! whose first and second derivatives vanish at 0 and 1, so the noise is C² across cell faces
//! (Perlin's 1985 cubic `3t² − 2t³` left the second derivative jumping there).
//!
//! **Ranges** (measured on 4·10⁶ points, and the bound maximised over every gradient choice):
//! [`improved`] lies in [−[`BOUND`], [`BOUND`]] with `BOUND` = 1.03636, has mean 0 (the
//! gradient set is symmetric under `g → −g`), standard deviation 0.270, and is exactly 0 at
//! every integer lattice point (every contribution there is `g · 0` or has weight 0).
//!
//! **What patterns use.** [`signed`] is `improved` read at `p + SHIFT`, so the zeros sit on a
//! lattice that a floor at `y = 0` or a wall at `x = 1` does not pass through (an unshifted
//! floor would show a grid of exact mid-grey points); [`unit`] maps it to [0, 1] as
//! `0.5 + 0.5·signed`, clamped (the clamp acts only where |n| > 1, beyond 3.7 standard
//! deviations: none of 4·10⁶ samples). That is rtc's counterpart of POV-Ray's `noise` (the
//! value `bozo` shows): POV-Ray 3.7's default generator is a different lattice noise (a value
//! and a gradient term per corner, cubic fade) scaled into [0, 1] with mean ≈ 0.506 and standard
//! deviation ≈ 0.126; ours has mean 0.5 and standard deviation 0.135, so colour maps written for
//! POV-Ray keep their look (slightly more contrast), not their bytes. [`vector`] is three
//! independent gradient noises at once (POV-Ray's `DNoise`, for turbulence), each component
//! distributed as `signed` (POV-Ray's components: standard deviation ≈ 0.257, mean ≈ −0.02).

use glam::DVec3;

use super::hash;

/// The largest |value| improved noise can take: `max Σ wᵢ · (two largest |components| of the
/// corner offset)` over the cell, 1.036354 at (0.355, 0.481, 0.5) and its mirror images.
pub const BOUND: f64 = 1.036_36;

/// Where [`signed`] and [`unit`] read [`improved`]: `signed(p) = improved(p + SHIFT)`, so
/// the lattice zeros fall on no integer or half-integer plane.
pub const SHIFT: DVec3 = DVec3::new(0.217_3, 0.543_7, 0.129_1);

/// The twelve gradient directions of improved noise (cube centre to edge midpoints).
const GRADIENTS: [[f64; 3]; 12] = [
    [1.0, 1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, -1.0, 0.0],
    [1.0, 0.0, 1.0],
    [-1.0, 0.0, 1.0],
    [1.0, 0.0, -1.0],
    [-1.0, 0.0, -1.0],
    [0.0, 1.0, 1.0],
    [0.0, -1.0, 1.0],
    [0.0, 1.0, -1.0],
    [0.0, -1.0, -1.0],
];

/// Perlin's 2002 fade: 6t⁵ − 15t⁴ + 10t³ (zero first and second derivatives at 0 and 1).
#[inline(always)]
pub fn quintic(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// Perlin's 1985 fade: 3t² − 2t³ (kept for the tests that show what the quintic buys).
#[inline(always)]
pub fn cubic(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

/// `a + t·(b − a)`.
#[inline(always)]
fn lerp(t: f64, a: f64, b: f64) -> f64 {
    a + t * (b - a)
}

/// One of the twelve gradients for hash `h` (the top digit of `12·h` in base 2³²) and what is
/// left of the hash for another choice.
#[inline(always)]
fn pick(h: u32) -> (usize, u32) {
    let wide = u64::from(h) * 12;
    ((wide >> 32) as usize, wide as u32)
}

/// `g · d` for gradient index `i`.
#[inline(always)]
fn dot(i: usize, d: DVec3) -> f64 {
    let g = &GRADIENTS[i];
    g[0] * d.x + g[1] * d.y + g[2] * d.z
}

/// A point's lattice cell: the offset from its lowest corner and the eight corner hashes,
/// corner `c` at offset `(c & 1, c >> 1 & 1, c >> 2 & 1)`.
struct Cell {
    t: DVec3,
    hashes: [u32; 8],
}

impl Cell {
    /// The cell of `p` with corner hashes chained from key `k`.
    #[inline(always)]
    fn of(p: DVec3, k: u32) -> Cell {
        let floor = p.floor();
        let t = p - floor;
        let (x, y, z) = (floor.x as i64, floor.y as i64, floor.z as i64);
        // Perlin's P[P[P[x] + y] + z], sharing each prefix between the corners that share it.
        let hx = [hash::chain(k, x as u32), hash::chain(k, (x + 1) as u32)];
        let mut hashes = [0; 8];
        for (c, h) in hashes.iter_mut().enumerate() {
            let hy = hash::chain(hx[c & 1], (y + ((c >> 1) & 1) as i64) as u32);
            *h = hash::chain(hy, (z + ((c >> 2) & 1) as i64) as u32);
        }
        Cell { t, hashes }
    }

    /// The offset of the point from corner `c`.
    #[inline(always)]
    fn offset(&self, c: usize) -> DVec3 {
        self.t - DVec3::new((c & 1) as f64, ((c >> 1) & 1) as f64, ((c >> 2) & 1) as f64)
    }
}

/// The trilinear blend of eight corner values with fade weights `u`.
#[inline(always)]
fn blend(v: [f64; 8], u: DVec3) -> f64 {
    let x00 = lerp(u.x, v[0], v[1]);
    let x10 = lerp(u.x, v[2], v[3]);
    let x01 = lerp(u.x, v[4], v[5]);
    let x11 = lerp(u.x, v[6], v[7]);
    lerp(u.z, lerp(u.y, x00, x10), lerp(u.y, x01, x11))
}

/// Improved noise at `p` under `seed`, with the fade function `fade` (always [`quintic`] but
/// in tests).
#[inline(always)]
pub fn improved_with(p: DVec3, seed: u32, fade: fn(f64) -> f64) -> f64 {
    let cell = Cell::of(p, hash::key(seed));
    let mut v = [0.0; 8];
    for (c, value) in v.iter_mut().enumerate() {
        *value = dot(pick(cell.hashes[c]).0, cell.offset(c));
    }
    let u = DVec3::new(fade(cell.t.x), fade(cell.t.y), fade(cell.t.z));
    blend(v, u)
}

/// Perlin's improved noise at `p` under `seed`: in [−`BOUND`, `BOUND`], mean 0, 0 at integer
/// lattice points.
#[inline]
pub fn improved(p: DVec3, seed: u32) -> f64 {
    improved_with(p, seed, quintic)
}

/// The quintic fade's derivative: 30t²(1 − t)².
#[inline(always)]
fn quintic_slope(t: f64) -> f64 {
    let s = t * (1.0 - t);
    30.0 * s * s
}

/// [`improved`] and its gradient at `p`, from the same cell walk: the value is bit-identical to
/// `improved(p, seed)`; the gradient is exact (the blend of the corner gradients plus the
/// fades' slopes times the corner values' differences), since improved noise is smooth.
#[inline]
pub fn improved_and_gradient(p: DVec3, seed: u32) -> (f64, DVec3) {
    let cell = Cell::of(p, hash::key(seed));
    let (mut v, mut gx, mut gy, mut gz) = ([0.0; 8], [0.0; 8], [0.0; 8], [0.0; 8]);
    for c in 0..8 {
        let i = pick(cell.hashes[c]).0;
        v[c] = dot(i, cell.offset(c));
        let g = &GRADIENTS[i];
        (gx[c], gy[c], gz[c]) = (g[0], g[1], g[2]);
    }
    let t = cell.t;
    let u = DVec3::new(quintic(t.x), quintic(t.y), quintic(t.z));
    // ∂/∂uₓ of the trilinear blend is the same blend, one dimension down, of the differences
    // along x; likewise for y and z.
    let along_x = [
        v[1] - v[0],
        v[1] - v[0],
        v[3] - v[2],
        v[3] - v[2],
        v[5] - v[4],
        v[5] - v[4],
        v[7] - v[6],
        v[7] - v[6],
    ];
    let along_y = [
        v[2] - v[0],
        v[3] - v[1],
        v[2] - v[0],
        v[3] - v[1],
        v[6] - v[4],
        v[7] - v[5],
        v[6] - v[4],
        v[7] - v[5],
    ];
    let along_z = [
        v[4] - v[0],
        v[5] - v[1],
        v[6] - v[2],
        v[7] - v[3],
        v[4] - v[0],
        v[5] - v[1],
        v[6] - v[2],
        v[7] - v[3],
    ];
    let fade_slope = DVec3::new(quintic_slope(t.x), quintic_slope(t.y), quintic_slope(t.z));
    let gradient = DVec3::new(blend(gx, u), blend(gy, u), blend(gz, u))
        + fade_slope
            * DVec3::new(
                blend(along_x, DVec3::new(0.0, u.y, u.z)),
                blend(along_y, DVec3::new(u.x, 0.0, u.z)),
                blend(along_z, DVec3::new(u.x, u.y, 0.0)),
            );
    (blend(v, u), gradient)
}

/// [`unit`] and its gradient (zero where the clamp holds the value).
#[inline]
pub fn unit_and_gradient(p: DVec3, seed: u32) -> (f64, DVec3) {
    let (n, g) = improved_and_gradient(p + SHIFT, seed);
    let v = 0.5 + 0.5 * n;
    if (0.0..=1.0).contains(&v) {
        (v, 0.5 * g)
    } else {
        (v.clamp(0.0, 1.0), DVec3::ZERO)
    }
}

/// Improved noise read at `p + SHIFT` (no zero on integer planes): what fBm and the noise
/// patterns sum.
#[inline]
pub fn signed(p: DVec3, seed: u32) -> f64 {
    improved(p + SHIFT, seed)
}

/// Noise in [0, 1] with mean 0.5: `0.5 + 0.5·signed(p)`, clamped (rtc's POV-Ray `noise`).
#[inline]
pub fn unit(p: DVec3, seed: u32) -> f64 {
    (0.5 + 0.5 * signed(p, seed)).clamp(0.0, 1.0)
}

/// What [`vector`] chains its corner hashes from instead of the seed's key, so a vector noise
/// is not the scalar noise of the same seed in its x component.
const VECTOR_TAG: u32 = 0x7665_6374;

/// Three independent improved noises at `p + SHIFT` (one cell walk: each corner's hash picks
/// three gradients, as successive base-12 digits), each distributed as [`signed`].
#[inline]
pub fn vector(p: DVec3, seed: u32) -> DVec3 {
    let cell = Cell::of(p + SHIFT, hash::chain(hash::key(seed), VECTOR_TAG));
    let (mut vx, mut vy, mut vz) = ([0.0; 8], [0.0; 8], [0.0; 8]);
    for c in 0..8 {
        let d = cell.offset(c);
        let (i, rest) = pick(cell.hashes[c]);
        let (j, rest) = pick(rest);
        let (k, _) = pick(rest);
        vx[c] = dot(i, d);
        vy[c] = dot(j, d);
        vz[c] = dot(k, d);
    }
    let u = DVec3::new(quintic(cell.t.x), quintic(cell.t.y), quintic(cell.t.z));
    DVec3::new(blend(vx, u), blend(vy, u), blend(vz, u))
}
