//! The world's batch queries (`World::intersect_batch_after`, `World::occluded_batch_among`)
//! give every ray exactly the one-ray answer: the course's duck mesh placed twice (once
//! mirrored and skewed) with a plane beside it (loose objects), then with spheres under the
//! world's BVH, camera-like packets through it and shadow-like packets from its hit points
//! towards a light.

mod geometry_support;

use rtc::num::Norm;
use std::path::PathBuf;

use geometry_support::{Rng, mirrored_transform, object, world};
use glam::{DAffine3, DVec3};
use rtc::geometry::lanes::cull::Bundle;
use rtc::geometry::world::SphereHit;
use rtc::geometry::{Ray, SurfaceHit, World};
use rtc::ir::Shape;

fn duck() -> Shape {
    Shape::Mesh {
        source: rtc::ir::MeshSource::File(
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/models/devilduk.obj"),
        ),
        smooth: true,
        use_mtl: false,
    }
}

fn scene_world(with_spheres: bool) -> World {
    let mut objects = vec![
        object(duck(), DAffine3::from_scale(DVec3::splat(4.0))),
        object(duck(), mirrored_transform()),
        object(
            Shape::Plane {
                point: DVec3::new(0.0, -0.5, 0.0),
                normal: DVec3::Y,
            },
            DAffine3::IDENTITY,
        ),
    ];
    // With twelve spheres the bounded objects go under the world's BVH (no packets there).
    if with_spheres {
        for k in 0..12 {
            let center = DVec3::new(k as f64 * 0.3 - 1.8, 0.8 + (k % 3) as f64 * 0.3, 0.5);
            objects.push(object(
                Shape::Sphere {
                    center,
                    radius: 0.3,
                },
                DAffine3::IDENTITY,
            ));
        }
    }
    world(objects)
}

fn bits(h: &Option<SurfaceHit>) -> Option<Vec<u64>> {
    h.map(|h| {
        [
            h.t, h.point.x, h.point.y, h.point.z, h.normal.x, h.normal.y, h.normal.z,
        ]
        .into_iter()
        .chain([h.geometric_normal.x, h.error.x, h.error.y, h.uv.x, h.uv.y])
        .map(f64::to_bits)
        .chain([u64::from(h.material.0), u64::from(h.surface.0)])
        .collect()
    })
}

#[test]
fn batches_match_single_rays_bit_for_bit() {
    let mut rng = Rng(2024);
    for with_spheres in [false, true] {
        let w = scene_world(with_spheres);
        let mut hits_seen = 0;
        for k in 0..400 {
            let eye = DVec3::new(
                rng.range(-3.0, 3.0),
                rng.range(0.5, 3.0),
                rng.range(4.0, 8.0),
            );
            let aim = DVec3::new(rng.range(-1.5, 1.5), rng.range(0.0, 2.0), 0.0);
            let spread = [1e-3, 1e-2, 0.3][k % 3];
            let n = [9, 16, 5, 1][k % 4];
            let rays: Vec<Ray> = (0..n)
                .map(|_| {
                    let target = aim + DVec3::new(rng.f() - 0.5, rng.f() - 0.5, 0.0) * spread;
                    Ray::new(eye, (target - eye).unit())
                })
                .collect();
            let mut bundle = Bundle::new();
            for r in &rays {
                bundle.push(r, f64::INFINITY);
            }
            let among = w.among(&bundle);
            let first: Vec<SphereHit> = rays
                .iter()
                .map(|r| w.nearest_sphere(r, 0.0, f64::INFINITY, among))
                .collect();
            let mut got = vec![None; n];
            w.intersect_batch_after(&rays, 0.0, f64::INFINITY, &first, &mut got);
            let light = DVec3::new(rng.range(-5.0, 5.0), 8.0, rng.range(-2.0, 6.0));
            let mut shadow = Vec::new();
            let mut limit = Vec::new();
            for (i, r) in rays.iter().enumerate() {
                let want = w.intersect_after(r, 0.0, f64::INFINITY, first[i]);
                assert_eq!(bits(&got[i]), bits(&want), "packet {k} ray {i}");
                if let Some(h) = want {
                    hits_seen += 1;
                    let p = h.surface_point + h.geometric_normal * 1e-4;
                    shadow.push(Ray::new(p, (light - p).unit()));
                    limit.push((light - p).norm() * if rng.f() < 0.2 { rng.f() } else { 1.0 });
                }
            }
            let mut bundle = Bundle::new();
            for (r, &t) in shadow.iter().zip(&limit) {
                bundle.push(r, t);
            }
            let among = w.among(&bundle);
            let mut occluded = vec![false; shadow.len()];
            w.occluded_batch_among(&shadow, 0.0, &limit, among, &mut occluded);
            for (i, r) in shadow.iter().enumerate() {
                let want = w.occluded_among(r, 0.0, limit[i], among);
                assert_eq!(occluded[i], want, "packet {k} shadow ray {i}");
            }
        }
        assert!(hits_seen > 1000, "{hits_seen} hits");
    }
}

/// More rays than one packet holds are traced in several.
#[test]
fn long_batches_are_split_into_packets() {
    let w = scene_world(false);
    let eye = DVec3::new(0.0, 1.0, 6.0);
    let rays: Vec<Ray> = (0..40)
        .map(|k| {
            let target = DVec3::new(k as f64 * 0.02 - 0.4, 0.5, 0.0);
            Ray::new(eye, (target - eye).unit())
        })
        .collect();
    let first = vec![SphereHit::default(); rays.len()];
    let mut got = vec![None; rays.len()];
    w.intersect_batch_after(&rays, 0.0, f64::INFINITY, &first, &mut got);
    for (r, g) in rays.iter().zip(&got) {
        assert_eq!(bits(g), bits(&w.intersect(r, 0.0, f64::INFINITY)));
    }
    assert!(got.iter().filter(|h| h.is_some()).count() > 10);
}
