//! Tridiagonal and cyclic tridiagonal systems with vector right-hand sides, in O(n).
//!
//! Row `i` of a tridiagonal system reads
//! `lower[i−1]·x_{i−1} + diagonal[i]·x_i + upper[i]·x_{i+1} = rhs[i]` (`lower` and `upper`
//! have `size − 1` entries: `lower[i]` is the entry `(i+1, i)`, `upper[i]` the entry
//! `(i, i+1)`). A cyclic system adds the two corners `(0, size−1)` (top-right) and
//! `(size−1, 0)` (bottom-left). The unknowns are points or vectors (`P: Point`), so one
//! elimination solves every coordinate.

use crate::error::{Error, Result};
use crate::geom::Point;

/// A tridiagonal system, optionally cyclic, as it was solved (for display).
#[derive(Debug, Clone, PartialEq)]
pub struct Tridiagonal<P> {
    /// Sub-diagonal: `lower[i]` is the entry `(i+1, i)`; `size − 1` numbers.
    pub lower: Vec<f64>,
    /// Diagonal: `size` numbers.
    pub diagonal: Vec<f64>,
    /// Super-diagonal: `upper[i]` is the entry `(i, i+1)`; `size − 1` numbers.
    pub upper: Vec<f64>,
    /// Right-hand sides, one per row.
    pub rhs: Vec<P>,
    /// The corners `[top-right (0, size−1), bottom-left (size−1, 0)]` of a cyclic system
    /// (`None` for a plain one). With `size = 2` they add to `upper[0]` and `lower[0]`.
    pub corners: Option<[f64; 2]>,
}

impl<P: Point> Tridiagonal<P> {
    /// Number of rows (and unknowns).
    pub fn size(&self) -> usize {
        self.diagonal.len()
    }

    /// Solves the system: Thomas' algorithm, or Sherman–Morrison for a cyclic one.
    ///
    /// # Errors
    /// [`Error::SingularSystem`] naming `what` and the row of a zero pivot.
    pub fn solve(&self, what: &'static str) -> Result<Vec<P>> {
        match self.corners {
            None => solve_tridiagonal(&self.lower, &self.diagonal, &self.upper, &self.rhs, what),
            Some([top_right, bottom_left]) => solve_cyclic(
                &self.lower,
                &self.diagonal,
                &self.upper,
                [top_right, bottom_left],
                &self.rhs,
                what,
            ),
        }
    }
}

/// Whether `pivot` is zero for elimination: exactly zero, not finite, or below rounding at
/// the size `scale` of its row.
fn is_zero_pivot(pivot: f64, scale: f64) -> bool {
    !pivot.is_finite() || pivot.abs() <= f64::EPSILON * scale
}

/// Solves a tridiagonal system by Thomas' algorithm (Gaussian elimination without pivoting,
/// forward sweep then back substitution), O(size). Suits the diagonally dominant systems of
/// splines.
///
/// # Errors
/// [`Error::SingularSystem`] naming `what` and the row where a pivot vanished (relative to its
/// row's size); never a silent division by zero. Lengths must agree (`lower` and `upper`
/// `size − 1`, `rhs` `size`), else [`Error::SingularSystem`] at row 0 as well.
pub fn solve_tridiagonal<P: Point>(
    lower: &[f64],
    diagonal: &[f64],
    upper: &[f64],
    rhs: &[P],
    what: &'static str,
) -> Result<Vec<P>> {
    let n = diagonal.len();
    if n == 0 || rhs.len() != n || lower.len() + 1 != n || upper.len() + 1 != n {
        return Err(Error::SingularSystem { what, row: 0 });
    }
    // c'[i] = upper[i] / pivot_i, d'[i] = (rhs[i] − lower[i−1]·d'[i−1]) / pivot_i.
    let mut c = vec![0.0; n];
    let mut d = vec![P::ZERO; n];
    for i in 0..n {
        let (a, up) = (
            if i > 0 { lower[i - 1] } else { 0.0 },
            if i + 1 < n { upper[i] } else { 0.0 },
        );
        let scale = a.abs() + diagonal[i].abs() + up.abs();
        let pivot = if i > 0 {
            diagonal[i] - a * c[i - 1]
        } else {
            diagonal[0]
        };
        if is_zero_pivot(pivot, scale) {
            return Err(Error::SingularSystem { what, row: i });
        }
        let inv = 1.0 / pivot;
        c[i] = up * inv;
        d[i] = if i > 0 {
            (rhs[i] - d[i - 1] * a) * inv
        } else {
            rhs[0] * inv
        };
    }
    for i in (0..n - 1).rev() {
        d[i] = d[i] - d[i + 1] * c[i];
    }
    Ok(d)
}

/// Solves a cyclic tridiagonal system (corners `[top_right, bottom_left]`) by the
/// Sherman–Morrison formula: with `γ = −diagonal[0]` (1 if that is 0), `A = T + u vᵀ` where
/// `T` is the tridiagonal part with `diagonal[0] − γ` and `diagonal[n−1] − top_right·bottom_left/γ`,
/// `u = (γ, 0, …, 0, bottom_left)`, `v = (1, 0, …, 0, top_right/γ)`; solve `T y = rhs` and
/// `T z = u`, then `x = y − (v·y)/(1 + v·z) z`. Two Thomas sweeps, O(size). A system of size 2
/// folds the corners into the off-diagonals; size 1 is `(diagonal + both corners) x = rhs`.
///
/// # Errors
/// [`Error::SingularSystem`] for a zero pivot or a zero `1 + v·z`.
pub fn solve_cyclic<P: Point>(
    lower: &[f64],
    diagonal: &[f64],
    upper: &[f64],
    [top_right, bottom_left]: [f64; 2],
    rhs: &[P],
    what: &'static str,
) -> Result<Vec<P>> {
    let n = diagonal.len();
    if n == 0 || rhs.len() != n || lower.len() + 1 != n || upper.len() + 1 != n {
        return Err(Error::SingularSystem { what, row: 0 });
    }
    if n == 1 {
        let a = diagonal[0] + top_right + bottom_left;
        return solve_tridiagonal(&[], &[a], &[], rhs, what);
    }
    if n == 2 {
        return solve_tridiagonal(
            &[lower[0] + bottom_left],
            diagonal,
            &[upper[0] + top_right],
            rhs,
            what,
        );
    }
    let gamma = if diagonal[0] == 0.0 {
        1.0
    } else {
        -diagonal[0]
    };
    let mut modified = diagonal.to_vec();
    modified[0] -= gamma;
    modified[n - 1] -= top_right * bottom_left / gamma;
    let y = solve_tridiagonal(lower, &modified, upper, rhs, what)?;
    let mut u = vec![0.0; n];
    u[0] = gamma;
    u[n - 1] = bottom_left;
    let z = solve_tridiagonal(lower, &modified, upper, &u, what)?;
    let ratio = top_right / gamma;
    let denominator = 1.0 + z[0] + ratio * z[n - 1];
    if is_zero_pivot(denominator, 1.0 + z[0].abs() + (ratio * z[n - 1]).abs()) {
        return Err(Error::SingularSystem { what, row: n - 1 });
    }
    let numerator = y[0] + y[n - 1] * ratio;
    let factor = numerator * (1.0 / denominator);
    Ok(y.iter()
        .zip(&z)
        .map(|(&yi, &zi)| yi - factor * zi)
        .collect())
}
