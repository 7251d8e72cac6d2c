//! Object constructors with schema-checked parameters, groups, and the CSG list forms.

use std::rc::Rc;

use glam::{DAffine3, DVec3};

use super::builtins::{BuiltinFn, Params, check, positive};
use super::call::{ArgVal, CallSite};
use super::error::{R, error};
use super::interp::Interp;
use super::types;
use super::value::{Obj, ObjShape, Value, obj_kind};
use crate::ir::{BlobComponent, CsgOp, Shape};
use crate::source::Span;

/// Object constructors.
pub const FNS: &[(&str, BuiltinFn)] = &[
    ("sphere", sphere),
    ("plane", plane),
    ("box", box_),
    ("triangle", triangle),
    ("quad", quad),
    ("polygon", polygon),
    ("disk", disk),
    ("cylinder", cylinder),
    ("cone", cone),
    ("torus", torus),
    ("blob", blob),
    ("mesh", mesh),
    ("group", group),
    ("union", union),
    ("intersection", intersection),
    ("difference", difference),
];

fn prim(shape: Shape, span: Span) -> Value {
    Value::Object(Rc::new(Obj {
        shape: ObjShape::Prim(shape),
        transform: DAffine3::IDENTITY,
        material: None,
        span,
    }))
}

fn unit_dir(it: &Interp, p: &mut Params, name: &str, default: DVec3) -> R<DVec3> {
    match p.get(name) {
        None => Ok(default),
        Some((v, sp)) => {
            let d = types::vec3(it, &v, sp)?;
            if d.length_squared() == 0.0 || !d.is_finite() {
                return Err(error(
                    "rtc::param::out_of_range",
                    sp,
                    format!("`{name}` must be a non-zero vector"),
                )
                .with_label("this vector has length 0")
                .with_help(format!("give a direction, e.g. `{name}: Y`"))
                .into());
            }
            Ok(d.normalize())
        }
    }
}

fn sphere(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["center", "radius"], a)?;
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    let (radius, rs) = p.num_or(it, "radius", 1.0)?;
    positive("radius", radius, rs)?;
    Ok(prim(Shape::Sphere { center, radius }, s.span))
}

fn plane(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["point", "normal"], a)?;
    let point = p.vec3_or(it, "point", DVec3::ZERO)?;
    let normal = unit_dir(it, &mut p, "normal", DVec3::Y)?;
    Ok(prim(Shape::Plane { point, normal }, s.span))
}

fn box_(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["min", "max"], a)?;
    let min = p.vec3_or(it, "min", DVec3::splat(-0.5))?;
    let (max, ms) = match p.get("max") {
        Some((v, sp)) => (types::vec3(it, &v, sp)?, sp),
        None => (DVec3::splat(0.5), s.span),
    };
    if !max.cmpgt(min).all() {
        return Err(error(
            "rtc::param::out_of_range",
            ms,
            "`max` must be greater than `min` on every axis",
        )
        .with_label(format!(
            "max = {} but min = {}",
            Value::Vec3(max).show(),
            Value::Vec3(min).show()
        ))
        .with_help("swap the corners or fix the smaller coordinate")
        .into());
    }
    Ok(prim(Shape::Box { min, max }, s.span))
}

fn triangle(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["a", "b", "c"], a)?;
    let (va, _) = p.vec3(it, "a")?;
    let (vb, _) = p.vec3(it, "b")?;
    let (vc, cs) = p.vec3(it, "c")?;
    if (vb - va).cross(vc - va).length_squared() == 0.0 {
        return Err(
            error("rtc::param::degenerate", cs, "the triangle has zero area")
                .with_label("its corners lie on one line")
                .with_help("move one corner off the line through the other two")
                .into(),
        );
    }
    Ok(prim(
        Shape::Triangle {
            vertices: [va, vb, vc],
        },
        s.span,
    ))
}

