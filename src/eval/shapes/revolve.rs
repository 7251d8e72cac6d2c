//! Surfaces of revolution, superquadrics and algebraic surfaces: `lathe(points, spline)`,
//! `sor(points, open)`, `superellipsoid(e, n)`, `poly(order, coefficients)` and its shorthands `cubic` and
//! `quartic` (POV-Ray's shapes of those names; docs/language.md).

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::R;
use crate::eval::host::{BuiltinFn, Host};
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir::{Shape, Spline};
use crate::source::Span;

use super::common::{checked, choice, pairs};

/// The constructors of this file.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&LATHE, lathe),
    (&SOR, sor),
    (&SUPERELLIPSOID, superellipsoid),
    (&POLY, poly),
    (&CUBIC, cubic),
    (&QUARTIC, quartic),
];

/// `lathe(points, spline)`.
static LATHE: Sig = Sig::new(
    "lathe",
    Group::Shape,
    "A profile of `[r, y]` points joined by a spline, revolved about the Y axis (POV-Ray's \
     `lathe`); a closed profile bounds a solid.",
    &[
        Param::new(
            "points",
            Ty::ListOf(&Ty::Pair(&Ty::Float)),
            "the profile's `[r, y]` points, r >= 0 (enough for the spline)",
        )
        .unit(Unit::Length),
        Param::new(
            "spline",
            Ty::String,
            "\"linear\" (default), \"quadratic\", \"cubic\" (Catmull-Rom) or \"bezier\"",
        )
        .optional(),
    ],
    "Object",
)
.examples(&[
    "lathe(points: [[0, 0], [1, 0], [0.3, 1], [0, 2]])  // a top, its tip on the axis",
    "lathe(points: [[0, -1], [1, -1], [1, 1], [0, 1], [0, 1]], spline: \"quadratic\")",
]);
fn lathe(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &LATHE, a)?;
    let (points, sp) = pairs(it, &mut p, "points")?;
    let points = points.iter().map(|q| q.to_array()).collect();
    let spline = match p.get("spline") {
        None => Spline::Linear,
        Some((Value::Str(name), ns)) => {
            Spline::NAMED[choice(&name, &Spline::NAMES, "spline", ns)?].1
        }
        Some((other, ns)) => return Err(types::mismatch(it, "String", &other, ns).into()),
    };
    checked(Shape::Lathe { points, spline }, s, &[("points", sp)])
}

/// `sor(points, open)`.
static SOR: Sig = Sig::new(
    "sor",
    Group::Shape,
    "A surface of revolution about the Y axis (POV-Ray's `sor`): its radius² a cubic of the \
     height through the `[r, y]` points, the first and last only steering; closed by a base and \
     a cap disk unless `open`.",
    &[
        Param::new(
            "points",
            Ty::ListOf(&Ty::Pair(&Ty::Float)),
            "at least 4 `[r, y]` points, r >= 0, heights increasing from the second to the last but one",
        )
        .unit(Unit::Length),
        Param::new(
            "open",
            Ty::Bool,
            "leaves out the base and cap disks (a surface, not a solid)",
        )
        .or(Lit::Bool(false)),
    ],
    "Object",
)
.examples(&[
    "sor(points: [[0, -0.5], [0.6, 0], [0.3, 0.6], [0.5, 1.2], [0.8, 1.5]])  // a vase",
    "sor(points: [[1, -1], [1, 0], [1, 1], [1, 2]], open: true)  // a tube",
]);
fn sor(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SOR, a)?;
    let (points, sp) = pairs(it, &mut p, "points")?;
    let points = points.iter().map(|q| q.to_array()).collect();
    let open = p.bool(it, "open")?;
    checked(Shape::Sor { points, open }, s, &[("points", sp)])
}

