//! [`Program`]: a user function of position compiled to a flat list of register operations
//! (the language's `pattern(f)`; `eval::compile` builds it), evaluated per sample without the
//! language's interpreter, without allocating and without unsafe code.
//!
//! The machine has up to [`REGISTERS`] `f64` registers: a number (an `Int`, a `Float`, an
//! angle in radians, a `Bool` as 0 or 1) takes one, a vector three consecutive ones. The point
//! is in registers 0, 1 and 2 when a program starts. Every operation reads all its inputs
//! before it writes its output, so outputs may overlap inputs. Jumps go forward only (an `if`),
//! so every program ends after at most `ops.len()` steps. Each operation computes exactly what
//! the interpreter computes for the same operator or built-in (the same `glam`, `libm` and
//! pattern-module calls), so a compiled function gives the interpreter's bits.

use glam::DVec3;

use crate::num::Norm;

use super::fbm::{self, Fractal};
use super::noisy::Crackle;
use super::{cells, noise};

/// The most registers a program may use.
pub const REGISTERS: usize = 256;
/// The most operations a program may have.
pub const MAX_OPS: usize = 4096;

/// A register's index.
pub type Reg = u16;

/// A one-number operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Un {
    /// `-x`.
    Neg,
    /// `!b` on 0 or 1.
    Not,
    /// `abs(x)`.
    Abs,
    /// `floor(x)`.
    Floor,
    /// `ceil(x)`.
    Ceil,
    /// `round(x)`, halves away from zero.
    Round,
    /// `int(x)`: towards zero.
    Trunc,
    /// `sqrt(x)`.
    Sqrt,
    /// `sin(a)` (`libm`).
    Sin,
    /// `cos(a)`.
    Cos,
    /// `tan(a)`.
    Tan,
    /// `asin(x)`.
    Asin,
    /// `acos(x)`.
    Acos,
    /// `atan(x)`.
    Atan,
    /// `exp(x)`.
    Exp,
    /// `ln(x)`.
    Ln,
}

impl Un {
    /// The operation on `x`.
    #[inline]
    pub fn apply(self, x: f64) -> f64 {
        match self {
            Un::Neg => -x,
            Un::Not => bool_f(x == 0.0),
            Un::Abs => x.abs(),
            Un::Floor => x.floor(),
            Un::Ceil => x.ceil(),
            Un::Round => x.round(),
            Un::Trunc => x.trunc(),
            Un::Sqrt => x.sqrt(),
            Un::Sin => libm::sin(x),
            Un::Cos => libm::cos(x),
            Un::Tan => libm::tan(x),
            Un::Asin => libm::asin(x),
            Un::Acos => libm::acos(x),
            Un::Atan => libm::atan(x),
            Un::Exp => libm::exp(x),
            Un::Ln => libm::log(x),
        }
    }
}

/// A two-number operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bin {
    /// `a + b`.
    Add,
    /// `a - b`.
    Sub,
    /// `a * b`.
    Mul,
    /// `a / b`.
    Div,
    /// `a % b`: the Euclidean remainder, as the language's `%`.
    Rem,
    /// `a div b`: the Euclidean quotient.
    IntDiv,
    /// `a ** b`, `pow(a, b)` (`libm`).
    Pow,
    /// `atan2(y: a, x: b)`.
    Atan2,
    /// `a < b` (1 or 0).
    Lt,
    /// `a <= b`.
    Le,
    /// `a > b`.
    Gt,
    /// `a >= b`.
    Ge,
    /// `a == b`.
    Eq,
    /// `a != b`.
    Ne,
    /// `a && b` on 0 or 1.
    And,
    /// `a || b` on 0 or 1.
    Or,
    /// `min(a, b)`: `b` when `b < a`, else `a` (the language's `min` keeps the first of equals).
    Min,
    /// `max(a, b)`: `b` when `b > a`, else `a`.
    Max,
}

