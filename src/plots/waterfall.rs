//! A waterfall: the spectra of a speed sweep stacked by speed, each drawn in dB above its
//! own baseline at its speed.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, mesh, png_and_svg};

/// One spectrum of the waterfall.
#[derive(Clone, Debug, PartialEq)]
pub struct WaterfallTrace {
    /// Speed set point (rev/min).
    pub rpm: f64,
    /// (Hz, power) per line.
    pub lines: Vec<(f64, f64)>,
}

/// dB of range each trace spans vertically.
const RANGE_DB: f64 = 80.0;

/// Writes `base.png` and `base.svg`.
pub fn write_waterfall(
    base: &Path,
    title: &str,
    traces: &[WaterfallTrace],
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, traces),
        |root| draw(root, title, traces),
    )
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    traces: &[WaterfallTrace],
) -> anyhow::Result<()> {
    let err = draw_error("waterfall");
    let fmax = traces
        .iter()
        .flat_map(|t| t.lines.last().map(|l| l.0))
        .fold(1.0, f64::max);
    let (low, high) = traces
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), t| {
            (a.min(t.rpm), b.max(t.rpm))
        });
    let spacing = if traces.len() > 1 {
        (high - low) / (traces.len() - 1) as f64
    } else {
        100.0
    };
    let top_db = traces
        .iter()
        .flat_map(|t| t.lines.iter().map(|l| 10.0 * l.1.max(1e-30).log10()))
        .fold(f64::NEG_INFINITY, f64::max);
    let mut chart = axes(
        &root,
        title,
        0.0..fmax,
        (low - spacing * 0.2)..(high + 2.5 * spacing),
    )?;
    mesh(
        &mut chart,
        (
            "frequency (Hz)",
            &format!("speed (rev/min); each trace {RANGE_DB} dB tall"),
        ),
        |m| {
            m.disable_mesh();
        },
    )?;
    for t in traces {
        let scale = 2.5 * spacing / RANGE_DB;
        let points = t.lines.iter().map(|&(f, p)| {
            let db = (10.0 * p.max(1e-30).log10() - (top_db - RANGE_DB)).max(0.0);
            (f, t.rpm + db * scale)
        });
        chart
            .draw_series(LineSeries::new(points, BLUE.stroke_width(1)))
            .map_err(&err)?;
    }
    root.present().map_err(&err)?;
    Ok(())
}
