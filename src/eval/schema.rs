//! The declaration of every built-in, once: a signature ([`Sig`]: name, one-line doc,
//! parameters, result) and per parameter ([`Param`]) its type, unit, range, default and doc.
//! Each is static data declared next to the function it describes and collected by the tables
//! of functions (`builtins::functions`) and methods (`methods::RECEIVERS`). The argument reader
//! (`args::Params`) takes its type, range and default checks and its did-you-mean from here,
//! `rtc convert` its reserved names (`eval::reserved_names`), and `docs/builtins.md` is written
//! from it. A leaf: it knows nothing of values or of the interpreter.

/// A built-in function, method or record form: what `docs/builtins.md` shows of it and what
/// the argument reader checks. What only the reference shows (here and in [`Param`]) is read by
/// the tests alone, which write and check `docs/builtins.md`: those fields allow `dead_code`
/// outside them.
#[derive(Debug)]
pub(crate) struct Sig {
    /// The name it is called by.
    pub(crate) name: &'static str,
    /// Where the reference lists it.
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) group: Group,
    /// One line saying what it gives.
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) doc: &'static str,
    /// Its parameters, in positional order.
    pub(crate) params: &'static [Param],
    /// The result's type as the docs show it.
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) result: &'static str,
    /// How an argument outside its range is reported.
    pub(crate) blame: Blame,
    /// The last parameter takes any number of values (`min(a, b, ...)`, `print(...)`).
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) variadic: bool,
    /// Calls that evaluate without an error, together reading every parameter (a test
    /// evaluates them; the reference shows them).
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) examples: &'static [&'static str],
}

/// The sections of the reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Group {
    /// Numbers, angles and vectors.
    Math,
    /// Lists.
    List,
    /// Conversions, `print`, `assert`.
    Misc,
    /// Colours.
    Colour,
    /// Object constructors (shapes, groups, CSG).
    Shape,
    /// Transforms.
    Transform,
    /// Materials and textures.
    Look,
    /// Noise functions of a point.
    Noise,
    /// Lights.
    Light,
    /// The camera.
    Camera,
    /// Render settings and their parts.
    Render,
    /// Random streams.
    Random,
    /// Methods that are no function (`.material(m)`, `.moving(..)`, `.map(f)`, ...).
    Method,
    /// Records a built-in reads (a blob's components).
    Record,
}

impl Group {
    /// The heading of the group's section in the reference.
    #[cfg(test)]
    pub(crate) fn title(self) -> &'static str {
        match self {
            Group::Math => "Math",
            Group::List => "Lists",
            Group::Misc => "Conversions and checks",
            Group::Colour => "Colours",
            Group::Shape => "Objects",
            Group::Transform => "Transforms",
            Group::Look => "Materials and textures",
            Group::Noise => "Noise",
            Group::Light => "Lights",
            Group::Camera => "Camera",
            Group::Render => "Render settings",
            Group::Random => "Randomness",
            Group::Method => "Methods",
            Group::Record => "Records",
        }
    }
}

/// How a range violation reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Blame {
    /// "`radius` must be > 0, but it is -1".
    Param,
    /// A function's domain: "`sqrt(x)` needs `x` >= 0, but `x` is -1".
    Function,
}

/// One parameter (or field of a record form).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Param {
    /// Its name (named arguments, record fields, messages).
    pub(crate) name: &'static str,
    /// What it accepts.
    pub(crate) ty: Ty,
    /// What a number of it measures.
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) unit: Unit,
    /// The values it allows.
    pub(crate) range: Range,
    /// Who checks `range`.
    pub(crate) checked: Checked,
    /// What it is when the call leaves it out.
    pub(crate) absent: Absent,
    /// One line saying what it does.
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) doc: &'static str,
}

