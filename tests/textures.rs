//! Procedural textures from the language (issue 36): colour maps, modifiers, textures that
//! follow their objects (transform, group, CSG, motion), material maps and layers. Scenes are
//! flat-lit (ka 1, kd 0, ks 0 under one white light: a pixel is the surface's colour), seen
//! almost orthographically so that pixel (i, j) looks at the plane z = 0 at world
//! (i + 0.5 − W/2, H/2 − j − 0.5); every expected colour is computed here from the pattern's
//! definition (docs/textures.md), never read from a render.

use std::path::Path;

use glam::DVec3;
use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::num::Norm;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

const W: u32 = 80;
const H: u32 = 40;

fn load(src: &str) -> Result<Scene, String> {
    let mut sources = SourceMap::default();
    let text = format!("rtc 1.1\n{src}");
    let loaded = load_source(
        Path::new("test.rtc"),
        &text,
        &mut sources,
        &EvalOptions::default(),
    );
    loaded.scene.ok_or_else(|| {
        loaded
            .diagnostics
            .items
            .iter()
            .map(|d| d.code.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    })
}

fn opts(threads: usize) -> RenderOptions {
    RenderOptions {
        threads,
        ..Default::default()
    }
}

/// A flat-lit plane z = 0 wearing `material`, seen face on: one world unit per pixel.
fn flat(material: &str) -> Scene {
    load(&format!(
        "camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan({H} / 2 / 1000),
                   resolution: [{W}, {H}] }}
         point_light {{ position: [0, 0, 1000] }}
         plane(point: [0, 0, 0], normal: Z).material({material})
         render {{ shadows: false, max_depth: 0 }}"
    ))
    .unwrap()
}

/// A flat material showing `texture`.
fn showing(texture: &str) -> String {
    format!("material {{ texture: {texture}, ka: 1, kd: 0, ks: 0 }}")
}

/// The world point pixel (i, j) looks at.
fn world(i: u32, j: u32) -> DVec3 {
    DVec3::new(
        f64::from(i) + 0.5 - f64::from(W) / 2.0,
        f64::from(H) / 2.0 - f64::from(j) - 0.5,
        0.0,
    )
}

/// Every pixel's colour against `expect` at its world point, within `tol` per channel.
fn assert_pixels(scene: &Scene, tol: f64, expect: impl Fn(DVec3) -> DVec3) {
    let img = render_scene(scene, &opts(2)).unwrap();
    for j in 0..H {
        for i in 0..W {
            let p = world(i, j);
            let (got, want) = (img.get(i, j), expect(p));
            assert!(
                (got - want).abs().max_element() <= tol,
                "pixel ({i}, {j}) at {p}: got {got}, want {want}"
            );
        }
    }
}

/// The fractional part, as the gradient pattern takes it.
fn frac(x: f64) -> f64 {
    x - x.floor()
}

#[test]
fn a_colour_map_interpolates_between_its_stops_in_linear_rgb() {
    // gradient along x over 80 units, from x = −40: value (x + 40) / 80 in [0, 1).
    let tex =
        "gradient(axis: X).colors([[0, rgb(1, 0, 0)], [0.5, rgb(0, 1, 0)], [1, rgb(0, 0, 1)]])
               .scale(80).translate([-40, 0, 0])";
    assert_pixels(&flat(&showing(tex)), 1e-9, |p| {
        let v = frac((p.x + 40.0) / 80.0);
        if v < 0.5 {
            DVec3::new(1.0 - 2.0 * v, 2.0 * v, 0.0)
        } else {
            DVec3::new(0.0, 2.0 - 2.0 * v, 2.0 * v - 1.0)
        }
    });
}

#[test]
fn stops_are_sorted_and_two_at_one_place_make_a_sharp_edge() {
    // Written out of order; the ends hold outside the first and last stop.
    let tex = "gradient(axis: Y).colors([[0.75, rgb(0, 0, 1)], [0.25, rgb(1, 0, 0)], [0.5, rgb(1, 0, 0)], [0.5, rgb(0, 0, 1)]])
               .scale(40).translate([0, -20, 0])";
    assert_pixels(&flat(&showing(tex)), 1e-12, |p| {
        let v = frac((p.y + 20.0) / 40.0);
        if v < 0.5 { DVec3::X } else { DVec3::Z }
    });
}

