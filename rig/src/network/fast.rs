//! The fast path: runs of output samples in one mode, each step one fused product, the
//! switch checks against targets taken once for the run, the samples stored without
//! asking again which mode they are in. A step where a function may cross is taken on
//! the exact path (`stepping.rs`), the rest of its output period too, and the run ends
//! there. Both paths take the same products in the same order: the same bytes. A run
//! that writes no samples (settling) takes strides of several steps in one product where
//! the mode allows (`system.rs`), checked for switches over the whole stride; where one
//! may fall, that stretch is taken in single steps.

use crate::error::RigError;
use crate::roots::may_cross;

use super::block::NetworkBlock;
use super::events::edge_values;
use super::plant::NetworkPlant;
use super::products;
use super::system::{ModeSystem, SystemCache};

/// How a fast run ended.
enum RunEnd {
    /// Every sample asked for is taken, or the next begins a stretch of set points or
    /// must be checked for bounds.
    Done,
    /// A function may cross within step `substep` of the current sample's output period
    /// (the sample stored, the steps before that one taken).
    MaySwitch { substep: u32 },
}

impl NetworkPlant {
    /// Takes up to `limit` samples, as many as it can on the fast path and the one where
    /// a switch may fall on the exact path, storing them only if `RECORD`; returns how
    /// many it took (at least one when `limit` > 0).
    pub(super) fn run_some<const RECORD: bool>(
        &mut self,
        limit: u64,
        block: &mut NetworkBlock,
    ) -> Result<u64, RigError> {
        let first = self.sample;
        let segment_begins = self.segment_end.is_some_and(|end| self.sample >= end);
        if RECORD && (segment_begins || !self.chunk.takes(self.sample, &self.mode)) {
            self.store_sample(block);
            self.finish_period(0)?;
            return Ok(1);
        }
        if !RECORD && segment_begins {
            self.begin_segment();
        }
        let Some(mut cache) = self.cache.take() else {
            return Err(RigError::Schedule(
                "a run began inside a step (the plant's cache was out)".into(),
            ));
        };
        let end = self.fast_run_dispatch::<RECORD>(&mut cache, limit, block);
        self.cache = Some(cache);
        if let RunEnd::MaySwitch { substep } = end {
            self.finish_period(substep)?;
        }
        Ok(self.sample - first)
    }

    /// The steps of the current sample's output period from `substep` on, on the exact
    /// path, then the sample counted.
    fn finish_period(&mut self, substep: u32) -> Result<(), RigError> {
        for k in substep..self.substeps {
            self.step_start_s = self.time_s() + f64::from(k) * self.step_s;
            self.step()?;
        }
        self.sample += 1;
        Ok(())
    }

    /// [`Self::fast_run`] compiled for AVX2 and FMA where the CPU has them (its products
    /// [`products::Inlined`]), else for baseline x86-64.
    fn fast_run_dispatch<const RECORD: bool>(
        &mut self,
        cache: &mut SystemCache,
        limit: u64,
        block: &mut NetworkBlock,
    ) -> RunEnd {
        #[cfg(target_arch = "x86_64")]
        if crate::fma::available() {
            // SAFETY: the CPU has AVX2 and FMA, checked at run time.
            return unsafe { self.fast_run_v3::<RECORD>(cache, limit, block) };
        }
        self.fast_run::<RECORD>(cache, limit, block)
    }

    /// [`Self::fast_run`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn fast_run_v3<const RECORD: bool>(
        &mut self,
        cache: &mut SystemCache,
        limit: u64,
        block: &mut NetworkBlock,
    ) -> RunEnd {
        self.fast_run::<RECORD>(cache, limit, block)
    }

    /// Samples on the fast path in the current mode (stored if `RECORD`), up to `limit`, stopping before a
    /// sample that begins a stretch of set points and after one due for a check of
    /// bounds.
    #[inline(always)]
    fn fast_run<const RECORD: bool>(
        &mut self,
        cache: &mut SystemCache,
        limit: u64,
        block: &mut NetworkBlock,
    ) -> RunEnd {
        let system = cache.get(&self.model, &self.mode);
        self.fill_targets(system);
        if self.edge.len() != system.events.len() {
            edge_values(&system.events, &self.u, &mut self.edge);
        }
        let stop = self.fast_stop(limit);
        // Strides only where no sample is written inside them, in whole output periods.
        let substeps = self.substeps;
        let stride = system
            .stride
            .as_ref()
            .filter(|s| !RECORD && s.steps.is_multiple_of(substeps));
        // After a stride that may switch, single steps up to this sample.
        let mut singles_until = 0;
        while self.sample < stop {
            if RECORD {
                if self.chunk.is_full() {
                    self.chunk.flush(&system.outputs, self.output_step_s, block);
                }
                self.chunk.store(self.sample, &self.mode, &self.u);
            }
            if let Some(stride) = stride {
                let samples = u64::from(stride.steps / substeps);
                if self.sample >= singles_until && self.sample + samples <= stop {
                    self.span_end(system, &stride.matrix, products::Inlined);
                    if !self.may_switch(system, f64::from(stride.steps) * self.step_s) {
                        self.take_span_end();
                        self.sample += samples;
                        continue;
                    }
                    singles_until = self.sample + samples;
                }
            }
            for substep in 0..substeps {
                self.span_end(system, &system.step, products::Inlined);
                if self.may_switch(system, self.step_s) {
                    return RunEnd::MaySwitch { substep };
                }
                self.take_span_end();
            }
            self.sample += 1;
        }
        RunEnd::Done
    }

    /// The first sample the fast run may not take: `limit` on, the next stretch of set
    /// points or the next check of bounds, whichever comes first (past the current one).
    fn fast_stop(&self, limit: u64) -> u64 {
        let check = super::plant::CHECK_EVERY;
        let mut stop = (self.sample + limit).min((self.sample / check + 1) * check);
        if let Some(end) = self.segment_end {
            stop = stop.min(end);
        }
        stop
    }

    /// Each switching function's target now, into `self.targets` (they move only at
    /// switches, so they hold for a fast run).
    fn fill_targets(&mut self, system: &ModeSystem) {
        let mut targets = std::mem::take(&mut self.targets);
        targets.clear();
        targets.extend(system.events.iter().map(|form| self.target(form)));
        self.targets = targets;
    }

    /// Whether any function may cross over the span of `span_s` from `self.u` to
    /// `self.next` (values and rates at its ends in `self.edge` and `self.next_edge`), as
    /// the exact path's check decides it.
    #[inline(always)]
    fn may_switch(&self, system: &ModeSystem, span_s: f64) -> bool {
        system.events.iter().enumerate().any(|(k, _)| {
            let target = self.targets[k];
            let (value_0, rate_0) = self.edge[k];
            let end = self.next_edge[k];
            let g0 = (value_0 - target).min(0.0);
            let g1 = end.0 - target;
            may_cross(g0, rate_0 * span_s, g1, end.1 * span_s)
        })
    }
}
