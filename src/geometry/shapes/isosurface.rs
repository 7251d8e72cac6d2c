//! Isosurfaces (POV-Ray's `isosurface`): the points of a box or sphere container where a
//! compiled function of the point ([`Program`], the same form `pattern(f)` runs) equals a
//! threshold, inside where it is below. Unless open, the container's walls close the solid
//! where the function is inside, so it takes part in CSG like any solid.
//!
//! Along a ray the search is Lipschitz-bounded: with `G` a bound on the function's rate of
//! change, no surface lies within `|f − threshold| / G` of a sample, so the search steps that
//! far (never less than `accuracy`), and a sign change between two samples is narrowed to
//! full precision by Brent's method (superlinear where the function is smooth, bisection's
//! guarantee where it is not). `G` is the scene's `max_gradient`, or estimated from the function's slopes
//! sampled on a grid over the container. Every step checks the bound against the slope it saw:
//! steps where the function changed faster are counted in a [`GradientLog`], which the
//! renderer reports after the render with the value to use. A search stops after
//! [`MAX_EVALUATIONS`] evaluations (counted too), so no ray can hang the render.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use glam::DVec3;

use crate::diag::{Diagnostic, Severity};
use crate::geometry::ray::equirectangular_uv;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};
use crate::ir::Container;
use crate::num::Norm;
use crate::pattern::Program;
use crate::source::Span;

use super::bracket::brent;
use super::cuboid::Cuboid;
use super::flaw::{OUT_OF_RANGE, ShapeFlaw, finite, in_range, positive, vec3};
use super::sphere;

/// The most function evaluations one search along a ray may take.
pub(crate) const MAX_EVALUATIONS: u64 = 200_000;
/// The most steps of length `accuracy` a container's diagonal may hold: finer steps would be
/// lost in the rounding of the ray parameter. (The search takes its shortest steps only near
/// the surface; [`MAX_EVALUATIONS`] bounds a ray that runs along it.)
pub(crate) const MAX_STEPS_ACROSS: f64 = 1e9;
/// Grid cells per axis over the container when the gradient is estimated.
pub(crate) const GRID: usize = 12;
/// The estimated bound: this many times the steepest slope sampled (a grid can miss peaks).
pub(crate) const SAFETY: f64 = 2.0;
/// How far an observed slope may exceed the bound before it counts (rounding of the samples).
const SLACK: f64 = 1.0 + 1e-9;

/// What searches along rays saw, shared by every copy of a prepared isosurface and read after
/// the render. Counts are sums and the slope a maximum, so any thread order gives the same.
#[derive(Debug, Default)]
pub(crate) struct GradientLog {
    /// Steps where the function changed faster than the bound.
    steps_over: AtomicU64,
    /// The steepest slope seen on those steps (`f64` bits; non-negative, so ordered as `u64`).
    max_slope: AtomicU64,
    /// Searches stopped at [`MAX_EVALUATIONS`].
    gave_up: AtomicU64,
}

impl GradientLog {
    fn over(&self, slope: f64) {
        self.steps_over.fetch_add(1, Ordering::Relaxed);
        self.max_slope.fetch_max(slope.to_bits(), Ordering::Relaxed);
    }

    /// Steps over the bound, the steepest slope seen on them, and searches stopped by the
    /// evaluation budget.
    pub(crate) fn read(&self) -> (u64, f64, u64) {
        (
            self.steps_over.load(Ordering::Relaxed),
            f64::from_bits(self.max_slope.load(Ordering::Relaxed)),
            self.gave_up.load(Ordering::Relaxed),
        )
    }
}

/// The container: where the function is searched.
#[derive(Clone, Copy, Debug)]
enum Walls {
    Box(Cuboid),
    Sphere { center: DVec3, radius: f64 },
}

impl Walls {
    /// Where the line of `ray` enters and leaves (entry first), if it meets the container.
    fn span(&self, ray: &Ray) -> Option<(Hit, Hit)> {
        let mut out = Vec::with_capacity(2);
        match *self {
            Walls::Box(b) => b.crossings(ray, &mut out),
            Walls::Sphere { center, radius } => sphere::crossings(center, radius, ray, &mut out),
        }
        match out.as_slice() {
            [a, b] if a.hit.t < b.hit.t => Some((a.hit, b.hit)),
            _ => None,
        }
    }

    fn contains(&self, p: DVec3) -> bool {
        match *self {
            Walls::Box(b) => b.contains(p),
            Walls::Sphere { center, radius } => sphere::contains(center, radius, p),
        }
    }

    fn bounds(&self) -> Aabb {
        match *self {
            Walls::Box(b) => b.bounds(),
            Walls::Sphere { center, radius } => sphere::bounds(center, radius),
        }
    }