#[test]
fn a_discrete_pattern_shows_one_colour_per_tile_and_checker_keeps_its_parity() {
    let tex = "checker().colors([rgb(1, 0, 0), rgb(0, 0, 1)]).scale(10)";
    assert_pixels(&flat(&showing(tex)), 0.0, |p| {
        let c = (p / 10.0).floor();
        if (c.x + c.y + c.z).rem_euclid(2.0) == 0.0 {
            DVec3::X
        } else {
            DVec3::Z
        }
    });
}

#[test]
fn frequency_phase_and_wave_shapes_act_on_the_value() {
    // onion in the plane: value = frac(|p| / 16); frequency 2, phase 0.25, triangle wave.
    let tex = "onion().scale(16).frequency(2).phase(0.25).wave(\"triangle\")
               .colors([[0, rgb(0, 0, 0)], [1, rgb(1, 1, 1)]])";
    assert_pixels(&flat(&showing(tex)), 1e-9, |p| {
        let v = frac(p.norm() / 16.0);
        let w = 2.0 * v + 0.25;
        let w = if (0.0..=1.0).contains(&w) { w } else { frac(w) };
        DVec3::splat(if w < 0.5 { 2.0 * w } else { 2.0 * (1.0 - w) })
    });
}

#[test]
fn stripes_given_a_modifier_stay_the_same_stripes() {
    let plain = "stripes(size: 5, a: rgb(1, 0, 0), b: rgb(0, 0, 1))";
    let moved = format!("{plain}.translate([0, 0, 0])");
    assert_pixels(&flat(&showing(&moved)), 0.0, |p| {
        if (p.x / 5.0).floor().rem_euclid(2.0) == 0.0 {
            DVec3::X
        } else {
            DVec3::Z
        }
    });
}

/// Compares two renders: at most `share` of the pixels may differ by more than 2 levels of 255
/// in a channel.
fn nearly_same(a: &Scene, b: &Scene, share: f64) {
    let (x, y) = (
        render_scene(a, &opts(2)).unwrap(),
        render_scene(b, &opts(2)).unwrap(),
    );
    let mut differ = 0;
    for j in 0..x.height {
        for i in 0..x.width {
            if (x.get(i, j) - y.get(i, j)).abs().max_element() > 2.0 / 255.0 {
                differ += 1;
            }
        }
    }
    let n = f64::from(x.width * x.height);
    assert!(
        f64::from(differ) <= share * n,
        "{differ} of {n} pixels differ"
    );
}

/// A lit, shaded scene of `object` (a textured object at the origin) seen by a camera and a
/// light, all moved by `place` (a chain of transform methods) — the same picture whatever
/// `place` is, if the texture follows the object.
fn placed(object: &str, place: &str) -> Scene {
    load(&format!(
        "let t = translate([0, 0, 0]){place}
         camera {{ eye: t.point([0.5, 1.5, 6]), center: t.point([0, 0, 0]), up: t.vector(Y),
                   fov: 40deg, resolution: [64, 48] }}
         point_light {{ position: t.point([-4, 6, 5]) }}
         ({object}){place}
         render {{ background: rgb(0, 0, 0) }}"
    ))
    .unwrap()
}

const VEINS: &str = "marble().turbulence(0.7).colors([[0, rgb(0.9, 0.85, 0.8)], [1, rgb(0.1, 0.1, 0.2)]]).scale(0.4)";

#[test]
fn a_texture_follows_its_object_when_the_object_moves() {
    let ball = format!("sphere(radius: 1.5).material(material {{ texture: {VEINS} }})");
    let place = ".rotate(axis: [1, 2, 0.5], angle: 70deg).translate([3, -2, 7])";
    nearly_same(&placed(&ball, ""), &placed(&ball, place), 0.005);
}

#[test]
fn a_texture_follows_a_group_a_csg_object_and_a_scaled_object() {
    let cut = format!(
        "difference(sphere(radius: 1.5), box(min: [0, 0, 0], max: [2, 2, 2]))
           .material(material {{ texture: {VEINS} }})"
    );
    let group = format!(
        "group([sphere(radius: 1).material(material {{ texture: {VEINS} }}),
                box(min: [-2, -2, -2], max: [2, -1.5, 2]).material(material {{ texture: granite().scale(0.3) }})])"
    );
    for object in [cut, group] {
        let place = ".rotate(y: 35deg).scale(1.7).translate([-3, 1, 2])";
        nearly_same(&placed(&object, ""), &placed(&object, place), 0.005);
    }
}

