//! Finish terms (issue 37) against their analytic values: an orthographic camera looks straight
//! down −z at a flat-lit white backdrop (`ka: 1`, one white light, so a pixel that sees it is 1)
//! through or at the surface under test, and every expected value is computed here from the
//! physics (Beer–Lambert, the Fresnel equations), never read from a render.

use std::path::Path;

use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::render::film::Film;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

const W: u32 = 32;
const H: u32 = 32;

fn load(src: &str) -> Scene {
    let mut sources = SourceMap::default();
    let text = format!(
        "rtc 1.1
         camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, projection: \"orthographic\",
                  height: {H}, resolution: [{W}, {H}] }}
         point_light {{ position: [0, 0, 500] }}
         {src}"
    );
    let loaded = load_source(
        Path::new("finish.rtc"),
        &text,
        &mut sources,
        &EvalOptions::default(),
    );
    let codes: Vec<String> = loaded
        .diagnostics
        .items
        .iter()
        .map(|d| format!("{}: {}", d.code, d.message))
        .collect();
    loaded.scene.unwrap_or_else(|| panic!("{codes:?}"))
}

fn render(scene: &Scene) -> Film {
    render_scene(scene, &RenderOptions::default()).unwrap()
}

/// The flat-lit white backdrop z = 0.
const BACKDROP: &str = "plane(point: [0, 0, 0], normal: Z).material(material { color: rgb(1, 1, 1), ka: 1, kd: 0, ks: 0 })";

/// Every pixel of `film` against `want` per channel.
fn assert_all(film: &Film, want: [f64; 3], tol: f64) {
    for j in 0..H {
        for i in 0..W {
            let got = film.get(i, j).to_array();
            for c in 0..3 {
                assert!(
                    (got[c] - want[c]).abs() < tol,
                    "pixel ({i}, {j}) channel {c}: got {}, want {}",
                    got[c],
                    want[c]
                );
            }
        }
    }
}

#[test]
fn absorption_over_a_slab_of_known_thickness_is_beer_lambert() {
    // Seen head on the rays cross the slab straight: thickness d = 2.5, so each channel keeps
    // exp(−σ·2.5). The glass neither reflects nor tints (filter 0), and passes all (refract 1).
    let sigma = [0.1, 0.4, 1.2];
    let scene = load(&format!(
        "{BACKDROP}
         box(min: [-40, -40, 1], max: [40, 40, 3.5]).material(material {{
             color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, refract: 1, eta: 1.5, filter: 0,
             absorption: rgb({}, {}, {}) }})
         render {{ shadows: false, max_depth: 4 }}",
        sigma[0], sigma[1], sigma[2]
    ));
    let want = sigma.map(|s| (-s * 2.5f64).exp());
    assert_all(&render(&scene), want, 1e-9);
}

#[test]
fn absorption_along_a_spheres_diameter() {
    // The ray through the centre of a sphere of radius 3 is not bent and crosses 6 units of
    // it. The pixel (16, 16) looks along x = 0.5, y = −0.5: the sphere is centred there.
    let scene = load(&format!(
        "{BACKDROP}
         sphere(center: [0.5, -0.5, 5], radius: 3).material(material {{
             color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, refract: 1, eta: 1.33, filter: 0,
             absorption: rgb(0.05, 0.2, 0.5) }})
         render {{ shadows: false, max_depth: 4 }}"
    ));
    let film = render(&scene);
    let got = film.get(16, 16).to_array();
    for (c, s) in [0.05f64, 0.2, 0.5].iter().enumerate() {
        let want = (-s * 6.0).exp();
        assert!(
            (got[c] - want).abs() < 1e-9,
            "channel {c}: {} vs {want}",
            got[c]
        );
    }
}

#[test]
fn filter_tints_the_light_seen_through_glass() {
    // Crossed twice: (refract · (filter·C + 1 − filter))² of the white backdrop.
    let (c, f, k) = ([1.0, 0.4, 0.1], 0.5, 0.9);
    let scene = load(&format!(
        "{BACKDROP}
         box(min: [-40, -40, 1], max: [40, 40, 3]).material(material {{
             color: rgb({}, {}, {}), ka: 0, kd: 0, ks: 0, refract: {k}, eta: 1.5, filter: {f} }})
         render {{ shadows: false, max_depth: 4 }}",
        c[0], c[1], c[2]
    ));
    let want = c.map(|x: f64| (k * (f * x + 1.0 - f)).powi(2));
    assert_all(&render(&scene), want, 1e-12);
}

#[test]
fn red_glass_looks_red_by_default_and_course_glass_stays_clear() {
    let glass = |filter: &str| {
        load(&format!(
            "{BACKDROP}
             box(min: [-40, -40, 1], max: [40, 40, 3]).material(material {{
                 color: rgb(1, 0.2, 0.2), ka: 0, kd: 0, ks: 0, refract: 1, eta: 1.5 {filter} }})
             render {{ shadows: false, max_depth: 4 }}"
        ))
    };
    assert_all(&render(&glass("")), [1.0, 0.04, 0.04], 1e-12);
    assert_all(&render(&glass(", filter: 0")), [1.0, 1.0, 1.0], 1e-12);
}

/// The exact unpolarised Fresnel reflectance from air into index `n` at incidence `theta`,
/// from Snell's law and the s and p amplitudes.
fn fresnel(theta: f64, n: f64) -> f64 {
    let st = theta.sin() / n;
    let (ci, ct) = (theta.cos(), (1.0 - st * st).sqrt());
    let rs = (ci - n * ct) / (ci + n * ct);
    let rp = (n * ci - ct) / (n * ci + ct);
    0.5 * (rs * rs + rp * rp)
}

#[test]
fn fresnel_mirror_at_normal_and_grazing_incidence() {
    // An opaque Fresnel mirror of index 1.5 turned by θ about x reflects the background B:
    // the pixel is F(θ)·B, the same at every pixel of the orthographic view.
    let b = [0.8, 0.6, 0.4];
    for deg in [0.0f64, 30.0, 60.0, 80.0, 87.0] {
        let scene = load(&format!(
            "plane(point: [0, 0, 0], normal: Z).rotate(x: {deg}deg).material(material {{
                 color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, reflect: 1, eta: 1.5, fresnel: true }})
             render {{ shadows: false, max_depth: 2, background: rgb({}, {}, {}) }}",
            b[0], b[1], b[2]
        ));
        let f = fresnel(deg.to_radians(), 1.5);
        assert_all(&render(&scene), b.map(|x| f * x), 1e-9);
    }
    // Head on into glass: ((n − 1)/(n + 1))² = 4 %.
    assert!((fresnel(0.0, 1.5) - 0.04).abs() < 1e-15);
}

#[test]
fn emission_glows_without_light() {
    // ka·C·Lc (one white light, per-light ambient) plus emission·C.
    let scene = load(
        "plane(point: [0, 0, 0], normal: Z).material(material {
             color: rgb(0.5, 1, 0.25), ka: 0.2, kd: 0, ks: 0, emission: rgb(0.4, 0.3, 0.8) })
         render { shadows: false, max_depth: 0 }",
    );
    let want = [(0.5, 0.4), (1.0, 0.3), (0.25, 0.8)].map(|(c, e)| 0.2 * c + e * c);
    assert_all(&render(&scene), want, 1e-12);
}
