//! `rtc merge`: parts of one render back into one film. The parts must come from the same scene
//! (fingerprint), the same pixel-changing settings and the same cut into N shards, and together
//! cover every shard exactly once; anything else is refused with a diagnostic that names the
//! parts. The image-wide stage, the colour encoding, runs once on the merged film.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::film::{Film, Stats};
use super::part::Part;
use crate::diag::{Diagnostic, Severity};
use crate::ir::Color;

fn refuse(code: &'static str, message: String, help: &str) -> Diagnostic {
    Diagnostic::new(Severity::Error, code, None, message).with_help(help)
}

/// The film of a whole render from its parts (each with the file it was read from).
pub fn merge(parts: &[(PathBuf, Part)]) -> Result<Film, Diagnostic> {
    let Some((first_path, first)) = parts.first() else {
        return Err(refuse(
            "rtc::merge::missing",
            "no parts to merge".into(),
            "name every part: `rtc merge out.part-*.rtcpart -o out.png`",
        ));
    };
    let name = |p: &Path| format!("`{}`", p.display());
    for (path, p) in &parts[1..] {
        let differs = |what: &str, help: &str| {
            refuse(
                "rtc::merge::mismatch",
                format!(
                    "{} and {} come from different {what}",
                    name(first_path),
                    name(path)
                ),
                help,
            )
        };
        if p.scene != first.scene {
            return Err(differs(
                "scenes (the scene or a file it reads changed between them)",
                "re-render every shard from the same scene and files",
            ));
        }
        if p.settings != first.settings {
            return Err(differs(
                "settings (command-line options that change pixels)",
                "render every shard with the same options apart from --shard, -o and --threads",
            ));
        }
        if p.shard.count != first.shard.count {
            return Err(differs(
                &format!(
                    "cuts ({} shards against {})",
                    first.shard.count, p.shard.count
                ),
                "merge the parts of one `--shard K/N` run, all with the same N",
            ));
        }
        if (p.width, p.height, &p.channels, p.encoding)
            != (first.width, first.height, &first.channels, first.encoding)
        {
            return Err(differs(
                "image sizes or channels",
                "render every shard from the same scene and options",
            ));
        }
    }
    let mut by_index: BTreeMap<u32, &PathBuf> = BTreeMap::new();
    for (path, p) in parts {
        if let Some(other) = by_index.insert(p.shard.index, path) {
            return Err(refuse(
                "rtc::merge::overlap",
                format!(
                    "shard {}/{} is given twice: {} and {}",
                    p.shard.index,
                    p.shard.count,
                    name(other),
                    name(path)
                ),
                "give each shard once",
            ));
        }
    }
    let n = first.shard.count;
    let missing: Vec<String> = (0..n)
        .filter(|k| !by_index.contains_key(k))
        .map(|k| k.to_string())
        .collect();
    if !missing.is_empty() {
        let shown = missing
            .iter()
            .take(8)
            .cloned()
            .collect::<Vec<_>>()
            .join(", ");
        let more = if missing.len() > 8 { ", ..." } else { "" };
        return Err(refuse(
            "rtc::merge::missing",
            format!("{} of {n} shards missing: {shown}{more}", missing.len()),
            &format!(
                "render the missing shards (`rtc render SCENE --shard {}/{n} -o PART`) and merge all {n} parts",
                missing[0]
            ),
        ));
    }
    let channels = first.channels.len();
    let row = first.width as usize * channels;
    let mut values = vec![Color::ZERO; row * first.height as usize];
    let mut stats = Stats::default();
    for (_, p) in parts {
        let mut from = p.values.chunks_exact(row);
        for r in &p.rows {
            for y in r.clone() {
                let line = from.next().unwrap_or(&[]);
                values[y as usize * row..(y as usize + 1) * row].copy_from_slice(line);
            }
        }
        stats.add(&p.stats);
    }
    Ok(Film::new(
        first.width,
        first.height,
        &first.channels,
        values,
        stats,
        first.encoding,
    ))
}
