//! Lights: where a light is, its shape (a point, a parallelogram or a direction), its colour,
//! and what shapes its light on the way (a spot cone, fading with distance, shadows or none),
//! after POV-Ray 3.7's `light_source`.

use glam::DVec3;

use crate::source::Span;

/// A light source with an RGB intensity.
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Where and what shape.
    pub kind: LightKind,
    /// RGB intensity; may exceed 1.
    pub color: DVec3,
    /// Where it was defined.
    pub span: Span,
    /// A spot light's cone (`None`: it shines every way).
    pub spot: Option<Spot>,
    /// Fading with distance (`None`: the same at every distance).
    pub fade: Option<Fade>,
    /// Whether objects cast shadows from it (false: POV-Ray's `shadowless` fill light).
    pub shadows: bool,
}

impl Light {
    /// A light of `kind` and `color` that shines every way, does not fade and casts shadows.
    pub fn new(kind: LightKind, color: DVec3, span: Span) -> Light {
        Light {
            kind,
            color,
            span,
            spot: None,
            fade: None,
            shadows: true,
        }
    }
}

/// A spot light's cone, POV-Ray's `spotlight`: full strength within `radius` of the axis,
/// falling to 0 at `falloff` along the smoothstep of the angle's cosine, and the whole times
/// `cos^tightness` of the angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spot {
    /// The point the axis goes through, as written.
    pub target: DVec3,
    /// The unit axis, from the light towards `target`.
    pub axis: DVec3,
    /// The half-angle of full strength, in radians.
    pub radius: f64,
    /// The half-angle where the light ends, in radians (≥ `radius`).
    pub falloff: f64,
    /// The exponent of the cosine over the whole cone (0: none).
    pub tightness: f64,
}

impl Spot {
    /// The share of the light reaching a point in unit direction `towards` from the light:
    /// POV-Ray's `Attenuate_Light` for a spot source.
    pub fn share(&self, towards: DVec3) -> f64 {
        let cos = towards.dot(self.axis);
        if cos <= 0.0 {
            return 0.0;
        }
        let mut share = if self.tightness == 0.0 {
            1.0
        } else {
            libm::pow(cos, self.tightness)
        };
        let (inner, outer) = (libm::cos(self.radius), libm::cos(self.falloff));
        if cos < inner {
            // POV-Ray's cubic spline between the two cosines.
            share *= if cos < outer || inner <= outer {
                0.0
            } else {
                let t = (cos - outer) / (inner - outer);
                (3.0 - 2.0 * t) * t * t
            };
        }
        share
    }
}

/// Fading with distance, POV-Ray's `fade_distance` and `fade_power`: the colour times
/// `2 / (1 + (d/D)^p)`, twice it at the light, itself at distance `D`, falling as `d^−p` far
/// away.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fade {
    /// The distance `D` (> 0) at which the light has its nominal strength.
    pub distance: f64,
    /// The power `p` (> 0): 1 linear, 2 the physical inverse square far away.
    pub power: f64,
}

impl Fade {
    /// The share of the light left at distance `d`.
    pub fn share(&self, d: f64) -> f64 {
        2.0 / (1.0 + libm::pow(d / self.distance, self.power))
    }
}

/// The geometry of a light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// A point light.
    Point {
        /// Position.
        position: DVec3,
    },
    /// A parallel light (a sun): light travelling along the unit `direction` everywhere,
    /// from infinitely far away (POV-Ray's `parallel`).
    Parallel {
        /// The unit direction the light travels in.
        direction: DVec3,
    },
    /// A parallelogram light `corner + s·u + t·v`, sampled on a `samples[0]×samples[1]` grid.
    Area {
        /// One corner.
        corner: DVec3,
        /// First edge.
        u: DVec3,
        /// Second edge.
        v: DVec3,
        /// Stratified sample counts along `u` and `v` (each ≥ 1).
        samples: [u32; 2],
        /// The light is the ellipse inscribed in the parallelogram (POV-Ray's `circular`): the
        /// grid is carried onto it by the equal-area concentric map.
        circular: bool,
        /// The disk turns to face each point it lights, keeping its radius `|u| / 2` (POV-Ray's
        /// `orient`; only with `circular`).
        orient: bool,
    },
    /// A cylinder light (POV-Ray's `cylinder`): light travelling along the unit `axis` in
    /// parallel beams, within a cylinder about the axis through `position`, starting at the
    /// plane through `position` across it.
    Cylinder {
        /// A point on the axis, where the light starts.
        position: DVec3,
        /// The point the axis goes through, as written.
        target: DVec3,
        /// The unit axis, from `position` towards `target`.
        axis: DVec3,
        /// Full strength within this distance of the axis.
        radius: f64,
        /// No light beyond this distance of the axis (≥ `radius`).
        falloff: f64,
        /// The exponent of `1 − distance / falloff` over the whole beam (0: none).
        tightness: f64,
    },
}

/// The share of a cylinder light of beam `radius`, `falloff` and `tightness` reaching a point at
/// distance `off_axis` from its axis: POV-Ray's `Attenuate_Light` for a cylinder source.
pub fn cylinder_share(radius: f64, falloff: f64, tightness: f64, off_axis: f64) -> f64 {
    if off_axis >= falloff {
        return 0.0;
    }
    let dist = 1.0 - off_axis / falloff;
    let mut share = if tightness == 0.0 {
        1.0
    } else {
        libm::pow(dist, tightness)
    };
    if radius > 0.0 && off_axis > radius {
        // POV-Ray's cubic spline from 0 at the falloff to 1 at the radius.
        let high = 1.0 - radius / falloff;
        share *= if dist >= high {
            1.0
        } else {
            let t = dist / high;
            (3.0 - 2.0 * t) * t * t
        };
    }
    share
}

/// How far away a parallel light's samples are placed (shadow rays aim there): far beyond any
/// scene the budgets allow, near enough that a direction to it keeps every bit of the light's.
pub const PARALLEL_DISTANCE: f64 = 1e12;

impl LightKind {
    /// The light's centre (its position for a point light).
    pub(crate) fn center(&self) -> DVec3 {
        match *self {
            LightKind::Point { position } => position,
            LightKind::Area { corner, u, v, .. } => corner + 0.5 * (u + v),
            LightKind::Cylinder { position, .. } => position,
            // A far point up the light, for the few who need a position (a lens flare).
            LightKind::Parallel { direction } => -PARALLEL_DISTANCE * direction,
        }
    }
}
