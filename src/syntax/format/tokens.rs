//! The formatter's input: the file as a flat list of tokens, each with the comments and newlines
//! written before it, and the bracket groups (argument lists, lists, records, blocks) with their
//! items. Tokens come from pest's tree, so every token knows its role (`-` negates or subtracts,
//! `<` compares or opens a type argument, `{` opens a record or a block); the literal punctuation
//! a rule matches without a pair of its own is read from the text between the pairs.

use pest::Parser;
use pest::iterators::Pair;

use crate::syntax::grammar::{RtcParser, Rule};

/// What kind of bracket group an opener starts (decides spacing and whether it may break).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Br {
    /// `f(a, b)`.
    Call,
    /// `fn f(a, b)`.
    Params,
    /// `[a, b]`.
    List,
    /// `{ a: 1, b: 2 }`.
    Record,
    /// `import m { a, b }`.
    Import,
    /// `{ statements }`.
    Block,
    /// `(a + b)`.
    Paren,
    /// `a[i]`.
    Index,
    /// `f {}`.
    Empty,
}

impl Br {
    /// Braces are padded inside (`{ a: 1 }`); parentheses and brackets are not.
    pub(super) fn padded(self) -> bool {
        matches!(self, Br::Record | Br::Import | Br::Block | Br::Empty)
    }
}

/// A token's role, which decides the spaces around it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    /// A name, literal or keyword.
    Word,
    /// A binary operator, spaced: `a + b`.
    Bin,
    /// `..` and `..=`, unspaced: `0..n`.
    Range,
    /// A prefix `-` or `!`, glued to its operand.
    Unary,
    /// An opening bracket.
    Open(Br),
    /// A closing bracket.
    Close(Br),
    /// `,`.
    Comma,
    /// `:` of a field, named argument or type annotation.
    Colon,
    /// `=` of a `let`, `param` or default value.
    Eq,
    /// `->`.
    Arrow,
    /// `.` of a member or a `std.path`.
    Dot,
    /// `?` of an optional type.
    Question,
    /// `<` of a type argument: `List<Int>`.
    TypeOpen,
    /// `>` of a type argument.
    TypeClose,
}

/// A comment or a line break between two tokens.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Trivia {
    /// A line break.
    Newline,
    /// A `//` comment (to the end of its line) or a `/* */` comment, as written.
    Comment { text: String, line: bool },
}

/// One token with the trivia written before it.
#[derive(Clone, Debug)]
pub(super) struct Tok {
    /// The text to print (as written, except the spacing inside `[x, y, z]` vectors).
    pub(crate) text: String,
    /// Its role.
    pub(crate) kind: Kind,
    /// Comments and line breaks between the previous token and this one.
    pub(crate) before: Vec<Trivia>,
}

/// A bracket group: its opener and closer token indices and its items' token ranges.
#[derive(Clone, Debug)]
pub(super) struct Group {
    /// What the brackets hold.
    pub(crate) br: Br,
    /// Index of the opening token.
    pub(crate) open: usize,
    /// Index of the closing token.
    pub(crate) close: usize,
    /// First and last token of each item (argument, element, field, statement).
    pub(crate) items: Vec<(usize, usize)>,
    /// A list of three plain numbers that is not a vector token: its trailing comma keeps it a
    /// list (without it, `[1, 2, 3]` would read as a `Vec3`).
    pub(crate) keep_trailing_comma: bool,
}

/// A chain that may be broken over lines: the binary operators of lowest precedence in one
/// expression (`a | b | c`), or the method calls of one operand (`x.f().g()`, two or more).
#[derive(Clone, Debug)]
pub(super) struct Chain {
    /// The tokens that start a line when the chain is broken (operators or `.`).
    pub(crate) breaks: Vec<usize>,
    /// First token of the expression or operand.
    pub(crate) first: usize,
    /// Last token of the expression or operand.
    pub(crate) last: usize,
}

