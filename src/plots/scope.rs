//! The storage scope's stored sweep, drawn on its graticule: ten divisions across, eight up.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{draw_error, png_and_svg};

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
    root.fill(&WHITE).map_err(&err)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..width_ms, -4.0..4.0)
        .map_err(&err)?;
    chart
        .configure_mesh()
        .x_labels(11)
        .y_labels(9)
        .x_desc("time from trigger (ms)")
        .y_desc("divisions")
        .label_style(("sans-serif", 14))
        .draw()
        .map_err(&err)?;
    chart
        .draw_series(LineSeries::new(
            trace.iter().map(|&(t, d)| (t * 1e3, d)),
            &BLUE,
        ))
        .map_err(&err)?;
    root.present().map_err(&err)?;
    Ok(())
}
