//! A switching function over one span as the switch checks see it: how far short of its
//! target it is at the span's ends and how much it changes over the span at its ends'
//! rates, judged by the cubic Hermite rules of `crate::roots` (the fast run's checks in
//! `fast.rs`, the exact path's in `stepping.rs`).

use crate::roots::{may_cross, may_cross_span, surely_short};

/// A switching function over a span, as the checks see it: its value less its target,
/// g0 and g1, at the span's ends (negative short of the target; the start's taken as at
/// most 0: a function just switched on stays until it falls) and its changes d0, d1 over
/// the span at its ends' rates.
#[derive(Clone, Copy, Debug)]
pub(super) struct SpanGaps {
    g0: f64,
    d0: f64,
    g1: f64,
    d1: f64,
}

impl SpanGaps {
    /// The gaps of a function of value and rate `start` and `end` at the ends of a span
    /// of `span_s` (s) to `target`.
    #[inline(always)]
    pub(super) fn of(
        (value_0, rate_0): (f64, f64),
        (value_1, rate_1): (f64, f64),
        target: f64,
        span_s: f64,
    ) -> Self {
        Self {
            g0: (value_0 - target).min(0.0),
            d0: rate_0 * span_s,
            g1: value_1 - target,
            d1: rate_1 * span_s,
        }
    }

    /// Whether the function may reach its target within the span: over one step as
    /// [`may_cross`] judges it, over several (`several_steps`) as [`may_cross_span`]
    /// does (any interior maximum).
    #[inline(always)]
    pub(super) fn may_reach(self, several_steps: bool) -> bool {
        let Self { g0, d0, g1, d1 } = self;
        if several_steps {
            may_cross_span(g0, d0, g1, d1)
        } else {
            may_cross(g0, d0, g1, d1)
        }
    }

    /// Whether [`Self::may_reach`] is surely false by a cheap, branch-free bound
    /// ([`surely_short`]): a loop over a mode's functions checks them all so, several at
    /// once, and leaves the rest to [`Self::may_reach`].
    #[inline(always)]
    pub(super) fn surely_short(self, several_steps: bool) -> bool {
        surely_short(self.g0, self.d0, self.g1, self.d1, several_steps)
    }
}
