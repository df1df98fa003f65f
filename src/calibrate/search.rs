//! The search: CMA-ES over the free parameters' unit box, a generation evaluated at a time
//! in parallel, every evaluation logged; resumed by replaying the seeded search against
//! the log.

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Instant;

use anyhow::bail;

use super::calibration_plan::{CalibrationPlan, TargetPoint};
use super::cma_es::{CmaEs, CmaSettings};
use super::evaluate::{Evaluation, evaluate_all};
use super::log::{EvaluationRecord, append, log_path, read_log, start_log};
use crate::sweep::Shard;
use crate::vocabulary::seeds::case_seed;

/// Which points the search sees.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrainingPoints {
    /// All target points.
    All,
    /// Those at even positions (the odd ones are held out).
    Even,
    /// Those at odd positions.
    Odd,
}

impl TrainingPoints {
    /// The points of `all` this selects.
    pub fn select(self, all: &[TargetPoint]) -> Vec<TargetPoint> {
        all.iter()
            .filter(|p| match self {
                Self::All => true,
                Self::Even => p.index % 2 == 0,
                Self::Odd => p.index % 2 == 1,
            })
            .cloned()
            .collect()
    }

    /// The points held out: those the search does not see.
    pub fn held_out(self, all: &[TargetPoint]) -> Vec<TargetPoint> {
        match self {
            Self::All => Vec::new(),
            Self::Even => Self::Odd.select(all),
            Self::Odd => Self::Even.select(all),
        }
    }
}

/// How to search.
#[derive(Clone, Debug)]
pub struct SearchOptions {
    /// Evaluations in all (the file's unless `--budget`).
    pub budget: usize,
    /// Continue the log in the output folder.
    pub resume: bool,
    /// Which independent search stream this machine runs.
    pub shard: Shard,
    /// Which points the search sees.
    pub training: TrainingPoints,
    /// Print a line per generation.
    pub verbose: bool,
}

/// What a search did.
#[derive(Debug)]
pub struct SearchOutcome {
    /// Every evaluation of this shard, in order.
    pub records: Vec<EvaluationRecord>,
    /// Evaluations taken from the log instead of run.
    pub reused: usize,
    /// Wall time (s).
    pub wall_s: f64,
    /// Whether it stopped early because every target was met with margin.
    pub all_met: bool,
}

/// Runs the search of `plan` into `out`.
pub fn run_search(
    plan: &CalibrationPlan,
    options: &SearchOptions,
    out: &Path,
) -> anyhow::Result<SearchOutcome> {
    let started = Instant::now();
    let path = log_path(out, options.shard.index, options.shard.count);
    let logged = if options.resume {
        read_log(&path)?
    } else {
        Vec::new()
    };
    let mut file = start_log(&path, &logged)?;
    let points = options.training.select(&plan.points);
    let budget = options.budget.div_ceil(options.shard.count);
    let mut cma = CmaEs::new(settings(plan, options.shard));
    let mut records: Vec<EvaluationRecord> = Vec::new();
    let mut reused = 0;
    let mut all_met = false;
    while records.len() < budget && !all_met {
        let candidates = cma.ask();
        let take = candidates.len().min(budget - records.len());
        let first = records.len();
        let xs: Vec<Vec<f64>> = candidates[..take].iter().map(|c| c.x.clone()).collect();
        let mut results = from_log(&logged, first, &xs, &path)?;
        reused += results.iter().filter(|r| r.is_some()).count();
        let missing: Vec<usize> = (0..take).filter(|&i| results[i].is_none()).collect();
        let missing_x: Vec<Vec<f64>> = missing.iter().map(|&i| xs[i].clone()).collect();
        for (i, e) in missing.iter().zip(evaluate_all(plan, &missing_x, &points)) {
            results[*i] = Some(e);
        }
        let fresh: Vec<EvaluationRecord> = results
            .into_iter()
            .enumerate()
            .filter_map(|(i, e)| e.map(|e| (i, e)))
            .map(|(i, result)| EvaluationRecord {
                evaluation: first + i,
                restart: candidates[i].restart,
                generation: candidates[i].generation,
                values: values_of(plan, &xs[i]),
                x: xs[i].clone(),
                result,
            })
            .collect();
        let new_ones: Vec<EvaluationRecord> = fresh
            .iter()
            .filter(|r| r.evaluation >= logged.len())
            .cloned()
            .collect();
        append(&mut file, &new_ones)?;
        records.extend(fresh);
        if take < candidates.len() {
            break;
        }
        let objectives: Vec<f64> = records[first..]
            .iter()
            .map(|r| r.result.objective)
            .collect();
        all_met = objectives.iter().any(|&f| f <= 0.0);
        cma.tell(&objectives);
        if options.verbose {
            report_generation(&cma, &records, first);
        }
    }
    Ok(SearchOutcome {
        records,
        reused,
        wall_s: started.elapsed().as_secs_f64(),
        all_met,
    })
}

/// The logged results of the candidates `xs`, evaluations `first`, `first + 1`, … of the
/// search (`None` past the log's end); a logged candidate that differs is an error.
fn from_log(
    logged: &[EvaluationRecord],
    first: usize,
    xs: &[Vec<f64>],
    path: &Path,
) -> anyhow::Result<Vec<Option<Evaluation>>> {
    xs.iter()
        .enumerate()
        .map(|(i, x)| match logged.get(first + i) {
            None => Ok(None),
            Some(r) if same_point(&r.x, x) => Ok(Some(r.result.clone())),
            Some(_) => bail!(
                "{}: evaluation {} does not match this calibration (the file, the seed or the program changed): start afresh without --resume",
                path.display(),
                first + i
            ),
        })
        .collect()
}

/// The optimiser's settings: start at the base rig's values where they lie in range.
fn settings(plan: &CalibrationPlan, shard: Shard) -> CmaSettings {
    let start: Vec<f64> = plan
        .free
        .iter()
        .map(|p| p.coordinate_of(&plan.base).unwrap_or(0.5))
        .collect();
    let seed = if shard.count == 1 {
        plan.seed
    } else {
        case_seed(plan.seed, shard.index)
    };
    let mut settings = CmaSettings::new(start, seed);
    settings.sigma0 = plan.sigma;
    settings.population = plan.population;
    // Parameters finer than 0.1 % of their range are below what the verdicts resolve.
    settings.tol_x = 1e-3;
    settings
}

/// The free parameters' values at `x`, by name.
pub fn values_of(plan: &CalibrationPlan, x: &[f64]) -> BTreeMap<String, String> {
    plan.free
        .iter()
        .zip(x)
        .map(|(p, &xi)| (p.name.clone(), p.value_text(xi)))
        .collect()
}

fn same_point(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12)
}

fn report_generation(cma: &CmaEs, records: &[EvaluationRecord], first: usize) {
    let (sigma, restart) = cma.sigma_and_restart();
    let generation = &records[first..];
    let best_here = generation
        .iter()
        .min_by(|a, b| a.result.objective.total_cmp(&b.result.objective));
    if let (Some(here), Some((_, best))) = (best_here, cma.best()) {
        eprintln!(
            "evaluations {:>4}: generation best {:.3} dB ({} of {} matched), best so far {:.3} dB, step {:.3}, restart {}",
            records.len(),
            here.result.objective,
            here.result.matched,
            here.result.points,
            best,
            sigma,
            restart
        );
    }
}