impl Bin {
    /// The operation on `a` and `b`.
    #[inline]
    pub fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            Bin::Add => a + b,
            Bin::Sub => a - b,
            Bin::Mul => a * b,
            Bin::Div => a / b,
            Bin::Rem => a.rem_euclid(b),
            Bin::IntDiv => a.div_euclid(b),
            Bin::Pow => libm::pow(a, b),
            Bin::Atan2 => libm::atan2(a, b),
            Bin::Lt => bool_f(a < b),
            Bin::Le => bool_f(a <= b),
            Bin::Gt => bool_f(a > b),
            Bin::Ge => bool_f(a >= b),
            Bin::Eq => bool_f(a == b),
            Bin::Ne => bool_f(a != b),
            Bin::And => bool_f(a != 0.0 && b != 0.0),
            Bin::Or => bool_f(a != 0.0 || b != 0.0),
            Bin::Min => {
                if b < a {
                    b
                } else {
                    a
                }
            }
            Bin::Max => {
                if b > a {
                    b
                } else {
                    a
                }
            }
        }
    }
}

/// An operation on vectors (`v` a vector, `s` a number).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VecOp {
    /// `v + w`.
    Add,
    /// `v - w`.
    Sub,
    /// `v * w`, by component.
    Mul,
    /// `v * s` (and `s * v`: `b` is the number).
    Scale,
    /// `v / s`.
    Div,
    /// `-v` (`b` unused).
    Neg,
    /// `dot(v, w)`: a number.
    Dot,
    /// `cross(v, w)`.
    Cross,
    /// `length(v)`: a number (`b` unused).
    Length,
    /// `distance(v, w)`: a number.
    Distance,
    /// `normalize(v)` (`b` unused).
    Normalize,
    /// `v == w`: 1 or 0.
    Eq,
    /// `v != w`: 1 or 0.
    Ne,
}

/// A noise built-in, its constant arguments folded in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NoiseFn {
    /// `noise(p)`: [`noise::unit`], in [0, 1].
    Unit {
        /// The seed.
        seed: u32,
    },
    /// `snoise(p)`: [`noise::signed`].
    Signed {
        /// The seed.
        seed: u32,
    },
    /// `vnoise(p)`: [`noise::vector`], a vector.
    Vector {
        /// The seed.
        seed: u32,
    },
    /// `fbm(p, ..)`: [`fbm::fbm`].
    Fbm {
        /// Octaves, omega and lambda.
        fractal: Fractal,
        /// The seed.
        seed: u32,
    },
    /// `turbulence(p, ..)`: [`fbm::turbulence`].
    Turbulence {
        /// Octaves, omega and lambda.
        fractal: Fractal,
        /// The seed.
        seed: u32,
    },
    /// `worley(p, ..)`: F1, F2 or F2 − F1 of [`cells::worley`], unclamped.
    Worley {
        /// Which distance.
        form: Crackle,
        /// The seed.
        seed: u32,
    },
}

impl NoiseFn {
    /// How many registers the result takes (3 for a vector).
    pub fn width(&self) -> usize {
        match self {
            NoiseFn::Vector { .. } => 3,
            _ => 1,
        }
    }

    /// The value at `p` (a number is in `x`).
    #[inline]
    pub fn eval(&self, p: DVec3) -> DVec3 {
        let n = |x: f64| DVec3::new(x, 0.0, 0.0);
        match *self {
            NoiseFn::Unit { seed } => n(noise::unit(p, seed)),
            NoiseFn::Signed { seed } => n(noise::signed(p, seed)),
            NoiseFn::Vector { seed } => noise::vector(p, seed),
            NoiseFn::Fbm { fractal, seed } => n(fbm::fbm(p, &fractal, seed)),
            NoiseFn::Turbulence { fractal, seed } => n(fbm::turbulence(p, &fractal, seed)),
            NoiseFn::Worley { form, seed } => n(worley(p, form, seed)),
        }
    }
}

/// Worley's F1, F2 or F2 − F1 at `p`, unclamped (the `worley` built-in).
#[inline]
pub fn worley(p: DVec3, form: Crackle, seed: u32) -> f64 {
    let d = cells::worley(p, seed);
    match form {
        Crackle::F1 => d.f1,
        Crackle::F2 => d.f2,
        Crackle::Edges => d.f2 - d.f1,
    }
}

