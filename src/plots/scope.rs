//! The storage scope's stored sweep, drawn on its graticule: ten divisions across, eight up.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, mesh, png_and_svg};

/// The scope's scales: horizontal (s per division) and vertical (V per division).
#[derive(Clone, Copy, Debug)]
pub struct ScopeScales {
    /// Seconds per division (ten across).
    pub seconds_per_div: f64,
    /// Volts per division (eight up, ±4 about the centre).
    pub volts_per_div: f64,
}

/// Writes `base.png` and `base.svg` of a trace of (time from trigger in s, divisions)
/// in volts against milliseconds, one grid line per division, the scales in the title.
pub fn write_scope_plots(
    base: &Path,
    title: &str,
    trace: &[(f64, f64)],
    scales: ScopeScales,
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, trace, scales),
        |root| draw(root, title, trace, scales),
    )
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    trace: &[(f64, f64)],
    scales: ScopeScales,
) -> anyhow::Result<()> {
    let err = draw_error("scope trace");
    let width_ms = 10.0 * scales.seconds_per_div * 1e3;
    let v = scales.volts_per_div;
    let mut chart = axes(&root, title, 0.0..width_ms, -4.0 * v..4.0 * v)?;
    mesh(&mut chart, ("time from trigger (ms)", "volts (V)"), |m| {
        m.x_labels(11).y_labels(9);
    })?;
    chart
        .draw_series(LineSeries::new(
            trace.iter().map(|&(t, d)| (t * 1e3, d * v)),
            &BLUE,
        ))
        .map_err(&err)?;
    root.present().map_err(&err)?;
    Ok(())
}
