//! `testrig simulate`: a rig alone, unpaced, at a set speed and load: a rig file's
//! (`--rig FILE`) or a preset's (`--preset NAME`, the short name of its rig file), the
//! same run, summary, columns and refusals for either.

use std::path::{Path, PathBuf};

use rig::{NetworkImpact, column_names, columns};
use serde::Serialize;

use super::signal_writer::SignalWriter;
use crate::cli::SimulateArgs;
use testrig::chain::watched_gear;
use testrig::plots::{AveragePlot, RasterImpact, write_impact_raster, write_synchronous_average};
use testrig::recording::{ImpactLog, PartialFile};
use testrig::runtime::write_command_manifest;
use testrig::scenario::command_rig;
use testrig::steady_point::{
    RigPointRun, RigPointSpec, RigPointSummary, judged_shaft, run_rig_point,
};
use testrig::vocabulary::FLAG_NAMES;

/// The JSON summary of one run.
#[derive(Serialize)]
struct Report<'a> {
    rig: &'a str,
    /// The preset named (`--preset`), if the rig is one.
    #[serde(skip_serializing_if = "Option::is_none")]
    preset: Option<&'a str>,
    /// The rig file read (`--rig`), if one was.
    #[serde(skip_serializing_if = "Option::is_none")]
    rig_file: Option<String>,
    rpm: f64,
    load_nm: f64,
    settle_s: f64,
    /// How the point was reached.
    approach: rig::Approach,
    simulated_s: f64,
    wall_s: f64,
    realtime_factor: f64,
    #[serde(flatten)]
    summary: RigPointSummary,
}

