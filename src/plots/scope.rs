//! The storage scope's stored sweep, drawn on its graticule: ten divisions across, eight up.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::canvas::{axes_with_right_area, draw_error, mesh, png_and_svg};
use crate::vocabulary::signal_names::MICROSTRAIN_UNIT;

/// The scope's scales: horizontal (s per division) and vertical (the signal's unit per
/// division), and the strain a unit of the signal stands for.
#[derive(Clone, Copy, Debug)]
pub struct ScopeScales {
    /// Seconds per division (ten across).
    pub seconds_per_div: f64,
    /// The signal's unit per division (eight up, ±4 about the centre).
    pub units_per_div: f64,
    /// The signal's unit (V for the chain's voltages).
    pub unit: &'static str,
    /// Strain (µε) per unit of the signal, where a static calibration gives it: drawn
    /// as a second vertical axis.
    pub microstrain_per_unit: Option<f64>,
}

/// Writes `base.png` and `base.svg` of a trace of (time from trigger in s, divisions)
/// in the signal's unit against milliseconds, one grid line per division, the scales in
/// the title; a second axis in µε where the signal has a strain calibration.
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
    let v = scales.units_per_div;
    let strain_axis = scales
        .microstrain_per_unit
        .filter(|_| scales.unit != MICROSTRAIN_UNIT);
    let right_px = if strain_axis.is_some() { 70 } else { 0 };
    let chart = axes_with_right_area(&root, title, 0.0..width_ms, -4.0 * v..4.0 * v, right_px)?;
    let mut chart = match strain_axis {
        Some(k) => chart.set_secondary_coord(0.0..width_ms, -4.0 * v * k..4.0 * v * k),
        // The same coordinates on the right, where no axis is drawn.
        None => chart.set_secondary_coord(0.0..width_ms, -4.0 * v..4.0 * v),
    };
    let y_desc = axis_label(scales.unit);
    mesh(&mut chart, ("time from trigger (ms)", &y_desc), |m| {
        m.x_labels(11).y_labels(9);
    })?;
    if strain_axis.is_some() {
        chart
            .configure_secondary_axes()
            .y_labels(9)
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(&err)?;
        // The right axis's name reads upwards, as the left one does (plotters would turn
        // it to read downwards).
        let (width_px, _) = root.dim_in_pixel();
        let (top_px, bottom_px) = (
            chart.backend_coord(&(0.0, 4.0 * v)).1,
            chart.backend_coord(&(0.0, -4.0 * v)).1,
        );
        let style = ("sans-serif", 14)
            .into_font()
            .transform(FontTransform::Rotate270)
            .into_text_style(&root)
            .pos(Pos::new(HPos::Center, VPos::Top));
        root.draw(&Text::new(
            axis_label(MICROSTRAIN_UNIT),
            (width_px as i32 - 22, (top_px + bottom_px) / 2),
            style,
        ))
        .map_err(&err)?;
    }
    chart
        .draw_series(LineSeries::new(
            trace.iter().map(|&(t, d)| (t * 1e3, d * v)),
            &BLUE,
        ))
        .map_err(&err)?;
    root.present().map_err(&err)?;
    Ok(())
}

/// The vertical axis's label for a signal in `unit`.
fn axis_label(unit: &str) -> String {
    match unit {
        "V" => "volts (V)".to_string(),
        MICROSTRAIN_UNIT => "strain (µε)".to_string(),
        other => format!("signal ({other})"),
    }
}
