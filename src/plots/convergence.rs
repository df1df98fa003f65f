//! A search's convergence: every evaluation's objective against its number, the best so far
//! as a line, restarts marked.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, legend, mesh, png_and_svg};

/// One evaluation of a search.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SearchPoint {
    /// Evaluation number (from 0).
    pub evaluation: usize,
    /// Its objective (dB).
    pub objective_db: f64,
    /// The restart it belongs to.
    pub restart: usize,
}

/// Writes `base.png` and `base.svg`.
pub fn write_convergence(
    base: &Path,
    title: &str,
    points: &[SearchPoint],
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, points),
        |root| draw(root, title, points),
    )
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    points: &[SearchPoint],
) -> anyhow::Result<()> {
    let err = draw_error("convergence plot");
    let finite = || points.iter().filter(|p| p.objective_db.is_finite());
    let top = finite().map(|p| p.objective_db).fold(1.0, f64::max) * 1.1;
    let right = points
        .iter()
        .map(|p| p.evaluation)
        .max()
        .unwrap_or(1)
        .max(1) as f64;
    let mut chart = axes(&root, title, 0.0..right, 0.0..top)?;
    mesh(&mut chart, ("evaluation", "objective (dB)"), |m| {
        m.x_label_formatter(&|v| format!("{v:.0}"));
    })?;
    chart
        .draw_series(finite().map(|p| {
            Circle::new(
                (p.evaluation as f64, p.objective_db),
                3,
                Palette99::pick(p.restart).filled(),
            )
        }))
        .map_err(&err)?
        .label("each evaluation (colour: restart)")
        .legend(|(x, y)| Circle::new((x + 10, y), 3, Palette99::pick(0).filled()));
    let mut best = f64::INFINITY;
    let line: Vec<(f64, f64)> = finite()
        .map(|p| {
            best = best.min(p.objective_db);
            (p.evaluation as f64, best)
        })
        .collect();
    chart
        .draw_series(LineSeries::new(line, BLACK.stroke_width(2)))
        .map_err(&err)?
        .label("best so far")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLACK.stroke_width(2)));
    legend(&mut chart, SeriesLabelPosition::UpperRight)?;
    root.present().map_err(&err)?;
    Ok(())
}
