//! Study probe for docs/accuracy-study.md (kept out of the build: it drives the pre-refactor
//! render internals). It renders a scene with an adaptive scheme the renderer does not have yet,
//! drawing each camera sample exactly as `render::sample` does (same grid offsets, same
//! (pixel, sample index, seed) keys), and writes the image the way `rtc render` does
//! (trunc(255·clamp(c))) plus one line of counts.
//!
//! sample_probe SCENE.rtc SCHEME OUT.png
//!   SCHEME = aligned:MIN:MAX:T    rtc's adaptive(min, max, threshold) with the refinement's
//!                                 sample indices starting at MAX² instead of MIN²
//!   SCHEME = halves:MIN:MAX:T:C   first pass MIN×MIN (MIN even); refine to MAX×MAX where the
//!                                 two half-sample means (the samples of the grid's two
//!                                 checkerboard colours) differ by more than 2·T in a channel,
//!                                 or (C > 0) a 4-neighbour of the coarse mean differs by > C
//!   a trailing `:jitter` puts every sample at a random point of its grid cell; a trailing
//!   `:dilate` (after it) also refines the 8 neighbours of every pixel the halves flag
use std::path::Path;
use std::time::Instant;

use rtc::ir::{Color, RenderMode};
use rtc::render::integrator::Media;
use rtc::render::plan::Plan;
use rtc::render::sampler::{Grid, Rng};
use rtc::render::shading::Ctx;
use rtc::render::Stats;

thread_local! {
    /// Jittered sample positions inside each grid cell (scheme suffix `:jitter`).
    static JITTER: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

fn sample(plan: &Plan<'_>, x: u32, y: u32, g: Grid, k: u32, index: u32, ctx: &mut Ctx) -> Color {
    let (mut sx, mut sy) = g.offset(k);
    if plan.random || JITTER.get() {
        ctx.rng = Rng::new(x, y, index, plan.scene.settings.seed);
    }
    if JITTER.get() {
        // Stratified jitter: a random point in the sample's grid cell (stream 0x5eed).
        let (u, v) = ctx.rng.get2(0x5eed);
        let f = f64::from(g.factor());
        sx += (u - 0.5) / f;
        sy += (v - 0.5) / f;
    }
    let lens = if plan.camera.has_lens() { ctx.rng.get2(0) } else { (0.5, 0.5) };
    let ray = plan.camera.ray(x, y, sx, sy, lens);
    ctx.stats.camera_rays += 1;
    assert!(matches!(plan.mode, RenderMode::Shaded));
    plan.trace(&ray, 0, Media::OUTSIDE, ctx)
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let mut sources = rtc::source::SourceMap::default();
    let loaded = rtc::frontend::load(Path::new(&a[1]), &mut sources, &rtc::eval::EvalOptions::default());
    let scene = loaded.scene.expect("scene");
    let plan = Plan::new(&scene).unwrap();
    let p: Vec<&str> = a[2].split(':').collect();
    let num = |i: usize| p[i].parse::<f64>().unwrap();
    let (min, max, t) = (num(1) as u32, num(2) as u32, num(3));
    let dilate = p.last() == Some(&"dilate");
    let p: Vec<&str> = if dilate { p[..p.len() - 1].to_vec() } else { p };
    let jitter = p.last() == Some(&"jitter");
    JITTER.set(jitter);
    let p: Vec<&str> = if jitter { p[..p.len() - 1].to_vec() } else { p };
    let num = |i: usize| p[i].parse::<f64>().unwrap();
    let contrast = if p.len() > 4 { num(4) } else { 0.0 };
    let (w, h) = (plan.camera.width(), plan.camera.height());
    let mut ctx = Ctx { rng: Rng::new(0, 0, 0, 0), stats: Stats::default() };
    let start = Instant::now();
    let first = Grid::new(min);
    let mut coarse = vec![Color::ZERO; (w * h) as usize];
    let mut split = vec![false; (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            let (mut sum, mut half) = (Color::ZERO, [Color::ZERO; 2]);
            for k in 0..first.len() {
                let c = sample(&plan, x, y, first, k, k, &mut ctx);
                sum += c;
                half[((k % min + k / min) % 2) as usize] += c;
            }
            let i = (y * w + x) as usize;
            coarse[i] = sum / f64::from(first.len());
            if p[0] == "halves" {
                let n = f64::from(first.len() / 2);
                split[i] = ((half[0] - half[1]) / n).abs().max_element() > 2.0 * t;
            }
        }
    }
    if dilate {
        // Pool the noisy two-half estimate over 3×3 pixels: noise regions are spatially coherent.
        let before = split.clone();
        for y in 0..h {
            for x in 0..w {
                let near = |dx: i64, dy: i64| {
                    let (nx, ny) = (i64::from(x) + dx, i64::from(y) + dy);
                    nx >= 0 && ny >= 0 && nx < i64::from(w) && ny < i64::from(h)
                        && before[(ny as u32 * w + nx as u32) as usize]
                };
                split[(y * w + x) as usize] = (-1..=1).any(|dy| (-1..=1).any(|dx| near(dx, dy)));
            }
        }
    }
    let at = |x: u32, y: u32| coarse[(y * w + x) as usize];
    let fine = Grid::new(max);
    let mut out = coarse.clone();
    let mut refined = 0u64;
    for y in 0..h {
        for x in 0..w {
            let c = at(x, y);
            let tau = if p[0] == "aligned" { t } else { contrast };
            let differs = |nx: u32, ny: u32| tau > 0.0 && (at(nx, ny) - c).abs().max_element() > tau;
            let edge = (x > 0 && differs(x - 1, y)) || (x + 1 < w && differs(x + 1, y))
                || (y > 0 && differs(x, y - 1)) || (y + 1 < h && differs(x, y + 1));
            if !(edge || split[(y * w + x) as usize]) {
                continue;
            }
            refined += 1;
            // Indices start at an aligned block of fine.len() samples, after the first pass's.
            let base = fine.len() * first.len().div_ceil(fine.len()).max(1);
            let mut sum = Color::ZERO;
            for k in 0..fine.len() {
                sum += sample(&plan, x, y, fine, k, base + k, &mut ctx);
            }
            out[(y * w + x) as usize] = sum / f64::from(fine.len());
        }
    }
    let secs = start.elapsed().as_secs_f64();
    let q = |v: f64| (255.0 * v.clamp(0.0, 1.0)) as u8;
    let bytes: Vec<u8> = out.iter().flat_map(|c| [q(c.x), q(c.y), q(c.z)]).collect();
    image::RgbImage::from_raw(w, h, bytes).unwrap().save(&a[3]).unwrap();
    let s = ctx.stats;
    println!("{}\t{}\t{}\t{}\t{}\t{}\t{:.3}", a[3], s.camera_rays + s.secondary_rays + s.shadow_rays, s.camera_rays, s.shadow_rays, refined, refined as f64 / f64::from(w * h), secs);
}
