//! The bifurcation diagram: the output-shaft torque sampled once per revolution against
//! speed, each approach (run-up, run-down, from rest, knocked repeats) in its colour. A
//! period-k motion shows k dots at a speed, a chaotic one a smear; the speeds where the
//! approaches settle to different motions (coexisting motions) are shaded.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, legend, legend_share, mesh, png_and_svg};

/// The once-per-revolution samples of one case.
#[derive(Clone, Debug, PartialEq)]
pub struct SectionColumn {
    /// Speed set point (rev/min).
    pub rpm: f64,
    /// Output-shaft torque once per revolution (N m).
    pub torque_nm: Vec<f64>,
}

/// Writes `base.png` and `base.svg`: one series of columns per `(label, columns)`, a
/// band shaded at each speed of `coexisting_rpm` (rev/min).
pub fn write_bifurcation(
    base: &Path,
    title: &str,
    series: &[(String, Vec<SectionColumn>)],
    coexisting_rpm: &[f64],
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, series, coexisting_rpm),
        |root| draw(root, title, series, coexisting_rpm),
    )
}

/// Colours of the series in turn: blue, red, green, orange, then grey.
const COLOURS: [RGBColor; 5] = [
    RGBColor(30, 90, 200),
    RGBColor(210, 40, 40),
    RGBColor(40, 150, 60),
    RGBColor(230, 140, 20),
    RGBColor(120, 120, 120),
];

/// The shade of a speed where motions coexist.
const COEXIST_SHADE: RGBColor = RGBColor(255, 225, 120);

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    series: &[(String, Vec<SectionColumn>)],
    coexisting_rpm: &[f64],
) -> anyhow::Result<()> {
    let err = draw_error("bifurcation diagram");
    let points = || {
        series
            .iter()
            .flat_map(|(_, cols)| cols.iter())
            .flat_map(|c| c.torque_nm.iter().map(move |&t| (c.rpm, t)))
            .filter(|(_, t)| t.is_finite())
    };
    let (r0, r1, t0, t1) = points().fold(
        (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ),
        |(a, b, c, d), (r, t)| (a.min(r), b.max(r), c.min(t), d.max(t)),
    );
    if !r0.is_finite() {
        anyhow::bail!("bifurcation diagram: no samples to draw");
    }
    let pad_r = 0.03 * (r1 - r0).max(100.0);
    let pad_t = 0.05 * (t1 - t0).max(0.1);
    let low = t0 - pad_t;
    let entries = series.len() + usize::from(!coexisting_rpm.is_empty());
    let top = low + (t1 + pad_t - low) / (1.0 - legend_share(entries));
    let mut chart = axes(&root, title, (r0 - pad_r)..(r1 + pad_r), low..top)?;
    mesh(
        &mut chart,
        (
            "speed (rev/min)",
            "output-shaft torque once per revolution (N m)",
        ),
        |_| {},
    )?;
    if !coexisting_rpm.is_empty() {
        let half = 0.6 * pad_r;
        chart
            .draw_series(coexisting_rpm.iter().map(|&r| {
                Rectangle::new([(r - half, low), (r + half, top)], COEXIST_SHADE.filled())
            }))
            .map_err(&err)?
            .label("motions coexist")
            .legend(|(x, y)| Rectangle::new([(x, y - 4), (x + 12, y + 4)], COEXIST_SHADE.filled()));
    }
    for (i, (label, columns)) in series.iter().enumerate() {
        let colour = COLOURS[i.min(COLOURS.len() - 1)];
        // Each series a little to the right of the one before, so that all show.
        let shift = 0.12 * pad_r * i as f64;
        chart
            .draw_series(columns.iter().flat_map(|c| {
                c.torque_nm
                    .iter()
                    .filter(|t| t.is_finite())
                    .map(move |&t| Circle::new((c.rpm + shift, t), 2, colour.filled()))
            }))
            .map_err(&err)?
            .label(label.clone())
            .legend(move |(x, y)| Circle::new((x + 6, y), 4, colour.filled()));
    }
    legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
    root.present().map_err(&err)?;
    Ok(())
}
