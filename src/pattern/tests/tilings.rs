//! Tilings: checker parity, square and hexagon and triangle colourings, brick joints, cells.

use glam::DVec3;

use super::Lcg;
use crate::pattern::tilings::{brick, cells, checker, hexagon, square, triangular};

/// Checker is the parity of the sum of the cube's coordinates; a floor at y = 0 reads one
/// colour per square whichever side of it rounding put the hit.
#[test]
fn checker_is_the_parity_of_the_cube() {
    let mut rng = Lcg::new(201);
    for _ in 0..10_000 {
        let p = rng.point(100.0);
        let sum = p.x.floor() + p.y.floor() + p.z.floor();
        assert_eq!(checker(p), sum.rem_euclid(2.0), "{p}");
    }
    assert_eq!(checker(DVec3::new(0.5, 0.5, 0.5)), 0.0);
    assert_eq!(checker(DVec3::new(1.5, 0.5, 0.5)), 1.0);
    assert_eq!(checker(DVec3::new(-0.5, 0.5, 0.5)), 1.0);
    for x in [0.25, 1.5, -3.75, 123.5] {
        let above = checker(DVec3::new(x, 1e-13, 0.5));
        let below = checker(DVec3::new(x, -1e-13, 0.5));
        assert_eq!(above, below, "x = {x}");
    }
}

/// Square: four values by the parity of the square's x and z; no two squares sharing an edge
/// or a corner have the same value, and y does not matter.
#[test]
fn square_colours_neighbours_apart() {
    let mut rng = Lcg::new(203);
    for _ in 0..5_000 {
        let c = (rng.point(50.0)).floor() + DVec3::splat(0.5);
        let v = square(c);
        assert_eq!(v, square(c + DVec3::new(0.3, 99.0, -0.2)));
        for (dx, dz) in [(1.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, -1.0)] {
            assert_ne!(v, square(c + DVec3::new(dx, 0.0, dz)), "{c}");
        }
    }
    let at = |x: f64, z: f64| square(DVec3::new(x, 0.0, z));
    assert_eq!(
        [at(0.5, 0.5), at(0.5, 1.5), at(1.5, 1.5), at(1.5, 0.5)],
        [0.0, 1.0, 2.0, 3.0]
    );
}

/// Hexagon centre `(i, j)`: `i·(1.5, √3/2) + j·(0, √3)` in x–z.
fn centre(i: f64, j: f64) -> DVec3 {
    DVec3::new(1.5 * i, 0.0, 3f64.sqrt() / 2.0 * i + 3f64.sqrt() * j)
}

/// Hexagon: every point takes the value of its nearest centre (the hexagons are the Voronoi
/// cells of the centres: regular, side 1), which is `(j − i) mod 3`; the six neighbours of a
/// hexagon all differ from it; POV-Ray's values at the first centres.
#[test]
fn hexagon_tiles_the_plane_with_three_colours() {
    let mut rng = Lcg::new(207);
    for _ in 0..20_000 {
        let p = DVec3::new(rng.point(60.0).x, rng.point(5.0).y, rng.point(60.0).z);
        // The nearest centre by brute force over the lattice coordinates nearby.
        let i0 = (p.x / 1.5).round();
        let mut best = (f64::INFINITY, 0.0);
        for di in -2..=2 {
            let i = i0 + f64::from(di);
            let j0 = ((p.z - 3f64.sqrt() / 2.0 * i) / 3f64.sqrt()).round();
            for dj in -2..=2 {
                let j = j0 + f64::from(dj);
                let c = centre(i, j);
                let d = (p.x - c.x).powi(2) + (p.z - c.z).powi(2);
                if d < best.0 {
                    best = (d, (j - i).rem_euclid(3.0));
                }
            }
        }
        assert_eq!(hexagon(p), best.1, "{p}");
    }
    let neighbours = [
        (1.0, 0.0),
        (1.0, -1.0),
        (0.0, -1.0),
        (-1.0, 0.0),
        (-1.0, 1.0),
        (0.0, 1.0),
    ];
    for i in -5..5 {
        for j in -5..5 {
            let (i, j) = (f64::from(i), f64::from(j));
            let v = hexagon(centre(i, j));
            assert_eq!(v, (j - i).rem_euclid(3.0));
            for (di, dj) in neighbours {
                assert_ne!(v, hexagon(centre(i + di, j + dj)));
            }
        }
    }
    // The hexagon at the origin has corners at x = ±1 and flat sides at z = ±√3/2.
    assert_eq!(hexagon(DVec3::new(0.99, 0.0, 0.0)), 0.0);
    assert_eq!(hexagon(DVec3::new(0.0, 0.0, 0.86)), 0.0);
    assert_eq!(hexagon(DVec3::new(0.0, 0.0, 0.87)), 1.0);
    assert_eq!(hexagon(DVec3::new(1.5, 0.0, 0.866)), 2.0);
}

