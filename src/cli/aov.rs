//! `rtc render --aov depth,normal,albedo,object`: which layers, the check that the output can
//! hold them (EXR), and the JSON sidecar that maps the object-id layer to source spans.

use std::path::{Path, PathBuf};

use rtc::diag::did_you_mean;
use rtc::ir::Scene;
use rtc::render::Channel;
use rtc::render::output::ImageFormat;
use rtc::source::{SourceMap, Span};

/// Parses one `--aov` name (clap splits the list at commas).
pub(crate) fn parse(text: &str) -> Result<Channel, String> {
    let name = text.trim();
    let names = Channel::AOVS.map(Channel::name);
    if let Some(c) = Channel::AOVS.into_iter().find(|c| c.name() == name) {
        return Ok(c);
    }
    let hint = match did_you_mean(name, names) {
        Some(s) => format!("did you mean `{s}`? "),
        None => String::new(),
    };
    Err(format!(
        "`{name}` is not an AOV layer: {hint}the layers are {}",
        names.join(", ")
    ))
}

/// The layers in the order asked, each once.
pub(crate) fn dedup(aovs: &[Channel]) -> Vec<Channel> {
    let mut out = Vec::new();
    for c in aovs {
        if !out.contains(c) {
            out.push(*c);
        }
    }
    out
}

/// What is wrong with writing AOV layers to `path` (only EXR holds them).
pub(crate) fn check_output(path: &Path) -> Result<(), String> {
    if ImageFormat::of(path) == Some(ImageFormat::Exr) {
        return Ok(());
    }
    Err(format!(
        "`--aov` layers need an OpenEXR output, but the image is `{}`: write `-o {}`",
        path.display(),
        path.with_extension("exr").display()
    ))
}

/// The sidecar of an image with an object-id layer: `out.exr` → `out.objects.json`.
pub(crate) fn sidecar_path(image: &Path) -> PathBuf {
    image.with_extension("objects.json")
}

/// Writes a sidecar document (atomically) and says so.
pub(crate) fn write_sidecar(
    json: &serde_json::Value,
    path: &Path,
) -> Result<(), rtc::diag::Diagnostic> {
    let text = serde_json::to_string_pretty(json).unwrap_or_default() + "\n";
    rtc::render::output::write_atomically(path, text.as_bytes())?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

/// The sidecar's JSON: for each object id of the `object.id` layer, the object's kind and where
/// the scene defined it (schema `rtc-objects/1`, docs/aov.md).
pub(crate) fn sidecar(scene: &Scene, sources: &SourceMap, image: &Path) -> serde_json::Value {
    let objects: Vec<serde_json::Value> = scene
        .objects
        .iter()
        .enumerate()
        .map(|(i, o)| {
            let mut entry = serde_json::json!({
                "id": i + 1,
                "kind": o.shape.kind_name(),
            });
            if let Some(at) = place(o.span, sources) {
                entry["source"] = at;
            }
            entry
        })
        .collect();
    serde_json::json!({
        "schema": "rtc-objects/1",
        "image": image.file_name().map(|n| n.to_string_lossy().into_owned()),
        "layer": "object.id",
        "background": 0,
        "objects": objects,
    })
}

/// A span as file, 1-based line and column, byte range and the first line of its text.
fn place(span: Span, sources: &SourceMap) -> Option<serde_json::Value> {
    let file = sources.files().get(span.file.0 as usize)?;
    let (line, column) = file.line_col(span.start as usize);
    let text = sources
        .snippet(span)
        .lines()
        .next()
        .unwrap_or("")
        .trim_end();
    Some(serde_json::json!({
        "file": file.path.display().to_string(),
        "line": line,
        "column": column,
        "start": span.start,
        "end": span.end,
        "text": text,
    }))
}
