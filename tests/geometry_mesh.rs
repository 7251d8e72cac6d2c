//! Meshes: watertightness at shared edges and vertices, invariants on random rays, smooth
//! normals, instancing, MTL materials, closed meshes in CSG.

mod geometry_support;

use rtc::num::Norm;
use std::fmt::Write as _;
use std::path::PathBuf;

use geometry_support::{Rng, hemisphere, object, ray_at_box, scene, world};
use glam::{DAffine3, DVec3, Vec3};
use rtc::geometry::Ray;
use rtc::ir::{CsgOp, MaterialId, Shape};

/// A fresh directory for this test's files.
fn tmp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("rtc-geom-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// A closed unit sphere: an octahedron subdivided `levels` times; returns the OBJ text and
/// the vertex positions exactly as an OBJ reader sees them (f32 parsed from the text).
fn sphere_obj(levels: u32) -> (String, Vec<Vec3>, Vec<[usize; 3]>) {
    let mut v: Vec<DVec3> = vec![
        DVec3::X,
        -DVec3::X,
        DVec3::Y,
        -DVec3::Y,
        DVec3::Z,
        -DVec3::Z,
    ];
    let mut f: Vec<[usize; 3]> = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    for _ in 0..levels {
        let mut mid = std::collections::HashMap::new();
        let mut next = Vec::new();
        for t in &f {
            let mut m = [0; 3];
            for k in 0..3 {
                let (a, b) = (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]));
                m[k] = *mid.entry((a, b)).or_insert_with(|| {
                    v.push((v[a] + v[b]).unit());
                    v.len() - 1
                });
            }
            next.extend([
                [t[0], m[0], m[2]],
                [m[0], t[1], m[1]],
                [m[2], m[1], t[2]],
                [m[0], m[1], m[2]],
            ]);
        }
        f = next;
    }
    let mut text = String::new();
    let mut exact = Vec::new();
    for p in &v {
        let s = [p.x, p.y, p.z].map(|c| format!("{c:.9}"));
        writeln!(text, "v {} {} {}", s[0], s[1], s[2]).unwrap();
        exact.push(Vec3::new(
            s[0].parse().unwrap(),
            s[1].parse().unwrap(),
            s[2].parse().unwrap(),
        ));
    }
    for t in &f {
        writeln!(text, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1).unwrap();
    }
    (text, exact, f)
}

fn mesh(path: PathBuf, smooth: bool) -> Shape {
    Shape::Mesh {
        source: rtc::ir::MeshSource::File(path),
        smooth,
        use_mtl: false,
    }
}

#[test]
fn rays_through_shared_edges_and_vertices_never_pass_through() {
    let dir = tmp_dir("watertight");
    let (text, verts, faces) = sphere_obj(3);
    let path = dir.join("sphere.obj");
    std::fs::write(&path, text).unwrap();
    let w = world(vec![object(mesh(path, false), DAffine3::IDENTITY)]);
    let mut targets: Vec<DVec3> = verts.iter().map(|p| p.as_dvec3()).collect();
    for t in &faces {
        for k in 0..3 {
            let (a, b) = (verts[t[k]], verts[t[(k + 1) % 3]]);
            // Points exactly on the edge as stored (f32 lerps at a few fractions).
            for s in [0.5f32, 0.25, 0.125] {
                targets.push((a + (b - a) * s).as_dvec3());
            }
        }
    }
    let mut rng = Rng(11);
    let mut rays = 0;
    for target in &targets {
        let inward = -target.unit();
        for _ in 0..4 {
            // From outside, steeply into the surface through the target (a ray that only
            // grazes a silhouette vertex may legitimately pass it by a rounding error).
            let d = loop {
                let d = rng.dir();
                if d.dot(inward) > 0.4 {
                    break d;
                }
            };
            let len = rng.range(2.0, 50.0);
            let origin = *target - len * d;
            let ray = Ray::new(origin, (*target - origin).unit());
            rays += 1;
            let h = w.intersect(&ray, 0.0, f64::INFINITY);
            let h = h.unwrap_or_else(|| panic!("ray {ray:?} aimed at {target} passed through"));
            assert!(
                (h.t - len).abs() < 1e-5 * len,
                "ray {ray:?} entered at {} not {len}",
                h.t
            );
            assert!(w.occluded(&ray, 0.0, 2.0 * len));
            // Shot from the centre outwards through the same point it must leave the sphere.
            let out = Ray::new(DVec3::ZERO, target.unit());
            assert!(
                w.intersect(&out, 0.0, f64::INFINITY).is_some(),
                "escaped through {target}"
            );
            assert!(w.occluded(&out, 0.0, 10.0));
        }
    }
    assert!(rays > 10_000, "{rays}");
}

