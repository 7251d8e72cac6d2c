//! Shards: a fixed, documented cut of an image into parts that separate processes (Slurm array
//! tasks, Kubernetes Indexed Jobs, `xargs -P`) render and `rtc merge` puts back together.
//!
//! The image is cut into bands of [`BAND_ROWS`] rows, numbered from the top from 0; shard `K` of
//! `N` renders the bands `b` with `b mod N = K` (interleaved, so every shard gets some sky and
//! some ground). A pixel's value depends only on the scene, the pixel, the seed and, under
//! adaptive supersampling, its neighbours' first-pass values, so a shard computes the first pass
//! on a one-row halo around its bands and the bytes of the merged image equal a single render's.

use std::ops::Range;

use crate::diag::{Diagnostic, Severity};

/// Rows per band: the unit shards are made of.
const BAND_ROWS: u32 = 16;

/// Most shards one image may be cut into.
const MAX_SHARDS: u32 = 100_000;

/// Shard `index` of `count` (indices count from 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Shard {
    /// This shard's index, `0..count`.
    pub index: u32,
    /// How many shards the image is cut into.
    pub count: u32,
}

impl Shard {
    /// Shard `index` of `count`, or a diagnostic when the pair is impossible.
    pub fn new(index: u32, count: u32) -> Result<Shard, Diagnostic> {
        if count == 0 || count > MAX_SHARDS || index >= count {
            return Err(Diagnostic::new(
                Severity::Error,
                "rtc::shard::index",
                None,
                format!("there is no shard {index} of {count}"),
            )
            .with_help(format!(
                "shards count from 0: use K/N with 0 ≤ K < N and 1 ≤ N ≤ {MAX_SHARDS}, e.g. `--shard 0/4`"
            )));
        }
        Ok(Shard { index, count })
    }

    /// Parses `K/N`.
    pub fn parse(text: &str) -> Result<Shard, Diagnostic> {
        let bad = || {
            Diagnostic::new(
                Severity::Error,
                "rtc::shard::syntax",
                None,
                format!("`{text}` is not a shard"),
            )
            .with_help("write the shard as K/N (shard K of N, from 0), e.g. `--shard 2/8`, or `--shard auto`")
        };
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let k = k.trim().parse().map_err(|_| bad())?;
        let n = n.trim().parse().map_err(|_| bad())?;
        Shard::new(k, n)
    }

    /// The shard a scheduler gave this task, from its environment (`lookup` reads a variable):
    /// Slurm array jobs set `SLURM_ARRAY_TASK_ID`, `SLURM_ARRAY_TASK_MIN` and
    /// `SLURM_ARRAY_TASK_COUNT` (index = id − min); Kubernetes Indexed Jobs set
    /// `JOB_COMPLETION_INDEX` and no count, so `count` (`--shards N`) gives it.
    pub fn from_env(
        count: Option<u32>,
        lookup: impl Fn(&str) -> Option<String>,
    ) -> Result<Shard, Diagnostic> {
        let num = |name: &str| -> Result<Option<u32>, Diagnostic> {
            match lookup(name) {
                None => Ok(None),
                Some(v) => v.trim().parse().map(Some).map_err(|_| {
                    Diagnostic::new(
                        Severity::Error,
                        "rtc::shard::environment",
                        None,
                        format!("`{name}` is `{v}`, not a task number"),
                    )
                    .with_help("run under the scheduler that sets it, or give `--shard K/N`")
                }),
            }
        };
        if let Some(id) = num("SLURM_ARRAY_TASK_ID")? {
            let min = num("SLURM_ARRAY_TASK_MIN")?.unwrap_or(0);
            let n = match count {
                Some(n) => Some(n),
                None => num("SLURM_ARRAY_TASK_COUNT")?,
            };
            let n = n.ok_or_else(|| no_count("SLURM_ARRAY_TASK_COUNT"))?;
            return Shard::new(id.saturating_sub(min), n);
        }
        if let Some(index) = num("JOB_COMPLETION_INDEX")? {
            let n = count.ok_or_else(|| no_count("--shards"))?;
            return Shard::new(index, n);
        }
        Err(Diagnostic::new(
            Severity::Error,
            "rtc::shard::environment",
            None,
            "`--shard auto` found no scheduler task index in the environment",
        )
        .with_help(
            "run it as a Slurm array task (SLURM_ARRAY_TASK_ID) or a Kubernetes Indexed Job (JOB_COMPLETION_INDEX with --shards N), or give `--shard K/N`",
        ))
    }

    /// Whether item `i` of a list dealt round robin (the frames of `--frames`: positions K,
    /// K+N, …) is this shard's.
    pub fn deals(self, i: usize) -> bool {
        i % self.count as usize == self.index as usize
    }

    /// Whether row `y` belongs to this shard.
    fn owns(self, y: u32) -> bool {
        (y / BAND_ROWS) % self.count == self.index
    }

    /// How many bands [`Shard::bands`] gives for an image `height` rows tall, without making
    /// them (`rtc merge` checks a part's header with it before allocating).
    pub(crate) fn band_count(self, height: u32) -> u64 {
        let bands = u64::from(height.div_ceil(BAND_ROWS));
        let (k, n) = (u64::from(self.index), u64::from(self.count));
        if k < bands {
            (bands - k).div_ceil(n)
        } else {
            0
        }
    }

