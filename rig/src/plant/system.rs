//! Per mode: A, e^{A h} and the switching functions (kept by `system_cache.rs` from the
//! mode's first use until the set points' rates change).

use nalgebra::DMatrix;

use crate::matrix_exp::{exp_powers_balanced, forcing_scales, spectral_radius};
use crate::stride::{MIN_RECORDED_STRIDE, stride_steps, takes_whole_periods};

use super::events::{EventForm, event_forms};
use super::mode::NetMode;
use super::model::{NetworkModel, SegmentRates};
use super::output::OutputForms;
use super::span_ends::{EndRead, SharedAngle, SpanEnds, meshes_share_an_angle, span_ends};
use super::sparse_rows::SparseRows;

/// e^{A τ} of one mode over one span τ (a step, or a stride of steps), as its products
/// take it.
#[derive(Clone, Debug)]
pub struct SpanMatrix {
    /// Column-major with `fused_rows` rows a column (see [`ModeSystem::fused_rows`]): the
    /// mechanical rows of e^{A τ}, then the value and the rate of each row event (a
    /// switching function of fixed target) side by side at the span's end; one column per
    /// state, or, folded for a fast run, per state its `RunSpans` reads. An inside span of
    /// a recorded stride ([`ModeSystem::inside`]) has the mechanical rows alone
    /// ([`ModeSystem::mechanical_rows`]).
    pub fused: Vec<f64>,
    /// The forcing block of e^{A τ} (rows and columns of the forcing states),
    /// column-major with `forcing_rows` rows a column. The forcing states evolve by
    /// themselves, the same in every mode.
    pub forcing: Vec<f64>,
}

/// A stride: several internal steps taken as one where the mode's fastest motion is slow
/// against the step (ρ·m·h ≤ [`crate::stride::MAX_RHO_STRIDE`]: mostly with every mesh
/// apart, but a soft mesh in contact may qualify), by a settling run that writes no
/// samples, and by one that does where it is [`crate::stride::MIN_RECORDED_STRIDE`]
/// output periods or more (`record_stride.rs`).
#[derive(Clone, Debug)]
pub struct Stride {
    /// Internal steps it takes (whole output periods, a power of two of them; at least 2).
    pub steps: u32,
    /// e^{A m h} for m = `steps`.
    pub matrix: SpanMatrix,
}

/// One mode's linear system.
#[derive(Clone, Debug)]
pub struct ModeSystem {
    /// A of u' = A u (1/s), in blocks of four rows over the columns where a block has an
    /// entry, as many rows as the layout's padded length (`sparse_rows.rs`).
    pub a: SparseRows,
    /// A's spectral radius (rad/s): the fastest motion of the mode, which sets the order of
    /// its Taylor expansions.
    pub rho_rad_s: f64,
    /// e^{A h}, the internal step.
    pub step: SpanMatrix,
    /// The stride of this mode, if its fastest motion is slow enough for one.
    pub stride: Option<Stride>,
    /// e^{A T} over one output period of several steps, if the mode's fastest motion is
    /// slow enough for the period to be checked as one span: a run that writes samples
    /// takes a period in one product where no switch may fall in it.
    pub period: Option<SpanMatrix>,
    /// Where the stride is k ≥ [`crate::stride::MIN_RECORDED_STRIDE`] whole output periods
    /// T: e^{A j T} for j = 1 … k − 1, the samples inside a stride a run that writes
    /// samples takes (`record_stride.rs`), each from the stride's first state. Their `fused` holds the mechanical rows alone
    /// ([`Self::mechanical_rows`]): no switch is checked inside a stride.
    pub inside: Vec<SpanMatrix>,
    /// Rows of each column of an `inside` span's `fused`: the mechanical states, rounded
    /// up to a multiple of 4.
    pub mechanical_rows: usize,
    /// Rows of each column of a span's `fused` (a multiple of 4).
    pub fused_rows: usize,
    /// Per switching function, how its value and rate at a span's end are read from the
    /// end rows: a row event's from the fused rows, a function of the set rotation's (its
    /// target moves, so it is not a row) from the row of one of `angles`
    /// (`span_ends.rs`).
    pub ends: Vec<EndRead>,
    /// The distinct angles the functions of the set rotation read.
    pub angles: Vec<SharedAngle>,
    /// Whether functions of two or more meshes read one of `angles`
    /// ([`meshes_share_an_angle`]): after a switch, the exact path looks first for
    /// another due at the same instant (`stepping.rs`).
    pub meshes_share_an_angle: bool,
    /// Rows of each column of a span's `forcing` (the forcing states, rounded up to a
    /// multiple of 4).
    pub forcing_rows: usize,
    /// The switching functions.
    pub events: Vec<EventForm>,
    /// The signals a sample writes, as linear forms of the state.
    pub outputs: OutputForms,
}