    /// The residual distance of `p` from the walls.
    fn distance(&self, p: DVec3) -> f64 {
        match *self {
            Walls::Box(b) => b.point_error(p).x,
            Walls::Sphere { center, radius } => sphere::point_error(center, radius, p).x,
        }
    }
}

/// An isosurface in object space, ready to trace.
#[derive(Clone, Debug)]
pub(crate) struct Isosurface {
    f: Arc<Program>,
    walls: Walls,
    threshold: f64,
    /// The gradient bound the search uses (given or estimated), > 0.
    bound: f64,
    /// Whether `bound` was estimated.
    estimated: bool,
    accuracy: f64,
    open: bool,
    /// The step of the central differences giving normals.
    h: f64,
    log: Arc<GradientLog>,
}

/// A prepared isosurface's bound and what its searches saw, for the report after a render.
#[derive(Clone, Debug)]
pub(crate) struct Watch {
    /// The bound the search used.
    pub(crate) bound: f64,
    /// Whether it was estimated (no `max_gradient` given).
    pub(crate) estimated: bool,
    /// The searches' counts.
    pub(crate) log: Arc<GradientLog>,
}

/// The steepest slope of `f` sampled in the container: at the points of a ([`GRID`] + 1)³ grid
/// over its bounds that lie inside it, forward differences (a step of 10⁻⁴ of the container's
/// size) along the axes and along the gradient they give. Each is a slope between two points,
/// so the maximum is a lower bound of the function's true bound (up to rounding).
fn sampled_slope(f: &Program, walls: &Walls) -> f64 {
    let b = walls.bounds();
    let size = b.max - b.min;
    let h = 1e-4 * size.max_element();
    let mut steepest: f64 = 0.0;
    for i in 0..=GRID {
        for j in 0..=GRID {
            for k in 0..=GRID {
                let s = DVec3::new(i as f64, j as f64, k as f64) / GRID as f64;
                let p = b.min + s * size;
                if !walls.contains(p) {
                    continue;
                }
                let v = f.eval(p);
                let d = |e: DVec3| (f.eval(p + h * e) - v) / h;
                let g = DVec3::new(d(DVec3::X), d(DVec3::Y), d(DVec3::Z));
                // Each slope is between two points, so none exceeds the true bound (a norm of
                // one-sided differences could, at a kink); the last is along the gradient.
                let along = g.try_unit().map_or(0.0, |u| d(u).abs());
                for x in [g.x.abs(), g.y.abs(), g.z.abs(), along] {
                    if x.is_finite() {
                        steepest = steepest.max(x);
                    }
                }
            }
        }
    }
    steepest
}

/// The steepest slope of the function `f` sampled in `container` (see `sampled_slope`), for
/// the language's check of a given `max_gradient`; `None` for an invalid container.
pub(crate) fn sample_slope(f: &Program, container: &Container) -> Option<f64> {
    walls(container).ok().map(|w| sampled_slope(f, &w))
}

/// `x` rounded up to three significant digits, written as a number for a `max_gradient`.
pub(crate) fn suggested(x: f64) -> String {
    if !(x > 0.0 && x.is_finite()) {
        return crate::diag::number(x);
    }
    let e = libm::floor(libm::log10(x));
    let scale = libm::pow(10.0, e - 2.0);
    let v = libm::ceil(x / scale - 1e-9) * scale;
    if (-3.0..15.0).contains(&e) {
        crate::diag::number(v)
    } else {
        format!("{v:.2e}")
    }
}

/// The container's walls, checked.
fn walls(container: &Container) -> Result<Walls, ShapeFlaw> {
    Ok(match *container {
        Container::Box { min, max } => {
            finite("min", &[min, max])?;
            if !max.cmpgt(min).all() {
                return Err(ShapeFlaw::other(
                    "max",
                    OUT_OF_RANGE,
                    "the container's `max` must be greater than `min` on every axis",
                    format!("max = {} but min = {}", vec3(max), vec3(min)),
                    "swap the corners or fix the smaller coordinate",
                ));
            }
            Walls::Box(Cuboid::new(min, max))
        }
        Container::Sphere { center, radius } => {
            positive("radius", radius)?;
            finite("center", &[center])?;
            Walls::Sphere { center, radius }
        }
    })
}

