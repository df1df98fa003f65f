//! The commands and their arguments.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};
use instruments::Window;
use testrig::runtime::Pace;
use testrig::sweep::Shard;
use testrig::vocabulary::SamplingChoice;

use super::values::{self, Approach, FilterArg, TrainingHalf};

/// A virtual test rig: F. Basmaji's 1983 geared rig with backlash.
#[derive(Debug, Parser)]
#[command(name = "testrig", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: CliCommand,
}

/// The commands.
#[derive(Debug, Subcommand)]
pub enum CliCommand {
    /// Natural frequencies (Hz) and mode shapes of the rig (thesis App. C).
    Modes(ModesArgs),
    /// Run the plant alone, unpaced, at a set speed and load.
    Simulate(SimulateArgs),
    /// Every parameter with its value, unit and meaning.
    Params(ParamsArgs),
    /// Any WAV file as the analogue signal through filter, ADC and Fourier analyser.
    Analyse(AnalyseArgs),
    /// Rehearse an experiment: a scenario's rig, chain and recordings, paced or unpaced.
    Run(RunArgs),
    /// A grid of cases (speed, load, backlash, any parameter) through the chain, in parallel.
    Sweep(SweepArgs),
    /// Join the outputs of sweep shards into one table and its plots.
    Merge(MergeArgs),
    /// Search free parameters for the rig that best reproduces target findings (CMA-ES).
    Calibrate(CalibrateArgs),
    /// Operate the rig live from a front panel in the browser (and from scripts, docs/api.md).
    Panel(PanelArgs),
    /// Export a rig file's plant as an FMI 3.0 co-simulation FMU (docs/fmu.md).
    Fmu(FmuArgs),
}

/// `testrig fmu`.
#[derive(Debug, Args)]
#[command(group(clap::ArgGroup::new("plant").required(true).args(["rig_file", "preset"])))]
pub struct FmuArgs {
    /// The rig file (docs/rig-files.md) whose plant the FMU holds.
    #[arg(long = "rig", value_name = "FILE")]
    pub rig_file: Option<PathBuf>,
    /// A preset (basmaji-1983), the short name of its rig file, instead of --rig.
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
    /// Set a number of the rig by its path (`mesh.gears.backlash_mm=0.5`; on a preset
    /// also by the thesis's name, `testrig params`): the parameter's start value in the
    /// FMU.
    #[arg(long = "set", value_name = "PATH=VALUE")]
    pub overrides: Vec<String>,
    /// The FMU to write (`.fmu`).
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,
}

/// `testrig panel`.
#[derive(Debug, Args)]
pub struct PanelArgs {
    /// The scenario (TOML); left out: the bundled scenarios/panel.toml.
    pub scenario: Option<PathBuf>,
    /// Address to serve the panel on; anything but loopback is reachable by others.
    #[arg(long, default_value = "127.0.0.1:8080")]
    pub listen: std::net::SocketAddr,
    /// Also serve SCPI for lab scripts on this address (VISA's
    /// `TCPIP::host::port::SOCKET`, newline-terminated; docs/scpi.md), e.g. 127.0.0.1:5025.
    #[arg(long, value_name = "ADDR:PORT")]
    pub scpi: Option<std::net::SocketAddr>,
    /// 1 for real time, or a factor.
    #[arg(long, default_value = "1", value_parser = values::pace)]
    pub pace: Pace,
    /// Change one scenario key (repeatable), as for `run`.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub overrides: Vec<String>,
    /// Output folder: recordings, spectra, scope traces, manifest.json and session.toml.
    #[arg(long, default_value = "out/panel")]
    pub out: PathBuf,
    /// Remove the files of another scenario's run from the output folder (only those its
    /// manifest or journal lists); without it such a folder is refused. A rerun of the
    /// same scenario always replaces its own files.
    #[arg(long)]
    pub replace: bool,
}

/// `testrig sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// The sweep file (TOML).
    pub sweep: PathBuf,
    /// Worker threads (default: one per core).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Run every N-th case from K (K/N, from 0); default from SLURM_ARRAY_TASK_ID and
    /// SLURM_ARRAY_TASK_COUNT, else all.
    #[arg(long, value_parser = values::shard)]
    pub shard: Option<Shard>,
    /// Skip the cases already finished in the output folder.
    #[arg(long)]
    pub resume: bool,
    /// Change one key of the sweep file (repeatable), e.g. --set case.measure_s=10.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub overrides: Vec<String>,
    /// Output folder.
    #[arg(long)]
    pub out: PathBuf,
}

