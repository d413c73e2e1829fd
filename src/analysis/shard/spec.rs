//! Which shard a process runs: `K/N` with 1 ≤ K ≤ N, or `slurm`, read from
//! the variables Slurm sets in each task of a job array.
//!
//! Under Slurm, K counts from the array's first task id: with
//! `--array=MIN-MAX` (step 1, any MIN, so `0-3` and `1-4` both work),
//! K = SLURM_ARRAY_TASK_ID − SLURM_ARRAY_TASK_MIN + 1 and
//! N = SLURM_ARRAY_TASK_COUNT. An array with a step or a list of ids
//! (`--array=1,5,9`, `0-15:4`) is refused: its ids are not one shard each.

use std::fmt;

/// Shard `k` of `n` (1-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub k: usize,
    pub n: usize,
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.k, self.n)
    }
}

/// Most shards one sweep may be cut into.
pub const MAX_SHARDS: usize = 1_000_000;

impl Shard {
    /// Parses `--shard`'s value: `K/N`, or `slurm` with `env` giving the
    /// process's variables. The error is one line naming the value and what
    /// is allowed.
    pub fn parse(text: &str, env: impl Fn(&str) -> Option<String>) -> Result<Shard, String> {
        let text = text.trim();
        if text == "slurm" {
            return Shard::from_slurm(env);
        }
        Shard::parse_k_of_n(text)
    }

    fn parse_k_of_n(text: &str) -> Result<Shard, String> {
        let bad = |why: &str| {
            format!(
                "--shard `{}`: {why}",
                crate::model::params::echo::text(text)
            )
        };
        let form = "expected K/N with 1 <= K <= N (e.g. 2/8), or slurm";
        let (k, n) = text.split_once('/').ok_or_else(|| bad(form))?;
        let (Ok(k), Ok(n)) = (k.trim().parse::<usize>(), n.trim().parse::<usize>()) else {
            return Err(bad(form));
        };
        if n == 0 {
            return Err(bad("N must be at least 1"));
        }
        if n > MAX_SHARDS {
            return Err(bad(&format!("N must be at most {MAX_SHARDS}")));
        }
        if k == 0 || k > n {
            return Err(bad(&format!("K must be 1 to {n}")));
        }
        Ok(Shard { k, n })
    }

    fn from_slurm(env: impl Fn(&str) -> Option<String>) -> Result<Shard, String> {
        let var = |name: &str| -> Result<Option<usize>, String> {
            match env(name) {
                None => Ok(None),
                Some(v) => v.trim().parse::<usize>().map(Some).map_err(|_| {
                    format!(
                        "--shard slurm: {name} = `{}` is not a task number",
                        crate::model::params::echo::text(&v)
                    )
                }),
            }
        };
        let (Some(id), Some(count)) = (var("SLURM_ARRAY_TASK_ID")?, var("SLURM_ARRAY_TASK_COUNT")?)
        else {
            return Err(
                "--shard slurm: SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT \
                        are not set (not a task of a job array); give --shard K/N"
                    .into(),
            );
        };
        let min = var("SLURM_ARRAY_TASK_MIN")?.unwrap_or(0);
        if let Some(max) = var("SLURM_ARRAY_TASK_MAX")?
            && max.checked_sub(min).map(|d| d + 1) != Some(count)
        {
            return Err(format!(
                "--shard slurm: the array's ids {min}-{max} are not {count} consecutive ids; \
                 submit it with --array=MIN-MAX (no step, no list)"
            ));
        }
        if count == 0 || id < min || id - min >= count {
            return Err(format!(
                "--shard slurm: SLURM_ARRAY_TASK_ID = {id} is outside the array \
                 ({count} tasks from {min})"
            ));
        }
        Shard::parse_k_of_n(&format!("{}/{count}", id - min + 1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn none(_: &str) -> Option<String> {
        None
    }

    #[test]
    fn k_of_n_and_refusals() {
        assert_eq!(Shard::parse("2/3", none), Ok(Shard { k: 2, n: 3 }));
        for bad in ["0/3", "4/3", "1/0", "1", "a/b", "-1/3", ""] {
            let e = Shard::parse(bad, none).unwrap_err();
            assert!(e.starts_with("--shard"), "{e}");
        }
        assert!(Shard::parse("slurm", none).unwrap_err().contains("not set"));
    }

    #[test]
    fn slurm_ids_from_zero_or_one() {
        let env = |id: &'static str, min: &'static str| {
            move |name: &str| match name {
                "SLURM_ARRAY_TASK_ID" => Some(id.to_string()),
                "SLURM_ARRAY_TASK_COUNT" => Some("4".to_string()),
                "SLURM_ARRAY_TASK_MIN" => Some(min.to_string()),
                _ => None,
            }
        };
        assert_eq!(
            Shard::parse("slurm", env("0", "0")),
            Ok(Shard { k: 1, n: 4 })
        );
        assert_eq!(
            Shard::parse("slurm", env("4", "1")),
            Ok(Shard { k: 4, n: 4 })
        );
        assert!(Shard::parse("slurm", env("5", "1")).is_err());
        let stepped = |name: &str| match name {
            "SLURM_ARRAY_TASK_ID" => Some("4".to_string()),
            "SLURM_ARRAY_TASK_COUNT" => Some("2".to_string()),
            "SLURM_ARRAY_TASK_MIN" => Some("0".to_string()),
            "SLURM_ARRAY_TASK_MAX" => Some("4".to_string()),
            _ => None,
        };
        assert!(
            Shard::parse("slurm", stepped)
                .unwrap_err()
                .contains("consecutive")
        );
    }
}