/// The whole file as tokens and groups, plus the trivia after the last token.
#[derive(Debug, Default)]
pub(super) struct Tokens {
    /// Every token in order.
    pub(crate) toks: Vec<Tok>,
    /// Every bracket group, in order of their openers.
    pub(crate) groups: Vec<Group>,
    /// Every operator and method chain.
    pub(crate) chains: Vec<Chain>,
    /// Comments and line breaks after the last token.
    pub(crate) tail: Vec<Trivia>,
}

/// Reads the (syntax-error-free) `text` into tokens; `Err` names what could not be read, which
/// means the formatter and the parser disagree (the file is then left alone).
pub(super) fn tokenize(text: &str) -> Result<Tokens, String> {
    let mut r = Reader {
        text,
        out: Tokens::default(),
        pending: Vec::new(),
    };
    let header = RtcParser::parse(Rule::header_line, text)
        .map_err(|_| "no `rtc` header".to_owned())?
        .next()
        .ok_or("no `rtc` header")?;
    let mut pos = header.as_span().end();
    r.visit(header, 0)?;
    while pos < text.len() {
        let line = RtcParser::parse(Rule::stmt_line, &text[pos..])
            .map_err(|e| format!("cannot read the statement at byte {pos}: {e}"))?
            .next()
            .ok_or("empty statement")?;
        let end = line.as_span().end();
        r.visit(line, pos)?;
        if end == 0 {
            break;
        }
        pos += end;
    }
    r.gap(pos, text.len(), Rule::stmt_line)?;
    r.out.tail = std::mem::take(&mut r.pending);
    Ok(r.out)
}

struct Reader<'a> {
    text: &'a str,
    out: Tokens,
    /// Trivia read since the last token.
    pending: Vec<Trivia>,
}

/// Rules whose pair is one token (not descended into).
fn leaf_kind(rule: Rule) -> Option<Kind> {
    Some(match rule {
        Rule::ident
        | Rule::number
        | Rule::vec_lit
        | Rule::string
        | Rule::hex_color
        | Rule::bool_lit
        | Rule::version
        | Rule::pub_kw
        | Rule::param_kw => Kind::Word,
        Rule::or_op
        | Rule::and_op
        | Rule::then_op
        | Rule::cmp_op
        | Rule::step_kw
        | Rule::union_op
        | Rule::pow_op
        | Rule::add_op
        | Rule::add_line_op
        | Rule::inter_op
        | Rule::mul_op => Kind::Bin,
        Rule::range_op => Kind::Range,
        Rule::unary_op => Kind::Unary,
        Rule::optional_mark => Kind::Question,
        Rule::eq_slip => Kind::Eq,
        _ => return None,
    })
}

/// The group kind a rule's brackets make.
fn group_kind(rule: Rule) -> Option<Br> {
    Some(match rule {
        Rule::call_args => Br::Call,
        Rule::params => Br::Params,
        Rule::list => Br::List,
        Rule::record => Br::Record,
        Rule::import_list => Br::Import,
        Rule::block => Br::Block,
        Rule::paren => Br::Paren,
        Rule::index => Br::Index,
        Rule::empty_record_arg => Br::Empty,
        _ => return None,
    })
}

