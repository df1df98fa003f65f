//! A mode's A without its zeros, for the Taylor expansion's products (`stepping.rs`):
//! A of a rig is mostly zeros (an angle's rate reads one or two speeds, a forcing state
//! one other; on the planetary bench 90 of its 28 × 26 entries are not).
//!
//! Each row's sum is the dense product's (`products::rows`) to the bit where that takes
//! 24 rows or more (every shipped rig), for any finite state: both sum the row's products
//! in column order from +0 with one rounding each (`crate::fma`), and an entry of 0 adds
//! ±0 there, which changes no sum but a zero one's sign, and that only where a product
//! underflowed to −0. Below 24 rows the dense product sums in two chains, so a smaller
//! rig's expansion moved at rounding (1e-11 of a one-mesh rig's forces).

/// Rows a block of [`SparseRows`] takes together: one vector of four sums (AVX2).
const BLOCK: usize = 4;

/// A matrix by blocks of four rows, each block the columns where any of its four
/// entries is nonzero, with those four entries: each block one vector of sums, a chain
/// of multiply-adds as long as its columns (on the planetary bench 5 for an angle's rows,
/// at most 18 for a speed's, where the dense product's chains were 26 long for every
/// row), and 51 vector multiply-adds where the dense product took 182.
#[derive(Clone, Debug, PartialEq)]
pub struct SparseRows {
    /// Where each block's columns begin in `columns`, then where the last one's end.
    starts: Vec<usize>,
    /// Per column of a block, its index and the block's four entries there, block
    /// after block, each block's in column order.
    columns: Vec<(usize, [f64; BLOCK])>,
}

impl SparseRows {
    /// The matrix stored by columns in `columns`, `rows` rows a column (a multiple of 4).
    pub fn of_columns(columns: &[f64], rows: usize) -> Self {
        debug_assert_eq!(rows % BLOCK, 0, "rows padded to whole blocks");
        let width = columns.len().checked_div(rows).unwrap_or(0);
        let mut starts = Vec::with_capacity(rows / BLOCK + 1);
        let mut kept = Vec::new();
        for first in (0..rows).step_by(BLOCK) {
            starts.push(kept.len());
            kept.extend((0..width).filter_map(|c| {
                let entries: [f64; BLOCK] = std::array::from_fn(|i| columns[c * rows + first + i]);
                entries.iter().any(|&a| a != 0.0).then_some((c, entries))
            }));
        }
        starts.push(kept.len());
        Self {
            starts,
            columns: kept,
        }
    }

    /// The entry at `row`, `column` (0 where none is stored).
    pub fn get(&self, row: usize, column: usize) -> f64 {
        let block = row / BLOCK;
        self.columns[self.starts[block]..self.starts[block + 1]]
            .iter()
            .find(|&&(c, _)| c == column)
            .map_or(0.0, |(_, entries)| entries[row % BLOCK])
    }

    /// out[r] = (Σ_c M[r, c] x[c]) · `scale` for every row r, `out` exactly as long as
    /// the rows (the layout's padded length): a Taylor vector from the one before it,
    /// M = A (1/s) and `scale` the span over the order, τ/k (s). Compiled for AVX2 and
    /// FMA where the CPU has them, else for baseline x86-64.
    pub fn product(&self, x: &[f64], scale: f64, out: &mut [f64]) {
        #[cfg(target_arch = "x86_64")]
        if crate::fma::available() {
            // SAFETY: the CPU has AVX2 and FMA, checked at run time.
            return unsafe { self.product_v3(x, scale, out) };
        }
        self.product_any(x, scale, out);
    }

    /// [`Self::product_any`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn product_v3(&self, x: &[f64], scale: f64, out: &mut [f64]) {
        self.product_any(x, scale, out);
    }

    /// [`Self::product`]: each block's four sums from +0 over its columns in order, then
    /// times `scale`.
    #[inline(always)]
    fn product_any(&self, x: &[f64], scale: f64, out: &mut [f64]) {
        debug_assert_eq!(
            out.len(),
            (self.starts.len() - 1) * BLOCK,
            "one output a row"
        );
        for (block, ends) in out.chunks_exact_mut(BLOCK).zip(self.starts.windows(2)) {
            let mut sum = [0.0; BLOCK];
            for (c, entries) in &self.columns[ends[0]..ends[1]] {
                let weight = x[*c];
                for (s, a) in sum.iter_mut().zip(entries) {
                    *s = a.mul_add(weight, *s);
                }
            }
            for (o, s) in block.iter_mut().zip(sum) {
                *o = s * scale;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::SparseRows;
    use crate::plant::products;

    /// A `rows` × `width` matrix by columns of a rig's shape: most entries 0, the rest of every
    /// size and sign, some rows empty (the padding).
    fn rig_like(rows: usize, width: usize) -> Vec<f64> {
        (0..rows * width)
            .map(|k| {
                let (c, r) = (k / rows, k % rows);
                if r >= width || (r * 7 + c * 3) % 5 != 0 {
                    0.0
                } else {
                    (k as f64 * 0.731 - 9.0) * 10f64.powi((k % 9) as i32 - 4)
                }
            })
            .collect()
    }

    /// The dense product's shapes from 24 rows: one band (24, 28 rows) and bands of 32
    /// and a rest (36 rows); an entry of −0 among the columns.
    #[test]
    fn the_sparse_product_is_the_dense_one_to_the_bit() {
        for (rows, width) in [(24, 22), (28, 26), (36, 34)] {
            same_as_dense(rows, width);
        }
    }

    fn same_as_dense(rows: usize, width: usize) {
        let mut columns = rig_like(rows, width);
        columns[2 * rows + 1] = -0.0;
        let sparse = SparseRows::of_columns(&columns, rows);
        let mut x: Vec<f64> = (0..rows)
            .map(|k| (k as f64 * 1.37 - 17.1) * 10f64.powi(k as i32 % 7 - 3))
            .collect();
        x[3] = 0.0;
        x[4] = -0.0;
        for scale in [1.0, 0.25 / 7.0, -3.5e-9] {
            let (mut dense_out, mut sparse_out) = (vec![f64::NAN; rows], vec![f64::NAN; rows]);
            products::rows(&columns, rows, &x, scale, &mut dense_out);
            sparse.product(&x, scale, &mut sparse_out);
            for (r, (d, s)) in dense_out.iter().zip(&sparse_out).enumerate() {
                assert_eq!(d.to_bits(), s.to_bits(), "row {r}: {d:e} and {s:e}");
            }
        }
        for (row, column) in [(0, 0), (1, 0), (1, 2), (5, 20), (rows - 1, width - 1)] {
            assert_eq!(sparse.get(row, column), columns[column * rows + row]);
        }
    }
}
