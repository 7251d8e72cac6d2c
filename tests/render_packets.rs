//! A pixel's samples traced as a packet (`Whitted::trace_batch`) give every sample the colour
//! it gets traced alone (`Whitted::trace`), bit for bit (a pixel's samples, or a row's pixel
//! centres), with the same counts of shadow and
//! mirror rays: random scenes of spheres (the packet's own sphere lanes), with a mesh, a plane
//! and a transformed sphere (the world's other objects), mirrors, several lights, shadows on
//! and off, both ambient conventions, and materials the packet hands to the one-ray path
//! (Gooch, glass, a texture). The rule is the packet's contract; nothing here comes from the
//! code under test.

use std::path::{Path, PathBuf};

use rtc::render::camera::Camera;
use rtc::render::context::Ctx;
use rtc::render::integrator::whitted::Whitted;
use rtc::render::path::Path as RayPath;

/// Uniform numbers in [0, 1) from a 64-bit LCG (Knuth's MMIX constants).
fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((s >> 11) as f64) / (1u64 << 53) as f64
    }
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-packets-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn prepare(path: &Path) -> rtc::opt::Prepared {
    let mut sources = rtc::source::SourceMap::new();
    let loaded = rtc::loader::load(path, &mut sources, &rtc::eval::EvalOptions::default());
    assert!(
        !loaded.diagnostics.has_errors(),
        "{:?}",
        loaded.diagnostics.items
    );
    rtc::opt::prepare(&loaded.scene.expect("the scene evaluates")).expect("it prepares")
}

/// Scene `round`: spheres only on even rounds, with other objects on odd ones.
fn scene(round: u64, models: &Path) -> String {
    let mut rnd = uniform(round * 7919 + 1);
    let mut pick = |n: usize| ((rnd() * n as f64) as usize).min(n - 1);
    let mut rnd = uniform(round * 104729 + 3);
    let mut src = String::from("rtc 1\n");
    src += "camera { eye: [0, 1.5, 7], center: [0, 0.5, 0], fov: 45deg, resolution: [24, 18] }\n";
    for _ in 0..1 + pick(3) {
        src += &format!(
            "point_light {{ position: [{:.3}, {:.3}, {:.3}], color: rgb({:.2}, {:.2}, {:.2}) }}\n",
            rnd() * 10.0 - 5.0,
            2.0 + rnd() * 6.0,
            rnd() * 8.0 - 2.0,
            0.3 + rnd() * 0.7,
            0.3 + rnd() * 0.7,
            0.3 + rnd() * 0.7
        );
    }
    for _ in 0..2 + pick(8) {
        let special = match (round % 2, pick(8)) {
            (1, 0) => ", shading: gooch()".to_string(),
            (1, 1) => ", refract: 0.6, eta: 1.5".to_string(),
            _ => String::new(),
        };
        src += &format!(
            "sphere(center: [{:.3}, {:.3}, {:.3}], radius: {:.3}).material(material {{ color: rgb({:.2}, {:.2}, {:.2}), ka: {:.2}, kd: {:.2}, ks: {:.2}, n: {}, reflect: {:.2}{special} }})\n",
            rnd() * 6.0 - 3.0,
            rnd() * 2.5,
            rnd() * 4.0 - 3.0,
            0.2 + rnd() * 1.2,
            rnd(),
            rnd(),
            rnd(),
            rnd() * 0.3,
            rnd(),
            [0.0, 0.3, 0.8][pick(3)],
            [1, 8, 33, 200][pick(4)],
            [0.0, 0.0, 0.4, 0.9][pick(4)],
        );
    }
    if round % 2 == 1 {
        src += "plane(point: [0, -0.5, 0], normal: Y).material(material { color: rgb(0.7, 0.7, 0.7), reflect: 0.3 })\n";
        src += &format!(
            "mesh(\"{}\", smooth: true).scale(0.8).translate([1, 0.5, 1]).material(material {{ color: rgb(0.9, 0.5, 0.2), ks: 0.5, n: 20, reflect: 0.2 }})\n",
            models.join("sphere.obj").display()
        );
        src +=
            "sphere(center: [0, 0, 0], radius: 1).scale([1, 0.4, 1]).translate([-1.5, 0.2, 1])\n";
    }
    src += &format!(
        "render {{ shadows: {}, max_depth: {}, supersampling: 4, ambient: {} }}\n",
        ["true", "false"][pick(2)],
        pick(4),
        ["per_light", "once"][pick(2)]
    );
    src
}