#[test]
fn a_moving_object_carries_its_texture() {
    // Spinning about y: a pattern that depends on y only looks the same, one that depends on
    // the angle smears. If textures stayed in world space both would be sharp.
    let ball = |tex: &str, moving: &str| {
        load(&format!(
            "camera {{ eye: [0, 0, 6], center: [0, 0, 0], up: Y, fov: 40deg, resolution: [48, 48],
                       shutter: [0, 1] }}
             point_light {{ position: [0, 0, 6] }}
             sphere(radius: 1.5).material(material {{ texture: {tex}, ka: 1, kd: 0, ks: 0 }}){moving}
             render {{ supersampling: 4, shadows: false, max_depth: 0 }}"
        ))
        .unwrap()
    };
    let spin = ".moving(rotate: rotate(y: 90deg))";
    let bands = "gradient(axis: Y).colors([rgb(1, 0, 0), rgb(0, 0, 1)]).scale(0.5)";
    nearly_same(&ball(bands, ""), &ball(bands, spin), 0.0);
    let sectors = "radial().frequency(4).colors([[0, rgb(1, 0, 0)], [0.5, rgb(1, 0, 0)], [0.5, rgb(0, 0, 1)], [1, rgb(0, 0, 1)]])";
    let (still, spun) = (
        render_scene(&ball(sectors, ""), &opts(2)).unwrap(),
        render_scene(&ball(sectors, spin), &opts(2)).unwrap(),
    );
    // The spun ball's sectors blur into purple: far from the still ball's pure red or blue.
    let (a, b) = (still.get(24, 24), spun.get(24, 30));
    assert!(a.x.min(a.z) < 0.05, "still is red or blue: {a}");
    assert!(b.x > 0.2 && b.z > 0.2, "spun is a blend: {b}");
}

#[test]
fn layers_show_the_top_where_it_covers_and_the_bottom_through_it() {
    let layered = |top: &str| {
        format!(
            "layers([material {{ texture: gradient(axis: X).colors([{top}]), ka: 1, kd: 0, ks: 0 }},
                     material {{ color: rgb(0.2, 0.4, 0.6), ka: 1, kd: 0, ks: 0 }}])"
        )
    };
    let bottom = DVec3::new(0.2, 0.4, 0.6);
    // Opaque top: the top's colour.
    assert_pixels(&flat(&layered("rgb(1, 0, 0)")), 1e-12, |_| DVec3::X);
    // Fully transmitting top: the bottom.
    let clear = layered("{ at: 0, color: rgb(1, 0, 0), transmit: 1 }");
    assert_pixels(&flat(&clear), 1e-12, |_| bottom);
    // Filtering top: the bottom tinted by the top's colour; half transmit: half of each.
    let tint = layered("{ at: 0, color: rgb(1, 0.5, 0), filter: 1 }");
    assert_pixels(&flat(&tint), 1e-12, |_| bottom * DVec3::new(1.0, 0.5, 0.0));
    let half = layered("{ at: 0, color: rgb(1, 0, 0), transmit: 0.5 }");
    assert_pixels(&flat(&half), 1e-12, |_| 0.5 * DVec3::X + 0.5 * bottom);
}

#[test]
fn the_order_of_layers_matters() {
    let spots = "material { texture: leopard().colors([{ at: 0, color: rgb(0, 0, 0), transmit: 1 }, [1, rgb(1, 1, 1)]]).scale(8), ka: 1, kd: 0, ks: 0 }";
    let red = "material { color: rgb(1, 0, 0), ka: 1, kd: 0, ks: 0 }";
    // Spots over red: red shows between the spots. Red over spots: only red.
    let img = |m: &str| render_scene(&flat(m), &opts(2)).unwrap();
    let over = img(&format!("layers([{spots}, {red}])"));
    let under = img(&format!("layers([{red}, {spots}])"));
    let mut spotted = 0;
    for j in 0..H {
        for i in 0..W {
            assert!((under.get(i, j) - DVec3::X).abs().max_element() < 1e-12);
            if (over.get(i, j) - DVec3::X).abs().max_element() > 0.1 {
                spotted += 1;
            }
        }
    }
    assert!(spotted > 50, "spots show over red ({spotted} pixels)");
}

