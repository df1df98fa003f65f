//! The RMS survey as the thesis plots it: the meter's RMS reading against load, one curve
//! per speed, beside the static line (the strain the load alone would give).

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, legend, legend_share, mesh, png_and_svg};

/// One reading of the survey.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurveyPoint {
    /// Speed set point (rev/min).
    pub speed_rpm: f64,
    /// Load (N m).
    pub load_nm: f64,
    /// Meter reading as strain (µε).
    pub rms_microstrain: f64,
}

/// Writes `base.png` and `base.svg`; `static_microstrain_per_nm` draws the static line.
pub fn write_survey_plots(
    base: &Path,
    title: &str,
    points: &[SurveyPoint],
    static_microstrain_per_nm: f64,
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, points, static_microstrain_per_nm),
        |root| draw(root, title, points, static_microstrain_per_nm),
    )
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    points: &[SurveyPoint],
    per_nm: f64,
) -> anyhow::Result<()> {
    let err = draw_error("RMS survey");
    let loads = points.iter().map(|p| p.load_nm);
    let (low, high) = (
        loads.clone().fold(0.0, f64::min),
        loads.fold(0.0, f64::max).max(1e-3),
    );
    let mut speeds: Vec<f64> = points.iter().map(|p| p.speed_rpm).collect();
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    // Headroom above the highest curve for the legend (one line per speed and the static).
    let top = points
        .iter()
        .map(|p| p.rms_microstrain)
        .chain([high * per_nm, low.abs() * per_nm])
        .fold(1e-3, f64::max)
        * 1.05
        / (1.0 - legend_share(speeds.len() + 1));
    let mut chart = axes(&root, title, low..high, 0.0..top)?;
    mesh(&mut chart, ("load (N m)", "RMS strain (µε)"), |_| {})?;
    chart
        .draw_series(LineSeries::new(
            [(low, low.abs() * per_nm), (0.0, 0.0), (high, high * per_nm)],
            BLACK.stroke_width(2),
        ))
        .map_err(&err)?
        .label("static")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLACK.stroke_width(2)));
    for (i, &speed) in speeds.iter().enumerate() {
        let colour = Palette99::pick(i).to_rgba();
        let curve: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.speed_rpm == speed)
            .map(|p| (p.load_nm, p.rms_microstrain))
            .collect();
        chart
            .draw_series(LineSeries::new(
                curve.iter().copied(),
                colour.stroke_width(2),
            ))
            .map_err(&err)?
            .label(format!("{speed} rev/min"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], colour.stroke_width(2)));
        chart
            .draw_series(curve.iter().map(|&p| Circle::new(p, 3, colour.filled())))
            .map_err(&err)?;
    }
    legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
    root.present().map_err(&err)?;
    Ok(())
}
