//! CSG against point membership: along every random ray, each boundary the world reports
//! must separate inside from outside (membership computed here, independently of the
//! library), every change of membership seen by dense sampling must be reported (all
//! intervals, not just the first), normals must point out of the result, cut faces carry
//! the cutter's material, and shadow rays agree with the hits.

mod geometry_support;

use geometry_support::{Rng, mirrored_transform, object, ray_at_box, world};
use glam::{DAffine3, DQuat, DVec2, DVec3};
use rtc::geometry::{Ray, World};
use rtc::ir::{CsgOp, MaterialId, Object, Shape, Spindle};
use rtc::num::Norm;

/// An independent model of a solid for membership tests.
#[derive(Clone)]
enum Solid {
    Sphere(DVec3, f64),
    Box(DVec3, DVec3),
    /// Capped cylinder along +Y from 0 to h, radius r.
    CylY(f64, f64),
    /// Torus about Y through the origin.
    Torus(f64, f64),
    /// Spindle torus (minor > major) about Y through the origin, with its mode.
    SpindleTorus(f64, f64, Spindle),
    /// Half-space below a plane through a point.
    Half(DVec3, DVec3),
    Placed(DAffine3, Box<Solid>),
    Csg(CsgOp, Vec<Solid>),
}

impl Solid {
    fn inside(&self, p: DVec3) -> bool {
        match self {
            Solid::Sphere(c, r) => (p - *c).length_squared() <= r * r,
            Solid::Box(lo, hi) => p.cmpge(*lo).all() && p.cmple(*hi).all(),
            Solid::CylY(h, r) => (0.0..=*h).contains(&p.y) && p.x * p.x + p.z * p.z <= r * r,
            Solid::Torus(big, small) => {
                DVec2::new(DVec2::new(p.x, p.z).norm() - big, p.y).norm() <= *small
            }
            Solid::SpindleTorus(big, small, mode) => {
                // Distances to the near and the far point of the centre circle.
                let ring = DVec2::new(p.x, p.z).norm();
                let apple = DVec2::new(ring - big, p.y).norm() <= *small;
                let lemon = DVec2::new(ring + big, p.y).norm() <= *small;
                match mode {
                    Spindle::Union | Spindle::Merge => apple,
                    Spindle::Intersection => lemon,
                    Spindle::Difference => apple && !lemon,
                }
            }
            Solid::Half(q, n) => (p - *q).dot(*n) <= 0.0,
            Solid::Placed(m, s) => s.inside(m.inverse().transform_point3(p)),
            Solid::Csg(op, c) => match op {
                CsgOp::Union | CsgOp::Merge => c.iter().any(|s| s.inside(p)),
                CsgOp::Intersection => c.iter().all(|s| s.inside(p)),
                CsgOp::Difference => c[0].inside(p) && !c[1..].iter().any(|s| s.inside(p)),
                CsgOp::Inverse => !c[0].inside(p),
                CsgOp::Clip => unreachable!("a clipped surface is not a solid"),
            },
        }
    }

    fn ir(&self) -> Object {
        self.ir_with(DAffine3::IDENTITY)
    }

    fn ir_with(&self, xf: DAffine3) -> Object {
        match self {
            Solid::Sphere(c, r) => object(
                Shape::Sphere {
                    center: *c,
                    radius: *r,
                },
                xf,
            ),
            Solid::Box(lo, hi) => object(Shape::Box { min: *lo, max: *hi }, xf),
            Solid::CylY(h, r) => object(
                Shape::Cylinder {
                    base: DVec3::ZERO,
                    top: DVec3::new(0.0, *h, 0.0),
                    radius: *r,
                    capped: true,
                },
                xf,
            ),
            Solid::Torus(big, small) => object(
                Shape::Torus {
                    center: DVec3::ZERO,
                    major_radius: *big,
                    minor_radius: *small,
                    spindle: Default::default(),
                },
                xf,
            ),
            Solid::SpindleTorus(big, small, mode) => object(
                Shape::Torus {
                    center: DVec3::ZERO,
                    major_radius: *big,
                    minor_radius: *small,
                    spindle: *mode,
                },
                xf,
            ),
            Solid::Half(q, n) => object(
                Shape::Plane {
                    point: *q,
                    normal: *n,
                },
                xf,
            ),
            Solid::Placed(m, s) => s.ir_with(xf * *m),
            Solid::Csg(op, c) => object(
                Shape::Csg {
                    op: *op,
                    children: c.iter().map(Solid::ir).collect(),
                },
                xf,
            ),
        }
    }
}

