//! Running a sweep: this shard's cases in parallel (rayon) with a progress bar, each
//! written as it finishes; then the table and the plots from every finished case.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use anyhow::Context;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;

use super::case_recording::RECORDINGS_DIR;
use super::case_result::CaseResult;
use super::case_run::run_case;
use super::grid::{Case, SweepPlan};
use super::held_motions::held_motions;
use super::knocked::run_knocked;
use super::labels::write_labels;
use super::meta::{SweepMeta, read_meta, write_meta};
use super::report::write_report;
use super::sequence::Direction;
use super::series::run_series;
use super::shard::Shard;
use super::table::{CASES_DIR, case_path, read_cases, write_case, write_table};
use crate::plots::{
    RegimeCell, SectionColumn, SpeedLines, WaterfallTrace, write_bifurcation, write_frequency_map,
    write_regime_map, write_waterfall,
};
use crate::recording::remove_files_with_extension;
use crate::runtime::previous_run::manifest_scenario;

/// How to run.
#[derive(Clone, Debug)]
pub struct SweepOptions {
    /// Worker threads (`None`: one per core).
    pub jobs: Option<usize>,
    /// Which cases.
    pub shard: Shard,
    /// Skip cases already finished in the output folder.
    pub resume: bool,
    /// Output folder.
    pub out: PathBuf,
    /// Draw a progress bar.
    pub progress: bool,
    /// Set (by Ctrl-C) to start no further case: those finished are kept, and the sweep
    /// ends with an error saying how to resume.
    pub stop: Option<Arc<AtomicBool>>,
}

/// What a sweep did.
#[derive(Debug)]
pub struct SweepOutcome {
    /// Cases run now.
    pub ran: usize,
    /// Cases skipped as already finished.
    pub skipped: usize,
    /// Cases that failed: (index, error).
    pub failed: Vec<(usize, String)>,
    /// Wall time of the cases (s).
    pub wall_s: f64,
    /// Files written by the assembly.
    pub files: Vec<PathBuf>,
}

impl SweepOutcome {
    /// An error listing the cases that failed, if any did (the others are kept).
    pub fn failures(&self) -> anyhow::Result<()> {
        if self.failed.is_empty() {
            return Ok(());
        }
        let list: Vec<String> = self
            .failed
            .iter()
            .map(|(i, e)| format!("case {i}: {e}"))
            .collect();
        anyhow::bail!(
            "{} case(s) failed (the others are kept): {}",
            list.len(),
            list.join("; ")
        )
    }
}

/// Runs this shard's cases of `plan` and assembles what is finished.
pub fn run_sweep(
    plan: &SweepPlan,
    meta: &SweepMeta,
    options: &SweepOptions,
) -> anyhow::Result<SweepOutcome> {
    let dir = &options.out;
    std::fs::create_dir_all(dir.join(CASES_DIR))
        .with_context(|| format!("--out {}: cannot create the output folder", dir.display()))?;
    clear_other_sweep(dir, meta, options.resume)?;
    write_meta(dir, meta)?;
    let units = work_units(plan, options.shard);
    let finished = |c: &&Case| options.resume && case_path(dir, c.index).exists();
    let mine: usize = units.iter().map(Vec::len).sum();
    // A series is run whole unless every case of it is finished (its cases depend on
    // the ones before them).
    let todo: Vec<Vec<&Case>> = units
        .into_iter()
        .filter(|unit| !unit.iter().all(finished))
        .collect();
    let count: usize = todo.iter().map(Vec::len).sum();
    let bar = progress_bar(count as u64, options.progress);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs.unwrap_or(0))
        .build()
        .context("cannot start the worker threads")?;
    let started = Instant::now();
    // The longest units (series of the most cases) first, each worker taking the next
    // when it is free: a long series begun last had kept one worker busy seconds after
    // the other had finished (the lab campaign's run-up and run-down series).
    let mut longest_first: Vec<&Vec<&Case>> = todo.iter().collect();
    longest_first.sort_by_key(|unit| std::cmp::Reverse(unit.len()));
    let mut failed: Vec<(usize, String)> = pool.install(|| {
        longest_first
            .into_iter()
            .par_bridge()
            .flat_map_iter(|unit| {
                let stopped = options
                    .stop
                    .as_ref()
                    .is_some_and(|s| s.load(Ordering::Relaxed));
                let results = match unit.as_slice() {
                    _ if stopped => Vec::new(),
                    [case] if case.series.is_none() => {
                        vec![(case.index, run_case(plan, case, Some(dir)))]
                    }
                    series if series[0].direction.is_own_start() => {
                        run_knocked(plan, series, Some(dir))
                    }
                    series => run_series(plan, series, Some(dir)),
                };
                results.into_iter().filter_map(|(index, result)| {
                    let done = result.and_then(|r| write_case(dir, &r));
                    bar.inc(1);
                    done.err().map(|e| (index, format!("{e:#}")))
                })
            })
            .collect()
    });
    failed.sort_by_key(|&(index, _)| index);
    bar.finish_and_clear();
    if options
        .stop
        .as_ref()
        .is_some_and(|s| s.load(Ordering::Relaxed))
    {
        anyhow::bail!(
            "stopped: the cases finished are kept in {}; run it again with resume to finish",
            dir.display()
        );
    }
    let wall_s = started.elapsed().as_secs_f64();
    let files = assemble(std::slice::from_ref(dir), dir)?.files;
    Ok(SweepOutcome {
        ran: count,
        skipped: mine - count,
        failed,
        wall_s,
        files,
    })
}

