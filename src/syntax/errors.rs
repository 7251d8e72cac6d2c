//! Turns pest's failures into diagnostics in plain words: rule names never reach the user.

use pest::error::{Error, ErrorVariant, InputLocation};

use crate::diag::Diagnostic;
use crate::source::{FileId, Span};
use crate::syntax::grammar::Rule;

/// Human words for a grammar rule, or `None` for rules that only add noise.
fn rule_words(rule: Rule) -> Option<&'static str> {
    Some(match rule {
        Rule::expr
        | Rule::head_expr
        // `unary_op` is tried at the start of every operand: its presence means "an expression".
        | Rule::unary_op
        | Rule::arg => "an expression",
        Rule::ident => "a name",
        Rule::block => "`{`",
        Rule::number | Rule::vec_lit => "a number",
        Rule::string => "a string",
        Rule::type_ann => "a type",
        Rule::params => "`(`",
        Rule::field => "a field",
        Rule::generator => "a loop variable",
        Rule::header => "`rtc 1.1`",
        Rule::version => "a version number",
        Rule::std_path => "a module path",
        Rule::EOI => "end of file",
        Rule::kw_else => "`else`",
        Rule::kw_in => "`in`",
        Rule::kw_with => "`with`",
        _ => return None,
    })
}

/// Order of preference when listing expected tokens: closers and separators first.
const PRIORITY: &[&str] = &[",", ")", "]", "}", ":", "=", "{", "("];

/// Converts a pest error at byte `base` of the file into a diagnostic.
pub(crate) fn convert(file: FileId, text: &str, base: usize, err: &Error<Rule>) -> Diagnostic {
    let pos = match err.location {
        InputLocation::Pos(p) => p,
        InputLocation::Span((s, _)) => s,
    } + base;
    let pos = back_over_newlines(text, pos).max(base);
    if let Some(d) = missing_statement(file, text, pos) {
        return d;
    }
    let mut words: Vec<String> = Vec::new();
    let mut tokens: Vec<String> = Vec::new();
    if let Some(attempts) = err.parse_attempts() {
        for t in attempts.expected_tokens() {
            // `ParsingToken` is not exported by pest; its Display gives the literal text.
            let text = t.to_string();
            let t = text.trim();
            let is_range = t.len() == 4 && t.get(1..3) == Some("..");
            if !t.is_empty() && !is_range && !matches!(t, "//" | "/*" | "BUILTIN_RULE") {
                tokens.push(t.to_owned());
            }
        }
    }
    let expects_expr = matches!(&err.variant, ErrorVariant::ParsingError { positives, .. }
        if positives.iter().any(|r| rule_words(*r) == Some("an expression")));
    let mut closers: Vec<&str> = PRIORITY
        .iter()
        .copied()
        .filter(|p| tokens.iter().any(|t| t == p))
        .collect();
    let separators = closers.iter().any(|c| matches!(*c, "," | ")" | "]" | "}"));
    if separators {
        closers.retain(|c| matches!(*c, "," | ")" | "]" | "}"));
    } else if expects_expr {
        closers.clear();
    }
    if !closers.is_empty() {
        for c in closers.iter().take(3) {
            push(&mut words, format!("`{c}`"));
        }
    } else if expects_expr {
        push(&mut words, "an expression".into());
    } else {
        if let ErrorVariant::ParsingError { positives, .. } = &err.variant {
            for r in positives {
                if let Some(w) = rule_words(*r) {
                    push(&mut words, w.to_owned());
                }
            }
        }
        for t in tokens
            .iter()
            .filter(|t| t.chars().all(|c| c.is_alphabetic()))
            .take(3)
        {
            push(&mut words, format!("`{t}`"));
        }
    }
    if words.is_empty() {
        push(&mut words, "the end of the line".into());
    }
    let (found, len) = found_at(text, pos);
    if found == "`;`" {
        return Diagnostic::error(
            "rtc::syntax::semicolon",
            Span::new(file, pos, pos + 1),
            "unexpected `;`",
        )
        .with_label("statements end at the end of the line")
        .with_help("remove the `;`");
    }
    if let Some(d) = foreign_operator(file, text, pos, &found) {
        return d;
    }
    let expected = join_or(&words);
    let span = Span::new(file, pos, pos + len);
    let mut d = Diagnostic::error(
        "rtc::syntax::unexpected",
        span,
        format!("expected {expected}, found {found}"),
    )
    .with_label(format!("expected {expected} here"));
    if let Some(help) = help_for(text, pos, &found, &words) {
        d = d.with_help(help);
    }
    d
}