/// `testrig calibrate`.
#[derive(Debug, Args)]
pub struct CalibrateArgs {
    /// The calibration file (TOML): targets, free parameters, search.
    pub calibration: PathBuf,
    /// Worker threads (default: one per core).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Evaluations in all, instead of the file's `search.budget`.
    #[arg(long)]
    pub budget: Option<usize>,
    /// Continue the search logged in the output folder (its evaluations are not run again).
    #[arg(long)]
    pub resume: bool,
    /// Run independent search stream K of N (K/N, from 0), each with its own seed, log and
    /// share of the budget; default from SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT.
    /// The report and preset come from every log in the output folder.
    #[arg(long, value_parser = values::shard)]
    pub shard: Option<Shard>,
    /// Search on the target points at even (or odd) positions only and score the best on
    /// the others too (cross-validation).
    #[arg(long, value_enum)]
    pub train_half: Option<TrainingHalf>,
    /// Change one key of the calibration file (repeatable), e.g. --set search.budget=20.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub overrides: Vec<String>,
    /// Output folder.
    #[arg(long)]
    pub out: PathBuf,
}

/// `testrig merge`.
#[derive(Debug, Args)]
pub struct MergeArgs {
    /// Output folders of the shards.
    #[arg(required = true)]
    pub dirs: Vec<PathBuf>,
    /// Folder for the merged table, cases and plots.
    #[arg(long)]
    pub out: PathBuf,
    /// Merge even if cases of the grid are in none of the folders (they are listed);
    /// without it such a merge is refused.
    #[arg(long)]
    pub partial: bool,
}

/// `testrig run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    /// The scenario file (TOML; see scenarios/README.md).
    pub scenario: PathBuf,
    /// 1 for real time, a factor for that many times faster, or max for unpaced.
    #[arg(long, default_value = "1", value_parser = values::pace)]
    pub pace: Pace,
    /// Simulated length (s), instead of the scenario's.
    #[arg(long)]
    pub duration: Option<f64>,
    /// Change one scenario key (repeatable), e.g. --set schedule.speed_rpm=1500 or
    /// --set rig.set.teeth=31.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub overrides: Vec<String>,
    /// Base seed of every random source, instead of the scenario's.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Fail instead of warning: refuse a run whose measurements cannot complete, and exit
    /// with status 3 when a run ends with warnings (its files and manifest are kept).
    #[arg(long)]
    pub strict: bool,
    /// Output folder.
    #[arg(long)]
    pub out: PathBuf,
    /// Remove the files of another scenario's run from the output folder (only those its
    /// manifest or journal lists); without it such a folder is refused. A rerun of the
    /// same scenario always replaces its own files.
    #[arg(long)]
    pub replace: bool,
}

/// Choice of parameter set.
#[derive(Debug, Args)]
pub struct RigArgs {
    /// Named parameter set, or the path of a preset file (`*.toml`, as `testrig calibrate`
    /// writes).
    #[arg(long, default_value = rig::DEFAULT_PRESET)]
    pub preset: String,
    /// Override one parameter (repeatable), e.g. --set teeth=31.
    #[arg(long = "set", value_name = "NAME=VALUE")]
    pub overrides: Vec<String>,
}

/// `testrig modes`.
#[derive(Debug, Args)]
pub struct ModesArgs {
    /// Parameters.
    #[command(flatten)]
    pub rig: RigArgs,
    /// A rig file (docs/rig-files.md) instead of a preset (a preset is its rig file: the
    /// same modes), --set by path (`mesh.stage1.backlash_mm=0.3`).
    #[arg(long = "rig", value_name = "FILE", conflicts_with = "preset")]
    pub rig_file: Option<PathBuf>,
    /// Print one JSON object instead of tables.
    #[arg(long)]
    pub json: bool,
}

