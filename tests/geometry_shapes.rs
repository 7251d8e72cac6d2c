//! Per-shape invariants over 10 000 random rays each, with and without a mirrored,
//! non-uniformly scaled transform: the hit lies on the surface (checked against formulas
//! written here, independent of the library), the normal is unit and faces out, a ray
//! leaving the hit point does not hit the surface again nearby, and the bounds hold every hit.

mod geometry_support;

use geometry_support::{Rng, hemisphere, mirrored_transform, object, ray_at_box, world};
use glam::{DAffine3, DVec2, DVec3};
use rtc::geometry::Ray;
use rtc::ir::{BlobComponent, Shape};
use rtc::num::Norm;

const RAYS: usize = 10_000;

/// A shape with independent reference formulas in object space.
struct Case {
    name: &'static str,
    shape: Shape,
    /// Signed: positive outside (or on the front side of a surface).
    side: Box<dyn Fn(DVec3) -> f64>,
    /// Unsigned distance to the surface patch (large when off the patch).
    dist: Box<dyn Fn(DVec3) -> f64>,
    /// Object-space region to aim rays at.
    aim: (DVec3, DVec3),
    /// Object-space size (tolerances scale with it).
    size: f64,
    /// Rays from outside must hit at least this share of the time.
    min_hit_share: f64,
}

fn box_sdf(q: DVec3, lo: DVec3, hi: DVec3) -> f64 {
    let c = 0.5 * (lo + hi);
    let h = 0.5 * (hi - lo);
    let d = (q - c).abs() - h;
    d.max(DVec3::ZERO).norm() + d.max_element().min(0.0)
}

/// (height along the axis, radial distance) of `q` for the segment base→top.
fn axial(q: DVec3, base: DVec3, top: DVec3) -> (f64, f64, f64) {
    let a = (top - base).unit();
    let w = q - base;
    let y = w.dot(a);
    (y, (w - y * a).norm(), (top - base).norm())
}

fn plane_frame(n: DVec3) -> (DVec3, DVec3) {
    let e1 = n.any_orthonormal_vector();
    (e1, n.cross(e1))
}

