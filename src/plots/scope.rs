//! The storage scope's stored sweep, drawn on its graticule: ten divisions across, eight up.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, mesh, png_and_svg};

/// Writes `base.png` and `base.svg` of a trace of (time from trigger in s, divisions),
/// with the scales in the title.
pub fn write_scope_plots(
    base: &Path,
    title: &str,
    trace: &[(f64, f64)],
    seconds_per_div: f64,
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, trace, seconds_per_div),
        |root| draw(root, title, trace, seconds_per_div),
    )
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    trace: &[(f64, f64)],
    seconds_per_div: f64,
) -> anyhow::Result<()> {
    let err = draw_error("scope trace");
    let width_ms = 10.0 * seconds_per_div * 1e3;
    let mut chart = axes(&root, title, 0.0..width_ms, -4.0..4.0)?;
    mesh(&mut chart, ("time from trigger (ms)", "divisions"), |m| {
        m.x_labels(11).y_labels(9);
    })?;
    chart
        .draw_series(LineSeries::new(
            trace.iter().map(|&(t, d)| (t * 1e3, d)),
            &BLUE,
        ))
        .map_err(&err)?;
    root.present().map_err(&err)?;
    Ok(())
}