fn quad(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["corner", "u", "v"], a)?;
    let corner = p.vec3_or(it, "corner", DVec3::ZERO)?;
    let (u, _) = p.vec3(it, "u")?;
    let (v, vs) = p.vec3(it, "v")?;
    if u.cross(v).length_squared() == 0.0 {
        return Err(
            error("rtc::param::degenerate", vs, "the quad has zero area")
                .with_label("`u` and `v` are parallel or zero")
                .with_help("use two edges that span a parallelogram")
                .into(),
        );
    }
    Ok(prim(Shape::Quad { corner, u, v }, s.span))
}

fn polygon(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["points"], a)?;
    let (v, sp) = p.req("points")?;
    let items: Vec<Value> = match &v {
        Value::List(l) => l.to_vec(),
        other => return Err(types::mismatch(it, "List", other, sp).into()),
    };
    if items.len() < 3 {
        return Err(error(
            "rtc::param::out_of_range",
            sp,
            format!("a polygon needs at least 3 points, found {}", items.len()),
        )
        .with_label("too few points")
        .with_help("list three or more corners")
        .into());
    }
    let mut points = Vec::with_capacity(items.len());
    for x in &items {
        points.push(types::vec3(it, x, sp)?);
    }
    Ok(prim(Shape::Polygon { points }, s.span))
}

fn disk(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["center", "normal", "radius"], a)?;
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    let normal = unit_dir(it, &mut p, "normal", DVec3::Y)?;
    let (radius, rs) = p.num_or(it, "radius", 1.0)?;
    positive("radius", radius, rs)?;
    Ok(prim(
        Shape::Disk {
            center,
            normal,
            radius,
        },
        s.span,
    ))
}

/// Reads `base`/`top`, or `center`/`axis`/`height` (centred on `center` along `axis`).
fn ends(it: &Interp, p: &mut Params) -> R<(DVec3, DVec3)> {
    let base = p.get("base");
    let top = p.get("top");
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    let axis = unit_dir(it, p, "axis", DVec3::Y)?;
    let (height, hs) = p.num_or(it, "height", 1.0)?;
    positive("height", height, hs)?;
    Ok(match (base, top) {
        (Some((b, bs)), Some((t, ts))) => {
            let (b, t) = (types::vec3(it, &b, bs)?, types::vec3(it, &t, ts)?);
            if b == t {
                return Err(error("rtc::param::degenerate", ts, "`top` equals `base`")
                    .with_label("zero height")
                    .with_help("move `top` away from `base`")
                    .into());
            }
            (b, t)
        }
        (Some((b, bs)), None) => {
            let b = types::vec3(it, &b, bs)?;
            (b, b + axis * height)
        }
        (None, Some((t, ts))) => {
            let t = types::vec3(it, &t, ts)?;
            (t - axis * height, t)
        }
        (None, None) => (
            center - axis * (height / 2.0),
            center + axis * (height / 2.0),
        ),
    })
}

fn cylinder(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(
        s,
        &[
            "radius", "base", "top", "center", "axis", "height", "capped",
        ],
        a,
    )?;
    let (radius, rs) = p.num_or(it, "radius", 1.0)?;
    positive("radius", radius, rs)?;
    let (base, top) = ends(it, &mut p)?;
    let capped = p.bool_or(it, "capped", true)?;
    Ok(prim(
        Shape::Cylinder {
            base,
            top,
            radius,
            capped,
        },
        s.span,
    ))
}