#[test]
fn mesh_hits_keep_the_invariants() {
    let dir = tmp_dir("invariants");
    let (text, _, _) = sphere_obj(4);
    let path = dir.join("sphere.obj");
    std::fs::write(&path, text).unwrap();
    let xf = DAffine3::from_scale_rotation_translation(
        DVec3::new(2.0, -1.0, 0.5),
        glam::DQuat::from_rotation_y(0.7),
        DVec3::new(1.0, 2.0, 3.0),
    );
    for smooth in [false, true] {
        let w = world(vec![object(mesh(path.clone(), smooth), xf)]);
        let b = w.bounds();
        let inv = xf.inverse();
        let mut rng = Rng(3);
        let mut hits = 0;
        let mut err_shading = 0.0;
        let mut err_geometric = 0.0;
        for i in 0..10_000 {
            let ray = ray_at_box(&mut rng, b.min, b.max);
            let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            hits += 1;
            let q = inv.transform_point3(h.point);
            // The tessellated unit sphere lies between radius cos(half the edge angle) and 1.
            let r = q.norm();
            assert!(
                (0.99..=1.0 + 1e-5).contains(&r),
                "ray {i}: object-space radius {r}"
            );
            assert!(
                (h.normal.norm() - 1.0).abs() < 1e-6
                    && (h.geometric_normal.norm() - 1.0).abs() < 1e-12
            );
            let outward = (xf.matrix3.inverse().transpose() * q).unit();
            assert!(
                h.geometric_normal.dot(outward) > 0.9,
                "ray {i}: geometric normal inward"
            );
            assert!(b.contains(h.point, 1e-5), "ray {i}: outside bounds");
            if !smooth {
                assert_eq!(h.normal, h.geometric_normal);
            }
            err_shading += h.normal.angle_between(outward);
            err_geometric += h.geometric_normal.angle_between(outward);
            // Leaving along the normal does not re-hit the (convex) mesh.
            let again = Ray::new(h.point + 1e-4 * h.geometric_normal, h.geometric_normal);
            assert!(
                w.intersect(&again, 0.0, f64::INFINITY).is_none(),
                "ray {i}: re-hit"
            );
        }
        assert!(hits > 3_000, "{hits}");
        if smooth {
            // Interpolated normals follow the true sphere far better than the facets do.
            assert!(
                err_shading < 0.3 * err_geometric,
                "{err_shading} vs {err_geometric}"
            );
        }
    }
}

#[test]
fn one_file_placed_many_times_is_loaded_once() {
    let dir = tmp_dir("instancing");
    let (text, _, faces) = sphere_obj(2);
    let path = dir.join("ball.obj");
    std::fs::write(&path, text).unwrap();
    let objects = (0..5)
        .map(|i| {
            object(
                mesh(path.clone(), true),
                DAffine3::from_translation(DVec3::new(3.0 * i as f64, 0.0, 0.0)),
            )
        })
        .collect();
    let prepared = rtc::opt::prepare(&scene(objects)).expect("meshes load");
    let s = prepared.stats();
    let w = prepared.world();
    assert_eq!(s.meshes, 1);
    assert_eq!(s.unique_triangles, faces.len());
    assert_eq!(s.instanced_triangles, 5 * faces.len());
    assert_eq!(s.objects, 5);
    // Every instance is really there.
    for i in 0..5 {
        let ray = Ray::new(DVec3::new(3.0 * i as f64, 0.0, 10.0), -DVec3::Z);
        let h = w.intersect(&ray, 0.0, f64::INFINITY).expect("instance hit");
        assert_eq!(w.object(&h), i);
        assert!((h.t - 9.0).abs() < 1e-5);
    }
}

