//! One cubic piece through a run of samples `Q_a … Q_b`: end points fixed at `P_0 = Q_a`,
//! `P_3 = Q_b`, the handles `A = P_1 − P_0` and `B = P_3 − P_2` chosen by least squares.
//!
//! With parameters `u_i` and the Bernstein weights `b_k = B_k^3(u_i)` the piece is
//! `C(u) = (b_0 + b_1) P_0 + (b_2 + b_3) P_3 + b_1 A − b_2 B`, linear in the handles, so
//! minimising `E = Σ |Q_i − C(u_i)|²` is a small linear system. Each end is either free (`A`
//! any vector), along a given unit tangent (`A = α d`, `α` free: a G1 joint), or fixed (`A`
//! given: the C1 joint with a neighbour). Between solves every `u_i` takes a Newton step
//! towards the closest point, `u ← u − f/f'` with `f = (C − Q)·C'`, `f' = C'·C' + (C − Q)·C''`
//! (Schneider's reparametrisation). Handle lengths are clamped to `[10⁻³ L, L]` (`L` the run's
//! polyline length) so a piece cannot loop or spike far beyond the stroke, and a check of the
//! curve between samples rejects what still does.

use super::stroke::Stroke;
use crate::geom::Cartesian;

/// The most samples the least-squares solve uses; longer runs are subsampled evenly (every
/// sample is still checked against the tolerance).
pub(crate) const FIT_SAMPLES: usize = 48;

/// The weight of the residual's tangential component after the first round.
const TANGENTIAL: f64 = 0.02;

/// Reparametrise-and-solve rounds per fit.
const ROUNDS: usize = 4;

/// How an end of a piece is constrained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum End<C> {
    /// The handle is free.
    Free,
    /// The handle lies along this unit vector (pointing along the stroke's direction).
    Dir(C),
    /// The handle is this vector (`P_1 − P_0` at the start, `P_3 − P_2` at the end).
    Handle(C),
}

/// A cubic with its power-basis coefficients for fast evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Cubic<C> {
    /// The control points.
    pub ctrl: [C; 4],
    /// `C(u) = c[0] + c[1] u + c[2] u² + c[3] u³`.
    c: [C; 4],
}

impl<C: Cartesian> Cubic<C> {
    /// The cubic with these control points.
    pub fn new(ctrl: [C; 4]) -> Self {
        let [p0, p1, p2, p3] = ctrl;
        let c = [
            p0,
            (p1 - p0) * 3.0,
            (p0 - p1 * 2.0 + p2) * 3.0,
            p3 - p0 + (p1 - p2) * 3.0,
        ];
        Cubic { ctrl, c }
    }

    /// `C(u)`.
    #[inline]
    pub fn eval(&self, u: f64) -> C {
        let c = &self.c;
        ((c[3] * u + c[2]) * u + c[1]) * u + c[0]
    }

    /// `C(u)`, `C'(u)`, `C''(u)`.
    #[inline]
    pub fn eval2(&self, u: f64) -> (C, C, C) {
        let c = &self.c;
        let p = ((c[3] * u + c[2]) * u + c[1]) * u + c[0];
        let d1 = (c[3] * (3.0 * u) + c[2] * 2.0) * u + c[1];
        let d2 = c[3] * (6.0 * u) + c[2] * 2.0;
        (p, d1, d2)
    }

    /// One Newton step of `u` towards the closest point to `q`, kept in `[0, 1]`.
    #[inline(never)]
    pub fn newton(&self, q: C, u: f64) -> f64 {
        let (p, d1, d2) = self.eval2(u);
        let r = p - q;
        let f = r.dot_with(d1);
        let df = d1.dot_with(d1) + r.dot_with(d2);
        if df > 0.0 {
            let v = u - f / df;
            if v.is_finite() {
                return v.clamp(0.0, 1.0);
            }
        }
        u
    }
}

