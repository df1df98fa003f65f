//! `testrig calibrate`: the search, then the best set as a preset file with its report.

use anyhow::{Context, bail};
use testrig::calibrate::PointOutcome;
use testrig::calibrate::read_all_logs;
use testrig::calibrate::{
    CalibrationFile, CalibrationResult, SearchOptions, TrainingPoints, best_record,
    build_calibration, evaluate_all, run_search, write_outputs,
};
use testrig::scenario::ScenarioSource;
use testrig::sweep::Shard;

use crate::cli::{CalibrateArgs, TrainingHalf};

pub fn run(args: &CalibrateArgs) -> anyhow::Result<()> {
    if args.jobs == Some(0) {
        bail!("--jobs 0: at least one worker");
    }
    if args.budget == Some(0) {
        bail!("--budget 0: at least one evaluation");
    }
    let shard = Shard::choose(args.shard, |k| std::env::var(k).ok())?;
    let source = ScenarioSource::read_with(&args.calibration, &args.overrides)?;
    let file: CalibrationFile = source.parse_calibration()?;
    let plan = build_calibration(&source, &file)?;
    let training = match args.train_half {
        Some(TrainingHalf::Even) => TrainingPoints::Even,
        Some(TrainingHalf::Odd) => TrainingPoints::Odd,
        None => TrainingPoints::All,
    };
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("{}: cannot create the output folder", args.out.display()))?;
    let options = SearchOptions {
        budget: args.budget.unwrap_or(plan.budget),
        resume: args.resume,
        shard,
        training,
        verbose: true,
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()
        .context("cannot start the worker threads")?;
    let outcome = pool.install(|| run_search(&plan, &options, &args.out))?;
    let records = read_all_logs(&args.out)?;
    let best = best_record(&records)
        .context("no evaluation succeeded: see the errors in the log")?
        .clone();
    let full = if training == TrainingPoints::All {
        best.result.clone()
    } else {
        let all = pool.install(|| evaluate_all(&plan, std::slice::from_ref(&best.x), &plan.points));
        all.into_iter()
            .next()
            .context("the best set could not be evaluated again")?
    };
    let held_out = training.held_out(&plan.points);
    let held_score = (!held_out.is_empty()).then(|| {
        score_of(&full.outcomes, |o| {
            held_out.iter().any(|p| p.index == o.index)
        })
    });
    let result = CalibrationResult {
        name: plan.name.clone(),
        evaluations: records.len(),
        restarts: records.iter().map(|r| r.restart).max().unwrap_or(0),
        best_evaluation: best.evaluation,
        values: best.values.clone(),
        objective_db: best.result.objective,
        training_score: (best.result.matched, best.result.points),
        held_out_score: held_score,
        score: (full.matched, full.points),
    };
    let files = write_outputs(&args.out, &plan, &records, &best, &full, &result)?;
    println!(
        "{}: {} evaluations ({} run now, {} from the log) in {:.1} s wall{}; best objective {:.3} dB, {} of {} points matched{}; {} files in {}",
        plan.name,
        outcome.records.len(),
        outcome.records.len() - outcome.reused,
        outcome.reused,
        outcome.wall_s,
        if outcome.all_met {
            " (every target met: stopped)"
        } else {
            ""
        },
        result.objective_db,
        result.score.0,
        result.score.1,
        held_score.map_or(String::new(), |(a, b)| format!(
            ", {a} of {b} held-out points"
        )),
        files.len(),
        args.out.display()
    );
    Ok(())
}

fn score_of(outcomes: &[PointOutcome], chosen: impl Fn(&PointOutcome) -> bool) -> (usize, usize) {
    let picked: Vec<_> = outcomes.iter().filter(|o| chosen(o)).collect();
    (picked.iter().filter(|o| o.matched).count(), picked.len())
}
