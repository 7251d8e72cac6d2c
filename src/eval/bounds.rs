//! `obj.bounds`: world-space axis-aligned bounds of an object value, as a record with `min`,
//! `max`, `center`, `size`, `top_center` and `bottom_center` (top and bottom along +Y).

use glam::{DAffine3, DVec3};

use crate::ir::{CsgOp, Shape};
use crate::source::Span;

use super::error::{R, error};
use super::interp::Interp;
use super::value::{Obj, ObjShape, Value};

type Bb = (DVec3, DVec3);

fn transformed(t: DAffine3, (lo, hi): Bb) -> Bb {
    let mut out = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for i in 0..8 {
        let c = DVec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        );
        let p = t.transform_point3(c);
        out = (out.0.min(p), out.1.max(p));
    }
    out
}

fn of_points(pts: impl IntoIterator<Item = DVec3>) -> Bb {
    pts.into_iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |b, p| (b.0.min(p), b.1.max(p)),
    )
}

fn disk_extent(normal: DVec3, r: f64) -> DVec3 {
    // Half-extent of a disk of radius r with unit normal n along each axis: r·sqrt(1 − n_i²).
    r * (DVec3::ONE - normal * normal).max(DVec3::ZERO).powf(0.5)
}

/// A mesh's vertex bounds, through the asset service (which keeps the load for the render; no
/// BVH is built to answer).
fn mesh_bounds(path: &std::path::Path, smooth: bool, span: Span) -> R<Bb> {
    let mesh = crate::assets::mesh(path, smooth).map_err(|e| e.diagnostic(span, path))?;
    Ok((mesh.min, mesh.max))
}

fn unbounded(span: Span) -> super::error::EvalError {
    error(
        "rtc::value::unbounded",
        span,
        "this object has no finite bounds",
    )
    .with_label("it contains an infinite plane")
    .with_help("ask for the bounds of a finite part instead")
    .into()
}

/// Bounds in the space the object's own transform maps into, composed with `parent`.
fn bb(o: &Obj, parent: DAffine3, span: Span) -> R<Bb> {
    let t = parent * o.transform;
    let local = match &o.shape {
        ObjShape::Prim(s) => match s {
            Shape::Sphere { center, radius } => (*center - *radius, *center + *radius),
            Shape::Plane { .. } => return Err(unbounded(span)),
            Shape::Box { min, max } => (*min, *max),
            Shape::Triangle { vertices } => of_points(vertices.iter().copied()),
            Shape::Quad { corner, u, v } => {
                of_points([*corner, *corner + *u, *corner + *v, *corner + *u + *v])
            }
            Shape::Polygon { points } => of_points(points.iter().copied()),
            Shape::Disk {
                center,
                normal,
                radius,
            } => {
                let e = disk_extent(*normal, *radius);
                (*center - e, *center + e)
            }
            Shape::Cylinder {
                base, top, radius, ..
            } => {
                let n = (*top - *base).normalize_or_zero();
                let e = disk_extent(n, *radius);
                of_points([*base - e, *base + e, *top - e, *top + e])
            }
            Shape::Cone {
                base,
                top,
                base_radius,
                top_radius,
                ..
            } => {
                let n = (*top - *base).normalize_or_zero();
                let (eb, et) = (disk_extent(n, *base_radius), disk_extent(n, *top_radius));
                of_points([*base - eb, *base + eb, *top - et, *top + et])
            }
            Shape::Torus {
                center,
                major_radius,
                minor_radius,
            } => {
                let r = major_radius + minor_radius;
                (
                    *center - DVec3::new(r, *minor_radius, r),
                    *center + DVec3::new(r, *minor_radius, r),
                )
            }
            Shape::Blob { components, .. } => of_points(
                components
                    .iter()
                    .flat_map(|c| [c.center - c.radius, c.center + c.radius]),
            ),
            Shape::Mesh { path, smooth, .. } => mesh_bounds(path, *smooth, span)?,
            Shape::Csg { .. } => unreachable!("CSG values use ObjShape::Csg"),
        },
        ObjShape::Group(ch) | ObjShape::Csg(CsgOp::Union | CsgOp::Merge, ch) => {
            let mut b = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
            for c in ch.iter() {
                let cb = bb(c, t, span)?;
                b = (b.0.min(cb.0), b.1.max(cb.1));
            }
            return Ok(b);
        }
        ObjShape::Csg(CsgOp::Difference, ch) => return bb(&ch[0], t, span),
        ObjShape::Csg(CsgOp::Intersection, ch) => {
            let mut b = (DVec3::splat(f64::NEG_INFINITY), DVec3::splat(f64::INFINITY));
            let mut any = false;
            for c in ch.iter() {
                if let Ok(cb) = bb(c, t, span) {
                    b = (b.0.max(cb.0), b.1.min(cb.1));
                    any = true;
                }
            }
            if !any {
                return Err(unbounded(span));
            }
            return Ok((b.0, b.1.max(b.0)));
        }
    };
    Ok(transformed(t, local))
}

/// The `bounds` record of an object.
pub fn bounds_value(_it: &mut Interp, o: &Obj, span: Span) -> R<Value> {
    let (lo, hi) = bb(o, DAffine3::IDENTITY, span)?;
    let c = (lo + hi) / 2.0;
    Ok(super::members::record_of(
        &[
            ("min", Value::Vec3(lo)),
            ("max", Value::Vec3(hi)),
            ("center", Value::Vec3(c)),
            ("size", Value::Vec3(hi - lo)),
            ("top_center", Value::Vec3(DVec3::new(c.x, hi.y, c.z))),
            ("bottom_center", Value::Vec3(DVec3::new(c.x, lo.y, c.z))),
        ],
        span,
    ))
}