/// The statements rtc does not have, recognised on the line of the error so that the message
/// says so instead of "expected ...": `while` and assignment to an existing name.
fn missing_statement(file: FileId, text: &str, pos: usize) -> Option<Diagnostic> {
    let line_start = text[..pos].rfind('\n').map_or(0, |p| p + 1);
    let line_end = text[pos..].find('\n').map_or(text.len(), |p| pos + p);
    let line = &text[line_start..line_end];
    let indent = line.len() - line.trim_start().len();
    let at = line_start + indent;
    let body = line.trim();
    let word_len = body
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(body.len());
    let (word, rest) = body.split_at(word_len);
    if word == "while" {
        return Some(
            Diagnostic::error(
                "rtc::syntax::no_while",
                Span::new(file, at, at + 5),
                "rtc has no `while` loop",
            )
            .with_label("loops are `for` over a range or a list")
            .with_help("loop over a range (`for i in 0..n`), or build the sequence with `iterate(start, next, while)` (§8)"),
        );
    }
    let rest = rest.trim_start();
    let op_len = ["+=", "-=", "*=", "/=", "="]
        .iter()
        .find(|op| rest.starts_with(**op) && !rest[op.len()..].starts_with('='))
        .map(|op| op.len())?;
    if word.is_empty() || word.starts_with(|c: char| c.is_ascii_digit()) || is_keyword(word) {
        return None;
    }
    let op_at = at + word_len + (body[word_len..].len() - rest.len());
    Some(
        Diagnostic::error(
            "rtc::syntax::reassign",
            Span::new(file, op_at, op_at + op_len),
            format!("`{word}` cannot be assigned to: names are bound once"),
        )
        .with_label("there is no assignment in rtc")
        .with_help(format!(
            "bind a new name (`let {word}2 = ...`), or accumulate with `reduce(list, start, f)` or a `for` (§6)"
        )),
    )
}

/// Operators other languages have and rtc spells differently, where the parse stopped at one:
/// `^` (power, `**` in rtc) and the conditional `c ? a : b` (`if c { a } else { b }`).
fn foreign_operator(file: FileId, text: &str, pos: usize, found: &str) -> Option<Diagnostic> {
    let line_start = text[..pos].rfind('\n').map_or(0, |p| p + 1);
    let line_end = text[pos..].find('\n').map_or(text.len(), |p| pos + p);
    let before = text[line_start..pos].trim_end();
    let operand = |s: &str| {
        s.rsplit(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, '_' | '.')))
            .next()
            .filter(|w| !w.is_empty())
            .unwrap_or("x")
            .to_owned()
    };
    let after = text.get(pos + 1..line_end).unwrap_or("").trim_start();
    match found {
        "`^`" => {
            let right = after
                .split(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, '_' | '.')))
                .next()
                .filter(|w| !w.is_empty())
                .unwrap_or("2");
            Some(
                Diagnostic::error(
                    "rtc::syntax::power",
                    Span::new(file, pos, pos + 1),
                    "rtc's power operator is `**`, not `^`",
                )
                .with_label("`^` is not an operator in rtc")
                .with_help(format!("write `{} ** {right}`", operand(before))),
            )
        }
        "`?`" => {
            let (a, b) = after.split_once(':').unwrap_or(("a", "b"));
            let b = b.trim().trim_end_matches([')', ']', '}', ',']).trim();
            let (a, b) = (a.trim(), if b.is_empty() { "b" } else { b });
            Some(
                Diagnostic::error(
                    "rtc::syntax::no_conditional",
                    Span::new(file, pos, pos + 1),
                    "rtc has no `?:` conditional operator",
                )
                .with_label("`?` is not an operator in rtc")
                .with_help(format!(
                    "write `if {} {{ {a} }} else {{ {b} }}` (`if` is an expression)",
                    operand(before)
                )),
            )
        }
        _ => None,
    }
}

