//! `testrig simulate`: the plant alone, unpaced, at a set speed and load.

use std::path::{Path, PathBuf};

use rig::{COLUMN_NAMES, Flank, Impact, SteadySummary};
use serde::Serialize;

use super::signal_writer::SignalWriter;
use crate::cli::SimulateArgs;
use testrig::plots::{RasterImpact, write_impact_raster};
use testrig::recording::{ImpactLog, PartialFile};
use testrig::runtime::write_command_manifest;
use testrig::steady_point::{PointRun, PointSpec, run_point};
use testrig::vocabulary::FLAG_NAMES;

/// The JSON summary of one run.
#[derive(Serialize)]
struct Report<'a> {
    preset: &'a str,
    rpm: f64,
    load_nm: f64,
    settle_s: f64,
    /// How the point was reached.
    approach: rig::Approach,
    simulated_s: f64,
    wall_s: f64,
    realtime_factor: f64,
    #[serde(flatten)]
    summary: SteadySummary,
    /// The condition indicators of the synchronous average (null under two revolutions).
    condition: serde_json::Value,
}

pub fn run(args: &SimulateArgs) -> anyhow::Result<()> {
    if let Some(path) = &args.rig_file {
        return super::simulate_rig::run(args, path);
    }
    let spec = PointSpec {
        preset: &args.rig.preset,
        overrides: &args.rig.overrides,
        rpm: args.rpm,
        load_nm: args.load,
        settle_s: args.settle,
        duration_s: args.duration,
        rate_hz: args.rate,
        approach: args.approach.to_rig(args.rpm, args.ramp_rate)?,
    };
    let mut writer = match &args.out {
        Some(dir) => Some(SignalWriter::create(dir, args.replace, COLUMN_NAMES)?),
        None => None,
    };
    let PointRun {
        plant,
        summary,
        simulated_s,
        wall_s,
        condition,
    } = run_point(
        &spec,
        FLAG_NAMES,
        || Ok(()),
        |block| match writer.as_mut() {
            Some(w) => w.write(block),
            None => Ok(()),
        },
    )?;
    let report = Report {
        preset: &args.rig.preset,
        rpm: args.rpm,
        load_nm: args.load,
        settle_s: args.settle,
        approach: spec.approach,
        simulated_s,
        wall_s,
        realtime_factor: simulated_s / wall_s.max(1e-9),
        summary,
        condition: condition.map_or(serde_json::Value::Null, |c| c.to_json()),
    };
    if let (Some(dir), Some(w)) = (&args.out, writer) {
        let mut files = vec![w.finish()?];
        let mut impacts = ImpactLog::of_gears(&dir.join("impacts.csv"))?;
        impacts.write_gears(plant.impacts())?;
        files.push(impacts.finish()?);
        files.extend(write_raster(
            dir,
            &report,
            plant.impacts(),
            plant.params().teeth,
        )?);
        let summary = serde_json::to_string_pretty(&report)?;
        files.push(PartialFile::write_whole(
            &dir.join("summary.json"),
            summary,
        )?);
        let details = serde_json::json!({
            "preset": args.rig.preset, "set": args.rig.overrides, "rpm": args.rpm,
            "load_nm": args.load, "approach": spec.approach, "settle_s": args.settle, "duration_s": args.duration,
            "rate_hz": args.rate,
        });
        write_command_manifest(dir, "simulate", &files, details)?;
        let bytes = std::fs::metadata(&files[0]).map_or(0, |m| m.len());
        eprintln!(
            "testrig: {} files and manifest.json in {}; signals.csv holds {:.1} MB ({} columns at {} Hz: --rate sets it)",
            files.len(),
            dir.display(),
            bytes as f64 / 1e6,
            COLUMN_NAMES.len(),
            args.rate
        );
    }
    if args.json {
        println!("{}", serde_json::to_string(&report)?);
    } else {
        print_text(&report);
    }
    Ok(())
}

