//! The fast path: runs of output samples in one mode, each step one fused product, the
//! switch checks against targets taken once for the run, the samples stored without
//! asking again which mode they are in. A step where a function may cross is taken on
//! the exact path (`stepping.rs`), the rest of its output period too, and the run ends
//! there. The fast path's products are folded for the run (`run_spans.rs`), so the two
//! paths part at rounding; which path takes a step depends on the motion alone, never
//! on the blocks a run is asked for in, so a run gives the same bytes whatever they are. A run
//! that writes no samples (settling) takes strides of several steps in one product where
//! the mode allows (`system.rs`), checked for switches over the whole stride; one that
//! writes samples takes an output period of several steps in one product where the mode
//! allows, and where the mode's stride is four output periods or more, strides too, each
//! begun at a multiple of its samples and its inside samples from its first state
//! (`record_stride.rs`); where a switch may fall, that stretch is taken in single steps.

use crate::error::RigError;

use super::block::NetworkBlock;
use super::network_plant::NetworkPlant;
use super::products;
use super::run_spans::RunSpans;
use super::span_gaps::SpanGaps;
use super::system::{ModeSystem, SpanMatrix};
use super::system_cache::SystemCache;

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
        // As at a block's start, so that the fast path takes the sample alike: the same
        // bytes whatever the blocks.
        self.ready_sample::<RECORD>(block);
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
    /// [`products::gathered`] inlined), else for baseline x86-64.
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
        let (system, run) = cache.get_run(&self.model, &self.mode, &self.u);
        self.fill_targets(system);
        if RECORD {
            self.stride.resume(self.sample, &self.mode, &self.u);
        } else {
            self.stride.drop_stride();
        }
        // A stride taken on has the functions' values at its end; none are read before.
        if self.edge.len() != system.events.len() && !self.stride.is_active() {
            system.ends_at(
                &self.u,
                self.model.layout.unit(),
                &mut self.fused_out,
                &mut self.edge,
            );
        }
        self.prepare_run(system, run);
        let stop = self.fast_stop(limit);
        // A recorded run's strides (`record_stride.rs`): k samples, begun where the sample
        // is a multiple of k and the stride ends before the run must stop whatever its
        // limit (so that a block's end never decides one).
        let record_stride = if RECORD {
            (system.stride.as_ref())
                .zip(run.stride.as_ref())
                .filter(|_| !run.inside.is_empty())
                .map(|(stride, matrix)| (stride.steps, matrix, run.inside.len() as u64 + 1))
        } else {
            None
        };
        let bound = self.run_bound();
        // Spans of several steps (`stride.rs`): where no sample is written, strides of
        // whole output periods; where samples are, one output period (a sample at its end).
        let substeps = self.substeps;
        let span = if RECORD {
            system
                .period
                .as_ref()
                .zip(run.period.as_ref())
                .map(|(_, matrix)| (substeps, matrix))
        } else {
            system
                .stride
                .as_ref()
                .zip(run.stride.as_ref())
                .map(|(stride, matrix)| (stride.steps, matrix))
        };
        // After a stride that may switch, single steps up to this sample.
        let mut singles_until = 0;
        while self.sample < stop {
            if RECORD {
                if self.chunk.is_full() {
                    self.chunk.flush(&system.outputs, self.output_step_s, block);
                }
                self.chunk.store(self.sample, &self.mode, &self.u);
                if self.stride.is_active() {
                    self.take_stride_sample(system, run);
                    continue;
                }
                if let Some((steps, matrix, k)) = record_stride
                    && self.sample.is_multiple_of(k)
                    && self.sample + k <= bound
                    && !self.span_may_switch(system, run, matrix, f64::from(steps) * self.step_s)
                {
                    let what = (self.sample, k, self.mode);
                    let ends = (&self.next[..], &self.next_edge[..]);
                    self.stride.begin(what, run, &self.u, ends);
                    self.take_stride_sample(system, run);
                    continue;
                }
            }
            if let Some((steps, matrix)) = span {
                let samples = u64::from(steps / substeps);
                if self.sample >= singles_until && self.sample + samples <= stop {
                    if !self.span_may_switch(system, run, matrix, f64::from(steps) * self.step_s) {
                        self.take_span_end();
                        self.sample += samples;
                        continue;
                    }
                    singles_until = self.sample + samples;
                }
            }
            for substep in 0..substeps {
                if self.span_may_switch(system, run, &run.step, self.step_s) {
                    return RunEnd::MaySwitch { substep };
                }
                self.take_span_end();
            }
            self.sample += 1;
        }
        if RECORD && self.stride.is_active() {
            // The functions' values at the state left are not known: a next run that does
            // not take the stride on computes them at its start.
            self.stride.leave(&self.u);
            self.edge.clear();
        }
        RunEnd::Done
    }

    /// Takes the current sample of the stride under way (`record_stride.rs`): the state
    /// moved to the next sample.
    #[inline(always)]
    fn take_stride_sample(&mut self, system: &ModeSystem, run: &RunSpans) {
        self.stride.take_sample(
            self.sample + 1,
            (system, run),
            self.model.layout.mechanical(),
            (&mut self.u, &mut self.edge),
            (&mut self.fused_out, &mut self.forcing_out),
        );
        self.sample += 1;
    }

    /// Readies the scratch for a fast run's products: room for their rows and for each
    /// switching function's end, and the forcing states the run holds copied into
    /// `self.next` (its products leave them be).
    fn prepare_run(&mut self, system: &ModeSystem, run: &RunSpans) {
        if self.fused_out.len() < system.end_rows() {
            self.fused_out.resize(system.end_rows(), 0.0);
        }
        if self.forcing_out.len() < run.moving_rows {
            self.forcing_out.resize(run.moving_rows, 0.0);
        }
        let mechanical = self.model.layout.mechanical();
        self.next[mechanical..].copy_from_slice(&self.u[mechanical..]);
        self.next_edge.resize(system.events.len(), (0.0, 0.0));
    }

    /// Takes the span of `matrix` (a step or a stride of `run`, `span_s` long) from
    /// `self.u`: `self.next` the state at its end; and whether any switching function may
    /// cross over it, as the exact path's check decides it over a step, and over a span
    /// of several steps as `may_cross_span` does (any interior maximum). `self.next_edge`
    /// holds each function's value and rate at the end (where one may cross, the exact
    /// path takes the span again).
    #[inline(always)]
    fn span_may_switch(
        &mut self,
        system: &ModeSystem,
        run: &RunSpans,
        matrix: &SpanMatrix,
        span_s: f64,
    ) -> bool {
        self.run_end_state(system, run, matrix);
        let several_steps = span_s > self.step_s;
        let events = system.events.len();
        system.write_angle_rows(&self.next, &mut self.fused_out);
        let unit = self.next[self.model.layout.unit()];
        let rows = &self.fused_out[..system.end_rows()];
        let ends = &mut self.next_edge[..events];
        for (end, read) in ends.iter_mut().zip(&system.ends) {
            *end = read.read(rows, unit);
        }
        let (starts, targets) = (&self.edge[..events], &self.targets[..events]);
        // The loop compiled apart for spans of one step and of several, each with its
        // own check inside.
        if several_steps {
            any_may_reach::<true>(starts, ends, targets, span_s)
        } else {
            any_may_reach::<false>(starts, ends, targets, span_s)
        }
    }

    /// The state at the end of the span of `matrix` (a step or a stride of `run`) from
    /// `self.u` into `self.next`, the row events' values and rates there in
    /// `self.fused_out`.
    #[inline(always)]
    fn run_end_state(&mut self, system: &ModeSystem, run: &RunSpans, matrix: &SpanMatrix) {
        let mechanical = self.model.layout.mechanical();
        products::gathered(
            &matrix.fused,
            system.fused_rows,
            &run.columns,
            &self.u,
            &mut self.fused_out,
        );
        products::copy_short(&mut self.next[..mechanical], &self.fused_out[..mechanical]);
        // None move with the set speed at zero and nothing ramping.
        if !run.moving.is_empty() {
            products::gathered(
                &matrix.forcing,
                run.moving_rows,
                &run.forcing_columns,
                &self.u,
                &mut self.forcing_out,
            );
            run.set_moving(&self.forcing_out, &mut self.next);
        }
    }

    /// The first sample the fast run may not take: `limit` on, the next stretch of set
    /// points or the next check of bounds, whichever comes first (past the current one).
    fn fast_stop(&self, limit: u64) -> u64 {
        (self.sample + limit).min(self.run_bound())
    }

    /// The first sample no fast run may take, whatever its limit: the next stretch of set
    /// points or the next check of bounds, whichever comes first (past the current one).
    fn run_bound(&self) -> u64 {
        let check = super::network_plant::CHECK_EVERY;
        let bound = (self.sample / check + 1) * check;
        self.segment_end.map_or(bound, |end| bound.min(end))
    }

    /// Each switching function's target now, into `self.targets` (they move only at
    /// switches, so they hold for a fast run, and on the exact path after it until the
    /// next switch, `stepping.rs`).
    pub(super) fn fill_targets(&mut self, system: &ModeSystem) {
        let mut targets = std::mem::take(&mut self.targets);
        targets.clear();
        targets.extend(system.events.iter().map(|form| self.target(form)));
        self.targets = targets;
    }
}

/// Whether any switching function of values and rates `starts` and `ends` at a span's
/// ends may reach its target (`targets`) over the span of `span_s` (of several steps if
/// `SEVERAL`, [`SpanGaps::may_reach`]). The cheap bound ([`SpanGaps::surely_short`]) is
/// taken for every function first, without a branch, so that it runs on several at once;
/// only where it leaves one undecided does the full rule run, function by function.
#[inline(always)]
fn any_may_reach<const SEVERAL: bool>(
    starts: &[(f64, f64)],
    ends: &[(f64, f64)],
    targets: &[f64],
    span_s: f64,
) -> bool {
    let gaps = || {
        (starts.iter().zip(ends).zip(targets))
            .map(|((&start, &end), &target)| SpanGaps::of(start, end, target, span_s))
    };
    let undecided = gaps().fold(false, |any, gaps| any | !gaps.surely_short(SEVERAL));
    undecided && gaps().any(|gaps| gaps.may_reach(SEVERAL))
}
