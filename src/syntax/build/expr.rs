//! The expression half of the tree builder: operators through the Pratt table, suffixes,
//! arguments, fields, numbers and the other primaries.

use std::rc::Rc;

use crate::diag::Diagnostic;
use crate::source::Span;
use crate::syntax::ast::*;
use crate::syntax::grammar::Rule;
use crate::syntax::intern::Sym;
use crate::syntax::numbers::{self, Number, NumberError};
use crate::syntax::pratt;

use super::{Builder, P, srgb_to_linear, unescape};

/// Longest chain of operators and suffixes (calls, indexing, members, `with`) in one
/// expression: the tree is as deep as the chain, and evaluating, formatting and dropping it
/// recurse once per level.
pub(crate) const MAX_CHAIN: usize = 10_000;

/// An expression with what its top operator was, so that `a < b < c` and `0..1..2` can be told
/// from `(a < b) < c`: parentheses reset the tag.
struct Built {
    expr: Expr,
    top: Top,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Top {
    Other,
    Comparison,
    Range,
    RangeWithStep,
}

impl Builder {
    /// Any expression-level pair.
    pub(crate) fn expr(&self, p: P) -> Expr {
        match p.as_rule() {
            Rule::expr | Rule::head_expr => self.flat(p),
            Rule::paren => {
                // The parentheses belong to the span, so `(-8) ** 0.5` is quoted whole.
                let span = self.span(&p);
                let mut e = self.expr(p.into_inner().next().expect("grammar: inner"));
                e.span = span;
                e
            }
            _ => {
                let span = self.span(&p);
                Expr {
                    kind: self.primary(p),
                    span,
                }
            }
        }
    }

    fn too_long(&self, span: Span) -> Expr {
        self.push(
            Diagnostic::error("rtc::budget::nesting", span, "expression is too long")
                .with_label(format!(
                    "more than {MAX_CHAIN} operators and suffixes (calls, indexing, members) in one expression"
                ))
                .with_help("split it into several `let` bindings"),
        );
        Expr {
            kind: ExprKind::Int(0),
            span,
        }
    }

    /// A flat `expr`: operands and operators in a row. Without prefix or infix operators (the
    /// common case: a literal, a name, a call chain) the suffixes are applied directly; otherwise
    /// the Pratt table decides.
    fn flat(&self, p: P) -> Expr {
        let mut inner = p.clone().into_inner();
        let first = inner.next().expect("grammar: operand");
        let (mut ops, mut suffixes) = (0usize, 0usize);
        for q in inner.clone() {
            let r = q.as_rule();
            if pratt::is_infix(r) || r == Rule::unary_op {
                ops += 1;
            } else if pratt::is_suffix(r) {
                suffixes += 1;
            }
        }
        if first.as_rule() == Rule::unary_op {
            ops += 1;
        }
        if ops + suffixes > MAX_CHAIN {
            return self.too_long(self.span(&p));
        }
        if ops == 0 {
            let mut e = self.expr(first);
            for s in inner {
                e = self.suffix(e, s);
            }
            return e;
        }
        let built = pratt::PRATT
            .map_primary(|q| Built {
                expr: self.expr(q),
                top: Top::Other,
            })
            .map_prefix(|op, rhs| {
                let span = self.span(&op).join(rhs.expr.span);
                let op = if op.as_str() == "-" {
                    UnOp::Neg
                } else {
                    UnOp::Not
                };
                Built {
                    expr: Expr {
                        kind: ExprKind::Unary(op, Box::new(rhs.expr)),
                        span,
                    },
                    top: Top::Other,
                }
            })
            .map_postfix(|lhs, s| Built {
                expr: self.suffix(lhs.expr, s),
                top: Top::Other,
            })
            .map_infix(|lhs, op, rhs| self.infix(lhs, op, rhs))
            .parse(p.into_inner());
        built.expr
    }

