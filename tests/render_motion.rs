//! Motion blur: a moving sphere's streak against the analytic box convolution of the still
//! sphere, and the promise that scenes without visible motion render exactly as before.

use std::path::Path;

use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

fn scene(src: &str) -> Scene {
    let mut sm = SourceMap::new();
    let loaded = load_source(
        Path::new("motion.rtc"),
        src,
        &mut sm,
        &EvalOptions::default(),
    );
    let errors: Vec<_> = loaded
        .diagnostics
        .items
        .iter()
        .filter(|d| d.is_error())
        .collect();
    assert!(errors.is_empty(), "{errors:?}");
    loaded.scene.expect("a scene")
}

/// A white sphere of radius `R` lit by ambient light only (so every visible point has value 1)
/// on black, seen almost orthographically: the camera is 1000 units away and one world unit on
/// the plane z = 0 is one pixel. The sphere starts at x = `X0` (y = `Y0`) and moves `D` along x.
const R: f64 = 10.0;
const X0: f64 = -30.0;
const Y0: f64 = 0.5;
const D: f64 = 60.0;
const W: u32 = 200;
const H: u32 = 40;
const SS: u32 = 8;

fn streak_scene(shutter: &str, moving: &str) -> String {
    format!(
        "rtc 1.1
camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan(20 / 1000),
         resolution: [{W}, {H}]{shutter} }}
point_light {{ position: [0, 0, 1000] }}
sphere(center: [{X0}, {Y0}, 0], radius: {R})
  .material(material {{ color: rgb(1, 1, 1), ka: 1, kd: 0, ks: 0 }}){moving}
render {{ supersampling: {SS}, shadows: false, max_depth: 0 }}
"
    )
}

/// The expected linear value of pixel (x, y): the mean over the pixel's SS×SS sample positions
/// of the fraction of the shutter during which the sphere covers that point. At image point
/// (px, py) (world x = px − W/2, y = py − H/2) the sphere's chord is |x − c| < r(y) with
/// r(y) = √(R² − (y − Y0)²) and its centre c = X0 + D·t, t ∈ [0, 1]: the covered share of t is
/// the length of [x − r − X0, x + r − X0] ∩ [0, D], over D.
fn box_convolution(x: u32, y: u32) -> f64 {
    let mut sum = 0.0;
    for j in 0..SS {
        for i in 0..SS {
            let sx = (f64::from(i) + 0.5) / f64::from(SS);
            let sy = (f64::from(j) + 0.5) / f64::from(SS);
            let wx = f64::from(x) + sx - f64::from(W) / 2.0;
            let wy = f64::from(H - 1 - y) + sy - f64::from(H) / 2.0;
            let dy = wy - Y0;
            if dy.abs() >= R {
                continue;
            }
            let r = (R * R - dy * dy).sqrt();
            let lo = (wx - r - X0).max(0.0);
            let hi = (wx + r - X0).min(D);
            sum += (hi - lo).max(0.0) / D;
        }
    }
    sum / f64::from(SS * SS)
}

#[test]
fn a_moving_sphere_streaks_as_the_box_convolution_of_the_still_one() {
    let s = scene(&streak_scene(
        ", shutter: [0, 1]",
        &format!(".moving(translate: [{D}, 0, 0])"),
    ));
    let film = render_scene(&s, &RenderOptions::default()).expect("renders");
    let (mut worst, mut total, mut n) = (0.0f64, 0.0, 0);
    for y in [H / 2 - 6, H / 2 - 1, H / 2, H / 2 + 4] {
        for x in 0..W {
            let got = film.get(x, y).x;
            let want = box_convolution(x, y);
            let err = (got - want).abs();
            worst = worst.max(err);
            total += err;
            n += 1;
        }
    }
    let mean = total / f64::from(n);
    println!("streak against the box convolution: worst {worst:.4}, mean {mean:.5}");
    // Bounds: 64 samples per pixel with stratified times leave ≈ 1/64 of noise per edge crossed;
    // the perspective of a camera 1000 units away bends the silhouette by < 0.02 pixel.
    assert!(worst < 0.06, "worst pixel error {worst}");
    assert!(mean < 0.01, "mean pixel error {mean}");
    // The streak is really there: the middle of the path is covered for 2R/D of the shutter.
    let mid = film.get(W / 2 + (X0 + D / 2.0) as u32, H / 2 - 1).x;
    assert!((mid - 2.0 * R / D).abs() < 0.05, "mid-streak value {mid}");
}