/// One operation of a [`Program`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    /// `dst = value`.
    Const {
        /// The register written.
        dst: Reg,
        /// The constant.
        value: f64,
    },
    /// `dst..dst+width = src..src+width`.
    Copy {
        /// The first register written.
        dst: Reg,
        /// The first register read.
        src: Reg,
        /// 1 or 3.
        width: u8,
    },
    /// `dst = f(a)`.
    Un {
        /// The operation.
        f: Un,
        /// The register written.
        dst: Reg,
        /// The register read.
        a: Reg,
    },
    /// `dst = f(a, b)`.
    Bin {
        /// The operation.
        f: Bin,
        /// The register written.
        dst: Reg,
        /// The first operand.
        a: Reg,
        /// The second operand.
        b: Reg,
    },
    /// `dst = f(a, b)` on vectors (see [`VecOp`] for which are vectors).
    Vec {
        /// The operation.
        f: VecOp,
        /// The first register written.
        dst: Reg,
        /// The first operand (a vector).
        a: Reg,
        /// The second operand.
        b: Reg,
    },
    /// `dst = f(p)`, `p` a vector.
    Noise {
        /// The function.
        f: NoiseFn,
        /// The first register written.
        dst: Reg,
        /// The point's first register.
        p: Reg,
    },
    /// Continue at operation `to` (forward).
    Jump {
        /// The next operation.
        to: u32,
    },
    /// Continue at operation `to` (forward) when register `cond` is 0.
    JumpUnless {
        /// The condition read.
        cond: Reg,
        /// The next operation when it is false.
        to: u32,
    },
}

/// A program that breaks the machine's rules (a bug in the compiler, or a function too large).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Invalid {
    /// More than [`MAX_OPS`] operations.
    TooLong(usize),
    /// A register at or above [`REGISTERS`].
    Register(usize),
    /// A jump backwards or past the end.
    Jump(usize),
}

/// A compiled function of position: its operations and the register holding its result.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    ops: Vec<Op>,
    result: Reg,
    registers: usize,
}

impl Program {
    /// The program running `ops` from the point in registers 0–2, its value in `result`;
    /// checked: every register below [`REGISTERS`], every jump forward, at most [`MAX_OPS`]
    /// operations.
    pub fn new(ops: Vec<Op>, result: Reg) -> Result<Program, Invalid> {
        if ops.len() > MAX_OPS {
            return Err(Invalid::TooLong(ops.len()));
        }
        let mut top = usize::from(result) + 1;
        let mut reach = |r: Reg, width: usize| {
            top = top.max(usize::from(r) + width);
        };
        for (i, op) in ops.iter().enumerate() {
            match *op {
                Op::Const { dst, .. } => reach(dst, 1),
                Op::Copy { dst, src, width } => {
                    reach(dst, usize::from(width.clamp(1, 3)));
                    reach(src, usize::from(width.clamp(1, 3)));
                }
                Op::Un { dst, a, .. } => {
                    reach(dst, 1);
                    reach(a, 1);
                }
                Op::Bin { dst, a, b, .. } => {
                    reach(dst, 1);
                    reach(a, 1);
                    reach(b, 1);
                }
                Op::Vec { f, dst, a, b } => {
                    let scalar_out = matches!(
                        f,
                        VecOp::Dot | VecOp::Length | VecOp::Distance | VecOp::Eq | VecOp::Ne
                    );
                    reach(dst, if scalar_out { 1 } else { 3 });
                    reach(a, 3);
                    reach(
                        b,
                        if matches!(f, VecOp::Scale | VecOp::Div) {
                            1
                        } else {
                            3
                        },
                    );
                }
                Op::Noise { f, dst, p } => {
                    reach(dst, f.width());
                    reach(p, 3);
                }
                Op::Jump { to } | Op::JumpUnless { to, .. } => {
                    if to as usize <= i || to as usize > ops.len() {
                        return Err(Invalid::Jump(i));
                    }
                    if let Op::JumpUnless { cond, .. } = *op {
                        reach(cond, 1);
                    }
                }
            }
        }
        let registers = top.max(3);
        if registers > REGISTERS {
            return Err(Invalid::Register(registers));
        }
        Ok(Program {
            ops,
            result,
            registers,
        })
    }

