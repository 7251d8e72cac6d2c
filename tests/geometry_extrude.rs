//! Prisms and text (issue 38) against references written here: random rays (with and without
//! a mirrored, non-uniformly scaled transform) hit them on the surface (the distance to the
//! outline's curves, evaluated from their control points by Bernstein polynomials and minimised
//! by sampling and golden-section search), with unit normals facing out (membership by a dense
//! polyline's crossing count or winding), inside the bounds, and without re-hitting their own
//! surface; a CSG difference with a prism; and a scene of prisms and text renders the same image
//! at every scale from 10⁻⁶ to 10⁸.

mod geometry_support;
mod numerics_support;

use std::path::Path;

use geometry_support::{Rng, hemisphere, mirrored_transform, object, ray_at_box, world};
use glam::{DAffine3, DVec2, DVec3};
use rtc::eval::{EvalOptions, load_source};
use rtc::geometry::Ray;
use rtc::ir::{GlyphCurve, PrismSweep, Shape, Spline};
use rtc::num::Norm;
use rtc::source::SourceMap;

/// One outline curve: control points of a Bézier curve of degree 1, 2 or 3.
type Curve = Vec<DVec2>;

/// The Bézier curve `c` at `s` (de Casteljau).
fn bez(c: &Curve, s: f64) -> DVec2 {
    let mut p = c.clone();
    while p.len() > 1 {
        p = p.windows(2).map(|w| w[0] * (1.0 - s) + w[1] * s).collect();
    }
    p[0]
}

/// The distance from `q` to the curve `c`.
fn curve_dist(c: &Curve, q: DVec2) -> f64 {
    let n = 64;
    let d = |s: f64| (bez(c, s) - q).length_squared();
    let best = (0..=n).min_by(|&a, &b| d(a as f64 / n as f64).total_cmp(&d(b as f64 / n as f64)));
    let k = best.unwrap_or(0) as f64;
    let (mut lo, mut hi) = (
        ((k - 1.0) / n as f64).max(0.0),
        ((k + 1.0) / n as f64).min(1.0),
    );
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..120 {
        let a = hi - g * (hi - lo);
        let b = lo + g * (hi - lo);
        if d(a) < d(b) {
            hi = b;
        } else {
            lo = a;
        }
    }
    d(0.5 * (lo + hi)).min(d(0.0)).min(d(1.0)).sqrt()
}

/// A 2-D outline with its fill rule, as dense polylines for membership.
struct Outline {
    curves: Vec<Curve>,
    poly: Vec<(DVec2, DVec2)>,
    nonzero: bool,
}

impl Outline {
    fn new(curves: Vec<Curve>, nonzero: bool) -> Outline {
        let mut poly = Vec::new();
        for c in &curves {
            let n = if c.len() == 2 { 1 } else { 400 };
            for i in 0..n {
                poly.push((
                    bez(c, i as f64 / n as f64),
                    bez(c, (i + 1) as f64 / n as f64),
                ));
            }
        }
        Outline {
            curves,
            poly,
            nonzero,
        }
    }

    fn dist(&self, q: DVec2) -> f64 {
        self.curves
            .iter()
            .map(|c| curve_dist(c, q))
            .fold(f64::INFINITY, f64::min)
    }

    fn inside(&self, q: DVec2) -> bool {
        let mut w = 0i32;
        for (a, b) in &self.poly {
            if (a.y > q.y) != (b.y > q.y) {
                let x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if q.x < x {
                    w += if b.y > a.y { 1 } else { -1 };
                }
            }
        }
        if self.nonzero { w != 0 } else { w % 2 != 0 }
    }
}

/// How the outline is swept, in the shape's object space.
#[derive(Clone, Copy)]
enum Frame {
    /// Outline in x–z, swept up y from h0 to h1 (straight or conic).
    Prism { h0: f64, h1: f64, conic: bool },
    /// Outline in x–y, extruded from z = 0 back to −thickness.
    Text { thickness: f64 },
}

struct Case {
    name: &'static str,
    shape: Shape,
    outline: Outline,
    frame: Frame,
    aim: (DVec3, DVec3),
    size: f64,
    rays: usize,
    min_hit_share: f64,
}

impl Case {
    /// (2-D point in outline units, height, height range, scale of the outline at that height).
    fn split(&self, q: DVec3) -> (DVec2, f64, f64, f64, f64) {
        match self.frame {
            Frame::Prism { h0, h1, conic } => {
                let s = if conic { q.y } else { 1.0 };
                (DVec2::new(q.x, q.z) / s, q.y, h0, h1, s)
            }
            Frame::Text { thickness } => (DVec2::new(q.x, q.y), -q.z, 0.0, thickness, 1.0),
        }
    }

