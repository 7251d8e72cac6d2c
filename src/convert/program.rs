//! A compiled function of the point ([`Program`]: an isosurface's `f`, a `pattern(f)`) written
//! back as an rtc function literal, `fn(p) { .. }`, that compiles to a program computing the
//! same value at every point.
//!
//! The program is run symbolically: each register holds the source text of its value, each
//! computing operation becomes a `let`, and the compiler's forward jumps (an `if` with its
//! `else`, the only shape it emits) become an `if` expression giving the registers its
//! branches changed. Every operation is spelled with the language operator or built-in that
//! the compiler turns into that same operation on `f64` (angles through `1rad`, which
//! multiplies or divides by exactly 1), so the values agree bit for bit. A program of any
//! other shape (none the compiler makes) gives `None`.

use crate::pattern::Crackle;
use crate::pattern::program::{Bin, NoiseFn, Op, Program, Reg, Un, VecOp};

use super::text::number;

/// The kind of value a register's text is in the language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// A number (`Int` or `Float`).
    Num,
    /// A `Bool` (the machine holds it as 0 or 1).
    Bool,
}

/// A register's value: source text (a name, a literal or a parenthesised expression).
#[derive(Clone, Debug, PartialEq)]
struct Sym {
    text: String,
    kind: Kind,
}

impl Sym {
    fn num(text: impl Into<String>) -> Sym {
        Sym {
            text: text.into(),
            kind: Kind::Num,
        }
    }

    /// The text as a number (a `Bool` as 1 or 0).
    fn as_num(&self) -> String {
        match self.kind {
            Kind::Num => self.text.clone(),
            Kind::Bool => format!("(if {} {{ 1.0 }} else {{ 0.0 }})", self.text),
        }
    }

    /// The text as a `Bool` (a number is true when it is not 0, as the machine reads it).
    fn as_bool(&self) -> String {
        match self.kind {
            Kind::Bool => self.text.clone(),
            Kind::Num => format!("({} != 0)", self.text),
        }
    }
}

/// `fn(p) { .. }` computing what `program` computes, or `None` for a program the compiler
/// would not have made.
pub(crate) fn function_source(program: &Program) -> Option<String> {
    let ops = program.ops();
    let mut w = Writer {
        ops,
        next: 0,
        result: usize::from(program.result()),
    };
    let mut regs: Vec<Sym> = (0..program.registers().max(3))
        .map(|i| match i {
            0 => Sym::num("p.x"),
            1 => Sym::num("p.y"),
            2 => Sym::num("p.z"),
            _ => Sym::num("0"),
        })
        .collect();
    let mut lines = Vec::new();
    w.block(&mut regs, 0, ops.len(), &mut lines)?;
    let result = regs.get(usize::from(program.result()))?;
    lines.push(result.as_num());
    let body: String = lines.iter().map(|l| format!("    {l}\n")).collect();
    Some(format!("fn(p) {{\n{body}}}"))
}

struct Writer<'a> {
    ops: &'a [Op],
    /// The number of the next `let`.
    next: usize,
    /// The register holding the function's value at the end.
    result: usize,
}

