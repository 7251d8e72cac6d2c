//! One pixel explained (`rtc why`): the integrator run for one camera sample with a recording
//! [`Recorder`], as a tree of rays, next to the pixel's value as the render computes it.
//!
//! The explained sample is the pixel centre (sub-pixel offset (½, ½)) with the random numbers
//! of the pixel's sample 0, or, when asked, sample `k` of the pixel's first grid exactly as
//! the render takes it. With one sample per pixel the two are the same, and the traced colour
//! equals the rendered pixel (before a lens-flare post stage, which spreads over the image).

use glam::DVec3;

use super::context::Ctx;
use super::film::encode;
use super::integrator::Integrator;
use super::path::Path;
use super::record::{Branch, LightTerm, Recorder};
use super::sampler::PixelSampler;
use super::view::View;
use crate::diag::Diagnostic;
use crate::geometry::{Ray, SurfaceHit};
use crate::ir::{Color, Encoding, MaterialId};
use crate::opt::{Prepared, TextureMap};

/// Where a recorded ray hit.
#[derive(Clone, Debug, PartialEq)]
pub struct HitInfo {
    /// Distance along the ray.
    pub t: f64,
    /// World-space point.
    pub point: DVec3,
    /// Unit outward normal.
    pub normal: DVec3,
    /// The top-level object (an index into the scene's objects).
    pub object: u32,
    /// The material shaded with (an index into the prepared material table).
    pub material: MaterialId,
    /// The patterns its material reads, with their values here.
    pub patterns: Vec<PatternReading>,
}

/// A pattern a material reads at a hit: what for, its value, and the colour-map stop the
/// value fell in.
#[derive(Clone, Debug, PartialEq)]
pub struct PatternReading {
    /// `texture`, `bump` or `material map`.
    pub role: &'static str,
    /// The pattern's constructor (`marble`).
    pub name: &'static str,
    /// Its value at the hit (after warps and wave).
    pub value: f64,
    /// For a texture: the stop the value fell in (its index and position) and how many stops
    /// the map has.
    pub stop: Option<(usize, f64, usize)>,
}

impl HitInfo {
    fn of(scene: &Prepared, hit: &SurfaceHit) -> HitInfo {
        HitInfo {
            t: hit.t,
            point: hit.point,
            normal: hit.normal,
            object: scene.world().object(hit),
            material: hit.material,
            patterns: patterns_at(scene, hit),
        }
    }
}

/// The patterns the material of `hit` reads, in the order texture, bump, material map.
fn patterns_at(scene: &Prepared, hit: &SurfaceHit) -> Vec<PatternReading> {
    let mat = scene.material(hit.material);
    let mix_texture = match mat.mix.as_deref() {
        Some(crate::ir::Mix::Map { texture, .. }) => Some(*texture),
        _ => None,
    };
    let uses = [
        ("texture", mat.texture),
        ("bump", mat.bump.map(|b| b.texture)),
        ("material map", mix_texture),
    ];
    let mut out = Vec::new();
    for (role, t) in uses {
        let Some(TextureMap::Pattern(pt)) = t.and_then(|t| scene.textures().get(t.0 as usize))
        else {
            continue;
        };
        let value = super::texture::pattern_value(pt, hit, hit.local_point);
        let stops = pt.map.stops();
        let stop = (role == "texture").then(|| {
            let i = pt.map.stop_index(value);
            (i, stops[i].at, stops.len())
        });
        out.push(PatternReading {
            role,
            name: pt.name,
            value,
            stop,
        });
    }
    out
}

/// One light's contribution at a recorded hit ([`LightTerm`], with the occluder resolved).
#[derive(Clone, Debug, PartialEq)]
pub struct LightInfo {
    /// The terms and sample counts.
    pub term: LightTerm,
    /// The first opaque surface found between the point and the light.
    pub occluder: Option<HitInfo>,
}