fn cone(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(
        s,
        &[
            "base_radius",
            "top_radius",
            "base",
            "top",
            "center",
            "axis",
            "height",
            "capped",
        ],
        a,
    )?;
    let (br, bs) = p.num_or(it, "base_radius", 1.0)?;
    let (tr, ts) = p.num_or(it, "top_radius", 0.0)?;
    check(br >= 0.0, "base_radius", ">= 0", br, bs)?;
    check(tr >= 0.0, "top_radius", ">= 0", tr, ts)?;
    if br == 0.0 && tr == 0.0 {
        return Err(error(
            "rtc::param::degenerate",
            bs,
            "a cone needs a non-zero radius at one end",
        )
        .with_label("both radii are 0")
        .with_help("set `base_radius` greater than 0")
        .into());
    }
    let (base, top) = ends(it, &mut p)?;
    let capped = p.bool_or(it, "capped", true)?;
    Ok(prim(
        Shape::Cone {
            base,
            top,
            base_radius: br,
            top_radius: tr,
            capped,
        },
        s.span,
    ))
}

fn torus(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["major_radius", "minor_radius", "center"], a)?;
    let (major, ms) = p.num(it, "major_radius")?;
    let (minor, ns) = p.num(it, "minor_radius")?;
    positive("major_radius", major, ms)?;
    positive("minor_radius", minor, ns)?;
    check(
        minor < major,
        "minor_radius",
        &format!("< major_radius ({})", super::value::fmt_f(major)),
        minor,
        ns,
    )?;
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    Ok(prim(
        Shape::Torus {
            center,
            major_radius: major,
            minor_radius: minor,
        },
        s.span,
    ))
}

fn blob(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["components", "threshold"], a)?;
    let (v, sp) = p.req("components")?;
    let Value::List(items) = &v else {
        return Err(types::mismatch(it, "List", &v, sp).into());
    };
    if items.is_empty() {
        return Err(error(
            "rtc::param::out_of_range",
            sp,
            "a blob needs at least one component",
        )
        .with_label("empty list")
        .with_help("add `{ center: [0, 0, 0], radius: 1, strength: 1 }`")
        .into());
    }
    let mut components = Vec::with_capacity(items.len());
    for c in items.iter() {
        let site = CallSite {
            span: sp,
            name: "blob component",
        };
        let arg = ArgVal {
            name: None,
            value: c.clone(),
            span: sp,
        };
        let mut cp = Params::new(site, &["center", "radius", "strength"], vec![arg])?;
        let center = cp.vec3_or(it, "center", DVec3::ZERO)?;
        let (radius, rs) = cp.num_or(it, "radius", 1.0)?;
        positive("radius", radius, rs)?;
        let (strength, _) = cp.num_or(it, "strength", 1.0)?;
        components.push(BlobComponent {
            center,
            radius,
            strength,
        });
    }
    let (threshold, ts) = p.num_or(it, "threshold", 0.5)?;
    positive("threshold", threshold, ts)?;
    Ok(prim(
        Shape::Blob {
            components,
            threshold,
        },
        s.span,
    ))
}

fn mesh(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["path", "smooth", "use_mtl"], a)?;
    let (pv, ps) = p.req("path")?;
    let rel = types::string(it, &pv, ps)?;
    let path = super::assets::existing(it, &rel, ps, "mesh")?;
    only_obj(&path, ps)?;
    let smooth = p.bool_or(it, "smooth", false)?;
    let use_mtl = p.bool_or(it, "use_mtl", false)?;
    Ok(prim(
        Shape::Mesh {
            path,
            smooth,
            use_mtl,
        },
        s.span,
    ))
}

/// Meshes are Wavefront OBJ: another format (STL, PLY, glTF...) is refused by its extension
/// before anyone tries to read it as OBJ.
fn only_obj(path: &std::path::Path, span: Span) -> R<()> {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    if ext == "obj" {
        return Ok(());
    }
    Err(crate::eval::error::error(
        "rtc::asset::format",
        span,
        format!("`{}` is not a Wavefront OBJ file", path.display()),
    )
    .with_label(if ext.is_empty() {
        "no `.obj` extension".to_owned()
    } else {
        format!("a `.{ext}` file")
    })
    .with_help(
        "only OBJ meshes are read; convert the model to `.obj` (e.g. with Blender or MeshLab)",
    )
    .into())
}

