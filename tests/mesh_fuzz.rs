//! The OBJ/MTL loader never panics: random edits of a course model and its material library,
//! written to a temporary directory (meshes load by path), come back as a mesh or a `MeshError`,
//! and a loaded mesh answers rays. The coverage-guided fuzzer in fuzz/ does this at scale; this
//! is the short version that runs in CI.

mod geometry_support;

use rtc::num::Norm;
use std::path::PathBuf;

use glam::DVec3;
use proptest::prelude::*;
use rtc::assets::MeshAsset;
use rtc::geometry::Ray;

mod fuzz_support;
use fuzz_support::splice;

const CUBE: &str = include_str!("data/course/models/cube.obj");
const DUCK_MTL: &str = include_str!("data/course/models/devilduk.mtl");

/// A directory of this test process's own.
fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-mesh-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("create a temporary directory");
    dir
}

/// Writes `obj` (after an `mtllib` line naming `mtl`) and loads it; `case` names the files, one
/// per test, since the tests of this file run in parallel threads.
fn load_and_trace(obj: &str, mtl: &str, smooth: bool, case: u32) {
    let dir = scratch();
    let path = dir.join(format!("m{case}.obj"));
    std::fs::write(&path, format!("mtllib m{case}.mtl\nusemtl bill\n{obj}")).expect("write");
    std::fs::write(dir.join(format!("m{case}.mtl")), mtl).expect("write");
    if let Ok(asset) = MeshAsset::load(&path, smooth) {
        let mesh = geometry_support::mesh_of(&asset);
        let b = mesh.bounds();
        let centre = 0.5 * (b.min + b.max);
        for dir in [DVec3::X, DVec3::NEG_Y, DVec3::new(0.3, 0.5, -0.8).unit()] {
            let ray = Ray::new(centre - 10.0 * dir, dir);
            if let Some(h) = mesh.intersect(&ray, 0.0, f64::INFINITY) {
                let finite = h.geometric.is_finite() && h.shading.is_finite();
                assert!(h.t >= 0.0 && finite, "{h:?}");
            }
        }
        let _ = asset.is_closed();
    }
}

const PIECES: &str = r"(?s)[ \t\r\n/#\-.0-9eE+a-zA-Z\\]{0,12}";

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn obj_loader_survives_edits_of_the_cube(
        at in 0usize..700, len in 0usize..20, with in PIECES, smooth in any::<bool>()
    ) {
        load_and_trace(&splice(CUBE, at, len, &with), DUCK_MTL, smooth, 1);
    }

    #[test]
    fn mtl_loader_survives_edits(at in 0usize..400, len in 0usize..20, with in PIECES) {
        load_and_trace(CUBE, &splice(DUCK_MTL, at, len, &with), true, 2);
    }

    #[test]
    fn obj_loader_never_panics_on_text(text in "(?s).{0,200}", smooth in any::<bool>()) {
        load_and_trace(&text, "", smooth, 3);
    }
}
