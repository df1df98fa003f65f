//! `testrig sweep`: a grid of cases through the chain, in parallel, shardable, resumable.

use std::io::IsTerminal;

use anyhow::bail;
use rig::RigChains;
use testrig::scenario::ScenarioSource;
use testrig::sweep::SweepFile;
use testrig::sweep::{Shard, SweepMeta, SweepOptions, build_sweep, fingerprint, run_sweep};

use crate::cli::SweepArgs;

pub fn run(args: &SweepArgs) -> anyhow::Result<()> {
    if args.jobs == Some(0) {
        bail!("--jobs 0: at least one worker");
    }
    let shard = Shard::choose(args.shard, |k| std::env::var(k).ok())?;
    let source = ScenarioSource::read_with(&args.sweep, &args.overrides)?;
    let file: SweepFile = source.parse_sweep()?;
    let plan = build_sweep(&source, &file)?;
    let base = plan.cases.first().map(|c| c.params.clone());
    let natural_hz = base
        .map(|p| {
            RigChains::of(&p)
                .whole_rig
                .modes()
                .iter()
                .map(|m| m.frequency_hz)
                .collect()
        })
        .unwrap_or_default();
    let meta = SweepMeta {
        name: plan.name.clone(),
        swept: plan.swept.clone(),
        natural_hz,
        fmax_hz: plan.analyser.settings.fmax_hz,
        cases: plan.cases.len(),
        fingerprint: fingerprint(&source.text, &plan),
    };
    let options = SweepOptions {
        jobs: args.jobs,
        shard,
        resume: args.resume,
        out: args.out.clone(),
        progress: std::io::stderr().is_terminal(),
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
    if !outcome.failed.is_empty() {
        let list: Vec<String> = outcome
            .failed
            .iter()
            .map(|(i, e)| format!("case {i}: {e}"))
            .collect();
        bail!(
            "{} case(s) failed (the others are kept): {}",
            list.len(),
            list.join("; ")
        );
    }
    Ok(())
}