/// The type of a parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Ty {
    /// A number (`Int` or `Float`).
    Float,
    /// An `Int`.
    Int,
    /// A `Bool`.
    Bool,
    /// An `Angle` (`30deg`).
    Angle,
    /// A `Vec3`.
    Vec3,
    /// A `Color`.
    Color,
    /// A `String`.
    String,
    /// A `List` (or a `Vec3` as three numbers).
    List,
    /// A `List` of the given type.
    ListOf(&'static Ty),
    /// A range (`0..n`).
    Range,
    /// `[a, b]`: two values of the given type.
    Pair(&'static Ty),
    /// A function value.
    Fn,
    /// An object.
    Object,
    /// A material.
    Material,
    /// A texture.
    Texture,
    /// A transform.
    Transform,
    /// A record.
    Record,
    /// A shading model (`phong`, `gooch { .. }`, `hatching`).
    Shading,
    /// An image mode (`shaded`, `normal`, `depth`, `depth(..)`).
    Mode,
    /// An ambient convention (`per_light`, `once`).
    Ambient,
    /// An output encoding (`srgb`, `linear`).
    Encoding,
    /// A texture mapping (`uv`, `planar`, `spherical`, `cylindrical`).
    Mapping,
    /// Lens flare parameters (`flare { .. }`).
    Flare,
    /// Fog parameters (`fog { .. }`).
    Fog,
    /// An integrator (`whitted`, `path(..)`).
    Integrator,
    /// A sampling scheme (`adaptive(..)`).
    Sampling,
    /// Anything.
    Any,
    /// Any of these.
    OneOf(&'static [Ty]),
}

impl Ty {
    /// The type as the reference writes it.
    #[cfg(test)]
    pub(crate) fn show(self) -> String {
        let name = match self {
            Ty::Float => "Float",
            Ty::Int => "Int",
            Ty::Bool => "Bool",
            Ty::Angle => "Angle",
            Ty::Vec3 => "Vec3",
            Ty::Color => "Color",
            Ty::String => "String",
            Ty::List => "List",
            Ty::ListOf(t) => return format!("List<{}>", t.show()),
            Ty::Range => "Range",
            Ty::Pair(t) => return format!("[{0}, {0}]", t.show()),
            Ty::Fn => "Fn",
            Ty::Object => "Object",
            Ty::Material => "Material",
            Ty::Texture => "Texture",
            Ty::Transform => "Transform",
            Ty::Record => "Record",
            Ty::Shading => "Shading",
            Ty::Mode => "Mode",
            Ty::Ambient => "Ambient",
            Ty::Encoding => "Encoding",
            Ty::Mapping => "Mapping",
            Ty::Flare => "Flare",
            Ty::Fog => "Fog",
            Ty::Integrator => "Integrator",
            Ty::Sampling => "Sampling",
            Ty::Any => "Any",
            Ty::OneOf(ts) => {
                return ts.iter().map(|t| t.show()).collect::<Vec<_>>().join(" or ");
            }
        };
        name.to_string()
    }
}

/// What a number measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Unit {
    /// A pure number.
    None,
    /// A length in scene units.
    Length,
    /// An angle.
    Angle,
    /// A fraction of a frame's time.
    Frame,
    /// Pixels.
    Pixels,
    /// Samples per axis of a pixel or of an area light.
    Samples,
    /// Rays.
    Rays,
}

impl Unit {
    /// The unit as the reference writes it ("" for none).
    #[cfg(test)]
    pub(crate) fn show(self) -> &'static str {
        match self {
            Unit::None => "",
            Unit::Length => "scene units",
            Unit::Angle => "angle",
            Unit::Frame => "fraction of a frame",
            Unit::Pixels => "pixels",
            Unit::Samples => "samples per axis",
            Unit::Rays => "rays",
        }
    }
}

/// The values a parameter allows (of a pair, each element).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Range {
    /// Any value of its type.
    Any,
    /// `> 0`.
    Positive,
    /// `>= 0`.
    NonNegative,
    /// `[0, 1]`.
    UnitInterval,
    /// `[-1, 1]`.
    SignedUnit,
    /// `[lo, hi]` of a `Float`, written `lo..=hi`.
    Between(f64, f64),
    /// `lo..=hi` of an `Int`.
    Ints(i64, i64),
    /// The open interval `(lo, hi)` (of an angle: radians, written in degrees).
    Open(f64, f64),
    /// A vector that is not zero (and finite).
    NonZero,
}

impl Range {
    /// Whether the number `x` is allowed (`NonZero` is a vector rule: always true here).
    pub(crate) fn holds(self, x: f64) -> bool {
        match self {
            Range::Any | Range::NonZero => true,
            Range::Positive => x > 0.0,
            Range::NonNegative => x >= 0.0,
            Range::UnitInterval => (0.0..=1.0).contains(&x),
            Range::SignedUnit => (-1.0..=1.0).contains(&x),
            Range::Between(lo, hi) => x >= lo && x <= hi,
            Range::Ints(lo, hi) => x >= lo as f64 && x <= hi as f64,
            Range::Open(lo, hi) => x > lo && x < hi,
        }
    }

    /// Whether the `Int` `i` is allowed (compared as integers, so `i64::MAX` bounds exactly).
    pub(crate) fn holds_int(self, i: i64) -> bool {
        match self {
            Range::Ints(lo, hi) => i >= lo && i <= hi,
            other => other.holds(i as f64),
        }
    }

