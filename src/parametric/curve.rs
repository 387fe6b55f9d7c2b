//! The curve: pieces of parsed coordinates with their intervals, the parameters, evaluation.

use super::eval::Coordinate;
use super::MAX_PIECES;
use crate::error::{check_finite, Error, Result};
use crate::expr::{self, ExprError, Node, Problem, Rational};
use crate::geom::MAX_SAMPLES;

/// The texts of one piece, as typed: `x`, `y`, optional `z`, and the bounds `from`, `to`
/// (expressions too: `"2pi"`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PieceSource {
    /// x(t).
    pub x: String,
    /// y(t).
    pub y: String,
    /// z(t), for a 3D curve (on every piece or none).
    pub z: Option<String>,
    /// Start of the piece's interval.
    pub from: String,
    /// End of the piece's interval.
    pub to: String,
}

/// An interval bound: its tree (it may use parameters, not t), value and exact value.
#[derive(Clone, Debug)]
pub(super) struct Bound {
    pub(super) coordinate: Coordinate,
    pub(super) value: f64,
    pub(super) exact: Option<Rational>,
}

/// One piece: its coordinates on `[from, to)` (the last piece: `[from, to]`).
#[derive(Clone, Debug)]
pub(super) struct Piece {
    pub(super) coords: Vec<Coordinate>,
    pub(super) from: Bound,
    pub(super) to: Bound,
}

/// A curve typed as text, in pieces that join in t: piece i's `to` is piece i+1's `from`.
///
/// `P(t) = (x_i(t), y_i(t)[, z_i(t)])` for `t ∈ [from_i, to_i)`, the last piece closed on the
/// right; at a joint the right piece's value is taken. A point where an expression is
/// undefined (ln 0, 1/0) evaluates to NaN or ±∞.
#[derive(Clone, Debug)]
pub struct ParametricCurve {
    pub(super) dim: usize,
    pub(super) names: Vec<String>,
    pub(super) values: Vec<f64>,
    pub(super) pieces: Vec<Piece>,
}

/// A piece's `[from, to]`, each with its exact value when rational.
type Bounds = [(f64, Option<Rational>); 2];

/// Relative difference under which two typed bounds are the same joint (`pi/2` against
/// `1.5707963267948966`): rounding of the two texts, not a gap.
const JOIN_RELATIVE: f64 = 1e-12;

/// A field's tree, or its error placed in the piece and field.
#[inline(never)]
fn parse_field(text: &str, names: &[&str], piece: usize, field: &str) -> Result<expr::Expr> {
    expr::parse(text, names).map_err(|e| Error::from(e.in_field(piece, field)))
}

#[inline(never)]
fn place(piece: usize, field: &str, problem: Problem) -> Error {
    ExprError::at(0, 0, problem).in_field(piece, field).into()
}

/// Whether a tree reads t anywhere.
fn uses_t(e: &expr::Expr) -> bool {
    match &e.node {
        Node::T => true,
        Node::Number { .. } | Node::Param(_) | Node::Constant(_) => false,
        Node::Neg(a) | Node::Call(_, a) => uses_t(a),
        Node::Binary(_, a, b) => uses_t(a) || uses_t(b),
    }
}

