//! The impact raster: which tooth of the driving gear takes each impact, revolution after
//! revolution. Impacts on every k-th tooth draw diagonal stripes; a motion that repeats
//! every two revolutions repeats its pattern every two columns (the thesis's explanation
//! of the half order: with 30 teeth, impacts on every fourth tooth close after two
//! revolutions).

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, legend, legend_share, mesh, png_and_svg};

/// One impact on the raster.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterImpact {
    /// Revolution of the driving gear it falls in (from the window's start).
    pub revolution: f64,
    /// Tooth of the driving gear struck, 1..=teeth (tooth 1 in mesh at the start, as
    /// `impacts.csv` numbers them).
    pub tooth: u32,
    /// Whether it struck the drive flank (else the back flank).
    pub drive_flank: bool,
}

/// Writes `base.png` and `base.svg` for a gear of `teeth` teeth.
pub fn write_impact_raster(
    base: &Path,
    title: &str,
    teeth: u32,
    impacts: &[RasterImpact],
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, teeth, impacts),
        |root| draw(root, title, teeth, impacts),
    )
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    teeth: u32,
    impacts: &[RasterImpact],
) -> anyhow::Result<()> {
    let err = draw_error("impact raster");
    let right = impacts
        .iter()
        .map(|i| i.revolution)
        .fold(1.0, f64::max)
        .ceil();
    let top = (teeth as f64 + 0.5) / (1.0 - legend_share(2));
    let mut chart = axes(&root, title, 0.0..right, -0.5..top)?;
    mesh(
        &mut chart,
        (
            "revolution of the driving gear",
            "tooth of the driving gear",
        ),
        |m| {
            m.y_label_formatter(&|v| format!("{v:.0}"));
        },
    )?;
    for (drive, label, colour) in [
        (true, "drive flank", RGBColor(30, 90, 200)),
        (false, "back flank", RGBColor(210, 40, 40)),
    ] {
        chart
            .draw_series(
                impacts
                    .iter()
                    .filter(|i| i.drive_flank == drive)
                    .map(|i| Circle::new((i.revolution, i.tooth as f64), 2, colour.filled())),
            )
            .map_err(&err)?
            .label(label)
            .legend(move |(x, y)| Circle::new((x + 6, y), 4, colour.filled()));
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight)?;
    root.present().map_err(&err)?;
    Ok(())
}