    /// The row ranges this shard renders in an image `height` rows tall, from the top.
    pub(crate) fn bands(self, height: u32) -> Vec<Range<u32>> {
        let bands = height.div_ceil(BAND_ROWS);
        (self.index..bands)
            .step_by(self.count as usize)
            .map(|b| b * BAND_ROWS..((b + 1) * BAND_ROWS).min(height))
            .collect()
    }

    /// Whether row `y` is this shard's or next to one of its rows (the halo adaptive
    /// refinement reads).
    fn owns_or_touches(self, y: u32) -> bool {
        self.owns(y) || (y > 0 && self.owns(y - 1)) || self.owns(y + 1)
    }
}

fn no_count(source: &str) -> Diagnostic {
    Diagnostic::new(
        Severity::Error,
        "rtc::shard::environment",
        None,
        "`--shard auto` knows this task's index but not how many tasks there are",
    )
    .with_help(format!(
        "give the task count with `--shards N` (or set {source})"
    ))
}

/// Which rows of an image a pass computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Rows {
    /// Every row.
    All,
    /// The rows of a shard.
    Of(Shard),
    /// The rows of a shard and the rows next to them.
    WithHalo(Shard),
}

impl Rows {
    /// Whether row `y` is computed.
    pub(crate) fn contains(self, y: u32) -> bool {
        match self {
            Rows::All => true,
            Rows::Of(s) => s.owns(y),
            Rows::WithHalo(s) => s.owns_or_touches(y),
        }
    }

    /// How many of `height` rows are computed.
    pub(crate) fn count(self, height: u32) -> u64 {
        (0..height).filter(|&y| self.contains(y)).count() as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_row_belongs_to_exactly_one_shard() {
        for n in [1, 2, 3, 7, 16] {
            for h in [1, 15, 16, 17, 100, 481] {
                for y in 0..h {
                    let owners = (0..n).filter(|&k| Shard::new(k, n).unwrap().owns(y));
                    assert_eq!(owners.count(), 1, "row {y} of {h}, {n} shards");
                }
                let rows: u32 = (0..n)
                    .flat_map(|k| Shard::new(k, n).unwrap().bands(h))
                    .map(|r| r.len() as u32)
                    .sum();
                assert_eq!(rows, h);
            }
        }
    }

    #[test]
    fn bands_are_interleaved_from_the_top() {
        let s = Shard::new(1, 3).unwrap();
        assert_eq!(s.bands(100), vec![16..32, 64..80]);
        assert_eq!(Shard::new(0, 1).unwrap().bands(20), vec![0..16, 16..20]);
    }

    #[test]
    fn impossible_shards_and_bad_text_are_diagnosed() {
        assert_eq!(Shard::parse("3/3").unwrap_err().code, "rtc::shard::index");
        assert_eq!(Shard::parse("0/0").unwrap_err().code, "rtc::shard::index");
        assert_eq!(Shard::parse("a/3").unwrap_err().code, "rtc::shard::syntax");
        assert_eq!(Shard::parse("2").unwrap_err().code, "rtc::shard::syntax");
        assert_eq!(
            Shard::parse(" 2 / 8 ").unwrap(),
            Shard { index: 2, count: 8 }
        );
    }

    #[test]
    fn the_environment_of_slurm_and_kubernetes_gives_the_shard() {
        let env = |pairs: &'static [(&'static str, &'static str)]| {
            move |k: &str| pairs.iter().find(|p| p.0 == k).map(|p| p.1.to_string())
        };
        let slurm = env(&[
            ("SLURM_ARRAY_TASK_ID", "7"),
            ("SLURM_ARRAY_TASK_MIN", "5"),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
        ]);
        assert_eq!(
            Shard::from_env(None, slurm).unwrap(),
            Shard { index: 2, count: 4 }
        );
        let k8s = env(&[("JOB_COMPLETION_INDEX", "3")]);
        assert_eq!(
            Shard::from_env(Some(8), k8s).unwrap(),
            Shard { index: 3, count: 8 }
        );
        let k8s = env(&[("JOB_COMPLETION_INDEX", "3")]);
        assert!(
            Shard::from_env(None, k8s)
                .unwrap_err()
                .help
                .unwrap()
                .contains("--shards")
        );
        assert_eq!(
            Shard::from_env(None, env(&[])).unwrap_err().code,
            "rtc::shard::environment"
        );
        let bad = env(&[("JOB_COMPLETION_INDEX", "x")]);
        assert_eq!(
            Shard::from_env(Some(2), bad).unwrap_err().code,
            "rtc::shard::environment"
        );
    }

    #[test]
    fn frames_are_dealt_round_robin() {
        let s = |k| Shard::new(k, 3).unwrap();
        let frames: Vec<i64> = (10..18).collect();
        let of = |k| -> Vec<i64> {
            frames
                .iter()
                .enumerate()
                .filter(|(i, _)| s(k).deals(*i))
                .map(|(_, f)| *f)
                .collect()
        };
        assert_eq!(of(0), vec![10, 13, 16]);
        assert_eq!(of(2), vec![12, 15]);
    }
}
