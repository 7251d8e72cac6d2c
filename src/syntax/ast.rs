//! The abstract syntax tree. Every node carries the [`Span`] of the text it came from.

use std::rc::Rc;

use crate::source::{FileId, Span};
use crate::syntax::intern::Sym;

/// A name with the span where it was written.
#[derive(Clone, Copy, Debug)]
pub struct Name {
    /// The interned name.
    pub(crate) sym: Sym,
    /// Where it was written.
    pub(crate) span: Span,
}

/// A parsed file: its header and statements, borrowing the text it was parsed from.
///
/// The statements the fast path read (one-line calls, names, numbers, `let`: most of a
/// generated file) are kept as the steps reading found (a tape, ~110 bytes a sphere line) and built
/// each time they are visited ([`File::stmts`]), so the AST of a file of 100 000 sphere lines
/// is never whole in memory (it was ~600 bytes a line); the statements pest read are kept built.
#[derive(Clone)]
pub struct File<'t> {
    /// The `rtc N` version as written (`1`, `1.1`), if the header was present.
    pub(crate) version: Option<(String, Span)>,
    /// The statements in order.
    pub(super) items: Vec<Item>,
    /// The statements pest read, which `Item::Built` indexes.
    pub(super) built: Vec<Stmt>,
    /// What the fast path read, which `Item::Line` indexes.
    pub(super) tapes: Vec<super::fast::Tape>,
    /// The file's id and text (for the names of `Item::Line` statements).
    pub(super) file: FileId,
    pub(super) text: &'t str,
}

/// One top-level statement of a [`File`].
#[derive(Clone, Copy)]
pub(super) enum Item {
    /// The statement `File::built[i]`.
    Built(u32),
    /// A statement the fast path read: written on `tapes[tape]` at `at`.
    Line {
        /// Which tape.
        tape: u32,
        /// Where on it.
        at: super::fast::Mark,
    },
}

/// A statement.
#[derive(Clone, Debug)]
pub(crate) enum Stmt {
    /// `import std.x as y`, `import "./f.rtc" { a, b }` (boxed: rare, and the largest).
    Import(Box<Import>),
    /// `let name = value`.
    Let(Let),
    /// `fn name(params) { body }`.
    Fn(Rc<FnDef>),
    /// An expression statement (emits in a scene file, yields in a block).
    Expr(Expr),
}

/// Where an import comes from.
#[derive(Clone, Debug)]
pub(crate) enum ImportSource {
    /// `std.name`: an embedded standard-library module.
    Std(String),
    /// A file path relative to the importing file.
    File(String),
}

/// An `import` statement.
#[derive(Clone, Debug)]
pub(crate) struct Import {
    /// The module.
    pub(crate) source: ImportSource,
    /// Span of the module path.
    pub(crate) source_span: Span,
    /// `as alias`.
    pub(crate) alias: Option<Name>,
    /// `{ a, b }`.
    pub(crate) names: Vec<Name>,
    /// The whole statement.
    pub(crate) span: Span,
}

/// A `let` binding.
#[derive(Clone, Debug)]
pub(crate) struct Let {
    /// Exported with `pub`.
    pub(crate) public: bool,
    /// Declared with `param`: the command line may override its value (`--set name=value`).
    pub(crate) param: bool,
    /// The bound name.
    pub(crate) name: Name,
    /// Optional type annotation (boxed: rare, and it would double a statement's size).
    pub(crate) ty: Option<Box<TypeAnn>>,
    /// The value.
    pub(crate) value: Expr,
    /// The whole statement.
    pub(crate) span: Span,
}

/// A type annotation such as `Float`, `List<Object>` or `Angle?`.
#[derive(Clone, Debug)]
pub(crate) struct TypeAnn {
    /// The type's name.
    pub(crate) name: Name,
    /// Element type of `List<T>`.
    pub(crate) arg: Option<Box<TypeAnn>>,
    /// The whole annotation.
    pub(crate) span: Span,
}

/// A function definition (named item or `fn(x) expr` literal).
#[derive(Clone, Debug)]
pub struct FnDef {
    /// Exported with `pub`.
    pub(crate) public: bool,
    /// Its name (`fn` literals are named `<fn>` at their span).
    pub(crate) name: Name,
    /// Parameters in order.
    pub(crate) params: Vec<Param>,
    /// Declared return type.
    pub(crate) ret: Option<TypeAnn>,
    /// The body; its last expression is the result.
    pub(crate) body: Block,
}

/// One parameter.
#[derive(Clone, Debug)]
pub(crate) struct Param {
    /// Its name.
    pub(crate) name: Name,
    /// Its type, if annotated.
    pub(crate) ty: Option<TypeAnn>,
    /// Default value, evaluated at call time in the function's scope.
    pub(crate) default: Option<Expr>,
}

