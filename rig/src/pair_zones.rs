//! The mesh stiffness along the tooth period: one pair in contact for part of it, two for
//! the rest (the contact ratio ε from the geometry, `mesh_pairs = "alternating"`), with
//! the changes between them sharp or smoothed.
//!
//! A real mesh does not switch its stiffness in a step where a second pair enters: the
//! entering tooth takes load gradually as its deflection builds up (tip relief, the
//! flexibility of the tooth near its tip; ISO 6336-1:2019 §9 gives the single-pair stiffness
//! c' and the mean mesh stiffness c_γ = c'(0.75 ε_α + 0.25), which lies between one and two
//! pairs' for a sharp profile). `mesh_stiffness_smoothing` spreads each change over a
//! fraction w of the pitch, centred on the geometric change, as a staircase of
//! [`TRANSITION_STEPS`] equal steps: the plant stays linear between switches (exact at
//! each), and the staircase approaches a linear ramp as the steps multiply.

use crate::mode::{PairZone, TRANSITION_STEPS};

/// The zones of one tooth period, repeated every pitch.
#[derive(Clone, Debug, PartialEq)]
pub struct PairZones {
    /// Where the period's first zone starts, in pitches (−w/2: the change into two pairs
    /// is centred on the period's start).
    origin: f64,
    /// Start of each zone within the period, in pitches from `origin`, increasing from 0.
    starts: Vec<f64>,
    /// Stiffness level of each zone.
    levels: Vec<PairZone>,
    /// The double-pair fraction f of the pitch (the sharp change into one pair).
    double_fraction: f64,
    /// The zone of each period that starts at the period's start (the tooth pass).
    entry: usize,
}

impl PairZones {
    /// Zones for a double-pair fraction `f` of the pitch (ε − 1) and changes `w` pitches
    /// wide (clamped so that no change overlaps the next: w ≤ min(f, 1 − f)).
    pub fn new(double_fraction: f64, smoothing: f64) -> Self {
        let f = double_fraction.clamp(0.0, 1.0);
        let w = smoothing.clamp(0.0, f.min(1.0 - f));
        let steps = if w > 0.0 { TRANSITION_STEPS } else { 0 };
        let step = if steps > 0 { w / f64::from(steps) } else { 0.0 };
        let mut starts = Vec::new();
        let mut levels = Vec::new();
        // From the origin: rising into two pairs, two pairs, falling to one, one pair.
        for i in 0..steps {
            starts.push(f64::from(i) * step);
            levels.push(PairZone(i + 1));
        }
        starts.push(w);
        levels.push(PairZone::TWO);
        for i in 0..steps {
            starts.push(f + f64::from(i) * step);
            levels.push(PairZone(steps - i));
        }
        starts.push(f + w);
        levels.push(PairZone::ONE);
        Self {
            origin: -w / 2.0,
            starts,
            levels,
            double_fraction: f,
            // The rising staircase is centred on the period's start: its middle step
            // starts there (−w/2 + (steps/2)·(w/steps) = 0 exactly).
            entry: usize::from(steps / 2),
        }
    }

    /// The zone that starts at the start of period `period` (a tooth pass; the pair
    /// that enters there takes the load from then on).
    pub fn entering(&self, period: i64) -> i64 {
        period * self.len() + self.entry as i64
    }

    /// Whether zone `index` starts at a period's start (a tooth pass).
    pub fn starts_period(&self, index: i64) -> bool {
        index.rem_euclid(self.len()) as usize == self.entry
    }

    /// The zone of the sharp division (w = 0: 2p two pairs, pairs p − 1 and p; 2p + 1 pair
    /// p alone) that holds zone `index`'s midpoint: which pairs a zone's teeth are.
    pub fn sharp(&self, index: i64) -> i64 {
        let (start, end) = self.bounds(index);
        let middle = 0.5 * (start + end);
        let period = middle.floor();
        2 * period as i64 + i64::from(middle - period >= self.double_fraction)
    }

    fn len(&self) -> i64 {
        self.starts.len() as i64
    }

    /// Start and end of zone `index` in pitches of the driving gear's angle (zone 0 is the
    /// first zone of period 0; each period holds the same zones).
    pub fn bounds(&self, index: i64) -> (f64, f64) {
        let period = index.div_euclid(self.len());
        let i = index.rem_euclid(self.len()) as usize;
        let base = period as f64 + self.origin;
        let end = self.starts.get(i + 1).copied().unwrap_or(1.0);
        (base + self.starts[i], base + end)
    }

    /// The zone holding the angle `pitches` (θ2 over the pitch).
    pub fn zone_at(&self, pitches: f64) -> i64 {
        let u = pitches - self.origin;
        let period = u.floor();
        let within = u - period;
        let i = self.starts.iter().rposition(|&s| s <= within).unwrap_or(0);
        period as i64 * self.len() + i as i64
    }

    /// The stiffness level of zone `index`.
    pub fn level(&self, index: i64) -> PairZone {
        self.levels[index.rem_euclid(self.len()) as usize]
    }
}