impl ModeSystem {
    /// Rows of a span's end: the fused rows, then each distinct angle's value and rate.
    pub fn end_rows(&self) -> usize {
        self.fused_rows + 2 * self.angles.len()
    }

    /// Writes each distinct angle (`span_ends.rs`) at the state `next` into the end rows
    /// after the fused rows, `end_rows` (at least [`Self::end_rows`] long): every
    /// function's end is then read from them.
    #[inline(always)]
    pub fn write_angle_rows(&self, next: &[f64], end_rows: &mut [f64]) {
        let rows = end_rows[self.fused_rows..self.end_rows()].chunks_exact_mut(2);
        for (row, angle) in rows.zip(&self.angles) {
            (row[0], row[1]) = angle.value_rate(next);
        }
    }

    /// Each distinct angle at the state `u` (its unit state at index `unit`) written into
    /// `end_rows` (whose fused rows hold the span's end), then every switching function's
    /// value and rate read from them into `out`.
    #[inline(always)]
    pub fn read_ends(
        &self,
        u: &[f64],
        unit: usize,
        end_rows: &mut [f64],
        out: &mut Vec<(f64, f64)>,
    ) {
        self.write_angle_rows(u, end_rows);
        let unit = u[unit];
        out.clear();
        out.extend(self.ends.iter().map(|read| read.read(end_rows, unit)));
    }

    /// Each switching function's value and rate at the state `u` (its unit state at index
    /// `unit`) into `out`, read as at a span's end ([`Self::read_ends`]) from `end_rows`
    /// (scratch, grown to [`Self::end_rows`]), its fused rows filled here with each row
    /// event's own sums: the values [`EventForm::value`] and [`EventForm::rate`] give
    /// (but for the sign of an exact zero of a function that reads its angle negated),
    /// each shared angle evaluated once.
    pub fn ends_at(
        &self,
        u: &[f64],
        unit: usize,
        end_rows: &mut Vec<f64>,
        out: &mut Vec<(f64, f64)>,
    ) {
        if end_rows.len() < self.end_rows() {
            end_rows.resize(self.end_rows(), 0.0);
        }
        for (form, read) in self.events.iter().zip(&self.ends) {
            if read.row < self.fused_rows {
                end_rows[read.row] = form.value(u);
                end_rows[read.row + 1] = form.rate(u);
            }
        }
        self.read_ends(u, unit, end_rows, out);
    }

    /// The system of `mode` of `model` for set points of `rates`, stepped by `step_s`
    /// (`substeps` steps an output period), its matrices balanced for ρ = `rho` (rad/s,
    /// the fastest rate of any mode).
    pub fn build(
        model: &NetworkModel,
        mode: &NetMode,
        rates: &SegmentRates,
        (step_s, substeps): (f64, u32),
        rho: f64,
    ) -> Self {
        let a = model.system_matrix(mode, rates);
        let padded = model.layout.padded();
        let rho_rad_s = block_spectral_radius(&a, model.layout.mechanical());
        let steps = stride_steps(rho_rad_s, step_s, substeps);
        let period = takes_whole_periods(rho_rad_s, step_s, substeps).then_some(substeps);
        let spans = exp_spans(model, &a, (step_s, rho), (period, substeps), steps as u32);
        let events = event_forms(model, mode, &a, rates.harmonic_rad_s);
        let a_rows = SparseRows::of_columns(&padded_columns(&a, padded), padded);
        let outputs = OutputForms::of(model, mode, rates.harmonic_rad_s);
        mode_system(model, a_rows, rho_rad_s, &spans, events, outputs)
    }
}

