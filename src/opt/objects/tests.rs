//! Which spheres the preparation stage keeps as compact balls, and that a translated ball
//! renders the image of the primitive it replaces bit for bit.

use std::path::Path;

use super::Builder;
use crate::geometry::World;
use crate::geometry::world::balls::WorldParts;
use crate::ir::{MaterialId, Object, Scene};
use crate::opt::{Prepared, expected_rays, material_table, prepare};
use crate::render::{Image, RenderOptions, Silent, render};
use crate::source::SourceMap;

/// The scene `body` describes (after a camera, a light and render settings).
fn scene(body: &str) -> Scene {
    let text = format!(
        "rtc 1\ncamera {{ eye: [0, 3, 9], center: [0, 0, 0], fov: 50deg, resolution: [64, 48] }}\n\
         point_light {{ position: [4, 8, 6] }}\nrender {{ shadows: true, max_depth: 2 }}\n{body}\n"
    );
    let loaded = crate::eval::load_source(
        Path::new("lean.rtc"),
        text,
        &mut SourceMap::new(),
        &crate::eval::EvalOptions::default(),
    );
    loaded.scene.expect("the scene evaluates")
}

/// `Some(translated)` for an object the builder keeps as a ball, `None` for a primitive.
fn balls(body: &str) -> Vec<Option<bool>> {
    let s = scene(body);
    let b = Builder::new(s.materials.len() as u32, 0, s.memory);
    let ball = |(i, o): (usize, &Object)| {
        b.ball(o, MaterialId(0), i as u32)
            .map(|b| b.is_translated())
    };
    s.objects.iter().enumerate().map(ball).collect()
}

/// Issue 42 item 4's rule: a sphere about its own origin that is only translated (however
/// the translations are written) becomes a translated ball; a sphere with no transform a plain
/// one; a scale (uniform or not), a rotation, a translated sphere whose centre is elsewhere,
/// and any motion stay primitives.
#[test]
fn only_untransformed_and_translated_spheres_become_balls() {
    let kept = balls(
        "sphere(radius: 0.4)\n\
         sphere(center: [1, 2, 3], radius: 0.4)\n\
         sphere(radius: 0.4).translate([1, 2, 3])\n\
         sphere(radius: 0.4).translate([1, 0, 0]).translate([0, 2, 0])\n\
         sphere(radius: 0.4).transform(translate([1, 2, 3]))\n\
         sphere(radius: 0.4).translate([0, 0, 0])\n\
         sphere(center: [1, 0, 0], radius: 0.4).translate([0, 1, 0])\n\
         sphere(radius: 0.4).scale(2).translate([1, 2, 3])\n\
         sphere(radius: 0.4).scale([1, 2, 1])\n\
         sphere(radius: 0.4).rotate(y: 30deg).translate([1, 2, 3])\n\
         sphere(radius: 0.4).translate([1, 2, 3]).moving(translate: [1, 0, 0])\n\
         box().translate([1, 2, 3])",
    );
    let want = [
        Some(false),
        Some(false),
        Some(true),
        Some(true),
        Some(true),
        Some(false),
        None,
        None,
        None,
        None,
        None,
        None,
    ];
    assert_eq!(kept, want);
}

/// A world holding `scene`'s objects as primitives only (what the preparation made of every
/// object before translated spheres became balls).
fn primitives_only(scene: &Scene, lights: &[crate::opt::PreparedLight]) -> World {
    let (materials, fallback) = material_table(scene);
    let mut b = Builder::new(materials.len() as u32, 0, scene.memory);
    let mut parts = WorldParts::default();
    for (i, o) in scene.objects.iter().enumerate() {
        let p = b.object(o, fallback).expect("the object prepares");
        parts.nodes.push(p);
        parts.object_of.push(i as u32);
    }
    World::new(parts, expected_rays(scene, lights))
}

/// The 8-bit image of `p`.
fn image(p: &Prepared) -> Image {
    let film = render(p, &RenderOptions::default(), &Silent).expect("renders");
    film.to_image()
}

/// The same scene rendered with its translated spheres as balls and as primitives: the same
/// bytes, with solid and spherical textures read in object space, reflections, shadows, a
/// floor outside the BVH and enough spheres for one (`count`), or so few that all are loose.
#[test]
fn translated_balls_render_the_primitives_image_bit_for_bit() {
    for count in [3, 40] {
        let body = format!(
            "let tex = material {{ texture: checker(size: 0.15), reflect: 0.3 }}\n\
             let ring = material {{ texture: stripes(size: 0.1).warp(\"spherical\"), ks: 0.5, n: 20 }}\n\
             plane(normal: Y).translate([0, -1, 0])\n\
             for i in 0..{count} {{\n\
               sphere(radius: 0.3 + 0.01 * i)\n\
                 .material(if i % 2 == 0 {{ tex }} else {{ ring }})\n\
                 .translate([(i % 7) * 0.8 - 2.4, (i % 3) * 0.5 - 0.5, -(i / 7) * 0.9])\n\
             }}"
        );
        let scene = scene(&body);
        let mut folded = prepare(&scene).expect("the scene prepares");
        let with_balls = image(&folded);
        let e = folded.effects();
        let need_uv = e.textures || e.bump || e.hatching || scene.settings.mode.reads_uv();
        let primitive_bytes = {
            let mut w = primitives_only(&scene, &folded.lights);
            w.need_uv(need_uv);
            let bytes = w.stats().memory_bytes;
            folded.world = w;
            bytes
        };
        assert!(
            folded.stats.memory_bytes < primitive_bytes,
            "{count} spheres: balls {} B, primitives {primitive_bytes} B",
            folded.stats.memory_bytes
        );
        assert!(
            with_balls == image(&folded),
            "{count} spheres: the images differ"
        );
    }
}
