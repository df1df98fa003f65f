//! Strides in a run that writes samples: k ≥ 4 output periods checked for switches as one
//! span (the mode's stride, `system.rs`; `stride.rs` bounds it), and the samples inside it
//! each one product from the stride's first state u_a: e^{A j T} u_a, the mechanical rows
//! and the forcing states that move (`ModeSystem::inside`), with no check of its own.
//! So a sample inside a stride costs a product of the mechanical rows alone, and the
//! checks of the switching functions are made once a stride, as the retired thesis plant
//! made them.
//!
//! A stride begins only at a sample that is a whole multiple of k, and one a run leaves
//! unfinished (its block full) is taken on by the next run from the same first state, so
//! that a run gives the same bytes whatever the blocks it is asked for in. The next run
//! takes it on only where nothing has touched the plant since: the same sample, mode and
//! state to the bit, and no new stretch of set points. A stride whose check says a
//! function may cross is taken in single steps (or output periods), as before.

use super::mode::NetMode;
use super::products;
use super::run_spans::RunSpans;
use super::system::ModeSystem;

/// A stride under way in a run that writes samples.
#[derive(Clone, Debug, Default)]
pub struct RecordStride {
    /// Its first sample.
    first: u64,
    /// Its samples, k.
    samples: u64,
    /// The mode it is taken in, while one is under way.
    mode: Option<NetMode>,
    /// The states of its first sample the inside products read, gathered as they read
    /// them (`RunSpans::columns`, `RunSpans::forcing_columns`).
    start_columns: Vec<f64>,
    start_forcing: Vec<f64>,
    /// The state at its end (the sample after its last), and every switching function's
    /// value and rate there.
    end: Vec<f64>,
    end_edge: Vec<(f64, f64)>,
    /// The state a run left it at, unfinished: the next run takes it on only from this
    /// state, to the bit.
    left_at: Vec<f64>,
}

impl RecordStride {
    /// Whether a stride is under way.
    #[inline(always)]
    pub fn is_active(&self) -> bool {
        self.mode.is_some()
    }

    /// Gives up the stride under way, if any.
    pub fn drop_stride(&mut self) {
        self.mode = None;
    }

    /// At a recorded run's start, at `sample` in `mode` from the state `u`: keeps the
    /// stride a run left unfinished only where this run takes it on as it was left (a
    /// sample inside it, its mode, and the state it was left at, to the bit).
    pub fn resume(&mut self, sample: u64, mode: &NetMode, u: &[f64]) {
        let keeps = sample > self.first
            && sample < self.first + self.samples
            && self.mode.as_ref() == Some(mode)
            && self.left_at.len() == u.len()
            && (self.left_at.iter().zip(u)).all(|(a, b)| a.to_bits() == b.to_bits());
        if !keeps {
            self.drop_stride();
        }
    }

    /// Begins a stride of `samples` samples at sample `first` in `mode`, from the state
    /// `u` (its inside products' states gathered as `run` reads them) to `end`, where the
    /// switching functions' values and rates are `end_edge` (the check over it passed).
    #[inline(always)]
    pub fn begin(
        &mut self,
        (first, samples, mode): (u64, u64, NetMode),
        run: &RunSpans,
        u: &[f64],
        (end, end_edge): (&[f64], &[(f64, f64)]),
    ) {
        self.first = first;
        self.samples = samples;
        self.mode = Some(mode);
        self.start_columns.clear();
        self.start_columns.extend(run.columns.iter().map(|&i| u[i]));
        self.start_forcing.clear();
        self.start_forcing
            .extend(run.forcing_columns.iter().map(|&i| u[i]));
        self.end.clear();
        self.end.extend_from_slice(end);
        self.end_edge.clear();
        self.end_edge.extend_from_slice(end_edge);
    }

    /// Moves the state `u` to sample `next` of the stride under way (`mechanical`
    /// mechanical states; `rows` and `forcing` room for the inside products' rows): inside it,
    /// e^{A j T} times its first state (the mechanical states and the moving forcing
    /// states; those that hold keep their values); at its end, its end state, with the
    /// functions' values and rates there into `edge`, and the stride is done.
    #[inline(always)]
    pub fn take_sample(
        &mut self,
        next: u64,
        (system, run): (&ModeSystem, &RunSpans),
        mechanical: usize,
        (u, edge): (&mut Vec<f64>, &mut Vec<(f64, f64)>),
        (rows, forcing): (&mut [f64], &mut [f64]),
    ) {
        let j = (next - self.first) as usize;
        if j as u64 >= self.samples {
            std::mem::swap(u, &mut self.end);
            std::mem::swap(edge, &mut self.end_edge);
            self.drop_stride();
            return;
        }
        let span = &run.inside[j - 1];
        products::dense(
            &span.fused,
            system.mechanical_rows,
            &self.start_columns,
            rows,
        );
        products::copy_short(&mut u[..mechanical], &rows[..mechanical]);
        if !run.moving.is_empty() {
            products::dense(&span.forcing, run.moving_rows, &self.start_forcing, forcing);
            run.set_moving(forcing, u);
        }
    }

    /// At a recorded run's end inside a stride: the state `u` it is left at, so that the
    /// next run takes it on only from there.
    pub fn leave(&mut self, u: &[f64]) {
        self.left_at.clear();
        self.left_at.extend_from_slice(u);
    }
}