#[test]
fn a_still_scene_is_byte_identical_with_an_open_shutter() {
    let closed = scene(&streak_scene("", ""));
    let open = scene(&streak_scene(", shutter: [0, 0.5]", ""));
    let a = render_scene(&closed, &RenderOptions::default()).expect("renders");
    let b = render_scene(&open, &RenderOptions::default()).expect("renders");
    assert_eq!(a.to_image().as_raw(), b.to_image().as_raw());
    assert_eq!(a.color(), b.color());
    assert_eq!(a.stats, b.stats, "the same rays");
    assert!(
        !rtc::opt::prepare(&open)
            .expect("prepares")
            .effects()
            .motion_blur
    );
}

#[test]
fn motion_without_an_open_shutter_renders_the_shutter_open_position() {
    let moving = scene(&streak_scene(
        "",
        &format!(".moving(translate: [{D}, 0, 0])"),
    ));
    let still = scene(&streak_scene("", ""));
    let a = render_scene(&moving, &RenderOptions::default()).expect("renders");
    let b = render_scene(&still, &RenderOptions::default()).expect("renders");
    assert_eq!(a.color(), b.color());
    let warnings = rtc::check::lint(&moving);
    assert!(
        warnings
            .items
            .iter()
            .any(|d| d.code == "rtc::motion::invisible")
    );
}

#[test]
fn a_moving_camera_blurs_a_still_sphere_like_the_sphere_moving_the_other_way() {
    // Moving the camera (eye and centre) by +D/4 along x shifts the image like moving the
    // sphere by −D/4; the two films agree up to sampling noise.
    let cam = scene(&streak_scene(
        &format!(
            ", shutter: [0, 1], eye_close: [{e}, 0, 1000], center_close: [{e}, 0, 0]",
            e = D / 4.0
        ),
        "",
    ));
    let obj = scene(&streak_scene(
        ", shutter: [0, 1]",
        &format!(".moving(translate: [{}, 0, 0])", -D / 4.0),
    ));
    let a = render_scene(&cam, &RenderOptions::default()).expect("renders");
    let b = render_scene(&obj, &RenderOptions::default()).expect("renders");
    let worst = a
        .color()
        .iter()
        .zip(b.color())
        .map(|(p, q)| (*p - *q).abs().max_element())
        .fold(0.0, f64::max);
    assert!(worst < 0.02, "camera vs object motion differ by {worst}");
    assert!(
        a.color()
            != render_scene(&scene(&streak_scene("", "")), &RenderOptions::default())
                .expect("renders")
                .color()
    );
}

#[test]
fn a_moving_csg_node_blurs() {
    let src = "rtc 1.1
camera { eye: [0, 0, 10], center: [0, 0, 0], resolution: [48, 32], shutter: [0, 1] }
point_light { position: [0, 5, 10] }
difference(box(min: [-1, -1, -1], max: [1, 1, 1]), sphere(radius: 1.3))
  .moving(translate: [2, 0, 0], rotate: rotate(y: 45deg))
render { supersampling: 2 }
";
    let moving = scene(src);
    let still = scene(&src.replace(
        ".moving(translate: [2, 0, 0], rotate: rotate(y: 45deg))",
        "",
    ));
    let p = rtc::opt::prepare(&moving).expect("prepares");
    assert!(p.effects().motion_blur);
    let a = render_scene(&moving, &RenderOptions::default()).expect("renders");
    let b = render_scene(&still, &RenderOptions::default()).expect("renders");
    assert!(a.color() != b.color());
}

#[test]
fn a_moving_mesh_instance_blurs_and_its_twin_stays_sharp() {
    // Two instances of one mesh share its BVH; only the first moves.
    let src = "rtc 1.1
camera { eye: [0, 0, 10], center: [0, 0, 0], resolution: [48, 32], shutter: [0, 1] }
point_light { position: [0, 5, 10] }
let duck = mesh(\"tests/data/course/models/devilduk.obj\")
duck.scale(2 / duck.bounds.size.y).translate([-1.5, 0, 0])MOVE
duck.scale(2 / duck.bounds.size.y).translate([1.5, 0, 0])
render { supersampling: 2 }
";
    let moving = scene(&src.replace("MOVE", ".moving(translate: [0, 1, 0])"));
    let still = scene(&src.replace("MOVE", ""));
    assert!(
        rtc::opt::prepare(&moving)
            .expect("prepares")
            .effects()
            .motion_blur
    );
    let a = render_scene(&moving, &RenderOptions::default()).expect("renders");
    let b = render_scene(&still, &RenderOptions::default()).expect("renders");
    let (w, h) = (a.width, a.height);
    let differs = |x0: u32, x1: u32| (0..h).any(|y| (x0..x1).any(|x| a.get(x, y) != b.get(x, y)));
    assert!(differs(0, w / 2), "the moving duck blurs");
    // The still duck's half changes only where the moving duck's shadow or blur reaches; its
    // own silhouette pixels in the right quarter stay as they were.
    assert!(!differs(3 * w / 4 + 2, w), "the still duck stays sharp");
}
