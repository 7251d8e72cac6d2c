//! Evaluating a scene frees everything it built: a process that evaluates many scenes (the test
//! suites, the fuzzers in fuzz/, a watcher) stays the same size. Found by the rtc_eval fuzzer,
//! whose memory grew by ~2 KB per input: module scopes and their functions kept each other alive
//! (an `Rc` cycle), and every evaluation thread leaked its interned names anew.

use std::path::Path;

use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

/// This process's resident memory in KiB (Linux).
fn resident_kib() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

fn evaluate(src: &str) {
    let mut sources = SourceMap::new();
    let loaded = load_source(
        Path::new("tests/lang/memory.rtc"),
        src,
        &mut sources,
        &EvalOptions::default(),
    );
    assert!(loaded.scene.is_some(), "{:?}", loaded.diagnostics.items);
}

#[test]
fn repeated_evaluation_keeps_memory_flat() {
    // A function (so the module scope is in a cycle with it), an import, and a list of 200,000
    // numbers (several MB) bound in the module scope: before the fix, every evaluation kept it.
    let src = "rtc 1\nimport std.prelude as p\nfn twice(x) { 2 * x }\n\
               let big = for i in 0..100000 { twice(i) }\n\
               camera { eye: [0, 0, 5] }\nsphere(radius: p.clamp(len(big), 1, 2))\n";
    evaluate(src);
    let Some(before) = resident_kib() else {
        return; // not Linux: nothing to measure
    };
    for _ in 0..25 {
        evaluate(src);
    }
    let after = resident_kib().unwrap_or(before);
    // Leaking would add 25 × ~4 MB; allow the allocator 32 MB of slack.
    assert!(
        after < before + 32 * 1024,
        "resident memory grew from {before} KiB to {after} KiB over 25 evaluations"
    );
}