impl ParametricCurve {
    /// The curve of `pieces` with the parameters `parameters` (name, value), in that order.
    ///
    /// Checked in this order: the piece count (1 ..= [`MAX_PIECES`]); the parameters (names
    /// one letter other than t and e, or a letter with a subscript; finite values); per piece
    /// x, y, z, from, to (every text parsed; z on every piece or none; a bound may use
    /// parameters but not t and must be finite); each interval non-empty; each piece starting
    /// where the previous one ends (within `1e-12` relative: then exactly there).
    pub fn new(pieces: &[PieceSource], parameters: &[(String, f64)]) -> Result<Self> {
        if pieces.is_empty() || pieces.len() > MAX_PIECES {
            return Err(ExprError::at(
                0,
                0,
                Problem::PieceCount {
                    count: pieces.len(),
                    max: MAX_PIECES,
                },
            )
            .into());
        }
        let mut names: Vec<String> = Vec::with_capacity(parameters.len());
        let mut values = Vec::with_capacity(parameters.len());
        for (name, value) in parameters {
            if !expr::is_parameter_name(name) || names.contains(name) {
                let mut e =
                    ExprError::at(0, 0, Problem::InvalidParameterName { name: name.clone() });
                e.field = Some(name.clone());
                return Err(e.into());
            }
            if !value.is_finite() {
                let mut e = ExprError::at(0, 0, Problem::NotFiniteValue { value: *value });
                e.field = Some(name.clone());
                return Err(e.into());
            }
            names.push(name.clone());
            values.push(*value);
        }
        let refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let dim = if pieces[0].z.is_some() { 3 } else { 2 };
        let mut built = Vec::with_capacity(pieces.len());
        for (i, p) in pieces.iter().enumerate() {
            let mut coords = Vec::with_capacity(dim);
            for (field, text) in [("x", Some(&p.x)), ("y", Some(&p.y)), ("z", p.z.as_ref())] {
                match text {
                    Some(text) if field != "z" || dim == 3 => {
                        coords.push(Coordinate::new(
                            parse_field(text, &refs, i, field)?,
                            &values,
                        ));
                    }
                    Some(_) => return Err(place(i, "z", Problem::MissingField {})),
                    None if dim == 3 => return Err(place(i, "z", Problem::MissingField {})),
                    None => {}
                }
            }
            let from = Self::bound(&p.from, &refs, &values, i, "from")?;
            let to = Self::bound(&p.to, &refs, &values, i, "to")?;
            built.push(Piece { coords, from, to });
        }
        let mut curve = ParametricCurve {
            dim,
            names,
            values,
            pieces: built,
        };
        let bounds = curve.bound_values(&curve.values)?;
        curve.set_bounds(bounds);
        Ok(curve)
    }

    fn bound(
        text: &str,
        names: &[&str],
        values: &[f64],
        piece: usize,
        field: &str,
    ) -> Result<Bound> {
        let tree = parse_field(text, names, piece, field)?;
        if uses_t(&tree) {
            let span = tree.span;
            return Err(ExprError::at(span.start, span.end, Problem::BoundUsesT {})
                .in_field(piece, field)
                .into());
        }
        let coordinate = Coordinate::new(tree, values);
        let (value, exact) = coordinate.constant(values);
        Ok(Bound {
            coordinate,
            value,
            exact,
        })
    }

    /// The bounds' values under the parameter values `values`, checked: finite, every
    /// interval non-empty, each piece starting where the previous one ends (a start within
    /// [`JOIN_RELATIVE`] of the previous end is taken as that end). Per piece `[from, to]`.
    fn bound_values(&self, values: &[f64]) -> Result<Vec<Bounds>> {
        let mut out: Vec<Bounds> = Vec::with_capacity(self.pieces.len());
        for (i, p) in self.pieces.iter().enumerate() {
            let mut from = p.from.coordinate.constant(values);
            let to = p.to.coordinate.constant(values);
            for (field, (v, _)) in [("from", from), ("to", to)] {
                if !v.is_finite() {
                    return Err(place(i, field, Problem::NotFiniteValue { value: v }));
                }
            }
            if let Some([_, end]) = out.last() {
                let scale = end.0.abs().max(from.0.abs()).max(1.0);
                if (from.0 - end.0).abs() > JOIN_RELATIVE * scale {
                    return Err(place(
                        i,
                        "from",
                        Problem::PiecesDoNotJoin {
                            previous: end.0,
                            from: from.0,
                        },
                    ));
                }
                from = (end.0, if from.1 == end.1 { end.1 } else { None });
            }
            if from.0 >= to.0 {
                return Err(place(
                    i,
                    "to",
                    Problem::EmptyInterval {
                        from: from.0,
                        to: to.0,
                    },
                ));
            }
            out.push([from, to]);
        }
        Ok(out)
    }