/// An isosurface's rules (a finite threshold, a positive `max_gradient` and `accuracy`, a
/// container no more than [`MAX_STEPS_ACROSS`] accuracy steps across), then the shape; the
/// gradient bound estimated when none is given.
pub(super) fn build(
    f: &Arc<Program>,
    container: &Container,
    threshold: f64,
    max_gradient: Option<f64>,
    accuracy: f64,
    open: bool,
) -> Result<Isosurface, ShapeFlaw> {
    let walls = walls(container)?;
    in_range(threshold.is_finite(), "threshold", "finite", threshold)?;
    if let Some(g) = max_gradient {
        in_range(g > 0.0 && g.is_finite(), "max_gradient", "> 0", g)?;
    }
    positive("accuracy", accuracy)?;
    let b = walls.bounds();
    let diagonal = (b.max - b.min).norm();
    let least = diagonal / MAX_STEPS_ACROSS;
    // `accuracy` is positive and finite here (`positive`), `least` finite.
    if accuracy < least {
        return Err(ShapeFlaw::other(
            "accuracy",
            OUT_OF_RANGE,
            format!(
                "`accuracy` is too fine for the container: at most {MAX_STEPS_ACROSS:e} steps across it"
            ),
            format!(
                "accuracy = {accuracy:e}, container {} across",
                crate::diag::number(diagonal)
            ),
            format!("write `accuracy: {}` or more", suggested(least)),
        ));
    }
    let sampled = sampled_slope(f, &walls);
    let (bound, estimated) = match max_gradient {
        Some(g) => (g, false),
        // A constant function has no slope; any positive bound steps straight across.
        None => ((SAFETY * sampled).max(f64::MIN_POSITIVE.sqrt()), true),
    };
    let extent = 0.5 * diagonal;
    Ok(Isosurface {
        f: f.clone(),
        walls,
        threshold,
        bound,
        estimated,
        accuracy,
        open,
        h: (1e-5 * extent).min(0.25 * accuracy),
        log: Arc::new(GradientLog::default()),
    })
}

/// One surface met along a ray: its `t`, whether the ray enters the solid there, and the
/// wall's normal when it is a container wall.
struct Event {
    t: f64,
    entering: bool,
    wall: Option<DVec3>,
}

impl Isosurface {
    /// The bound used and what the searches saw.
    pub(crate) fn watch(&self) -> Watch {
        Watch {
            bound: self.bound,
            estimated: self.estimated,
            log: self.log.clone(),
        }
    }

    /// `f − threshold` at `p`: negative inside, never NaN (`Program::eval` reads a value that
    /// is not finite as 0; a difference too large for `f64` is clamped).
    fn value(&self, p: DVec3) -> f64 {
        (self.f.eval(p) - self.threshold).clamp(-f64::MAX, f64::MAX)
    }

    /// The function's gradient at `p` by central differences.
    fn gradient(&self, p: DVec3) -> DVec3 {
        // Scale-aware: no finer than the point's own rounding allows.
        let h = self.h.max(1e-9 * p.abs().max_element());
        let d = |e: DVec3| (self.f.eval(p + h * e) - self.f.eval(p - h * e)) / (2.0 * h);
        DVec3::new(d(DVec3::X), d(DVec3::Y), d(DVec3::Z))
    }

    /// Object-space bounds: the container's.
    pub(crate) fn bounds(&self) -> Aabb {
        self.walls.bounds()
    }

