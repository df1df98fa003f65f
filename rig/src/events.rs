//! Switching functions: linear functions of the augmented state whose sign change ends
//! a linear segment, and the location of their first crossing.

use nalgebra::DMatrix;

use crate::layout::{Layout, REV, UNIT, V0, VF, X0, Z};
use crate::mode::{MeshMode, Mode, MotorMode};
use crate::model::ModelConstants;
use crate::options::ContactLaw;

/// What a crossing means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// Apart → drive-flank contact (an impact).
    TouchDrive,
    /// Apart → back-flank contact (an impact).
    TouchBack,
    /// Drive-flank overlap ends: teeth apart.
    LeaveDrive,
    /// Back-flank overlap ends.
    LeaveBack,
    /// No-pull law: drive-flank torque reaches zero while the teeth still overlap.
    DriveUnloads,
    /// No-pull law: clipped drive-flank torque becomes positive again.
    DriveReloads,
    /// No-pull law: back-flank torque reaches zero.
    BackUnloads,
    /// No-pull law: clipped back-flank torque becomes positive again.
    BackReloads,
    /// The driving gear turns past the end of the current pair zone.
    ZoneEnd,
    /// The driving gear turns back past the start of the current pair zone.
    ZoneStart,
    /// Controller output reaches +limit.
    LimitHigh,
    /// Controller output reaches −limit.
    LimitLow,
    /// Controller output comes back inside the limits.
    LimitRelease,
    /// The driving gear turns past the next tooth boundary.
    ToothPass,
    /// The driving gear turns past the next whole revolution.
    Revolution,
}

/// Terms a form evaluates unrolled; most switching functions have at most this many.
const SMALL_TERMS: usize = 4;

/// A sparse linear form over the augmented state.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SparseRow {
    /// (index, coefficient) pairs.
    pub terms: Vec<(usize, f64)>,
    /// The same terms padded with zeros, when there are at most four (evaluated unrolled).
    small: Option<[(usize, f64); SMALL_TERMS]>,
}

impl SparseRow {
    fn new(terms: &[(usize, f64)]) -> Self {
        let terms: Vec<(usize, f64)> = terms.iter().copied().filter(|&(_, c)| c != 0.0).collect();
        let small = (terms.len() <= SMALL_TERMS)
            .then(|| std::array::from_fn(|k| terms.get(k).copied().unwrap_or((0, 0.0))));
        Self { terms, small }
    }

    /// Value of the form at `u`.
    #[inline(always)]
    pub fn dot(&self, u: &[f64]) -> f64 {
        match &self.small {
            Some(t) => {
                t[0].1 * u[t[0].0] + t[1].1 * u[t[1].0] + t[2].1 * u[t[2].0] + t[3].1 * u[t[3].0]
            }
            None => self.terms.iter().map(|&(i, c)| c * u[i]).sum(),
        }
    }

    /// The form c·A, i.e. the time derivative of c·u along u' = A u.
    fn times(&self, a: &DMatrix<f64>) -> Self {
        let terms: Vec<(usize, f64)> = (0..a.ncols())
            .map(|col| (col, self.terms.iter().map(|&(i, c)| c * a[(i, col)]).sum()))
            .collect();
        Self::new(&terms)
    }

    fn negated(&self) -> Self {
        let terms: Vec<(usize, f64)> = self.terms.iter().map(|&(i, c)| (i, -c)).collect();
        Self::new(&terms)
    }
}

/// One switching function g(u, τ) = value·u + sign·(φ(τ) − target) for angle events.
///
/// The segment ends when g crosses from ≤ 0 to > 0.
#[derive(Clone, Debug, PartialEq)]
pub struct EventFn {
    /// What the crossing means.
    pub kind: EventKind,
    /// g's linear form over u.
    pub value: SparseRow,
    /// dg/dt's linear form over u (c·A).
    pub slope: SparseRow,
    /// For angle events: +1 when g grows with the driving gear's angle θ2 = φ + X2, −1 when it falls.
    pub angle_sign: f64,
}