    /// Writes checked bound values (from [`Self::bound_values`]) into the pieces.
    fn set_bounds(&mut self, bounds: Vec<Bounds>) {
        for (p, [from, to]) in self.pieces.iter_mut().zip(bounds) {
            (p.from.value, p.from.exact) = from;
            (p.to.value, p.to.exact) = to;
        }
    }

    /// 2 or 3.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Number of pieces.
    pub fn piece_count(&self) -> usize {
        self.pieces.len()
    }

    /// `[a, b]`: the first piece's start and the last piece's end.
    pub fn domain(&self) -> (f64, f64) {
        let first = self.pieces.first().map_or(0.0, |p| p.from.value);
        let last = self.pieces.last().map_or(1.0, |p| p.to.value);
        (first, last)
    }

    /// Piece `i`'s interval `[from, to]`.
    pub fn piece_domain(&self, i: usize) -> Result<(f64, f64)> {
        let p = self.piece(i)?;
        Ok((p.from.value, p.to.value))
    }

    pub(super) fn piece(&self, i: usize) -> Result<&Piece> {
        self.pieces.get(i).ok_or(Error::IndexOutOfRange {
            index: i,
            count: self.pieces.len(),
        })
    }

    /// The parameters' names, in the order given.
    pub fn parameter_names(&self) -> &[String] {
        &self.names
    }

    /// The parameters' current values.
    pub fn parameter_values(&self) -> &[f64] {
        &self.values
    }

    /// Sets parameter `name` to `value` in place (the slider path: nothing is parsed again).
    /// Bounds that use it are evaluated again and checked as in [`ParametricCurve::new`]; on
    /// an error the curve keeps its previous value.
    pub fn set_parameter(&mut self, name: &str, value: f64) -> Result<()> {
        let Some(index) = self.names.iter().position(|n| n == name) else {
            return Err(
                ExprError::at(0, 0, Problem::UnknownParameter { name: name.into() }).into(),
            );
        };
        if !value.is_finite() {
            let mut e = ExprError::at(0, 0, Problem::NotFiniteValue { value });
            e.field = Some(name.into());
            return Err(e.into());
        }
        let mut values = self.values.clone();
        if let Some(v) = values.get_mut(index) {
            *v = value;
        }
        let bounds = self.bound_values(&values)?;
        self.values = values;
        self.set_bounds(bounds);
        for p in &mut self.pieces {
            for c in &mut p.coords {
                c.parameters_changed(&self.values);
            }
        }
        Ok(())
    }

    /// The index of the piece that holds `t` (checked against the domain first).
    pub(super) fn piece_at(&self, t: f64) -> Result<usize> {
        check_finite("t", None, t)?;
        let (a, b) = self.domain();
        if !(a..=b).contains(&t) {
            return Err(Error::ParameterOutOfRange {
                name: "t",
                value: t,
                min: a,
                max: b,
            });
        }
        // The last piece whose start is ≤ t: right-continuous at joints.
        let i = self.pieces.partition_point(|p| p.from.value <= t);
        Ok(i.saturating_sub(1))
    }

    /// `P(t)` into `out` (`dim` numbers).
    pub fn evaluate_into(&self, t: f64, out: &mut [f64]) -> Result<()> {
        let i = self.piece_at(t)?;
        let p = self.piece(i)?;
        for (o, c) in out.iter_mut().zip(&p.coords) {
            *o = defined(c.value(t, &self.values));
        }
        Ok(())
    }

    /// `P(t)`.
    pub fn evaluate(&self, t: f64) -> Result<Vec<f64>> {
        let mut out = vec![0.0; self.dim];
        self.evaluate_into(t, &mut out)?;
        Ok(out)
    }

