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

/// A bracket [0, b] narrower than this, p(b) > 0 and p(0) ≥ 0: the crossing is at the
/// step's start. No polynomial of a step's Taylor expansion dips below 0 within 1e-20 of a
/// step (its coefficients would have to differ by 1e20 from one order to the next).
const DUE_NOW: f64 = 1e-20;

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
    for _ in 0..100 {
        let (value, slope) = poly_eval(coeffs, s);
        if value > 0.0 {
            b = s;
        } else {
            a = s;
        }
        if due_now && a == 0.0 && b < DUE_NOW {
            return f64::from_bits(1);
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
            return f64::from_bits(1);
        }
    }
    b
}

/// Whether a cubic through (0, g0, d0) and (1, g1, d1) (values and slopes in s) may exceed 0 in (0, 1).
///
/// Used before any expensive search: true on a sign change or when the Hermite cubic's
/// interior maximum lies within a safety margin of zero.
#[inline(always)]
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A crossing due at the step's start (p(0) = 0, rising: a zone boundary another
    /// planet's mesh crossed at the same instant) is found there, at the least positive
    /// s; one inside the step where the secant and Newton say.
    #[test]
    fn crossings_at_the_start_and_inside() {
        let due = [0.0, 8.1e-5, -5.1e-10, 4.0e-12];
        assert_eq!(first_crossing(&due), Some(f64::from_bits(1)));
        // p = s − 0.3: crosses at 0.3 (the bracket's right end, within 64 ulps).
        let inside = first_crossing(&[-0.3, 1.0]).expect("a crossing");
        assert!(
            inside > 0.3 && inside - 0.3 < 64.0 * f64::EPSILON,
            "{inside}"
        );
        // Falling from 0: no crossing.
        assert_eq!(first_crossing(&[0.0, -1.0]), None);
    }
}