#[test]
fn mtl_materials_become_rtc_materials() {
    let path = PathBuf::from("tests/data/course/models/devilduk.obj");
    let sc = scene(vec![object(
        Shape::Mesh {
            source: rtc::ir::MeshSource::File(path),
            smooth: true,
            use_mtl: true,
        },
        DAffine3::IDENTITY,
    )]);
    // The material table: the scene's three, the fallback for objects that name none (id 3),
    // then the MTL materials.
    let p = rtc::opt::prepare(&sc).expect("duck loads");
    assert_eq!(p.stats().unique_triangles, 3712);
    let extra = &p.materials()[4..];
    assert!(extra.len() >= 3, "{}", extra.len());
    // "horns": Kd 1 0 0, Ks 0.5, Ns 60 (devilduk.mtl).
    let horns =
        |m: &rtc::ir::Material| m.color == DVec3::new(1.0, 0.0, 0.0) && m.ks == 0.5 && m.n == 60.0;
    assert!(extra.iter().any(horns));
    let w = p.world();
    let b = w.bounds();
    let mut rng = Rng(9);
    let mut from_mtl = 0;
    let mut seen: Vec<MaterialId> = Vec::new();
    for _ in 0..2_000 {
        let ray = ray_at_box(&mut rng, b.min, b.max);
        if let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) {
            assert!((h.material.0 as usize) < p.materials().len());
            assert!(h.material.0 >= 4, "use_mtl faces take their MTL material");
            from_mtl += 1;
            if !seen.contains(&h.material) {
                seen.push(h.material);
            }
        }
    }
    // Faces keep their own groups' materials: the red horns and at least one other.
    assert!(seen.iter().any(|&id| horns(p.material(id))), "{seen:?}");
    assert!(seen.len() >= 2, "{seen:?}");
    assert!(from_mtl > 100, "{from_mtl}");
}

#[test]
fn closed_mesh_works_in_csg() {
    // The course cube (unit cube, 12 triangles) minus a sphere, checked by point membership.
    let cube = object(
        mesh(PathBuf::from("tests/data/course/models/cube.obj"), false),
        DAffine3::IDENTITY,
    );
    let (c, r) = (DVec3::new(0.9, 0.8, 0.7), 0.5);
    let ball = object(
        Shape::Sphere {
            center: c,
            radius: r,
        },
        DAffine3::IDENTITY,
    );
    let node = object(
        Shape::Csg {
            op: CsgOp::Difference,
            children: vec![cube, ball],
        },
        DAffine3::IDENTITY,
    );
    let sc = scene(vec![node]);
    assert!(rtc::opt::validate(&sc).items.is_empty());
    let p = rtc::opt::prepare(&sc).unwrap();
    let w = p.world();
    let inside =
        |p: DVec3| p.cmpge(DVec3::ZERO).all() && p.cmple(DVec3::ONE).all() && (p - c).norm() > r;
    let mut rng = Rng(21);
    let mut cut = 0;
    for i in 0..5_000 {
        let ray = ray_at_box(&mut rng, DVec3::ZERO, DVec3::ONE);
        let mut t = 0.0;
        while let Some(h) = w.intersect(&ray, t, f64::INFINITY) {
            let d = 1e-4;
            assert!(
                inside(h.point - d * h.normal) && !inside(h.point + d * h.normal),
                "ray {i} t {}",
                h.t
            );
            if ((h.point - c).norm() - r).abs() < 1e-9 {
                cut += 1;
            }
            t = h.t + 1e-6;
        }
    }
    assert!(cut > 200, "{cut}");
}

/// Secondary rays leave a mesh hit as the renderer does (`SpawnPoint`: just outside the f64 error
/// bound of the hit point, far below the
/// f32 triangle test's rounding) and must not hit the surface they leave: on a convex mesh no
/// ray into the outer hemisphere may hit anything (shadow acne, caught in the bunny scene).
#[test]
fn rays_leaving_a_mesh_with_the_render_offset_do_not_rehit_it() {
    let dir = tmp_dir("acne");
    let (text, _, _) = sphere_obj(4);
    let path = dir.join("sphere.obj");
    std::fs::write(&path, text).unwrap();
    for (scale, offset) in [
        (1.0, DVec3::new(1.0, 2.0, 3.0)),
        (0.05, DVec3::new(0.1, -0.2, 0.0)),
    ] {
        let xf = DAffine3::from_scale_rotation_translation(
            DVec3::splat(scale),
            glam::DQuat::from_rotation_x(0.3),
            offset,
        );
        let w = world(vec![object(mesh(path.clone(), false), xf)]);
        let b = w.bounds();
        let mut rng = Rng(11);
        let mut tested = 0;
        for i in 0..10_000 {
            let ray = ray_at_box(&mut rng, b.min, b.max);
            let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            let n = h.geometric_normal;
            let d = hemisphere(&mut rng, n);
            if d.dot(n) < 0.05 {
                continue;
            }
            tested += 1;
            let out = rtc::render::offset::SpawnPoint::of(&h).ray(d);
            assert!(
                !w.occluded(&out, 0.0, f64::INFINITY),
                "ray {i}: self-shadowed"
            );
            assert!(
                w.intersect(&out, 0.0, f64::INFINITY).is_none(),
                "ray {i}: re-hit"
            );
        }
        assert!(tested > 2_000, "{tested}");
    }
}