/// This shard's work: each case of its own, or each series whole (a series belongs to
/// the shard of its number), in index order.
fn work_units(plan: &SweepPlan, shard: Shard) -> Vec<Vec<&Case>> {
    let mut units: Vec<Vec<&Case>> = Vec::new();
    for case in &plan.cases {
        match case.series {
            None if shard.has(case.index) => units.push(vec![case]),
            None => {}
            Some(series) if shard.has(series) => match units.last_mut() {
                Some(unit) if unit[0].series == Some(series) => unit.push(case),
                _ => units.push(vec![case]),
            },
            Some(_) => {}
        }
    }
    units
}

/// A folder holding a run's files (its `manifest.json`: `run`, `simulate`, `analyse`) is
/// refused. A folder holding the cases of another sweep (its `sweep.json` differs) has them removed,
/// so that they are not assembled with this one's; with `--resume` that is an error.
/// Cases of this same sweep (other shards writing to one folder) stay.
fn clear_other_sweep(dir: &Path, meta: &SweepMeta, resume: bool) -> anyhow::Result<()> {
    if let Some(earlier) = manifest_scenario(dir) {
        anyhow::bail!(
            "--out {}: holds the files of a run (`{earlier}`, its manifest.json), not a sweep's cases: choose another folder",
            dir.display()
        );
    }
    let Ok(earlier) = read_meta(dir) else {
        return Ok(());
    };
    if earlier == *meta {
        return Ok(());
    }
    if resume {
        anyhow::bail!(
            "--resume: {} holds the cases of another sweep (`{}`, {} cases); resume into the folder of this sweep, or run without --resume to replace them",
            dir.display(),
            earlier.name,
            earlier.cases
        );
    }
    remove_files_with_extension(&dir.join(CASES_DIR), "json")?;
    let recordings = dir.join(RECORDINGS_DIR);
    if recordings.is_dir() {
        std::fs::remove_dir_all(&recordings)
            .with_context(|| format!("{}: cannot remove", recordings.display()))?;
    }
    Ok(())
}

/// Copies the cases' recordings of the shard folders `dirs` into `out`.
fn copy_recordings(dirs: &[PathBuf], out: &Path) -> anyhow::Result<()> {
    for dir in dirs {
        let Ok(entries) = std::fs::read_dir(dir.join(RECORDINGS_DIR)) else {
            continue;
        };
        let into = out.join(RECORDINGS_DIR);
        std::fs::create_dir_all(&into)
            .with_context(|| format!("{}: cannot create the folder", into.display()))?;
        for entry in entries {
            let path = entry?.path();
            if path.extension().is_some_and(|e| e == "partial") {
                continue;
            }
            if let Some(name) = path.file_name() {
                std::fs::copy(&path, into.join(name))
                    .with_context(|| format!("copying {}", path.display()))?;
            }
        }
    }
    Ok(())
}