/// `testrig simulate`.
#[derive(Debug, Args)]
pub struct SimulateArgs {
    /// Motor speed set point (rev/min).
    #[arg(long, allow_negative_numbers = true)]
    pub rpm: f64,
    /// Brake load (N m), ≥ 0: an eddy-current brake resists the rotation.
    #[arg(long, allow_negative_numbers = true)]
    pub load: f64,
    /// Parameters.
    #[command(flatten)]
    pub rig: RigArgs,
    /// A rig file (docs/rig-files.md) instead of a preset (a preset is the short name of
    /// its rig file: the same run): --rpm the motor's body, --load on the brake's, --set
    /// by path (`mesh.stage1.backlash_mm=0.3`, on a preset also the thesis's names);
    /// signals named after its bodies, shafts and meshes.
    #[arg(long = "rig", value_name = "FILE", conflicts_with = "preset")]
    pub rig_file: Option<PathBuf>,
    /// How the point is reached: `static` starts there in steady motion from the static
    /// load; `rest` from standstill, the knob at the set speed (--settle 0 records the
    /// run-up from t = 0, as an FMU of a rig starts); `up` the lab's slow run-up from 250
    /// rev/min (or half the speed); `down` its run-down from 2000 rev/min (or a fifth
    /// above). Where motions coexist, each approach may settle to a different one.
    #[arg(long, value_enum, default_value = "static")]
    pub approach: Approach,
    /// With `--approach up|down`: the ramp's rate (rev/min per second); --settle counts
    /// from its end.
    #[arg(long, default_value_t = rig::approach::LAB_RAMP_RPM_PER_S, allow_negative_numbers = true)]
    pub ramp_rate: f64,
    /// Measuring window after settling (s).
    #[arg(long, default_value_t = 10.0)]
    pub duration: f64,
    /// Simulated time before measuring, for transients to die (s). 60 s: at some of the
    /// thesis's operating points the rig wanders for 40–60 s before its motion settles
    /// (`docs/calibration.md`).
    #[arg(long, default_value_t = 60.0)]
    pub settle: f64,
    /// Output rate of the true signals (Hz).
    #[arg(long, default_value_t = 51_200.0)]
    pub rate: f64,
    /// Write signals.csv (every true signal at --rate: 16 columns, about 2.3 MB per
    /// simulated second at 51.2 kHz), impacts.csv, the impact raster, summary.json and
    /// manifest.json of the measuring window here.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Remove another command's or scenario's files from --out first (only those its
    /// manifest or journal lists); an earlier `simulate` there is replaced without it.
    #[arg(long)]
    pub replace: bool,
    /// Print one JSON object instead of a text summary.
    #[arg(long)]
    pub json: bool,
}

/// `testrig params`.
#[derive(Debug, Args)]
pub struct ParamsArgs {
    /// Parameters.
    #[command(flatten)]
    pub rig: RigArgs,
    /// A rig file (docs/rig-files.md) instead of a preset: every field by its path
    /// (`mesh.stage1.backlash_mm`), with unit, and what follows from them.
    #[arg(long = "rig", value_name = "FILE", conflicts_with = "overrides")]
    pub rig_file: Option<PathBuf>,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// `testrig analyse`.
#[derive(Debug, Args)]
pub struct AnalyseArgs {
    /// The WAV file (ours or a real recording), taken as the analogue signal at its own rate.
    pub file: PathBuf,
    /// Channel of the file: a number (0 = first) or a signal name from the sidecar
    /// (`FILE.json`, as `testrig run` writes beside recording.wav).
    #[arg(long, default_value = "0")]
    pub channel: String,
    /// Start of the analysed section (s from the start of the file).
    #[arg(long, default_value_t = 0.0)]
    pub start: f64,
    /// Length of the analysed section (s); default to the end of the file.
    #[arg(long)]
    pub length: Option<f64>,
    /// Top of the displayed band (Hz).
    #[arg(long, default_value_t = 2_000.0)]
    pub fmax: f64,
    /// Block size N (a power of two).
    #[arg(long, default_value_t = 1024)]
    pub block: usize,
    /// Window: uniform, hanning or flattop.
    #[arg(long, default_value = "hanning", value_parser = values::window)]
    pub window: Window,
    /// Spectra to average (linear: sum, then divide).
    #[arg(long, default_value_t = 10)]
    pub averages: usize,
    /// Overlap of successive blocks (%).
    #[arg(long, default_value_t = 0.0)]
    pub overlap: f64,
    /// Sampling convention: thesis (fs = 2 Fmax, N/2 lines) or 2.56 (fs = 2.56 Fmax).
    #[arg(long, default_value = "thesis", value_parser = values::sampling)]
    pub sampling: SamplingChoice,
    /// Anti-alias filter: none, butterworth:ORDER or bessel:ORDER.
    #[arg(long, default_value = "none", value_parser = values::filter)]
    pub filter: FilterArg,
    /// Filter cut-off (Hz); default Fmax.
    #[arg(long)]
    pub cutoff: Option<f64>,
    /// ADC resolution (bits).
    #[arg(long, default_value_t = 12)]
    pub bits: u32,
    /// ADC full scale ±range in the signal's unit. Default: the recording's full scale
    /// (from the sidecar, or ±1 for an integer WAV without one), else the 1-2-5 step
    /// above the section's peak.
    #[arg(long)]
    pub range: Option<f64>,
    /// Run an HP 5451C keyboard program (e.g. scenarios/appendix-e.prg) on the ADC samples
    /// instead of the analyser's averaging: each DISPLAY is written as display-NN.csv.
    #[arg(long)]
    pub program: Option<PathBuf>,
    /// The running speed of the recorded rig (rev/min): marks its orders on the plot.
    #[arg(long)]
    pub rpm: Option<f64>,
    /// Folder for spectrum.csv and spectrum.png.
    #[arg(long)]
    pub out: PathBuf,
    /// Remove another command's or scenario's files from --out first (only those its
    /// manifest or journal lists); an earlier `analyse` there is replaced without it.
    #[arg(long)]
    pub replace: bool,
}
