//! One run of a scenario: the plant's thread, a thread per instrument stage and per sink,
//! the console on the calling thread; returns when every file is closed.

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};

use anyhow::Context;

use super::console::Console;
use super::pacing::Pace;
use super::plant_source::{PlantJob, PlantReport, run_plant};
use super::process_usage::cpu_s_and_peak_rss_mib;
use super::run_plant::RunPlant;
use super::sinks::analyser::AnalyserSink;
use super::sinks::monitor::MonitorSink;
use super::sinks::recorder::RecorderSink;
use super::sinks::scope::ScopeSink;
use super::sinks::tap::TapSink;
use super::sinks::{Sink, SinkReport};
use super::status::SharedStatus;
use super::wiring::{channel, guarded, run_chain, run_sink};
use crate::chain::NamedStage;
use crate::recording::start_journal;
use crate::scenario::Plan;
use crate::vocabulary::control::refusals;
use crate::vocabulary::frame::SignalNames;
use crate::vocabulary::signal_names::{AMPLIFIER_V, FILTER_V};
use crate::vocabulary::{CommandInbox, Request, Target};

/// How to run.
#[derive(Clone, Debug)]
pub struct RunOptions {
    /// Pace.
    pub pace: Pace,
    /// Output folder.
    pub out: PathBuf,
    /// Set (e.g. by Ctrl-C) to end the run early, keeping what was recorded.
    pub stop: Arc<AtomicBool>,
    /// Draw the console (progress and rack readings).
    pub console: bool,
    /// Live commands (a panel's), besides the scenario's timed ones.
    pub control: Option<crossbeam_channel::Receiver<Request>>,
    /// Remove the files of another scenario's run from `out` (else such a folder is
    /// refused); a rerun of the same scenario always replaces its own.
    pub replace: bool,
}

/// What a run did.
#[derive(Debug)]
pub struct RunResult {
    /// The plant's report.
    pub plant: PlantReport,
    /// The sinks' reports.
    pub sinks: Vec<SinkReport>,
    /// Wall time (s).
    pub wall_s: f64,
    /// CPU time of the process during the run (s).
    pub cpu_s: f64,
    /// Peak resident memory of the process (MiB).
    pub peak_rss_mib: f64,
    /// Errors of the sinks (the plant's is in its report).
    pub errors: Vec<String>,
    /// Whether the run was stopped before its end (Ctrl-C or an error).
    pub stopped_early: bool,
    /// The scenario's `[[command]]` entries that were refused, with why.
    pub refused_commands: Vec<String>,
}

impl RunResult {
    /// Simulated time released by the plant (s).
    pub fn simulated_s(&self) -> f64 {
        self.plant.samples as f64 * self.plant.step_s
    }

    /// Every error that stopped the run: the sinks', then the plant's; empty if none.
    pub fn failures(&self) -> Vec<String> {
        self.errors
            .iter()
            .cloned()
            .chain(self.plant.error.clone())
            .collect()
    }

    /// Every sink's warnings (spectra short of their averages, measurements not reached,
    /// ADC overloads, scopes that did not trigger), in sink order.
    pub fn warnings(&self) -> Vec<String> {
        self.sinks
            .iter()
            .flat_map(|s| s.warnings.iter().cloned())
            .chain(self.refused_commands.iter().cloned())
            .collect()
    }
}

/// Runs `plan`, writing into `options.out`.
pub fn run(plan: &Plan, options: &RunOptions) -> anyhow::Result<RunResult> {
    run_with_status(plan, options, SharedStatus::default())
}

/// As [`run`], the rack's readings and displays kept in `status` (a live panel reads it).
pub fn run_with_status(
    plan: &Plan,
    options: &RunOptions,
    status: SharedStatus,
) -> anyhow::Result<RunResult> {
    std::fs::create_dir_all(&options.out).with_context(|| {
        format!(
            "--out {}: cannot create the output folder",
            options.out.display()
        )
    })?;
    start_journal(&options.out, &plan.name)?;
    let run = RunParts {
        plan,
        options,
        status: &status,
    };
    let rig = &plan.rig.topology;
    let (schedule, ceiling) = (plan.schedule.clone(), plan.live_ceiling);
    let columns = plan.rig_columns_read();
    let names = crate::rig_roles::signals_with(rig, &columns);
    let plant = RunPlant::new(rig, schedule, plan.rate_hz, ceiling, columns)
        .with_context(|| format!("rig `{}` and the scenario's schedule", rig.name))?;
    run.run(plant, names)
}

/// A run's plan, options and status, before its plant is built.
struct RunParts<'a> {
    plan: &'a Plan,
    options: &'a RunOptions,
    status: &'a SharedStatus,
}

