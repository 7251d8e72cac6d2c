//! What the command line tells a scene before it is evaluated: `--frame`, `--fps`, `--set`,
//! `--memory-budget`.

use rtc::eval::EvalOptions;

/// What the command line tells the scene before it is evaluated.
#[derive(clap::Args, Debug, Clone)]
pub(crate) struct SceneInputs {
    /// The frame to evaluate: the scene's built-in `frame` (and `time` = frame / fps).
    #[arg(long, default_value_t = 0, allow_hyphen_values = true)]
    pub(crate) frame: i64,
    /// Frames per second, for the built-in `time`.
    #[arg(long, default_value_t = rtc::eval::DEFAULT_FPS)]
    fps: f64,
    /// Overrides a `param` the scene file declares (repeatable): `--set size=3`, `-D size=3`.
    #[arg(long = "set", short = 'D', value_name = "NAME=VALUE")]
    set: Vec<String>,
    /// Most memory one load of the scene may take for its values, objects, textures and meshes
    /// (`512MiB`, `8GiB`; default 4GiB).
    #[arg(long, value_name = "SIZE", value_parser = rtc::ir::limits::parse_bytes)]
    memory_budget: Option<u64>,
}

impl SceneInputs {
    /// The evaluation options for `frame`, or what is wrong with the command line.
    pub(crate) fn options(&self, frame: i64) -> Result<EvalOptions, String> {
        if !(self.fps.is_finite() && self.fps > 0.0) {
            return Err(format!(
                "`--fps {}`: frames per second must be a positive number",
                self.fps
            ));
        }
        let mut overrides = Vec::new();
        for s in &self.set {
            let Some((name, value)) = s.split_once('=') else {
                return Err(format!(
                    "`--set {s}` needs a value: write `--set NAME=VALUE`, e.g. `--set size=3`"
                ));
            };
            let name = name.trim();
            let ident = name
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
            if !ident {
                return Err(format!(
                    "`--set {s}`: `{name}` is not a parameter name (letters, digits and `_`)"
                ));
            }
            overrides.push((name.to_string(), value.to_string()));
        }
        Ok(EvalOptions {
            frame,
            fps: self.fps,
            overrides,
            max_memory: self
                .memory_budget
                .unwrap_or(rtc::ir::limits::DEFAULT_MEMORY_BUDGET),
            ..EvalOptions::default()
        })
    }
}
