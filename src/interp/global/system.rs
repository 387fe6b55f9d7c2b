//! The collocation system of global interpolation: one row per equation, `p + 1` coefficients
//! each, and its solution by the banded solver (cyclic rows for a closed curve).
//!
//! Row `C(τ) = p` holds the basis functions `N_{k−p,p}(τ) … N_{k,p}(τ)` of the span `k` of `τ`
//! in columns `k − p … k`; a derivative row `C'(τ) = D` holds their derivatives. For an open
//! curve the columns are the control points and the matrix is banded (bandwidth `≤ p` on each
//! side when Schoenberg–Whitney holds). For a closed curve there are `N` distinct control points
//! `P_j = P_{j mod N}`, so column `j` wraps to `j mod N`: a cyclic band, whose corners the
//! solver keeps in a dense border after moving the first `M` columns to the end (`M` = the
//! largest cyclic offset of an entry from the diagonal), O(N·p²) in all.

use super::super::banded::AlmostBanded;
use crate::bspline::{basis_derivatives, basis_functions, BasisScratch, KnotVector};
use crate::error::Result;

/// What equation a row of the interpolation system states.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RowKind {
    /// `C(t_i) = p_i`.
    Point,
    /// `C'(t_0) = D_0`.
    StartDerivative,
    /// `C'(t_n) = D_n`.
    EndDerivative,
}

impl RowKind {
    /// The word the JS layer uses: `"point"`, `"start-derivative"`, `"end-derivative"`.
    pub fn as_str(self) -> &'static str {
        match self {
            RowKind::Point => "point",
            RowKind::StartDerivative => "start-derivative",
            RowKind::EndDerivative => "end-derivative",
        }
    }
}

/// The rows of a collocation system: row `r` has `p + 1` values for columns
/// `firsts[r] … firsts[r] + p` (taken mod `size` when `cyclic`).
#[derive(Debug, Clone)]
pub(crate) struct Collocation {
    pub degree: usize,
    pub size: usize,
    pub cyclic: bool,
    pub firsts: Vec<usize>,
    pub values: Vec<f64>,
    pub kinds: Vec<RowKind>,
}

impl Collocation {
    /// An empty system of `size` unknowns.
    pub fn new(degree: usize, size: usize, cyclic: bool) -> Self {
        Collocation {
            degree,
            size,
            cyclic,
            firsts: Vec::with_capacity(size),
            values: Vec::with_capacity(size * (degree + 1)),
            kinds: Vec::with_capacity(size),
        }
    }

    /// Appends the row of `kind` at parameter `t` (`t` in the knots' domain): values for a
    /// point row, first derivatives otherwise. `scratch` is reused between rows.
    pub fn push(&mut self, knots: &KnotVector, t: f64, kind: RowKind, scratch: &mut BasisScratch) {
        let p = self.degree;
        // Sites come in increasing order: start the span search at the previous row's span.
        let hint = self.firsts.last().map_or(p, |&first| first + p);
        let k = knots.span_from(t, hint);
        self.firsts.push(k - p);
        let start = self.values.len();
        self.values.resize(start + p + 1, 0.0);
        if kind == RowKind::Point {
            basis_functions(
                knots.as_slice(),
                k,
                t,
                p,
                &mut self.values[start..],
                scratch,
                None,
            );
        } else {
            let ders = basis_derivatives(knots.as_slice(), k, t, p, 1);
            self.values[start..].copy_from_slice(&ders[1]);
        }
        self.kinds.push(kind);
    }

    /// The entries of row `r`: `(column, value)`, columns wrapped for a cyclic system.
    pub fn entries(&self, r: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let w = self.degree + 1;
        let first = self.firsts[r];
        self.values[r * w..(r + 1) * w]
            .iter()
            .enumerate()
            .map(move |(j, &v)| {
                let col = first + j;
                (if self.cyclic { col % self.size } else { col }, v)
            })
    }

    /// The matrix written out dense, row-major `size × size` (entries that wrap onto the same
    /// column of a small closed system add up, as in the solver).
    pub fn dense(&self) -> Vec<f64> {
        let n = self.size;
        let mut out = vec![0.0; n * n];
        for r in 0..self.kinds.len() {
            for (col, v) in self.entries(r) {
                out[r * n + col] += v;
            }
        }
        out
    }

    /// Solves the system for `rhs` (row-major `size × dim`) in place, in O(size·p²).
    pub fn solve(&self, rhs: &mut [f64], dim: usize, what: &'static str) -> Result<()> {
        if !self.cyclic {
            let (mut lower, mut upper) = (0, 0);
            for (r, &first) in self.firsts.iter().enumerate() {
                lower = lower.max(r.saturating_sub(first));
                upper = upper.max((first + self.degree).saturating_sub(r));
            }
            let mut a = AlmostBanded::new(self.size, lower, upper, 0);
            for r in 0..self.kinds.len() {
                for (col, v) in self.entries(r) {
                    a.add(r, col, v);
                }
            }
            return a.solve(rhs, dim, what);
        }
        self.solve_cyclic(rhs, dim, what)
    }

    /// The cyclic case: columns renumbered `j ↦ (j − M) mod N` so the wrapped corners land in
    /// the last `2M + 1` columns, kept dense (an entry at cyclic offset `δ ∈ [−M, M]` from the
    /// diagonal then lies at `r − 2M ≤ c ≤ r` or in that border); a small system is solved
    /// dense outright.
    fn solve_cyclic(&self, rhs: &mut [f64], dim: usize, what: &'static str) -> Result<()> {
        let n = self.size;
        let mut reach = 0usize;
        for r in 0..self.kinds.len() {
            for (col, _) in self.entries(r) {
                let d = (col + n - r) % n;
                reach = reach.max(d.min(n - d));
            }
        }
        let border = 2 * reach + 1;
        let renumber = |col: usize| (col + n - reach % n) % n;
        let (mut lower, mut upper) = (0, 0);
        for r in 0..self.kinds.len() {
            for (col, _) in self.entries(r) {
                let c = renumber(col);
                if c + border < n {
                    lower = lower.max(r.saturating_sub(c));
                    upper = upper.max(c.saturating_sub(r));
                }
            }
        }
        let mut a = AlmostBanded::new(n, lower, upper, border);
        let fits = border + 2 * reach + 2 <= n
            && (0..self.kinds.len())
                .all(|r| self.entries(r).all(|(col, v)| a.add(r, renumber(col), v)));
        if !fits {
            a = AlmostBanded::new(n, 0, 0, n);
            for r in 0..self.kinds.len() {
                for (col, v) in self.entries(r) {
                    a.add(r, renumber(col), v);
                }
            }
        }
        a.solve(rhs, dim, what)?;
        unrenumber(rhs, dim, n, reach);
        Ok(())
    }
}

/// Undoes the column renumbering `j ↦ (j − shift) mod n` on a solution: unknown `j` is row
/// `(j − shift) mod n` of `x`.
fn unrenumber(x: &mut [f64], dim: usize, n: usize, shift: usize) {
    if n == 0 || shift.is_multiple_of(n) {
        return;
    }
    // x_new[c] holds unknown (c + shift) mod n: rotate right by `shift` rows.
    x.rotate_right((shift % n) * dim);
}