impl Writer<'_> {
    /// A new `let v<n> = text` in `lines`, returning its name.
    fn bind(&mut self, text: String, lines: &mut Vec<String>) -> String {
        self.next += 1;
        let name = format!("v{}", self.next);
        lines.push(format!("let {name} = {text}"));
        name
    }

    /// The registers `r..r+3` as a vector: the name of a vector when they are its components.
    fn vector(regs: &[Sym], r: Reg) -> Option<String> {
        let r = usize::from(r);
        let [x, y, z] = [regs.get(r)?, regs.get(r + 1)?, regs.get(r + 2)?];
        if let Some(base) = x.text.strip_suffix(".x")
            && y.text.strip_suffix(".y") == Some(base)
            && z.text.strip_suffix(".z") == Some(base)
            && is_name(base)
        {
            return Some(base.to_string());
        }
        Some(format!("[{}, {}, {}]", x.as_num(), y.as_num(), z.as_num()))
    }

    /// Writes `name`'s components into `r..r+3`.
    fn put_vector(regs: &mut [Sym], r: Reg, name: &str) -> Option<()> {
        let r = usize::from(r);
        for (i, c) in ["x", "y", "z"].iter().enumerate() {
            *regs.get_mut(r + i)? = Sym::num(format!("{name}.{c}"));
        }
        Some(())
    }

    /// Operations `from..to` into `lines`, updating `regs`.
    fn block(
        &mut self,
        regs: &mut [Sym],
        from: usize,
        to: usize,
        lines: &mut Vec<String>,
    ) -> Option<()> {
        let mut i = from;
        while i < to {
            match self.ops[i] {
                Op::JumpUnless { cond, to: other } => {
                    i = self.if_else(regs, i, cond, other as usize, to, lines)?;
                    continue;
                }
                Op::Jump { .. } => return None,
                op => self.straight(regs, op, lines)?,
            }
            i += 1;
        }
        Some(())
    }

    /// The `if` whose `JumpUnless` is at `at` (its `else` starting at `other`), within the
    /// enclosing block ending at `end`; returns the operation after it.
    fn if_else(
        &mut self,
        regs: &mut [Sym],
        at: usize,
        cond: Reg,
        other: usize,
        end: usize,
        lines: &mut Vec<String>,
    ) -> Option<usize> {
        // The compiler's shape: then-branch, `Jump` past the else-branch, else-branch.
        let Some(&Op::Jump { to: after }) = other.checked_sub(1).and_then(|j| self.ops.get(j))
        else {
            return None;
        };
        let after = after as usize;
        if other <= at + 1 || after < other || after > end {
            return None;
        }
        let test = regs.get(usize::from(cond))?.as_bool();
        let (mut then_regs, mut else_regs) = (regs.to_vec(), regs.to_vec());
        let (mut then_lines, mut else_lines) = (Vec::new(), Vec::new());
        self.block(&mut then_regs, at + 1, other - 1, &mut then_lines)?;
        self.block(&mut else_regs, other, after, &mut else_lines)?;
        // Registers a branch changed and a later operation reads: the `if`'s value. The
        // branches' scratch registers are dead after it; they keep a branch's (now out of
        // scope) name, so a reader this analysis missed would fail to compile, not misread.
        let mut changed = Vec::new();
        for r in 0..regs.len() {
            if then_regs[r] == regs[r] && else_regs[r] == regs[r] {
                continue;
            }
            if self.live_after(r, after) {
                changed.push(r);
            } else {
                regs[r] = then_regs[r].clone();
            }
        }
        match changed.len() {
            0 => {}
            1 => {
                let r = changed[0];
                let (t, e) = (&then_regs[r], &else_regs[r]);
                let (tv, ev, kind) = if t.kind == e.kind {
                    (t.text.clone(), e.text.clone(), t.kind)
                } else {
                    (t.as_num(), e.as_num(), Kind::Num)
                };
                let text = branches(&test, &then_lines, &tv, &else_lines, &ev);
                let name = self.bind(text, lines);
                regs[r] = Sym { text: name, kind };
            }
            2 | 3 => {
                let pick = |rs: &[Sym]| {
                    let mut c: Vec<String> = changed.iter().map(|&r| rs[r].as_num()).collect();
                    c.resize(3, "0".into());
                    format!("[{}]", c.join(", "))
                };
                let text = branches(
                    &test,
                    &then_lines,
                    &pick(&then_regs),
                    &else_lines,
                    &pick(&else_regs),
                );
                let name = self.bind(text, lines);
                for (&r, c) in changed.iter().zip(["x", "y", "z"]) {
                    regs[r] = Sym::num(format!("{name}.{c}"));
                }
            }
            _ => return None,
        }
        Some(after)
    }

    /// True when register `r` may be read from operation `from` on before it is written on
    /// every path (a write inside an `if`'s branch does not count), or holds the result.
    fn live_after(&self, r: usize, from: usize) -> bool {
        let mut conditional_until = from;
        for (k, op) in self.ops.iter().enumerate().skip(from) {
            let (reads, writes) = footprint(op);
            if reads.iter().any(|&(at, n)| (at..at + n).contains(&r)) {
                return true;
            }
            if let Op::JumpUnless { to, .. } = *op
                && let Some(Op::Jump { to: after }) =
                    (to as usize).checked_sub(1).and_then(|j| self.ops.get(j))
            {
                conditional_until = conditional_until.max(*after as usize);
            }
            if k >= conditional_until && writes.is_some_and(|(at, n)| (at..at + n).contains(&r)) {
                return false;
            }
        }
        r == self.result
    }

    /// One operation without jumps.
    fn straight(&mut self, regs: &mut [Sym], op: Op, lines: &mut Vec<String>) -> Option<()> {
        let get = |regs: &[Sym], r: Reg| regs.get(usize::from(r)).cloned();
        match op {
            Op::Const { dst, value } => {
                if !value.is_finite() {
                    return None;
                }
                let text = number(value);
                let text = if text.starts_with('-') {
                    format!("({text})")
                } else {
                    text
                };
                *regs.get_mut(usize::from(dst))? = Sym::num(text);
            }
            Op::Copy { dst, src, width } => {
                for k in 0..usize::from(width.clamp(1, 3)) {
                    let v = get(regs, src + k as Reg)?;
                    *regs.get_mut(usize::from(dst) + k)? = v;
                }
            }
            Op::Un { f, dst, a } => {
                let a = get(regs, a)?;
                let (text, kind) = unary(f, &a);
                let name = self.bind(text, lines);
                *regs.get_mut(usize::from(dst))? = Sym { text: name, kind };
            }
            Op::Bin { f, dst, a, b } => {
                let (a, b) = (get(regs, a)?, get(regs, b)?);
                let (text, kind) = binary(f, &a, &b);
                let name = self.bind(text, lines);
                *regs.get_mut(usize::from(dst))? = Sym { text: name, kind };
            }
            Op::Vec { f, dst, a, b } => {
                let x = Self::vector(regs, a)?;
                let scalar = matches!(f, VecOp::Scale | VecOp::Div);
                let y = if scalar {
                    get(regs, b)?.as_num()
                } else {
                    Self::vector(regs, b)?
                };
                let (text, width, kind) = match f {
                    VecOp::Add => (format!("{x} + {y}"), 3, Kind::Num),
                    VecOp::Sub => (format!("{x} - {y}"), 3, Kind::Num),
                    VecOp::Mul | VecOp::Scale => (format!("{x} * {y}"), 3, Kind::Num),
                    VecOp::Div => (format!("{x} / {y}"), 3, Kind::Num),
                    VecOp::Neg => (format!("-{x}"), 3, Kind::Num),
                    VecOp::Dot => (format!("dot({x}, {y})"), 1, Kind::Num),
                    VecOp::Cross => (format!("cross({x}, {y})"), 3, Kind::Num),
                    VecOp::Length => (format!("length({x})"), 1, Kind::Num),
                    VecOp::Distance => (format!("distance({x}, {y})"), 1, Kind::Num),
                    VecOp::Normalize => (format!("normalize({x})"), 3, Kind::Num),
                    VecOp::Eq => (format!("{x} == {y}"), 1, Kind::Bool),
                    VecOp::Ne => (format!("{x} != {y}"), 1, Kind::Bool),
                };
                let name = self.bind(text, lines);
                if width == 3 {
                    Self::put_vector(regs, dst, &name)?;
                } else {
                    *regs.get_mut(usize::from(dst))? = Sym { text: name, kind };
                }
            }
            Op::Noise { f, dst, p } => {
                let p = Self::vector(regs, p)?;
                let name = self.bind(noise(f, &p), lines);
                if f.width() == 3 {
                    Self::put_vector(regs, dst, &name)?;
                } else {
                    *regs.get_mut(usize::from(dst))? = Sym::num(name);
                }
            }
            Op::Jump { .. } | Op::JumpUnless { .. } => return None,
        }
        Some(())
    }
}

