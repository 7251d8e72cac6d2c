//! Geometry benchmarks (run: `cargo bench --bench geometry`, or `benches/meshes.sh`).
//!
//! Scene B of ../shared/peers (same camera and light as tools/meshcam.py: 35° fov from +z at
//! the bounding-box centre, 800×800 pixel centres, one primary + one shadow ray per hit), the
//! devil duck at 400×400 with 3×3 supersampling, and the 1.1M-triangle bunny-x16 (time to
//! first ray). Rays go through `World` directly with a pinhole camera written here; shading
//! is a plain Phong evaluation so the duck figure approximates a whole render.
//! Large models are looked up in /work/shared/models and the peers' work directory (or
//! `RTC_MODELS`); a missing one is skipped with a message.

use rtc::num::Norm;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use glam::DVec3;
use rayon::prelude::*;
use rtc::geometry::bvh::packet::PACKET;
use rtc::geometry::lanes::cull::Among;
use rtc::geometry::world::SphereHit;
use rtc::geometry::{Ray, SurfaceHit, World};
use rtc::ir::{Camera, Material, Object, Projection, RenderSettings, Scene, Shape};
use rtc::opt::Prepared;
use rtc::source::Span;

const REPS: usize = 5;

fn find(name: &str) -> Option<PathBuf> {
    let mut dirs: Vec<PathBuf> = Vec::new();
    if let Ok(d) = std::env::var("RTC_MODELS") {
        dirs.push(d.into());
    }
    dirs.extend(
        [
            "/work/shared/models",
            "/work/shared/peers/work",
            "tests/data/course/models",
        ]
        .map(PathBuf::from),
    );
    dirs.into_iter().map(|d| d.join(name)).find(|p| p.exists())
}

fn scene_of(path: &Path, smooth: bool) -> Scene {
    Scene {
        camera: Camera {
            eye: DVec3::Z,
            center: DVec3::ZERO,
            up: DVec3::Y,
            width: 1,
            height: 1,
            projection: Projection::Perspective { fov_y: 0.6 },
            aperture: 0.0,
            focus_distance: 1.0,
            shutter: None,
            motion: None,
            span: Span::default(),
        },
        lights: Vec::new(),
        materials: vec![Material::default()],
        textures: Vec::new(),
        objects: vec![Object {
            motion: None,
            shape: Shape::Mesh {
                source: rtc::ir::MeshSource::File(path.to_path_buf()),
                smooth,
                use_mtl: true,
            },
            transform: rtc::ir::Transform::IDENTITY,
            material: None,
            span: Span::default(),
            visibility: Default::default(),
        }],
        settings: RenderSettings::default(),
        memory: Default::default(),
    }
}

/// meshcam.py's camera and light for a world's bounds.
struct Cam {
    eye: DVec3,
    right: DVec3,
    up: DVec3,
    forward: DVec3,
    tan: f64,
    light: DVec3,
    scale: f64,
}

fn camera(w: &World) -> Cam {
    let b = w.bounds();
    let c = b.center();
    let half = 0.5 * (b.max - b.min);
    let s = half.x.max(half.y);
    let fov = 35f64.to_radians();
    let d = half.z + 1.15 * s / (fov / 2.0).tan();
    Cam {
        eye: c + DVec3::new(0.0, 0.0, d),
        right: DVec3::X,
        up: DVec3::Y,
        forward: -DVec3::Z,
        tan: (fov / 2.0).tan(),
        light: c + DVec3::new(-0.6 * d, 0.8 * d, 0.9 * d),
        scale: (b.max - b.min).norm(),
    }
}

impl Cam {
    fn ray(&self, x: f64, y: f64, w: u32, h: u32) -> Ray {
        let sx = (2.0 * x / w as f64 - 1.0) * self.tan;
        let sy = (1.0 - 2.0 * y / h as f64) * self.tan;
        Ray::new(
            self.eye,
            (self.forward + sx * self.right + sy * self.up).unit(),
        )
    }
}

#[derive(Default, Clone, Copy)]
struct Count {
    primary: u64,
    hits: u64,
    shadow: u64,
    lit: u64,
    shade: f64,
}

