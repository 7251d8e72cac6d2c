//! The command line of sharded renders: which shard this process is, where its part goes, the
//! fingerprint of the options that change pixels, and `rtc merge`.

use std::path::{Path, PathBuf};

use rtc::diag::{Diagnostic, IO_ERROR};
use rtc::opt::fingerprint;
use rtc::render::part::Part;
use rtc::render::shard::Shard;
use rtc::source::SourceMap;

use super::report::{self, Format};
use crate::cli::Outcome;

/// Options that never change a pixel: they may differ between the shards of one render. Every
/// other option is part of the settings fingerprint, so an option added later is safe by
/// default (parts rendered with different values are refused, never mixed).
const NEUTRAL_WITH_VALUE: &[&str] = &[
    "--shard",
    "--shards",
    "-o",
    "--output",
    "--threads",
    "--format",
];
const NEUTRAL_FLAGS: &[&str] = &["--stats"];

/// The shard of `--shard` (`K/N` or `auto` with `--shards`), if any.
pub(crate) fn resolve(
    spec: Option<&str>,
    shards: Option<u32>,
) -> Result<Option<Shard>, Diagnostic> {
    match spec {
        None => Ok(None),
        Some("auto") => Shard::from_env(shards, |k| std::env::var(k).ok()).map(Some),
        Some(text) => Shard::parse(text).map(Some),
    }
}

/// Prints a usage diagnostic (no source spans) and gives the usage exit code.
pub(crate) fn usage_error(d: &Diagnostic) -> Outcome {
    let text = report::render(
        std::slice::from_ref(d),
        &SourceMap::new(),
        "rtc",
        Format::Human,
        false,
    );
    eprintln!("{}", text.trim_end());
    Outcome::IoOrUsage
}

/// Where shard `s` goes: `-o` as given, else the image's name with `.part-K-of-N.rtcpart`.
pub(crate) fn part_path(output: Option<PathBuf>, image: &Path, s: Shard) -> PathBuf {
    output
        .unwrap_or_else(|| image.with_extension(format!("part-{}-of-{}.rtcpart", s.index, s.count)))
}

/// Options whose whole effect is on the evaluated scene, which the scene fingerprint holds
/// (`opt::fingerprint::scene` hashes the IR): `--set a=1` and `--set a=1.0` give the same scene
/// when `a` is a `Float`, and a frame or rate the scene does not read changes nothing.
const IN_THE_SCENE: &[&str] = &["--set", "--frame", "--fps"];

/// The fingerprint of this process's pixel-changing options ([`settings_of`] of its
/// arguments after `render`).
fn settings_fingerprint(scene_file: &Path) -> String {
    let args: Vec<String> = std::env::args().skip(2).collect();
    settings_of(&args, scene_file)
}

/// The fingerprint of the pixel-changing options among `args` (the arguments after `render`):
/// each option with the values that follow it is one item, items are sorted, so their order
/// on the command line does not matter; the scene path (its content is in the scene
/// fingerprint), the neutral options and those whose effect is in the scene are left out.
fn settings_of(args: &[String], scene_file: &Path) -> String {
    let mut items: Vec<String> = Vec::new();
    let mut skipping = false;
    let mut seen_file = false;
    for a in args {
        if !seen_file && Path::new(a) == scene_file {
            seen_file = true;
            continue;
        }
        if a.starts_with('-') && a.len() > 1 {
            let name = a.split('=').next().unwrap_or(a);
            let neutral = NEUTRAL_WITH_VALUE.contains(&name)
                || NEUTRAL_FLAGS.contains(&name)
                || IN_THE_SCENE.contains(&name);
            // An option's values follow it unless it is written `--name=value`.
            skipping = neutral && !a.contains('=');
            if !neutral {
                items.push(a.clone());
            }
        } else if skipping {
            // A value of a left-out option.
        } else if let Some(last) = items.last_mut() {
            last.push(' ');
            last.push_str(a);
        } else {
            items.push(a.clone());
        }
    }
    items.sort();
    fingerprint::bytes(items.join("\n").as_bytes())
}

