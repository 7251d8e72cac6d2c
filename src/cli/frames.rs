//! Animation on the command line: `--frame N`, `--frames A..B[:STEP]` and the output names
//! that number the frames (`{frame}` or a run of `#`, zero-padded to its length).

use std::path::{Path, PathBuf};

/// The frames `--frames` asks for: `A..B` (B excluded) or `A..=B`, optionally `:STEP` (> 0).
pub(crate) fn parse_range(text: &str) -> Result<Vec<i64>, String> {
    let bad = || {
        format!(
            "`--frames {text}` is not a frame range: write `A..B` (B excluded), `A..=B`, or add a step, e.g. `0..=48:2`"
        )
    };
    let (range, step) = match text.split_once(':') {
        Some((r, s)) => (r, s.trim().parse::<i64>().map_err(|_| bad())?),
        None => (text, 1),
    };
    if step <= 0 {
        return Err(format!(
            "`--frames {text}`: the step must be at least 1, not {step}"
        ));
    }
    let (a, b, inclusive) = if let Some((a, b)) = range.split_once("..=") {
        (a, b, true)
    } else if let Some((a, b)) = range.split_once("..") {
        (a, b, false)
    } else {
        return Err(bad());
    };
    let a: i64 = a.trim().parse().map_err(|_| bad())?;
    let b: i64 = b.trim().parse().map_err(|_| bad())?;
    let end = if inclusive { b } else { b - 1 };
    let frames: Vec<i64> = (a..=end).step_by(step as usize).collect();
    if frames.is_empty() {
        return Err(format!(
            "`--frames {text}` holds no frame: the end must come after the start"
        ));
    }
    if frames.len() > MAX_FRAMES {
        return Err(format!(
            "`--frames {text}` asks for {} frames; at most {MAX_FRAMES} per run",
            frames.len()
        ));
    }
    Ok(frames)
}

/// Frames one `rtc render` may render (a typo such as `0..100000` should not start a day's work).
const MAX_FRAMES: usize = 10_000;

/// True when `path` has a place for the frame number.
pub(crate) fn has_pattern(path: &Path) -> bool {
    let s = path.to_string_lossy();
    s.contains("{frame}") || s.contains('#')
}

/// `path` with `{frame}` replaced by the frame number and the first run of `#` by the number
/// zero-padded to the run's length (`shot_####.png`, frame 7 → `shot_0007.png`).
pub(crate) fn numbered(path: &Path, frame: i64) -> PathBuf {
    let s = path
        .to_string_lossy()
        .replace("{frame}", &frame.to_string());
    let Some(start) = s.find('#') else {
        return PathBuf::from(s);
    };
    let len = s[start..].chars().take_while(|c| *c == '#').count();
    let digits = if frame < 0 {
        format!("-{:0w$}", -frame, w = len.saturating_sub(1))
    } else {
        format!("{frame:0len$}")
    };
    PathBuf::from(format!("{}{}{}", &s[..start], digits, &s[start + len..]))
}

/// The output name when `--frames` has none with a pattern: the input's name with `_####.png`.
pub(crate) fn default_pattern(file: &Path) -> PathBuf {
    let stem = file
        .file_stem()
        .map_or_else(|| "frame".into(), |s| s.to_string_lossy().into_owned());
    file.with_file_name(format!("{stem}_####.png"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_follow_the_language() {
        assert_eq!(parse_range("0..3"), Ok(vec![0, 1, 2]));
        assert_eq!(parse_range("0..=3"), Ok(vec![0, 1, 2, 3]));
        assert_eq!(parse_range("2..=10:4"), Ok(vec![2, 6, 10]));
        assert!(parse_range("3..3").is_err());
        assert!(parse_range("0..4:0").is_err());
        assert!(parse_range("a..b").is_err());
        assert!(parse_range("0..1000000").is_err());
    }

    #[test]
    fn names_are_numbered() {
        assert_eq!(
            numbered(Path::new("s_####.png"), 7),
            PathBuf::from("s_0007.png")
        );
        assert_eq!(
            numbered(Path::new("s_{frame}.png"), 12),
            PathBuf::from("s_12.png")
        );
        assert_eq!(
            numbered(Path::new("s_##.png"), 123),
            PathBuf::from("s_123.png")
        );
        assert_eq!(
            numbered(Path::new("plain.png"), 3),
            PathBuf::from("plain.png")
        );
        assert_eq!(
            default_pattern(Path::new("d/ball.rtc")),
            PathBuf::from("d/ball_####.png")
        );
    }
}