impl RunParts<'_> {
    /// Runs `plant`, whose channels `names` names, through the chain into the sinks.
    fn run(&self, plant: RunPlant, mut names: SignalNames) -> anyhow::Result<RunResult> {
        let (plan, options, status) = (self.plan, self.options, self.status);
        let stages = plan.chain.stages.build(plan.rate_hz, &mut names)?;
        let live = options.control.is_some();
        let sinks = build_sinks(plan, &options.out, &names, status, live)?;
        let total_samples = (plan.duration_s * plan.rate_hz).round() as u64;
        let inbox = CommandInbox::new(
            &plan.commands,
            options.control.clone(),
            command_targets(plan),
            plan.rate_hz,
        );
        let scheduled_answers = inbox.scheduled_answers();
        let job = PlantJob {
            plant,
            total_samples,
            block_samples: plan.block_samples,
            pace: options.pace,
            overflow: plan.overflow,
            stop: Arc::clone(&options.stop),
            status: status.clone(),
            inbox,
            measures_s: plan.measures.iter().map(|m| m.at_s).collect(),
        };
        let (cpu_before, _) = cpu_s_and_peak_rss_mib();
        let started = Instant::now();
        let console = Console::new(total_samples, plan.rate_hz, options.console);
        let errors = Mutex::new(Vec::new());
        let threads = Threads {
            queue_blocks: plan.queue_blocks,
            stop: &options.stop,
            errors: &errors,
            console: &console,
            status,
        };
        let (plant, sink_reports) = threads.run(job, stages, sinks);
        console.finish();
        let plant = plant.map_err(|_| anyhow::anyhow!("the plant's thread panicked"))?;
        let (cpu_after, peak_rss_mib) = cpu_s_and_peak_rss_mib();
        let errors = errors.into_inner().unwrap_or_else(PoisonError::into_inner);
        Ok(RunResult {
            stopped_early: plant.samples < total_samples,
            plant,
            sinks: sink_reports,
            wall_s: started.elapsed().as_secs_f64(),
            cpu_s: cpu_after - cpu_before,
            peak_rss_mib,
            errors,
            refused_commands: refusals(&scheduled_answers),
        })
    }
}

/// What the threads of a run share.
struct Threads<'a> {
    queue_blocks: usize,
    stop: &'a AtomicBool,
    errors: &'a Mutex<Vec<String>>,
    console: &'a Console,
    status: &'a SharedStatus,
}

type PlantOutcome = std::thread::Result<PlantReport>;

impl Threads<'_> {
    /// Spawns the plant, the chain's thread (its stages in turn, feeding every sink) and a
    /// thread per sink; draws the console until the plant is done; joins all.
    fn run(
        &self,
        job: PlantJob,
        stages: Vec<NamedStage>,
        sinks: Vec<NamedSink>,
    ) -> (PlantOutcome, Vec<SinkReport>) {
        std::thread::scope(|scope| {
            let (plant_tx, input) = channel(self.queue_blocks);
            let plant = scope.spawn(move || run_plant(job, plant_tx));
            let (sink_outputs, sink_inputs): (Vec<_>, Vec<_>) =
                sinks.iter().map(|_| channel(self.queue_blocks)).unzip();
            scope.spawn(move || {
                guarded("chain", self.stop, self.errors, (), || {
                    run_chain(stages, input, sink_outputs, self.status)
                })
            });
            let handles: Vec<_> = sinks
                .into_iter()
                .zip(sink_inputs)
                .map(|((name, sink), rx)| {
                    scope.spawn(move || {
                        guarded(name, self.stop, self.errors, SinkReport::default(), || {
                            run_sink(name, sink, rx, self.stop, self.errors)
                        })
                    })
                })
                .collect();
            while !plant.is_finished() {
                self.console.show(&self.status.snapshot());
                std::thread::sleep(Duration::from_millis(100));
            }
            let plant = plant.join();
            let reports = handles.into_iter().filter_map(|h| h.join().ok()).collect();
            (plant, reports)
        })
    }
}

type NamedSink = (&'static str, Box<dyn Sink>);

/// The parts of `plan`'s rig that carry out commands.
fn command_targets(plan: &Plan) -> Vec<Target> {
    let mut targets = vec![Target::Plant];
    for stage in [AMPLIFIER_V, FILTER_V] {
        if plan.chain.stages.producing(stage).is_some() {
            targets.push(Target::Stage(stage));
        }
    }
    if plan.analyser.is_some() {
        targets.extend([Target::Analyser, Target::Displays]);
    }
    if plan.chain.scope.is_some() {
        targets.push(Target::Scope);
    }
    if plan.record.is_some() {
        targets.push(Target::Recorder);
    }
    targets
}

fn build_sinks(
    plan: &Plan,
    dir: &Path,
    names: &SignalNames,
    status: &SharedStatus,
    live: bool,
) -> anyhow::Result<Vec<NamedSink>> {
    let measures = plan.measurements();
    let index = |n: &str| {
        names
            .index(n)
            .ok_or_else(|| anyhow::anyhow!("internal wiring: no `{n}`"))
    };
    let mut sinks: Vec<NamedSink> = vec![(
        "monitor",
        Box::new(MonitorSink::create(
            dir,
            plan,
            names,
            plan.measures.clone(),
            status.clone(),
        )?),
    )];
    let mut recorder = RecorderSink::create(dir, plan, names)?;
    if live {
        recorder.go_live(status.clone());
    }
    sinks.push(("recorder", Box::new(recorder)));
    if let Some(analyser) = &plan.analyser {
        let mut sink = AnalyserSink::create(
            dir,
            plan,
            analyser.clone(),
            index(&analyser.input)?,
            measures.clone(),
            status.clone(),
        )?;
        if live {
            sink.go_live();
        }
        sinks.push(("analyser", Box::new(sink)));
    }
    if live {
        let tap = TapSink::new(names.names().to_vec(), status.clone());
        sinks.push(("tap", Box::new(tap)));
    }
    if let Some(scope) = &plan.chain.scope {
        let mut sink = ScopeSink::create(dir, plan, scope, index(&scope.input)?, measures)?;
        // The panel's scope runs in every run, so that a session's saved traces come
        // out alike when it is replayed.
        sink.go_live(status.clone())?;
        sinks.push(("scope", Box::new(sink)));
    }
    Ok(sinks)
}
