//! Matrix exponentials of a mode's matrix A (balanced Padé) and its spectral radius.

use nalgebra::DMatrix;

/// The largest balancing scale of a forcing state: products of A's entries with it and
/// its inverse stay far from overflow and underflow.
pub const MAX_FORCING_SCALE: f64 = 1e100;

/// The balancing scale of every state: `mechanical` for the first states as given (ρ for
/// speeds, 1 for angles), and for each later (forcing) state the scale that brings its
/// column's largest entry in the mechanical rows to ρ, at most [`MAX_FORCING_SCALE`] (a
/// set speed of 1e-297 rev/min gave a column of 1e-298 and a scale that overflowed).
pub fn forcing_scales(a: &DMatrix<f64>, mechanical: &[f64], rho: f64) -> Vec<f64> {
    let n_mech = mechanical.len();
    (0..a.ncols())
        .map(|c| {
            if c < n_mech {
                return mechanical[c];
            }
            let largest = (0..n_mech)
                .map(|r| a[(r, c)].abs() / mechanical[r])
                .fold(0.0, f64::max);
            if largest > 0.0 {
                (rho / largest).min(MAX_FORCING_SCALE)
            } else {
                1.0
            }
        })
        .collect()
}

/// e^{A k h} for k = 1..=`count`, computed on the balanced matrix D⁻¹AD with
/// D = diag(`scale`), whose entries are all of order ρ or less (D = 1 for angles and the
/// controller integral, ρ for speeds, and for each forcing state the scale that brings
/// its column's largest entry to ρ: [`forcing_scales`]). The Padé exponential of the
/// balanced matrix is then accurate to rounding in every entry, not only relative to the
/// largest (K/J·h ≈ 3000 for the mesh), and the constant forcing adds no bias; its powers
/// are taken there too.
pub fn exp_powers_balanced(
    a: &DMatrix<f64>,
    step_s: f64,
    scale: &[f64],
    count: usize,
) -> Vec<DMatrix<f64>> {
    let len = a.nrows();
    let balanced = DMatrix::from_fn(len, len, |r, c| a[(r, c)] * scale[c] / scale[r] * step_s);
    let exp = balanced.exp();
    let mut power = exp.clone();
    let mut powers = Vec::with_capacity(count);
    for k in 1..=count {
        if k > 1 {
            power = &exp * &power;
        }
        powers.push(DMatrix::from_fn(len, len, |r, c| {
            power[(r, c)] * scale[r] / scale[c]
        }));
    }
    powers
}

/// Spectral radius of `a` (rad/s): the fastest rate the Taylor expansion must resolve.
pub fn spectral_radius(a: &DMatrix<f64>) -> f64 {
    a.complex_eigenvalues()
        .iter()
        .map(|l| l.norm())
        .fold(0.0, f64::max)
}
