//! Analog low-pass prototypes: poles of Butterworth and Bessel filters with their −3 dB
//! point at 1 rad/s (all-pole, unit gain at DC).

use nalgebra::DMatrix;
use num_complex::Complex64;

/// Butterworth poles of order `n`: e^{jπ(2k + n + 1)/(2n)}, k = 0..n, on the unit circle.
pub fn butterworth_poles(n: usize) -> Vec<Complex64> {
    (0..n)
        .map(|k| {
            Complex64::from_polar(
                1.0,
                std::f64::consts::PI * (2 * k + n + 1) as f64 / (2 * n) as f64,
            )
        })
        .collect()
}

/// Bessel (Thomson) poles of order `n`, scaled so that |H(j·1)| = 1/√2.
///
/// The roots of the reverse Bessel polynomial θ_n(s) = Σ a_k s^k,
/// a_k = (2n − k)! / (2^(n−k) k! (n − k)!), give unit group delay at DC; they are found as
/// eigenvalues of the companion matrix and then scaled to the −3 dB point by bisection.
pub fn bessel_poles(n: usize) -> Vec<Complex64> {
    let coefficients: Vec<f64> = (0..=n).map(|k| bessel_coefficient(n, k)).collect();
    let roots = polynomial_roots(&coefficients);
    let gain = |w: f64| {
        let s = Complex64::new(0.0, w);
        let product: Complex64 = roots.iter().map(|p| -p / (s - p)).product();
        product.norm()
    };
    let (mut low, mut high): (f64, f64) = (1e-3, 1e3);
    for _ in 0..200 {
        let mid = (low * high).sqrt();
        if gain(mid) > std::f64::consts::FRAC_1_SQRT_2 {
            low = mid;
        } else {
            high = mid;
        }
    }
    let w3 = (low * high).sqrt();
    roots.iter().map(|p| p / w3).collect()
}

fn bessel_coefficient(n: usize, k: usize) -> f64 {
    let factorial = |m: usize| (1..=m).map(|v| v as f64).product::<f64>();
    factorial(2 * n - k) / (2f64.powi((n - k) as i32) * factorial(k) * factorial(n - k))
}

/// Roots of Σ c_k s^k (c_n ≠ 0) as eigenvalues of the companion matrix.
fn polynomial_roots(c: &[f64]) -> Vec<Complex64> {
    let n = c.len() - 1;
    let lead = c[n];
    let companion = DMatrix::from_fn(n, n, |r, col| {
        if r == 0 {
            -c[n - 1 - col] / lead
        } else if r == col + 1 {
            1.0
        } else {
            0.0
        }
    });
    companion.complex_eigenvalues().iter().copied().collect()
}