impl std::ops::Add for Count {
    type Output = Count;
    fn add(self, o: Count) -> Count {
        Count {
            primary: self.primary + o.primary,
            hits: self.hits + o.hits,
            shadow: self.shadow + o.shadow,
            lit: self.lit + o.lit,
            shade: self.shade + o.shade,
        }
    }
}

/// Traces one row: `ss×ss` pixel samples, a shadow ray per hit, Phong shading.
fn row(w: &World, cam: &Cam, y: u32, width: u32, height: u32, ss: u32, shadows: bool) -> Count {
    let mut c = Count::default();
    for x in 0..width {
        for j in 0..ss {
            for i in 0..ss {
                let fx = x as f64 + (i as f64 + 0.5) / ss as f64;
                let fy = y as f64 + (j as f64 + 0.5) / ss as f64;
                let ray = cam.ray(fx, fy, width, height);
                c.primary += 1;
                let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) else {
                    continue;
                };
                let s = ShadowRay::of(cam, &ray, &h);
                let blocked = shadows && w.occluded(&s.ray, 0.0, s.dist);
                c.shade_hit(&ray, &h, &s, shadows, blocked);
            }
        }
    }
    c
}

/// [`row`] with one sample a pixel, traced as `rtc render` traces it: the camera rays of 16
/// pixels as one packet (`World::intersect_batch_after`), then their hits' shadow rays as
/// one (`World::occluded_batch_among`); each ray's answer is the one-ray query's.
fn row_packets(w: &World, cam: &Cam, y: u32, width: u32, height: u32, shadows: bool) -> Count {
    let mut c = Count::default();
    let first = [SphereHit::default(); PACKET];
    let mut hits = [None; PACKET];
    for x0 in (0..width).step_by(PACKET) {
        let n = PACKET.min((width - x0) as usize);
        let rays: [Ray; PACKET] = std::array::from_fn(|i| {
            cam.ray(x0 as f64 + i as f64 + 0.5, y as f64 + 0.5, width, height)
        });
        c.primary += n as u64;
        w.intersect_batch_after(&rays[..n], 0.0, f64::INFINITY, &first, &mut hits[..n]);
        // The hits' shadow rays side by side in fixed arrays (no allocation per packet).
        let mut lane = [0; PACKET];
        let mut shadow = [Ray::new(DVec3::ZERO, DVec3::Z); PACKET];
        let mut dist = [0.0; PACKET];
        let mut m = 0;
        for i in (0..n).filter(|&i| hits[i].is_some()) {
            let s = ShadowRay::of(cam, &rays[i], &hits[i].expect("a hit"));
            (lane[m], shadow[m], dist[m]) = (i, s.ray, s.dist);
            m += 1;
        }
        let mut blocked = [false; PACKET];
        if shadows {
            w.occluded_batch_among(&shadow[..m], 0.0, &dist[..m], Among::ALL, &mut blocked[..m]);
        }
        for k in 0..m {
            let i = lane[k];
            let s = ShadowRay {
                ray: shadow[k],
                dist: dist[k],
            };
            c.shade_hit(&rays[i], &hits[i].expect("a hit"), &s, shadows, blocked[k]);
        }
    }
    c
}

/// A hit's shadow ray towards the light, leaving the surface on the ray's side.
struct ShadowRay {
    ray: Ray,
    dist: f64,
}

impl ShadowRay {
    fn of(cam: &Cam, ray: &Ray, h: &SurfaceHit) -> ShadowRay {
        let to_light = cam.light - h.point;
        let dist = to_light.norm();
        let ng = if h.geometric_normal.dot(ray.dir) > 0.0 {
            -h.geometric_normal
        } else {
            h.geometric_normal
        };
        let origin = h.point + 1e-4 * cam.scale * ng;
        ShadowRay {
            ray: Ray::new(origin, to_light / dist),
            dist,
        }
    }
}