pub fn run(args: &SimulateArgs) -> anyhow::Result<()> {
    let overrides = &args.rig.overrides;
    let rig = command_rig(args.rig_file.as_deref(), &args.rig.preset, overrides)?;
    let rig_file = args.rig_file.as_ref().map(|p| p.display().to_string());
    let preset = args.rig_file.is_none().then_some(args.rig.preset.as_str());
    let spec = RigPointSpec {
        rig: &rig,
        rpm: args.rpm,
        load_nm: args.load,
        settle_s: args.settle,
        duration_s: args.duration,
        rate_hz: args.rate,
        approach: args.approach.to_rig(args.rpm, args.ramp_rate)?,
    };
    let mut writer = match &args.out {
        Some(dir) => Some(SignalWriter::create(dir, args.replace, column_names(&rig))?),
        None => None,
    };
    let RigPointRun {
        plant,
        impacts,
        summary,
        simulated_s,
        wall_s,
        average_nm,
    } = {
        // One row's buffer for the whole run, not one a sample.
        let mut row = Vec::new();
        run_rig_point(
            &spec,
            FLAG_NAMES,
            || Ok(()),
            |block| match writer.as_mut() {
                Some(w) => {
                    let columns = columns(&rig, block);
                    (0..block.len()).try_for_each(|i| {
                        row.clear();
                        row.extend(columns.iter().map(|c| c[i]));
                        w.write_row(&row)
                    })
                }
                None => Ok(()),
            },
        )?
    };
    let report = Report {
        rig: &rig.name,
        preset,
        rig_file,
        rpm: args.rpm,
        load_nm: args.load,
        settle_s: args.settle,
        approach: spec.approach,
        simulated_s,
        wall_s,
        realtime_factor: simulated_s / wall_s.max(1e-9),
        summary,
    };
    if let (Some(dir), Some(w)) = (&args.out, writer) {
        let mut files = vec![
            w.finish()?,
            impact_log(dir, &rig, &impacts)?,
            PartialFile::write_whole(
                &dir.join("summary.json"),
                serde_json::to_string_pretty(&report)?,
            )?,
        ];
        if let Some(average) = &average_nm {
            files.extend(write_average(dir, &rig, average)?);
        }
        files.extend(write_raster(
            dir,
            &report,
            &rig,
            plant.speed_ratios(),
            &impacts,
        )?);
        let details = serde_json::json!({
            "rig_file": report.rig_file, "preset": report.preset, "set": args.rig.overrides, "rpm": args.rpm,
            "load_nm": args.load, "approach": spec.approach, "settle_s": args.settle, "duration_s": args.duration,
            "rate_hz": args.rate,
        });
        write_command_manifest(dir, "simulate", &files, details)?;
        eprintln!(
            "testrig: {} files and manifest.json in {}; signals.csv holds {} columns at {} Hz",
            files.len(),
            dir.display(),
            column_names(&rig).len(),
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
        r.rig, r.rpm, r.load_nm, r.approach, r.simulated_s, r.wall_s, r.realtime_factor
    );
    println!(
        "measured {:.1} s after {:.1} s settling, {} revolutions of the motor's body; motor {:.4} N m",
        s.steady.measured_s, r.settle_s, s.steady.revolutions, s.motor_torque_mean_nm
    );
    println!(
        "motion of shaft {}: {}",
        s.judged_shaft, s.steady.motion.motion
    );
    for b in &s.bodies {
        println!("  body {:<20} {:>10.2} rev/min", b.name, b.speed_mean_rpm);
    }
    for t in &s.shafts {
        println!(
            "  shaft {:<19} mean {:>10.4} N m, ac rms {:.4} N m",
            t.name, t.torque_mean_nm, t.torque_ac_rms_nm
        );
    }
    for m in &s.meshes {
        println!(
            "  mesh {:<20} {} impacts, apart {:.1} % of the time",
            m.name,
            m.impacts,
            100.0 * m.apart_fraction
        );
    }
    if s.steady.motion.motion == rig::judge::Motion::NoVibration {
        println!(
            "gear condition   not shown: shaft {}'s torque does not vibrate (the indicators' ratios would be of rounding; --json keeps them)",
            s.judged_shaft
        );
    } else if let Some(c) = &s.condition {
        let n = |key: &str| c[key].as_f64().unwrap_or(f64::NAN);
        println!(
            "gear condition   shaft {} averaged over {} revolutions of {}:\n  FM0 {:.3}, FM4 {:.3}, NA4 {:.3}, sideband level {:.4}, residual RMS {:.3e} N m",
            s.judged_shaft,
            c["revolutions_averaged"],
            c["gear"].as_str().unwrap_or(""),
            n("fm0"),
            n("fm4"),
            n("na4"),
            n("sideband_level"),
            n("residual_rms_nm")
        );
    }
}

/// `synchronous-average.png` and `.svg`: the watched gear's averaged revolution of the
/// judged shaft's torque, its faulted tooth marked.
fn write_average(
    dir: &Path,
    rig: &rig::RigTopology,
    average: &[f64],
) -> anyhow::Result<Vec<PathBuf>> {
    let Some((gear, teeth)) = watched_gear(rig) else {
        return Ok(Vec::new());
    };
    let marked_tooth = rig
        .meshes
        .iter()
        .flat_map(|m| m.faults.iter().map(move |f| (m, f)))
        .find(|(m, f)| {
            let body = match f.gear {
                rig::FaultedGear::Driver => m.gears[0],
                rig::FaultedGear::Driven => m.gears[1],
            };
            body == gear
        })
        .map(|(_, f)| f.tooth);
    let shaft = &rig.shafts[judged_shaft(rig)].name;
    let title = format!(
        "{}: shaft {shaft} averaged over the revolutions of {}",
        rig.name, rig.bodies[gear].name
    );
    let plot = AveragePlot {
        title: &title,
        average_nm: average,
        teeth,
        marked_tooth,
    };
    write_synchronous_average(&dir.join("synchronous-average"), &plot)
}

/// `impacts.csv` of the window's `impacts`.
fn impact_log(
    dir: &Path,
    rig: &rig::RigTopology,
    impacts: &[NetworkImpact],
) -> anyhow::Result<PathBuf> {
    let mut log = ImpactLog::of_meshes(&dir.join("impacts.csv"), rig)?;
    log.write(impacts)?;
    log.finish()
}

/// The impact raster of the first mesh over the measuring window, by the driving gear's
/// tooth and revolution (at most its first [`RASTER_REVOLUTIONS`] revolutions, so that
/// the pattern stays legible; the title says how many of how many): `impact-raster.png`
/// and `.svg`. None for a rig without a mesh.
fn write_raster(
    dir: &Path,
    report: &Report,
    rig: &rig::RigTopology,
    speed_ratios: &[f64],
    impacts: &[NetworkImpact],
) -> anyhow::Result<Vec<PathBuf>> {
    let Some(mesh) = rig.meshes.first() else {
        return Ok(Vec::new());
    };
    let driver_hz = report.rpm / 60.0 * speed_ratios[mesh.gears[0]].abs();
    let start_s = report.settle_s + report.approach.lead_in_s();
    let points: Vec<RasterImpact> = impacts
        .iter()
        .filter(|i| i.mesh == 0)
        .map(|i| RasterImpact {
            revolution: (i.time_s - start_s) * driver_hz,
            tooth: i.teeth[0],
            drive_flank: i.flank == rig::Contact::Drive,
        })
        .filter(|p| (0.0..RASTER_REVOLUTIONS).contains(&p.revolution))
        .collect();
    let revolutions = (report.summary.steady.measured_s * driver_hz).floor();
    let shown = if revolutions > RASTER_REVOLUTIONS {
        format!("first {RASTER_REVOLUTIONS} of {revolutions} revolutions")
    } else {
        format!("{revolutions} revolutions")
    };
    let title = format!(
        "mesh {} impacts by tooth of {}, {shown}: {} rev/min, {} N m, {}",
        mesh.name,
        rig.bodies[mesh.gears[0]].name,
        report.rpm,
        report.load_nm,
        report.summary.steady.motion.motion
    );
    write_impact_raster(&dir.join("impact-raster"), &title, mesh.teeth[0], &points)
}

/// Revolutions the impact raster shows.
const RASTER_REVOLUTIONS: f64 = 40.0;