fn rot(x: f64, y: f64, z: f64, t: DVec3) -> DAffine3 {
    DAffine3::from_rotation_translation(DQuat::from_euler(glam::EulerRot::XYZ, x, y, z), t)
}

fn scenes() -> Vec<(&'static str, Solid)> {
    use Solid::*;
    let cyl = |m: DAffine3| Placed(m, std::boxed::Box::new(CylY(3.0, 0.7)));
    vec![
        (
            "box minus sphere",
            Csg(
                CsgOp::Difference,
                vec![
                    Box(DVec3::splat(-1.0), DVec3::splat(1.0)),
                    Sphere(DVec3::new(0.5, 0.6, 0.7), 0.9),
                ],
            ),
        ),
        (
            "three cylinders intersected",
            Csg(
                CsgOp::Intersection,
                vec![
                    cyl(DAffine3::from_translation(DVec3::new(0.0, -1.5, 0.0))),
                    cyl(rot(
                        std::f64::consts::FRAC_PI_2,
                        0.0,
                        0.0,
                        DVec3::new(0.0, 0.0, -1.5),
                    )),
                    cyl(rot(
                        0.0,
                        0.0,
                        std::f64::consts::FRAC_PI_2,
                        DVec3::new(1.5, 0.0, 0.0),
                    )),
                ],
            ),
        ),
        (
            "merge of sphere, box and torus",
            Csg(
                CsgOp::Merge,
                vec![
                    Sphere(DVec3::new(0.4, 0.0, 0.0), 0.8),
                    Box(DVec3::new(-1.0, -0.3, -0.3), DVec3::new(0.2, 0.3, 1.2)),
                    Torus(1.0, 0.25),
                ],
            ),
        ),
        (
            "nested and transformed",
            Placed(
                mirrored_transform(),
                std::boxed::Box::new(Csg(
                    CsgOp::Difference,
                    vec![
                        Csg(
                            CsgOp::Intersection,
                            vec![
                                Sphere(DVec3::ZERO, 1.2),
                                Box(DVec3::splat(-1.0), DVec3::splat(1.0)),
                            ],
                        ),
                        Csg(
                            CsgOp::Merge,
                            vec![
                                cyl(DAffine3::from_translation(DVec3::new(0.0, -1.5, 0.0))
                                    * DAffine3::from_scale(DVec3::new(0.5, 1.0, 0.5))),
                                Placed(
                                    rot(1.0, 0.2, 0.0, DVec3::new(0.2, 0.1, 0.0)),
                                    std::boxed::Box::new(Torus(0.9, 0.2)),
                                ),
                            ],
                        ),
                    ],
                )),
            ),
        ),
        (
            "sphere minus a half-space",
            Csg(
                CsgOp::Difference,
                vec![
                    Sphere(DVec3::ZERO, 1.0),
                    Half(DVec3::new(0.0, 0.3, 0.0), DVec3::new(0.3, -1.0, 0.2).unit()),
                ],
            ),
        ),
        (
            "box and an inverted sphere (a difference spelled with inverse)",
            Csg(
                CsgOp::Intersection,
                vec![
                    Box(DVec3::splat(-1.0), DVec3::splat(1.0)),
                    Csg(CsgOp::Inverse, vec![Sphere(DVec3::new(0.5, 0.6, 0.7), 0.9)]),
                ],
            ),
        ),
        (
            "an inverted merge, turned and cut by a sphere",
            Csg(
                CsgOp::Intersection,
                vec![
                    Sphere(DVec3::ZERO, 1.3),
                    Placed(
                        mirrored_transform(),
                        std::boxed::Box::new(Csg(
                            CsgOp::Inverse,
                            vec![Csg(
                                CsgOp::Merge,
                                vec![
                                    Box(DVec3::new(-0.4, -2.0, -0.4), DVec3::new(0.4, 2.0, 0.4)),
                                    Torus(0.9, 0.25),
                                ],
                            )],
                        )),
                    ),
                ],
            ),
        ),
        (
            "spindle tori of every mode, cut open by half-spaces",
            Csg(
                CsgOp::Union,
                [
                    Spindle::Union,
                    Spindle::Merge,
                    Spindle::Intersection,
                    Spindle::Difference,
                ]
                .into_iter()
                .enumerate()
                .map(|(k, mode)| {
                    Placed(
                        // Apart (3.2 > twice R + r): a union keeps the surfaces inside it.
                        rot(
                            0.3 * k as f64,
                            0.5,
                            0.1,
                            DVec3::new(3.2 * k as f64, 0.0, 0.0),
                        ),
                        std::boxed::Box::new(Csg(
                            CsgOp::Intersection,
                            vec![
                                SpindleTorus(0.5, 1.0, mode),
                                Half(DVec3::new(0.0, 0.0, 0.2), DVec3::new(0.1, 0.2, 1.0).unit()),
                            ],
                        )),
                    )
                })
                .collect(),
            ),
        ),
        (
            "intersection with a half-space",
            Csg(
                CsgOp::Intersection,
                vec![
                    Torus(1.0, 0.4),
                    Half(DVec3::ZERO, DVec3::new(0.0, 0.2, 1.0).unit()),
                ],
            ),
        ),
    ]
}

