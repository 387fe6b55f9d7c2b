//! Banded linear systems in O(n·b²): LU with partial pivoting for an almost-banded matrix (a
//! band plus a dense border of trailing columns, which also holds the corners of a cyclic
//! band), and Cholesky for a symmetric positive definite band.
//!
//! **LU.** Entries `(i, j)` lie either in the band `i − lower ≤ j ≤ i + upper` or in the last
//! `border` columns. Column `c` can then only be non-zero in rows `c ..= c + lower`, so partial
//! pivoting searches those rows alone, and swapping row `c` with row `r ≤ c + lower` widens the
//! upper band to `lower + upper` (the classic result for banded LU with partial pivoting,
//! LAPACK `gbtrf`); the border columns stay dense. Every step touches `lower` rows of
//! `2·lower + upper + 1 + border` entries: O(n·lower·(lower + upper + border)) in all. The right
//! sides are eliminated with the rows (no multipliers are kept), then back substitution.
//! Gaussian elimination without pivoting would do for the totally positive collocation matrix
//! of plain interpolation (NURBS Book §9.2.1), but a derivative row breaks total positivity, so
//! this solver always pivots.
//!
//! **Cholesky.** `A = L Lᵀ` with `L` lower triangular of bandwidth `b` (the band does not grow),
//! O(n·b²); a pivot `≤ 0` (up to rounding) means `A` is not positive definite.

use crate::error::{Error, Result};

/// Relative size below which a pivot counts as zero: rows are scaled to a largest entry of 1
/// before elimination, so a pivot this small means the matrix is singular to rounding.
const PIVOT_TOLERANCE: f64 = 16.0 * f64::EPSILON;

/// An `n × n` matrix whose entries lie in a band or in the last `border` columns (see the
/// module doc), stored row by row: `band[i·width + (j − i + lower)]` for band entries (`width =
/// 2·lower + upper + 1`, room for the fill of pivoting), `edge[i·border + (j − (n − border))]`
/// for the border.
#[derive(Debug, Clone)]
pub struct AlmostBanded {
    n: usize,
    lower: usize,
    upper: usize,
    border: usize,
    width: usize,
    band: Vec<f64>,
    edge: Vec<f64>,
}

impl AlmostBanded {
    /// A zero matrix of size `n` with the given lower and upper bandwidths and `border` dense
    /// trailing columns (`border` is cut to `n`).
    pub fn new(n: usize, lower: usize, upper: usize, border: usize) -> Self {
        let border = border.min(n);
        let width = 2 * lower + upper + 1;
        AlmostBanded {
            n,
            lower,
            upper,
            border,
            width,
            band: vec![0.0; n * width],
            edge: vec![0.0; n * border],
        }
    }

    /// The size `n`.
    pub fn size(&self) -> usize {
        self.n
    }

    /// The storage slot of `(i, j)`, `None` outside the band and the border.
    fn slot(&self, i: usize, j: usize) -> Option<(bool, usize)> {
        if i >= self.n || j >= self.n {
            return None;
        }
        let first_border = self.n - self.border;
        if j >= first_border {
            return Some((true, i * self.border + (j - first_border)));
        }
        let offset = (j + self.lower).checked_sub(i)?;
        (offset < self.width).then_some((false, i * self.width + offset))
    }

    fn get(&self, i: usize, j: usize) -> f64 {
        match self.slot(i, j) {
            Some((true, s)) => self.edge[s],
            Some((false, s)) => self.band[s],
            None => 0.0,
        }
    }

    fn set(&mut self, i: usize, j: usize, value: f64) {
        match self.slot(i, j) {
            Some((true, s)) => self.edge[s] = value,
            Some((false, s)) => self.band[s] = value,
            None => {}
        }
    }

    /// Adds `value` to entry `(i, j)`; returns `false` (and changes nothing) if `(i, j)` lies
    /// outside the band and the border.
    pub fn add(&mut self, i: usize, j: usize, value: f64) -> bool {
        match self.slot(i, j) {
            Some((true, s)) => self.edge[s] += value,
            Some((false, s)) if j <= i + self.upper => self.band[s] += value,
            _ => return false,
        }
        true
    }

    /// The last column of the band part plus one (`n − border`).
    fn band_end(&self) -> usize {
        self.n - self.border
    }

    /// Multiplies row `i` (and its right side) by `factor`.
    fn scale_row(&mut self, i: usize, factor: f64, rhs: &mut [f64], dim: usize) {
        for v in &mut self.band[i * self.width..(i + 1) * self.width] {
            *v *= factor;
        }
        for v in &mut self.edge[i * self.border..(i + 1) * self.border] {
            *v *= factor;
        }
        for v in &mut rhs[i * dim..(i + 1) * dim] {
            *v *= factor;
        }
    }

    /// The largest absolute entry of row `i`.
    fn row_max(&self, i: usize) -> f64 {
        self.band[i * self.width..(i + 1) * self.width]
            .iter()
            .chain(&self.edge[i * self.border..(i + 1) * self.border])
            .fold(0.0, |m: f64, v| m.max(v.abs()))
    }