    /// `P^(k)(t)` into `out` (`dim` numbers), `k ≤ MAX_JET_ORDER`: the k-th derivative by
    /// automatic differentiation of the piece that holds t (the right piece at a joint).
    pub fn derivative_into(&self, t: f64, order: usize, out: &mut [f64]) -> Result<()> {
        check_order(order)?;
        let i = self.piece_at(t)?;
        self.piece_derivatives(i, t, order, &mut |k, c, v| {
            if k == order {
                if let Some(o) = out.get_mut(c) {
                    *o = defined(v);
                }
            }
        })
    }

    /// `P^(k)(t)`.
    pub fn derivative(&self, t: f64, order: usize) -> Result<Vec<f64>> {
        let mut out = vec![0.0; self.dim];
        self.derivative_into(t, order, &mut out)?;
        Ok(out)
    }

    /// Derivatives `0..=order` of piece `i`'s coordinates at any `t` (not checked against the
    /// piece's interval: a joint's left side is piece i at its `to`), handed to `f(k, coordinate,
    /// value)`.
    pub(super) fn piece_derivatives(
        &self,
        i: usize,
        t: f64,
        order: usize,
        f: &mut dyn FnMut(usize, usize, f64),
    ) -> Result<()> {
        let p = self.piece(i)?;
        let mut jet = [0.0; expr::MAX_JET_ORDER + 1];
        let n = order.min(expr::MAX_JET_ORDER);
        for (c, coord) in p.coords.iter().enumerate() {
            coord.jet(t, n, &self.values, &mut jet[..=n]);
            for (k, v) in jet[..=n].iter().enumerate() {
                f(k, c, *v);
            }
        }
        Ok(())
    }

    /// The points at every t of `ts`, flat (`ts.len() · dim` numbers).
    pub fn sample(&self, ts: &[f64]) -> Result<Vec<f64>> {
        check_count(ts.len())?;
        let mut out = vec![0.0; ts.len() * self.dim];
        for (i, (t, o)) in ts.iter().zip(out.chunks_exact_mut(self.dim)).enumerate() {
            self.evaluate_into(*t, o).map_err(|e| in_list("ts", i, e))?;
        }
        Ok(out)
    }

    /// `count ≥ 2` points at equally spaced t over the domain, both ends included.
    pub fn sample_uniform(&self, count: usize) -> Result<Vec<f64>> {
        check_count(count)?;
        if count < 2 {
            return Err(Error::NotPositive {
                name: "count",
                value: count as f64,
            });
        }
        let (a, b) = self.domain();
        let mut out = vec![0.0; count * self.dim];
        let step = (b - a) / (count - 1) as f64;
        for (k, o) in out.chunks_exact_mut(self.dim).enumerate() {
            let t = if k + 1 == count {
                b
            } else {
                a + step * k as f64
            };
            self.evaluate_into(t.min(b), o)?;
        }
        Ok(out)
    }
}

/// An error about element `index` of the list argument `name` (`ts[3]`).
fn in_list(name: &'static str, index: usize, err: Error) -> Error {
    Error::InArgument {
        name,
        index: Some(index),
        source: Box::new(err),
    }
}

/// A coordinate as the API returns it: NaN where the formula is undefined (IEEE's ±∞ of
/// `1/0` or `ln 0` included), so "undefined" has one value.
fn defined(v: f64) -> f64 {
    if v.is_finite() {
        v
    } else {
        f64::NAN
    }
}

/// A derivative order the jets reach.
pub(super) fn check_order(order: usize) -> Result<()> {
    if order > expr::MAX_JET_ORDER {
        return Err(Error::TooLarge {
            what: "derivative-order",
            value: order,
            max: expr::MAX_JET_ORDER,
        });
    }
    Ok(())
}

fn check_count(count: usize) -> Result<()> {
    if count > MAX_SAMPLES {
        return Err(Error::TooLarge {
            what: "sample-count",
            value: count,
            max: MAX_SAMPLES,
        });
    }
    Ok(())
}
