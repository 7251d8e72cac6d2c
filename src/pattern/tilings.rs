//! Tilings: checker, square, hexagon, triangular and brick give the index of the tile a point
//! is in (a whole number; a colour list picks by it), cells a random value per unit cube. The
//! plane tilings lie in the x–z plane (POV-Ray's), constant along y.
//!
//! Coordinates within 5·10⁻⁷ of a cell face are snapped onto it before the floor (rtc's checker
//! rule, render/texture.rs): a hit on a floor at y = 0 lands a rounding error above or below it,
//! and the whole floor must read one row of tiles, not salt and pepper.

use glam::DVec3;

use super::hash;

/// The floor of `v` after snapping it to a millionth: faces at whole numbers read one side.
#[inline(always)]
fn tile(v: f64) -> f64 {
    ((v * 1e6).round() / 1e6).floor()
}

/// Whether a whole number (as f64) is odd.
#[inline(always)]
fn odd(v: f64) -> bool {
    v.rem_euclid(2.0) == 1.0
}

/// `checker`: 0 or 1 alternating between unit cubes; 0 in the cube [0, 1)³.
#[inline]
pub fn checker(p: DVec3) -> f64 {
    let sum = tile(p.x) + tile(p.y) + tile(p.z);
    if odd(sum) { 1.0 } else { 0.0 }
}

/// `square`: four values on the unit squares of the x–z plane, `(x even, z even)` → 0,
/// `(even, odd)` → 1, `(odd, odd)` → 2, `(odd, even)` → 3 (by the squares' floors), so no two
/// squares sharing an edge or a corner match.
#[inline]
pub fn square(p: DVec3) -> f64 {
    match (odd(tile(p.x)), odd(tile(p.z))) {
        (false, false) => 0.0,
        (false, true) => 1.0,
        (true, true) => 2.0,
        (true, false) => 3.0,
    }
}

/// `hexagon`: three values on the regular hexagons of side 1 in the x–z plane, one centred at
/// the origin with corners at x = ±1 (flat sides facing ±z). Centres are `i·(1.5, √3/2) +
/// j·(0, √3)`, and the hexagon `(i, j)` gets `(j − i) mod 3`, so neighbours always differ:
/// the origin's is 0, the one above it (0, √3) is 1, the one at (1.5, √3/2) is 2 — POV-Ray's.
#[inline]
pub fn hexagon(p: DVec3) -> f64 {
    // Lattice coordinates of the point; the nearest centre is the cube-rounded triple
    // (i, j, −i − j), correcting the coordinate that rounded furthest. The point is snapped to
    // a millionth first (a wall at z = 0 is hit a rounding error either side of the edge
    // between two rows of hexagons) and then moved a billionth towards +z, so a point on an
    // edge along x reads the hexagon on its +z side, as POV-Ray's does.
    let snap = |v: f64| (v * 1e6).round() / 1e6;
    let (x, z) = (snap(p.x), snap(p.z) + 1e-9);
    let fi = x * (2.0 / 3.0);
    let fj = z / 3f64.sqrt() - x / 3.0;
    let fk = -fi - fj;
    let (mut i, mut j, k) = (fi.round(), fj.round(), fk.round());
    let (di, dj, dk) = ((i - fi).abs(), (j - fj).abs(), (k - fk).abs());
    if di > dj && di > dk {
        i = -j - k;
    } else if dj > dk {
        j = -i - k;
    }
    // + 0.0 turns a −0 remainder into 0.
    (j - i).rem_euclid(3.0) + 0.0
}

/// `triangular`: six values on the equilateral triangles of side 1 in the x–z plane, rows √3/2
/// high from z = 0, the row from 0 pointing its first triangle up from the edge [0, 1]. In even
/// rows the upward triangle on [a, a + 1] is `−2a mod 6` and the downward one centred on whole
/// `c` is `2c + 1 mod 6`; odd rows are their mirror images with `5 − value`. POV-Ray's colouring:
/// the six triangles around every vertex are the six values.
#[inline]
pub fn triangular(p: DVec3) -> f64 {
    let h = 3f64.sqrt() / 2.0;
    let rows = p.z / h;
    let row = rows.floor();
    let v = rows - row; // height within the row, 0 at its bottom edge
    let half = v / 2.0;
    let index = if !odd(row) {
        // Upward triangles on [a, a + 1]: half-width (1 − v)/2 about a + 1/2.
        let a = p.x.floor();
        let f = p.x - a;
        if f >= half && f <= 1.0 - half {
            -2.0 * a
        } else {
            2.0 * p.x.round() + 1.0
        }
    } else {
        // Upward triangles centred on whole c, downward ones on [a, a + 1].
        let x = p.x + 0.5;
        let c = x.floor();
        let f = x - c;
        if f >= half && f <= 1.0 - half {
            4.0 - 2.0 * c
        } else {
            2.0 * x.round() + 3.0
        }
    };
    index.rem_euclid(6.0) + 0.0
}

/// How far short of each multiple of the brick size its joints end (POV-Ray's `EPSILON`, which
/// its brick adds to the mortar): the multiples themselves, where faces of walls and floors lie,
/// read brick.
pub const BRICK_FACE: f64 = 1e-10;

/// `brick size mortar`: 1 in a brick, 0 in the mortar. Courses `size.y` high, bricks `size.x`
/// long and `size.z` deep, joints `mortar` thick; each course is offset by half a brick from the
/// one below along x (and the end joints along z the other way), so the wall reads as bricks
/// on the x–y and the z–y faces. Mortar lies just below and just before each whole multiple of
/// the size (the origin sits at the top corner of a joint), POV-Ray's placement. A point on a
/// multiple itself reads the brick: the joints end [`BRICK_FACE`] short of it, as POV-Ray's do,
/// so a wall's face at z = 0 (or a floor at y = 0) shows bricks, not one sheet of mortar.
#[inline]
pub fn brick(p: DVec3, size: DVec3, mortar: f64) -> f64 {
    let q = p + DVec3::splat(mortar + BRICK_FACE);
    // Course and where in it: the bottom `mortar` of each course is a bed joint.
    let course = tile(q.y / size.y);
    if q.y - course * size.y <= mortar {
        return 0.0;
    }
    let shift = if odd(course) { 0.5 } else { 0.0 };
    let joint = |v: f64, length: f64, offset: f64| {
        let u = v / length + offset;
        (u - tile(u)) * length <= mortar
    };
    if joint(q.x, size.x, shift) || joint(q.z, size.z, 0.5 - shift) {
        0.0
    } else {
        1.0
    }
}

/// `cells`: a random value in [0, 1) for each unit cube (POV-Ray's `cells`; its `crackle` is
/// Worley's).
#[inline]
pub fn cells(p: DVec3, seed: u32) -> f64 {
    let h = hash::lattice(seed, tile(p.x) as i64, tile(p.y) as i64, tile(p.z) as i64);
    hash::unit(h)
}
