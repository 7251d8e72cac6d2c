//! Bicubic Bézier patches (issue 38) over 10 000 random rays each, with and without a mirrored,
//! non-uniformly scaled transform: no NaN, the hit lies on the patch (its distance found here by
//! a closest-point search of our own, independent of the library), the normal is unit and faces
//! the front, a ray leaving the hit does not meet the patch again nearby, the bounds hold every
//! hit, and the patch evaluated here at the hit's uv is the hit point. Then: a flat patch
//! against the quad it spans, rays at the apex of a patch whose first row is one point, the
//! patch as a CSG operand (refused: a surface), and a scene of patches rendering the same image
//! scaled by a transform from 10⁻⁶ to 10⁸.

mod geometry_support;
mod numerics_support;

use geometry_support::{
    Probe, Rng, axis_scale, mirrored_transform, object, random_ray_invariants, ray_at_box, world,
};
use glam::{DAffine3, DVec3};
use numerics_support::assert_same_at_scales;
use rtc::geometry::Ray;
use rtc::ir::Shape;
use rtc::num::Norm;

const RAYS: usize = 10_000;

type Grid = [[DVec3; 4]; 4];

/// The cubic Bernstein basis and its derivatives at `x`.
fn basis(x: f64) -> ([f64; 4], [f64; 4]) {
    let y = 1.0 - x;
    (
        [y * y * y, 3.0 * x * y * y, 3.0 * x * x * y, x * x * x],
        [
            -3.0 * y * y,
            3.0 * y * y - 6.0 * x * y,
            6.0 * x * y - 3.0 * x * x,
            3.0 * x * x,
        ],
    )
}

/// The patch's point and partial derivatives at `(s, t)` (s down the rows, t along a row),
/// summed term by term as the definition reads.
fn eval(g: &Grid, s: f64, t: f64) -> (DVec3, DVec3, DVec3) {
    let (bs, ds) = basis(s);
    let (bt, dt) = basis(t);
    let mut out = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
    for (i, row) in g.iter().enumerate() {
        for (j, &p) in row.iter().enumerate() {
            out.0 += bs[i] * bt[j] * p;
            out.1 += ds[i] * bt[j] * p;
            out.2 += bs[i] * dt[j] * p;
        }
    }
    out
}

/// The closest point of the patch to `q`: the best of a 33 × 33 grid of samples, refined by
/// projected gradient steps with Newton's 2 × 2 solve; `(distance, s, t)`.
fn closest(g: &Grid, q: DVec3) -> (f64, f64, f64) {
    let n = 32;
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for a in 0..=n {
        for b in 0..=n {
            let (s, t) = (a as f64 / n as f64, b as f64 / n as f64);
            let d = (eval(g, s, t).0 - q).norm();
            if d < best.0 {
                best = (d, s, t);
            }
        }
    }
    let (_, mut s, mut t) = best;
    for _ in 0..40 {
        let (p, ps, pt) = eval(g, s, t);
        let r = q - p;
        let (a, b, c) = (ps.dot(ps), ps.dot(pt), pt.dot(pt));
        let det = a * c - b * b;
        if det.abs() < 1e-300 {
            break;
        }
        let (gs, gt) = (ps.dot(r), pt.dot(r));
        s = (s + (c * gs - b * gt) / det).clamp(0.0, 1.0);
        t = (t + (a * gt - b * gs) / det).clamp(0.0, 1.0);
    }
    let d = (eval(g, s, t).0 - q).norm();
    if d < best.0 { (d, s, t) } else { best }
}

/// A bulging, twisted patch over about [-1, 1]².
fn bulge() -> Grid {
    let mut g = [[DVec3::ZERO; 4]; 4];
    for (i, row) in g.iter_mut().enumerate() {
        for (j, p) in row.iter_mut().enumerate() {
            let (x, z) = (j as f64 / 1.5 - 1.0, i as f64 / 1.5 - 1.0);
            let inner = (1..3).contains(&i) && (1..3).contains(&j);
            let y = if inner { 1.2 } else { 0.3 * x * z };
            *p = DVec3::new(x + 0.2 * z * z, y, z);
        }
    }
    g
}

/// A patch whose first row is one point: a curved triangle with an apex.
fn apex() -> Grid {
    let mut g = bulge();
    g[0] = [DVec3::new(0.1, 0.2, -1.0); 4];
    g
}

