//! Layout decisions: which bracket groups are laid out one item per line, which line breaks a
//! token must have or may lose, which commas go or come; and the loop that breaks groups until
//! no line is longer than [`MAX_WIDTH`] (or nothing more can be broken).

use super::print::print;
use super::tokens::{Br, Group, Kind, Tokens, Trivia};

/// Lines longer than this (in characters) get their bracket groups broken one item per line.
const MAX_WIDTH: usize = 100;

/// What the gap before a token must be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Brk {
    /// Line breaks as written (blank lines collapsed), else the spacing rule.
    Auto,
    /// A line break.
    Force,
    /// No line break unless a `//` comment needs one (`} else`, `a,` in a broken list).
    Join,
}

/// The decisions for every token.
pub(super) struct Plan {
    /// The gap before each token.
    pub(crate) brk: Vec<Brk>,
    /// Tokens left out (a trailing comma on one line, commas between a record's fields when
    /// they stand one per line); their comments stay.
    pub(crate) skip: Vec<bool>,
    /// Tokens after which a comma is added (the last item of a broken list).
    pub(crate) comma_after: Vec<bool>,
}

/// Formats the tokens: groups written over several lines stay so (one item per line), chains
/// with a written break get all their breaks; then the outermost group or chain of every
/// too-long line is broken, until none is left to break.
pub(super) fn layout(t: &Tokens) -> String {
    let mut broken = Broken {
        groups: t.groups.iter().map(|g| written_broken(t, g)).collect(),
        chains: t
            .chains
            .iter()
            .map(|c| c.breaks.iter().any(|&b| has_newline(t, b)))
            .collect(),
    };
    let mut close_of = vec![usize::MAX; t.toks.len()];
    for (i, g) in t.groups.iter().enumerate() {
        close_of[g.close] = i;
    }
    // An `if` / `else if` / `else` chain is laid out as one: written over several lines (an
    // `else` on a line of its own), every block of it stands over lines.
    let if_chains = if_chains(t);
    let mut chain_of = vec![usize::MAX; t.groups.len()];
    for (c, blocks) in if_chains.iter().enumerate() {
        let written = blocks.iter().any(|&b| {
            let e = t.groups[b].close + 1;
            e < t.toks.len() && is_else(t, e) && has_newline(t, e)
        });
        for &b in blocks {
            chain_of[b] = c;
            broken.groups[b] |= written;
        }
    }
    loop {
        let plan = plan(t, &broken);
        let printed = print(t, &plan);
        let mut changed = false;
        for (line, text) in printed.text.split('\n').enumerate() {
            if text.chars().count() <= MAX_WIDTH {
                continue;
            }
            match pick(t, &broken, &close_of, &chain_of, &printed.tok_line, line) {
                Some(Unit::Group(g)) if chain_of[g] != usize::MAX => {
                    for &b in &if_chains[chain_of[g]] {
                        broken.groups[b] = true;
                    }
                }
                Some(Unit::Group(g)) => broken.groups[g] = true,
                Some(Unit::Chain(c)) => broken.chains[c] = true,
                None => continue,
            }
            changed = true;
        }
        if !changed {
            return printed.text;
        }
    }
}

fn is_else(t: &Tokens, i: usize) -> bool {
    t.toks[i].kind == Kind::Word && t.toks[i].text == "else"
}

/// The blocks of each `if` chain of two or more (`if c { } else if d { } else { }`), as group
/// indices in order: a block followed by `else` is linked to the first block opening after it.
fn if_chains(t: &Tokens) -> Vec<Vec<usize>> {
    let mut open_blocks: Vec<(usize, usize)> = (t.groups.iter().enumerate())
        .filter(|(_, g)| g.br == Br::Block)
        .map(|(i, g)| (g.open, i))
        .collect();
    open_blocks.sort_unstable();
    let mut next = vec![usize::MAX; t.groups.len()];
    let mut has_prev = vec![false; t.groups.len()];
    for (i, g) in t.groups.iter().enumerate() {
        let e = g.close + 1;
        if g.br != Br::Block || e >= t.toks.len() || !is_else(t, e) {
            continue;
        }
        let k = open_blocks.partition_point(|&(o, _)| o <= e);
        if let Some(&(_, b)) = open_blocks.get(k) {
            next[i] = b;
            has_prev[b] = true;
        }
    }
    let mut chains = Vec::new();
    for start in 0..t.groups.len() {
        if has_prev[start] || next[start] == usize::MAX {
            continue;
        }
        let mut chain = vec![start];
        let mut at = start;
        while next[at] != usize::MAX && chain.len() <= t.groups.len() {
            at = next[at];
            chain.push(at);
        }
        chains.push(chain);
    }
    chains
}

/// Which groups are one item per line and which chains are broken.
pub(super) struct Broken {
    groups: Vec<bool>,
    chains: Vec<bool>,
}

/// Something that can be broken over lines.
#[derive(Clone, Copy)]
enum Unit {
    Group(usize),
    Chain(usize),
}

/// Groups that can be laid out one item per line.
fn breakable(g: &Group) -> bool {
    !matches!(g.br, Br::Paren | Br::Index | Br::Empty)
}

fn has_newline(t: &Tokens, i: usize) -> bool {
    t.toks[i].before.contains(&Trivia::Newline)
}