    /// The distance to the surface (horizontal on a conic prism's sides: within a constant
    /// factor of the true distance).
    fn dist(&self, q: DVec3) -> f64 {
        let (p, h, h0, h1, s) = self.split(q);
        let tol = 1e-7 * self.size;
        let mut d = f64::INFINITY;
        if h >= h0 - tol && h <= h1 + tol {
            d = d.min(self.outline.dist(p) * s.abs());
        }
        for hc in [h0, h1] {
            let (pc, sc) = match self.frame {
                Frame::Prism { conic: true, .. } => (DVec2::new(q.x, q.z) / hc, hc),
                _ => (p, 1.0),
            };
            if hc != 0.0 || sc == 1.0 {
                let on = self.outline.inside(pc) || self.outline.dist(pc) * sc < tol;
                if on {
                    d = d.min((h - hc).abs());
                }
            }
        }
        d
    }

    fn outside(&self, q: DVec3) -> bool {
        let (p, h, h0, h1, s) = self.split(q);
        !(h >= h0 && h <= h1 && s > 0.0 && self.outline.inside(p))
    }
}

fn line(a: [f64; 2], b: [f64; 2]) -> Curve {
    vec![DVec2::from(a), DVec2::from(b)]
}

fn cases() -> Vec<Case> {
    let mut v = Vec::new();
    // A square frame (a square hole), linear spline: POV-Ray's even-odd rule.
    let sq = |r: f64| {
        [[-r, -r], [r, -r], [r, r], [-r, r], [-r, -r]]
            .map(DVec2::from)
            .to_vec()
    };
    let mut pts = sq(1.0);
    pts.extend(sq(0.45));
    let curves = (0..4)
        .chain(5..9)
        .map(|i| line(pts[i].into(), pts[i + 1].into()))
        .collect();
    v.push(Case {
        name: "prism linear frame",
        shape: Shape::Prism {
            points: pts,
            heights: [-0.3, 0.6],
            spline: Spline::Linear,
            sweep: PrismSweep::Linear,
        },
        outline: Outline::new(curves, false),
        frame: Frame::Prism {
            h0: -0.3,
            h1: 0.6,
            conic: false,
        },
        aim: (DVec3::new(-1.0, -0.3, -1.0), DVec3::new(1.0, 0.6, 1.0)),
        size: 2.5,
        rays: 10_000,
        min_hit_share: 0.4,
    });
    // A Bézier blob with a Bézier hole.
    let b = |p: [[f64; 2]; 4]| p.map(DVec2::from).to_vec();
    let blob = vec![
        b([[-1.0, 0.0], [-1.0, 0.8], [-0.5, 1.2], [0.0, 1.0]]),
        b([[0.0, 1.0], [0.6, 0.8], [1.3, 0.6], [1.0, 0.0]]),
        b([[1.0, 0.0], [0.8, -0.7], [0.4, -1.1], [0.0, -1.0]]),
        b([[0.0, -1.0], [-0.6, -1.2], [-1.1, -0.6], [-1.0, 0.0]]),
        b([[-0.4, -0.3], [-0.6, 0.0], [-0.5, 0.3], [-0.4, 0.4]]),
        b([[-0.4, 0.4], [0.0, 0.6], [0.2, 0.3], [0.4, 0.4]]),
        b([[0.4, 0.4], [0.5, 0.1], [0.4, 0.0], [0.4, -0.3]]),
        b([[0.4, -0.3], [0.1, -0.5], [-0.1, -0.1], [-0.4, -0.3]]),
    ];
    v.push(Case {
        name: "prism bezier with a hole",
        shape: Shape::Prism {
            points: blob.iter().flatten().copied().collect(),
            heights: [0.0, 0.4],
            spline: Spline::Bezier,
            sweep: PrismSweep::Linear,
        },
        outline: Outline::new(blob.clone(), false),
        frame: Frame::Prism {
            h0: 0.0,
            h1: 0.4,
            conic: false,
        },
        aim: (DVec3::new(-1.1, 0.0, -1.1), DVec3::new(1.2, 0.4, 1.1)),
        size: 2.5,
        rays: 10_000,
        min_hit_share: 0.4,
    });
    // The same blob swept conically: POV-Ray's quadratic and cubic splines are Bézier curves
    // in another basis, so a cubic-spline outline is checked through its Bézier form.
    // Catmull-Rom (POV-Ray's cubic) through p1..p2 with neighbours p0, p3, as a Bézier curve.
    let ring = [[0.0, -1.0], [1.2, 0.0], [0.0, 0.9], [-1.1, 0.0]].map(DVec2::from);
    let cubic: Vec<Curve> = (0..4)
        .map(|i| {
            let p = |k: usize| ring[(i + k) % 4];
            let (p0, p1, p2, p3) = (p(0), p(1), p(2), p(3));
            vec![p1, p1 + (p2 - p0) / 6.0, p2 - (p3 - p1) / 6.0, p2]
        })
        .collect();
    let mut cpts: Vec<DVec2> = (0..5).map(|k| ring[k % 4]).collect();
    cpts.extend([ring[1], ring[2]]);
    v.push(Case {
        name: "prism cubic conic",
        shape: Shape::Prism {
            points: cpts,
            heights: [0.4, 1.2],
            spline: Spline::Cubic,
            sweep: PrismSweep::Conic,
        },
        outline: Outline::new(cubic, false),
        frame: Frame::Prism {
            h0: 0.4,
            h1: 1.2,
            conic: true,
        },
        aim: (DVec3::new(-1.3, 0.4, -1.2), DVec3::new(1.4, 1.2, 1.1)),
        size: 3.0,
        rays: 10_000,
        min_hit_share: 0.3,
    });
    // Text: the glyphs of "Bg%" laid out by the language, checked against their curves with
    // TrueType's nonzero rule.
    let mut sources = SourceMap::new();
    let loaded = load_source(
        Path::new("t.rtc"),
        "rtc 1.1\ncamera { eye: [0, 0, 5] }\ntext(string: \"Bg%\", thickness: 0.3)\n",
        &mut sources,
        &EvalOptions::default(),
    );
    let scene = loaded.scene.expect("the text scene evaluates");
    let shape = scene.objects[0].shape.clone();
    let Shape::Text { glyphs, .. } = &shape else {
        panic!("not a text: {shape:?}");
    };
    let curves: Vec<Curve> = glyphs
        .glyphs
        .iter()
        .flatten()
        .map(|c| match c {
            GlyphCurve::Line(p) => p.to_vec(),
            GlyphCurve::Quad(p) => p.to_vec(),
            GlyphCurve::Cubic(p) => p.to_vec(),
        })
        .collect();
    v.push(Case {
        name: "text Bg%",
        shape,
        outline: Outline::new(curves, true),
        frame: Frame::Text { thickness: 0.3 },
        aim: (DVec3::new(0.0, -0.25, -0.3), DVec3::new(2.2, 0.8, 0.0)),
        size: 2.2,
        rays: 4_000,
        min_hit_share: 0.2,
    });
    v
}