impl Count {
    /// Counts a hit and adds its Phong value (ambient only when `blocked`).
    fn shade_hit(
        &mut self,
        ray: &Ray,
        h: &SurfaceHit,
        s: &ShadowRay,
        shadows: bool,
        blocked: bool,
    ) {
        self.hits += 1;
        let mut v = 0.2;
        if shadows {
            self.shadow += 1;
            if blocked {
                self.shade += v;
                return;
            }
            self.lit += 1;
        }
        let n = if h.normal.dot(ray.dir) > 0.0 {
            -h.normal
        } else {
            h.normal
        };
        let l = s.ray.dir;
        let ndl = n.dot(l).max(0.0);
        let r = 2.0 * ndl * n - l;
        v += 0.7 * ndl + 0.3 * r.dot(-ray.dir).max(0.0).powf(32.0);
        self.shade += v;
    }
}

/// Rays traced one by one, or as `rtc render` traces them (packets of 16, one sample a pixel).
#[derive(Clone, Copy, PartialEq)]
enum Mode {
    Single,
    Packets,
}

fn trace_as(
    mode: Mode,
    w: &World,
    cam: &Cam,
    size: u32,
    ss: u32,
    shadows: bool,
    threads: usize,
) -> (Duration, Count) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("pool");
    let start = Instant::now();
    let c = pool.install(|| {
        (0..size)
            .into_par_iter()
            .map(|y| match mode {
                Mode::Single => row(w, cam, y, size, size, ss, shadows),
                Mode::Packets => row_packets(w, cam, y, size, size, shadows),
            })
            .reduce(Count::default, |a, b| a + b)
    });
    (start.elapsed(), c)
}

/// Process CPU time (user + system) from /proc/self/stat, in seconds (USER_HZ = 100 assumed).
/// On this shared machine wall time depends on everyone else's load; CPU time much less.
fn cpu_time() -> f64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let rest = stat.rsplit_once(')').map_or("", |(_, r)| r);
    let f: Vec<f64> = rest
        .split_whitespace()
        .map(|x| x.parse().unwrap_or(0.0))
        .collect();
    (f.get(11).copied().unwrap_or(0.0) + f.get(12).copied().unwrap_or(0.0)) / 100.0
}

fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v[v.len() / 2]
}

fn build(path: &Path, smooth: bool) -> (Duration, Prepared) {
    // Load afresh each time: the process-wide asset cache would make repeats free.
    rtc::assets::clear_cache();
    let start = Instant::now();
    let p = rtc::opt::prepare(&scene_of(path, smooth)).expect("model loads");
    (start.elapsed(), p)
}

fn report_world(name: &str, load: Duration, p: &Prepared) {
    let s = p.stats();
    println!(
        "{name}: {} triangles; load+build {:.3} s (BVH build {:.3} s); geometry memory ≈ {:.1} MB",
        s.unique_triangles,
        load.as_secs_f64(),
        s.bvh_build_time.as_secs_f64(),
        s.memory_bytes as f64 / 1e6
    );
}

fn scene_b(name: &str, file: &str) {
    let Some(path) = find(file) else {
        println!("{name}: skipped ({file} not found; see benches/meshes.sh)");
        return;
    };
    let mut loads = Vec::new();
    let mut world = None;
    for _ in 0..REPS.min(3) {
        let (t, w) = build(&path, false);
        loads.push(t);
        world = Some(w);
    }
    let p = world.expect("built");
    report_world(name, median(loads), &p);
    let w = p.world();
    let cam = camera(w);
    // One by one (Embree's `viewer` and embreex's rtcIntersect1 loop are the peers), then as
    // the renderer traces them (Embree's stream mode is the peer there).
    for (mode, how) in [
        (Mode::Single, "one by one"),
        (Mode::Packets, "packets of 16 as rtc render traces them"),
    ] {
        for threads in [1, 2] {
            let mut tp = Vec::new();
            let mut tb = Vec::new();
            let mut last = Count::default();
            let mut cpu_p = Vec::new();
            for _ in 0..REPS {
                let c0 = cpu_time();
                let (t, _) = trace_as(mode, w, &cam, 800, 1, false, threads);
                cpu_p.push(Duration::from_secs_f64(cpu_time() - c0));
                tp.push(t);
                let (t, c) = trace_as(mode, w, &cam, 800, 1, true, threads);
                tb.push(t);
                last = c;
            }
            let cpu_p = median(cpu_p).as_secs_f64().max(0.01);
            println!(
                "  {threads} thread(s), {how}: primary rays per CPU-second {:.2} M ({:.2} CPU-s per frame)",
                last.primary as f64 / cpu_p / 1e6,
                cpu_p
            );
            let (tp, tb) = (median(tp), median(tb));
            let shadow_time = tb.saturating_sub(tp).as_secs_f64().max(1e-9);
            println!(
                "  {threads} thread(s), {how}: primary {:.3} s = {:.2} Mray/s; primary+shadow {:.3} s = {:.2} Mray/s ({} primary, {} hits = {:.3}, {} shadow rays ≈ {:.2} Mray/s)",
                tp.as_secs_f64(),
                last.primary as f64 / tp.as_secs_f64() / 1e6,
                tb.as_secs_f64(),
                (last.primary + last.shadow) as f64 / tb.as_secs_f64() / 1e6,
                last.primary,
                last.hits,
                last.hits as f64 / last.primary as f64,
                last.shadow,
                last.shadow as f64 / shadow_time / 1e6,
            );
        }
    }
}

