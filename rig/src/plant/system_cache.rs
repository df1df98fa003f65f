//! The modes met so far: each mode's system built when it is first met and kept until
//! the set points' rates (`SegmentRates`) change, and its products folded for fast runs
//! (`run_spans.rs`), kept while the forcing states they hold keep their values.

use rustc_hash::FxHashMap;

use super::mode::NetMode;
use super::model::{NetworkModel, SegmentRates};
use super::run_spans::RunSpans;
use super::system::ModeSystem;

/// The modes met so far.
#[derive(Clone, Debug)]
pub struct SystemCache {
    /// Where each mode's system sits in `built`, found by the Fx hash: a mode is a few
    /// dozen bytes of flags, asked for at every switch, and the standard SipHash (proof
    /// against crafted keys, which a mode cannot be) was 3 % of a planetary bench's time.
    systems: FxHashMap<NetMode, usize>,
    built: Vec<ModeSystem>,
    /// The mode asked for last and where its system sits (most steps stay in one mode).
    last: Option<(NetMode, usize)>,
    step_s: f64,
    /// Internal steps an output period.
    substeps: u32,
    rho: f64,
    /// The rates of the set points the systems were built for.
    rates: SegmentRates,
    /// Per built system, its products folded for fast runs (`run_spans.rs`), if asked for.
    runs: Vec<Option<RunSpans>>,
}

impl SystemCache {
    /// An empty cache for steps of `step_s`, `substeps` an output period, ρ the fastest
    /// rate of any mode (rad/s).
    pub fn new(step_s: f64, substeps: u32, rho: f64) -> Self {
        Self {
            systems: FxHashMap::default(),
            built: Vec::new(),
            last: None,
            step_s,
            substeps,
            rho,
            rates: SegmentRates::default(),
            runs: Vec::new(),
        }
    }

    /// Sets the rates of the set points the systems are built for; a change empties the
    /// cache.
    pub fn set_rates(&mut self, rates: SegmentRates) {
        if rates != self.rates {
            self.systems.clear();
            self.built.clear();
            self.runs.clear();
            self.last = None;
            self.rates = rates;
        }
    }

    /// The system of `mode`, built if new.
    pub fn get(&mut self, model: &NetworkModel, mode: &NetMode) -> &ModeSystem {
        let index = self.index(model, mode);
        &self.built[index]
    }

    /// The system of `mode` and its products folded for a fast run from the state `u`
    /// (built anew where the forcing states they hold have changed).
    pub fn get_run(
        &mut self,
        model: &NetworkModel,
        mode: &NetMode,
        u: &[f64],
    ) -> (&ModeSystem, &RunSpans) {
        let index = self.index(model, mode);
        if self.runs.len() < self.built.len() {
            self.runs.resize(self.built.len(), None);
        }
        let system = &self.built[index];
        let run = &mut self.runs[index];
        if !run.as_ref().is_some_and(|r| r.holds(u)) {
            *run = Some(RunSpans::new(system, &model.layout, u));
        }
        (system, run.as_ref().expect("just built"))
    }

    /// Where the system of `mode` sits, built if new (the last one asked for kept at hand).
    fn index(&mut self, model: &NetworkModel, mode: &NetMode) -> usize {
        match self.last {
            Some((last, index)) if last == *mode => index,
            _ => {
                let index = self.index_of(model, mode);
                self.last = Some((*mode, index));
                index
            }
        }
    }

    /// Where the system of `mode` sits, built if new.
    fn index_of(&mut self, model: &NetworkModel, mode: &NetMode) -> usize {
        if let Some(&index) = self.systems.get(mode) {
            return index;
        }
        self.built.push(ModeSystem::build(
            model,
            mode,
            &self.rates,
            (self.step_s, self.substeps),
            self.rho,
        ));
        self.systems.insert(*mode, self.built.len() - 1);
        self.built.len() - 1
    }
}