/// A `{ ... }` block: statements, the last expression is its value.
#[derive(Clone, Debug)]
pub struct Block {
    /// The statements.
    pub(crate) stmts: Vec<Stmt>,
    /// From `{` to `}`.
    pub(crate) span: Span,
}

/// An expression node.
#[derive(Clone, Debug)]
pub struct Expr {
    /// What it is.
    pub(crate) kind: ExprKind,
    /// Where it is.
    pub(crate) span: Span,
}

/// Binary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum BinOp {
    /// `||`
    Or,
    /// `&&`
    And,
    /// `==`
    Eq,
    /// `!=`
    Ne,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `>>` (transform "then")
    Then,
    /// `|` (union)
    Union,
    /// `+`
    Add,
    /// `-` (also CSG difference)
    Sub,
    /// `&` (intersection)
    Inter,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `%`
    Rem,
    /// `div` (integer division, rounding toward negative infinity for a positive divisor)
    IntDiv,
    /// `**`
    Pow,
}

impl BinOp {
    /// The operator as written.
    pub(crate) fn as_str(self) -> &'static str {
        match self {
            BinOp::Or => "||",
            BinOp::And => "&&",
            BinOp::Eq => "==",
            BinOp::Ne => "!=",
            BinOp::Lt => "<",
            BinOp::Le => "<=",
            BinOp::Gt => ">",
            BinOp::Ge => ">=",
            BinOp::Then => ">>",
            BinOp::Union => "|",
            BinOp::Add => "+",
            BinOp::Sub => "-",
            BinOp::Inter => "&",
            BinOp::Mul => "*",
            BinOp::Div => "/",
            BinOp::Rem => "%",
            BinOp::IntDiv => "div",
            BinOp::Pow => "**",
        }
    }
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum UnOp {
    /// `-x`
    Neg,
    /// `!x`
    Not,
}

/// A piece of a string literal.
#[derive(Clone, Debug)]
pub(crate) enum StrPart {
    /// Literal text (escapes resolved).
    Text(String),
    /// `{expr}` or `{expr:.2}` (digits after the point).
    Interp(Expr, Option<usize>),
}

/// A record field `name: value`.
#[derive(Clone, Debug)]
pub(crate) struct Field {
    /// The field name.
    pub(crate) name: Name,
    /// Its value.
    pub(crate) value: Expr,
}

/// A call argument, positional or named.
#[derive(Clone, Debug)]
pub struct Arg {
    /// `name:` for a named argument.
    pub(crate) name: Option<Name>,
    /// The value.
    pub(crate) value: Expr,
}

/// One `name in iterable` of a `for`.
#[derive(Clone, Debug)]
pub struct Generator {
    /// The loop variable.
    pub(crate) var: Name,
    /// What it ranges over.
    pub(crate) iter: Expr,
}

/// Expression kinds.
#[derive(Clone, Debug)]
pub(crate) enum ExprKind {
    /// `3`
    Int(i64),
    /// `0.5`
    Float(f64),
    /// `30deg` (stored in radians).
    Angle(f64),
    /// `true`
    Bool(bool),
    /// `#ff8800` (linear RGB, converted from sRGB).
    Color([f64; 3]),
    /// `[1, 2.5, -3]`: three plain numbers, read as one token.
    Vec3([f64; 3]),
    /// `"a {x} b"`
    Str(Vec<StrPart>),
    /// A string without interpolation, shared so evaluating it never allocates.
    StrLit(Rc<str>),
    /// A name.
    Ident(Sym),
    /// `[a, b]`; `true` for three plain numbers followed by a comma (`[1, 2, 3,]`, a `List`
    /// where three numbers would make a `Vec3`: docs/fmt.md).
    List(Vec<Expr>, bool),
    /// `{ a: 1 }`
    Record(Vec<Field>),
    /// `-x`, `!x`
    Unary(UnOp, Box<Expr>),
    /// `a + b`
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `a..b`, `a..=b step s`
    Range {
        /// Start.
        start: Box<Expr>,
        /// End.
        end: Box<Expr>,
        /// `..=`
        inclusive: bool,
        /// `step s`
        step: Option<Box<Expr>>,
    },
    /// `f(args)` and `f { record }`.
    Call(Box<Expr>, Vec<Arg>),
    /// `a.name`
    Member(Box<Expr>, Name),
    /// `a[i]`
    Index(Box<Expr>, Box<Expr>),
    /// `a with { f: v }`
    With(Box<Expr>, Vec<Field>),
    /// `if c { a } else { b }` (blocks are boxed here and in `For` so that every expression
    /// node stays small: a generated file holds millions of them).
    If(Box<Expr>, Box<Block>, Option<Box<Expr>>),
    /// `for i in r, j in s if c { body }`
    For(Box<[Generator]>, Option<Box<Expr>>, Box<Block>),
    /// `fn(x) x * 2`
    Lambda(Rc<FnDef>),
    /// A `{ ... }` block used as an `else` branch.
    Block(Block),
}
