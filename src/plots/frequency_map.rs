//! Output frequency against input frequency (thesis Figs 4.73–4.75): every spectral line
//! of every speed as a point, with the natural frequencies as horizontal lines and the
//! orders ½, 1, 2, … of the running speed as rays from the origin.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{axes, draw_error, legend, mesh, png_and_svg};

/// The lines of one speed.
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedLines {
    /// Running speed (rev/s).
    pub running_hz: f64,
    /// Lines that stand out: (Hz, power).
    pub peaks: Vec<(f64, f64)>,
}

/// Writes `base.png` and `base.svg`, frequencies up to `fmax_hz`.
pub fn write_frequency_map(
    base: &Path,
    title: &str,
    speeds: &[SpeedLines],
    natural_hz: &[f64],
    fmax_hz: f64,
) -> anyhow::Result<Vec<PathBuf>> {
    png_and_svg(
        base,
        |root| draw(root, title, speeds, natural_hz, fmax_hz),
        |root| draw(root, title, speeds, natural_hz, fmax_hz),
    )
}

/// A label's height as a share of the plot's frequency range (12-pt text on ~560 px).
const LABEL_HEIGHT_SHARE: f64 = 0.03;

/// Labels for the natural frequencies `hz` (ascending or not): those closer than `gap_hz`
/// to the group's first share one label, e.g. `86.3 / 88.7 / 91.9 Hz`, placed at the
/// group's top line.
fn natural_labels(hz: &[f64], gap_hz: f64) -> Vec<(f64, String)> {
    let mut sorted = hz.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mut groups: Vec<Vec<f64>> = Vec::new();
    for f in sorted {
        match groups.last_mut() {
            Some(group) if f - group[0] < gap_hz => group.push(f),
            _ => groups.push(vec![f]),
        }
    }
    groups
        .into_iter()
        .map(|group| {
            let text: Vec<String> = group.iter().map(|f| format!("{f:.1}")).collect();
            (group[group.len() - 1], format!("{} Hz", text.join(" / ")))
        })
        .collect()
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    speeds: &[SpeedLines],
    natural_hz: &[f64],
    fmax_hz: f64,
) -> anyhow::Result<()> {
    let err = draw_error("frequency map");
    let xmax = speeds.iter().map(|s| s.running_hz).fold(1.0, f64::max) * 1.05;
    let mut chart = axes(&root, title, 0.0..xmax, 0.0..fmax_hz)?;
    mesh(
        &mut chart,
        (
            "input frequency: running speed (rev/s)",
            "output frequency (Hz)",
        ),
        |_| {},
    )?;
    let grey = RGBColor(160, 160, 160);
    let shown: Vec<f64> = natural_hz
        .iter()
        .copied()
        .filter(|f| *f < fmax_hz)
        .collect();
    for (i, &f) in shown.iter().enumerate() {
        let series = chart
            .draw_series(DashedLineSeries::new(
                [(0.0, f), (xmax, f)],
                6,
                4,
                grey.stroke_width(1),
            ))
            .map_err(&err)?;
        if i == 0 {
            series
                .label("natural frequency (linear model)")
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 16, y)], grey));
        }
    }
    // Lines closer than a label's height share one label.
    for (f, label) in natural_labels(&shown, fmax_hz * LABEL_HEIGHT_SHARE) {
        chart
            .draw_series(std::iter::once(Text::new(
                label,
                (xmax * 0.8, f),
                ("sans-serif", 12).into_font().color(&grey),
            )))
            .map_err(&err)?;
    }
    let orders = [0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0];
    for &k in &orders {
        let end = (xmax * k).min(fmax_hz);
        let series = chart
            .draw_series(LineSeries::new(
                [(0.0, 0.0), (end / k, end)],
                grey.stroke_width(1),
            ))
            .map_err(&err)?;
        if k == orders[0] {
            series
                .label("order of the running speed")
                .legend(move |(x, y)| PathElement::new([(x, y + 4), (x + 16, y - 4)], grey));
        }
        let label = if k == 0.5 {
            "½".to_string()
        } else {
            format!("{k}")
        };
        chart
            .draw_series(std::iter::once(Text::new(
                label,
                (end / k, end),
                ("sans-serif", 12).into_font().color(&grey),
            )))
            .map_err(&err)?;
    }
    let strongest = speeds
        .iter()
        .flat_map(|s| s.peaks.iter().map(|p| p.1))
        .fold(f64::MIN_POSITIVE, f64::max);
    for s in speeds {
        let points = s
            .peaks
            .iter()
            .filter(|p| p.0 <= fmax_hz)
            .map(|&(f, power)| {
                // Darker and larger for stronger lines: 60 dB of range.
                let level = (10.0 * (power / strongest).log10() / 60.0 + 1.0).clamp(0.1, 1.0);
                let shade = (200.0 * (1.0 - level)) as u8;
                Circle::new(
                    (s.running_hz, f),
                    (2.0 + 3.0 * level) as i32,
                    RGBColor(shade, shade, 255).filled(),
                )
            });
        chart.draw_series(points).map_err(&err)?;
    }
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
        .map_err(&err)?
        .label("spectral line: larger, darker = stronger (60 dB)")
        .legend(|(x, y)| Circle::new((x + 8, y), 4, RGBColor(0, 0, 255).filled()));
    legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
    root.present().map_err(&err)?;
    Ok(())
}
