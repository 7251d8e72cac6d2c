//! Objects made of objects: `group` and the CSG constructors' list forms (`union`,
//! `intersection`, `difference`), with the rule their operands follow.

use std::rc::Rc;

use glam::DAffine3;

use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::{R, error};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Sig, Ty};
use crate::eval::types;
use crate::eval::value::{Obj, ObjShape, Value, obj_kind};
use crate::ir::CsgOp;
use crate::source::Span;

/// Group and CSG constructors with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&GROUP, group),
    (&UNION, union),
    (&INTERSECTION, intersection),
    (&DIFFERENCE, difference),
];

/// A list of objects (nested lists flatten).
const OBJECTS: Ty = Ty::ListOf(&Ty::Object);

/// Flattens nested lists of objects (as `for` produces) into `out`.
fn collect_objects(it: &dyn Host, v: &Value, span: Span, out: &mut Vec<Obj>) -> R<()> {
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

fn object_list(it: &dyn Host, p: &mut Params, name: &str) -> R<(Vec<Obj>, Span)> {
    let (v, sp) = p.req(name)?;
    let mut out = Vec::new();
    collect_objects(it, &v, sp, &mut out)?;
    Ok((out, sp))
}

/// `group(children)`.
static GROUP: Sig = Sig::new(
    "group",
    Group::Shape,
    "Objects as one value, moved and given a material as a whole.",
    &[Param::new(
        "children",
        OBJECTS,
        "the objects (nested lists flatten)",
    )],
    "Object",
)
.examples(&["group(children: [sphere(), box().translate([2, 0, 0])])"]);
fn group(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &GROUP, a)?;
    let (children, _) = object_list(it, &mut p, "children")?;
    Ok(Value::Object(Rc::new(Obj {
        shape: ObjShape::Group(Rc::new(children)),
        transform: DAffine3::IDENTITY,
        material: None,
        motion: None,
        span: s.span,
        origin: 0,
        visibility: crate::ir::Visibility::ALL,
    })))
}

fn csg_node(it: &dyn Host, op: CsgOp, children: Vec<Obj>, sp: Span, s: CallSite) -> R<Value> {
    if let Err(flaw) = crate::geometry::shapes::csg_operands(children.len()) {
        return Err(flaw.diagnostic(sp).into());
    }
    for c in &children {
        require_closed(it, c, sp)?;
    }
    Ok(Value::Object(Rc::new(Obj {
        shape: ObjShape::Csg(op, crate::eval::operands::Operands::new(children)),
        transform: DAffine3::IDENTITY,
        material: None,
        motion: None,
        span: s.span,
        origin: 0,
        visibility: crate::ir::Visibility::ALL,
    })))
}

/// The operands of `union` and `intersection`.
const OPERANDS: Param = Param::new("objects", OBJECTS, "closed solids, at least two");

/// `union(objects, merge)`.
static UNION: Sig = Sig::new(
    "union",
    Group::Shape,
    "Inside any operand (`a | b`).",
    &[
        OPERANDS,
        Param::new(
            "merge",
            Ty::Bool,
            "remove the internal surfaces (for transparent unions)",
        )
        .or(Lit::Bool(false)),
    ],
    "Object",
)
.examples(&["union(objects: [sphere(), sphere(center: [0.8, 0, 0])], merge: true)"]);
fn union(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &UNION, a)?;
    let (children, sp) = object_list(it, &mut p, "objects")?;
    let op = if p.bool(it, "merge")? {
        CsgOp::Merge
    } else {
        CsgOp::Union
    };
    csg_node(it, op, children, sp, s)
}

/// `intersection(objects)`.
static INTERSECTION: Sig = Sig::new(
    "intersection",
    Group::Shape,
    "Inside every operand (`a & b`).",
    &[OPERANDS],
    "Object",
)
.examples(&["intersection(objects: [sphere(radius: 0.7), box()])"]);
fn intersection(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &INTERSECTION, a)?;
    let (children, sp) = object_list(it, &mut p, "objects")?;
    csg_node(it, CsgOp::Intersection, children, sp, s)
}

/// `difference(base, cutters)`.
static DIFFERENCE: Sig = Sig::new(
    "difference",
    Group::Shape,
    "Inside `base` and outside every cutter (`a - b`).",
    &[
        Param::new("base", Ty::Object, "the closed solid to cut"),
        Param::new("cutters", OBJECTS, "the closed solids cut away"),
    ],
    "Object",
)
.examples(&["difference(base: box(), cutters: [sphere(radius: 0.6)])"]);
fn difference(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &DIFFERENCE, a)?;
    let (bv, bs) = p.req("base")?;
    let Value::Object(base) = &bv else {
        return Err(types::mismatch(it, "Object", &bv, bs).into());
    };
    let (cutters, sp) = object_list(it, &mut p, "cutters")?;
    let mut children = vec![(**base).clone()];
    children.extend(cutters);
    csg_node(it, CsgOp::Difference, children, sp, s)
}

/// CSG needs solids with an inside: open surfaces are rejected (geometry's rule,
/// `geometry::shapes::encloses_volume`).
pub(crate) fn require_closed(it: &dyn Host, o: &Obj, span: Span) -> R<()> {
    require_closed_to(it, o, span, "take part in CSG")
}

/// [`require_closed`] for a use other than CSG: `purpose` completes "so it cannot ...".
pub(crate) fn require_closed_to(it: &dyn Host, o: &Obj, span: Span, purpose: &str) -> R<()> {
    let _ = it;
    let open = match &o.shape {
        // A mesh file's closedness is checked when the preparation stage loads it.
        ObjShape::Prim(s) => !crate::geometry::shapes::encloses_volume(s, &|_, _| true),
        // A clipped surface is left open.
        ObjShape::Csg(CsgOp::Clip, _) => true,
        ObjShape::Group(ch) => {
            for c in ch.iter() {
                require_closed_to(it, c, span, purpose)?;
            }
            false
        }
        _ => false,
    };
    if open {
        let mut d = error("rtc::csg::open_operand", span, format!("a {} has no inside, so it cannot {purpose}", obj_kind(o)))
            .with_label("an open surface")
            .with_help("use a closed solid (sphere, box, capped cylinder, torus, ...), or a `group` instead of CSG");
        if o.span != span {
            d = d.with_secondary(o.span, "made here");
        }
        return Err(d.into());
    }
    Ok(())
}