/// A mode's e^{A τ} over its spans: the step, and where the mode allows, an output period
/// of several steps, a stride and the samples inside a recorded stride.
struct ModeSpans {
    step: DMatrix<f64>,
    period: Option<DMatrix<f64>>,
    stride: Option<(u32, DMatrix<f64>)>,
    inside: Vec<DMatrix<f64>>,
}

/// A's spectral radius (rad/s) from its two diagonal blocks, the mechanical states' and
/// the forcing states': the forcing states read only one another, so A is block upper
/// triangular and its eigenvalues are the blocks' together. Two small eigenproblems cost
/// a fraction of the whole one (cubic in the size: a sixth on the 1983 rig). Should a
/// forcing state read a mechanical one, the whole. The two may differ from the whole
/// one's ρ in rounding; ρ only sets thresholds (the Taylor order, strides, whole periods),
/// and the campaign's and the lab campaign's files came out byte-identical.
fn block_spectral_radius(a: &DMatrix<f64>, mechanical: usize) -> f64 {
    let n = a.nrows();
    let lower_left = a.view((mechanical, 0), (n - mechanical, mechanical));
    if lower_left.iter().any(|&x| x != 0.0) {
        return spectral_radius(a);
    }
    let block = |from: usize| a.view((from, from), (n - from, n - from));
    let mechanical_block = a.view((0, 0), (mechanical, mechanical)).clone_owned();
    spectral_radius(&mechanical_block).max(spectral_radius(&block(mechanical).clone_owned()))
}

/// The system of a mode from its A (`a`, spectral radius `rho_rad_s`), its e^{A τ}
/// over its spans (`spans`), its switching functions and its signals.
fn mode_system(
    model: &NetworkModel,
    a: SparseRows,
    rho_rad_s: f64,
    spans: &ModeSpans,
    events: Vec<EventForm>,
    outputs: OutputForms,
) -> ModeSystem {
    let l = &model.layout;
    let SpanEnds {
        reads: ends,
        rows: forms,
        angles,
        fused_rows,
    } = span_ends(&events, l.mechanical(), l.phase(), l.unit());
    let forcing_rows = (l.len() - l.mechanical()).div_ceil(4) * 4;
    let mechanical_rows = l.mechanical().div_ceil(4) * 4;
    let matrix = |span: &DMatrix<f64>| span_matrix(model, span, &forms, fused_rows, forcing_rows);
    let step = matrix(&spans.step);
    let stride = spans.stride.as_ref().map(|(steps, span)| Stride {
        steps: *steps,
        matrix: matrix(span),
    });
    ModeSystem {
        a,
        rho_rad_s,
        step,
        stride,
        period: spans.period.as_ref().map(matrix),
        inside: (spans.inside.iter())
            .map(|span| span_matrix(model, span, &[], mechanical_rows, forcing_rows))
            .collect(),
        mechanical_rows,
        fused_rows,
        meshes_share_an_angle: meshes_share_an_angle(&events, &ends, fused_rows),
        ends,
        angles,
        forcing_rows,
        events,
        outputs,
    }
}

/// The products' form of e^{A τ} = `span`: its fused rows (mechanical rows, then the row
/// events' value and rate side by side, by `forms`) and its forcing block.
fn span_matrix(
    model: &NetworkModel,
    span: &DMatrix<f64>,
    forms: &[&EventForm],
    fused_rows: usize,
    forcing_rows: usize,
) -> SpanMatrix {
    let l = &model.layout;
    let mechanical = l.mechanical();
    let mut fused = vec![0.0; fused_rows * l.padded()];
    let times_span = |terms: &[(usize, f64)], col: usize| -> f64 {
        terms.iter().map(|&(i, c)| c * span[(i, col)]).sum()
    };
    for col in 0..span.ncols() {
        let column = &mut fused[col * fused_rows..(col + 1) * fused_rows];
        for (row, entry) in column[..mechanical].iter_mut().enumerate() {
            *entry = span[(row, col)];
        }
        for (j, form) in forms.iter().enumerate() {
            column[mechanical + 2 * j] = times_span(&form.terms, col);
            column[mechanical + 2 * j + 1] = times_span(&form.slope, col);
        }
    }
    let forcing = span.nrows() - mechanical;
    let mut forcing_block = vec![0.0; forcing_rows * forcing];
    for col in 0..forcing {
        for row in 0..forcing {
            forcing_block[col * forcing_rows + row] = span[(mechanical + row, mechanical + col)];
        }
    }
    SpanMatrix {
        fused,
        forcing: forcing_block,
    }
}