/// A group with a line break between its items (not only inside them): after the opener,
/// around a separator, or before the closer.
fn written_broken(t: &Tokens, g: &Group) -> bool {
    let inner = |i: usize| g.items.iter().any(|&(a, b)| i > a && i <= b);
    (g.open + 1..=g.close)
        .filter(|&i| !inner(i))
        .any(|i| has_newline(t, i))
}

/// What to break on the too-long output line `line`: the largest outermost group or chain that
/// starts or ends there; when that is a bracket list holding a single item ending in a group,
/// that group (so `f(g {` ... `})` rather than a lone argument on its own line).
fn pick(
    t: &Tokens,
    broken: &Broken,
    close_of: &[usize],
    chain_of: &[usize],
    tok_line: &[usize],
    line: usize,
) -> Option<Unit> {
    let on_line = |a: usize, b: usize| tok_line[a] == line || tok_line[b] == line;
    let mut found: Vec<(usize, usize, Unit)> = Vec::new();
    for (i, g) in t.groups.iter().enumerate() {
        if breakable(g) && !broken.groups[i] && !g.items.is_empty() && on_line(g.open, g.close) {
            found.push((g.open, g.close, Unit::Group(i)));
        }
    }
    for (i, c) in t.chains.iter().enumerate() {
        if !broken.chains[i] && on_line(c.first, c.last) {
            found.push((c.first, c.last, Unit::Chain(i)));
        }
    }
    let outer = |&&(a, b, _): &&(usize, usize, Unit)| {
        !found
            .iter()
            .any(|&(oa, ob, _)| oa <= a && ob >= b && (oa, ob) != (a, b))
    };
    // The blocks of an `if` chain first (breaking `a == b` in its conditions reads badly);
    // then largest first; a chain and a group over the same tokens: the group.
    let in_if = |u: Unit| matches!(u, Unit::Group(g) if chain_of[g] != usize::MAX);
    let (_, _, unit) = *found
        .iter()
        .filter(outer)
        .max_by_key(|&&(a, b, u)| (in_if(u), b - a, matches!(u, Unit::Group(_)), usize::MAX - a))?;
    let Unit::Group(mut best) = unit else {
        return Some(unit);
    };
    loop {
        let g = &t.groups[best];
        // A record or block breaks itself: its fields and statements are what should stand
        // one per line.
        if matches!(g.br, Br::Record | Br::Block) {
            break;
        }
        let [(_, last)] = g.items[..] else { break };
        let inner = close_of[last];
        if inner == usize::MAX || broken.groups[inner] || !breakable(&t.groups[inner]) {
            break;
        }
        if t.groups[inner].items.is_empty() {
            break;
        }
        best = inner;
    }
    Some(Unit::Group(best))
}

/// The decisions for the given broken groups and chains.
fn plan(t: &Tokens, broken: &Broken) -> Plan {
    let n = t.toks.len();
    let mut p = Plan {
        brk: vec![Brk::Auto; n],
        skip: vec![false; n],
        comma_after: vec![false; n],
    };
    for (i, tok) in t.toks.iter().enumerate() {
        // `}` and `else` on one line, like every other `else`.
        if tok.kind == Kind::Word && tok.text == "else" {
            p.brk[i] = Brk::Join;
        }
    }
    for (g, grp) in t.groups.iter().enumerate() {
        if !breakable(grp) {
            continue;
        }
        if broken.groups[g] {
            one_per_line(t, grp, &mut p);
        } else {
            one_line(t, grp, &mut p);
        }
    }
    for (c, chain) in t.chains.iter().enumerate() {
        if broken.chains[c] {
            for &b in &chain.breaks {
                p.brk[b] = Brk::Force;
            }
        }
    }
    p
}

/// The separator tokens after item `k` (up to the next item or the closer).
fn after_item(g: &Group, k: usize) -> std::ops::Range<usize> {
    let next = g.items.get(k + 1).map_or(g.close, |n| n.0);
    g.items[k].1 + 1..next
}

fn one_per_line(t: &Tokens, g: &Group, p: &mut Plan) {
    p.brk[g.close] = Brk::Force;
    let commas = g.br != Br::Block;
    for (k, &(first, last)) in g.items.iter().enumerate() {
        p.brk[first] = Brk::Force;
        if !commas {
            continue;
        }
        let mut has_comma = false;
        for j in after_item(g, k) {
            if t.toks[j].kind == Kind::Comma {
                has_comma = true;
                // A record's fields one per line need no commas; other lists keep theirs.
                if g.br == Br::Record {
                    p.skip[j] = true;
                } else {
                    p.brk[j] = Brk::Join;
                }
            }
        }
        // Not after three numbers: the comma would make a `Vec3` a `List` (docs/fmt.md).
        if !has_comma && g.br != Br::Record && k + 1 == g.items.len() && !g.keep_trailing_comma {
            p.comma_after[last] = true;
        }
    }
}

fn one_line(t: &Tokens, g: &Group, p: &mut Plan) {
    let Some(k) = g.items.len().checked_sub(1) else {
        return;
    };
    let trailing = after_item(g, k).find(|&j| t.toks[j].kind == Kind::Comma);
    // Three numbers keep the comma they have, and get none: with it they are a `List`,
    // without it a `Vec3`.
    if let Some(j) = trailing
        && !g.keep_trailing_comma
    {
        p.skip[j] = true;
    }
}