/// All boundary hits along the ray, in order.
fn all_hits(w: &World, ray: &Ray) -> Vec<rtc::geometry::SurfaceHit> {
    let mut out = Vec::new();
    let mut t = 0.0;
    while let Some(h) = w.intersect(ray, t, f64::INFINITY) {
        t = h.t + 1e-9;
        out.push(h);
        assert!(out.len() < 64, "runaway hits");
    }
    out
}

#[test]
fn csg_matches_point_membership_along_every_ray() {
    for (k, (name, solid)) in scenes().into_iter().enumerate() {
        let w = world(vec![solid.ir()]);
        let b = w.bounds();
        assert!(b.is_finite(), "{name}: bounds {b:?}");
        let scale = (b.max - b.min).norm();
        let mut rng = Rng(77 + k as u64);
        let mut transitions = 0;
        for i in 0..2_000 {
            let ray = ray_at_box(&mut rng, b.min, b.max);
            let hits = all_hits(&w, &ray);
            let at = |t: f64| solid.inside(ray.at(t));
            // Every reported boundary separates inside from outside, with an outward normal.
            let d = 1e-7 * scale;
            for h in &hits {
                let ctx = format!("{name} ray {i} {ray:?} t {}", h.t);
                assert!(at(h.t - d) != at(h.t + d), "{ctx}: not a boundary");
                assert!(
                    !solid.inside(h.point + d * h.normal) && solid.inside(h.point - d * h.normal),
                    "{ctx}: normal not outward"
                );
                assert!((h.normal.norm() - 1.0).abs() < 1e-12);
            }
            // Every membership change seen by dense sampling is reported.
            let far = (ray.origin - b.center()).norm() + scale;
            let n = 3_000;
            let step = far / n as f64;
            let mut prev = at(0.0);
            for s in 1..=n {
                let t = s as f64 * step;
                let now = at(t);
                if now != prev {
                    transitions += 1;
                    assert!(
                        hits.iter()
                            .any(|h| h.t > t - step - 1e-9 && h.t <= t + 1e-9),
                        "{name} ray {i} {ray:?}: membership changes in ({}, {t}] but no hit there: {:?}",
                        t - step,
                        hits.iter().map(|h| h.t).collect::<Vec<_>>()
                    );
                }
                prev = now;
            }
            // Shadow rays agree with the nearest hit.
            let first = hits.first().map(|h| h.t);
            assert_eq!(
                w.occluded(&ray, 0.0, far),
                first.is_some(),
                "{name} ray {i}"
            );
            if let Some(t) = first {
                assert!(
                    !w.occluded(&ray, 0.0, t * (1.0 - 1e-9)),
                    "{name} ray {i}: shadow hit before the first hit"
                );
            }
        }
        assert!(
            transitions > 500,
            "{name}: only {transitions} transitions; the test is not exercising it"
        );
    }
}