/// The switching functions active in `mode`.
pub fn mode_events(
    mc: &ModelConstants,
    layout: &Layout,
    law: ContactLaw,
    flags: EventFlags,
    mode: Mode,
    a: &DMatrix<f64>,
    rotation_rad_s: f64,
) -> Vec<EventFn> {
    let (k, c) = mc.mesh_spring(mode.pairs);
    let b0 = mc.half_backlash_rad;
    let bc = b0 * mc.backlash_variation;
    let (x2, x3, v2, v3) = (X0 + 1, X0 + 2, V0 + 1, V0 + 2);
    // The transmission error E cos φ moves both flanks' contact the same way: it adds to
    // the drive flank's overlap and takes from the back flank's.
    let e = mc.te_once_rad;
    let (rev_drive, rev_back) = (bc + e, bc - e);
    let mut gap_drive = vec![(x2, 1.0), (x3, -1.0), (UNIT, -b0), (REV, rev_drive)];
    let mut gap_back = vec![(x2, -1.0), (x3, 1.0), (UNIT, -b0), (REV, rev_back)];
    // Pushing torque K δ + C δ' of each flank; δ' includes the rates of B₀C1 cos φ and E cos φ.
    let mut force_drive = vec![
        (x2, k),
        (x3, -k),
        (UNIT, -k * b0),
        (REV, k * rev_drive),
        (v3, -c),
        (v2, c),
        (REV + 1, -c * rev_drive * rotation_rad_s),
    ];
    let mut force_back = vec![
        (x2, -k),
        (x3, k),
        (UNIT, -k * b0),
        (REV, k * rev_back),
        (v3, c),
        (v2, -c),
        (REV + 1, -c * rev_back * rotation_rad_s),
    ];
    // The profile error P cos zφ, like E cos φ: to the drive flank's overlap, from the back's.
    if let Some(mesh) = layout.mesh {
        let p = mc.te_mesh_rad;
        let p_rate = p * mc.teeth * rotation_rad_s;
        for (flank, gap, force) in [
            (1.0, &mut gap_drive, &mut force_drive),
            (-1.0, &mut gap_back, &mut force_back),
        ] {
            gap.push((mesh, flank * p));
            force.extend([(mesh, flank * k * p), (mesh + 1, -flank * c * p_rate)]);
        }
    }
    // The spacing error s of the pair in mesh, a displacement like the others (constant
    // between tooth passes: no rate).
    if let Some(spacing) = layout.spacing {
        gap_drive.push((spacing, 1.0));
        gap_back.push((spacing, -1.0));
        force_drive.push((spacing, k));
        force_back.push((spacing, -k));
    }
    let limit = mc.torque_limit_nm;
    let (kp, ki) = (mc.kp_nms_per_rad, mc.ki_nm_per_rad);
    let over_high = [(VF, -kp), (Z, ki), (UNIT, -limit)];
    let under_low = [(VF, kp), (Z, -ki), (UNIT, -limit)];
    // At the limit the command is held there; it leaves when the unclamped controller
    // would move it back inside: −(rate of kp·(−VF) + ki·Z) = kp·ωf·(V1 − VF) + ki·VF > 0.
    let wf = mc.filter_rad_s;
    let falls_back = [(V0, kp * wf), (VF, ki - kp * wf)];

    let mut list: Vec<(EventKind, SparseRow, f64)> = Vec::new();
    let mut push = |kind, terms: &[(usize, f64)]| list.push((kind, SparseRow::new(terms), 0.0));
    let no_pull = law == ContactLaw::NoPull;
    match mode.mesh {
        MeshMode::Apart => {
            push(EventKind::TouchDrive, &gap_drive);
            push(EventKind::TouchBack, &gap_back);
        }
        MeshMode::Drive | MeshMode::DriveClipped => {
            let kinds = [
                EventKind::LeaveDrive,
                EventKind::DriveReloads,
                EventKind::DriveUnloads,
            ];
            flank_events(
                &mut push,
                kinds,
                mode.mesh == MeshMode::DriveClipped,
                no_pull,
                &gap_drive,
                &force_drive,
            );
        }
        MeshMode::Back | MeshMode::BackClipped => {
            let kinds = [
                EventKind::LeaveBack,
                EventKind::BackReloads,
                EventKind::BackUnloads,
            ];
            flank_events(
                &mut push,
                kinds,
                mode.mesh == MeshMode::BackClipped,
                no_pull,
                &gap_back,
                &force_back,
            );
        }
    }
    match mode.motor {
        MotorMode::Linear => {
            push(EventKind::LimitHigh, &over_high);
            push(EventKind::LimitLow, &under_low);
        }
        MotorMode::LimitHigh => push(EventKind::LimitRelease, &falls_back),
        MotorMode::LimitLow => push(
            EventKind::LimitRelease,
            &SparseRow::new(&falls_back).negated().terms,
        ),
    }
    let angle = [(x2, 1.0)];
    let engaged = matches!(mode.mesh, MeshMode::Drive | MeshMode::Back);
    if flags.alternating_pairs && engaged {
        list.push((EventKind::ZoneEnd, SparseRow::new(&angle), 1.0));
        list.push((EventKind::ZoneStart, SparseRow::new(&angle).negated(), -1.0));
    }
    // Apart, a tooth pass changes nothing unless the pairs differ in spacing: without
    // spacing errors the plant catches up with it at the next contact.
    if flags.spacing_errors || (flags.tooth_shifting && mode.mesh != MeshMode::Apart) {
        list.push((EventKind::ToothPass, SparseRow::new(&angle), 1.0));
    }
    list.push((EventKind::Revolution, SparseRow::new(&angle), 1.0));
    list.into_iter()
        .map(|(kind, value, angle_sign)| EventFn {
            kind,
            slope: value.times(a),
            value,
            angle_sign,
        })
        .collect()
}

