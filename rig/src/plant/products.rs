//! The matrix–state product of the plant of any rig: a matrix stored by columns, each
//! padded to a multiple of 4 rows, times the state (a mode's A for the Taylor expansion,
//! square; the fused step's rows: the mechanical rows of e^{A h} and the switching
//! functions' values and rates after it). Fused multiply-adds (one rounding each, the
//! same bytes on every CPU, `crate::fma`): compiled for AVX2 and FMA where the CPU has
//! them, else for baseline x86-64. Two ways in: [`rows`] asks the CPU each call, out of
//! line; [`gathered`] is inlined into the fast run's loop (`fast.rs`), compiled for the
//! CPU, with which the products, copies and checks of a step are one loop (12 % faster
//! on the 1983 rig, measured, than products called out of line).

/// out[..rows] = Σ_k M[:, k] u[columns[k]]: M's columns stand for the states `columns`
/// picks (a fast run's folded spans, `run_spans.rs`). Inlined, compiled with its
/// caller's features: for the fast run's loop, compiled for the CPU (reached from code
/// compiled for baseline x86-64, each multiply-add would be a library call, ten times
/// slower).
#[inline(always)]
pub fn gathered(m: &[f64], rows: usize, columns: &[usize], u: &[f64], out: &mut [f64]) {
    match rows {
        4 => gathered_of::<4>(m, columns, u, out),
        8 => gathered_of::<8>(m, columns, u, out),
        12 => gathered_of::<12>(m, columns, u, out),
        16 => gathered_of::<16>(m, columns, u, out),
        20 => gathered_of::<20>(m, columns, u, out),
        24 => gathered_of::<24>(m, columns, u, out),
        28 => gathered_of::<28>(m, columns, u, out),
        32 => gathered_of::<32>(m, columns, u, out),
        _ => rows_dynamic(m, rows, columns.iter().map(|&i| u[i]), out),
    }
}

/// [`gathered`] for `R` rows: the columns taken two at a time into two chains summed in
/// registers (no column passed over: a fast run reads only states that feed its rows).
#[inline(always)]
fn gathered_of<const R: usize>(m: &[f64], columns: &[usize], u: &[f64], out: &mut [f64]) {
    if R >= ONE_CHAIN_ROWS {
        let picked = m[..columns.len() * R].chunks_exact(R).zip(columns);
        return one_chain::<R>(picked.map(|(column, &i)| (column, u[i])), out);
    }
    let (mut even, mut odd) = ([0.0; R], [0.0; R]);
    let m = &m[..columns.len() * R];
    let mut pairs = m.chunks_exact(2 * R);
    let mut indices = columns.chunks_exact(2);
    for (block, pair) in pairs.by_ref().zip(indices.by_ref()) {
        let (x0, x1) = (u[pair[0]], u[pair[1]]);
        let (c0, c1) = block.split_at(R);
        for r in 0..R {
            even[r] = c0[r].mul_add(x0, even[r]);
            odd[r] = c1[r].mul_add(x1, odd[r]);
        }
    }
    if let ([i], last) = (indices.remainder(), pairs.remainder()) {
        let x = u[*i];
        for r in 0..R {
            even[r] = last[r].mul_add(x, even[r]);
        }
    }
    for ((o, e), d) in out[..R].iter_mut().zip(even).zip(odd) {
        *o = e + d;
    }
}

/// Rows from which one chain of sums keeps enough products in flight: R/4 vectors of
/// four, each an independent multiply-add chain, six or more. Two chains of as many rows
/// fill the sixteen vector registers, and their sums went to the stack and back at every
/// column (seen in the planetary bench's 32 fused rows).
const ONE_CHAIN_ROWS: usize = 24;

/// out[..R] = Σ column · x over `columns` (each of `R` rows, with the state it weighs) in
/// one chain of sums, for `R` ≥ [`ONE_CHAIN_ROWS`]: [`gathered_of`]'s and [`rows_of`]'s.
#[inline(always)]
fn one_chain<'a, const R: usize>(columns: impl Iterator<Item = (&'a [f64], f64)>, out: &mut [f64]) {
    let mut sum = [0.0; R];
    for (column, x) in columns {
        for (s, &a) in sum.iter_mut().zip(column) {
            *s = a.mul_add(x, *s);
        }
    }
    out[..R].copy_from_slice(&sum);
}

/// out[..rows] = M u for M of `rows` rows (a multiple of 4) stored by columns, one column
/// per state of `u`, columns whose weight is 0 passed over.
pub fn rows(m: &[f64], rows: usize, u: &[f64], out: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if crate::fma::available() {
        // SAFETY: the CPU has AVX2 and FMA, checked at run time.
        return unsafe { rows_v3(m, rows, u, out) };
    }
    rows_any(m, rows, u.iter().copied(), out);
}

/// [`rows_any`] compiled for AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn rows_v3(m: &[f64], rows: usize, u: &[f64], out: &mut [f64]) {
    rows_any(m, rows, u.iter().copied(), out);
}

/// out[..rows] = M x, M stored by columns, x the states each column stands for.
#[inline(always)]
fn rows_any(m: &[f64], rows: usize, u: impl Iterator<Item = f64>, out: &mut [f64]) {
    match rows {
        4 => rows_of::<4>(m, u, out),
        8 => rows_of::<8>(m, u, out),
        12 => rows_of::<12>(m, u, out),
        16 => rows_of::<16>(m, u, out),
        20 => rows_of::<20>(m, u, out),
        24 => rows_of::<24>(m, u, out),
        28 => rows_of::<28>(m, u, out),
        32 => rows_of::<32>(m, u, out),
        36 => rows_of::<36>(m, u, out),
        40 => rows_of::<40>(m, u, out),
        44 => rows_of::<44>(m, u, out),
        48 => rows_of::<48>(m, u, out),
        _ => rows_dynamic(m, rows, u, out),
    }
}

/// [`rows_any`] for `R` rows: the result summed in registers over the columns (a fixed
/// shape the compiler unrolls), in two chains taken alternately.
#[inline(always)]
fn rows_of<const R: usize>(m: &[f64], u: impl Iterator<Item = f64>, out: &mut [f64]) {
    if R >= ONE_CHAIN_ROWS {
        return one_chain::<R>(m.chunks_exact(R).zip(u).filter(|&(_, x)| x != 0.0), out);
    }
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
        *o = e + d;
    }
}

/// [`rows_any`] for any number of rows.
#[inline(always)]
fn rows_dynamic(m: &[f64], rows: usize, u: impl Iterator<Item = f64>, out: &mut [f64]) {
    out[..rows].fill(0.0);
    for (column, x) in m.chunks_exact(rows).zip(u) {
        if x == 0.0 {
            continue;
        }
        for (o, &a) in out[..rows].iter_mut().zip(column) {
            *o = a.mul_add(x, *o);
        }
    }
}