#[test]
fn cut_faces_take_the_cutters_material() {
    let mut cutter = object(
        Shape::Sphere {
            center: DVec3::new(0.5, 0.6, 0.7),
            radius: 0.9,
        },
        DAffine3::IDENTITY,
    );
    cutter.material = Some(MaterialId(1));
    let mut base = object(
        Shape::Box {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        },
        DAffine3::IDENTITY,
    );
    base.material = None;
    let mut node = object(
        Shape::Csg {
            op: CsgOp::Difference,
            children: vec![base, cutter],
        },
        DAffine3::IDENTITY,
    );
    node.material = Some(MaterialId(2));
    let w = world(vec![node]);
    let mut rng = Rng(5);
    let (mut cut, mut outer) = (0, 0);
    for _ in 0..5_000 {
        let ray = ray_at_box(&mut rng, DVec3::splat(-1.0), DVec3::splat(1.0));
        if let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) {
            let on_sphere = ((h.point - DVec3::new(0.5, 0.6, 0.7)).norm() - 0.9).abs() < 1e-9;
            if on_sphere {
                cut += 1;
                assert_eq!(h.material, MaterialId(1), "cut face");
                // The cut face's normal points into the sphere's hollow.
                assert!(h.normal.dot(DVec3::new(0.5, 0.6, 0.7) - h.point) > 0.0);
            } else {
                outer += 1;
                assert_eq!(
                    h.material,
                    MaterialId(2),
                    "the base inherits the CSG node's material"
                );
            }
        }
    }
    assert!(cut > 100 && outer > 100, "{cut} {outer}");
}

#[test]
fn union_keeps_inner_surfaces_and_merge_removes_them() {
    let spheres = |op| {
        object(
            Shape::Csg {
                op,
                children: vec![
                    object(
                        Shape::Sphere {
                            center: DVec3::new(-0.5, 0.0, 0.0),
                            radius: 1.0,
                        },
                        DAffine3::IDENTITY,
                    ),
                    object(
                        Shape::Sphere {
                            center: DVec3::new(0.5, 0.0, 0.0),
                            radius: 1.0,
                        },
                        DAffine3::IDENTITY,
                    ),
                ],
            },
            DAffine3::IDENTITY,
        )
    };
    let ray = Ray::new(DVec3::new(-5.0, 0.1, 0.0), DVec3::X);
    let ts = |op| {
        all_hits(&world(vec![spheres(op)]), &ray)
            .iter()
            .map(|h| h.t)
            .collect::<Vec<_>>()
    };
    assert_eq!(ts(CsgOp::Union).len(), 4);
    let merged = ts(CsgOp::Merge);
    assert_eq!(merged.len(), 2);
    let x0 = -0.5 - (1.0f64 - 0.01).sqrt();
    assert!((merged[0] - (x0 + 5.0)).abs() < 1e-12);
}