    /// The rule as the reference writes it (`> 0`, `≥ 0`, `[0, 1]`, `1..=64`; "" for any).
    #[cfg(test)]
    pub(crate) fn show(self, ty: Ty) -> String {
        let num = |x: f64| crate::diag::number(x);
        match self {
            Range::Any => String::new(),
            Range::Positive => "> 0".to_string(),
            Range::NonNegative => "≥ 0".to_string(),
            Range::UnitInterval => "[0, 1]".to_string(),
            Range::SignedUnit => "[−1, 1]".to_string(),
            Range::Between(lo, hi) => format!("[{}, {}]", num(lo), num(hi)),
            Range::Ints(lo, hi) => format!("{lo}..={hi}"),
            Range::Open(..) => self.rule(ty).trim_start_matches("in ").to_string(),
            Range::NonZero => "non-zero".to_string(),
        }
    }

    /// The rule as a message says it after "must be" (`> 0`, `in [0, 1]`, `in 1..=64`); the
    /// bounds of an angle in degrees.
    pub(crate) fn rule(self, ty: Ty) -> String {
        let num = |x: f64| crate::diag::number(x);
        match self {
            Range::Any => "any value".to_string(),
            Range::Positive => "> 0".to_string(),
            Range::NonNegative => ">= 0".to_string(),
            Range::UnitInterval => "in [0, 1]".to_string(),
            Range::SignedUnit => "in [-1, 1]".to_string(),
            Range::Between(lo, hi) => format!("in {lo}..={hi}"),
            Range::Ints(lo, hi) => format!("in {lo}..={hi}"),
            Range::Open(lo, hi) if ty == Ty::Angle => format!(
                "in ({}deg, {}deg)",
                num(lo.to_degrees()),
                num(hi.to_degrees())
            ),
            Range::Open(lo, hi) => format!("in ({}, {})", num(lo), num(hi)),
            Range::NonZero => "a non-zero vector".to_string(),
        }
    }
}

/// Who checks a parameter's range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Checked {
    /// The argument reader, as the argument is read.
    OnRead,
    /// The built-in itself, later: the rule involves other parameters (`max` ≥ `min`), or
    /// geometry's shape rules check it once the shape is assembled (the one home of shape
    /// validity, which also names the parameter to blame).
    ByBuiltin,
}

/// What a parameter is when the call leaves it out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Absent {
    /// The call must give it (`rtc::arg::missing`).
    Required,
    /// This value.
    Is(Lit),
    /// Nothing: the built-in does without it (or, with another parameter, needs it).
    Optional,
    /// A value computed from the other arguments, described in words.
    Computed(&'static str),
}

/// A default value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Lit {
    /// A number.
    Float(f64),
    /// An `Int`.
    Int(i64),
    /// A `Bool`.
    Bool(bool),
    /// An angle, in degrees.
    Degrees(f64),
    /// A vector.
    Vec3([f64; 3]),
    /// A colour.
    Color([f64; 3]),
    /// Two `Int`s.
    Ints([i64; 2]),
    /// A named value of the language (`phong`, `uv`, `per_light`).
    Name(&'static str),
}

impl Lit {
    /// The value as rtc source writes it (`1`, `40deg`, `Y`, `[0, 0, 0]`, `rgb(1, 1, 1)`).
    #[cfg(test)]
    fn show(self) -> String {
        let v = |xs: [f64; 3]| xs.map(|x| format!("{x}")).join(", ");
        match self {
            Lit::Float(x) => format!("{x}"),
            Lit::Int(i) => format!("{i}"),
            Lit::Bool(b) => format!("{b}"),
            Lit::Degrees(d) => format!("{d}deg"),
            Lit::Vec3([1.0, 0.0, 0.0]) => "X".to_string(),
            Lit::Vec3([0.0, 1.0, 0.0]) => "Y".to_string(),
            Lit::Vec3([0.0, 0.0, 1.0]) => "Z".to_string(),
            Lit::Vec3(xs) => format!("[{}]", v(xs)),
            Lit::Color(xs) => format!("rgb({})", v(xs)),
            Lit::Ints([a, b]) => format!("[{a}, {b}]"),
            Lit::Name(n) => n.to_string(),
        }
    }
}

impl Absent {
    /// The default as the reference writes it: `required`, the value, `none`, or the words
    /// that say how it is computed.
    #[cfg(test)]
    pub(crate) fn show(self) -> String {
        match self {
            Absent::Required => "required".to_string(),
            Absent::Is(l) => format!("`{}`", l.show()),
            Absent::Optional => "none".to_string(),
            Absent::Computed(how) => how.to_string(),
        }
    }
}