#[test]
fn a_material_map_blends_or_switches_whole_materials() {
    let map = |blend: bool| {
        format!(
            "material_map(pattern: gradient(axis: X).scale(80).translate([-40, 0, 0]),
                          stops: [[0.25, material {{ color: rgb(1, 0, 0), ka: 1, kd: 0, ks: 0 }}],
                                  [0.75, material {{ color: rgb(0, 0, 1), ka: 0.5, kd: 0, ks: 0 }}]],
                          blend: {blend})"
        )
    };
    // Blended: colour and ka both interpolate, so the pixel is C(w)·ka(w).
    assert_pixels(&flat(&map(true)), 1e-9, |p| {
        let v = frac((p.x + 40.0) / 80.0);
        let w = ((v - 0.25) / 0.5).clamp(0.0, 1.0);
        let color = DVec3::new(1.0 - w, 0.0, w);
        color * (1.0 - 0.5 * w)
    });
    assert_pixels(&flat(&map(false)), 1e-12, |p| {
        let v = frac((p.x + 40.0) / 80.0);
        if v < 0.75 { DVec3::X } else { DVec3::Z * 0.5 }
    });
}

#[test]
fn a_noise_texture_gives_the_same_bytes_on_one_and_two_threads() {
    let scene = flat(&showing(
        "granite().turbulence(0.3).colors([rgb(0, 0, 0), rgb(1, 0.8, 0.6)]).scale(9)",
    ));
    let one = render_scene(&scene, &opts(1)).unwrap();
    let two = render_scene(&scene, &opts(2)).unwrap();
    for j in 0..H {
        for i in 0..W {
            assert_eq!(one.get(i, j).to_array(), two.get(i, j).to_array());
        }
    }
}

#[test]
fn a_bump_pattern_tilts_the_normal_by_its_gradient() {
    // A plane lit from straight ahead, diffuse only: brightness is the cosine between the
    // bumped normal and +z. gradient(axis: X) scaled by 40 rises 1/40 per unit along x, so its
    // gradient is (1/40, 0, 0) and the normal tilts to (−s/40, 0, 1) normalised.
    let s = 8.0;
    let scene = load(&format!(
        "camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan({H} / 2 / 1000),
                   resolution: [{W}, {H}] }}
         point_light {{ position: [0, 0, 1e9] }}
         plane(point: [0, 0, 0], normal: Z).material(material {{ ka: 0, kd: 1, ks: 0, color: rgb(1, 1, 1),
             bump: gradient(axis: X).scale(40).translate([-20, 0, 0]), bump_scale: {s} }})
         render {{ shadows: false, max_depth: 0 }}"
    ))
    .unwrap();
    let img = render_scene(&scene, &opts(2)).unwrap();
    let cos = 1.0 / (1.0 + (s / 40.0_f64).powi(2)).sqrt();
    // Away from the ramp's wrap at x = 20 (where the central difference straddles the drop).
    for i in [5, 30, 45, 55, 75] {
        let got = img.get(i, 10).x;
        assert!((got - cos).abs() < 1e-6, "pixel {i}: {got} vs {cos}");
    }
}

#[test]
fn bad_texture_calls_are_diagnosed() {
    let code = |src: &str| load(&format!("plane().material({})", showing(src))).unwrap_err();
    assert_eq!(code("marble().colors([])"), "rtc::texture::stop");
    assert_eq!(code("marble().colors([[0, 1]])"), "rtc::texture::stop");
    assert_eq!(code("marble().wave(\"sin\")"), "rtc::texture::choice");
    assert_eq!(code("crackle(form: \"edge\")"), "rtc::texture::choice");
    assert_eq!(
        code("brick().repeat([1, 1, 0], width: 2)"),
        "rtc::texture::axis"
    );
    assert_eq!(
        code("image(path: \"tests/data/flip/zoom-1x1.png\").turbulence(1)"),
        "rtc::texture::image"
    );
    let layers = load("plane().material(layers([]))").unwrap_err();
    assert_eq!(layers, "rtc::material::parts");
    let map = load("plane().material(material_map(pattern: bozo(), stops: [[0, 1]]))").unwrap_err();
    assert_eq!(map, "rtc::material::stop");
}

