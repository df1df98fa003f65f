//! A gear's synchronous average: the averaged revolution of a shaft's torque against the
//! gear's angle, the span where a faulted tooth is in mesh shaded.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, legend, mesh, png_and_svg};

/// What one averaged revolution plot shows.
#[derive(Clone, Debug, PartialEq)]
pub struct AveragePlot<'a> {
    /// The title.
    pub title: &'a str,
    /// The averaged revolution (N m), evenly over one turn from the once-per-revolution
    /// pulse.
    pub average_nm: &'a [f64],
    /// The gear's teeth.
    pub teeth: u32,
    /// A tooth to mark (1..=teeth): it is in mesh over [(k − 1)/z, k/z) of the turn.
    pub marked_tooth: Option<u32>,
}

/// Writes `base.png` and `base.svg`.
pub fn write_synchronous_average(base: &Path, plot: &AveragePlot) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(base, |root| draw(root, plot), |root| draw(root, plot))
}

/// The shade of the marked tooth's span.
const MARK: RGBColor = RGBColor(255, 205, 160);

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    plot: &AveragePlot,
) -> anyhow::Result<()> {
    let err = draw_error("synchronous average plot");
    let n = plot.average_nm.len();
    if n == 0 {
        anyhow::bail!("synchronous average plot: no average to draw");
    }
    let (low, high) = plot
        .average_nm
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let pad = 0.1 * (high - low).max(1e-6);
    let (bottom, top) = (low - pad, high + 2.0 * pad);
    let mut chart = axes(&root, plot.title, 0.0..360.0, bottom..top)?;
    mesh(
        &mut chart,
        (
            "gear angle from the once-per-revolution pulse (degrees)",
            "averaged shaft torque (N m)",
        ),
        |_| {},
    )?;
    if let Some(k) = plot.marked_tooth {
        let pitch = 360.0 / f64::from(plot.teeth);
        let from = f64::from(k - 1) * pitch;
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(from, bottom), (from + pitch, top)],
                MARK.filled(),
            )))
            .map_err(&err)?
            .label(format!("tooth {k} in mesh"))
            .legend(|(x, y)| Rectangle::new([(x, y - 4), (x + 12, y + 4)], MARK.filled()));
    }
    chart
        .draw_series(LineSeries::new(
            plot.average_nm
                .iter()
                .enumerate()
                .map(|(i, &v)| (360.0 * i as f64 / n as f64, v)),
            BLUE.stroke_width(2),
        ))
        .map_err(&err)?
        .label("averaged revolution")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 12, y)], BLUE.stroke_width(2)));
    legend(&mut chart, SeriesLabelPosition::UpperRight)?;
    root.present().map_err(&err)?;
    Ok(())
}
