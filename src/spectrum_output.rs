//! Writing a displayed spectrum: `spectrum.csv` with its metadata and `spectrum.png` as the
//! HP 5451C plotted it (log amplitude, linear frequency).

use std::io::Write;
use std::path::Path;

use anyhow::Context;
use instruments::Line;
use plotters::prelude::*;

/// Metadata lines written as `# key: value` before the header.
pub type Metadata = Vec<(&'static str, String)>;

/// Writes `path` with metadata, a header `frequency_hz,power,alias_of_hz` and one row per line.
pub fn write_csv(
    path: &Path,
    metadata: &Metadata,
    lines: &[Line],
    alias_of: &[Option<f64>],
) -> anyhow::Result<()> {
    let mut file = std::io::BufWriter::new(
        std::fs::File::create(path).with_context(|| format!("cannot write {}", path.display()))?,
    );
    for (key, value) in metadata {
        writeln!(file, "# {key}: {value}")?;
    }
    let mut csv = csv::Writer::from_writer(file);
    csv.write_record(["frequency_hz", "power", "alias_of_hz"])?;
    for (line, alias) in lines.iter().zip(alias_of) {
        let alias = alias.map_or(String::new(), |f| format!("{f}"));
        csv.write_record([
            format!("{}", line.frequency_hz),
            format!("{:e}", line.value),
            alias,
        ])?;
    }
    csv.flush()
        .with_context(|| format!("writing {}", path.display()))?;
    Ok(())
}

const FONT: &[u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");

/// Draws the spectrum in dB (10·log10 of the power) against linear frequency, aliases in red.
pub fn write_png(
    path: &Path,
    title: &str,
    unit: &str,
    lines: &[Line],
    alias_of: &[Option<f64>],
) -> anyhow::Result<()> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
        .map_err(|_| anyhow::anyhow!("the embedded font cannot be read"))?;
    let db: Vec<(f64, f64)> = lines
        .iter()
        .map(|l| (l.frequency_hz, 10.0 * l.value.max(1e-30).log10()))
        .collect();
    let top = db
        .iter()
        .map(|p| p.1)
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil();
    let bottom = (top - 100.0).max(db.iter().map(|p| p.1).fold(f64::INFINITY, f64::min).floor());
    let fmax = lines.last().map_or(1.0, |l| l.frequency_hz.max(1.0));
    let root = BitMapBackend::new(path, (1024, 640)).into_drawing_area();
    root.fill(&WHITE).map_err(draw_error)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..fmax, bottom..top + 3.0)
        .map_err(draw_error)?;
    chart
        .configure_mesh()
        .x_desc("frequency (Hz)")
        .y_desc(format!("power (dB re 1 {unit}² rms)"))
        .label_style(("sans-serif", 14))
        .draw()
        .map_err(draw_error)?;
    chart
        .draw_series(LineSeries::new(
            db.iter().map(|&(f, v)| (f, v.max(bottom))),
            &BLUE,
        ))
        .map_err(draw_error)?;
    let aliases = db
        .iter()
        .zip(alias_of)
        .filter(|(_, a)| a.is_some())
        .map(|(&(f, v), _)| Circle::new((f, v.max(bottom)), 3, RED.filled()));
    chart.draw_series(aliases).map_err(draw_error)?;
    root.present().map_err(draw_error)?;
    Ok(())
}

fn draw_error<E: std::fmt::Debug>(error: E) -> anyhow::Error {
    anyhow::anyhow!("drawing the spectrum: {error:?}")
}