/// The outcome of fitting and checking one run.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PieceFit<C> {
    /// The piece.
    pub cubic: Cubic<C>,
    /// Whether every sample is within the tolerance and the curve stays near the stroke.
    pub ok: bool,
}

/// Reusable scratch for fitting runs (no allocation per fit once warmed up).
#[derive(Debug, Default)]
pub(crate) struct Fitter {
    /// Indices of the samples used by the solve.
    idx: Vec<usize>,
    /// Their parameters.
    u: Vec<f64>,
}

impl Fitter {
    /// Fits the run `a..=b` of `stroke` (`a < b`) with end constraints `start`, `end`, then
    /// checks every sample against `tol` (stopping at the first one beyond it).
    pub fn fit<C: Cartesian>(
        &mut self,
        stroke: &Stroke<C>,
        a: usize,
        b: usize,
        start: End<C>,
        end: End<C>,
        tol: f64,
    ) -> PieceFit<C> {
        let cubic = self.solve(stroke, a, b, start, end);
        let ok = self.check(stroke, a, b, &cubic, tol).1;
        PieceFit { cubic, ok }
    }

    /// The least-squares piece (with reparametrisation) for the run `a..=b`.
    pub fn solve<C: Cartesian>(
        &mut self,
        stroke: &Stroke<C>,
        a: usize,
        b: usize,
        start: End<C>,
        end: End<C>,
    ) -> Cubic<C> {
        let pts = &stroke.pts;
        let (p0, p3) = (pts[a], pts[b]);
        let len = stroke.arc[b] - stroke.arc[a];
        let chord = p3 - p0;
        // The default handles: a third of the chord along the constraint.
        let default = |e: End<C>| match e {
            End::Handle(h) => h,
            End::Dir(d) => d * (len.max(chord.norm()) / 3.0),
            End::Free => chord * (1.0 / 3.0),
        };
        let mut handles = (default(start), default(end));
        if b == a + 1 {
            return piece(p0, p3, handles);
        }
        self.subsample(stroke, a, b);
        for round in 0..ROUNDS {
            let current = piece(p0, p3, handles);
            if round > 0 {
                let last = self.u.len() - 1;
                for k in 1..last {
                    self.u[k] = current.newton(pts[self.idx[k]], self.u[k]);
                }
            }
            let tangents = (round > 0).then_some(&current);
            if let Some(h) = self.least_squares(pts, p0, p3, start, end, tangents) {
                handles = h;
            }
            // A fixed handle (a C1 joint) stays as given.
            if !matches!(start, End::Handle(_)) {
                handles.0 = clamp_handle(forward(start, handles.0, len), len);
            }
            if !matches!(end, End::Handle(_)) {
                handles.1 = clamp_handle(forward(end, handles.1, len), len);
            }
        }
        piece(p0, p3, handles)
    }

    /// Evenly spaced sample indices of `a..=b` (all when few) and chord-length parameters.
    fn subsample<C: Cartesian>(&mut self, stroke: &Stroke<C>, a: usize, b: usize) {
        self.idx.clear();
        self.u.clear();
        let count = b - a + 1;
        if count <= FIT_SAMPLES {
            self.idx.extend(a..=b);
        } else {
            let m = FIT_SAMPLES - 1;
            self.idx
                .extend((0..=m).map(|k| a + ((b - a) as f64 * k as f64 / m as f64) as usize));
            self.idx[m] = b;
        }
        let (s0, s1) = (stroke.arc[a], stroke.arc[b]);
        let span = s1 - s0;
        let n = self.idx.len() - 1;
        for (k, &i) in self.idx.iter().enumerate() {
            let u = if span > 0.0 {
                (stroke.arc[i] - s0) / span
            } else {
                k as f64 / n as f64
            };
            self.u.push(u);
        }
    }