/// One traced ray and what it met.
#[derive(Clone, Debug, PartialEq)]
pub struct RayNode {
    /// How it came about.
    pub branch: Branch,
    /// Its branch's coefficient (`reflect` or `refract`; 1 for the camera ray).
    pub k: f64,
    /// Rays its branch traced (more than 1 over a glossy lobe, whose mean is weighed by `k`).
    pub rays: u32,
    /// Bounces before it (0 for the camera ray).
    pub depth: u32,
    /// The product of the coefficients from the camera to it.
    pub weight: f64,
    /// Where it starts.
    pub origin: DVec3,
    /// Its unit direction.
    pub dir: DVec3,
    /// What it hit (`None`: the background).
    pub hit: Option<HitInfo>,
    /// The ambient term added once (`ambient: once`).
    pub ambient: Option<Color>,
    /// Each light's contribution.
    pub lights: Vec<LightInfo>,
    /// The shading model's colour, before reflection and refraction.
    pub local: Option<Color>,
    /// Total internal reflection moved the refracted share to the reflected ray.
    pub total_internal_reflection: bool,
    /// Branches not traced because their weight fell under the cut-off, with their coefficient.
    pub cut: Vec<(Branch, f64)>,
    /// The secondary rays it spawned.
    pub children: Vec<RayNode>,
    /// Its colour (local plus weighted children).
    pub color: Color,
    /// The branch its next secondary rays belong to (recording state).
    next: (Branch, f64, u32),
}

/// The explanation of one pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Explanation {
    /// The pixel.
    pub x: u32,
    /// The pixel's row (0 at the top).
    pub y: u32,
    /// The explained sample: `None` for the pixel centre, else its number in the first grid.
    pub sample: Option<u32>,
    /// Its sub-pixel offset.
    pub offset: (f64, f64),
    /// Samples the pixel's first pass takes.
    pub samples: u32,
    /// The explained ray tree (the camera ray at its root).
    pub root: RayNode,
    /// The explained sample's colour (linear, unclamped).
    pub color: Color,
    /// The pixel's value as the render computes it (all samples, adaptive refinement).
    pub pixel: Color,
    /// Whether adaptive refinement took the finer grid here.
    pub refined: bool,
    /// The image's 8-bit encoding.
    pub encoding: Encoding,
    /// A lens-flare post stage changes the image after this value.
    pub flare: bool,
}

impl Explanation {
    /// The pixel's bytes as the image stores them (without a flare).
    pub fn pixel_bytes(&self) -> [u8; 3] {
        encode(self.pixel, self.encoding)
    }

    /// The explained sample's bytes in the image's encoding.
    pub fn sample_bytes(&self) -> [u8; 3] {
        encode(self.color, self.encoding)
    }
}

/// The recorder that builds the tree.
struct Tree<'a> {
    scene: &'a Prepared,
    stack: Vec<RayNode>,
    root: Option<RayNode>,
}

impl Recorder for Tree<'_> {
    const ON: bool = true;

    fn ray(&mut self, ray: &Ray, path: &Path) {
        let (branch, k, rays) = self
            .stack
            .last()
            .map_or((Branch::Camera, 1.0, 1), |p| p.next);
        self.stack.push(RayNode {
            branch,
            k,
            rays,
            depth: path.depth,
            weight: path.weight,
            origin: ray.origin,
            dir: ray.dir,
            hit: None,
            ambient: None,
            lights: Vec::new(),
            local: None,
            total_internal_reflection: false,
            cut: Vec::new(),
            children: Vec::new(),
            color: Color::ZERO,
            next: (branch, k, rays),
        });
    }

    fn hit(&mut self, hit: &SurfaceHit) {
        let info = HitInfo::of(self.scene, hit);
        if let Some(n) = self.stack.last_mut() {
            n.hit = Some(info);
        }
    }

    fn light(&mut self, term: LightTerm) {
        let occluder = term.occluder.map(|h| HitInfo::of(self.scene, &h));
        if let Some(n) = self.stack.last_mut() {
            n.lights.push(LightInfo { term, occluder });
        }
    }

    fn ambient(&mut self, c: Color) {
        if let Some(n) = self.stack.last_mut() {
            n.ambient = Some(c);
        }
    }

    fn local(&mut self, c: Color) {
        if let Some(n) = self.stack.last_mut() {
            n.local = Some(c);
        }
    }

    fn branch(&mut self, b: Branch, k: f64, rays: u32, cut: bool) {
        if let Some(n) = self.stack.last_mut() {
            if cut {
                n.cut.push((b, k));
            } else {
                n.next = (b, k, rays);
            }
        }
    }

    fn total_internal_reflection(&mut self) {
        if let Some(n) = self.stack.last_mut() {
            n.total_internal_reflection = true;
        }
    }

    fn done(&mut self, c: Color) {
        let Some(mut n) = self.stack.pop() else {
            return;
        };
        n.color = c;
        match self.stack.last_mut() {
            Some(p) => p.children.push(n),
            None => self.root = Some(n),
        }
    }
}

