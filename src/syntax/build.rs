//! Builds the AST from pest's parse tree, reporting the slips the grammar accepts on purpose
//! (`=` instead of `:` in records and named arguments).

use std::rc::Rc;

use pest::iterators::Pair;

use crate::diag::Diagnostic;
use crate::source::{FileId, Span};
use crate::syntax::Rule;
use crate::syntax::ast::*;
use crate::syntax::intern::Sym;

/// Converts sRGB-encoded [0, 1] to linear light (the IEC 61966-2-1 curve; `libm::pow` so the
/// value is the same on every machine).
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        libm::pow((c + 0.055) / 1.055, 2.4)
    }
}

/// Tree builder for one statement parsed at byte `base` of `file`.
pub struct Builder<'a> {
    /// The file being parsed.
    pub file: FileId,
    /// Offset of the parsed slice in the file.
    pub base: usize,
    /// Where slips are reported.
    pub diags: &'a mut Vec<Diagnostic>,
}

type P<'i> = Pair<'i, Rule>;

/// Longest operator chain in one expression: evaluation recurses once per operator.
const MAX_CHAIN: usize = 10_000;

impl Builder<'_> {
    fn span(&self, p: &P) -> Span {
        let s = p.as_span();
        Span::new(self.file, self.base + s.start(), self.base + s.end())
    }

    fn name(&self, p: &P) -> Name {
        Name {
            sym: Sym::new(p.as_str()),
            span: self.span(p),
        }
    }

    /// A statement pair (`import_stmt`, `let_stmt`, `fn_def` or `expr`).
    pub fn stmt(&mut self, p: P) -> Stmt {
        match p.as_rule() {
            Rule::import_stmt => Stmt::Import(self.import(p)),
            Rule::let_stmt => Stmt::Let(self.let_stmt(p)),
            Rule::fn_def => Stmt::Fn(Rc::new(self.fn_def(p))),
            _ => Stmt::Expr(self.expr(p)),
        }
    }

    fn import(&mut self, p: P) -> Import {
        let span = self.span(&p);
        let mut it = p.into_inner();
        let src = it.next().expect("grammar: import source");
        let source_span = self.span(&src);
        let source = if src.as_rule() == Rule::string {
            ImportSource::File(self.plain_string(src))
        } else {
            ImportSource::Std(src.as_str().to_owned())
        };
        let mut alias = None;
        let mut names = Vec::new();
        for q in it {
            match q.as_rule() {
                Rule::ident => alias = Some(self.name(&q)),
                _ => names = q.into_inner().map(|n| self.name(&n)).collect(),
            }
        }
        Import {
            source,
            source_span,
            alias,
            names,
            span,
        }
    }

    fn plain_string(&mut self, p: P) -> String {
        let mut out = String::new();
        for part in p.into_inner() {
            match part.as_rule() {
                Rule::str_text => out.push_str(part.as_str()),
                Rule::str_escape => out.push(unescape(part.as_str())),
                _ => {
                    let s = self.span(&part);
                    self.diags.push(
                        Diagnostic::error(
                            "rtc::syntax::unexpected",
                            s,
                            "interpolation is not allowed in an import path",
                        )
                        .with_label("not a fixed path")
                        .with_help("write the path as plain text"),
                    );
                }
            }
        }
        out
    }

    fn let_stmt(&mut self, p: P) -> Let {
        let span = self.span(&p);
        let mut public = false;
        let mut name = None;
        let mut ty = None;
        let mut value = None;
        for q in p.into_inner() {
            match q.as_rule() {
                Rule::pub_kw => public = true,
                Rule::ident => name = Some(self.name(&q)),
                Rule::type_ann => ty = Some(self.type_ann(q)),
                _ => value = Some(self.expr(q)),
            }
        }
        Let {
            public,
            name: name.expect("grammar: let name"),
            ty,
            value: value.expect("grammar: let value"),
            span,
        }
    }

    fn type_ann(&mut self, p: P) -> TypeAnn {
        let span = self.span(&p);
        let mut it = p.into_inner();
        let name = self.name(&it.next().expect("grammar: type name"));
        let mut arg = None;
        let mut optional = false;
        for q in it {
            match q.as_rule() {
                Rule::type_ann => arg = Some(Box::new(self.type_ann(q))),
                _ => optional = true,
            }
        }
        TypeAnn {
            name,
            arg,
            optional,
            span,
        }
    }

    fn fn_def(&mut self, p: P) -> FnDef {
        let span = self.span(&p);
        let mut public = false;
        let mut name = None;
        let mut params = Vec::new();
        let mut ret = None;
        let mut body = None;
        for q in p.into_inner() {
            match q.as_rule() {
                Rule::pub_kw => public = true,
                Rule::ident => name = Some(self.name(&q)),
                Rule::params => params = self.params(q),
                Rule::type_ann => ret = Some(self.type_ann(q)),
                _ => body = Some(self.block(q)),
            }
        }
        FnDef {
            public,
            name: name.expect("grammar: fn name"),
            params,
            ret,
            body: body.expect("grammar: fn body"),
            span,
        }
    }

    fn params(&mut self, p: P) -> Vec<Param> {
        p.into_inner()
            .map(|q| {
                let mut it = q.into_inner();
                let name = self.name(&it.next().expect("grammar: param name"));
                let mut ty = None;
                let mut default = None;
                for r in it {
                    match r.as_rule() {
                        Rule::type_ann => ty = Some(self.type_ann(r)),
                        _ => default = Some(self.expr(r)),
                    }
                }
                Param { name, ty, default }
            })
            .collect()
    }

    fn block(&mut self, p: P) -> Block {
        let span = self.span(&p);
        let stmts = p.into_inner().map(|q| self.stmt(q)).collect();
        Block { stmts, span }
    }

    /// Any expression-level pair.
    pub fn expr(&mut self, p: P) -> Expr {
        let span = self.span(&p);
        match p.as_rule() {
            Rule::expr | Rule::paren => self.expr(p.into_inner().next().expect("grammar: inner")),
            Rule::or_expr
            | Rule::and_expr
            | Rule::cmp_expr
            | Rule::then_expr
            | Rule::union_expr
            | Rule::add_expr
            | Rule::inter_expr
            | Rule::mul_expr => self.binary(p),
            Rule::range_expr => self.range(p),
            Rule::unary_expr => self.unary(p),
            Rule::postfix => self.postfix(p),
            _ => Expr {
                kind: self.primary(p),
                span,
            },
        }
    }

    fn too_long(&mut self, span: Span) {
        self.diags.push(
            Diagnostic::error("rtc::budget::nesting", span, "expression is too long")
                .with_label(format!("more than {MAX_CHAIN} operators in one expression"))
                .with_help("split it into several `let` bindings"),
        );
    }

    fn binary(&mut self, p: P) -> Expr {
        let span = self.span(&p);
        if p.clone().into_inner().count() > 2 * MAX_CHAIN {
            self.too_long(span);
            return Expr {
                kind: ExprKind::Int(0),
                span,
            };
        }
        let mut it = p.into_inner();
        let mut lhs = self.expr(it.next().expect("grammar: operand"));
        while let Some(op) = it.next() {
            let rhs = self.expr(it.next().expect("grammar: operand"));
            let op = match op.as_str() {
                "||" => BinOp::Or,
                "&&" => BinOp::And,
                "==" => BinOp::Eq,
                "!=" => BinOp::Ne,
                "<" => BinOp::Lt,
                "<=" => BinOp::Le,
                ">" => BinOp::Gt,
                ">=" => BinOp::Ge,
                ">>" => BinOp::Then,
                "|" => BinOp::Union,
                "+" => BinOp::Add,
                "-" => BinOp::Sub,
                "&" => BinOp::Inter,
                "*" => BinOp::Mul,
                "/" => BinOp::Div,
                _ => BinOp::Rem,
            };
            let span = lhs.span.join(rhs.span);
            lhs = Expr {
                kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                span,
            };
        }
        lhs
    }

    fn range(&mut self, p: P) -> Expr {
        let span = self.span(&p);
        let mut it = p.into_inner();
        let start = self.expr(it.next().expect("grammar: operand"));
        let Some(op) = it.next() else { return start };
        let end = self.expr(it.next().expect("grammar: range end"));
        let step = it
            .find(|s| s.as_rule() != Rule::step_kw)
            .map(|s| Box::new(self.expr(s)));
        Expr {
            kind: ExprKind::Range {
                start: Box::new(start),
                end: Box::new(end),
                inclusive: op.as_str() == "..=",
                step,
            },
            span,
        }
    }

    fn unary(&mut self, p: P) -> Expr {
        let span = self.span(&p);
        let pairs: Vec<P> = p.into_inner().collect();
        if pairs.len() > MAX_CHAIN {
            self.too_long(span);
            return Expr {
                kind: ExprKind::Int(0),
                span,
            };
        }
        let mut iter = pairs.into_iter().rev();
        let mut e = self.expr(iter.next().expect("grammar: operand"));
        for op in iter {
            let s = self.span(&op).join(e.span);
            let op = if op.as_str() == "-" {
                UnOp::Neg
            } else {
                UnOp::Not
            };
            e = Expr {
                kind: ExprKind::Unary(op, Box::new(e)),
                span: s,
            };
        }
        e
    }

    fn postfix(&mut self, p: P) -> Expr {
        let mut it = p.into_inner();
        let mut e = self.expr(it.next().expect("grammar: primary"));
        for s in it {
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
                _ => {
                    let r = s.into_inner().next().expect("grammar: record");
                    ExprKind::With(Box::new(e), self.fields(r))
                }
            };
            e = Expr { kind, span };
        }
        e
    }

    fn eq_slip(&mut self, p: &P) {
        let s = self.span(p);
        self.diags.push(
            Diagnostic::error("rtc::syntax::eq_for_colon", s, "expected `:`, found `=`")
                .with_label("fields and named arguments use `:`")
                .with_help("write `:` instead of `=`"),
        );
    }

    fn arg(&mut self, p: P) -> Arg {
        let mut name = None;
        let mut value = None;
        for q in p.into_inner() {
            match q.as_rule() {
                Rule::ident => name = Some(self.name(&q)),
                Rule::eq_slip => self.eq_slip(&q),
                _ => value = Some(self.expr(q)),
            }
        }
        Arg {
            name,
            value: value.expect("grammar: argument value"),
        }
    }

    fn fields(&mut self, record: P) -> Vec<Field> {
        let mut out = Vec::new();
        for f in record.into_inner() {
            let mut name = None;
            let mut value = None;
            for q in f.into_inner() {
                match q.as_rule() {
                    Rule::ident => name = Some(self.name(&q)),
                    Rule::eq_slip => self.eq_slip(&q),
                    _ => value = Some(self.expr(q)),
                }
            }
            out.push(Field {
                name: name.expect("grammar: field name"),
                value: value.expect("grammar: field value"),
            });
        }
        out
    }

    fn number(&mut self, p: &P) -> f64 {
        p.as_str().parse::<f64>().unwrap_or(f64::NAN)
    }

    fn primary(&mut self, p: P) -> ExprKind {
        match p.as_rule() {
            Rule::int_lit => match p.as_str().parse::<i64>() {
                Ok(v) => ExprKind::Int(v),
                Err(_) => {
                    let s = self.span(&p);
                    self.diags.push(
                        Diagnostic::error("rtc::syntax::number", s, "integer literal is too large")
                            .with_label("does not fit in 64 bits")
                            .with_help(format!("write it as a float: `{}.0`", p.as_str())),
                    );
                    ExprKind::Int(0)
                }
            },
            Rule::float_lit => ExprKind::Float(self.number(&p)),
            Rule::angle_lit => {
                let mut it = p.into_inner();
                let n = it.next().expect("grammar: angle number");
                let v = self.number(&n);
                let unit = it.next().map_or("deg", |u| u.as_str());
                ExprKind::Angle(match unit {
                    "rad" => v,
                    "turn" => v * std::f64::consts::TAU,
                    _ => v.to_radians(),
                })
            }
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
            Rule::list => ExprKind::List(p.into_inner().map(|q| self.expr(q)).collect()),
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
                ExprKind::If(Box::new(cond), then, els)
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
                ExprKind::For(gens, filter, body.expect("grammar: for body"))
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
                    span,
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

fn unescape(s: &str) -> char {
    match s.as_bytes().get(1) {
        Some(b'n') => '\n',
        Some(b't') => '\t',
        Some(&c) => c as char,
        None => '\\',
    }
}