fn progress_bar(len: u64, visible: bool) -> ProgressBar {
    let target = if visible {
        ProgressDrawTarget::stderr_with_hz(4)
    } else {
        ProgressDrawTarget::hidden()
    };
    let bar = ProgressBar::with_draw_target(Some(len), target);
    if let Ok(style) = ProgressStyle::with_template("{bar:30} {pos}/{len} cases (eta {eta})") {
        bar.set_style(style);
    }
    bar
}

/// What [`assemble`] wrote, and which cases of the grid it did not find.
#[derive(Debug)]
pub struct Assembled {
    /// Files written.
    pub files: Vec<PathBuf>,
    /// Indices of the grid's cases finished in none of the folders.
    pub missing: Vec<usize>,
}

/// Writes into `out` the table and the plots of every case finished in `dirs` (and the
/// cases themselves when `out` is not among `dirs`). The folders must hold shards of one
/// sweep (the same `sweep.json`).
pub fn assemble(dirs: &[PathBuf], out: &Path) -> anyhow::Result<Assembled> {
    let meta = same_sweep(dirs)?;
    let cases = read_cases(dirs)?;
    let found: std::collections::BTreeSet<usize> = cases.iter().map(|c| c.index).collect();
    let missing = (0..meta.cases).filter(|i| !found.contains(i)).collect();
    std::fs::create_dir_all(out.join(CASES_DIR))
        .with_context(|| format!("{}: cannot create the folder", out.display()))?;
    if !dirs.iter().any(|d| d == out) {
        write_meta(out, &meta)?;
        for c in &cases {
            write_case(out, c)?;
        }
        copy_recordings(dirs, out)?;
    }
    let mut files = vec![write_table(
        out,
        &meta.swept,
        &cases,
        meta.held_against_thesis(),
    )?];
    if cases
        .iter()
        .any(|c| !c.recordings.is_empty() || !c.faults.is_empty())
    {
        files.push(write_labels(out, &meta.swept, &cases)?);
    }
    files.extend(plots(out, &meta, &cases)?);
    let report = write_report(out, &meta, &cases, &files)?;
    files.push(report);
    Ok(Assembled { files, missing })
}

/// The sweep description the folders `dirs` share; refused if they hold different
/// sweeps.
fn same_sweep(dirs: &[PathBuf]) -> anyhow::Result<SweepMeta> {
    let first = dirs.first().context("no sweep folder given")?;
    let meta = read_meta(first)?;
    for dir in &dirs[1..] {
        let other = read_meta(dir)?;
        if other != meta {
            anyhow::bail!(
                "{} and {} hold different sweeps (their sweep.json differ{}): merge shards of one sweep",
                first.display(),
                dir.display(),
                if other.fingerprint != meta.fingerprint {
                    ": another grid, seed, case timing, chain, analyser, rig or program"
                } else {
                    ""
                }
            );
        }
    }
    Ok(meta)
}

/// Indices of the grid's cases that none of the folders `dirs` (shards of one sweep)
/// holds finished.
pub fn missing_cases(dirs: &[PathBuf]) -> anyhow::Result<Vec<usize>> {
    let meta = same_sweep(dirs)?;
    let found: std::collections::BTreeSet<usize> =
        read_cases(dirs)?.iter().map(|c| c.index).collect();
    Ok((0..meta.cases).filter(|i| !found.contains(i)).collect())
}

/// One group per swept-parameter variant and load: its label and cases in speed order.
fn groups(cases: &[CaseResult]) -> Vec<(String, Vec<&CaseResult>)> {
    let mut groups: Vec<(String, Vec<&CaseResult>)> = Vec::new();
    for c in cases {
        let mut label: Vec<String> = c.values.clone();
        label.push(format!("{} N m", c.load_nm));
        if c.direction != Direction::Static {
            label.push(format!("{}", c.direction));
        }
        let label = label.join(", ");
        match groups.iter_mut().find(|(l, _)| *l == label) {
            Some((_, members)) => members.push(c),
            None => groups.push((label, vec![c])),
        }
    }
    for (_, members) in &mut groups {
        members.sort_by(|a, b| a.rpm.total_cmp(&b.rpm));
    }
    groups
}