/// Writes shard `s` of a rendered film to `path` atomically; `scene` is the scene's
/// fingerprint (`opt::fingerprint::scene`).
pub(crate) fn write_part(
    film: &rtc::render::film::Film,
    scene_file: &Path,
    scene: String,
    s: Shard,
    path: &Path,
    sidecar: Option<serde_json::Value>,
) -> Result<(), Diagnostic> {
    let mut part = Part::of_film(film, s, scene, settings_fingerprint(scene_file));
    part.sidecar = sidecar;
    rtc::render::output::write_atomically(path, &part.to_bytes())
}

/// `rtc merge PARTS -o OUTPUT`.
pub(crate) fn merge(paths: &[PathBuf], output: &Path) -> Outcome {
    let fail = |d: Diagnostic| {
        let io = d.code == IO_ERROR;
        usage_error(&d);
        if io {
            Outcome::IoOrUsage
        } else {
            Outcome::SceneErrors
        }
    };
    if let Err(d) = rtc::render::output::encode(&rtc::render::Image::new(1, 1), output) {
        return fail(d);
    }
    let mut parts = Vec::new();
    for p in paths {
        // Only a regular file (a FIFO would block); its header is checked against its length.
        let bytes = match rtc::source::read_regular(p, u64::MAX) {
            Ok(b) => b,
            Err(e) => {
                return fail(
                    Diagnostic::new(
                        rtc::diag::Severity::Error,
                        IO_ERROR,
                        None,
                        format!("cannot read `{}`: {e}", p.display()),
                    )
                    .with_help("check the path of each part"),
                );
            }
        };
        match Part::from_bytes(&bytes, p) {
            Ok(part) => parts.push((p.clone(), part)),
            Err(d) => return fail(d),
        }
    }
    let film = match rtc::render::merge::merge(&parts) {
        Ok(f) => f,
        Err(d) => return fail(d),
    };
    if let Err(d) = rtc::render::output::save_film(&film, output) {
        return fail(d);
    }
    eprintln!("merged {} parts into {}", parts.len(), output.display());
    if let Some(json) = parts.first().and_then(|(_, p)| p.sidecar.as_ref()) {
        let mut json = json.clone();
        json["image"] = output
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .into();
        let path = crate::cli::aov::sidecar_path(output);
        if let Err(d) = crate::cli::aov::write_sidecar(&json, &path) {
            return fail(d);
        }
    }
    Outcome::Ok
}

#[cfg(test)]
mod tests {
    use super::*;

    fn of(args: &[&str]) -> String {
        let args: Vec<String> = args.iter().map(|a| a.to_string()).collect();
        settings_of(&args, Path::new("s.rtc"))
    }

    #[test]
    fn the_settings_do_not_depend_on_the_order_of_the_arguments() {
        assert_eq!(
            of(&["--frame", "0", "s.rtc"]),
            of(&["s.rtc", "--frame", "0"])
        );
        assert_eq!(
            of(&["--aov", "depth", "s.rtc", "--shard", "1/2"]),
            of(&["s.rtc", "--shard=0/2", "--aov", "depth"])
        );
        // What is in the evaluated scene is left to the scene fingerprint.
        assert_eq!(
            of(&["s.rtc", "--set", "a=1"]),
            of(&["--set", "a=1.0", "s.rtc"])
        );
        // A pixel-changing option with its value is one item: values do not swap between
        // options, and a changed value counts.
        assert_ne!(
            of(&["s.rtc", "--aov", "depth"]),
            of(&["s.rtc", "--aov", "normal"])
        );
        assert_ne!(
            of(&["s.rtc", "--target-error", "0.1", "--aov", "depth"]),
            of(&["s.rtc", "--target-error", "depth", "--aov", "0.1"])
        );
    }
}