fn print_text(r: &Report) {
    let s = &r.summary;
    println!(
        "{} at {} rev/min, {} N m, {}: {:.1} s simulated in {:.3} s ({:.0}x real time)",
        r.preset, r.rpm, r.load_nm, r.approach, r.simulated_s, r.wall_s, r.realtime_factor
    );
    println!(
        "measured {:.1} s after {:.1} s settling, {} revolutions",
        s.measured_s, r.settle_s, s.revolutions
    );
    println!("regime           {}", s.regime);
    let m = &s.motion;
    let number =
        |v: Option<f64>, unit: &str| v.map_or("–".to_string(), |v| format!("{v:.3}{unit}"));
    println!(
        "motion (judge)   {} (0-1 test for chaos K {})\n  samples every k revolutions scatter by k=1 {}, k=2 {} of the AC RMS\n  band power on the lines of period k=1 {}, k=2 {}\n  half order {} and third order {} over the floor",
        m.motion,
        number(m.chaos_k, ""),
        number(m.spread[0], ""),
        number(m.spread[1], ""),
        number(m.line_fraction[0], ""),
        number(m.line_fraction[1], ""),
        number(m.half_order_db, " dB"),
        number(m.third_order_db, " dB"),
    );
    println!(
        "impacts          {} ({:.3} per revolution)",
        s.impacts, s.impacts_per_rev
    );
    println!(
        "teeth separate   {} ({:.1} % of the time apart)",
        s.separates,
        100.0 * s.apart_fraction
    );
    println!(
        "output shaft     mean {:.4} N m, rms {:.4} N m, ac rms {:.4} N m",
        s.torque_mean_nm, s.torque_rms_nm, s.torque_ac_rms_nm
    );
    println!(
        "motor speed      {:+.2} rev/min from the set speed (mean over the window)",
        s.speed_offset_rpm
    );
    let c = &r.condition;
    if m.motion == rig::judge::Motion::NoVibration {
        println!(
            "gear condition   not shown: the output-shaft torque does not vibrate (the indicators' ratios would be of rounding; --json keeps them)"
        );
    } else if !c.is_null() {
        let n = |k: &str| c[k].as_f64().unwrap_or(f64::NAN);
        println!(
            "gear condition   synchronous average of the output-shaft torque over {} revolutions of the driven gear:\n  FM0 {:.3}, FM4 {:.3}, M6A {:.3}, M8A {:.3}, NA4 {:.3}, sideband level {:.3}, crest factor {:.3}, kurtosis {:.3}",
            c["revolutions_averaged"],
            n("fm0"),
            n("fm4"),
            n("m6a"),
            n("m8a"),
            n("na4"),
            n("sideband_level"),
            n("crest_factor"),
            n("kurtosis")
        );
    }
}

/// The impact raster of the measuring window (at most its first [`RASTER_REVOLUTIONS`]
/// revolutions, so that the pattern stays legible; the title says how many of how many):
/// `impact-raster.png` and `.svg`.
fn write_raster(
    dir: &Path,
    report: &Report,
    impacts: &[Impact],
    teeth: u32,
) -> anyhow::Result<Vec<PathBuf>> {
    let running_hz = report.rpm / 60.0;
    let start_s = report.settle_s;
    let points: Vec<RasterImpact> = impacts
        .iter()
        .map(|i| RasterImpact {
            revolution: (i.time_s - start_s) * running_hz,
            tooth: i.tooth,
            drive_flank: i.flank == Flank::Drive,
        })
        .filter(|p| (0.0..RASTER_REVOLUTIONS).contains(&p.revolution))
        .collect();
    let revolutions = report.summary.revolutions;
    let shown = if revolutions as f64 > RASTER_REVOLUTIONS {
        format!("first {RASTER_REVOLUTIONS} of {revolutions} revolutions")
    } else {
        format!("{revolutions} revolutions")
    };
    let title = format!(
        "impacts by tooth, {shown}: {} rev/min, {} N m, {}",
        report.rpm, report.load_nm, report.summary.motion.motion
    );
    write_impact_raster(&dir.join("impact-raster"), &title, teeth, &points)
}

/// Revolutions the impact raster shows.
const RASTER_REVOLUTIONS: f64 = 40.0;