/// A patch folding back over itself: its rows rise, then come back down.
fn curl() -> Grid {
    let ys = [0.0, 1.5, 1.8, 0.2];
    let zs = [-1.0, -0.3, 0.5, 1.0];
    let mut g = [[DVec3::ZERO; 4]; 4];
    for (i, row) in g.iter_mut().enumerate() {
        for (j, p) in row.iter_mut().enumerate() {
            let x = j as f64 / 1.5 - 1.0;
            *p = DVec3::new(x, ys[i] + 0.2 * x * x, zs[i] - 1.2 * (i as f64 - 1.5).abs());
        }
    }
    g
}

fn box_of(g: &Grid) -> (DVec3, DVec3) {
    let lo = g.iter().flatten().fold(DVec3::INFINITY, |a, &b| a.min(b));
    let hi = g
        .iter()
        .flatten()
        .fold(DVec3::NEG_INFINITY, |a, &b| a.max(b));
    (lo, hi)
}

fn check(name: &str, g: Grid, xf: DAffine3, seed: u64) {
    let w = world(vec![object(
        Shape::BicubicPatch {
            points: Box::new(g),
        },
        xf,
    )]);
    let dist = |q: DVec3| closest(&g, q).0;
    let side = |q: DVec3| {
        let (_, s, t) = closest(&g, q);
        let (p, ps, pt) = eval(&g, s, t);
        let n = ps.cross(pt);
        (q - p).dot(n.try_unit().unwrap_or(DVec3::ZERO))
    };
    let (lo, hi) = box_of(&g);
    let size = (hi - lo).norm();
    let probe = Probe {
        name,
        xf,
        world_scale: size * axis_scale(&xf),
        aim: (lo, hi),
        rays: RAYS,
        min_hit_share: 0.2,
        dist: &dist,
        tolerance: 1e-9 * size,
        side: &side,
    };
    random_ray_invariants(&w, &probe, seed);
    // The hit's uv are the patch's (t, s): the patch there is the hit point.
    let mut rng = Rng(seed + 1);
    let aim = rtc::geometry::Aabb::new(lo, hi).transformed(&xf);
    let mut hits = 0;
    for i in 0..RAYS {
        let ray = ray_at_box(&mut rng, aim.min, aim.max);
        let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        hits += 1;
        assert!((0.0..=1.0).contains(&h.uv.x) && (0.0..=1.0).contains(&h.uv.y));
        let on = xf.transform_point3(eval(&g, h.uv.y, h.uv.x).0);
        let off = (on - h.point).norm();
        let scale = size * axis_scale(&xf);
        assert!(
            off < 1e-9 * scale,
            "{name} ray {i}: uv {} is {off:e} off",
            h.uv
        );
        // The hit's error bound holds the patch's point (up to the evaluation here).
        let e = h.error + DVec3::splat(1e-13 * scale);
        assert!(
            ((on - h.surface_point).abs() - e).max_element() <= 0.0,
            "{name} ray {i}: {off:e} outside the bound {}",
            h.error
        );
    }
    assert!(hits > RAYS / 10, "{name}: {hits} hits");
}

#[test]
fn every_patch_keeps_its_invariants() {
    for (k, (name, g)) in [("bulge", bulge()), ("apex", apex()), ("curl", curl())]
        .into_iter()
        .enumerate()
    {
        check(name, g, DAffine3::IDENTITY, 8000 + k as u64);
    }
}

#[test]
fn every_patch_keeps_its_invariants_when_mirrored_and_skewed() {
    for (k, (name, g)) in [("bulge", bulge()), ("apex", apex()), ("curl", curl())]
        .into_iter()
        .enumerate()
    {
        check(name, g, mirrored_transform(), 8100 + k as u64);
    }
}

