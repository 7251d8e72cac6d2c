//! The loader: picks the front end for a scene file by its extension (the scene language in
//! [`crate::eval`], the course formats in [`crate::compat`]); each returns an [`ir::Loaded`].

use std::path::Path;

use crate::diag::IO_ERROR;
use crate::eval::EvalOptions;
use crate::ir::{self, Loaded};
use crate::source::SourceMap;

/// The scene formats rtc reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneFormat {
    /// The rtc scene language.
    Rtc,
    /// The course's legacy line-based format.
    LegacyIn,
    /// The course's YAML scenes.
    CourseYaml,
}

impl SceneFormat {
    /// The format implied by a file's extension.
    pub fn of(path: &Path) -> Option<SceneFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "rtc" => Some(SceneFormat::Rtc),
            "in" => Some(SceneFormat::LegacyIn),
            "yaml" | "yml" => Some(SceneFormat::CourseYaml),
            _ => None,
        }
    }
}

/// Reads and evaluates any supported scene file into the IR.
pub fn load(path: &Path, sources: &mut SourceMap, options: &EvalOptions) -> ir::Loaded {
    match SceneFormat::of(path) {
        Some(SceneFormat::Rtc) => crate::eval::load_file(path, sources, options),
        Some(SceneFormat::LegacyIn) => {
            let mut loaded = crate::compat::load_in(path, sources);
            if let Some(scene) = &mut loaded.scene {
                scene.memory = ir::limits::Memory::new(options.max_memory);
            }
            loaded
        }
        Some(SceneFormat::CourseYaml) => {
            crate::compat::load_yaml_within(path, sources, options.max_memory)
        }
        None => Loaded::failure(
            IO_ERROR,
            format!("`{}` is not a scene file rtc knows", path.display()),
            "scene files end in `.rtc`, `.in` (legacy course format) or `.yaml` (course YAML)",
        ),
    }
}
