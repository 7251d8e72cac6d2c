//! The texture fuzz target's work, and the one-object scene it shares with the mesh target.

use std::path::Path;

use glam::{DAffine3, DVec3};
use rtc::ir::{
    Bump, Camera, Light, LightKind, Mapping, Material, Object, Projection, RenderSettings, Scene,
    Shape, Texture,
};

/// Most pixels an input image may claim in its header for the fuzzer to decode it: 2²⁰, a
/// 24 MiB texture. rtc's own budget is 2²⁶ (`ir::limits::MAX_TEXTURE_PIXELS`, 1.5 GiB of texels,
/// tested in `tests/budgets.rs`): a 358-byte JPEG claiming 65296×255 pixels decodes (the missing
/// data is filled in) to 400 MB in 3 s, and 2²⁶ pixels would pass the fuzzer's 2 GB limit; both are
/// within rtc's budget, so the fuzzer clamps the size as `later_stages` clamps the render.
const MAX_FUZZ_PIXELS: u64 = 1 << 20;

/// Renders a sphere textured and bump-mapped by the image at `path`, under every mapping.
pub fn exercise(path: &Path) {
    // Headers that do not parse go on: reporting them is the loader's job under test.
    if let Ok((w, h)) = image::ImageReader::open(path).and_then(|r| {
        r.into_dimensions()
            .map_err(|e| std::io::Error::other(e.to_string()))
    }) && u64::from(w) * u64::from(h) > MAX_FUZZ_PIXELS
    {
        return;
    }
    // The asset cache knows a file by (path, size, modification time). It keeps only the newest
    // version of a path now (the first texture run, when it kept every version, stopped out of
    // memory at 92,832 inputs), but two inputs of one size written within one tick of the
    // file-system clock look like the same version: without this, an input could be rendered
    // with the previous input's image.
    rtc::assets::clear_cache();
    for mapping in [
        Mapping::Uv,
        Mapping::Spherical,
        Mapping::Planar,
        Mapping::Cylindrical,
    ] {
        let mut scene = one_object_scene(Object {
            shape: Shape::Sphere {
                center: DVec3::ZERO,
                radius: 1.0,
            },
            transform: DAffine3::IDENTITY.into(),
            material: None,
            motion: None,
            span: Default::default(),
            visibility: Default::default(),
        });
        let tex = scene.add_texture(Texture::Image {
            path: path.to_path_buf(),
            mapping,
            filter: Default::default(),
            span: Default::default(),
        });
        let mat = scene.add_material(Material {
            texture: Some(tex),
            bump: Some(Bump {
                texture: tex,
                scale: 0.5,
            }),
            ..Material::default()
        });
        scene.objects[0].material = Some(mat);
        crate::later_stages(scene, &crate::synthetic_sources());
    }
}

/// A scene with `object`, a point light and a camera 5 units away on +z looking at the origin.
pub fn one_object_scene(object: Object) -> Scene {
    Scene {
        camera: Camera {
            eye: DVec3::new(0.0, 0.0, 5.0),
            center: DVec3::ZERO,
            up: DVec3::Y,
            width: 4,
            height: 4,
            projection: Projection::Perspective { fov_y: 0.8 },
            aperture: 0.0,
            focus_distance: 0.0,
            shutter: None,
            motion: None,
            span: Default::default(),
        },
        lights: vec![Light::new(
            LightKind::Point {
                position: DVec3::new(3.0, 4.0, 5.0),
            },
            DVec3::ONE,
            Default::default(),
        )],
        materials: vec![Material::default()],
        textures: Vec::new(),
        objects: vec![object],
        settings: RenderSettings {
            shadows: true,
            ..RenderSettings::default()
        },
        memory: Default::default(),
    }
}
