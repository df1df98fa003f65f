//! The motion of each measured point, judged in the plant's thread over the point's
//! settled window: from the measurement (which a scenario places after its settling
//! time) until the set speed or load changes, the next measurement comes or the run
//! ends. A run with no measurement of its own is one point, judged over its last stretch
//! ([`REGIME_WINDOW_S`], at most half the run). Blocks are whole: a window takes the
//! blocks that start inside it.

use std::sync::Arc;

use rig::SetPoints;

use super::rolling_regime::REGIME_WINDOW_S;
use super::run_plant::{RunBlock, RunPlant, RunWindow};
use crate::vocabulary::PointVerdict;

/// One point's window, in samples of the run.
#[derive(Clone, Copy, Debug)]
struct Span {
    from: u64,
    to: u64,
}

/// The set speed (rev/min) and load (N m) a window was opened under.
type HeldSetPoints = (f64, f64);

/// A point's window being filled: its index, the window and the set points it was
/// opened under.
struct OpenWindow {
    index: usize,
    window: RunWindow,
    held: HeldSetPoints,
}

/// The windows of a run's points and the one being filled.
pub struct PointJudge {
    spans: Vec<Span>,
    next: usize,
    open: Option<OpenWindow>,
    step_s: f64,
}

impl PointJudge {
    /// Windows for measurements at `measures_s` (s; empty: the run is one point) in a run
    /// of `total_samples` samples every `step_s`.
    pub fn new(measures_s: &[f64], total_samples: u64, step_s: f64) -> Self {
        let duration_s = total_samples as f64 * step_s;
        let sample = |s: f64| ((s / step_s).round().max(0.0) as u64).min(total_samples);
        let spans = if measures_s.is_empty() {
            let from_s = duration_s - REGIME_WINDOW_S.min(duration_s / 2.0);
            vec![Span {
                from: sample(from_s),
                to: total_samples,
            }]
        } else {
            measures_s
                .iter()
                .enumerate()
                .map(|(i, &at_s)| Span {
                    from: sample(at_s),
                    to: measures_s.get(i + 1).map_or(total_samples, |&s| sample(s)),
                })
                .collect()
        };
        Self {
            spans,
            next: 0,
            open: None,
            step_s,
        }
    }

    /// Adds `plant`'s block starting at sample `start`, made under set points `set`;
    /// returns the verdicts on windows that ended before it, or with it when `last` (the
    /// run's last block).
    pub fn add(
        &mut self,
        plant: &RunPlant,
        start: u64,
        block: &RunBlock,
        set: &SetPoints,
        last: bool,
    ) -> Vec<Arc<PointVerdict>> {
        let held = (set.speed_rpm, set.load_nm);
        let mut verdicts = Vec::new();
        if let Some(open) = &self.open
            && (start >= self.spans[open.index].to || open.held != held)
        {
            verdicts.extend(self.close());
        }
        if self.open.is_none() {
            self.open_window_at(start, held, plant);
        }
        if let Some(open) = &mut self.open {
            open.window.add(block, set);
        }
        if last {
            verdicts.extend(self.close());
        }
        verdicts
    }

    /// Opens the window the block starting at `start` falls in, if any (windows that no
    /// block started in are passed over).
    fn open_window_at(&mut self, start: u64, held: HeldSetPoints, plant: &RunPlant) {
        while let Some(span) = self.spans.get(self.next) {
            if start >= span.to {
                self.next += 1;
                continue;
            }
            if start >= span.from {
                self.open = Some(OpenWindow {
                    index: self.next,
                    window: plant.window(true),
                    held,
                });
                self.next += 1;
            }
            return;
        }
    }

    /// The verdict on the open window, which is closed.
    fn close(&mut self) -> Option<Arc<PointVerdict>> {
        let open = self.open.take()?;
        let (summary, condition) = open.window.verdict();
        Some(Arc::new(PointVerdict {
            index: open.index,
            from_s: self.spans[open.index].from as f64 * self.step_s,
            summary,
            condition,
        }))
    }
}