impl Reader<'_> {
    /// Adds the tokens of `pair` (whose offsets count from `base`).
    fn visit(&mut self, pair: Pair<'_, Rule>, base: usize) -> Result<(), String> {
        let rule = pair.as_rule();
        let (start, end) = (base + pair.as_span().start(), base + pair.as_span().end());
        if rule == Rule::EOI {
            return Ok(());
        }
        if let Some(kind) = leaf_kind(rule) {
            let text = if rule == Rule::vec_lit {
                vec_text(pair.as_str())
            } else {
                pair.as_str().to_owned()
            };
            self.push(text, kind);
            return Ok(());
        }
        let first = self.out.toks.len();
        let group = group_kind(rule).map(|br| {
            self.out.groups.push(Group {
                br,
                open: first,
                close: first,
                items: Vec::new(),
                keep_trailing_comma: false,
            });
            self.out.groups.len() - 1
        });
        let mut cursor = start;
        let mut items = Vec::new();
        let mut plain_numbers = 0;
        let children: Vec<Pair<'_, Rule>> = pair.into_inner().collect();
        let mut chains = ChainScan::default();
        for (k, child) in children.iter().enumerate() {
            let (cs, ce) = (base + child.as_span().start(), base + child.as_span().end());
            self.gap(cursor, cs, rule)?;
            if rule == Rule::list && is_plain_number(child) {
                plain_numbers += 1;
            }
            let before = self.out.toks.len();
            self.visit(child.clone(), base)?;
            if self.out.toks.len() > before {
                items.push((before, self.out.toks.len() - 1));
                if matches!(rule, Rule::expr | Rule::head_expr) {
                    let call_follows =
                        children.get(k + 1).map(Pair::as_rule) == Some(Rule::call_args);
                    chains.child(
                        child.as_rule(),
                        before,
                        self.out.toks.len() - 1,
                        call_follows,
                    );
                }
            }
            cursor = ce;
        }
        self.gap(cursor, end, rule)?;
        chains.finish(&mut self.out.chains);
        if let Some(g) = group {
            let last = self.out.toks.len().saturating_sub(1);
            let opens = self.out.toks.get(first).map(|t| t.kind);
            let closes = self.out.toks.get(last).map(|t| t.kind);
            if opens != Some(Kind::Open(self.out.groups[g].br))
                || closes != Some(Kind::Close(self.out.groups[g].br))
            {
                return Err(format!("brackets of {rule:?} not found"));
            }
            let group = &mut self.out.groups[g];
            group.close = last;
            group.keep_trailing_comma =
                rule == Rule::list && items.len() == 3 && plain_numbers == 3;
            group.items = items;
        }
        Ok(())
    }

    fn push(&mut self, text: String, kind: Kind) {
        self.out.toks.push(Tok {
            text,
            kind,
            before: std::mem::take(&mut self.pending),
        });
    }

    /// Reads the literal tokens and trivia of `text[from..to]`, inside a pair of rule `ctx`.
    fn gap(&mut self, from: usize, to: usize, ctx: Rule) -> Result<(), String> {
        let s = &self.text[from..to];
        let mut i = 0;
        while i < s.len() {
            let rest = &s[i..];
            let c = rest.chars().next().unwrap_or(' ');
            if c == '\n' {
                self.pending.push(Trivia::Newline);
                i += 1;
            } else if c == ' ' || c == '\t' || c == '\r' {
                i += 1;
            } else if rest.starts_with("//") {
                let len = rest.find('\n').unwrap_or(rest.len());
                self.comment(&rest[..len], true);
                i += len;
            } else if let Some(body) = rest.strip_prefix("/*") {
                let len = body.find("*/").map_or(rest.len(), |e| e + 4);
                self.comment(&rest[..len], false);
                i += len;
            } else if rest.starts_with("->") {
                self.push("->".to_owned(), Kind::Arrow);
                i += 2;
            } else if c.is_ascii_alphabetic() || c == '_' {
                let len = rest
                    .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .unwrap_or(rest.len());
                self.push(rest[..len].to_owned(), Kind::Word);
                i += len;
            } else {
                let kind = punct_kind(c, ctx)
                    .ok_or_else(|| format!("unexpected `{c}` at byte {} in {ctx:?}", from + i))?;
                self.push(c.to_string(), kind);
                i += c.len_utf8();
            }
        }
        Ok(())
    }

    fn comment(&mut self, text: &str, line: bool) {
        // Trailing spaces inside a block comment's lines carry nothing; they go like all others.
        let text = text
            .split('\n')
            .map(str::trim_end)
            .collect::<Vec<_>>()
            .join("\n");
        self.pending.push(Trivia::Comment { text, line });
    }
}

