//! `testrig sweep`: a grid of cases through the chain, in parallel, shardable, resumable.

use std::io::IsTerminal;

use anyhow::bail;
use testrig::scenario::ScenarioSource;
use testrig::sweep::SweepFile;
use testrig::sweep::{Shard, SweepOptions, build_sweep, run_sweep, sweep_meta};

use crate::cli::SweepArgs;

pub fn run(args: &SweepArgs) -> anyhow::Result<()> {
    if args.jobs == Some(0) {
        bail!("--jobs 0: at least one worker");
    }
    let shard = Shard::choose(args.shard, |k| std::env::var(k).ok())?;
    let source = ScenarioSource::read_with(&args.sweep, &args.overrides)?;
    let file: SweepFile = source.parse_sweep()?;
    let plan = build_sweep(&source, &file)?;
    let meta = sweep_meta(&source, &plan);
    let options = SweepOptions {
        jobs: args.jobs,
        shard,
        resume: args.resume,
        out: args.out.clone(),
        progress: std::io::stderr().is_terminal(),
        stop: None,
    };
    let outcome = run_sweep(&plan, &meta, &options)?;
    println!(
        "{}: {} cases run in {:.2} s wall ({} skipped as finished, shard {}/{}), {} files in {}",
        plan.name,
        outcome.ran,
        outcome.wall_s,
        outcome.skipped,
        shard.index,
        shard.count,
        outcome.files.len(),
        args.out.display()
    );
    outcome.failures()
}