/// When pest stopped at the start of a later line, the problem is at the end of the line before.
fn back_over_newlines(text: &str, pos: usize) -> usize {
    let before = text.get(..pos).unwrap_or("");
    let trimmed = before.trim_end();
    if before[trimmed.len()..].contains('\n') && !trimmed.is_empty() {
        trimmed.len()
    } else {
        pos
    }
}

fn push(words: &mut Vec<String>, w: String) {
    if !words.contains(&w) {
        words.push(w);
    }
}

fn join_or(words: &[String]) -> String {
    match words {
        [] => String::new(),
        [a] => a.clone(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    }
}

/// The words that cannot be names (the grammar's `keyword` rule).
pub(crate) const KEYWORDS: &[&str] = &[
    "rtc", "let", "fn", "for", "in", "if", "else", "import", "as", "pub", "with", "true", "false",
    "step", "div",
];

/// Whether `word` cannot be a name (one of [`KEYWORDS`]).
pub(crate) fn is_keyword(word: &str) -> bool {
    KEYWORDS.contains(&word)
}

/// A description of the text at `pos` and its length in bytes.
fn found_at(text: &str, pos: usize) -> (String, usize) {
    let rest = text.get(pos..).unwrap_or("");
    let Some(c) = rest.chars().next() else {
        return ("end of file".into(), 0);
    };
    let line_rest = rest.trim_start_matches([' ', '\t', '\r']);
    if line_rest.is_empty() {
        return ("end of file".into(), 0);
    }
    if line_rest.starts_with('\n') || line_rest.starts_with("//") {
        return ("end of line".into(), 0);
    }
    if c.is_alphanumeric() || c == '_' {
        let word: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == '.')
            .collect();
        let word = word.trim_end_matches('.').to_owned();
        let len = word.len();
        if is_keyword(&word) {
            return (format!("keyword `{word}`"), len);
        }
        return (format!("`{word}`"), len);
    }
    for op in ["==", "!=", "<=", ">=", "->", ">>", "&&", "||", "..="] {
        if rest.starts_with(op) {
            return (format!("`{op}`"), op.len());
        }
    }
    (format!("`{c}`"), c.len_utf8())
}

/// One concrete fix for the common slips.
fn help_for(text: &str, pos: usize, found: &str, expected: &[String]) -> Option<String> {
    let has = |w: &str| expected.iter().any(|e| e == w);
    if found.starts_with("keyword") && has("a name") {
        return Some(format!("{} is reserved; choose another name", &found[8..]));
    }
    if has("`,`") && !found.starts_with("`=") && !found.ends_with("of file") {
        let what = if has("`)`") {
            "arguments"
        } else if has("`]`") {
            "list items"
        } else {
            "fields"
        };
        return Some(format!("separate {what} with `,`"));
    }
    if found == "`=`" && has("`:`") {
        return Some("write `:` instead of `=` for fields and named arguments".into());
    }
    if let [only] = expected
        && matches!(only.as_str(), "`)`" | "`]`" | "`}`")
    {
        return Some(format!("add the missing {only}"));
    }
    if found == "`=`"
        && text
            .get(..pos)
            .is_some_and(|t| t.trim_end().ends_with("let"))
    {
        return None;
    }
    if has("an expression") && (found == "end of line" || found == "end of file") {
        return Some("write the rest of the expression on this line".into());
    }
    None
}
