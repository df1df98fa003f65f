//! Order lines in a displayed spectrum: the power at k times the running speed, and how
//! far it stands above the lines around it.

use instruments::Line;

/// Lines each side whose median is the local floor.
const FLOOR_SPAN: usize = 10;
/// Lines each side of the order left out of the floor (the Hanning main lobe and leakage).
const FLOOR_GAP: usize = 2;

/// One order line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrderLine {
    /// Power of the strongest line within one line of the order (unit² rms).
    pub power: f64,
    /// Its height above the local floor (dB).
    pub above_floor_db: f64,
}

/// The order line at `freq_hz` in `lines` (evenly spaced from 0 Hz); `None` beyond the band.
pub fn order_line(lines: &[Line], freq_hz: f64) -> Option<OrderLine> {
    let df = lines.get(1)?.frequency_hz - lines[0].frequency_hz;
    let centre = (freq_hz / df).round() as usize;
    if centre + 1 >= lines.len() {
        return None;
    }
    let power = lines[centre.saturating_sub(1)..=centre + 1]
        .iter()
        .map(|l| l.value)
        .fold(0.0, f64::max);
    let mut around: Vec<f64> = (centre.saturating_sub(FLOOR_SPAN)
        ..(centre + FLOOR_SPAN + 1).min(lines.len()))
        .filter(|&i| i.abs_diff(centre) > FLOOR_GAP && i > 0)
        .map(|i| lines[i].value)
        .collect();
    around.sort_by(f64::total_cmp);
    let floor = around.get(around.len() / 2).copied().unwrap_or(0.0);
    Some(OrderLine {
        power,
        above_floor_db: 10.0 * (power / floor.max(1e-300)).log10(),
    })
}

/// Frequencies (Hz) of the lines that stand `line_db` above their local floor and above
/// both neighbours: the spectral lines of a case, for the frequency map.
pub fn peaks(lines: &[Line], line_db: f64) -> Vec<(f64, f64)> {
    (1..lines.len().saturating_sub(1))
        .filter(|&i| lines[i].value > lines[i - 1].value && lines[i].value >= lines[i + 1].value)
        .filter_map(|i| {
            let o = order_line(lines, lines[i].frequency_hz)?;
            (o.above_floor_db >= line_db).then_some((lines[i].frequency_hz, lines[i].value))
        })
        .collect()
}
