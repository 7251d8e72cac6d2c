//! Degenerate inputs build deep BVHs (the same box many times cannot be split), and rtc handles
//! any depth (its traversal stack spills to the heap). obvhs's own build helper asserts a depth
//! below 96 in debug builds, the size of its traversal stack: the obj_mtl fuzzer found a
//! 10 kB OBJ repeating cube faces that made `rtc` panic in debug and test builds
//! (`fuzz/found/obj_mtl-3-deep-bvh`, replayed here).

mod geometry_support;

use geometry_support::{mesh_of, object, world};
use glam::{DAffine3, DVec3};
use rtc::assets::MeshAsset;
use rtc::geometry::Ray;
use rtc::ir::Shape;

#[test]
fn a_mesh_of_one_triangle_repeated_loads_and_is_hit() {
    let dir = std::env::temp_dir().join(format!("rtc-bvh-degenerate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("same.obj");
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    obj.push_str(&"f 1 2 3\n".repeat(400));
    std::fs::write(&path, obj).expect("write");
    let mesh = mesh_of(&MeshAsset::load(&path, false).expect("loads"));
    assert_eq!(mesh.triangle_count(), 400);
    let down = Ray::new(DVec3::new(0.25, 0.25, 1.0), -DVec3::Z);
    let hit = mesh.intersect(&down, 0.0, f64::INFINITY).expect("hit");
    assert!((hit.t - 1.0).abs() < 1e-6, "{}", hit.t);
    let mut all = Vec::new();
    mesh.all_hits(&down, &mut all);
    assert_eq!(all.len(), 400, "every copy is crossed");
}

#[test]
fn a_world_of_one_sphere_repeated_is_hit() {
    let ball = || {
        object(
            Shape::Sphere {
                center: DVec3::ZERO,
                radius: 1.0,
            },
            DAffine3::from_translation(DVec3::new(0.5, 0.0, 0.0)),
        )
    };
    let w = world((0..400).map(|_| ball()).collect());
    let ray = Ray::new(DVec3::new(0.5, 0.0, 5.0), -DVec3::Z);
    let hit = w.intersect(&ray, 0.0, f64::INFINITY).expect("hit");
    assert!((hit.t - 4.0).abs() < 1e-9, "{}", hit.t);
}

#[test]
fn the_obj_the_fuzzer_found_loads_and_is_hit() {
    // The fuzz input: one flag byte (0: flat, no MTL), the OBJ, a NUL, then the MTL text.
    let input = include_bytes!("../fuzz/found/obj_mtl-3-deep-bvh");
    let end = input
        .iter()
        .skip(1)
        .position(|&b| b == 0)
        .map_or(input.len(), |i| i + 1);
    let dir = std::env::temp_dir().join(format!("rtc-bvh-fuzzed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("cubes.obj");
    std::fs::write(&path, &input[1..end]).expect("write");
    let asset = MeshAsset::load(&path, false).expect("loads");
    let mesh = mesh_of(&asset);
    let b = mesh.bounds();
    let centre = 0.5 * (b.min + b.max);
    let ray = Ray::new(centre + DVec3::new(0.0, 0.0, 10.0), -DVec3::Z);
    assert!(mesh.intersect(&ray, 0.0, f64::INFINITY).is_some());
}
