//! The matrix–state product of the plant of any rig: a matrix stored by columns, each
//! padded to a multiple of 4 rows, times the state (the fused step's rows: the
//! mechanical rows of e^{A h} and the switching functions' values and rates after it;
//! the Taylor expansion's products with A are `sparse_rows.rs`'s). Fused multiply-adds
//! (one rounding each, the same bytes on every CPU, `crate::fma`): compiled for AVX2 and
//! FMA where the CPU has them, else for baseline x86-64. Two ways in: [`rows`] asks the
//! CPU each call, out of line; [`gathered`] is inlined into the fast run's loop
//! (`fast.rs`), compiled for the CPU, with which the products, copies and checks of a
//! step are one loop (12 % faster on the 1983 rig, measured, than products called out
//! of line).

/// out[..rows] = Σ_k M[:, k] u[columns[k]]: M's columns stand for the states `columns`
/// picks (a fast run's folded spans, `run_spans.rs`). Inlined, compiled with its
/// caller's features: for the fast run's loop, compiled for the CPU (reached from code
/// compiled for baseline x86-64, each multiply-add would be a library call, ten times
/// slower).
#[inline(always)]
pub fn gathered(m: &[f64], rows: usize, columns: &[usize], u: &[f64], out: &mut [f64]) {
    weighted(m, rows, columns, |&i: &usize| u[i], out);
}

/// out[..rows] = Σ_k M[:, k] x[k]: [`gathered`] for weights already gathered (the first
/// state of a recorded stride, `record_stride.rs`), the same sums in the same order.
#[inline(always)]
pub fn dense(m: &[f64], rows: usize, x: &[f64], out: &mut [f64]) {
    weighted(m, rows, x, |&v: &f64| v, out);
}

/// out[..rows] = Σ_k M[:, k] weight(of[k]), the row count's own loop.
#[inline(always)]
fn weighted<T>(
    m: &[f64],
    rows: usize,
    of: &[T],
    weight: impl Fn(&T) -> f64 + Copy,
    out: &mut [f64],
) {
    match rows {
        4 => weighted_of::<4, _>(m, of, weight, out),
        8 => weighted_of::<8, _>(m, of, weight, out),
        12 => weighted_of::<12, _>(m, of, weight, out),
        16 => weighted_of::<16, _>(m, of, weight, out),
        20 => weighted_of::<20, _>(m, of, weight, out),
        _ => banded(m, rows, of.iter().map(weight), 1.0, out),
    }
}

/// The products of [`gathered`] and [`dense`] for `R` rows, fewer than 24: M's columns,
/// one per entry of `of` (its weight `weight` of the entry), taken two at a time into
/// two chains summed in registers (no column passed over: a fast run reads only states
/// that feed its rows). From 24 rows one chain keeps enough multiply-adds in flight (six
/// or more vectors of sums), and two chains of as many rows spilled their sums to the
/// stack at every column ([`banded`]).
#[inline(always)]
fn weighted_of<const R: usize, T>(
    m: &[f64],
    of: &[T],
    weight: impl Fn(&T) -> f64,
    out: &mut [f64],
) {
    let (mut even, mut odd) = ([0.0; R], [0.0; R]);
    let m = &m[..of.len() * R];
    let mut pairs = m.chunks_exact(2 * R);
    let mut entries = of.chunks_exact(2);
    for (block, pair) in pairs.by_ref().zip(entries.by_ref()) {
        let (x0, x1) = (weight(&pair[0]), weight(&pair[1]));
        let (c0, c1) = block.split_at(R);
        for r in 0..R {
            even[r] = c0[r].mul_add(x0, even[r]);
            odd[r] = c1[r].mul_add(x1, odd[r]);
        }
    }
    if let ([entry], last) = (entries.remainder(), pairs.remainder()) {
        let x = weight(entry);
        for r in 0..R {
            even[r] = last[r].mul_add(x, even[r]);
        }
    }
    for ((o, e), d) in out[..R].iter_mut().zip(even).zip(odd) {
        *o = e + d;
    }
}

/// Rows of one band of [`banded`]: eight vectors of sums, as many multiply-adds in flight
/// as two FMA units of four cycles' latency take, and room left in the sixteen registers.
const BAND_ROWS: usize = 32;

