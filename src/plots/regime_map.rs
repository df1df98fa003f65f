//! The regime map: speed × load, each case coloured by its period.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;
use rig::Regime;

use super::canvas::{axes, draw_error, legend, legend_share, mesh, png_and_svg};

/// One case on the map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegimeCell {
    /// Speed set point (rev/min).
    pub rpm: f64,
    /// Load (N m).
    pub load_nm: f64,
    /// Its motion.
    pub regime: Regime,
}

/// Writes `base.png` and `base.svg`.
pub fn write_regime_map(
    base: &Path,
    title: &str,
    cells: &[RegimeCell],
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, cells),
        |root| draw(root, title, cells),
    )
}

/// Colour of a period: 1 green, 2 red, 3 orange, 4 purple, more blue, aperiodic black.
fn colour(regime: Regime) -> RGBColor {
    let Some(period) = regime.period() else {
        return RGBColor(0, 0, 0);
    };
    match period {
        1 => RGBColor(60, 170, 60),
        2 => RGBColor(220, 40, 40),
        3 => RGBColor(240, 150, 20),
        4 => RGBColor(140, 60, 180),
        5 => RGBColor(40, 90, 220),
        6 => RGBColor(0, 170, 190),
        7 => RGBColor(150, 100, 50),
        8 => RGBColor(230, 110, 180),
        _ => RGBColor(120, 120, 120),
    }
}

/// Smallest gap between distinct values, if there are two.
fn smallest_step(values: impl Iterator<Item = f64>) -> Option<f64> {
    let mut v: Vec<f64> = values.collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v.windows(2).map(|w| w[1] - w[0]).reduce(f64::min)
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    cells: &[RegimeCell],
) -> anyhow::Result<()> {
    let err = draw_error("regime map");
    let (r0, r1) = cells
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
            (a.min(c.rpm), b.max(c.rpm))
        });
    let (l0, l1) = cells
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
            (a.min(c.load_nm), b.max(c.load_nm))
        });
    let half_r = 0.45 * smallest_step(cells.iter().map(|c| c.rpm)).unwrap_or(100.0);
    let half_l = 0.45 * smallest_step(cells.iter().map(|c| c.load_nm)).unwrap_or(1.0);
    let (pad_r, pad_l) = (2.0 * half_r, 2.0 * half_l);
    let mut regimes: Vec<Regime> = cells.iter().map(|c| c.regime).collect();
    regimes.sort_by_key(|r| r.period().unwrap_or(0));
    regimes.dedup();
    // Headroom above the top row of cells for the legend.
    let span_l = (l1 + pad_l) - (l0 - pad_l);
    let top = (l0 - pad_l) + span_l / (1.0 - legend_share(regimes.len()));
    let mut chart = axes(&root, title, (r0 - pad_r)..(r1 + pad_r), (l0 - pad_l)..top)?;
    mesh(&mut chart, ("speed (rev/min)", "load (N m)"), |_| {})?;
    for regime in regimes {
        let c = colour(regime);
        let label = regime.to_string();
        chart
            .draw_series(
                cells
                    .iter()
                    .filter(|cell| cell.regime == regime)
                    .map(move |cell| {
                        Rectangle::new(
                            [
                                (cell.rpm - half_r, cell.load_nm - half_l),
                                (cell.rpm + half_r, cell.load_nm + half_l),
                            ],
                            c.filled(),
                        )
                    }),
            )
            .map_err(&err)?
            .label(label)
            .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], c.filled()));
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight)?;
    root.present().map_err(&err)?;
    Ok(())
}