fn check(case: &Case, xf: DAffine3, seed: u64) {
    let w = world(vec![object(case.shape.clone(), xf)]);
    let inv = xf.inverse();
    let world_scale = case.size
        * xf.matrix3
            .x_axis
            .norm()
            .max(xf.matrix3.y_axis.norm())
            .max(xf.matrix3.z_axis.norm());
    let aim = rtc::geometry::Aabb::new(case.aim.0, case.aim.1).transformed(&xf);
    let bounds = w.bounds();
    let mut rng = Rng(seed);
    let mut hits = 0;
    for i in 0..case.rays {
        let ray = ray_at_box(&mut rng, aim.min, aim.max);
        let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        hits += 1;
        let ctx = format!("{} ray {i}: {ray:?} hit t = {}", case.name, h.t);
        assert!(
            h.t.is_finite() && h.point.is_finite() && h.normal.is_finite(),
            "{ctx}: NaN"
        );
        let q = inv.transform_point3(h.point);
        let d = case.dist(q);
        assert!(d < 1e-9 * case.size, "{ctx}: off the surface by {d:e}");
        assert!(
            (h.normal.norm() - 1.0).abs() < 1e-12,
            "{ctx}: |n| = {}",
            h.normal.norm()
        );
        let eps = 1e-6 * world_scale;
        let out = inv.transform_point3(h.point + eps * h.normal);
        assert!(case.outside(out), "{ctx}: the normal points inward");
        assert!(
            bounds.contains(h.point, 1e-9 * world_scale),
            "{ctx}: outside the bounds {bounds:?}"
        );
        let dir = loop {
            let d = hemisphere(&mut rng, h.normal);
            if d.dot(h.normal) > 0.2 {
                break d;
            }
        };
        let again = Ray::new(h.point + 1e-7 * world_scale * h.normal, dir);
        // Glyphs have concave corners: a ray leaving a wall near one may meet the other wall
        // there; meeting the surface it left (a normal within 8°) is the failure.
        if let Some(h2) = w
            .intersect(&again, 0.0, 1e-4 * world_scale)
            .filter(|h2| h2.normal.dot(h.normal) > 0.99)
        {
            panic!(
                "{ctx}: re-hit its own surface at t = {:e} (point {:?} normal {:?}; again {:?} normal {:?} dir {dir:?})",
                h2.t,
                q,
                h.normal,
                inv.transform_point3(h2.point),
                h2.normal
            );
        }
    }
    let share = hits as f64 / case.rays as f64;
    let want = case.min_hit_share * if xf == DAffine3::IDENTITY { 1.0 } else { 0.4 };
    assert!(share >= want, "{}: only {share} of rays hit", case.name);
}