#[test]
fn every_std_textures_preset_loads_and_shows_its_colours() {
    let textures = [
        "white_marble",
        "green_marble",
        "black_marble",
        "pink_granite",
        "grey_granite",
        "oak",
        "pine",
        "cherry",
        "sandstone",
        "slate",
        "sky",
        "clouds",
    ];
    let materials = [
        "marble_material()",
        "granite_material()",
        "wood_material()",
        "stone_material()",
        "brushed_metal()",
        "hammered_metal()",
        "water()",
    ];
    for t in textures {
        // Flat-lit: every pixel is a colour of the preset's map, so not one pixel is the
        // background's pure magenta and the preset varies across the floor.
        let scene = load(&format!(
            "import std.textures as tex
             camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan(2 / 1000), resolution: [24, 24] }}
             point_light {{ position: [0, 0, 1000] }}
             plane(point: [0, 0, 0], normal: Z).material(material {{ texture: tex.{t}(scale: 0.5, seed: 2), ka: 1, kd: 0, ks: 0 }})
             render {{ shadows: false, max_depth: 0, background: rgb(1, 0, 1) }}"
        ))
        .unwrap_or_else(|e| panic!("{t}: {e}"));
        let img = render_scene(&scene, &opts(2)).unwrap();
        let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
        for j in 0..24 {
            for i in 0..24 {
                let c = img.get(i, j);
                assert!(
                    c != DVec3::new(1.0, 0.0, 1.0),
                    "{t}: background at ({i}, {j})"
                );
                lo = lo.min(c.element_sum());
                hi = hi.max(c.element_sum());
            }
        }
        assert!(hi > lo, "{t} is uniform");
    }
    for m in materials {
        let scene = load(&format!(
            "import std.textures as tex
             camera {{ eye: [0, 0, 6], center: [0, 0, 0], up: Y, fov: 40deg, resolution: [24, 24] }}
             point_light {{ position: [2, 4, 6] }}
             sphere(radius: 1.5).material(tex.{m})"
        ))
        .unwrap_or_else(|e| panic!("{m}: {e}"));
        render_scene(&scene, &opts(2)).unwrap();
    }
}

#[test]
fn the_uv_mode_shows_surface_coordinates_and_a_uv_pattern_reads_them() {
    // A face-on quad over the whole view: its uv is (s, t) along its edges, so at world (x, y)
    // u = (x + 40) / 80 and v = (y + 20) / 40.
    let quad = |material: &str, mode: &str| {
        load(&format!(
            "camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan({H} / 2 / 1000),
                       resolution: [{W}, {H}] }}
             point_light {{ position: [0, 0, 1000] }}
             quad(corner: [-40, -20, 0], u: [80, 0, 0], v: [0, 40, 0]).material({material})
             render {{ shadows: false, max_depth: 0{mode} }}"
        ))
        .unwrap()
    };
    let uv = |p: DVec3| DVec3::new((p.x + 40.0) / 80.0, (p.y + 20.0) / 40.0, 0.0);
    assert_pixels(&quad("material {}", ", mode: uv"), 1e-12, uv);
    // gradient along x read in uv space: grey u, through the grey map.
    let tex = showing("gradient(axis: X).uv()");
    assert_pixels(&quad(&tex, ""), 1e-12, |p| DVec3::splat(uv(p).x));
}

#[test]
fn a_bilinear_image_blends_between_texel_centres() {
    // A 2×1 image, black then white (linear 0 and 1), on a face-on quad filling the view: in
    // uv, texel centres are at u = 1/4 and 3/4; bilinear reads 0 left of 1/4, 1 right of 3/4 and
    // 2(u − 1/4) between; nearest reads int(u·1): 0 for u < 1, so all black but the right edge.
    let dir = std::env::temp_dir().join(format!("rtc-textures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("two.png");
    image::RgbImage::from_fn(2, 1, |x, _| image::Rgb([if x == 0 { 0 } else { 255 }; 3]))
        .save(&png)
        .unwrap();
    let quad = |filter: &str| {
        let tex = format!("image(path: \"{}\", filter: \"{filter}\")", png.display());
        load(&format!(
            "camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan({H} / 2 / 1000),
                       resolution: [{W}, {H}] }}
             point_light {{ position: [0, 0, 1000] }}
             quad(corner: [-40, -20, 0], u: [80, 0, 0], v: [0, 40, 0]).material({})
             render {{ shadows: false, max_depth: 0 }}",
            showing(&tex)
        ))
        .unwrap()
    };
    assert_pixels(&quad("bilinear"), 1e-12, |p| {
        let u = (p.x + 40.0) / 80.0;
        DVec3::splat((2.0 * (u - 0.25)).clamp(0.0, 1.0))
    });
    assert_pixels(&quad("nearest"), 0.0, |_| DVec3::ZERO);
    assert_eq!(
        load(&format!(
            "plane().material({})",
            showing(&format!(
                "image(path: \"{}\", filter: \"linear\")",
                png.display()
            ))
        ))
        .unwrap_err(),
        "rtc::texture::choice"
    );
}