    /// Swaps rows `a < b` (entries in columns `from..`, where both rows may be non-zero) and
    /// their right sides.
    fn swap_rows(&mut self, a: usize, b: usize, from: usize, rhs: &mut [f64], dim: usize) {
        let last = (from + self.lower + self.upper).min(self.band_end().saturating_sub(1));
        for j in from..=last.max(from) {
            if j < self.band_end() {
                let (x, y) = (self.get(a, j), self.get(b, j));
                self.set(a, j, y);
                self.set(b, j, x);
            }
        }
        for k in 0..self.border {
            self.edge.swap(a * self.border + k, b * self.border + k);
        }
        for k in 0..dim {
            rhs.swap(a * dim + k, b * dim + k);
        }
    }

    /// Row `r` −= `f` · row `c` over columns `from..` (band part up to the fill bound, then the
    /// border), and the same on the right sides.
    fn eliminate(&mut self, r: usize, c: usize, f: f64, from: usize, rhs: &mut [f64], dim: usize) {
        let end = (c + self.lower + self.upper + 1).min(self.band_end());
        for j in from..end {
            let v = self.get(c, j);
            if v != 0.0 {
                let w = self.get(r, j);
                self.set(r, j, w - f * v);
            }
        }
        for k in 0..self.border {
            let v = self.edge[c * self.border + k];
            self.edge[r * self.border + k] -= f * v;
        }
        for k in 0..dim {
            let v = rhs[c * dim + k];
            rhs[r * dim + k] -= f * v;
        }
    }

    /// Solves `A X = B` in place: `rhs` holds `B` row-major (`n × dim`) and receives `X`. The
    /// matrix is consumed (overwritten by its factor). Rows are first scaled to a largest entry
    /// of 1; a pivot below [`PIVOT_TOLERANCE`] gives [`Error::SingularSystem`] naming `what` and
    /// the row (after pivoting) where elimination stopped.
    pub fn solve(mut self, rhs: &mut [f64], dim: usize, what: &'static str) -> Result<()> {
        let n = self.n;
        debug_assert_eq!(rhs.len(), n * dim);
        for i in 0..n {
            let m = self.row_max(i);
            if m == 0.0 || !m.is_finite() {
                return Err(Error::SingularSystem { what, row: i });
            }
            self.scale_row(i, 1.0 / m, rhs, dim);
        }
        for c in 0..n {
            let rows_end = if c < self.band_end() {
                (c + self.lower + 1).min(n)
            } else {
                n
            };
            let (mut pivot_row, mut pivot) = (c, 0.0f64);
            for r in c..rows_end {
                let v = self.get(r, c);
                if v.abs() > pivot.abs() {
                    (pivot_row, pivot) = (r, v);
                }
            }
            if pivot.abs() <= PIVOT_TOLERANCE {
                return Err(Error::SingularSystem { what, row: c });
            }
            if pivot_row != c {
                self.swap_rows(c, pivot_row, c, rhs, dim);
            }
            for r in c + 1..rows_end {
                let f = self.get(r, c) / pivot;
                if f != 0.0 {
                    self.eliminate(r, c, f, c, rhs, dim);
                    self.set(r, c, 0.0);
                }
            }
        }
        for i in (0..n).rev() {
            let end = if i < self.band_end() {
                (i + self.lower + self.upper + 1).min(self.band_end())
            } else {
                i + 1
            };
            let diagonal = self.get(i, i);
            for k in 0..dim {
                let mut s = rhs[i * dim + k];
                for j in i + 1..end {
                    s -= self.get(i, j) * rhs[j * dim + k];
                }
                for j in self.band_end().max(i + 1)..n {
                    s -= self.get(i, j) * rhs[j * dim + k];
                }
                rhs[i * dim + k] = s / diagonal;
            }
        }
        Ok(())
    }
}

/// A symmetric `n × n` matrix of half-bandwidth `b` (`A_{ij} = 0` for `|i − j| > b`), stored as
/// its lower band: `lower[i·(b+1) + (i − j)]` holds `A_{ij}` for `i − b ≤ j ≤ i`.
#[derive(Debug, Clone)]
pub struct SymmetricBanded {
    n: usize,
    b: usize,
    lower: Vec<f64>,
}

impl SymmetricBanded {
    /// The zero matrix of size `n` and half-bandwidth `b`.
    pub fn new(n: usize, b: usize) -> Self {
        SymmetricBanded {
            n,
            b,
            lower: vec![0.0; n * (b + 1)],
        }
    }

    /// Adds `value` to `A_{ij}` (and so to `A_{ji}`); `false` outside the band.
    pub fn add(&mut self, i: usize, j: usize, value: f64) -> bool {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        if i >= self.n || i - j > self.b {
            return false;
        }
        self.lower[i * (self.b + 1) + (i - j)] += value;
        true
    }

    fn at(&self, i: usize, j: usize) -> f64 {
        self.lower[i * (self.b + 1) + (i - j)]
    }