/// Registers `first..first + width`, as `(first, width)`.
type Run = (usize, usize);

/// The registers `op` reads (first register and width, each) and writes.
fn footprint(op: &Op) -> (Vec<Run>, Option<Run>) {
    let u = usize::from;
    match *op {
        Op::Const { dst, .. } => (vec![], Some((u(dst), 1))),
        Op::Copy { dst, src, width } => {
            let w = usize::from(width.clamp(1, 3));
            (vec![(u(src), w)], Some((u(dst), w)))
        }
        Op::Un { dst, a, .. } => (vec![(u(a), 1)], Some((u(dst), 1))),
        Op::Bin { dst, a, b, .. } => (vec![(u(a), 1), (u(b), 1)], Some((u(dst), 1))),
        Op::Vec { f, dst, a, b } => {
            let scalar_b = matches!(f, VecOp::Scale | VecOp::Div);
            let scalar_out = matches!(
                f,
                VecOp::Dot | VecOp::Length | VecOp::Distance | VecOp::Eq | VecOp::Ne
            );
            (
                vec![(u(a), 3), (u(b), if scalar_b { 1 } else { 3 })],
                Some((u(dst), if scalar_out { 1 } else { 3 })),
            )
        }
        Op::Noise { f, dst, p } => (vec![(u(p), 3)], Some((u(dst), f.width()))),
        Op::JumpUnless { cond, .. } => (vec![(u(cond), 1)], None),
        Op::Jump { .. } => (vec![], None),
    }
}