    /// Solves the normal equations for the free handle components; `None` when singular.
    ///
    /// With `current` (the previous round's piece) the residual's component along that
    /// piece's unit tangent `t_i` at `u_i` counts only with weight [`TANGENTIAL`]: the
    /// squared-distance minimisation of Wang, Pottmann & Liu (2006), which converges in a few
    /// rounds where the plain point distance (all components, the first round) creeps — a
    /// sample's tangential offset is what the next reparametrisation removes anyway.
    #[allow(clippy::needless_range_loop)]
    fn least_squares<C: Cartesian>(
        &self,
        pts: &[C],
        p0: C,
        p3: C,
        start: End<C>,
        end: End<C>,
        current: Option<&Cubic<C>>,
    ) -> Option<(C, C)> {
        // Unknowns: (side, direction). A = a_fix + Σ x_j e_j, B = b_fix + Σ x_j e_j.
        let mut dirs = [(0usize, C::ZERO); 6];
        let mut count = 0;
        let mut fixed = [C::ZERO; 2];
        for (side, e) in [start, end].into_iter().enumerate() {
            match e {
                End::Handle(h) => fixed[side] = h,
                End::Dir(d) => {
                    dirs[count] = (side, d);
                    count += 1;
                }
                End::Free => {
                    for k in 0..C::DIM {
                        let mut axis = [0.0; 3];
                        axis[k] = 1.0;
                        dirs[count] = (side, C::from_slice(&axis));
                        count += 1;
                    }
                }
            }
        }
        if count == 0 {
            return Some((fixed[0], fixed[1]));
        }
        // Residual R − b1 A + b2 B: the weight of side A is b1, of side B −b2.
        let mut m = [[0.0; 7]; 6];
        for (&i, &u) in self.idx.iter().zip(&self.u) {
            let v = 1.0 - u;
            let (b0, b1, b2, b3) = (v * v * v, 3.0 * u * v * v, 3.0 * u * u * v, u * u * u);
            let r = pts[i] - p0 * (b0 + b1) - p3 * (b2 + b3) - fixed[0] * b1 + fixed[1] * b2;
            let w = [b1, -b2];
            // P = I − (1 − λ) t tᵀ.
            let (t, shrink) = match current {
                Some(c) => {
                    let d = c.eval2(u).1;
                    let n = d.norm();
                    if n > 0.0 {
                        (d * (1.0 / n), 1.0 - TANGENTIAL)
                    } else {
                        (C::ZERO, 0.0)
                    }
                }
                None => (C::ZERO, 0.0),
            };
            let tr = t.dot_with(r);
            for j in 0..count {
                let (sj, ej) = dirs[j];
                let wj = w[sj];
                let ejt = ej.dot_with(t);
                for l in j..count {
                    let (sl, el) = dirs[l];
                    m[j][l] += wj * w[sl] * (ej.dot_with(el) - shrink * ejt * el.dot_with(t));
                }
                m[j][count] += wj * (ej.dot_with(r) - shrink * ejt * tr);
            }
        }
        for j in 0..count {
            for l in 0..j {
                m[j][l] = m[l][j];
            }
        }
        let x = solve_small(&mut m, count)?;
        let mut out = fixed;
        for j in 0..count {
            out[dirs[j].0] = out[dirs[j].0] + dirs[j].1 * x[j];
        }
        Some((out[0], out[1]))
    }