impl Param {
    /// A required parameter of type `ty`, unitless and of any value.
    pub(crate) const fn new(name: &'static str, ty: Ty, doc: &'static str) -> Param {
        Param {
            name,
            ty,
            unit: Unit::None,
            range: Range::Any,
            checked: Checked::OnRead,
            absent: Absent::Required,
            doc,
        }
    }

    /// With its unit.
    pub(crate) const fn unit(self, unit: Unit) -> Param {
        Param { unit, ..self }
    }

    /// With its range.
    pub(crate) const fn range(self, range: Range) -> Param {
        Param { range, ..self }
    }

    /// Its range is checked by the built-in, not the reader ([`Checked::ByBuiltin`]).
    pub(crate) const fn checked_by_builtin(self) -> Param {
        Param {
            checked: Checked::ByBuiltin,
            ..self
        }
    }

    /// With a default value.
    pub(crate) const fn or(self, value: Lit) -> Param {
        Param {
            absent: Absent::Is(value),
            ..self
        }
    }

    /// Optional without a default.
    pub(crate) const fn optional(self) -> Param {
        Param {
            absent: Absent::Optional,
            ..self
        }
    }

    /// With a default computed from the other arguments, as `how` says.
    pub(crate) const fn computed(self, how: &'static str) -> Param {
        Param {
            absent: Absent::Computed(how),
            ..self
        }
    }
}

impl Sig {
    /// A signature whose range violations name the parameter.
    pub(crate) const fn new(
        name: &'static str,
        group: Group,
        doc: &'static str,
        params: &'static [Param],
        result: &'static str,
    ) -> Sig {
        Sig {
            name,
            group,
            doc,
            params,
            result,
            blame: Blame::Param,
            variadic: false,
            examples: &[],
        }
    }

    /// With example calls.
    pub(crate) const fn examples(self, examples: &'static [&'static str]) -> Sig {
        Sig { examples, ..self }
    }

    /// Range violations are the function's domain ([`Blame::Function`]).
    pub(crate) const fn domain(self) -> Sig {
        Sig {
            blame: Blame::Function,
            ..self
        }
    }

    /// The last parameter takes any number of values.
    pub(crate) const fn variadic(self) -> Sig {
        Sig {
            variadic: true,
            ..self
        }
    }

    /// The index of parameter `name`. The name is usually the very literal the schema lists
    /// (a built-in asks for its own parameters), so its address is compared first: the calls
    /// are hot (a loop making a million spheres).
    #[inline]
    pub(crate) fn index(&self, name: &str) -> Option<usize> {
        let i = self
            .params
            .iter()
            .position(|p| std::ptr::eq(p.name, name))
            .or_else(|| self.params.iter().position(|p| p.name == name));
        #[cfg(test)]
        if let Some(i) = i {
            read::record(self, i);
        }
        i
    }

    /// Parameter `name`.
    pub(crate) fn param(&self, name: &str) -> Option<&'static Param> {
        let params: &'static [Param] = self.params;
        self.index(name).map(|i| &params[i])
    }

    /// How a call reads: `sphere(center, radius)`, `min(values...)`.
    #[cfg(test)]
    pub(crate) fn usage(&self) -> String {
        let mut names: Vec<String> = self.names().map(String::from).collect();
        if self.variadic
            && let Some(last) = names.last_mut()
        {
            last.push_str("...");
        }
        format!("{}({})", self.name, names.join(", "))
    }

    /// The parameter names in order.
    pub(crate) fn names(&self) -> impl Iterator<Item = &'static str> + Clone + use<> {
        let params: &'static [Param] = self.params;
        params.iter().map(|p| p.name)
    }
}

/// Which parameters the built-ins asked for (tests only; evaluation runs on threads of its
/// own, so the record is the process's): every parameter a schema declares must be read
/// somewhere, and a built-in asking for a name its schema lacks panics.
#[cfg(test)]
pub(crate) mod read {
    use std::collections::BTreeSet;
    use std::sync::Mutex;

    use super::Sig;

    /// (address of the signature, parameter index) of every parameter asked for.
    static READ: Mutex<BTreeSet<(usize, usize)>> = Mutex::new(BTreeSet::new());

    /// Notes that parameter `i` of `sig` was asked for.
    pub(crate) fn record(sig: &Sig, i: usize) {
        let mut read = READ.lock().unwrap_or_else(|e| e.into_inner());
        read.insert((sig as *const Sig as usize, i));
    }

    /// Whether parameter `i` of `sig` was asked for.
    pub(crate) fn was_read(sig: &Sig, i: usize) -> bool {
        let read = READ.lock().unwrap_or_else(|e| e.into_inner());
        read.contains(&(sig as *const Sig as usize, i))
    }
}
