//! The Taylor expansion of e^{A τ} within a step: its order and its coefficients.

/// Highest Taylor order kept; with ρ·h ≤ 0.5 the remainder of order 16 is below 1e-17.
pub const TAYLOR_ORDER: usize = 16;

/// Largest ρ·h (spectral radius of A times the internal step) the Taylor expansion is used at.
pub const MAX_RHO_H: f64 = 0.5;

/// 1/k for k = 0..=TAYLOR_ORDER (1/0 taken as 0, never used).
pub(crate) const RECIPROCALS: [f64; TAYLOR_ORDER + 1] = {
    let mut r = [0.0; TAYLOR_ORDER + 1];
    let mut k = 1;
    while k <= TAYLOR_ORDER {
        r[k] = 1.0 / k as f64;
        k += 1;
    }
    r
};

/// Taylor order K whose remainder (ρτ)^(K+1)/(K+1)! is below 1e-16 (the rounding of the
/// state itself) for a span τ of a mode of spectral radius ρ, `rho_span` = ρτ (rad); at
/// least 4, at most [`TAYLOR_ORDER`].
pub fn taylor_order(rho_span: f64) -> usize {
    let x = rho_span;
    let mut term = x;
    (1..TAYLOR_ORDER)
        .find(|&k| {
            term *= x * RECIPROCALS[k + 1];
            term < 1e-16
        })
        .map_or(TAYLOR_ORDER, |k| k + 1)
        .max(4)
}
