//! Closed (periodic) interpolation, as scipy's `make_interp_spline(x, y, k,
//! bc_type="periodic")`: the data close (`p_n = p_0`), the knots are scipy's periodic knots
//! ([`super::knots::periodic_knots`], domain `[t_0, t_n]`, gaps repeating with the period
//! `t_n − t_0`), and the `N = n` distinct control points `P_0 … P_{N−1}` repeat,
//! `P_{N+j} = P_j` for `j < p`, so the curve and its first `p − 1` derivatives agree at `t_0` and
//! `t_n`. The `N` equations `C(t_i) = p_i`, `i < N`, form a cyclic banded system (row `i` holds
//! `N_{k−p,p}(t_i) … N_{k,p}(t_i)` in columns `(k − p) mod N … k mod N`), solved in O(N·p²).

use super::system::{Collocation, RowKind};
use super::{knots::periodic_knots, Setup};
use crate::bspline::{BasisScratch, KnotVector};
use crate::error::InterpError;
use crate::error::{Error, Result};

/// The periodic system for the points `coords` (flat, dimension `dim`; last = first) at
/// `params`.
///
/// # Errors
/// [`InterpError::NotClosed`] when the last point differs from the first.
pub(super) fn setup(coords: &[f64], dim: usize, degree: usize, params: &[f64]) -> Result<Setup> {
    let n = coords.len() / dim - 1;
    if coords[n * dim..] != coords[..dim] {
        return Err(Error::Interp(InterpError::NotClosed { last: n }));
    }
    let knots = KnotVector::new(periodic_knots(params, degree), degree, n + degree)?;
    let mut rows = Collocation::new(degree, n, true);
    let mut scratch = BasisScratch::default();
    for &t in &params[..n] {
        rows.push(&knots, t, RowKind::Point, &mut scratch);
    }
    Ok(Setup {
        knots,
        rows,
        rhs: coords[..n * dim].to_vec(),
        dim,
    })
}