/// Collects the chains of one `expr` from its children in order.
#[derive(Default)]
struct ChainScan {
    /// `(token, precedence)` of each binary operator.
    ops: Vec<(usize, u8)>,
    /// The `.` of each method call in the current operand.
    dots: Vec<usize>,
    operand_first: Option<usize>,
    operand_last: usize,
    first: Option<usize>,
    last: usize,
    found: Vec<Chain>,
}

impl ChainScan {
    fn child(&mut self, rule: Rule, first: usize, last: usize, call_follows: bool) {
        self.first.get_or_insert(first);
        self.last = last;
        if let Some(prec) = precedence(rule) {
            self.ops.push((first, prec));
            self.end_operand();
            return;
        }
        self.operand_first.get_or_insert(first);
        self.operand_last = last;
        if rule == Rule::member && call_follows {
            self.dots.push(first);
        }
    }

    fn end_operand(&mut self) {
        let dots = std::mem::take(&mut self.dots);
        if let Some(first) = self.operand_first.take()
            && dots.len() >= 2
        {
            self.found.push(Chain {
                breaks: dots,
                first,
                last: self.operand_last,
            });
        }
    }

    fn finish(mut self, out: &mut Vec<Chain>) {
        self.end_operand();
        if let (Some(first), Some(low)) = (self.first, self.ops.iter().map(|o| o.1).min()) {
            let breaks = self
                .ops
                .iter()
                .filter(|o| o.1 == low)
                .map(|o| o.0)
                .collect();
            out.push(Chain {
                breaks,
                first,
                last: self.last,
            });
        }
        out.append(&mut self.found);
    }
}

/// Binding strength of a binary operator (src/syntax/pratt.rs; higher binds tighter).
fn precedence(rule: Rule) -> Option<u8> {
    Some(match rule {
        Rule::or_op => 0,
        Rule::and_op => 1,
        Rule::cmp_op => 2,
        Rule::step_kw => 3,
        Rule::range_op => 4,
        Rule::then_op => 5,
        Rule::union_op => 6,
        Rule::add_op | Rule::add_line_op => 7,
        Rule::inter_op => 8,
        Rule::mul_op => 9,
        Rule::pow_op => 10,
        _ => return None,
    })
}

/// The role of a punctuation character matched as a literal inside a pair of rule `ctx`.
fn punct_kind(c: char, ctx: Rule) -> Option<Kind> {
    let br = group_kind(ctx);
    Some(match c {
        '(' | '[' | '{' => Kind::Open(br?),
        ')' | ']' | '}' => Kind::Close(br?),
        ',' => Kind::Comma,
        ':' => Kind::Colon,
        '=' => Kind::Eq,
        '.' => Kind::Dot,
        '<' if ctx == Rule::type_ann => Kind::TypeOpen,
        '>' if ctx == Rule::type_ann => Kind::TypeClose,
        _ => return None,
    })
}

/// `[ 1,-2 ,3]` as `[1, -2, 3]` (a vector token's text, spaces only between its parts).
fn vec_text(s: &str) -> String {
    let inner = &s[1..s.len() - 1];
    let parts: Vec<&str> = inner.split(',').map(str::trim).collect();
    format!("[{}]", parts.join(", "))
}

/// An element that reads as a plain number (an optional `-`, digits, no unit): three of them
/// without the trailing comma would print as a vector token.
fn is_plain_number(p: &Pair<'_, Rule>) -> bool {
    if p.as_rule() != Rule::expr {
        return false;
    }
    let parts: Vec<_> = p.clone().into_inner().collect();
    let number = match parts.as_slice() {
        [n] => n,
        [u, n] if u.as_str() == "-" => n,
        _ => return false,
    };
    number.as_rule() == Rule::number
        && number
            .as_str()
            .chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '+' | '-'))
}