/// out[..rows] = (Σ column · x) · `scale` over M's columns (`rows` rows each, `rows` ≥
/// 24 and a multiple of 4) and the weights `x`, in bands of up to
/// [`BAND_ROWS`] rows, each summed in registers over every column in one chain: every
/// row's sum in column order from zero, as one chain over all rows gives it, bit for bit,
/// without sums that spill to memory (the planetary bench's 56 fused rows). A column of
/// zero weight adds ±0, which changes no sum but a zero one's sign, and that only where
/// a product underflowed to −0.
#[inline(always)]
fn banded(
    m: &[f64],
    rows: usize,
    x: impl Iterator<Item = f64> + Clone,
    scale: f64,
    out: &mut [f64],
) {
    // One band: its shape fixed, the columns' stride known to the compiler.
    match rows {
        24 => return band::<24>(m, 24, 0, x, scale, out),
        28 => return band::<28>(m, 28, 0, x, scale, out),
        32 => return band::<32>(m, 32, 0, x, scale, out),
        _ => {}
    }
    let mut first = 0;
    while rows - first >= BAND_ROWS {
        band::<BAND_ROWS>(m, rows, first, x.clone(), scale, out);
        first += BAND_ROWS;
    }
    match rows - first {
        0 => {}
        4 => band::<4>(m, rows, first, x, scale, out),
        8 => band::<8>(m, rows, first, x, scale, out),
        12 => band::<12>(m, rows, first, x, scale, out),
        16 => band::<16>(m, rows, first, x, scale, out),
        20 => band::<20>(m, rows, first, x, scale, out),
        24 => band::<24>(m, rows, first, x, scale, out),
        28 => band::<28>(m, rows, first, x, scale, out),
        _ => unreachable!("a product's rows are a multiple of 4"),
    }
}

/// out[first..first + B] = the rows `first..first + B` of Σ column · x over M's columns
/// (`rows` rows each), summed in one chain from zero in column order, times `scale`.
#[inline(always)]
fn band<const B: usize>(
    m: &[f64],
    rows: usize,
    first: usize,
    x: impl Iterator<Item = f64>,
    scale: f64,
    out: &mut [f64],
) {
    let mut sum = [0.0; B];
    for (column, x) in m.chunks_exact(rows).zip(x) {
        for (s, &a) in sum.iter_mut().zip(&column[first..first + B]) {
            *s = a.mul_add(x, *s);
        }
    }
    for (o, s) in out[first..first + B].iter_mut().zip(sum) {
        *o = s * scale;
    }
}

/// out[..rows] = (M u) · `scale` for M of `rows` rows (a multiple of 4) stored by
/// columns, one column per state of `u`: each row's sum, then times `scale` (1 leaves it
/// as it is; a Taylor vector's τ/k, applied in registers).
pub fn rows(m: &[f64], rows: usize, u: &[f64], scale: f64, out: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if crate::fma::available() {
        // SAFETY: the CPU has AVX2 and FMA, checked at run time.
        return unsafe { rows_v3(m, rows, u, scale, out) };
    }
    rows_any(m, rows, u.iter().copied(), scale, out);
}

/// [`rows_any`] compiled for AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn rows_v3(m: &[f64], rows: usize, u: &[f64], scale: f64, out: &mut [f64]) {
    rows_any(m, rows, u.iter().copied(), scale, out);
}

/// out[..rows] = (M x) · `scale`, M stored by columns, x the states each column stands
/// for. Below 24 rows a column whose weight is 0 is passed over (it would shift the
/// alternation of the two chains); from 24 rows it is summed, adding ±0, which leaves
/// every sum as it was.
#[inline(always)]
fn rows_any(
    m: &[f64],
    rows: usize,
    u: impl Iterator<Item = f64> + Clone,
    scale: f64,
    out: &mut [f64],
) {
    match rows {
        4 => rows_of::<4>(m, u, scale, out),
        8 => rows_of::<8>(m, u, scale, out),
        12 => rows_of::<12>(m, u, scale, out),
        16 => rows_of::<16>(m, u, scale, out),
        20 => rows_of::<20>(m, u, scale, out),
        _ => banded(m, rows, u, scale, out),
    }
}

/// [`rows_any`] for `R` rows, fewer than 24: the result summed in
/// registers over the columns (a fixed shape the compiler unrolls), in two chains taken
/// alternately over the columns of nonzero weight.
#[inline(always)]
fn rows_of<const R: usize>(m: &[f64], u: impl Iterator<Item = f64>, scale: f64, out: &mut [f64]) {
    let (mut even, mut odd) = ([0.0; R], [0.0; R]);
    let mut columns = m.chunks_exact(R).zip(u).filter(|&(_, x)| x != 0.0);
    while let Some((c0, x0)) = columns.next() {
        for (s, &a) in even.iter_mut().zip(c0) {
            *s = a.mul_add(x0, *s);
        }
        let Some((c1, x1)) = columns.next() else {
            break;
        };
        for (s, &a) in odd.iter_mut().zip(c1) {
            *s = a.mul_add(x1, *s);
        }
    }
    for ((o, e), d) in out[..R].iter_mut().zip(even).zip(odd) {
        *o = (e + d) * scale;
    }
}

