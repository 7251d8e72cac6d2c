//! Output encoding of `.rtc` scenes (issue 11, point 1): sRGB by default, so an sRGB colour
//! written in the scene (`#rrggbb`, `srgb(..)`) comes out as the very bytes it names; the course's
//! linear `trunc(255·c)` on request. The rule is the definition of the sRGB curve, so the expected
//! bytes are the hex digits themselves, not numbers produced by the renderer.

use std::path::Path;

use rtc::eval::{EvalOptions, load_source};
use rtc::render::{RenderOptions, render_image};
use rtc::source::SourceMap;

/// The colour of a 1×1 render of an empty scene with this `render` block body.
fn pixel(render_fields: &str) -> [u8; 3] {
    let src = format!(
        "rtc 1\ncamera {{ eye: [0, 0, 10], resolution: [1, 1] }}\nrender {{ {render_fields} }}\n"
    );
    let mut sources = SourceMap::default();
    let loaded = load_source(
        Path::new("colour.rtc"),
        &src,
        &mut sources,
        &EvalOptions::default(),
    );
    let scene = loaded
        .scene
        .unwrap_or_else(|| panic!("{src}: {:?}", loaded.diagnostics.items));
    let image = render_image(&scene, &RenderOptions::default()).expect("render");
    image.get_pixel(0, 0).0
}

#[test]
fn every_grey_hex_level_comes_out_as_its_own_byte() {
    for k in 0..=255u8 {
        let hex = format!("#{k:02x}{k:02x}{k:02x}");
        assert_eq!(pixel(&format!("background: {hex}")), [k; 3], "{hex}");
    }
}

#[test]
fn hex_and_srgb_colours_keep_their_bytes() {
    assert_eq!(pixel("background: #808080"), [128, 128, 128]);
    assert_eq!(pixel("background: #ff8000"), [255, 128, 0]);
    assert_eq!(pixel("background: #0a64c8"), [10, 100, 200]);
    assert_eq!(pixel("background: srgb(0.2, 0.4, 0.6)"), [51, 102, 153]);
    // hsv(0deg, 1, 0.5) is sRGB (0.5, 0, 0): 127.5 rounds to 128.
    assert_eq!(pixel("background: hsv(0deg, 1, 0.5)"), [128, 0, 0]);
}

#[test]
fn linear_encoding_is_the_course_truncation() {
    // #808080 is linear 0.2158605…; 255 × that is 55.04, truncated to 55 (what `rtc 1` gave).
    assert_eq!(pixel("background: #808080, encoding: linear"), [55, 55, 55]);
    assert_eq!(
        pixel("background: rgb(0.5), encoding: linear"),
        [127, 127, 127]
    );
    // The same linear 0.5 in sRGB is 0.7354 → 187.5… → 188.
    assert_eq!(pixel("background: rgb(0.5)"), [188, 188, 188]);
    assert_eq!(
        pixel("background: rgb(0.5), encoding: srgb"),
        [188, 188, 188]
    );
}

#[test]
fn course_front_ends_stay_linear() {
    let mut sources = SourceMap::default();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let yaml = rtc::compat::load_yaml(
        &root.join("tests/data/course/yaml/scene01.yaml"),
        &mut sources,
    );
    let inn = rtc::compat::load_in(&root.join("tests/data/course/in/rt1.in"), &mut sources);
    for loaded in [yaml, inn] {
        let scene = loaded.scene.expect("course scene");
        assert_eq!(scene.settings.encoding, rtc::ir::Encoding::Linear);
    }
}

#[test]
fn a_wrong_encoding_names_the_choices() {
    let src = "rtc 1\ncamera { eye: [0, 0, 10] }\nrender { encoding: 2 }\n";
    let mut sources = SourceMap::default();
    let loaded = load_source(
        Path::new("e.rtc"),
        src,
        &mut sources,
        &EvalOptions::default(),
    );
    let d = &loaded.diagnostics.items[0];
    assert_eq!(d.code, "rtc::type::mismatch");
    assert!(
        d.help
            .as_deref()
            .unwrap_or("")
            .contains("`srgb` or `linear`"),
        "{d:?}"
    );
}