/// Explains pixel (x, y) of `scene` (the caller checks it is inside the image): the pixel
/// centre, or sample `sample` of its first grid. `Err` when the sample number is past the
/// grid or the render cannot start (the depth range pass).
pub fn explain(
    scene: &Prepared,
    x: u32,
    y: u32,
    sample: Option<u32>,
) -> Result<Explanation, Diagnostic> {
    let pool = super::tiles::pool(1)?;
    let sampler = PixelSampler::new(scene.settings().sampling);
    let view = View::new(scene);
    let ray_of = |x, y, k| view.sample_ray(x, y, k, sampler.first);
    let integrator = Integrator::new(scene, &view.first_rays(sampler.first, &ray_of), &pool)?;
    let n = integrator.channels().len();
    let (w, h) = (view.camera.width(), view.camera.height());
    let grid = sampler.first;
    if let Some(k) = sample
        && k >= grid.len()
    {
        return Err(Diagnostic::new(
            crate::diag::Severity::Error,
            "rtc::why::sample",
            None,
            format!(
                "sample {k} does not exist: the scene takes {} sample(s) per pixel",
                grid.len()
            ),
        )
        .with_help(format!(
            "give `--sample` a number from 0 to {}, or leave it out to explain the pixel centre",
            grid.len() - 1
        )));
    }
    // The pixel's value, as `render` computes it: the first grid, then the finer one where a
    // 4-neighbour's first-pass value differs by more than the threshold.
    let coarse = |px: u32, py: u32| {
        let mut out = vec![Color::ZERO; n];
        super::pixel::average(
            &view,
            &integrator,
            grid,
            0,
            px,
            py,
            &mut Ctx::new(),
            &mut out,
        );
        out[0]
    };
    let here = coarse(x, y);
    let mut pixel = here;
    let mut refined = false;
    if let Some((fine, threshold)) = sampler.refine {
        let differs = |nx: u32, ny: u32| (coarse(nx, ny) - here).abs().max_element() > threshold;
        refined = (x > 0 && differs(x - 1, y))
            || (x + 1 < w && differs(x + 1, y))
            || (y > 0 && differs(x, y - 1))
            || (y + 1 < h && differs(x, y + 1));
        if refined {
            let mut out = vec![Color::ZERO; n];
            let start = super::refine_start(fine);
            super::pixel::average(
                &view,
                &integrator,
                fine,
                start,
                x,
                y,
                &mut Ctx::new(),
                &mut out,
            );
            pixel = out[0];
        }
    }
    let (k, offset) = match sample {
        Some(k) => (k, grid.offset(k)),
        None => (0, (0.5, 0.5)),
    };
    let mut ctx = Ctx::new();
    let ray = view.camera_sample(x, y, k, (k, grid.len()), offset, &mut ctx);
    if super::panorama::is_blind(&ray) {
        return Err(Diagnostic::new(
            crate::diag::Severity::Error,
            "rtc::why::no_ray",
            Some(scene.camera().span),
            format!("pixel ({x}, {y}) is outside the fisheye's circle: it is black, no ray is traced"),
        )
        .with_help("ask about a pixel inside the circle (radius min(width, height) / 2 around the image centre)"));
    }
    let mut tree = Tree {
        scene,
        stack: Vec::new(),
        root: None,
    };
    let mut out = vec![Color::ZERO; n];
    integrator.sample_with(&ray, &mut ctx, &mut out, &mut tree);
    let root = tree.root.ok_or_else(|| {
        Diagnostic::new(
            crate::diag::Severity::Error,
            "rtc::why::unrecorded",
            None,
            "the integrator traced no ray for this pixel",
        )
        .with_help("this is a bug in rtc: please report it with the scene")
    })?;
    Ok(Explanation {
        x,
        y,
        sample,
        offset,
        samples: grid.len(),
        root,
        color: out[0],
        pixel,
        refined,
        encoding: scene.settings().encoding,
        flare: scene.effects().flare && scene.settings().flare.is_some(),
    })
}