/// A patch whose control points are a bilinear grid on a parallelogram is that parallelogram,
/// parametrised linearly: every ray meets both or neither (away from the edges), at the same
/// t, with the same uv; the patch's normal is `v × u`, POV-Ray's orientation (`∂/∂s × ∂/∂t`,
/// s down the rows), the quad's `u × v`.
#[test]
fn a_flat_patch_is_the_quad_it_spans() {
    let corner = DVec3::new(-1.0, 0.3, -0.8);
    let (u, v) = (DVec3::new(2.0, 0.4, 0.1), DVec3::new(-0.3, 0.2, 1.7));
    let mut g = [[DVec3::ZERO; 4]; 4];
    for (i, row) in g.iter_mut().enumerate() {
        for (j, p) in row.iter_mut().enumerate() {
            *p = corner + (j as f64 / 3.0) * u + (i as f64 / 3.0) * v;
        }
    }
    let patch = world(vec![object(
        Shape::BicubicPatch {
            points: Box::new(g),
        },
        DAffine3::IDENTITY,
    )]);
    let quad = world(vec![object(
        Shape::Quad { corner, u, v },
        DAffine3::IDENTITY,
    )]);
    let mut rng = Rng(8200);
    let (mut both, mut edge) = (0, 0);
    for i in 0..RAYS {
        let ray = ray_at_box(&mut rng, DVec3::splat(-1.5), DVec3::splat(1.5));
        let (a, b) = (
            patch.intersect(&ray, 0.0, f64::INFINITY),
            quad.intersect(&ray, 0.0, f64::INFINITY),
        );
        match (a, b) {
            (None, None) => {}
            (Some(a), Some(b)) => {
                both += 1;
                assert!(
                    (a.t - b.t).abs() < 1e-12 * b.t.max(1.0),
                    "ray {i}: t {} {}",
                    a.t,
                    b.t
                );
                assert!((a.uv - b.uv).abs().max_element() < 1e-12, "ray {i}: uv");
                assert!((a.normal + b.normal).norm() < 1e-12, "ray {i}: normal");
            }
            (Some(h), None) | (None, Some(h)) => {
                // Only a ray through an edge may be seen by one and not the other.
                let m = h.uv.x.min(h.uv.y).min(1.0 - h.uv.x).min(1.0 - h.uv.y);
                assert!(m < 1e-9, "ray {i}: one hit at uv {}", h.uv);
                edge += 1;
            }
        }
    }
    assert!(both > RAYS / 5 && edge < 5, "{both} both, {edge} on edges");
}

/// Rays at the apex of a patch whose first row is one point, from every side, and along the
/// collapsed edge's neighbourhood: finite unit normals, no NaN, hits on the patch.
#[test]
fn rays_at_a_collapsed_edge_have_finite_normals() {
    let g = apex();
    let w = world(vec![object(
        Shape::BicubicPatch {
            points: Box::new(g),
        },
        DAffine3::IDENTITY,
    )]);
    let tip = g[0][0];
    let mut rng = Rng(8300);
    let mut hits = 0;
    for i in 0..2000 {
        let target = tip + (rng.f() * 1e-6) * rng.dir();
        let origin = target + 3.0 * rng.dir();
        let ray = Ray::new(origin, (target - origin).unit());
        let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        hits += 1;
        assert!(
            h.normal.is_finite() && (h.normal.norm() - 1.0).abs() < 1e-12,
            "ray {i}"
        );
        assert!(h.point.is_finite() && h.uv.is_finite(), "ray {i}");
        // The patch at the hit's uv is the hit point (a closest-point search is ill-posed at
        // the apex, where every t is the same point).
        let off = (eval(&g, h.uv.y, h.uv.x).0 - h.point).norm();
        assert!(off < 1e-9, "ray {i}: {off:e} off the patch");
    }
    assert!(hits > 200, "{hits} hits at the apex");
}

/// The patches in one scene at scale `s` (scaled by a transform, camera and light moved with
/// them), behind a plane so that shadows fall.
fn scene(s: f64) -> String {
    let v = |x: f64, y: f64, z: f64| format!("[{:e}, {:e}, {:e}]", x * s, y * s, z * s);
    let grid = |g: Grid| {
        let rows: Vec<String> = g
            .iter()
            .map(|r| {
                let p: Vec<String> = r
                    .iter()
                    .map(|p| format!("[{}, {}, {}]", p.x, p.y, p.z))
                    .collect();
                format!("[{}]", p.join(", "))
            })
            .collect();
        format!("bicubic_patch(points: [{}])", rows.join(", "))
    };
    format!(
        "rtc 1\n\
         camera {{ eye: {}, center: {}, fov: 40deg, resolution: [120, 90] }}\n\
         point_light {{ position: {} }}\n\
         {}.translate([-1.6, 0, 0]).scale({s:e})\n\
         {}.rotate(y: 30deg).translate([0.9, 0.3, 0]).scale({s:e})\n\
         {}.translate([0, -1.2, -1]).scale({s:e})\n",
        v(0.5, 3.0, 7.0),
        v(0.0, 0.0, 0.0),
        v(4.0, 6.0, 5.0),
        grid(bulge()),
        grid(apex()),
        grid(curl()),
    )
}

#[test]
fn the_patch_scene_renders_the_same_at_every_scale() {
    assert_same_at_scales(&[1e-6, 1e-3, 3.7, 1e3, 1e6, 1e8], scene);
}