    fn infix(&self, lhs: Built, op: P, rhs: Built) -> Built {
        let span = lhs.expr.span.join(rhs.expr.span);
        let op_span = self.span(&op);
        let chained = |what: &str, help: &str| {
            Diagnostic::error(
                "rtc::syntax::unexpected",
                op_span,
                format!("{what} do not chain"),
            )
            .with_label("the second operator of the chain")
            .with_help(help.to_owned())
        };
        match op.as_rule() {
            Rule::range_op => {
                if lhs.top != Top::Other || rhs.top != Top::Other {
                    self.push(chained(
                        "ranges",
                        "put a range in parentheses to use it as a value",
                    ));
                }
                Built {
                    expr: Expr {
                        kind: ExprKind::Range {
                            start: Box::new(lhs.expr),
                            end: Box::new(rhs.expr),
                            inclusive: op.as_str() == "..=",
                            step: None,
                        },
                        span,
                    },
                    top: Top::Range,
                }
            }
            Rule::step_kw => {
                let Built {
                    expr:
                        Expr {
                            kind:
                                ExprKind::Range {
                                    start,
                                    end,
                                    inclusive,
                                    step: None,
                                },
                            ..
                        },
                    top: Top::Range,
                } = lhs
                else {
                    self.push(
                        Diagnostic::error(
                            "rtc::syntax::unexpected",
                            op_span,
                            "`step` must follow a range",
                        )
                        .with_label("no range before this `step`")
                        .with_help("write `a..b step s`"),
                    );
                    return lhs;
                };
                Built {
                    expr: Expr {
                        kind: ExprKind::Range {
                            start,
                            end,
                            inclusive,
                            step: Some(Box::new(rhs.expr)),
                        },
                        span,
                    },
                    top: Top::RangeWithStep,
                }
            }
            _ => {
                let bop = pratt::bin_op(op.as_str()).expect("grammar: binary operator");
                let is_cmp = op.as_rule() == Rule::cmp_op;
                if is_cmp && (lhs.top == Top::Comparison || rhs.top == Top::Comparison) {
                    self.push(chained(
                        "comparisons",
                        "join two comparisons with `&&`, e.g. `a < b && b < c`",
                    ));
                }
                Built {
                    expr: Expr {
                        kind: ExprKind::Binary(bop, Box::new(lhs.expr), Box::new(rhs.expr)),
                        span,
                    },
                    top: if is_cmp { Top::Comparison } else { Top::Other },
                }
            }
        }
    }

    /// Applies one suffix (call, index, member, record call, `with`) to `e`.
    fn suffix(&self, e: Expr, s: P) -> Expr {
        let span = e.span.join(self.span(&s));
        let kind = match s.as_rule() {
            Rule::call_args => {
                let args = s.into_inner().map(|a| self.arg(a)).collect();
                ExprKind::Call(Box::new(e), args)
            }
            Rule::index => {
                let i = self.expr(s.into_inner().next().expect("grammar: index"));
                ExprKind::Index(Box::new(e), Box::new(i))
            }
            Rule::member => {
                let n = self.name(&s.into_inner().next().expect("grammar: member"));
                ExprKind::Member(Box::new(e), n)
            }
            Rule::record_arg => {
                let r = s.into_inner().next().expect("grammar: record");
                let rspan = self.span(&r);
                let fields = self.fields(r);
                let value = Expr {
                    kind: ExprKind::Record(fields),
                    span: rspan,
                };
                ExprKind::Call(Box::new(e), vec![Arg { name: None, value }])
            }
            Rule::empty_record_arg => {
                let value = Expr {
                    kind: ExprKind::Record(Vec::new()),
                    span: self.span(&s),
                };
                ExprKind::Call(Box::new(e), vec![Arg { name: None, value }])
            }
            _ => {
                let r = s.into_inner().next().expect("grammar: record");
                ExprKind::With(Box::new(e), self.fields(r))
            }
        };
        Expr { kind, span }
    }

    fn eq_slip(&self, p: &P) {
        let s = self.span(p);
        self.push(
            Diagnostic::error("rtc::syntax::eq_for_colon", s, "expected `:`, found `=`")
                .with_label("fields and named arguments use `:`")
                .with_help("write `:` instead of `=`"),
        );
    }