    /// Checks every sample of `a..=b` against `cubic`: parameters interpolated from the
    /// solve's (by arc length), two Newton steps, the distance to that point of the curve (an
    /// upper bound of the distance to the piece). Also checks, at the solve's samples, that the
    /// curve between consecutive ones stays within `tol + ¼·gap` of their chord (no loops or
    /// spikes). Returns the largest bound seen and whether all passed; stops at the first
    /// failure.
    #[allow(clippy::needless_range_loop)]
    pub fn check<C: Cartesian>(
        &self,
        stroke: &Stroke<C>,
        a: usize,
        b: usize,
        cubic: &Cubic<C>,
        tol: f64,
    ) -> (f64, bool) {
        if b <= a + 1 {
            return (0.0, true);
        }
        let pts = &stroke.pts;
        let mut worst: f64 = 0.0;
        // Between consecutive solve samples.
        for k in 0..self.idx.len() - 1 {
            let (i, j) = (self.idx[k], self.idx[k + 1]);
            let um = 0.5 * (self.u[k] + self.u[k + 1]);
            let gap = (pts[j] - pts[i]).norm();
            let d = cubic.eval(um).distance_to_segment(pts[i], pts[j]);
            let allowed = tol + 0.25 * gap + 0.5 * (stroke.arc[j] - stroke.arc[i] - gap);
            if d.is_nan() || d > allowed {
                return (d.max(worst), false);
            }
        }
        for k in 0..self.idx.len() - 1 {
            let (i, j) = (self.idx[k], self.idx[k + 1]);
            let (u0, u1) = (self.u[k], self.u[k + 1]);
            let (s0, s1) = (stroke.arc[i], stroke.arc[j]);
            let span = s1 - s0;
            for m in i..j {
                let q = pts[m];
                let mut u = if span > 0.0 {
                    u0 + (u1 - u0) * (stroke.arc[m] - s0) / span
                } else {
                    u0
                };
                let mut d = (cubic.eval(u) - q).norm();
                let mut steps = 0;
                while d > 0.25 * tol && steps < 3 {
                    u = cubic.newton(q, u);
                    d = (cubic.eval(u) - q).norm();
                    steps += 1;
                }
                worst = worst.max(d);
                if d.is_nan() || d > tol {
                    return (worst, false);
                }
            }
        }
        (worst, true)
    }
}

/// The cubic with end points `p0`, `p3` and handles `(A, B)`.
pub(crate) fn piece<C: Cartesian>(p0: C, p3: C, (a, b): (C, C)) -> Cubic<C> {
    Cubic::new([p0, p0 + a, p3 - b, p3])
}

/// A handle along a tangent direction kept pointing forward along it: the least squares may
/// ask for a negative length (the samples pull the other way), which would turn a G1 joint
/// into a cusp; it gets the shortest length [`clamp_handle`] allows instead.
fn forward<C: Cartesian>(end: End<C>, h: C, len: f64) -> C {
    match end {
        End::Dir(d) if h.dot_with(d) <= 0.0 => d * (1e-3 * len),
        _ => h,
    }
}

/// A handle with its length kept in `[10⁻³ L, L]` (unchanged when `L = 0` or not finite).
fn clamp_handle<C: Cartesian>(h: C, len: f64) -> C {
    let n = h.norm();
    if len.is_nan() || len <= 0.0 || !n.is_finite() {
        return if n.is_finite() { h } else { C::ZERO };
    }
    if n > len {
        h * (len / n)
    } else if n < 1e-3 * len && n > 0.0 {
        h * (1e-3 * len / n)
    } else {
        h
    }
}

/// Gaussian elimination with partial pivoting on the augmented `count × (count + 1)` system;
/// `None` when a pivot is negligible.
#[allow(clippy::needless_range_loop)]
fn solve_small(m: &mut [[f64; 7]; 6], count: usize) -> Option<[f64; 6]> {
    let scale = (0..count).map(|i| m[i][i].abs()).fold(0.0, f64::max);
    if scale.is_nan() || scale <= 0.0 || !scale.is_finite() {
        return None;
    }
    for col in 0..count {
        let pivot = (col..count).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        if m[pivot][col].abs() <= 1e-12 * scale {
            return None;
        }
        m.swap(col, pivot);
        for row in col + 1..count {
            let f = m[row][col] / m[col][col];
            for k in col..=count {
                m[row][k] -= f * m[col][k];
            }
        }
    }
    let mut x = [0.0; 6];
    for row in (0..count).rev() {
        let mut s = m[row][count];
        for k in row + 1..count {
            s -= m[row][k] * x[k];
        }
        x[row] = s / m[row][row];
    }
    x.iter().take(count).all(|v| v.is_finite()).then_some(x)
}
