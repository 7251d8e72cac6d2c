//! Every diagnostic code the program can emit for a `.rtc` scene is listed in the codes table of
//! docs/language.md (§25). The codes are collected from the source text (`"rtc::..."` string
//! literals under src/), so a new code without documentation fails here. The course front ends'
//! own codes (`rtc::compat::`, `rtc::in::`, `rtc::yaml::`) are documented with those formats, and
//! the image metrics' codes (`rtc::metrics::`, emitted by tools, not scenes) in docs/metrics.md.

use std::path::{Path, PathBuf};

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).expect("src directory") {
        let p = e.expect("entry").path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

fn codes_in(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(p) = rest.find("\"rtc::") {
        let after = &rest[p + 1..];
        let end = after.find('"').unwrap_or(0);
        let code = &after[..end];
        if code
            .chars()
            .all(|c| c.is_ascii_lowercase() || c == ':' || c == '_')
        {
            out.push(code.to_owned());
        }
        rest = &after[end..];
    }
    out
}

#[test]
fn every_language_code_is_in_the_reference_table() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let doc = std::fs::read_to_string(root.join("docs/language.md")).expect("docs/language.md");
    let table = &doc[doc.find("## 25. Diagnostic codes").expect("§25")..];
    let table = &table[..table.find("## 26.").expect("§26")];
    let metrics = std::fs::read_to_string(root.join("docs/metrics.md")).expect("docs/metrics.md");
    let mut files = Vec::new();
    sources(&root.join("src"), &mut files);
    let mut missing = Vec::new();
    let mut seen = 0;
    for f in files {
        let text = std::fs::read_to_string(&f).expect("source file");
        for code in codes_in(&text) {
            if ["rtc::compat::", "rtc::in::", "rtc::yaml::"]
                .iter()
                .any(|p| code.starts_with(p))
            {
                continue;
            }
            seen += 1;
            // `rtc::budget::loop`, `::recursion`, ... share one row of the table.
            let short = code.rsplit("::").next().unwrap_or("");
            let listed = table.contains(&format!("`{code}`"))
                || (code.starts_with("rtc::metrics::") && metrics.contains(&format!("`{code}`")))
                || (code.starts_with("rtc::budget::") && table.contains(&format!("`::{short}`")));
            if !listed && !missing.contains(&code) {
                missing.push(code);
            }
        }
    }
    assert!(seen > 50, "found only {seen} codes: is the scan broken?");
    assert!(missing.is_empty(), "codes missing from §25: {missing:?}");
}