fn duck() {
    let Some(path) = find("devilduk.obj") else {
        println!("duck: skipped (devilduk.obj not found)");
        return;
    };
    for threads in [1, 2] {
        let mut totals = Vec::new();
        let mut last = None;
        for _ in 0..REPS {
            let start = Instant::now();
            let (load, p) = build(&path, true);
            let cam = camera(p.world());
            let (_, c) = trace_as(Mode::Single, p.world(), &cam, 400, 3, true, threads);
            totals.push(start.elapsed());
            last = Some((load, c, p));
        }
        let (load, c, w) = last.expect("ran");
        if threads == 1 {
            report_world("duck", load, &w);
        }
        println!(
            "  duck 400×400 3×3 ss + shadows + Phong, {threads} thread(s): {:.3} s wall (load+build+trace; {} primary, {} shadow rays)",
            median(totals).as_secs_f64(),
            c.primary,
            c.shadow
        );
    }
}

fn x16() {
    let Some(path) = find("bunny-x16.obj") else {
        println!("bunny-x16: skipped (bunny-x16.obj not found; benches/meshes.sh makes it)");
        return;
    };
    let mut firsts = Vec::new();
    let mut last = None;
    let mut cpus = Vec::new();
    for _ in 0..3 {
        let start = Instant::now();
        let c0 = cpu_time();
        let (_, w) = build(&path, false);
        cpus.push(Duration::from_secs_f64(cpu_time() - c0));
        let cam = camera(w.world());
        let first = w
            .world()
            .intersect(&cam.ray(400.0, 400.0, 800, 800), 0.0, f64::INFINITY);
        firsts.push(start.elapsed());
        last = Some((w, first.is_some()));
    }
    let (w, hit) = last.expect("ran");
    report_world("bunny-x16", median(firsts.clone()), &w);
    println!(
        "  time to first ray (load + build + one ray; centre ray hit: {hit}): {:.3} s wall, {:.2} CPU-s for load + build",
        median(firsts).as_secs_f64(),
        median(cpus).as_secs_f64()
    );
    let cam = camera(w.world());
    let (t, c) = trace_as(Mode::Single, w.world(), &cam, 800, 1, true, 2);
    println!(
        "  800×800 primary+shadow, 2 threads: {:.3} s = {:.2} Mray/s",
        t.as_secs_f64(),
        (c.primary + c.shadow) as f64 / t.as_secs_f64() / 1e6
    );
}

fn main() {
    // `cargo bench` passes `--bench`; `cargo test --all-targets` does not, and must stay quick.
    let args: Vec<String> = std::env::args().skip(1).collect();
    if !args.iter().any(|a| a == "--bench") {
        println!("geometry benchmarks: run `cargo bench --bench geometry [duck|bunny|ogre|x16]`");
        return;
    }
    // A name filter picks one part.
    let filter: Vec<String> = args.into_iter().filter(|a| !a.starts_with("--")).collect();
    let want = |n: &str| filter.is_empty() || filter.iter().any(|f| n.contains(f.as_str()));
    if want("duck") {
        duck();
    }
    if want("bunny") {
        scene_b("stanford-bunny", "stanford-bunny.obj");
    }
    if want("ogre") {
        scene_b("ogre", "ogre.obj");
    }
    if want("x16") {
        x16();
    }
}
