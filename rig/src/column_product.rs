//! The product of a fixed-shape column matrix with the augmented state, the inner loop of
//! every step, stride and derivative.

use crate::layout::Layout;

/// `columns` times `u` over the first `len` columns (16, 18, 20 or 22): a fixed shape for
/// each, which the compiler unrolls into vector multiply-adds, the columns summed in two
/// chains (even and odd) to halve the latency.
#[inline]
pub fn product<const ROWS: usize>(
    columns: &[[f64; ROWS]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
    len: usize,
) -> [f64; ROWS] {
    #[cfg(target_arch = "x86_64")]
    if crate::fma::available() {
        // SAFETY: the CPU has AVX2 and FMA, checked at run time.
        return unsafe { product_v3::<ROWS>(columns, u, len) };
    }
    product_any::<ROWS>(columns, u, len)
}

/// [`product`] compiled for AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn product_v3<const ROWS: usize>(
    columns: &[[f64; ROWS]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
    len: usize,
) -> [f64; ROWS] {
    product_any::<ROWS>(columns, u, len)
}

#[inline(always)]
fn product_any<const ROWS: usize>(
    columns: &[[f64; ROWS]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
    len: usize,
) -> [f64; ROWS] {
    match len {
        16 => product_of::<ROWS, 16>(columns, u),
        18 => product_of::<ROWS, 18>(columns, u),
        20 => product_of::<ROWS, 20>(columns, u),
        _ => product_of::<ROWS, { Layout::MAX_LEN }>(columns, u),
    }
}

#[inline(always)]
fn product_of<const ROWS: usize, const N: usize>(
    columns: &[[f64; ROWS]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
) -> [f64; ROWS] {
    let (mut even, mut odd) = ([0.0; ROWS], [0.0; ROWS]);
    for (pair, weights) in columns[..N].chunks_exact(2).zip(u[..N].chunks_exact(2)) {
        for ((e, o), (&c0, &c1)) in even
            .iter_mut()
            .zip(odd.iter_mut())
            .zip(pair[0].iter().zip(&pair[1]))
        {
            *e = c0.mul_add(weights[0], *e);
            *o = c1.mul_add(weights[1], *o);
        }
    }
    for (e, o) in even.iter_mut().zip(odd) {
        *e += o;
    }
    even
}

/// A·`u` for a square A of size `len` (16, 18, 20 or 22) stored by columns in the
/// largest shape: only the first `len` rows and columns are multiplied (a fixed shape for
/// each), the rest of the result is zero.
#[inline]
pub fn square_product(
    columns: &[[f64; Layout::MAX_LEN]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
    len: usize,
) -> [f64; Layout::MAX_LEN] {
    #[cfg(target_arch = "x86_64")]
    if crate::fma::available() {
        // SAFETY: the CPU has AVX2 and FMA, checked at run time.
        return unsafe { square_product_v3(columns, u, len) };
    }
    square_product_any(columns, u, len)
}

/// [`square_product`] compiled for AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn square_product_v3(
    columns: &[[f64; Layout::MAX_LEN]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
    len: usize,
) -> [f64; Layout::MAX_LEN] {
    square_product_any(columns, u, len)
}

#[inline(always)]
fn square_product_any(
    columns: &[[f64; Layout::MAX_LEN]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
    len: usize,
) -> [f64; Layout::MAX_LEN] {
    match len {
        16 => square_of::<16>(columns, u),
        18 => square_of::<18>(columns, u),
        20 => square_of::<20>(columns, u),
        _ => product_of::<{ Layout::MAX_LEN }, { Layout::MAX_LEN }>(columns, u),
    }
}

#[inline(always)]
fn square_of<const N: usize>(
    columns: &[[f64; Layout::MAX_LEN]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
) -> [f64; Layout::MAX_LEN] {
    let (mut even, mut odd) = ([0.0; N], [0.0; N]);
    for (pair, weights) in columns[..N].chunks_exact(2).zip(u[..N].chunks_exact(2)) {
        let (c0, c1) = (&pair[0][..N], &pair[1][..N]);
        for ((e, o), (&a, &b)) in even.iter_mut().zip(odd.iter_mut()).zip(c0.iter().zip(c1)) {
            *e = a.mul_add(weights[0], *e);
            *o = b.mul_add(weights[1], *o);
        }
    }
    let mut out = [0.0; Layout::MAX_LEN];
    for ((r, e), o) in out.iter_mut().zip(even).zip(odd) {
        *r = e + o;
    }
    out
}