    /// The optional name and the value of an argument or a record field (`name: value`; a
    /// `=` slipped in for `:` is reported).
    fn named_value(&self, p: P) -> (Option<Name>, Option<Expr>) {
        let mut name = None;
        let mut value = None;
        for q in p.into_inner() {
            match q.as_rule() {
                Rule::ident => name = Some(self.name(&q)),
                Rule::eq_slip => self.eq_slip(&q),
                _ => value = Some(self.expr(q)),
            }
        }
        (name, value)
    }

    fn arg(&self, p: P) -> Arg {
        let (name, value) = self.named_value(p);
        Arg {
            name,
            value: value.expect("grammar: argument value"),
        }
    }

    fn fields(&self, record: P) -> Vec<Field> {
        record
            .into_inner()
            .map(|f| {
                let (name, value) = self.named_value(f);
                Field {
                    name: name.expect("grammar: field name"),
                    value: value.expect("grammar: field value"),
                }
            })
            .collect()
    }

    fn number_error(&self, p: &P, message: &str, help: String) {
        let s = self.span(p);
        self.push(
            Diagnostic::error("rtc::syntax::number", s, message.to_owned())
                .with_label("does not fit in 64 bits")
                .with_help(help),
        );
    }

    /// A plain number `3`, `0.5`, `2e6` (no unit) as `Int` or `Float`; a too-large integer or
    /// a float that overflows to infinity is an error.
    fn plain_number(&self, p: &P, text: &str) -> Number {
        match numbers::plain(text) {
            Ok(n) => n,
            Err(NumberError::IntTooLarge) => {
                self.number_error(
                    p,
                    "integer literal is too large",
                    format!("write it as a float: `{}.0`", text.trim_start_matches('-')),
                );
                Number::Int(0)
            }
            Err(NumberError::TooLarge) => {
                self.number_error(
                    p,
                    "number is too large",
                    "numbers must be below about 1.8e308".to_owned(),
                );
                Number::Float(0.0)
            }
        }
    }

    /// `number`: an Int, a Float or an Angle (`30deg`, `0.5rad`, `0.25turn`, `45°`).
    fn number(&self, p: &P) -> ExprKind {
        let (digits, unit) = numbers::split_unit(p.as_str());
        numbers::apply_unit(self.plain_number(p, digits), unit).into()
    }

    /// `vec_lit`: `[x, y, z]` of plain numbers, read from the token's text.
    fn vec_lit(&self, p: &P) -> ExprKind {
        let text = p.as_str();
        let mut out = [0.0; 3];
        for (slot, part) in out.iter_mut().zip(text[1..text.len() - 1].split(',')) {
            *slot = numbers::component(self.plain_number(p, part.trim()));
        }
        ExprKind::Vec3(out)
    }

