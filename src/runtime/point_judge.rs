//! The motion of each measured point, judged in the plant's thread over the point's
//! settled window: from the measurement (which a scenario places after its settling
//! time) until the set speed or load changes, the next measurement comes or the run
//! ends. A run with no measurement of its own is one point, judged over its last stretch
//! ([`REGIME_WINDOW_S`], at most half the run). Blocks are whole: a window takes the
//! blocks that start inside it.

use std::sync::Arc;

use rig::{Impact, RegimeCriteria, RevolutionSample, SetPoints, SignalBlock, SteadyWindow};

use crate::chain::GearCondition;
use crate::vocabulary::GearIndicators;

use super::rolling_regime::REGIME_WINDOW_S;
use crate::vocabulary::PointVerdict;

/// One point's window, in samples of the run.
#[derive(Clone, Copy, Debug)]
struct Span {
    from: u64,
    to: u64,
}

/// The set speed (rev/min) and load (N m) a window was opened under.
type HeldSetPoints = (f64, f64);

/// A point's window being filled: its index, its summary, the driven gear's average and
/// the set points it was opened under.
struct OpenWindow {
    index: usize,
    window: SteadyWindow,
    condition: GearCondition,
    held: HeldSetPoints,
}

/// The windows of a run's points and the one being filled.
pub struct PointJudge {
    spans: Vec<Span>,
    next: usize,
    open: Option<OpenWindow>,
    teeth: u32,
    step_s: f64,
}

impl PointJudge {
    /// Windows for measurements at `measures_s` (s; empty: the run is one point) in a run
    /// of `total_samples` samples every `step_s` of a plant of `teeth` teeth.
    pub fn new(measures_s: &[f64], total_samples: u64, step_s: f64, teeth: u32) -> Self {
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
            teeth,
            step_s,
        }
    }

    /// Adds the block starting at sample `start`, made under set points `set` (with its
    /// impacts and revolution samples); returns the verdicts on windows that ended before
    /// it, or with it when `last` (the run's last block).
    pub fn add(
        &mut self,
        start: u64,
        block: &SignalBlock,
        set: &SetPoints,
        impacts: &[Impact],
        revolutions: &[RevolutionSample],
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
            self.open_window_at(start, held);
        }
        if let Some(open) = &mut self.open {
            open.window.add_block(block, set.speed_rad_s());
            open.window.add_impacts(impacts);
            open.window.add_revolutions(revolutions);
            open.condition.add(block);
        }
        if last {
            verdicts.extend(self.close());
        }
        verdicts
    }

    /// Opens the window the block starting at `start` falls in, if any (windows that no
    /// block started in are passed over).
    fn open_window_at(&mut self, start: u64, held: HeldSetPoints) {
        while let Some(span) = self.spans.get(self.next) {
            if start >= span.to {
                self.next += 1;
                continue;
            }
            if start >= span.from {
                self.open = Some(OpenWindow {
                    index: self.next,
                    window: SteadyWindow::new(self.teeth, self.step_s),
                    condition: GearCondition::new(1.0 / self.step_s),
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
        let report = open.condition.report(self.teeth as usize);
        Some(Arc::new(PointVerdict {
            index: open.index,
            from_s: self.spans[open.index].from as f64 * self.step_s,
            summary: open.window.summary(&RegimeCriteria::default()),
            condition: report.as_ref().map(GearIndicators::from),
        }))
    }
}