/// `if test { then.. value } else { else.. value }` on as many lines as it needs.
fn branches(test: &str, then: &[String], tv: &str, els: &[String], ev: &str) -> String {
    let block = |lines: &[String], value: &str| {
        if lines.is_empty() {
            format!("{{ {value} }}")
        } else {
            let body: String = lines
                .iter()
                .flat_map(|l| l.lines())
                .map(|l| format!("        {l}\n"))
                .collect();
            format!("{{\n{body}        {value}\n    }}")
        }
    };
    format!("if {test} {} else {}", block(then, tv), block(els, ev))
}

/// A one-number operation as source, and its kind.
fn unary(f: Un, a: &Sym) -> (String, Kind) {
    let x = a.as_num();
    let text = match f {
        Un::Neg => format!("-{x}"),
        Un::Not => return (format!("!{}", a.as_bool()), Kind::Bool),
        Un::Abs => format!("abs({x})"),
        Un::Floor => format!("floor({x})"),
        Un::Ceil => format!("ceil({x})"),
        Un::Round => format!("round({x})"),
        Un::Trunc => format!("int({x})"),
        Un::Sqrt => format!("sqrt({x})"),
        // Angles: `x * 1rad` and `.. / 1rad` multiply and divide by exactly 1.
        Un::Sin => format!("sin({x} * 1rad)"),
        Un::Cos => format!("cos({x} * 1rad)"),
        Un::Tan => format!("tan({x} * 1rad)"),
        Un::Asin => format!("asin({x}) / 1rad"),
        Un::Acos => format!("acos({x}) / 1rad"),
        Un::Atan => format!("atan({x}) / 1rad"),
        Un::Exp => format!("exp({x})"),
        Un::Ln => format!("ln({x})"),
    };
    (text, Kind::Num)
}

/// A two-number operation as source, and its kind.
fn binary(f: Bin, a: &Sym, b: &Sym) -> (String, Kind) {
    let (x, y) = (a.as_num(), b.as_num());
    let num = |t: String| (t, Kind::Num);
    let test = |op: &str| (format!("{x} {op} {y}"), Kind::Bool);
    match f {
        Bin::Add => num(format!("{x} + {y}")),
        Bin::Sub => num(format!("{x} - {y}")),
        Bin::Mul => num(format!("{x} * {y}")),
        Bin::Div => num(format!("{x} / {y}")),
        Bin::Rem => num(format!("{x} % {y}")),
        // Only `Int`s divide with `div`; the compiler made this of integers, which `int` keeps.
        Bin::IntDiv => num(format!("int({x}) div int({y})")),
        Bin::Pow => num(format!("pow({x}, {y})")),
        Bin::Atan2 => num(format!("atan2({x}, {y}) / 1rad")),
        Bin::Lt => test("<"),
        Bin::Le => test("<="),
        Bin::Gt => test(">"),
        Bin::Ge => test(">="),
        Bin::Eq | Bin::Ne if a.kind == Kind::Bool && b.kind == Kind::Bool => {
            let op = if f == Bin::Eq { "==" } else { "!=" };
            (format!("{} {op} {}", a.text, b.text), Kind::Bool)
        }
        Bin::Eq => test("=="),
        Bin::Ne => test("!="),
        Bin::And => (format!("{} && {}", a.as_bool(), b.as_bool()), Kind::Bool),
        Bin::Or => (format!("{} || {}", a.as_bool(), b.as_bool()), Kind::Bool),
        Bin::Min => num(format!("min({x}, {y})")),
        Bin::Max => num(format!("max({x}, {y})")),
    }
}

/// A noise call with its constant options spelled out.
fn noise(f: NoiseFn, p: &str) -> String {
    let fractal = |name: &str, fr: crate::pattern::Fractal, seed: u32| {
        format!(
            "{name}({p}, octaves: {}, omega: {}, lambda: {}, seed: {seed})",
            fr.octaves,
            number(fr.omega),
            number(fr.lambda)
        )
    };
    match f {
        NoiseFn::Unit { seed } => format!("noise({p}, seed: {seed})"),
        NoiseFn::Signed { seed } => format!("snoise({p}, seed: {seed})"),
        NoiseFn::Vector { seed } => format!("vnoise({p}, seed: {seed})"),
        NoiseFn::Fbm { fractal: fr, seed } => fractal("fbm", fr, seed),
        NoiseFn::Turbulence { fractal: fr, seed } => fractal("turbulence", fr, seed),
        NoiseFn::Worley { form, seed } => {
            let form = match form {
                Crackle::F1 => "f1",
                Crackle::F2 => "f2",
                Crackle::Edges => "edges",
            };
            format!("worley({p}, form: \"{form}\", seed: {seed})")
        }
    }
}

/// True for a plain name (`v3`, `p`): a vector's components can be read off it.
fn is_name(s: &str) -> bool {
    !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}
