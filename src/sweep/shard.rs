//! Which cases this process runs: every N-th from K (`--shard K/N`, or a SLURM job
//! array's SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT).

use anyhow::{Context, bail};

/// Shard K of N (0 ≤ K < N).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// This shard (from 0).
    pub index: usize,
    /// Number of shards.
    pub count: usize,
}

impl Shard {
    /// All cases.
    pub const ALL: Self = Self { index: 0, count: 1 };

    /// Parses `K/N`.
    pub fn parse(text: &str) -> anyhow::Result<Self> {
        let (k, n) = text
            .split_once('/')
            .with_context(|| format!("--shard {text}: expected K/N, e.g. 0/3"))?;
        let index: usize = k
            .trim()
            .parse()
            .with_context(|| format!("--shard {text}: K is not a whole number"))?;
        let count: usize = n
            .trim()
            .parse()
            .with_context(|| format!("--shard {text}: N is not a whole number"))?;
        if count == 0 || index >= count {
            bail!("--shard {text}: needs 0 ≤ K < N");
        }
        Ok(Self { index, count })
    }

    /// From `--shard` if given, else from SLURM's job-array variables, else all cases.
    pub fn choose(
        flag: Option<Self>,
        env: impl Fn(&str) -> Option<String>,
    ) -> anyhow::Result<Self> {
        if let Some(shard) = flag {
            return Ok(shard);
        }
        let (Some(id), Some(count)) = (env("SLURM_ARRAY_TASK_ID"), env("SLURM_ARRAY_TASK_COUNT"))
        else {
            return Ok(Self::ALL);
        };
        // Arrays may start anywhere (--array=1-4): shard K counts from the first task.
        let first = env("SLURM_ARRAY_TASK_MIN").unwrap_or_else(|| "0".into());
        let whole = |text: &str| text.trim().parse::<usize>().ok();
        match (whole(&id), whole(&first)) {
            (Some(id), Some(first)) if id >= first => {
                Self::parse(&format!("{}/{count}", id - first))
            }
            _ => bail!("SLURM_ARRAY_TASK_ID {id} (first {first}): not a task of the array"),
        }
        .context("from SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_MIN / SLURM_ARRAY_TASK_COUNT")
    }

    /// Whether case `index` belongs to this shard.
    pub fn has(self, index: usize) -> bool {
        index % self.count == self.index
    }
}
