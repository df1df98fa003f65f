//! `testrig simulate`: the plant alone, unpaced, at a set speed and load.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use anyhow::Context;
use rig::{COLUMN_NAMES, Flank, Impact, SignalBlock, SteadySummary};
use serde::Serialize;

use crate::cli::SimulateArgs;
use testrig::plots::{RasterImpact, write_impact_raster};
use testrig::steady_point::{FLAG_NAMES, PointRun, PointSpec, run_point};

/// The JSON summary of one run.
#[derive(Serialize)]
struct Report<'a> {
    preset: &'a str,
    rpm: f64,
    load_nm: f64,
    settle_s: f64,
    simulated_s: f64,
    wall_s: f64,
    realtime_factor: f64,
    #[serde(flatten)]
    summary: SteadySummary,
}

pub fn run(args: &SimulateArgs) -> anyhow::Result<()> {
    let spec = PointSpec {
        preset: &args.rig.preset,
        overrides: &args.rig.overrides,
        rpm: args.rpm,
        load_nm: args.load,
        settle_s: args.settle,
        duration_s: args.duration,
        rate_hz: args.rate,
    };
    let mut writer = match &args.out {
        Some(dir) => Some(SignalWriter::create(dir)?),
        None => None,
    };
    let PointRun {
        plant,
        summary,
        simulated_s,
        wall_s,
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
        simulated_s,
        wall_s,
        realtime_factor: simulated_s / wall_s.max(1e-9),
        summary,
    };
    if let (Some(dir), Some(w)) = (&args.out, writer) {
        w.finish()?;
        write_impacts(&dir.join("impacts.csv"), plant.impacts())?;
        write_raster(dir, &report, plant.impacts(), plant.params().teeth)?;
        let path = dir.join("summary.json");
        std::fs::write(&path, serde_json::to_string_pretty(&report)?)
            .with_context(|| format!("writing {}", path.display()))?;
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
        "{} at {} rev/min, {} N m: {:.1} s simulated in {:.3} s ({:.0}x real time)",
        r.preset, r.rpm, r.load_nm, r.simulated_s, r.wall_s, r.realtime_factor
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
}

/// Streams the true signals to `signals.csv`, under a temporary name until finished.
struct SignalWriter {
    csv: csv::Writer<BufWriter<File>>,
    partial: PathBuf,
    path: PathBuf,
}

impl SignalWriter {
    fn create(dir: &Path) -> anyhow::Result<Self> {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("--out {}: cannot create the folder", dir.display()))?;
        let path = dir.join("signals.csv");
        let partial = dir.join("signals.csv.partial");
        let file = File::create(&partial).with_context(|| {
            format!(
                "--out {}: cannot write {}",
                dir.display(),
                partial.display()
            )
        })?;
        let mut csv = csv::Writer::from_writer(BufWriter::new(file));
        csv.write_record(COLUMN_NAMES)?;
        Ok(Self { csv, partial, path })
    }

    fn write(&mut self, block: &SignalBlock) -> anyhow::Result<()> {
        for i in 0..block.len() {
            self.csv
                .serialize(block.row(i))
                .context("writing signals.csv")?;
        }
        Ok(())
    }

    fn finish(mut self) -> anyhow::Result<()> {
        self.csv.flush().context("writing signals.csv")?;
        std::fs::rename(&self.partial, &self.path).context("closing signals.csv")?;
        Ok(())
    }
}

/// The impact raster of the measuring window (at most its first [`RASTER_REVOLUTIONS`]
/// revolutions, so that the pattern stays legible): `impact-raster.png` and `.svg`.
fn write_raster(dir: &Path, report: &Report, impacts: &[Impact], teeth: u32) -> anyhow::Result<()> {
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
    let title = format!(
        "impacts by tooth: {} rev/min, {} N m, {}",
        report.rpm, report.load_nm, report.summary.motion.motion
    );
    write_impact_raster(&dir.join("impact-raster"), &title, teeth, &points)?;
    Ok(())
}

/// Revolutions the impact raster shows.
const RASTER_REVOLUTIONS: f64 = 40.0;

fn write_impacts(path: &Path, impacts: &[Impact]) -> anyhow::Result<()> {
    // The header is written here, so that a window without impacts still has one;
    // `serialize` would write another before the first row.
    let mut csv = csv::WriterBuilder::new()
        .has_headers(false)
        .from_path(path)
        .with_context(|| format!("writing {}", path.display()))?;
    csv.write_record(["time_s", "flank", "tooth", "closing_speed_rad_s"])?;
    for i in impacts {
        csv.serialize(i)?;
    }
    csv.flush()?;
    Ok(())
}
