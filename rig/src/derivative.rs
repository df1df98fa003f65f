//! The product A·u of the Taylor expansion. A is stored by columns and multiplied as the
//! step matrices are ([`crate::column_product::product`]): every row at once in vector
//! multiply-adds. (Over A's nonzero entries alone, about a quarter of them, the product
//! took twice as long: its index loads and scattered rows cost more than the zeros.)

use nalgebra::DMatrix;

use crate::column_product::square_product;
use crate::layout::Layout;

/// A·u for one mode's matrix A.
pub struct Derivative {
    /// A by columns, zero beyond its size.
    columns: Box<[[f64; Layout::MAX_LEN]; Layout::MAX_LEN]>,
    len: usize,
}

impl Derivative {
    /// The product with `a` (square, at most [`Layout::MAX_LEN`] rows).
    pub fn of(a: &DMatrix<f64>) -> Self {
        let len = a.nrows();
        let columns = std::array::from_fn(|col| {
            std::array::from_fn(|row| {
                if row < len && col < len {
                    a[(row, col)]
                } else {
                    0.0
                }
            })
        });
        Self {
            columns: Box::new(columns),
            len,
        }
    }

    /// `out` = scale·A·u (zero past A's size). Always inlined: the Taylor expansion's
    /// inner loop.
    #[inline(always)]
    pub fn scaled(&self, u: &[f64; Layout::MAX_LEN], scale: f64, out: &mut [f64; Layout::MAX_LEN]) {
        let product = square_product(&self.columns, u, self.len);
        for (o, p) in out.iter_mut().zip(product) {
            *o = scale * p;
        }
    }
}
