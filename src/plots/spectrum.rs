//! The analyser display as the thesis plots it: log amplitude (dB) against linear
//! frequency (Hz), aliases marked in red, and the running-speed orders marked.

use std::path::{Path, PathBuf};

use instruments::Line;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, legend, mesh, png_and_svg};

/// A spectrum to draw.
#[derive(Clone, Copy, Debug)]
pub struct SpectrumPlot<'a> {
    /// Title.
    pub title: &'a str,
    /// Unit of the analysed signal (the power is in unit² rms).
    pub unit: &'a str,
    /// Displayed lines.
    pub lines: &'a [Line],
    /// For each line, the true frequency of an alias on it.
    pub alias_of: &'a [Option<f64>],
    /// Running speed (rev/s) whose orders ½, 1, 2, … are marked; `None` for none.
    pub running_hz: Option<f64>,
}

/// Writes `base.png` and `base.svg`.
pub fn write_spectrum_plots(base: &Path, plot: &SpectrumPlot) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(base, |root| draw(root, plot), |root| draw(root, plot))
}

/// Width the upper-right legend takes (px): its longest entry, "orders of the running
/// speed", in 13-pt type with the sample line and the box's margins.
const LEGEND_WIDTH_PX: i32 = 240;

/// Most order lines drawn; with more orders in band only every k-th is marked.
const MAX_ORDER_MARKS: usize = 24;

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    plot: &SpectrumPlot,
) -> anyhow::Result<()> {
    let err = draw_error("spectrum");
    let db: Vec<(f64, f64)> = plot
        .lines
        .iter()
        .map(|l| (l.frequency_hz, 10.0 * l.value.max(1e-30).log10()))
        .collect();
    let top = db
        .iter()
        .map(|p| p.1)
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil();
    let low = db.iter().map(|p| p.1).fold(f64::INFINITY, f64::min).floor();
    let bottom = (top - 100.0).max(low);
    let top = if top.is_finite() { top + 3.0 } else { 0.0 };
    let bottom = if bottom.is_finite() && bottom < top {
        bottom
    } else {
        top - 100.0
    };
    let fmax = plot.lines.last().map_or(1.0, |l| l.frequency_hz.max(1.0));
    let mut chart = axes(&root, plot.title, 0.0..fmax, bottom..top)?;
    mesh(
        &mut chart,
        (
            "frequency (Hz)",
            &format!("power (dB re 1 {}² rms)", plot.unit),
        ),
        |m| {
            m.disable_x_mesh();
        },
    )?;
    if let Some(running) = plot.running_hz.filter(|f| *f > 0.0) {
        draw_orders(&mut chart, running, fmax, (bottom, top)).map_err(&err)?;
    }
    chart
        .draw_series(LineSeries::new(
            db.iter().map(|&(f, v)| (f, v.max(bottom))),
            &BLUE,
        ))
        .map_err(&err)?
        .label("power spectrum")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 16, y)], BLUE));
    let aliases: Vec<_> = db
        .iter()
        .zip(plot.alias_of)
        .filter(|(_, a)| a.is_some())
        .map(|(&(f, v), _)| Circle::new((f, v.max(bottom)), 3, RED.filled()))
        .collect();
    if !aliases.is_empty() {
        chart
            .draw_series(aliases)
            .map_err(&err)?
            .label("alias (ground truth)")
            .legend(|(x, y)| Circle::new((x + 8, y), 3, RED.filled()));
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight)?;
    root.present().map_err(&err)?;
    Ok(())
}

type Chart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// Dashed-grey lines at the half order and at the orders of the running speed, labelled.
fn draw_orders<DB: DrawingBackend>(
    chart: &mut Chart<DB>,
    running_hz: f64,
    fmax: f64,
    (bottom, top): (f64, f64),
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let in_band = (fmax / running_hz).floor() as usize;
    let every = in_band.div_ceil(MAX_ORDER_MARKS).max(1);
    let mut orders: Vec<(f64, String)> = vec![(0.5, "½".into())];
    orders.extend(
        (1..=in_band)
            .filter(|k| k % every == 0 || *k == 1)
            .map(|k| (k as f64, k.to_string())),
    );
    let grey = RGBColor(150, 150, 150);
    let plot_right_px = chart.backend_coord(&(fmax, top)).0;
    let legend_left_px = plot_right_px - LEGEND_WIDTH_PX;
    let mut labelled = false;
    for (order, label) in orders {
        let f = order * running_hz;
        if f > fmax {
            continue;
        }
        let series = chart.draw_series(DashedLineSeries::new(
            [(f, bottom), (f, top)],
            4,
            4,
            grey.into(),
        ))?;
        if !labelled {
            series
                .label("orders of the running speed")
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 16, y)], grey));
            labelled = true;
        }
        // Every order keeps its line; its label only where the legend leaves room.
        let x_px = chart.backend_coord(&(f, top)).0;
        if x_px < legend_left_px {
            chart.draw_series(std::iter::once(Text::new(
                label,
                (f, top),
                ("sans-serif", 12).into_font().color(&grey),
            )))?;
        }
    }
    Ok(())
}