/// `dst` = `src` (of the same length), copied four at a time in line: a state's few
/// dozen entries, for which a call to `memcpy` cost the fast run 5 % (measured).
#[inline(always)]
pub fn copy_short(dst: &mut [f64], src: &[f64]) {
    debug_assert_eq!(dst.len(), src.len(), "a short copy between unequal slices");
    let mut to = dst.chunks_exact_mut(4);
    let mut from = src.chunks_exact(4);
    for (d, s) in (&mut to).zip(&mut from) {
        d.copy_from_slice(s);
    }
    for (d, s) in to.into_remainder().iter_mut().zip(from.remainder()) {
        *d = *s;
    }
}

#[cfg(test)]
mod tests {
    use super::{copy_short, gathered, rows};

    /// Entries of every size and sign, some of them zero, from a seeded sequence.
    fn entries(n: usize, seed: u64) -> Vec<f64> {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(seed);
        (0..n)
            .map(|_| {
                let x: f64 = rng.random::<f64>() - 0.5;
                if x.abs() < 0.1 {
                    0.0
                } else {
                    x * 10f64.powi((x * 40.0) as i32)
                }
            })
            .collect()
    }

    /// Row r of M x as the products sum it: from 24 rows one chain over the columns in
    /// order; below, the columns of nonzero weight taken alternately into two chains.
    fn reference(m: &[f64], rows: usize, x: &[f64], r: usize) -> f64 {
        let terms = m.chunks_exact(rows).zip(x).filter(|&(_, &x)| x != 0.0);
        if rows >= 24 {
            return terms.fold(0.0, |s, (c, &x)| c[r].mul_add(x, s));
        }
        let (mut even, mut odd) = (0.0, 0.0);
        for (k, (c, &x)) in terms.enumerate() {
            if k % 2 == 0 {
                even = c[r].mul_add(x, even);
            } else {
                odd = c[r].mul_add(x, odd);
            }
        }
        even + odd
    }

    #[test]
    fn every_shape_sums_each_row_in_its_stated_order_bit_for_bit() {
        for rows_count in (4..=72).step_by(4) {
            for columns in [1, 7, 22, 31] {
                let m = entries(
                    rows_count * columns,
                    rows_count as u64 * 100 + columns as u64,
                );
                let x = entries(columns, 7 + columns as u64);
                let mut out = vec![f64::NAN; rows_count];
                rows(&m, rows_count, &x, 1.0, &mut out);
                for (r, &o) in out.iter().enumerate() {
                    let want = reference(&m, rows_count, &x, r);
                    assert_eq!(o.to_bits(), want.to_bits(), "{rows_count} rows, row {r}");
                }
            }
        }
    }

    #[test]
    fn a_gathered_product_reads_the_states_its_columns_name() {
        for rows_count in (4..=72).step_by(4) {
            let picked = [5, 0, 9, 3, 11, 2, 7];
            let u = entries(12, 3);
            let m = entries(rows_count * picked.len(), rows_count as u64);
            let mut out = vec![f64::NAN; rows_count];
            gathered(&m, rows_count, &picked, &u, &mut out);
            let x: Vec<f64> = picked.iter().map(|&i| u[i]).collect();
            // Every weight nonzero: below 24 rows, a zero would shift the dense product's
            // alternation of chains, which the gathered one does not skip.
            assert!(x.iter().all(|&v| v != 0.0));
            let mut dense = vec![f64::NAN; rows_count];
            rows(&m, rows_count, &x, 1.0, &mut dense);
            for (r, (&g, &d)) in out.iter().zip(&dense).enumerate() {
                assert_eq!(g.to_bits(), d.to_bits(), "{rows_count} rows, row {r}");
            }
        }
    }

    #[test]
    fn a_short_copy_copies_every_entry() {
        for n in 0..14 {
            let from = entries(n, n as u64);
            let mut to = vec![f64::NAN; n];
            copy_short(&mut to, &from);
            assert!(
                to.iter()
                    .zip(&from)
                    .all(|(a, b)| a.to_bits() == b.to_bits())
            );
        }
    }
}