#[test]
fn prisms_and_text_keep_the_shape_invariants() {
    for (k, case) in cases().iter().enumerate() {
        check(case, DAffine3::IDENTITY, 3000 + k as u64);
    }
}

#[test]
fn prisms_and_text_keep_the_shape_invariants_when_mirrored_and_skewed() {
    for (k, case) in cases().iter().enumerate() {
        check(case, mirrored_transform(), 4000 + k as u64);
    }
}

/// A flat-lit prism with a cylinder drilled through it: the hole shows the background where
/// the hole is, the prism's colour around it (CSG classifies with the prism's crossings).
#[test]
fn a_prism_drilled_by_a_cylinder_shows_the_hole() {
    let src = "rtc 1.1\n\
        camera { eye: [0, 10, 0], center: [0, 0, 0], up: Z, projection: \"orthographic\", height: 4, resolution: [40, 40] }\n\
        point_light { position: [0, 100, 0] }\n\
        (prism(points: [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5], [-1.5, -1.5]], heights: [0, 1])\n\
          - cylinder(base: [0, -1, 0], top: [0, 2, 0], radius: 0.8))\n\
          .material(material { color: rgb(1, 0, 0), ka: 1, kd: 0, ks: 0 })\n\
        render { shadows: false, max_depth: 0, background: rgb(0, 0, 1) }\n";
    let img = numerics_support::render_rtc(src);
    let px = |x: u32, y: u32| img.get_pixel(x, y).0;
    // Pixel (i, j) looks down at x, z = ±(i + 0.5 − 20)/10: the middle is in the hole, a
    // point 1.2 from the axis on the prism, a point 1.8 away beyond it.
    assert_eq!(px(20, 20)[..3], [0, 0, 255], "the hole");
    assert_eq!(px(32, 20)[..3], [255, 0, 0], "the prism around the hole");
    assert_eq!(px(38, 20)[..3], [0, 0, 255], "beside the prism");
}

/// The same scene of prisms and text scaled by 10⁻⁶ … 10⁸ renders the image it renders at
/// scale 1 but for at most 0.1 % of its pixels (rounding at silhouettes).
#[test]
fn prisms_and_text_render_the_same_at_every_scale() {
    use numerics_support::{assert_same_at_scales, at};
    let scene = |s: f64| {
        let p = |x: [f64; 3]| at(s, [0.0; 3], x);
        format!(
            "rtc 1.1\n\
             camera {{ eye: {}, center: {}, fov: 40deg, resolution: [120, 90] }}\n\
             render {{ max_depth: 2 }}\n\
             point_light {{ position: {} }}\n\
             plane(point: {}, normal: Y).material(material {{ color: rgb(0.8, 0.8, 0.7), reflect: 0.2 }})\n\
             prism(points: [[0, -1], [1.2, 0], [0, 0.9], [-1.1, 0], [0, -1], [1.2, 0], [0, 0.9]], heights: [0.4, 1.2], spline: \"cubic\", sweep: \"conic\").scale({s:e}).translate({}).material(material {{ color: rgb(0.3, 0.5, 0.9) }})\n\
             prism(points: [[-1, -1], [1, -1], [1, 1], [-1, 1], [-1, -1], [-0.4, -0.4], [0.4, -0.4], [0.4, 0.4], [-0.4, 0.4], [-0.4, -0.4]], heights: [0, 0.5]).scale({s:e}).translate({}).material(material {{ color: rgb(0.9, 0.3, 0.2) }})\n\
             text(string: \"Bg%\", thickness: 0.3, align: \"center\").scale({:e}).translate({}).material(material {{ color: rgb(0.3, 0.8, 0.3) }})\n",
            p([0.0, 2.5, 6.0]),
            p([0.0, 0.6, 0.0]),
            p([4.0, 6.0, 5.0]),
            p([0.0, 0.0, 0.0]),
            p([1.6, 0.0, -0.5]),
            p([-1.6, 0.0, 0.0]),
            1.5 * s,
            p([0.0, 0.1, 1.2]),
        )
    };
    assert_same_at_scales(&[1e-6, 1e-4, 1e-2, 3.7, 1e2, 1e4, 1e6, 1e8], scene);
}
