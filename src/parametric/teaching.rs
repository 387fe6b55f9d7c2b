//! What the formula panel and the "Bézier form" show: the exact Bernstein form of a
//! polynomial piece and the typed formulas with their symbolic derivatives as TeX.

use super::curve::ParametricCurve;
use crate::bezier::BezierCurve;
use crate::error::Result;
use crate::expr::{self, ExprError, Problem, Rational};
use glam::{DVec2, DVec3};

/// A polynomial piece in Bernstein form on its own interval `[from, to]`.
#[derive(Clone, Debug, PartialEq)]
pub struct BezierForm {
    /// The control points, flat (`dim` numbers each), degree = the highest of the coordinates'.
    pub points: Vec<f64>,
    /// The same exactly, when every coefficient and both bounds are rational.
    pub exact: Option<Vec<Rational>>,
    /// The piece's interval.
    pub from: f64,
    /// The piece's interval.
    pub to: f64,
}

/// One coordinate as TeX: the parsed text and its first two derivatives (`None` when a
/// derivative is too large to show).
#[derive(Clone, Debug, PartialEq)]
pub struct CoordinateTex {
    /// The expression as understood.
    pub expr: String,
    /// Its derivative with respect to t, lightly simplified.
    pub d1: Option<String>,
    /// The second derivative.
    pub d2: Option<String>,
}

/// A piece as TeX.
#[derive(Clone, Debug, PartialEq)]
pub struct PieceTex {
    /// x, y (and z).
    pub coords: Vec<CoordinateTex>,
    /// The start as TeX.
    pub from: String,
    /// The end as TeX.
    pub to: String,
}

impl ParametricCurve {
    /// Whether every coordinate of piece `i` is a polynomial in t (for the current parameter
    /// values).
    pub fn is_polynomial(&self, i: usize) -> Result<bool> {
        Ok(self.piece(i)?.coords.iter().all(|c| c.poly.is_some()))
    }

    /// Piece `i` in Bernstein form on `[from, to]`: `P(t) = Σ B_k^n(s) b_k`, `s = (t − from)/(to
    /// − from)`; an Error when the piece is not a polynomial.
    pub fn bezier_form(&self, i: usize) -> Result<BezierForm> {
        let p = self.piece(i)?;
        let (from, to) = (p.from.value, p.to.value);
        let mut polys: Vec<&expr::Polynomial> = Vec::with_capacity(p.coords.len());
        for c in &p.coords {
            let Some(q) = c.poly.as_ref() else {
                return Err(ExprError::at(0, 0, Problem::NotPolynomial {})
                    .in_piece(i)
                    .into());
            };
            polys.push(q);
        }
        let degree = polys
            .iter()
            .map(|q| q.coefficients.len().saturating_sub(1))
            .max()
            .unwrap_or(0)
            .max(1);
        let dim = self.dim;
        let mut points = vec![0.0; (degree + 1) * dim];
        let mut exact = match (p.from.exact, p.to.exact) {
            (Some(_), Some(_)) => Some(vec![Rational::ZERO; (degree + 1) * dim]),
            _ => None,
        };
        for (c, q) in polys.iter().enumerate() {
            let mut coefficients = q.coefficients.clone();
            coefficients.resize(degree + 1, 0.0);
            let b = expr::poly::bernstein_f64(&coefficients, from, to);
            for (k, v) in b.iter().enumerate() {
                if let Some(o) = points.get_mut(k * dim + c) {
                    *o = *v;
                }
            }
            let exact_b = match (&q.exact, p.from.exact, p.to.exact) {
                (Some(e), Some(a), Some(b)) => {
                    let mut e = e.clone();
                    e.resize(degree + 1, Rational::ZERO);
                    expr::poly::bernstein_exact(&e, a, b)
                }
                _ => None,
            };
            match (exact_b, exact.as_mut()) {
                (Some(e), Some(out)) => {
                    for (k, v) in e.iter().enumerate() {
                        if let Some(o) = out.get_mut(k * dim + c) {
                            *o = *v;
                        }
                        if let Some(o) = points.get_mut(k * dim + c) {
                            *o = v.to_f64();
                        }
                    }
                }
                _ => exact = None,
            }
        }
        Ok(BezierForm {
            points,
            exact,
            from,
            to,
        })
    }

    /// Piece `i` as a Bézier curve on its interval `[from, to]` (exact control points rounded
    /// once to f64).
    pub fn to_bezier(&self, i: usize) -> Result<BezierForm> {
        self.bezier_form(i)
    }

    /// Piece `i`'s formulas as TeX (parameters by name).
    pub fn tex(&self, i: usize) -> Result<PieceTex> {
        let p = self.piece(i)?;
        let coords = p
            .coords
            .iter()
            .map(|c| {
                let d1 = expr::derivative(&c.tree);
                let d2 = d1.as_ref().and_then(expr::derivative);
                CoordinateTex {
                    expr: expr::tex(&c.tree, &self.names),
                    d1: d1.map(|d| expr::tex(&d, &self.names)),
                    d2: d2.map(|d| expr::tex(&d, &self.names)),
                }
            })
            .collect();
        Ok(PieceTex {
            coords,
            from: expr::tex(&p.from.coordinate.tree, &self.names),
            to: expr::tex(&p.to.coordinate.tree, &self.names),
        })
    }
}

impl BezierForm {
    /// The 2D Bézier curve on `[from, to]` (of a 2D piece).
    pub fn curve_2d(&self) -> Result<BezierCurve<DVec2>> {
        BezierCurve::from_flat(&self.points, None)?.with_interval(self.from, self.to)
    }

    /// The 3D Bézier curve on `[from, to]` (of a 3D piece).
    pub fn curve_3d(&self) -> Result<BezierCurve<DVec3>> {
        BezierCurve::from_flat(&self.points, None)?.with_interval(self.from, self.to)
    }
}
