//! The product A·u of the Taylor expansion, over A's nonzero entries. Most rows of the
//! model's matrix hold one entry (an angle's rate is its speed, a harmonic pair turns)
//! and are a single product; the speed and controller rows hold up to nine and are
//! summed in two interleaved chains, which halves their latency.

use nalgebra::DMatrix;

use crate::layout::Layout;

/// A·u for one mode's matrix A.
pub struct Derivative {
    /// Rows with one nonzero entry: (row, column, value).
    single: Vec<(usize, usize, f64)>,
    /// Rows with more: (row, start, end) of its terms in `terms`.
    multi: Vec<(usize, usize, usize)>,
    /// (column, value) of the entries of the `multi` rows, in column order.
    terms: Vec<(usize, f64)>,
}

impl Derivative {
    /// The nonzero entries of `a` (square, at most [`Layout::MAX_LEN`] rows).
    pub fn of(a: &DMatrix<f64>) -> Self {
        let mut derivative = Self {
            single: Vec::new(),
            multi: Vec::new(),
            terms: Vec::new(),
        };
        for row in 0..a.nrows() {
            let entries: Vec<(usize, f64)> = (0..a.ncols())
                .filter(|&col| a[(row, col)] != 0.0)
                .map(|col| (col, a[(row, col)]))
                .collect();
            match entries[..] {
                [] => {}
                [(col, value)] => derivative.single.push((row, col, value)),
                _ => {
                    let start = derivative.terms.len();
                    derivative.terms.extend(entries);
                    derivative.multi.push((row, start, derivative.terms.len()));
                }
            }
        }
        derivative
    }

    /// `out` = scale·A·u (rows without entries, and past A's size, are zero). Always
    /// inlined: the Taylor expansion's inner loop.
    #[inline(always)]
    pub fn scaled(&self, u: &[f64; Layout::MAX_LEN], scale: f64, out: &mut [f64; Layout::MAX_LEN]) {
        out.fill(0.0);
        for &(row, col, value) in &self.single {
            out[row] = scale * (value * u[col]);
        }
        for &(row, start, end) in &self.multi {
            out[row] = scale * interleaved_sum(&self.terms[start..end], u);
        }
    }
}

/// Σ value·u[column] over `terms`, the even and odd terms in two chains of multiply-adds.
#[inline(always)]
fn interleaved_sum(terms: &[(usize, f64)], u: &[f64; Layout::MAX_LEN]) -> f64 {
    let mut pairs = terms.chunks_exact(2);
    let (mut even, mut odd) = (0.0, 0.0);
    for pair in &mut pairs {
        even = pair[0].1.mul_add(u[pair[0].0], even);
        odd = pair[1].1.mul_add(u[pair[1].0], odd);
    }
    if let [(col, value)] = pairs.remainder() {
        even = value.mul_add(u[*col], even);
    }
    even + odd
}