/// Triangular: constant within each triangle (its incircle sampled around its centroid), and
/// the six triangles around every vertex take the six values; POV-Ray's values at the first
/// triangles.
#[test]
fn triangular_tiles_the_plane_with_six_colours() {
    let h = 3f64.sqrt() / 2.0;
    let mut rng = Lcg::new(211);
    for row in -6..6 {
        for col in -6..6 {
            // Vertex `col` of row `row`'s bottom edge (odd rows shifted half a side).
            let shift = if row % 2 == 0 { 0.0 } else { 0.5 };
            let v = DVec3::new(f64::from(col) + shift, 0.0, f64::from(row) * h);
            let mut seen = [false; 6];
            for k in 0..6 {
                let angle = std::f64::consts::PI / 6.0 + std::f64::consts::PI / 3.0 * f64::from(k);
                // The centroid of each triangle around the vertex is 1/√3 away.
                let centroid =
                    v + DVec3::new(libm::cos(angle), 0.0, libm::sin(angle)) / 3f64.sqrt();
                let value = triangular(centroid);
                seen[value as usize] = true;
                for _ in 0..20 {
                    // Within the incircle (radius √3/6 ≈ 0.2887).
                    let a = std::f64::consts::TAU * rng.next();
                    let r = 0.28 * rng.next().sqrt();
                    let q = centroid + DVec3::new(r * libm::cos(a), 5.0, r * libm::sin(a));
                    assert_eq!(triangular(q), value, "at {q}, triangle of {centroid}");
                }
            }
            assert!(seen.iter().all(|&s| s), "around {v}: {seen:?}");
        }
    }
    let at = |x: f64, z: f64| triangular(DVec3::new(x, 0.0, z));
    // Row 0: upward triangles on [0, 1], [1, 2], [2, 3] are 0, 4, 2; downward ones centred on
    // 0, 1, 2 are 1, 3, 5. Row 1: downward on [0, 1] is 5, upward centred on 0 is 4.
    assert_eq!([at(0.5, 0.2), at(1.5, 0.2), at(2.5, 0.2)], [0.0, 4.0, 2.0]);
    assert_eq!([at(0.0, 0.7), at(1.0, 0.7), at(2.0, 0.7)], [1.0, 3.0, 5.0]);
    assert_eq!([at(0.5, h + 0.7), at(0.0, h + 0.2)], [5.0, 4.0]);
}

/// The lengths of the runs of mortar (0) and brick (1) met walking along `dir` from `start`.
fn runs(start: DVec3, dir: DVec3, length: f64, size: DVec3, mortar: f64) -> Vec<(f64, f64)> {
    let step = 1e-3;
    let mut out: Vec<(f64, f64)> = Vec::new();
    for i in 0..(length / step) as usize {
        let v = brick(start + dir * (i as f64 * step), size, mortar);
        match out.last_mut() {
            Some((value, run)) if *value == v => *run += step,
            _ => out.push((v, step)),
        }
    }
    out
}

/// Brick: bed joints `mortar` thick every course height, head joints `mortar` thick every
/// brick length, staggered by half a brick between courses (and the end joints on the z face
/// the other way); the origin at the top corner of a joint.
#[test]
fn brick_joints_are_mortar_thick_and_staggered() {
    let (size, mortar) = (DVec3::new(8.0, 3.0, 4.5), 0.5);
    // Up a column through bricks: mortar 0.5, brick 2.5, repeating.
    let column = runs(DVec3::new(2.0, 0.25, 1.0), DVec3::Y, 12.0, size, mortar);
    for &(v, run) in &column[1..column.len() - 1] {
        let want = if v == 0.0 { mortar } else { size.y - mortar };
        assert!((run - want).abs() < 2e-3, "{column:?}");
    }
    // Along x in course 0 (y in (0, 2.5]) the joints are at x in [8k − 0.5, 8k]; in course 1
    // half a brick further.
    assert_eq!(brick(DVec3::new(-0.25, 1.0, 1.0), size, mortar), 0.0);
    assert_eq!(brick(DVec3::new(0.25, 1.0, 1.0), size, mortar), 1.0);
    assert_eq!(brick(DVec3::new(7.75, 1.0, 1.0), size, mortar), 0.0);
    assert_eq!(brick(DVec3::new(-0.25, 4.0, 1.0), size, mortar), 1.0);
    assert_eq!(brick(DVec3::new(3.75, 4.0, 1.0), size, mortar), 0.0);
    assert_eq!(brick(DVec3::new(1.0, -0.25, 1.0), size, mortar), 0.0);
    for y in [1.0, 4.0] {
        let row = runs(DVec3::new(-20.0, y, 1.0), DVec3::X, 40.0, size, mortar);
        for &(v, run) in &row[1..row.len() - 1] {
            let want = if v == 0.0 { mortar } else { size.x - mortar };
            assert!((run - want).abs() < 2e-3, "y {y}: {row:?}");
        }
        // Along z on the end face the joints come every depth, staggered the other way.
        let end = runs(DVec3::new(3.0, y, -20.0), DVec3::Z, 40.0, size, mortar);
        for &(v, run) in &end[1..end.len() - 1] {
            let want = if v == 0.0 { mortar } else { size.z - mortar };
            assert!((run - want).abs() < 2e-3, "y {y}: {end:?}");
        }
    }
    assert_eq!(brick(DVec3::new(3.0, 1.0, 2.0), size, mortar), 0.0);
    assert_eq!(brick(DVec3::new(3.0, 4.0, 2.0), size, mortar), 1.0);
    assert_eq!(brick(DVec3::new(3.0, 4.0, -0.25), size, mortar), 0.0);
}

/// Cells: one value in [0, 1) per unit cube, the same anywhere in it, different between cubes
/// and seeds, with mean 0.5.
#[test]
fn cells_are_constant_per_cube() {
    let mut rng = Lcg::new(213);
    let (mut sum, mut same) = (0.0, 0);
    for _ in 0..20_000 {
        let c = rng.point(1000.0).floor();
        let v = cells(c + DVec3::splat(0.5), 3);
        assert!((0.0..1.0).contains(&v));
        assert_eq!(v, cells(c + DVec3::new(0.01, 0.99, 0.4), 3));
        if v == cells(c + DVec3::new(1.5, 0.5, 0.5), 3) || v == cells(c + DVec3::splat(0.5), 4) {
            same += 1;
        }
        sum += v;
    }
    assert!(same < 5, "{same}");
    assert!((sum / 20_000.0 - 0.5).abs() < 0.01);
}