    /// Solves `A X = B` in place by banded Cholesky `A = L Lᵀ` (`rhs` row-major `n × dim`).
    /// A pivot `L_{ii}² ≤ 16ε·A_{ii}` (or not above zero) gives [`Error::SingularSystem`]: the
    /// matrix is not (numerically) positive definite.
    pub fn solve_cholesky(mut self, rhs: &mut [f64], dim: usize, what: &'static str) -> Result<()> {
        let (n, b) = (self.n, self.b);
        debug_assert_eq!(rhs.len(), n * dim);
        for i in 0..n {
            for j in i.saturating_sub(b)..=i {
                let mut s = self.at(i, j);
                for k in i.saturating_sub(b)..j {
                    s -= self.at(i, k) * self.at(j, k);
                }
                let slot = i * (b + 1) + (i - j);
                if i == j {
                    let original = self.at(i, i);
                    if s.is_nan() || s <= PIVOT_TOLERANCE * original {
                        return Err(Error::SingularSystem { what, row: i });
                    }
                    self.lower[slot] = s.sqrt();
                } else {
                    self.lower[slot] = s / self.at(j, j);
                }
            }
        }
        for k in 0..dim {
            for i in 0..n {
                let mut s = rhs[i * dim + k];
                for j in i.saturating_sub(b)..i {
                    s -= self.at(i, j) * rhs[j * dim + k];
                }
                rhs[i * dim + k] = s / self.at(i, i);
            }
            for i in (0..n).rev() {
                let mut s = rhs[i * dim + k];
                for j in i + 1..(i + b + 1).min(n) {
                    s -= self.at(j, i) * rhs[j * dim + k];
                }
                rhs[i * dim + k] = s / self.at(i, i);
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    #[test]
    fn pivoting_solves_a_matrix_with_a_zero_diagonal() {
        // [[0, 1], [1, 0]] x = [2, 3] → x = [3, 2].
        let mut a = AlmostBanded::new(2, 1, 1, 0);
        assert!(a.add(0, 1, 1.0) && a.add(1, 0, 1.0));
        let mut rhs = [2.0, 3.0];
        a.solve(&mut rhs, 1, "test").unwrap();
        assert_eq!(rhs, [3.0, 2.0]);
    }

    #[test]
    fn singular_matrix_is_refused() {
        let mut a = AlmostBanded::new(2, 1, 1, 0);
        for (i, j) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            a.add(i, j, 1.0);
        }
        let e = a.solve(&mut [1.0, 2.0], 1, "test").unwrap_err();
        assert_eq!(
            e,
            Error::SingularSystem {
                what: "test",
                row: 1
            }
        );
    }

    #[test]
    fn border_columns_hold_the_corners_of_a_cyclic_matrix() {
        // A cyclic tridiagonal matrix (1 on the diagonal, 2 above, 3 below, corners wrapping)
        // with columns renumbered so column 0 is last: b = A x for a known x, then solve.
        let n = 7;
        let x: Vec<f64> = (0..n).map(|i| (i * i) as f64 - 3.0).collect();
        let entry = |i: usize, j: usize| match (j + n - i) % n {
            0 => 1.0,
            1 => 2.0,
            d if d == n - 1 => 3.0,
            _ => 0.0,
        };
        let b: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| entry(i, j) * x[j]).sum())
            .collect();
        // New column c holds unknown (c + 1) mod n; border = the last 3 columns.
        let mut a = AlmostBanded::new(n, 2, 1, 3);
        for i in 0..n {
            for j in 0..n {
                let v = entry(i, j);
                if v != 0.0 {
                    assert!(a.add(i, (j + n - 1) % n, v), "({i}, {j})");
                }
            }
        }
        let mut rhs = b.clone();
        a.solve(&mut rhs, 1, "test").unwrap();
        for c in 0..n {
            let want = x[(c + 1) % n];
            assert!(
                (rhs[c] - want).abs() < 1e-12,
                "x_{}: {} vs {want}",
                (c + 1) % n,
                rhs[c]
            );
        }
    }

    #[test]
    fn entries_outside_band_and_border_are_refused() {
        let mut a = AlmostBanded::new(6, 1, 1, 2);
        assert!(!a.add(0, 2, 1.0), "above the band");
        assert!(!a.add(3, 1, 1.0), "below the band");
        assert!(a.add(0, 4, 1.0), "border");
    }

    #[test]
    fn cholesky_of_a_tridiagonal() {
        // [[2, -1, 0], [-1, 2, -1], [0, -1, 2]] x = [1, 0, 1] → x = [1, 1, 1].
        let mut a = SymmetricBanded::new(3, 1);
        for i in 0..3 {
            a.add(i, i, 2.0);
        }
        a.add(1, 0, -1.0);
        a.add(1, 2, -1.0);
        let mut rhs = [1.0, 0.0, 1.0];
        a.solve_cholesky(&mut rhs, 1, "test").unwrap();
        for v in rhs {
            assert!((v - 1.0).abs() < 1e-15, "{rhs:?}");
        }
    }
}