fn file_label(label: &str) -> String {
    label
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '.' || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect::<String>()
        .replace("__", "_")
}

fn plots(out: &Path, meta: &SweepMeta, cases: &[CaseResult]) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for (label, members) in groups(cases) {
        let tag = file_label(&label);
        let speeds: Vec<SpeedLines> = members
            .iter()
            .map(|c| SpeedLines {
                running_hz: c.rpm / 60.0,
                peaks: c.peaks.clone(),
            })
            .collect();
        let title = format!("{}: output against input frequency, {label}", meta.name);
        files.extend(write_frequency_map(
            &out.join(format!("frequency-map-{tag}")),
            &title,
            &speeds,
            &meta.natural_hz,
            meta.fmax_hz,
        )?);
        let traces: Vec<WaterfallTrace> = members
            .iter()
            .map(|c| WaterfallTrace {
                rpm: c.rpm,
                lines: c.spectrum.clone(),
            })
            .collect();
        let title = format!("{}: spectra against speed, {label}", meta.name);
        files.extend(write_waterfall(
            &out.join(format!("waterfall-{tag}")),
            &title,
            &traces,
        )?);
    }
    files.extend(bifurcation_plots(out, meta, cases)?);
    let mut variants: Vec<Vec<String>> = cases.iter().map(|c| c.values.clone()).collect();
    variants.dedup();
    for values in variants {
        let cells: Vec<RegimeCell> = cases
            .iter()
            .filter(|c| c.values == values)
            .map(|c| RegimeCell {
                rpm: c.rpm,
                load_nm: c.load_nm,
                regime: c.regime,
            })
            .collect();
        let what = if values.is_empty() {
            String::new()
        } else {
            format!(", {}", values.join(", "))
        };
        let tag = if values.is_empty() {
            String::new()
        } else {
            format!("-{}", file_label(&values.join("_")))
        };
        let title = format!("{}: regime by speed and load{what}", meta.name);
        files.extend(write_regime_map(
            &out.join(format!("regime-map{tag}")),
            &title,
            &cells,
        )?);
    }
    Ok(files)
}

/// One bifurcation diagram per parameter variant and load, each approach a series, the
/// speeds where the approaches settle to different motions shaded.
fn bifurcation_plots(
    out: &Path,
    meta: &SweepMeta,
    cases: &[CaseResult],
) -> anyhow::Result<Vec<PathBuf>> {
    let mut keys: Vec<(Vec<String>, f64)> = Vec::new();
    for c in cases {
        let key = (c.values.clone(), c.load_nm);
        if !keys.contains(&key) {
            keys.push(key);
        }
    }
    let mut files = Vec::new();
    for (values, load) in keys {
        let mut label = values.clone();
        label.push(format!("{load} N m"));
        let label = label.join(", ");
        let here = |c: &CaseResult| c.values == values && c.load_nm == load;
        let series: Vec<(String, Vec<SectionColumn>)> = [
            Direction::Up,
            Direction::Down,
            Direction::Rest,
            Direction::Static,
            Direction::Repeat,
        ]
        .into_iter()
        .map(|d| {
            let columns: Vec<SectionColumn> = cases
                .iter()
                .filter(|c| here(c) && c.direction == d)
                .map(|c| SectionColumn {
                    rpm: c.rpm,
                    torque_nm: c.revolution_torque_nm.clone(),
                })
                .collect();
            let label = match d {
                Direction::Static => "from the static load",
                Direction::Rest => "from rest",
                Direction::Up => "run-up",
                Direction::Down => "run-down",
                Direction::Repeat => "knocked repeats",
            };
            (label.to_string(), columns)
        })
        .filter(|(_, columns)| columns.iter().any(|c| !c.torque_nm.is_empty()))
        .collect();
        let coexisting: Vec<f64> = held_motions(cases)
            .iter()
            .filter(|h| here(h.point) && h.coexist())
            .map(|h| h.point.rpm)
            .collect();
        if series.is_empty() {
            continue;
        }
        let title = format!(
            "{}: once-per-revolution torque against speed, {label}",
            meta.name
        );
        files.extend(write_bifurcation(
            &out.join(format!("bifurcation-{}", file_label(&label))),
            &title,
            &series,
            &coexisting,
        )?);
    }
    Ok(files)
}