    /// Every surface along the line of `ray` within [t_min, t_max], in increasing `t`, until
    /// `visit` returns false.
    fn search(&self, ray: &Ray, t_min: f64, t_max: f64, mut visit: impl FnMut(Event) -> bool) {
        let len = ray.dir.norm();
        if !(len > 0.0 && len.is_finite()) {
            return;
        }
        let Some((enter, exit)) = self.walls.span(ray) else {
            return;
        };
        let (a, b) = (enter.t.max(t_min), exit.t.min(t_max));
        if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
            return;
        }
        // Work from the start, so points stay small however far the ray's origin is.
        let (o, d) = (ray.at(a), ray.dir);
        let span = b - a;
        let at = |s: f64| self.value(o + s * d);
        let mut evals = 1;
        let (mut s, mut v) = (0.0, at(0.0));
        if enter.t > t_min && !self.open && v < 0.0 {
            let wall = Some(enter.normal);
            if !visit(Event {
                t: a,
                entering: true,
                wall,
            }) {
                return;
            }
        }
        let lipschitz = self.bound * len;
        let least = self.accuracy / len;
        while s < span {
            if evals >= MAX_EVALUATIONS {
                self.log.gave_up.fetch_add(1, Ordering::Relaxed);
                return;
            }
            let step = (v.abs() / lipschitz).max(least);
            let mut s1 = (s + step).min(span);
            if s1 <= s {
                s1 = span;
            }
            let v1 = at(s1);
            evals += 1;
            let slope = (v1 - v).abs() / ((s1 - s) * len);
            if slope > self.bound * SLACK {
                self.log.over(slope);
            }
            if (v < 0.0) != (v1 < 0.0) {
                let (t, n) = self.narrow(o, d, (s, v), (s1, v1));
                evals += n;
                if !visit(Event {
                    t: a + t,
                    entering: v1 < 0.0,
                    wall: None,
                }) {
                    return;
                }
            }
            s = s1;
            v = v1;
        }
        if exit.t < t_max && !self.open && v < 0.0 {
            visit(Event {
                t: b,
                entering: false,
                wall: Some(exit.normal),
            });
        }
    }

    /// The sign change of the function along `o + s·d` between two samples `(s, value)`, to
    /// full precision, and the evaluations it took.
    fn narrow(&self, o: DVec3, d: DVec3, lo: (f64, f64), hi: (f64, f64)) -> (f64, u64) {
        let mut n = 0;
        let (t, _, _) = brent(
            |s| {
                n += 1;
                self.value(o + s * d)
            },
            lo.0,
            hi.0,
            lo.1,
            hi.1,
        );
        (t, n)
    }

    /// The hit of an event: the wall's normal, or the function's gradient (facing out, as the
    /// function grows outwards; along the ray when the gradient vanishes).
    fn hit(&self, ray: &Ray, e: &Event) -> Hit {
        let normal = e.wall.unwrap_or_else(|| {
            self.gradient(ray.at(e.t)).try_unit().unwrap_or_else(|| {
                let along = ray.dir.unit();
                if e.entering { -along } else { along }
            })
        });
        Hit {
            t: e.t,
            normal,
            uv: equirectangular_uv(normal),
        }
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let mut found = None;
        self.search(ray, t_min, t_max, |e| {
            if e.t > t_min && e.t < t_max {
                found = Some(e);
                false
            } else {
                true
            }
        });
        found.map(|e| self.hit(ray, &e))
    }

    /// Boundary crossings along the whole line (none when open: it is a surface).
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        if self.open {
            return;
        }
        self.search(ray, f64::NEG_INFINITY, f64::INFINITY, |e| {
            out.push(Crossing {
                hit: self.hit(ray, &e),
                entering: e.entering,
            });
            true
        });
    }

    /// True when `p` is inside the closed solid (an open isosurface contains nothing).
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        !self.open && self.walls.contains(p) && self.value(p) < 0.0
    }

    /// Error bound of a computed point `p` on the surface: its distance to the nearer of the
    /// function's zero set (first order, `|f| / |∇f|`) and the walls, at most `accuracy`, plus
    /// rounding.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let g = self.gradient(p).norm();
        let along = if g > 0.0 {
            self.value(p).abs() / g
        } else {
            f64::INFINITY
        };
        let residual = along.min(self.walls.distance(p)).min(self.accuracy);
        let b = self.walls.bounds();
        let size = p.abs().max_element().max((b.max - b.min).max_element());
        rounding::from_residual(residual, 64, size)
    }
}

impl Watch {
    /// `rtc::isosurface::estimated`: the note that the bound of the isosurface at `span` was
    /// estimated (none when it was given).
    pub(crate) fn note(&self, span: Span) -> Option<Diagnostic> {
        self.estimated.then(|| {
            Diagnostic::new(
                Severity::Note,
                "rtc::isosurface::estimated",
                Some(span),
                format!(
                    "`max_gradient` not given: estimated as {} ({SAFETY} times the steepest slope sampled on a {}³ grid in the container)",
                    suggested(self.bound),
                    GRID + 1
                ),
            )
            .with_help(format!(
                "write `max_gradient: {}` to keep it, or a smaller bound you know holds to render faster",
                suggested(self.bound)
            ))
        })
    }

    /// What the searches of the isosurface at `span` saw that the user should know, after a
    /// render: steps where the function changed faster than the bound
    /// (`rtc::isosurface::max_gradient`) and searches stopped by the budget
    /// (`rtc::isosurface::budget`).
    pub(crate) fn report(&self, span: Span) -> Vec<Diagnostic> {
        let (over, slope, gave_up) = self.log.read();
        let mut out = Vec::new();
        if over > 0 {
            let how = if self.estimated { "estimated" } else { "given" };
            out.push(
                Diagnostic::warning(
                    "rtc::isosurface::max_gradient",
                    span,
                    format!(
                        "the isosurface's function changed faster than `max_gradient` {} ({how}) on {over} search step{}: up to {} per unit length; parts of the surface may be missing",
                        suggested(self.bound),
                        if over == 1 { "" } else { "s" },
                        suggested(slope)
                    ),
                )
                .with_label("its bound is too small")
                .with_help(format!(
                    "write `max_gradient: {}` (the steepest slope seen, and 10 % more)",
                    suggested(1.1 * slope)
                )),
            );
        }
        if gave_up > 0 {
            out.push(
                Diagnostic::warning(
                    "rtc::isosurface::budget",
                    span,
                    format!(
                        "{gave_up} search{} along rays stopped after {MAX_EVALUATIONS} evaluations of the function; parts of the surface may be missing",
                        if gave_up == 1 { "" } else { "es" }
                    ),
                )
                .with_label("too many evaluations per ray")
                .with_help(
                    "make `accuracy` larger (longer shortest steps), give a `max_gradient` closer to the true slope, or shrink the container",
                ),
            );
        }
        out
    }
}
