//! The matrix–state products of the plant of any rig: a mode's e^{A h} or A times the
//! state (square, columns padded to a multiple of 4), and the fused step's rows (the
//! mechanical rows of e^{A h} and the switching functions' values and rates after it)
//! times the state. Fused multiply-adds (one rounding each, the same bytes on every CPU,
//! `crate::fma`): compiled for AVX2 and FMA where the CPU has them, else for baseline
//! x86-64.

/// out = M u for a square M stored as columns padded to the state's padded length (a
/// multiple of 4, `u.len()`), whose rows from `forcing` on are 0 in the columns before it
/// (the forcing states evolve by themselves), columns whose weight is 0 passed over. Fused
/// multiply-adds (one rounding each, the same bytes on every CPU, `crate::fma`): compiled
/// for AVX2 and FMA where the CPU has them, else for baseline x86-64.
pub fn square(m: &[f64], u: &[f64], out: &mut [f64], forcing: usize) {
    #[cfg(target_arch = "x86_64")]
    if crate::fma::available() {
        // SAFETY: the CPU has AVX2 and FMA, checked at run time.
        return unsafe { product_v3(m, u, out, forcing) };
    }
    product_any(m, u, out, forcing);
}

/// [`product_any`] compiled for AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn product_v3(m: &[f64], u: &[f64], out: &mut [f64], forcing: usize) {
    product_any(m, u, out, forcing);
}

#[inline(always)]
fn product_any(m: &[f64], u: &[f64], out: &mut [f64], forcing: usize) {
    match u.len() {
        8 => product_of::<8>(m, u, out),
        12 => product_of::<12>(m, u, out),
        16 => product_of::<16>(m, u, out),
        20 => product_of::<20>(m, u, out),
        24 => product_of::<24>(m, u, out),
        28 => product_of::<28>(m, u, out),
        32 => product_of::<32>(m, u, out),
        36 => product_of::<36>(m, u, out),
        40 => product_of::<40>(m, u, out),
        _ => product_rows(m, u, out, forcing),
    }
}

/// [`product_any`] for a state of padded length `N`: the result summed in registers over
/// the columns (a fixed shape the compiler unrolls), every row of every column taken (the
/// forcing rows of the mechanical columns are exact zeros, which add nothing).
#[inline(always)]
fn product_of<const N: usize>(m: &[f64], u: &[f64], out: &mut [f64]) {
    // Two chains (the columns taken alternately, zero weights passed over) halve the
    // latency of the multiply-adds.
    let (mut even, mut odd) = ([0.0; N], [0.0; N]);
    let mut columns = m.chunks_exact(N).zip(u).filter(|&(_, &x)| x != 0.0);
    while let Some((c0, &x0)) = columns.next() {
        for (s, &a) in even.iter_mut().zip(c0) {
            *s = a.mul_add(x0, *s);
        }
        let Some((c1, &x1)) = columns.next() else {
            break;
        };
        for (s, &a) in odd.iter_mut().zip(c1) {
            *s = a.mul_add(x1, *s);
        }
    }
    for ((o, e), d) in out[..N].iter_mut().zip(even).zip(odd) {
        *o = e + d;
    }
}

/// [`product_any`] for any padded length, the mechanical columns over the mechanical rows
/// only.
#[inline(always)]
fn product_rows(m: &[f64], u: &[f64], out: &mut [f64], forcing: usize) {
    let padded = u.len();
    let mechanical_rows = forcing.div_ceil(4) * 4;
    out.fill(0.0);
    for (col, (column, &x)) in m.chunks_exact(padded).zip(u).enumerate() {
        if x == 0.0 {
            continue;
        }
        let rows = if col < forcing {
            mechanical_rows
        } else {
            padded
        };
        for (o, a) in out[..rows]
            .chunks_exact_mut(4)
            .zip(column[..rows].chunks_exact(4))
        {
            for k in 0..4 {
                o[k] = a[k].mul_add(x, o[k]);
            }
        }
    }
}

/// out[..rows] = M u for M of `rows` rows (a multiple of 4) stored by columns, one column
/// per state of `u`, columns whose weight is 0 passed over.
pub fn rows(m: &[f64], rows: usize, u: &[f64], out: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if crate::fma::available() {
        // SAFETY: the CPU has AVX2 and FMA, checked at run time.
        return unsafe { rows_v3(m, rows, u, out) };
    }
    rows_any(m, rows, u, out);
}

/// [`rows_any`] compiled for AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn rows_v3(m: &[f64], rows: usize, u: &[f64], out: &mut [f64]) {
    rows_any(m, rows, u, out);
}

#[inline(always)]
fn rows_any(m: &[f64], rows: usize, u: &[f64], out: &mut [f64]) {
    match rows {
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
fn rows_of<const R: usize>(m: &[f64], u: &[f64], out: &mut [f64]) {
    let (mut even, mut odd) = ([0.0; R], [0.0; R]);
    let mut columns = m.chunks_exact(R).zip(u).filter(|&(_, &x)| x != 0.0);
    while let Some((c0, &x0)) = columns.next() {
        for (s, &a) in even.iter_mut().zip(c0) {
            *s = a.mul_add(x0, *s);
        }
        let Some((c1, &x1)) = columns.next() else {
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
fn rows_dynamic(m: &[f64], rows: usize, u: &[f64], out: &mut [f64]) {
    out[..rows].fill(0.0);
    for (column, &x) in m.chunks_exact(rows).zip(u) {
        if x == 0.0 {
            continue;
        }
        for (o, &a) in out[..rows].iter_mut().zip(column) {
            *o = a.mul_add(x, *o);
        }
    }
}