/// `superellipsoid(e, n)`.
static SUPERELLIPSOID: Sig = Sig::new(
    "superellipsoid",
    Group::Shape,
    "The superellipsoid (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in the cube [-1, 1]³ \
     (POV-Ray's `superellipsoid { <e, n> }`): 1 is round, near 0 a box, 2 a double cone, \
     3 pinched.",
    &[
        Param::new(
            "e",
            Ty::Float,
            "the squareness of the sections across z (in 0.001..=10)",
        )
        .range(Range::Between(0.001, 10.0))
        .checked_by_builtin()
        .or(Lit::Float(1.0)),
        Param::new("n", Ty::Float, "the squareness along z (in 0.001..=10)")
            .range(Range::Between(0.001, 10.0))
            .checked_by_builtin()
            .or(Lit::Float(1.0)),
    ],
    "Object",
)
.examples(&[
    "superellipsoid(e: 0.25, n: 0.25)  // a rounded box",
    "superellipsoid(e: 1, n: 3)  // a pinched spindle",
]);
fn superellipsoid(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SUPERELLIPSOID, a)?;
    let (e, es) = p.float(it, "e")?;
    let (n, ns) = p.float(it, "n")?;
    checked(Shape::Superellipsoid { e, n }, s, &[("e", es), ("n", ns)])
}

/// `poly(order, coefficients)`.
static POLY: Sig = Sig::new(
    "poly",
    Group::Shape,
    "The zeros of a polynomial in x, y, z, inside where negative (POV-Ray's `poly`; usually \
     unbounded: bound it with CSG). Coefficients in POV-Ray's order: x^order first, then \
     falling powers of x, y, z; the constant last.",
    &[
        Param::new("order", Ty::Int, "the total degree (2 to 15)")
            .range(Range::Ints(2, 15))
            .checked_by_builtin(),
        Param::new(
            "coefficients",
            Ty::ListOf(&Ty::Float),
            "(order+1)(order+2)(order+3)/6 numbers, 0 for an absent term",
        ),
    ],
    "Object",
)
.examples(&["poly(order: 2, coefficients: [1, 0, 0, 0, 1, 0, 0, 1, 0, -1])  // the unit sphere"]);
fn poly(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &POLY, a)?;
    let (order, os) = p.int(it, "order")?;
    p.declared_range("order", order as f64, os)?;
    let order = u32::try_from(order).unwrap_or(0);
    made(it, &mut p, s, order, os)
}

/// `cubic(coefficients)`.
static CUBIC: Sig = Sig::new(
    "cubic",
    Group::Shape,
    "A `poly` of order 3 (POV-Ray's `cubic`): 20 coefficients.",
    &[Param::new(
        "coefficients",
        Ty::ListOf(&Ty::Float),
        "20 numbers: x³, x²y, x²z, x², xy², ... , z, 1",
    )],
    "Object",
)
.examples(&[
    "cubic(coefficients: [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, -0.5])",
]);
fn cubic(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &CUBIC, a)?;
    made(it, &mut p, s, 3, s.span)
}

/// `quartic(coefficients)`.
static QUARTIC: Sig = Sig::new(
    "quartic",
    Group::Shape,
    "A `poly` of order 4 (POV-Ray's `quartic`): 35 coefficients.",
    &[Param::new(
        "coefficients",
        Ty::ListOf(&Ty::Float),
        "35 numbers: x⁴, x³y, x³z, x³, x²y², ... , z, 1",
    )],
    "Object",
)
.examples(&["quartic(coefficients: [1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1])  // x⁴ + y⁴ + z⁴ = 1"]);
fn quartic(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &QUARTIC, a)?;
    made(it, &mut p, s, 4, s.span)
}

/// Reads `coefficients` and makes the checked poly of `order` (its span `os`).
fn made(it: &mut dyn Host, p: &mut Params, s: CallSite, order: u32, os: Span) -> R<Value> {
    let (v, cs) = p.req("coefficients")?;
    let coefficients = match &v {
        Value::List(items) => {
            let mut c = Vec::with_capacity(items.len());
            for x in items.iter() {
                c.push(types::num(it, x, cs)?);
            }
            c
        }
        // Three numbers in brackets read as a vector: still a (too short) coefficient list,
        // which the shape's rules report with the count it needs.
        Value::Vec3(x) => x.to_array().to_vec(),
        _ => return Err(types::mismatch(it, "List", &v, cs).into()),
    };
    checked(
        Shape::Poly {
            order,
            coefficients,
        },
        s,
        &[("order", os), ("coefficients", cs)],
    )
}