fn cases() -> Vec<Case> {
    let mut v = Vec::new();
    {
        let (c, r) = (DVec3::new(0.3, -0.2, 0.1), 1.3);
        v.push(Case {
            name: "sphere",
            shape: Shape::Sphere {
                center: c,
                radius: r,
            },
            side: Box::new(move |q| (q - c).norm() - r),
            dist: Box::new(move |q| ((q - c).norm() - r).abs()),
            aim: (c - r, c + r),
            size: 2.0 * r,
            min_hit_share: 0.25,
        });
    }
    {
        let (lo, hi) = (DVec3::new(-1.0, -0.5, -2.0), DVec3::new(1.5, 0.7, 0.3));
        v.push(Case {
            name: "box",
            shape: Shape::Box { min: lo, max: hi },
            side: Box::new(move |q| box_sdf(q, lo, hi)),
            dist: Box::new(move |q| box_sdf(q, lo, hi).abs()),
            aim: (lo, hi),
            size: (hi - lo).norm(),
            min_hit_share: 0.9,
        });
    }
    {
        let p = DVec3::new(0.0, 0.5, 0.0);
        let n = DVec3::new(0.2, 1.0, 0.1).unit();
        v.push(Case {
            name: "plane",
            shape: Shape::Plane {
                point: p,
                normal: n,
            },
            side: Box::new(move |q| (q - p).dot(n)),
            dist: Box::new(move |q| (q - p).dot(n).abs()),
            aim: (DVec3::splat(-2.0), DVec3::splat(2.0)),
            size: 4.0,
            min_hit_share: 0.4,
        });
    }
    {
        let t = [
            DVec3::new(-1.0, -0.8, 0.2),
            DVec3::new(1.2, -0.3, -0.4),
            DVec3::new(0.1, 1.1, 0.5),
        ];
        let n = (t[1] - t[0]).cross(t[2] - t[0]);
        v.push(Case {
            name: "triangle",
            shape: Shape::Triangle { vertices: t },
            side: Box::new(move |q| (q - t[0]).dot(n.unit())),
            dist: Box::new(move |q| {
                // Barycentric coordinates of the projection onto the plane.
                let nn = n.length_squared();
                let b1 = (q - t[0]).cross(t[2] - t[0]).dot(n) / nn;
                let b2 = (t[1] - t[0]).cross(q - t[0]).dot(n) / nn;
                let inside = b1 >= -1e-9 && b2 >= -1e-9 && b1 + b2 <= 1.0 + 1e-9;
                if inside {
                    (q - t[0]).dot(n.unit()).abs()
                } else {
                    1e9
                }
            }),
            aim: (DVec3::new(-1.0, -0.8, -0.4), DVec3::new(1.2, 1.1, 0.5)),
            size: 3.0,
            min_hit_share: 0.2,
        });
    }
    {
        let (c, u, w) = (
            DVec3::new(-0.5, -0.5, 0.0),
            DVec3::new(1.4, 0.2, 0.1),
            DVec3::new(-0.3, 1.0, 0.6),
        );
        let n = u.cross(w);
        v.push(Case {
            name: "quad",
            shape: Shape::Quad { corner: c, u, v: w },
            side: Box::new(move |q| (q - c).dot(n.unit())),
            dist: Box::new(move |q| {
                let nn = n.length_squared();
                let s = (q - c).cross(w).dot(n) / nn;
                let r = u.cross(q - c).dot(n) / nn;
                let e = 1e-9;
                let inside = (-e..=1.0 + e).contains(&s) && (-e..=1.0 + e).contains(&r);
                if inside {
                    (q - c).dot(n.unit()).abs()
                } else {
                    1e9
                }
            }),
            aim: (DVec3::new(-0.8, -0.5, 0.0), DVec3::new(0.9, 0.7, 0.7)),
            size: 2.0,
            min_hit_share: 0.3,
        });
    }
    {
        // A concave "L" in a tilted plane; winding-number test written here.
        let n = DVec3::new(0.3, 0.2, 1.0).unit();
        let (e1, e2) = plane_frame(n);
        let o = DVec3::new(0.2, 0.1, -0.3);
        let flat = [
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 0.6),
            DVec2::new(0.6, 0.6),
            DVec2::new(0.6, 2.0),
            DVec2::new(0.0, 2.0),
        ];
        let pts: Vec<DVec3> = flat.iter().map(|p| o + p.x * e1 + p.y * e2).collect();
        let winding = move |q: DVec2| {
            let mut wn = 0i32;
            for i in 0..flat.len() {
                let (a, b) = (flat[i], flat[(i + 1) % flat.len()]);
                let cross = (b - a).perp_dot(q - a);
                if a.y <= q.y && b.y > q.y && cross > 0.0 {
                    wn += 1;
                } else if a.y > q.y && b.y <= q.y && cross < 0.0 {
                    wn -= 1;
                }
            }
            wn != 0
        };
        let pn = (e1.cross(e2)).dot(n).signum() * n;
        v.push(Case {
            name: "polygon (concave)",
            shape: Shape::Polygon { points: pts },
            side: Box::new(move |q| (q - o).dot(pn)),
            dist: Box::new(move |q| {
                let w = q - o;
                let f = DVec2::new(w.dot(e1), w.dot(e2));
                if winding(f) { w.dot(pn).abs() } else { 1e9 }
            }),
            aim: (o - 0.5, o + 2.0),
            size: 2.8,
            min_hit_share: 0.05,
        });
    }
    {
        let (c, n, r) = (
            DVec3::new(0.1, 0.0, -0.2),
            DVec3::new(-0.4, 1.0, 0.3).unit(),
            0.9,
        );
        v.push(Case {
            name: "disk",
            shape: Shape::Disk {
                center: c,
                normal: n,
                radius: r,
            },
            side: Box::new(move |q| (q - c).dot(n)),
            dist: Box::new(move |q| {
                let w = q - c;
                let radial = (w - w.dot(n) * n).norm();
                if radial <= r * (1.0 + 1e-9) {
                    w.dot(n).abs()
                } else {
                    1e9
                }
            }),
            aim: (c - r, c + r),
            size: 2.0 * r,
            min_hit_share: 0.2,
        });
    }
    {
        let (c, n, r, inner) = (
            DVec3::new(-0.1, 0.2, 0.1),
            DVec3::new(0.3, 1.0, -0.5).unit(),
            1.1,
            0.45,
        );
        v.push(Case {
            name: "ring",
            shape: Shape::Ring {
                center: c,
                normal: n,
                radius: r,
                inner,
            },
            side: Box::new(move |q| (q - c).dot(n)),
            dist: Box::new(move |q| {
                let w = q - c;
                let radial = (w - w.dot(n) * n).norm();
                if radial <= r * (1.0 + 1e-9) && radial >= inner * (1.0 - 1e-9) {
                    w.dot(n).abs()
                } else {
                    1e9
                }
            }),
            aim: (c - r, c + r),
            size: 2.0 * r,
            min_hit_share: 0.15,
        });
    }
    for capped in [true, false] {
        let (b, t, r) = (DVec3::new(0.0, -1.0, 0.0), DVec3::new(0.5, 1.0, 0.2), 0.6);
        let side: Box<dyn Fn(DVec3) -> f64> = if capped {
            Box::new(move |q| {
                let (y, rad, h) = axial(q, b, t);
                let d = DVec2::new(rad - r, (y - 0.5 * h).abs() - 0.5 * h);
                d.max(DVec2::ZERO).norm() + d.max_element().min(0.0)
            })
        } else {
            Box::new(move |q| axial(q, b, t).1 - r)
        };
        let dist: Box<dyn Fn(DVec3) -> f64> = if capped {
            Box::new(move |q| {
                let (y, rad, h) = axial(q, b, t);
                let d = DVec2::new(rad - r, (y - 0.5 * h).abs() - 0.5 * h);
                (d.max(DVec2::ZERO).norm() + d.max_element().min(0.0)).abs()
            })
        } else {
            Box::new(move |q| {
                let (y, rad, h) = axial(q, b, t);
                if (-1e-9..=h + 1e-9).contains(&y) {
                    (rad - r).abs()
                } else {
                    1e9
                }
            })
        };
        v.push(Case {
            name: if capped {
                "cylinder (capped)"
            } else {
                "cylinder (open)"
            },
            shape: Shape::Cylinder {
                base: b,
                top: t,
                radius: r,
                capped,
            },
            side,
            dist,
            aim: (DVec3::new(-0.6, -1.0, -0.6), DVec3::new(1.1, 1.0, 0.8)),
            size: 2.5,
            min_hit_share: 0.3,
        });
    }
    for (name, r0, r1, capped) in [
        ("cone frustum (capped)", 1.0, 0.3, true),
        ("cone (capped, apex)", 0.8, 0.0, true),
        ("cone frustum (open)", 0.4, 0.9, false),
    ] {
        let (b, t) = (DVec3::new(0.2, -0.8, 0.1), DVec3::new(-0.3, 0.9, 0.4));
        let k = move |h: f64| (r1 - r0) / h;
        // Distance to the slanted side in the meridian half-plane, and to the caps.
        let parts = move |q: DVec3| {
            let (y, rad, h) = axial(q, b, t);
            let kk = k(h);
            let rho = r0 + kk * y;
            let side = (rad - rho) / (1.0 + kk * kk).sqrt();
            (y, rad, h, rho, side)
        };
        let side: Box<dyn Fn(DVec3) -> f64> = Box::new(move |q| {
            let (y, _, h, _, side) = parts(q);
            if capped {
                side.max(-y).max(y - h)
            } else {
                side
            }
        });
        let dist: Box<dyn Fn(DVec3) -> f64> = Box::new(move |q| {
            let (y, rad, h, _, side) = parts(q);
            let e = 1e-9;
            let mut d = if (-e..=h + e).contains(&y) {
                side.abs()
            } else {
                1e9
            };
            if capped {
                if rad <= r0 * (1.0 + e) + e {
                    d = d.min(y.abs());
                }
                if rad <= r1 * (1.0 + e) + e {
                    d = d.min((y - h).abs());
                }
            }
            d
        });
        v.push(Case {
            name,
            shape: Shape::Cone {
                base: b,
                top: t,
                base_radius: r0,
                top_radius: r1,
                capped,
            },
            side,
            dist,
            aim: (DVec3::new(-1.0, -0.8, -0.8), DVec3::new(1.0, 0.9, 1.2)),
            size: 2.5,
            min_hit_share: 0.2,
        });
    }
    {
        let (c, big, small) = (DVec3::new(0.1, 0.2, -0.3), 1.2, 0.4);
        let sdf = move |q: DVec3| {
            let p = q - c;
            DVec2::new(DVec2::new(p.x, p.z).norm() - big, p.y).norm() - small
        };
        v.push(Case {
            name: "torus",
            shape: Shape::Torus {
                center: c,
                major_radius: big,
                minor_radius: small,
                spindle: Default::default(),
            },
            side: Box::new(sdf),
            dist: Box::new(move |q| sdf(q).abs()),
            aim: (c - DVec3::new(1.6, 0.4, 1.6), c + DVec3::new(1.6, 0.4, 1.6)),
            size: 3.2,
            min_hit_share: 0.3,
        });
    }
    {
        let comps = vec![
            BlobComponent {
                center: DVec3::new(-0.5, 0.0, 0.0),
                radius: 1.0,
                strength: 1.0,
                end: None,
            },
            BlobComponent {
                center: DVec3::new(0.6, 0.1, 0.0),
                radius: 0.9,
                strength: 1.0,
                end: None,
            },
            BlobComponent {
                center: DVec3::new(0.0, 0.6, 0.2),
                radius: 0.5,
                strength: -0.8,
                end: None,
            },
        ];
        let threshold = 0.3;
        let cs = comps.clone();
        let field = move |q: DVec3| -> (f64, DVec3) {
            let mut f = 0.0;
            let mut g = DVec3::ZERO;
            for c in &cs {
                let w = q - c.center;
                let s = 1.0 - w.length_squared() / (c.radius * c.radius);
                if s > 0.0 {
                    f += c.strength * s * s;
                    g += c.strength * 2.0 * s * (-2.0 * w / (c.radius * c.radius));
                }
            }
            (f, g)
        };
        let f2 = field.clone();
        v.push(Case {
            name: "blob",
            shape: Shape::Blob {
                components: comps,
                threshold,
            },
            side: Box::new(move |q| threshold - field(q).0),
            dist: Box::new(move |q| {
                let (f, g) = f2(q);
                (f - threshold).abs() / g.norm().max(1e-300)
            }),
            aim: (DVec3::new(-1.5, -1.0, -1.0), DVec3::new(1.5, 1.1, 1.0)),
            size: 3.0,
            min_hit_share: 0.3,
        });
    }
    {
        // A blob of a slanted cylinder component (round ends) and a ball. The field is written
        // here from the segment distance: the nearest point of a segment a→b is
        // a + clamp((q − a)·(b − a) / |b − a|², 0, 1)·(b − a).
        let (a, b) = (DVec3::new(-0.8, -0.5, 0.1), DVec3::new(0.7, 0.6, -0.2));
        let (rc, ball, rb) = (0.6, DVec3::new(0.6, -0.5, 0.0), 0.7);
        let threshold = 0.4;
        let field = move |q: DVec3| -> (f64, DVec3) {
            let ab = b - a;
            let h = ((q - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
            let mut f = 0.0;
            let mut g = DVec3::ZERO;
            for (w, r) in [(q - (a + h * ab), rc), (q - ball, rb)] {
                let s = 1.0 - w.length_squared() / (r * r);
                if s > 0.0 {
                    f += s * s;
                    g += 2.0 * s * (-2.0 * w / (r * r));
                }
            }
            (f, g)
        };
        let f2 = field;
        v.push(Case {
            name: "blob with a cylinder component",
            shape: Shape::Blob {
                components: vec![
                    BlobComponent {
                        center: a,
                        radius: rc,
                        strength: 1.0,
                        end: Some(b),
                    },
                    BlobComponent {
                        center: ball,
                        radius: rb,
                        strength: 1.0,
                        end: None,
                    },
                ],
                threshold,
            },
            side: Box::new(move |q| threshold - field(q).0),
            dist: Box::new(move |q| {
                let (f, g) = f2(q);
                (f - threshold).abs() / g.norm().max(1e-300)
            }),
            aim: (DVec3::new(-1.4, -1.2, -0.8), DVec3::new(1.4, 1.2, 0.8)),
            size: 3.0,
            min_hit_share: 0.3,
        });
    }
    // Quadrics: the distance is |f| / |∇f| with f and ∇f written out here per surface.
    {
        // An ellipsoid with semi-axes 1.5, 0.8, 1.1 centred at (0.2, -0.1, 0.3).
        let (c, r) = (DVec3::new(0.2, -0.1, 0.3), DVec3::new(1.5, 0.8, 1.1));
        let f = move |q: DVec3| {
            let w = (q - c) / r;
            w.length_squared() - 1.0
        };
        let grad = move |q: DVec3| 2.0 * (q - c) / (r * r);
        let inv = 1.0 / (r * r);
        v.push(Case {
            name: "quadric ellipsoid",
            shape: Shape::Quadric {
                squares: inv,
                mixed: DVec3::ZERO,
                linear: -2.0 * c * inv,
                constant: (c * c * inv).element_sum() - 1.0,
            },
            side: Box::new(f),
            dist: Box::new(move |q| f(q).abs() / grad(q).norm()),
            aim: (c - r, c + r),
            size: 3.0,
            min_hit_share: 0.3,
        });
    }
    {
        // A hyperboloid of one sheet around y, tilted by a mixed xy term:
        // x² + z² − y² + 0.5·xy − 0.25 = 0.
        let f = |q: DVec3| q.x * q.x + q.z * q.z - q.y * q.y + 0.5 * q.x * q.y - 0.25;
        let grad = |q: DVec3| DVec3::new(2.0 * q.x + 0.5 * q.y, -2.0 * q.y + 0.5 * q.x, 2.0 * q.z);
        v.push(Case {
            name: "quadric hyperboloid",
            shape: Shape::Quadric {
                squares: DVec3::new(1.0, -1.0, 1.0),
                mixed: DVec3::new(0.5, 0.0, 0.0),
                linear: DVec3::ZERO,
                constant: -0.25,
            },
            side: Box::new(f),
            dist: Box::new(move |q| f(q).abs() / grad(q).norm()),
            aim: (DVec3::splat(-1.0), DVec3::splat(1.0)),
            size: 2.0,
            min_hit_share: 0.3,
        });
    }
    v
}

fn check(case: &Case, xf: DAffine3, seed: u64) {
    let w = world(vec![object(case.shape.clone(), xf)]);
    let inv = xf.inverse();
    let world_scale = case.size
        * xf.matrix3
            .x_axis
            .norm()
            .max(xf.matrix3.y_axis.norm())
            .max(xf.matrix3.z_axis.norm());
    let aim = rtc::geometry::Aabb::new(case.aim.0, case.aim.1).transformed(&xf);
    let bounds = w.bounds();
    let mut rng = Rng(seed);
    let mut hits = 0;
    for i in 0..RAYS {
        let ray = ray_at_box(&mut rng, aim.min, aim.max);
        let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        hits += 1;
        let ctx = format!("{} ray {i}: {ray:?} hit t = {}", case.name, h.t);
        let q = inv.transform_point3(h.point);
        let d = (case.dist)(q);
        assert!(d < 1e-9 * case.size, "{ctx}: off the surface by {d:e}");
        assert!(
            (h.normal.norm() - 1.0).abs() < 1e-12,
            "{ctx}: |n| = {}",
            h.normal.norm()
        );
        let eps = 1e-6 * world_scale;
        let out = (case.side)(inv.transform_point3(h.point + eps * h.normal));
        assert!(out > 0.0, "{ctx}: the normal points inward (side {out:e})");
        if bounds.is_finite() {
            assert!(
                bounds.contains(h.point, 1e-9 * world_scale),
                "{ctx}: outside the bounds {bounds:?}"
            );
        }
        // Leave the surface at least ~12° above its tangent plane.
        let dir = loop {
            let d = hemisphere(&mut rng, h.normal);
            if d.dot(h.normal) > 0.2 {
                break d;
            }
        };
        let again = Ray::new(h.point + 1e-7 * world_scale * h.normal, dir);
        if let Some(h2) = w.intersect(&again, 0.0, 1e-4 * world_scale) {
            panic!("{ctx}: re-hit its own surface at t = {:e}", h2.t);
        }
    }
    let share = hits as f64 / RAYS as f64;
    // A skewed placement fills less of its (world) aiming box.
    let want = case.min_hit_share * if xf == DAffine3::IDENTITY { 1.0 } else { 0.4 };
    assert!(share >= want, "{}: only {share} of rays hit", case.name);
}

#[test]
fn every_shape_keeps_its_invariants() {
    for (k, case) in cases().iter().enumerate() {
        check(case, DAffine3::IDENTITY, 1000 + k as u64);
    }
}

#[test]
fn every_shape_keeps_its_invariants_when_mirrored_and_skewed() {
    for (k, case) in cases().iter().enumerate() {
        check(case, mirrored_transform(), 2000 + k as u64);
    }
}