#[test]
fn empty_intersection_is_never_hit_and_has_empty_bounds() {
    let node = object(
        Shape::Csg {
            op: CsgOp::Intersection,
            children: vec![
                object(
                    Shape::Sphere {
                        center: DVec3::new(-3.0, 0.0, 0.0),
                        radius: 1.0,
                    },
                    DAffine3::IDENTITY,
                ),
                object(
                    Shape::Sphere {
                        center: DVec3::new(3.0, 0.0, 0.0),
                        radius: 1.0,
                    },
                    DAffine3::IDENTITY,
                ),
            ],
        },
        DAffine3::IDENTITY,
    );
    let w = world(vec![node]);
    assert!(w.bounds().is_empty());
    let ray = Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X);
    assert!(w.intersect(&ray, 0.0, f64::INFINITY).is_none());
}

/// A clipped surface (`clipped_by`) against its definition, written here: the hits along a ray
/// are the hits of the surface (a sphere, both roots of its quadratic) whose points lie inside
/// the clipper (a turned box, membership by `Solid::inside`), in order; nothing else. The
/// clipper's own faces never show, and the cut is left open (a ray through the opening meets
/// the far wall from inside).
#[test]
fn a_clipped_surface_is_its_surface_inside_the_clipper() {
    let (c, r) = (DVec3::new(0.1, -0.2, 0.05), 1.0);
    let clipper = Solid::Placed(
        rot(0.5, 0.3, -0.2, DVec3::new(0.0, 0.3, 0.0)),
        std::boxed::Box::new(Solid::Box(
            DVec3::new(-2.0, -2.0, -2.0),
            DVec3::new(2.0, 0.2, 2.0),
        )),
    );
    let sphere = Solid::Sphere(c, r).ir();
    let clipped = object(
        Shape::Csg {
            op: CsgOp::Clip,
            children: vec![sphere, clipper.ir()],
        },
        mirrored_transform(),
    );
    let w = world(vec![clipped]);
    let b = w.bounds();
    assert!(b.is_finite(), "bounds {b:?}");
    let to_local = mirrored_transform().inverse();
    let mut rng = Rng(4242);
    let (mut through_opening, mut clipped_away) = (0, 0);
    for i in 0..5_000 {
        let ray = ray_at_box(&mut rng, b.min - 0.3, b.max + 0.3);
        // The sphere's roots, in world t (the transform keeps t).
        let o = to_local.transform_point3(ray.origin);
        let d = to_local.transform_vector3(ray.dir);
        let oc = o - c;
        let (qa, qb, qc) = (d.dot(d), 2.0 * oc.dot(d), oc.dot(oc) - r * r);
        let disc = qb * qb - 4.0 * qa * qc;
        let mut want = Vec::new();
        let mut near_a_face = false;
        if disc > 0.0 {
            for t in [
                (-qb - disc.sqrt()) / (2.0 * qa),
                (-qb + disc.sqrt()) / (2.0 * qa),
            ] {
                let p = o + t * d;
                // Points within rounding of the clipper's faces may go either way: skip the ray.
                let margin = DVec3::splat(1e-7);
                near_a_face |= clipper.inside(p + margin) != clipper.inside(p - margin);
                if t <= 1e-9 {
                    continue;
                }
                if clipper.inside(p) {
                    want.push(t);
                } else {
                    clipped_away += 1;
                }
            }
        }
        if near_a_face {
            continue;
        }
        let got: Vec<f64> = all_hits(&w, &ray).iter().map(|h| h.t).collect();
        assert_eq!(
            got.len(),
            want.len(),
            "ray {i} {ray:?}: hits {got:?}, want {want:?}"
        );
        for (g, x) in got.iter().zip(&want) {
            assert!(
                (g - x).abs() <= 1e-9 * (1.0 + x.abs()),
                "ray {i}: t {g} vs {x}"
            );
        }
        // One root kept of two: the ray passes the open cut.
        if disc > 0.0 && want.len() == 1 {
            through_opening += 1;
        }
    }
    assert!(
        through_opening > 200 && clipped_away > 200,
        "the rays do not exercise the cut: {through_opening} through the opening, {clipped_away} clipped roots"
    );
}
