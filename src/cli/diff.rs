//! A unified diff of two texts by lines (what `rtc fmt --check` shows): `---`/`+++` headers,
//! `@@ -a,n +b,m @@` hunks with three lines of context.

use std::fmt::Write as _;

/// Lines of unchanged context around each change.
const CONTEXT: usize = 3;

/// Above this many line pairs the middle of the texts is shown as one replaced block instead of
/// being matched line by line (the table would need too much memory).
const MAX_TABLE: usize = 4_000_000;

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Op {
    Same,
    Del,
    Add,
}

/// The unified diff from `old` to `new` (empty when they are equal); `name` heads it.
pub(crate) fn unified(name: &str, old: &str, new: &str) -> String {
    let a: Vec<&str> = old.lines().collect();
    let b: Vec<&str> = new.lines().collect();
    let ops = script(&a, &b);
    if ops.iter().all(|&o| o == Op::Same) {
        return String::new();
    }
    let mut out = format!("--- {name}\n+++ {name} (formatted)\n");
    // Positions in a and b at every op.
    let mut at = Vec::with_capacity(ops.len() + 1);
    let (mut i, mut j) = (0, 0);
    for &op in &ops {
        at.push((i, j));
        match op {
            Op::Same => (i, j) = (i + 1, j + 1),
            Op::Del => i += 1,
            Op::Add => j += 1,
        }
    }
    at.push((i, j));
    let changed: Vec<usize> = (0..ops.len()).filter(|&k| ops[k] != Op::Same).collect();
    let mut k = 0;
    while k < changed.len() {
        let start = changed[k].saturating_sub(CONTEXT);
        let mut end = changed[k] + 1;
        while k + 1 < changed.len() && changed[k + 1] <= end + 2 * CONTEXT {
            k += 1;
            end = changed[k] + 1;
        }
        let end = (end + CONTEXT).min(ops.len());
        let count = |op: Op| {
            ops[start..end]
                .iter()
                .filter(|&&o| o == op || o == Op::Same)
                .count()
        };
        let (sa, sb) = at[start];
        let _ = writeln!(
            out,
            "@@ -{},{} +{},{} @@",
            sa + 1,
            count(Op::Del),
            sb + 1,
            count(Op::Add)
        );
        for (&op, &(ia, ib)) in ops[start..end].iter().zip(&at[start..end]) {
            let _ = match op {
                Op::Same => writeln!(out, " {}", a[ia]),
                Op::Del => writeln!(out, "-{}", a[ia]),
                Op::Add => writeln!(out, "+{}", b[ib]),
            };
        }
        k += 1;
    }
    out
}

/// The edit script: common prefix and suffix, then a longest common subsequence of the rest.
fn script(a: &[&str], b: &[&str]) -> Vec<Op> {
    let pre = a.iter().zip(b).take_while(|(x, y)| x == y).count();
    let suf = a[pre..]
        .iter()
        .rev()
        .zip(b[pre..].iter().rev())
        .take_while(|(x, y)| x == y)
        .count();
    let (ma, mb) = (&a[pre..a.len() - suf], &b[pre..b.len() - suf]);
    let mut ops = vec![Op::Same; pre];
    if (ma.len() + 1) * (mb.len() + 1) > MAX_TABLE {
        ops.extend(std::iter::repeat_n(Op::Del, ma.len()));
        ops.extend(std::iter::repeat_n(Op::Add, mb.len()));
    } else {
        ops.extend(lcs(ma, mb));
    }
    ops.extend(std::iter::repeat_n(Op::Same, suf));
    ops
}

fn lcs(a: &[&str], b: &[&str]) -> Vec<Op> {
    let w = b.len() + 1;
    // len[i * w + j]: the longest common subsequence of a[i..] and b[j..].
    let mut len = vec![0u32; (a.len() + 1) * w];
    for i in (0..a.len()).rev() {
        for j in (0..b.len()).rev() {
            len[i * w + j] = if a[i] == b[j] {
                len[(i + 1) * w + j + 1] + 1
            } else {
                len[(i + 1) * w + j].max(len[i * w + j + 1])
            };
        }
    }
    let (mut i, mut j) = (0, 0);
    let mut ops = Vec::new();
    while i < a.len() || j < b.len() {
        if i < a.len() && j < b.len() && a[i] == b[j] {
            ops.push(Op::Same);
            (i, j) = (i + 1, j + 1);
        } else if i < a.len() && (j == b.len() || len[(i + 1) * w + j] >= len[i * w + j + 1]) {
            // Removed lines before added ones, as diff(1) shows them.
            ops.push(Op::Del);
            i += 1;
        } else {
            ops.push(Op::Add);
            j += 1;
        }
    }
    ops
}

#[cfg(test)]
mod tests {
    use super::unified;

    #[test]
    fn equal_texts_have_no_diff() {
        assert_eq!(unified("f", "a\nb\n", "a\nb\n"), "");
    }

    #[test]
    fn a_change_shows_with_its_context() {
        let old = "1\n2\n3\n4\n5\n6\n7\n8\n9\n";
        let new = "1\n2\n3\n4\nfive\n6\n7\n8\n9\n";
        assert_eq!(
            unified("f", old, new),
            "--- f\n+++ f (formatted)\n@@ -2,7 +2,7 @@\n 2\n 3\n 4\n-5\n+five\n 6\n 7\n 8\n"
        );
        // Inserted and removed lines count on their own side only.
        assert_eq!(
            unified("f", "a\nb\n", "a\nx\nb\n"),
            "--- f\n+++ f (formatted)\n@@ -1,2 +1,3 @@\n a\n+x\n b\n"
        );
    }
}