    /// The operations.
    pub fn ops(&self) -> &[Op] {
        &self.ops
    }

    /// The register holding the result.
    pub fn result(&self) -> Reg {
        self.result
    }

    /// How many registers it uses.
    pub fn registers(&self) -> usize {
        self.registers
    }

    /// The pattern's value at `p`: [`Program::run`], with a value that is not finite (where
    /// the interpreter would have stopped: a division by zero, `sqrt` of a negative number)
    /// read as 0.
    #[inline]
    pub fn eval(&self, p: DVec3) -> f64 {
        let v = self.run(p);
        if v.is_finite() { v } else { 0.0 }
    }

    /// The function's value at `p`, as computed.
    #[inline]
    pub fn run(&self, p: DVec3) -> f64 {
        // Register files of three sizes, so a small program does not clear a large one.
        if self.registers <= 16 {
            self.run_in(&mut [0.0; 16], p)
        } else if self.registers <= 64 {
            self.run_in(&mut [0.0; 64], p)
        } else {
            self.run_in(&mut [0.0; REGISTERS], p)
        }
    }

    fn run_in(&self, r: &mut [f64], p: DVec3) -> f64 {
        let v3 = |r: &[f64], i: Reg| {
            let i = usize::from(i);
            DVec3::new(r[i], r[i + 1], r[i + 2])
        };
        let put3 = |r: &mut [f64], i: Reg, v: DVec3| {
            let i = usize::from(i);
            r[i] = v.x;
            r[i + 1] = v.y;
            r[i + 2] = v.z;
        };
        put3(r, 0, p);
        let mut pc = 0;
        while let Some(op) = self.ops.get(pc) {
            pc += 1;
            match *op {
                Op::Const { dst, value } => r[usize::from(dst)] = value,
                Op::Copy { dst, src, width } => {
                    if width == 3 {
                        let v = v3(r, src);
                        put3(r, dst, v);
                    } else {
                        r[usize::from(dst)] = r[usize::from(src)];
                    }
                }
                Op::Un { f, dst, a } => r[usize::from(dst)] = f.apply(r[usize::from(a)]),
                Op::Bin { f, dst, a, b } => {
                    r[usize::from(dst)] = f.apply(r[usize::from(a)], r[usize::from(b)]);
                }
                Op::Vec { f, dst, a, b } => {
                    let x = v3(r, a);
                    let s = r[usize::from(b)];
                    let y = if matches!(f, VecOp::Scale | VecOp::Div) {
                        DVec3::ZERO
                    } else {
                        v3(r, b)
                    };
                    match f {
                        VecOp::Add => put3(r, dst, x + y),
                        VecOp::Sub => put3(r, dst, x - y),
                        VecOp::Mul => put3(r, dst, x * y),
                        VecOp::Scale => put3(r, dst, x * s),
                        VecOp::Div => put3(r, dst, x / s),
                        VecOp::Neg => put3(r, dst, -x),
                        VecOp::Dot => r[usize::from(dst)] = x.dot(y),
                        VecOp::Cross => put3(r, dst, x.cross(y)),
                        VecOp::Length => r[usize::from(dst)] = x.norm(),
                        VecOp::Distance => r[usize::from(dst)] = x.distance_to(y),
                        VecOp::Normalize => put3(r, dst, x.unit()),
                        VecOp::Eq => r[usize::from(dst)] = bool_f(x == y),
                        VecOp::Ne => r[usize::from(dst)] = bool_f(x != y),
                    }
                }
                Op::Noise { f, dst, p } => {
                    let v = f.eval(v3(r, p));
                    if f.width() == 3 {
                        put3(r, dst, v);
                    } else {
                        r[usize::from(dst)] = v.x;
                    }
                }
                Op::Jump { to } => pc = to as usize,
                Op::JumpUnless { cond, to } => {
                    if r[usize::from(cond)] == 0.0 {
                        pc = to as usize;
                    }
                }
            }
        }
        r[usize::from(self.result)]
    }
}

/// 1 for true, 0 for false.
#[inline(always)]
fn bool_f(b: bool) -> f64 {
    if b { 1.0 } else { 0.0 }
}
