//! Where a polynomial first crosses zero on [0, 1] (the Taylor expansion of a switching
//! function over a step), and whether a cubic Hermite interpolant between two steps may
//! cross: general root finding, apart from what the switching functions are (`events.rs`).

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

/// First s in (0, `before`) where the polynomial crosses from ≤ 0 to > 0, taking p(0)
/// as ≤ 0 (`before` = ∞ for the first crossing on (0, 1]).
///
/// Scans [0, 1] in 4 parts; in each, a sign change or an interior maximum above zero
/// (found where p' changes sign) brackets the crossing, which is then refined to full
/// precision. Returns the right end of the final bracket, where p > 0. A crossing at or
/// after `before` counts for nothing, so the scan stops at the part that starts there,
/// and a bracket across `before` is not refined where p is short of zero at `before`
/// and at 0: the part holds one extremum at most, so p crosses once in the bracket, after
/// `before` (as refining it would find). Where it returns a crossing, it is the one a
/// scan without `before` gives, to the bit: the search for a step's first switch
/// (`plant/stepping.rs`) asks each function after the first that crosses only for a
/// crossing before the best so far (every planet's mesh of an in-phase stage crosses
/// within rounding of the others).
pub fn first_crossing(coeffs: &[f64], before: f64) -> Option<f64> {
    let (value_0, mut slope_a) = poly_eval(coeffs, 0.0);
    let mut value_a = value_0.min(0.0);
    let mut s_a = 0.0;
    let width = 1.0 / SCAN as f64;
    // The crossing in the bracket [a, b], if before `before`: where p is short of zero
    // at 0 and at `before` inside the bracket, its one crossing there is after `before`
    // and is not refined.
    let settle = |(a, value_a): (f64, f64), (b, value_b): (f64, f64)| {
        let after_before = value_0 < 0.0 && before < b && poly_eval(coeffs, before).0 <= 0.0;
        (!after_before)
            .then(|| refine(coeffs, (a, value_a), (b, value_b)))
            .filter(|&s| s < before)
    };
    for j in 1..=SCAN {
        if s_a >= before {
            return None;
        }
        let s_b = j as f64 * width;
        let (value_b, slope_b) = poly_eval(coeffs, s_b);
        if value_b > 0.0 {
            return settle((s_a, value_a), (s_b, value_b));
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
                return settle((s_a, value_a), (s_max, value_max));
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

/// A bracket [0, b] narrower than this, p(b) > 0 and p(0) ≥ 0: the crossing is at the
/// step's start. No polynomial of a step's Taylor expansion dips below 0 within 1e-20 of a
/// step (its coefficients would have to differ by 1e20 from one order to the next).
pub const DUE_NOW: f64 = 1e-20;

/// The crossing [`first_crossing`] gives a function due at the step's start: the least
/// positive number, so that it comes before any other crossing but one also due then.
pub const AT_START: f64 = f64::from_bits(1);

/// Whether a function whose polynomial over a step begins c0 + c1 s is due at the step's
/// start, as [`first_crossing`] finds it ([`AT_START`]), judged from c0 and c1 alone
/// (without the step's whole expansion): `Some(true)` at or past zero (c0 ≥ 0), rising
/// (c1 > 0) and above zero at [`DUE_NOW`]; `Some(false)` short of zero (c0 < 0) or at
/// zero falling (c0 = 0, c1 < 0); `None` where only the whole polynomial tells (past
/// zero but level or falling, or at zero and level). It decides as [`first_crossing`]
/// does where c1 is not small against the later terms: they weigh 10⁻²⁰ less each at
/// [`DUE_NOW`]. Where it is (a function grazing zero, its peak or dip within about
/// 10⁻¹¹ of the step, below what [`first_crossing`] resolves), the whole polynomial may
/// decide otherwise: callers use it only where c1 is a gear's turn over the step.
pub fn due_at_start(c0: f64, c1: f64) -> Option<bool> {
    if c0 < 0.0 || (c0 == 0.0 && c1 < 0.0) {
        Some(false)
    } else if c0 >= 0.0 && c1 > 0.0 && poly_eval(&[c0, c1], DUE_NOW).0 > 0.0 {
        Some(true)
    } else {
        None
    }
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
    // Where p(0) ≥ 0 (an event due at the step's start: simultaneous with the one just
    // taken, or held at 0 by rounding) and p stays above 0 as the bracket closes on 0, it
    // does so all the way down: the bisection would run on to the least positive number
    // (a thousand halvings), which is returned once the bracket is below [`DUE_NOW`].
    let due_now = coeffs.first().is_some_and(|&c| c >= 0.0);
    // Rising from such a start, and above 0 at [`DUE_NOW`]: the crossing is at the start,
    // without the halvings that would close on it (an event simultaneous with another
    // just taken: every planet's mesh of an in-phase stage at once). One at 0 to rounding
    // but falling (a mesh's force just after its impact) crosses later, if at all.
    let rising = coeffs.get(1).is_some_and(|&c| c > 0.0);
    if due_now && rising && a == 0.0 && poly_eval(coeffs, DUE_NOW).0 > 0.0 {
        return AT_START;
    }
    for _ in 0..100 {
        let (value, slope) = poly_eval(coeffs, s);
        if value > 0.0 {
            b = s;
        } else {
            a = s;
        }
        if due_now && a == 0.0 && b < DUE_NOW {
            return AT_START;
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
        if due_now && a == 0.0 && b < DUE_NOW {
            return AT_START;
        }
    }
    b
}

/// Whether a function with values g0, g1 and slopes d0, d1 (in s) at the ends of one
/// step ([0, 1], ρh ≤ 0.5 rad of the fastest motion) may exceed 0 inside it, judged by
/// the cubic Hermite interpolant through them.
///
/// Used before any expensive search: true on a sign change at the end, or where the
/// slopes turn from + to − and the cubic's maximum comes within a safety margin of zero
/// (a quarter of the ends' values and slopes). Over a step a function holds at most one
/// extremum, so a maximum needs those slopes; a function resting at its target to
/// rounding (a mesh at zero load: value and slope 0 at the start) is not taken for one
/// about to cross.
#[inline(always)]
pub fn may_cross(g0: f64, d0: f64, g1: f64, d1: f64) -> bool {
    g1 > 0.0 || (d0 > 0.0 && d1 < 0.0 && cubic_peaks_near_zero(g0, d0, g1, d1, true))
}

/// [`may_cross`] over a span of several steps (a stride or an output period, up to
/// ρτ = [`crate::stride::MAX_RHO_STRIDE`]): any interior maximum of the cubic counts,
/// whatever the slopes' signs at the ends, for a function of several motions may dip
/// and rise again within such a span. Of sampled functions of up to three damped motions,
/// a ramp and a parabola, peaking up to 5 % of their amplitude above zero, it missed none
/// over 1.75 rad and at most one in a thousand over 2 rad, each peaking under 2 % of the
/// amplitude; the step's rule, sound over a step, misses some over 1.5 rad (the test
/// below).
#[inline(always)]
pub fn may_cross_span(g0: f64, d0: f64, g1: f64, d1: f64) -> bool {
    g1 > 0.0 || cubic_peaks_near_zero(g0, d0, g1, d1, false)
}

/// Whether a cheap bound settles that the function cannot cross: [`may_cross`]
/// (`several_steps` false) or [`may_cross_span`] (true) is then false. Branch-free, so
/// that a loop over many functions computes it for several at once; where it is false,
/// the full rule decides.
#[inline(always)]
pub fn surely_short(g0: f64, d0: f64, g1: f64, d1: f64, several_steps: bool) -> bool {
    let no_step_peak = !several_steps & !((d0 > 0.0) & (d1 < 0.0));
    (g1 <= 0.0) & (no_step_peak | chord_bound_short(g0, d0, g1, d1))
}

/// Whether the cubic Hermite interpolant through (0, g0, d0) and (1, g1, d1) stays
/// below minus the margin of [`cubic_peaks_near_zero`] by a cheap bound: the cubic
/// departs from the chord by s(1−s)[(1−s)(d0 − Δ) − s(d1 − Δ)], Δ = g1 − g0, at most
/// (|d0 − Δ| + |d1 − Δ|)/4, which settles most cases.
#[inline(always)]
fn chord_bound_short(g0: f64, d0: f64, g1: f64, d1: f64) -> bool {
    let margin = 0.25 * (g0.abs() + g1.abs() + d0.abs() + d1.abs());
    let delta = g1 - g0;
    g0.max(g1) + 0.25 * ((d0 - delta).abs() + (d1 - delta).abs()) <= -margin
}

/// Whether the cubic Hermite interpolant through (0, g0, d0) and (1, g1, d1) has an
/// interior maximum within a margin of zero: a quarter of the ends' values and slopes.
/// `peak_sure`: the slopes turn from + to −, so a maximum lies in [0, 1] even where
/// rounding puts it at an end (then the higher end stands for it).
#[inline(always)]
fn cubic_peaks_near_zero(g0: f64, d0: f64, g1: f64, d1: f64, peak_sure: bool) -> bool {
    if chord_bound_short(g0, d0, g1, d1) {
        return false;
    }
    let margin = 0.25 * (g0.abs() + g1.abs() + d0.abs() + d1.abs());
    let delta = g1 - g0;
    // Hermite cubic p(s) = g0 + d0 s + c2 s² + c3 s³.
    let c2 = 3.0 * delta - 2.0 * d0 - d1;
    let c3 = -2.0 * delta + d0 + d1;
    let top = interior_max(g0, d0, c2, c3);
    let top = if peak_sure {
        top.or(Some(g0.max(g1)))
    } else {
        top
    };
    top.is_some_and(|top| top > -margin)
}

/// The value at the interior maximum of g0 + d0 s + c2 s² + c3 s³ on (0, 1), if it has
/// one: at a root of p'(s) = d0 + 2 c2 s + 3 c3 s² where p'' < 0.
fn interior_max(g0: f64, d0: f64, c2: f64, c3: f64) -> Option<f64> {
    let is_max = |r: f64| r > 0.0 && r < 1.0 && 2.0 * c2 + 6.0 * c3 * r < 0.0;
    let s = if c3.abs() < 1e-12 * (c2.abs() + d0.abs()) {
        Some(-d0 / (2.0 * c2)).filter(|&r| is_max(r))
    } else {
        let disc = c2 * c2 - 3.0 * c3 * d0;
        if disc < 0.0 {
            return None;
        }
        // The roots (−c2 ∓ √disc) / (3 c3), written to avoid cancellation (a 0/0 root is
        // NaN and no maximum).
        let q = -(c2 + c2.signum() * disc.sqrt());
        [q / (3.0 * c3), d0 / q].into_iter().find(|&r| is_max(r))
    };
    s.map(|s| poly_eval(&[g0, d0, c2, c3], s).0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A crossing due at the step's start (p(0) = 0, rising: a zone boundary another
    /// planet's mesh crossed at the same instant) is found there, at the least positive
    /// s; one inside the step where the secant and Newton say.
    #[test]
    fn crossings_at_the_start_and_inside() {
        let due = [0.0, 8.1e-5, -5.1e-10, 4.0e-12];
        assert_eq!(first_crossing(&due, f64::INFINITY), Some(f64::from_bits(1)));
        // p = s − 0.3: crosses at 0.3 (the bracket's right end, within 64 ulps).
        let inside = first_crossing(&[-0.3, 1.0], f64::INFINITY).expect("a crossing");
        assert!(
            inside > 0.3 && inside - 0.3 < 64.0 * f64::EPSILON,
            "{inside}"
        );
        // Falling from 0: no crossing.
        assert_eq!(first_crossing(&[0.0, -1.0], f64::INFINITY), None);
        // At 0 to rounding but falling, then rising through 0 at s = 1/8 within the first
        // quarter (p = 1e-18 − s + 8 s²): the crossing is there, not at the start.
        let later = first_crossing(&[1e-18, -1.0, 8.0], f64::INFINITY).expect("a crossing");
        assert!((later - 0.125).abs() < 1e-12, "{later}");
    }

    /// A crossing sought only before a bound is the whole scan's where the scan's is
    /// before it, to the bit, and none otherwise: Taylor polynomials of steps (up to three
    /// motions of up to ρh = 0.5 rad, a ramp, an offset below zero), bounds anywhere in
    /// the step and within a few ulps of the crossing (another planet's mesh of an
    /// in-phase stage, crossing within rounding of the first).
    #[test]
    fn a_crossing_before_a_bound_is_the_whole_scans() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(2024);
        let (mut crossings, mut skipped) = (0, 0);
        for _ in 0..20_000 {
            let mut c = vec![0.0; 15];
            for _ in 0..rng.random_range(1..=3) {
                let (size, rho_h): (f64, f64) = (rng.random(), rng.random_range(0.01..0.5));
                let phase = rng.random_range(0.0..std::f64::consts::TAU);
                let mut scale = size;
                for (k, ck) in c.iter_mut().enumerate() {
                    let turn = phase + k as f64 * std::f64::consts::FRAC_PI_2;
                    *ck += scale * turn.sin();
                    scale *= rho_h / (k + 1) as f64;
                }
            }
            c[1] += rng.random_range(-0.5..1.0);
            c[0] = -rng.random_range(0.0..0.5);
            let whole = first_crossing(&c, f64::INFINITY);
            let near = whole.map_or(0.5, |s| s);
            let ulps = rng.random_range(-4_i64..=4);
            for before in [
                rng.random_range(0.0..1.0),
                f64::from_bits((near.to_bits() as i64 + ulps) as u64),
            ] {
                let bounded = first_crossing(&c, before);
                assert_eq!(
                    bounded,
                    whole.filter(|&s| s < before),
                    "{c:?} before {before}"
                );
                crossings += usize::from(bounded.is_some());
                skipped += usize::from(whole.is_some() && bounded.is_none());
            }
        }
        // Both outcomes are exercised.
        assert!(crossings > 2000 && skipped > 2000, "{crossings} {skipped}");
    }

    /// Where [`due_at_start`] decides from a polynomial's first two coefficients, it
    /// decides as [`first_crossing`] does from the whole one (due: at [`AT_START`]).
    /// Taylor-like polynomials of a step (c_k of the size of (ρh)^k/k!, ρh ≤ 0.5) that
    /// start at, past or just short of zero, rising or falling, some with a vanishing
    /// slope.
    #[test]
    fn due_at_start_decides_as_the_whole_polynomial() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(47);
        const CASES: usize = 20_000;
        let (mut due, mut undecided) = (0, 0);
        for _ in 0..CASES {
            let rho_h: f64 = rng.random_range(0.01..0.5);
            let mut scale = 1.0;
            let mut c: Vec<f64> = (0..13)
                .map(|k| {
                    if k > 0 {
                        scale *= rho_h / k as f64;
                    }
                    scale * rng.random_range(-1.0..1.0)
                })
                .collect();
            c[0] = match rng.random_range(0..4) {
                0 => 0.0,
                1 => rng.random_range(0.0..1e-15),
                2 => -rng.random_range(0.0..1e-15),
                _ => c[0],
            };
            if rng.random_range(0..8) == 0 {
                c[1] = 0.0;
            }
            let whole = first_crossing(&c, f64::INFINITY) == Some(AT_START);
            match due_at_start(c[0], c[1]) {
                Some(first_two) => assert_eq!(first_two, whole, "{c:?}"),
                None => undecided += 1,
            }
            due += usize::from(whole);
        }
        // Both answers are exercised, and most are decided from two coefficients.
        assert!(due > 1000 && CASES - due > 1000, "{due} of {CASES}");
        assert!(
            undecided < CASES / 4,
            "{undecided} of {CASES} left undecided"
        );
    }

    /// Functions of a span of ρτ rad of the fastest motion: up to three damped motions
    /// (the fastest at ρ, the others slower, of random size and phase), a ramp and a
    /// parabola, shifted to peak up to 5 % of their amplitude above zero with both ends
    /// at or below it. Returns how many crossed and, of those `check` missed, how many
    /// and the highest peak (fraction of the amplitude).
    fn missed_peaks(
        check: fn(f64, f64, f64, f64) -> bool,
        rho_tau: f64,
        trials: usize,
        seed: u64,
    ) -> (usize, usize, f64) {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(seed);
        let points = 1001;
        let (mut crossed, mut missed, mut worst) = (0, 0, 0.0_f64);
        let mut g = vec![0.0; points];
        for _ in 0..trials {
            let motions = rng.random_range(1..=3);
            let mut parts = Vec::new();
            for k in 0..motions {
                let w = if k == 0 {
                    rho_tau
                } else {
                    rho_tau * rng.random::<f64>()
                };
                let size = if k == 0 {
                    1.0
                } else {
                    3.0 * rng.random::<f64>()
                };
                let decay = if rng.random() {
                    w * rng.random::<f64>()
                } else {
                    0.0
                };
                parts.push((size, w, decay, std::f64::consts::TAU * rng.random::<f64>()));
            }
            let ramp = rho_tau * 3.0 * (rng.random::<f64>() - 0.5);
            let bend = rho_tau * rho_tau * (rng.random::<f64>() - 0.5);
            let value = |s: f64| -> (f64, f64) {
                let mut v = (ramp + bend * s) * s;
                let mut d = ramp + 2.0 * bend * s;
                for &(a, w, k, p) in &parts {
                    let (sin, cos) = (w * s + p).sin_cos();
                    v += a * (-k * s).exp() * sin;
                    d += a * (-k * s).exp() * (w * cos - k * sin);
                }
                (v, d)
            };
            for (j, x) in g.iter_mut().enumerate() {
                *x = value(j as f64 / (points - 1) as f64).0;
            }
            let amplitude: f64 = parts.iter().map(|p| p.0).sum();
            let top = g.iter().copied().fold(f64::MIN, f64::max);
            let shift = -top + 0.05 * amplitude * rng.random::<f64>();
            let ((g0, d0), (g1, d1)) = (value(0.0), value(1.0));
            let (g0, g1) = (g0 + shift, g1 + shift);
            if g0 > 0.0 || g1 > 0.0 || top + shift <= 0.0 {
                continue;
            }
            crossed += 1;
            if !check(g0, d0, g1, d1) {
                missed += 1;
                worst = worst.max((top + shift) / amplitude);
            }
        }
        (crossed, missed, worst)
    }

    /// The checks a step and a stride rely on: over a step (0.5 rad) the step's rule
    /// misses none of the sampled functions that peak above zero, but over 1.5 rad it
    /// misses some (those that dip and rise again, their end slopes of one sign); the span's
    /// rule misses none over 1.75 rad (`stride.rs`'s bound) and over 2 rad one in a
    /// thousand at most, none peaking above 2 % of its amplitude.
    #[test]
    fn a_span_check_misses_no_peak_of_a_few_motions() {
        let (crossed, missed, _) = missed_peaks(may_cross, 0.5, 60_000, 10);
        assert!(crossed > 500, "{crossed} crossed");
        assert_eq!(
            missed, 0,
            "the step's rule missed {missed} of {crossed} over 0.5 rad"
        );
        let (crossed, missed, _) = missed_peaks(may_cross, 1.5, 20_000, 15);
        assert!(
            missed > 0,
            "the step's rule missed none of {crossed} over 1.5 rad"
        );
        let (crossed, missed, _) = missed_peaks(may_cross_span, 1.75, 20_000, 15);
        assert!(crossed > 2_000, "{crossed} crossed");
        assert_eq!(missed, 0, "{missed} of {crossed} missed over 1.75 rad");
        let (crossed, missed, worst) = missed_peaks(may_cross_span, 2.0, 20_000, 20);
        assert!(crossed > 2_000, "{crossed} crossed");
        assert!(
            missed * 1000 <= crossed && worst <= 0.02,
            "{missed} of {crossed} missed over 2 rad, peaks to {worst}"
        );
    }
}