/// `m`'s columns, each padded with zeros to `padded` rows.
fn padded_columns(m: &DMatrix<f64>, padded: usize) -> Vec<f64> {
    let mut out = vec![0.0; m.ncols() * padded];
    for (c, column) in m.column_iter().enumerate() {
        out[c * padded..c * padded + m.nrows()].copy_from_slice(column.as_slice());
    }
    out
}

/// e^{A h} (1 step), e^{A T} over an output period of `period` steps where given, and,
/// where `steps` > 1, e^{A m h} (m = `steps`) and, where m is k ≥ [`MIN_RECORDED_STRIDE`]
/// output periods of `substeps` steps, e^{A j T} for j = 1 … k − 1 (the samples inside
/// it), balanced as the 1983 plant's: angles and the integral at 1, speeds and the filtered speed at ρ, forcing states scaled to ρ, the
/// two states of each harmonic pair alike.
fn exp_spans(
    model: &NetworkModel,
    a: &DMatrix<f64>,
    (step_s, rho): (f64, f64),
    (period, substeps): (Option<u32>, u32),
    steps: u32,
) -> ModeSpans {
    let l = &model.layout;
    let rho = rho.max(1.0);
    let mechanical: Vec<f64> = (0..l.mechanical())
        .map(|i| {
            if (l.speed(0)..l.speed(0) + l.coordinates).contains(&i) || i == l.filtered() {
                rho
            } else {
                1.0
            }
        })
        .collect();
    let mut scale = forcing_scales(a, &mechanical, rho);
    // Each harmonic pair turns one state into the other: one scale for both, else the
    // balanced rotation's entries would be as large as their ratio.
    let pairs = l.harmonics();
    let starts = std::iter::once(l.oscillating()).chain(pairs.iter().map(|p| p.0));
    for pair in starts {
        let shared = scale[pair].max(scale[pair + 1]);
        scale[pair] = shared;
        scale[pair + 1] = shared;
    }
    let count = steps.max(period.unwrap_or(1)) as usize;
    let powers = exp_powers_balanced(a, step_s, &scale, count);
    let power = |k: u32| powers[k as usize - 1].clone();
    let substeps = substeps.max(1);
    let whole_periods = steps.is_multiple_of(substeps) && steps / substeps >= MIN_RECORDED_STRIDE;
    let samples = if whole_periods { steps / substeps } else { 1 };
    ModeSpans {
        step: power(1),
        period: period.map(power),
        stride: (steps > 1).then(|| (steps, power(steps))),
        inside: (1..samples).map(|j| power(j * substeps)).collect(),
    }
}

/// The fastest rate (rad/s) of `model`: A's spectral radius with every mesh on its drive
/// flank with two pairs where pairs alternate (the stiffest mode).
pub fn fastest_rate(model: &NetworkModel) -> f64 {
    let mut mode = NetMode::apart(model.meshes.len());
    for (state, m) in mode.meshes.iter_mut().zip(&model.meshes) {
        state.contact = super::mode::Contact::Drive;
        state.level = if m.alternating {
            crate::mode::PairZone::TWO
        } else {
            crate::mode::PairZone::ONE
        };
    }
    let a = model.system_matrix(&mode, &SegmentRates::default());
    if a.iter().all(|x| x.is_finite()) {
        spectral_radius(&a)
    } else {
        f64::INFINITY
    }
}
