//! Where the scenario's measurement instants fall within the stream of blocks.

use crate::scenario::Measure;

/// Sample indices of the measurements, consumed in order.
#[derive(Clone, Debug)]
pub struct MeasureClock {
    marks: Vec<u64>,
    next: usize,
}

impl MeasureClock {
    /// Marks at `times_s` on a stream of `rate_hz`.
    pub fn new(times_s: impl IntoIterator<Item = f64>, rate_hz: f64) -> Self {
        Self {
            marks: times_s
                .into_iter()
                .map(|t| (t * rate_hz).round() as u64)
                .collect(),
            next: 0,
        }
    }

    /// The next measurement within samples `[start, start + len)`: its offset in the
    /// block and its index; each is returned once.
    pub fn next_within(&mut self, start: u64, len: usize) -> Option<(usize, usize)> {
        let mark = *self.marks.get(self.next)?;
        if mark >= start + len as u64 {
            return None;
        }
        let index = self.next;
        self.next += 1;
        Some((mark.saturating_sub(start) as usize, index))
    }

    /// Indices of the measurements the stream has not reached (yet).
    fn unreached(&self) -> std::ops::Range<usize> {
        self.next..self.marks.len()
    }

    /// A warning for each measurement of `measures` not reached, saying what `lost` (e.g.
    /// "no spectrum").
    pub fn unreached_warnings<'a>(
        &'a self,
        measures: &'a [Measure],
        lost: &'a str,
    ) -> impl Iterator<Item = String> + 'a {
        self.unreached().map(move |index| {
            format!(
                "measurement {} ({}): not reached before the run ended; {lost}",
                index + 1,
                measures[index].label
            )
        })
    }
}