    fn primary(&self, p: P) -> ExprKind {
        match p.as_rule() {
            Rule::number => self.number(&p),
            Rule::vec_lit => self.vec_lit(&p),
            Rule::bool_lit => ExprKind::Bool(p.as_str() == "true"),
            Rule::hex_color => {
                let h = &p.as_str()[1..];
                let digits: Vec<u32> = h.chars().filter_map(|c| c.to_digit(16)).collect();
                let rgb = if digits.len() == 3 {
                    [digits[0] * 17, digits[1] * 17, digits[2] * 17]
                } else {
                    [
                        digits[0] * 16 + digits[1],
                        digits[2] * 16 + digits[3],
                        digits[4] * 16 + digits[5],
                    ]
                };
                ExprKind::Color(rgb.map(|c| srgb_to_linear(c as f64 / 255.0)))
            }
            Rule::string => {
                let mut parts = Vec::new();
                for q in p.into_inner() {
                    match q.as_rule() {
                        Rule::str_text => push_text(&mut parts, q.as_str()),
                        Rule::str_escape => {
                            push_text(&mut parts, &unescape(q.as_str()).to_string())
                        }
                        _ => {
                            let mut it = q.into_inner();
                            let e = self.expr(it.next().expect("grammar: interpolation"));
                            let prec = it.next().and_then(|f| f.as_str()[1..].parse().ok());
                            parts.push(StrPart::Interp(e, prec));
                        }
                    }
                }
                match parts.as_slice() {
                    [] => ExprKind::StrLit(Rc::from("")),
                    [StrPart::Text(t)] => ExprKind::StrLit(Rc::from(t.as_str())),
                    _ => ExprKind::Str(parts),
                }
            }
            Rule::ident => ExprKind::Ident(Sym::new(p.as_str())),
            Rule::list => {
                // A comma right before the closing `]` (comments and blank lines aside).
                let body = p.as_str().strip_suffix(']').unwrap_or(p.as_str());
                let trailing = body
                    .lines()
                    .map(|l| l.split("//").next().unwrap_or("").trim())
                    .rfind(|l| !l.is_empty())
                    .is_some_and(|l| l.ends_with(','));
                let items: Vec<Expr> = p.into_inner().map(|q| self.expr(q)).collect();
                // Three plain numbers: a `List` with a trailing comma, else the `Vec3` the
                // one-token form `[1, -2, 3]` is (so `[1, - 2, 3]` and its formatted text,
                // which loses the space, are the same program).
                let number = |e: &Expr| match &e.kind {
                    ExprKind::Int(i) => Some(*i as f64),
                    ExprKind::Float(f) => Some(*f),
                    ExprKind::Unary(UnOp::Neg, x) => match x.kind {
                        ExprKind::Int(i) => i.checked_neg().map(|n| n as f64),
                        ExprKind::Float(f) => Some(-f),
                        _ => None,
                    },
                    _ => None,
                };
                match items.iter().map(number).collect::<Option<Vec<f64>>>() {
                    Some(v) if v.len() == 3 && !trailing => ExprKind::Vec3([v[0], v[1], v[2]]),
                    Some(v) if v.len() == 3 => ExprKind::List(items, true),
                    _ => ExprKind::List(items, false),
                }
            }
            Rule::record_lit => {
                ExprKind::Record(self.fields(p.into_inner().next().expect("grammar: record")))
            }
            Rule::if_expr => {
                let mut it = p.into_inner();
                let cond = self.expr(it.next().expect("grammar: if condition"));
                let then = self.block(it.next().expect("grammar: if block"));
                let els = it.next().map(|q| {
                    let span = self.span(&q);
                    let kind = if q.as_rule() == Rule::block {
                        ExprKind::Block(self.block(q))
                    } else {
                        self.primary(q)
                    };
                    Box::new(Expr { kind, span })
                });
                ExprKind::If(Box::new(cond), Box::new(then), els)
            }
            Rule::for_expr => {
                let mut gens = Vec::new();
                let mut filter = None;
                let mut body = None;
                for q in p.into_inner() {
                    match q.as_rule() {
                        Rule::generator => {
                            let mut it = q.into_inner();
                            let var = self.name(&it.next().expect("grammar: loop variable"));
                            let iter = self.expr(it.next().expect("grammar: iterable"));
                            gens.push(Generator { var, iter });
                        }
                        Rule::filter => {
                            let c = q.into_inner().next().expect("grammar: filter");
                            filter = Some(Box::new(self.expr(c)));
                        }
                        _ => body = Some(self.block(q)),
                    }
                }
                ExprKind::For(
                    gens.into_boxed_slice(),
                    filter,
                    Box::new(body.expect("grammar: for body")),
                )
            }
            Rule::fn_lit => {
                let span = self.span(&p);
                let mut params = Vec::new();
                let mut body = None;
                for q in p.into_inner() {
                    match q.as_rule() {
                        Rule::params => params = self.params(q),
                        Rule::block => body = Some(self.block(q)),
                        _ => {
                            let e = self.expr(q);
                            body = Some(Block {
                                span: e.span,
                                stmts: vec![Stmt::Expr(e)],
                            });
                        }
                    }
                }
                let name = Name {
                    sym: Sym::new("<fn>"),
                    span,
                };
                ExprKind::Lambda(Rc::new(FnDef {
                    public: false,
                    name,
                    params,
                    ret: None,
                    body: body.expect("grammar: fn body"),
                }))
            }
            other => unreachable!("grammar: unexpected primary {other:?}"),
        }
    }
}

fn push_text(parts: &mut Vec<StrPart>, s: &str) {
    if let Some(StrPart::Text(t)) = parts.last_mut() {
        t.push_str(s);
    } else {
        parts.push(StrPart::Text(s.to_owned()));
    }
}
