//! The course front ends never panic: random text, and random edits of the real course files,
//! always come back as a scene or as diagnostics with spans inside the file.

use std::path::Path;

use proptest::prelude::*;
use rtc::compat::{load_in_source, load_yaml_source};
use rtc::ir::Loaded;
use rtc::source::SourceMap;

mod fuzz_support;
use fuzz_support::splice;

const RT1: &str = include_str!("data/course/in/rt1.in");
const SCENE01: &str = include_str!("data/course/yaml/scene01.yaml");
const TEXTURE: &str =
    include_str!("data/course/yaml/scene01-texture-ss-reflect-lights-shadows.yaml");

fn spans_in_bounds(loaded: &Loaded, text: &str) {
    for d in &loaded.diagnostics.items {
        if let Some(s) = d.span {
            assert!(s.start <= s.end && s.end as usize <= text.len(), "{d:?}");
            assert!(text.is_char_boundary(s.start as usize), "{d:?}");
        }
        // A scene comes back exactly when there is no error.
    }
    assert_eq!(loaded.scene.is_some(), !loaded.diagnostics.has_errors());
}

const PIECES: &str = r#"(?s)[ \t\r\n#:\-\[\]{}()<>,.0-9eE+a-zA-Z"'&*!|>%@`~]{0,12}"#;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn in_reader_never_panics(text in "(?s).{0,200}") {
        let loaded = load_in_source(Path::new("f.in"), &text, &mut SourceMap::new());
        spans_in_bounds(&loaded, &text);
    }

    #[test]
    fn in_reader_survives_edits_of_rt1(at in 0usize..2000, len in 0usize..20, with in PIECES) {
        let text = splice(RT1, at, len, &with);
        let loaded = load_in_source(Path::new("rt1.in"), &text, &mut SourceMap::new());
        spans_in_bounds(&loaded, &text);
    }

    #[test]
    fn yaml_reader_never_panics(text in "(?s).{0,200}") {
        let loaded = load_yaml_source(Path::new("f.yaml"), &text, &mut SourceMap::new());
        spans_in_bounds(&loaded, &text);
    }

    #[test]
    fn yaml_reader_survives_edits_of_course_files(
        which in 0usize..2, at in 0usize..2000, len in 0usize..20, with in PIECES
    ) {
        let base = if which == 0 { SCENE01 } else { TEXTURE };
        let text = splice(base, at, len, &with);
        let path = Path::new("tests/data/course/yaml/edited.yaml");
        let loaded = load_yaml_source(path, &text, &mut SourceMap::new());
        spans_in_bounds(&loaded, &text);
    }
}