/// The switching functions while one flank overlaps: the overlap ending (`kinds[0]`), and
/// with the no-pull law the clipped torque coming back (`kinds[1]`) or the torque
/// reaching zero (`kinds[2]`).
fn flank_events(
    push: &mut impl FnMut(EventKind, &[(usize, f64)]),
    kinds: [EventKind; 3],
    clipped: bool,
    no_pull: bool,
    gap: &[(usize, f64)],
    force: &[(usize, f64)],
) {
    push(kinds[0], &SparseRow::new(gap).negated().terms);
    if clipped {
        push(kinds[1], force);
    } else if no_pull {
        push(kinds[2], &SparseRow::new(force).negated().terms);
    }
}

/// Which optional switching functions exist in this plant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EventFlags {
    /// Pair-zone boundaries (contact ratio > 1).
    pub alternating_pairs: bool,
    /// Tooth-pass instants while the teeth touch (numerical tooth shifting).
    pub tooth_shifting: bool,
    /// Tooth-pass instants in every mode (the spacing error of the pair in mesh changes).
    pub spacing_errors: bool,
}

/// Evaluates a polynomial Σ c_k s^k and its derivative at `s` (Horner).
pub fn poly_eval(coeffs: &[f64], s: f64) -> (f64, f64) {
    let mut value = 0.0;
    let mut slope = 0.0;
    for &c in coeffs.iter().rev() {
        slope = slope * s + value;
        value = value * s + c;
    }
    (value, slope)
}

/// Subintervals of [0, 1] scanned for the first crossing: a step spans at most ρh ≤ 0.5 rad
/// of the fastest motion, so each quarter holds at most one extremum.
const SCAN: usize = 4;

/// First s in (0, 1] where the polynomial crosses from ≤ 0 to > 0, taking p(0) as ≤ 0.
///
/// Scans [0, 1] in 4 parts; in each, a sign change or an interior maximum above zero
/// (found where p' changes sign) brackets the crossing, which is then refined to full
/// precision. Returns the right end of the final bracket, where p > 0.
pub fn first_crossing(coeffs: &[f64]) -> Option<f64> {
    let (value_0, mut slope_a) = poly_eval(coeffs, 0.0);
    let mut value_a = value_0.min(0.0);
    let mut s_a = 0.0;
    let width = 1.0 / SCAN as f64;
    for j in 1..=SCAN {
        let s_b = j as f64 * width;
        let (value_b, slope_b) = poly_eval(coeffs, s_b);
        if value_b > 0.0 {
            return Some(refine(coeffs, (s_a, value_a), (s_b, value_b)));
        }
        // An interior maximum above zero needs p' to turn from + to −, and (the quarter
        // being near-cubic) a Hermite cubic through the ends that comes near zero.
        if slope_a > 0.0
            && slope_b < 0.0
            && may_cross(value_a, slope_a * width, value_b, slope_b * width)
        {
            let s_max = slope_root(coeffs, s_a, s_b);
            let value_max = poly_eval(coeffs, s_max).0;
            if value_max > 0.0 {
                return Some(refine(coeffs, (s_a, value_a), (s_max, value_max)));
            }
        }
        s_a = s_b;
        value_a = value_b;
        slope_a = slope_b;
    }
    None
}