#[test]
fn a_packet_traces_each_sample_as_it_is_traced_alone() {
    let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/models");
    let dir = scratch("rounds");
    let mut rnd = uniform(99);
    let mut packets = 0;
    for round in 0..16 {
        let path = dir.join(format!("scene{round}.rtc"));
        std::fs::write(&path, scene(round, &models)).unwrap();
        let prepared = prepare(&path);
        let w = Whitted::new(&prepared);
        assert!(w.batches(), "round {round}: the packet path applies");
        let camera = Camera::new(prepared.camera());
        for y in 0..18 {
            for x in 0..24 {
                // A pixel's samples at random sub-pixel positions, 1 to 16 of them, or (as
                // single-sample images trace them) the centres of up to 16 pixels of a row.
                let n = 1 + (rnd() * 16.0) as usize;
                let rays: Vec<_> = if (x + y) % 2 == 0 {
                    (0..n)
                        .map(|_| camera.ray(x, y, rnd(), rnd(), (0.5, 0.5)))
                        .collect()
                } else {
                    (0..n as u32)
                        .map(|k| camera.ray((x + k) % 24, y, 0.5, 0.5, (0.5, 0.5)))
                        .collect()
                };
                let mut packet_ctx = Ctx::new();
                let mut got = vec![glam::DVec3::ZERO; n];
                w.trace_batch(&rays, &mut packet_ctx, &mut got);
                let mut alone_ctx = Ctx::new();
                for (k, ray) in rays.iter().enumerate() {
                    let want = w.trace(ray, RayPath::CAMERA, &mut alone_ctx);
                    assert_eq!(
                        got[k].to_array().map(f64::to_bits),
                        want.to_array().map(f64::to_bits),
                        "round {round}, pixel ({x}, {y}), sample {k}: {} against {}",
                        got[k],
                        want
                    );
                }
                let counts = |c: &Ctx| (c.stats.shadow_rays, c.stats.secondary_rays);
                assert_eq!(counts(&packet_ctx), counts(&alone_ctx), "round {round}");
                packets += 1;
            }
        }
    }
    assert_eq!(packets, 16 * 24 * 18);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A whole render with supersampling: each pixel is the mean of its grid's samples traced
/// alone, summed in row-major sample order and divided by their number (the rule of
/// `sampler::Grid`: sample (i, j) of an f×f grid at ((i + ½)/f, (j + ½)/f)), bit for bit,
/// although the renderer traces the samples of a row's pixels together, packets straddling
/// pixels (9 samples of a 3×3 grid do not fill 16 lanes) and a row's end (24 = 16 + 8).
#[test]
fn a_supersampled_render_gives_each_pixel_the_mean_of_its_samples_traced_alone() {
    let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/models");
    let dir = scratch("grids");
    for (round, f) in [(2u64, 2u32), (3, 3), (4, 5), (5, 3), (7, 1)] {
        let src = scene(round, &models).replace("supersampling: 4", &format!("supersampling: {f}"));
        let path = dir.join(format!("grid{round}.rtc"));
        std::fs::write(&path, src).unwrap();
        let prepared = prepare(&path);
        let film = rtc::render::render(
            &prepared,
            &rtc::render::RenderOptions {
                threads: 2,
                ..Default::default()
            },
            &rtc::render::progress::Silent,
        )
        .expect("renders");
        let w = Whitted::new(&prepared);
        let camera = Camera::new(prepared.camera());
        let mut ctx = Ctx::new();
        for y in 0..18 {
            for x in 0..24 {
                let mut sum = glam::DVec3::ZERO;
                for j in 0..f {
                    for i in 0..f {
                        let (sx, sy) = (
                            (f64::from(i) + 0.5) / f64::from(f),
                            (f64::from(j) + 0.5) / f64::from(f),
                        );
                        sum += w.trace(
                            &camera.ray(x, y, sx, sy, (0.5, 0.5)),
                            RayPath::CAMERA,
                            &mut ctx,
                        );
                    }
                }
                let want = sum / f64::from(f * f);
                let got = film.get(x, y);
                assert_eq!(
                    got.to_array().map(f64::to_bits),
                    want.to_array().map(f64::to_bits),
                    "round {round}, {f}×{f}, pixel ({x}, {y}): {got} against {want}"
                );
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