/// Flattens nested lists of objects (as `for` produces) into `out`.
pub fn collect_objects(it: &Interp, v: &Value, span: Span, out: &mut Vec<Obj>) -> R<()> {
    match v {
        Value::Object(o) => out.push((**o).clone()),
        Value::List(l) => {
            for x in l.iter() {
                collect_objects(it, x, span, out)?;
            }
        }
        Value::Unit => {}
        other => return Err(types::mismatch(it, "Object", other, span).into()),
    }
    Ok(())
}

fn object_list(it: &Interp, p: &mut Params, name: &str) -> R<(Vec<Obj>, Span)> {
    let (v, sp) = p.req(name)?;
    let mut out = Vec::new();
    collect_objects(it, &v, sp, &mut out)?;
    Ok((out, sp))
}

fn group(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["children"], a)?;
    let (children, _) = object_list(it, &mut p, "children")?;
    Ok(Value::Object(Rc::new(Obj {
        shape: ObjShape::Group(Rc::new(children)),
        transform: DAffine3::IDENTITY,
        material: None,
        span: s.span,
    })))
}

fn csg_node(it: &Interp, op: CsgOp, children: Vec<Obj>, sp: Span, s: CallSite) -> R<Value> {
    if children.len() < 2 {
        return Err(error(
            "rtc::csg::operands",
            sp,
            format!(
                "`{}` needs at least two objects, found {}",
                s.name,
                children.len()
            ),
        )
        .with_label("too few operands")
        .with_help("pass a list of two or more objects")
        .into());
    }
    for c in &children {
        require_closed(it, c, sp)?;
    }
    Ok(Value::Object(Rc::new(Obj {
        shape: ObjShape::Csg(op, Rc::new(children)),
        transform: DAffine3::IDENTITY,
        material: None,
        span: s.span,
    })))
}

fn union(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["objects", "merge"], a)?;
    let (children, sp) = object_list(it, &mut p, "objects")?;
    let op = if p.bool_or(it, "merge", false)? {
        CsgOp::Merge
    } else {
        CsgOp::Union
    };
    csg_node(it, op, children, sp, s)
}

fn intersection(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["objects"], a)?;
    let (children, sp) = object_list(it, &mut p, "objects")?;
    csg_node(it, CsgOp::Intersection, children, sp, s)
}

fn difference(it: &mut Interp, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["base", "cutters"], a)?;
    let (bv, bs) = p.req("base")?;
    let Value::Object(base) = &bv else {
        return Err(types::mismatch(it, "Object", &bv, bs).into());
    };
    let (cutters, sp) = object_list(it, &mut p, "cutters")?;
    let mut children = vec![(**base).clone()];
    children.extend(cutters);
    csg_node(it, CsgOp::Difference, children, sp, s)
}

/// CSG needs solids with an inside: open surfaces are rejected.
pub fn require_closed(it: &Interp, o: &Obj, span: Span) -> R<()> {
    let _ = it;
    let open = match &o.shape {
        ObjShape::Prim(
            Shape::Triangle { .. }
            | Shape::Quad { .. }
            | Shape::Polygon { .. }
            | Shape::Disk { .. },
        ) => true,
        ObjShape::Prim(Shape::Cylinder { capped, .. } | Shape::Cone { capped, .. }) => !capped,
        ObjShape::Group(ch) => {
            for c in ch.iter() {
                require_closed(it, c, span)?;
            }
            false
        }
        _ => false,
    };
    if open {
        let mut d = error("rtc::csg::open_operand", span, format!("a {} has no inside, so it cannot take part in CSG", obj_kind(o)))
            .with_label("an open surface")
            .with_help("use a closed solid (sphere, box, capped cylinder, torus, ...), or a `group` instead of CSG");
        if o.span != span {
            d = d.with_secondary(o.span, "made here");
        }
        return Err(d.into());
    }
    Ok(())
}