/// Bisection for p' = 0 in [a, b] with p'(a) > 0 > p'(b).
///
/// 32 halvings place the maximum within 2⁻³² of the interval; p is flat there, so its value
/// (all that is used) is exact to rounding.
fn slope_root(coeffs: &[f64], mut a: f64, mut b: f64) -> f64 {
    for _ in 0..32 {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        if poly_eval(coeffs, mid).1 > 0.0 {
            a = mid;
        } else {
            b = mid;
        }
    }
    0.5 * (a + b)
}

/// Narrows [a, b] with p(a) = `value_a` ≤ 0 < p(b) = `value_b` to within 64 ulps of the
/// crossing (far below any time the model resolves): Newton steps from the secant point,
/// kept inside the bracket. Returns its right end, where p > 0.
fn refine(coeffs: &[f64], (mut a, value_a): (f64, f64), (mut b, value_b): (f64, f64)) -> f64 {
    let secant = a + (b - a) * (value_a / (value_a - value_b));
    let mut s = if secant > a && secant < b {
        secant
    } else {
        0.5 * (a + b)
    };
    for _ in 0..100 {
        let (value, slope) = poly_eval(coeffs, s);
        if value > 0.0 {
            b = s;
        } else {
            a = s;
        }
        let close = 16.0 * f64::EPSILON * b;
        if b - a <= 4.0 * close {
            return b;
        }
        // Newton inside the bracket; where it lands within `close` of the end it started
        // from on a rising p (as where p is exactly 0 at a), a probe just inside that end
        // closes the bracket at once; otherwise bisection.
        let newton = s - value / slope;
        s = if newton > a + close && newton < b - close {
            newton
        } else if slope > 0.0 && s == a && newton <= a + close {
            a + close
        } else if slope > 0.0 && s == b && newton >= b - close {
            b - close
        } else {
            0.5 * (a + b)
        };
    }
    // Should Newton fail to close in, bisection finishes the job.
    while b - a > 64.0 * f64::EPSILON * b {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        if poly_eval(coeffs, mid).0 > 0.0 {
            b = mid;
        } else {
            a = mid;
        }
    }
    b
}

/// Whether a cubic through (0, g0, d0) and (1, g1, d1) (values and slopes in s) may exceed 0 in (0, 1).
///
/// Used before any expensive search: true on a sign change or when the Hermite cubic's
/// interior maximum lies within a safety margin of zero.
#[inline]
pub fn may_cross(g0: f64, d0: f64, g1: f64, d1: f64) -> bool {
    if g1 > 0.0 {
        return true;
    }
    if !(d0 > 0.0 && d1 < 0.0) {
        return false;
    }
    let margin = 0.25 * (g0.abs() + g1.abs() + d0.abs() + d1.abs());
    // The cubic departs from the chord by s(1−s)[(1−s)(d0 − Δ) − s(d1 − Δ)], Δ = g1 − g0,
    // at most (|d0 − Δ| + |d1 − Δ|)/4: a cheap bound that settles most cases.
    let delta = g1 - g0;
    if g0.max(g1) + 0.25 * ((d0 - delta).abs() + (d1 - delta).abs()) <= -margin {
        return false;
    }
    // Hermite cubic p(s) = g0 + d0 s + c2 s² + c3 s³.
    let c2 = 3.0 * delta - 2.0 * d0 - d1;
    let c3 = -2.0 * delta + d0 + d1;
    hermite_max(g0, d0, c2, c3) > -margin
}

/// Largest value on (0, 1) of g0 + d0 s + c2 s² + c3 s³ given d0 > 0 > p'(1): at the root
/// of p'(s) = d0 + 2 c2 s + 3 c3 s² where p' turns from positive to negative.
fn hermite_max(g0: f64, d0: f64, c2: f64, c3: f64) -> f64 {
    let coeffs = [g0, d0, c2, c3];
    let s = if c3.abs() < 1e-12 * (c2.abs() + d0.abs()) {
        -d0 / (2.0 * c2)
    } else {
        let disc = (c2 * c2 - 3.0 * c3 * d0).max(0.0).sqrt();
        // The root where p'' < 0: s = (−c2 − √disc) / (3 c3), written to avoid cancellation.
        let q = -(c2 + c2.signum() * disc);
        let roots = [q / (3.0 * c3), d0 / q];
        roots
            .into_iter()
            .find(|r| (0.0..=1.0).contains(r) && 2.0 * c2 + 6.0 * c3 * r <= 0.0)
            .unwrap_or(0.5)
    };
    poly_eval(&coeffs, s.clamp(0.0, 1.0)).0
}
