//! Joint verdicts: at each joint, the largest k ≤ 3 with C^k and with G^k, the first
//! derivative order that differs and its one-sided values, and whether it is proven.
//!
//! - **C^k**: the one-sided derivatives of orders 0..=k are equal.
//! - **G^k** (geometric continuity: C^k after a regular reparametrisation; C^k implies G^k):
//!   G⁰ = the pieces meet; G¹ = the unit tangents agree (the direction of the first
//!   non-vanishing derivative where the velocity is 0); G² = also the curvature vectors
//!   `κN = (a|v|² − (a·v)v)/|v|⁴`; G³ = also their arc-length derivatives `d(κN)/ds`.
//! - **Exact**: when both pieces are polynomials with rational coefficients (typed decimals)
//!   and the joint is rational, every comparison is made in exact fractions and the verdict is
//!   proven; identical polynomials on both sides give C^∞ (`c = g = ∞`).
//! - **Otherwise** values from the jets are compared with a tolerance invariant under scaling
//!   space and t: order-k differences are measured as `|Δ⁽ᵏ⁾|·T^k ≤ ε·L` with T the shorter
//!   piece's length in t and L the two pieces' extent in space (ε = 1e-9); geometric
//!   quantities alike (unit tangents ε, curvature vectors ε/L, their derivatives ε/L²). Where
//!   interval enclosures of the differing order's two sides are disjoint (orders ≤ 2), the
//!   "not C^k" part of the verdict is proven too ([`Joint::disjoint`]).

use super::curve::ParametricCurve;
use super::eval::{Coordinate, Interval};
use crate::expr::{self, opaque, Rational};

/// The verdict at one joint.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// The joint's parameter value.
    pub t: f64,
    /// Largest k ≤ 3 with C^k; −1: the pieces do not meet; `f64::INFINITY`: both sides are
    /// one polynomial.
    pub c: f64,
    /// Largest k ≤ 3 with G^k (≥ `c`), same conventions.
    pub g: f64,
    /// The verdict is proven in exact arithmetic.
    pub exact: bool,
    /// The first derivative order (≤ [`expr::MAX_JET_ORDER`]) whose one-sided values differ.
    pub order: Option<usize>,
    /// Its value from the left piece (`dim` numbers).
    pub left: Option<Vec<f64>>,
    /// Its value from the right piece.
    pub right: Option<Vec<f64>>,
    /// The interval enclosures of that order's two sides are disjoint: "not C^order" is
    /// proven even where the comparison is not exact.
    pub disjoint: bool,
}

/// Relative tolerance of the floating comparisons.
const EPS: f64 = 1e-9;

/// Orders compared for C^k (the verdict stops at 3) and searched for the first difference.
const C_MAX: usize = 3;

/// Derivatives 0..=MAX_JET_ORDER at a joint.
const N: usize = expr::MAX_JET_ORDER + 1;

/// A vector of a 2D or 3D curve, padded with zeros to three coordinates (zeros change no
/// distance, dot product or comparison; fixed arrays keep the wasm small).
type V = [f64; 3];
/// The same in exact fractions.
type Q = [Rational; 3];

impl ParametricCurve {
    /// The verdict at every joint, in order (`pieceCount − 1` entries).
    pub fn joints(&self) -> Vec<Joint> {
        (0..self.pieces.len().saturating_sub(1))
            .map(|i| self.joint(i))
            .collect()
    }

    /// Piece `i`'s and piece `i + 1`'s derivatives 0..=MAX_JET_ORDER at their joint.
    fn sides(&self, i: usize, t: f64) -> [[V; N]; 2] {
        let mut sides = [[[0.0; 3]; N]; 2];
        for (s, side) in opaque(&mut sides[..]).iter_mut().enumerate() {
            let _ =
                self.piece_derivatives(i + s, t, opaque(expr::MAX_JET_ORDER), &mut |k, c, v| {
                    if let Some(x) = side.get_mut(k).and_then(|d| d.get_mut(c)) {
                        *x = v;
                    }
                });
        }
        sides
    }

    fn joint(&self, i: usize) -> Joint {
        let (Some(left), Some(right)) = (self.pieces.get(i), self.pieces.get(i + 1)) else {
            return Joint::none(f64::NAN);
        };
        let t = right.from.value;
        let [l, r] = self.sides(i, t);
        let exact = match right.from.exact {
            Some(tj) => exact_verdict(&left.coords, &right.coords, tj),
            None => None,
        };
        let mut joint = match exact {
            Some(v) => Joint {
                t,
                c: v.c,
                g: v.g,
                exact: true,
                order: v.order,
                left: None,
                right: None,
                disjoint: v.order.is_some(),
            },
            None => self.float_verdict(i, t, opaque(&l[..]), opaque(&r[..])),
        };
        if let Some(k) = joint.order {
            let value = |side: &[V; N]| {
                side.get(k)
                    .and_then(|v| v.get(..self.dim))
                    .map(<[f64]>::to_vec)
            };
            joint.left = value(&l);
            joint.right = value(&r);
        }
        joint
    }

    /// The verdict from f64 jets (see the module's comment for the tolerances).
    fn float_verdict(&self, i: usize, t: f64, l: &[V], r: &[V]) -> Joint {
        let (time, space) = self.scales(i);
        let order = l.iter().zip(r).zip(0..).position(|((a, b), k)| {
            let d = dist(a, b);
            !(d.is_finite() && d * time.powi(k) <= EPS * space)
        });
        let c = if self.same_polynomials(i) {
            f64::INFINITY
        } else {
            match order {
                Some(k) if k <= C_MAX => k as f64 - 1.0,
                _ => C_MAX as f64,
            }
        };
        let g = if c.is_infinite() {
            c
        } else {
            c.max(geometric(l, r, space) as f64)
        };
        let disjoint = order.is_some_and(|k| k <= 2 && self.disjoint_at(i, t, k));
        Joint {
            t,
            c,
            g,
            exact: false,
            order,
            left: None,
            right: None,
            disjoint,
        }
    }

    /// Whether both pieces are polynomials with the same coefficients (C^∞ at the joint).
    fn same_polynomials(&self, i: usize) -> bool {
        let (Some(a), Some(b)) = (self.pieces.get(i), self.pieces.get(i + 1)) else {
            return false;
        };
        a.coords
            .iter()
            .zip(&b.coords)
            .all(|(x, y)| match (&x.poly, &y.poly) {
                (Some(p), Some(q)) => {
                    let n = p.coefficients.len().max(q.coefficients.len());
                    let scale = p
                        .coefficients
                        .iter()
                        .chain(&q.coefficients)
                        .fold(0.0f64, |m, c| m.max(c.abs()))
                        .max(f64::MIN_POSITIVE);
                    (0..n).all(|k| {
                        let u = p.coefficients.get(k).copied().unwrap_or(0.0);
                        let v = q.coefficients.get(k).copied().unwrap_or(0.0);
                        (u - v).abs() <= 1e-14 * scale
                    })
                }
                _ => false,
            })
    }

    /// T: the shorter piece's length in t; L: the diagonal of both pieces' sampled extent (or
    /// 1 for a curve that stays at one point).
    fn scales(&self, i: usize) -> (f64, f64) {
        let mut time = f64::INFINITY;
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        let both = self.pieces.get(i..(i + 2).min(self.pieces.len()));
        for p in opaque(both.unwrap_or_default()) {
            let (a, b) = (p.from.value, p.to.value);
            time = time.min(b - a);
            for s in 0..=opaque(32) {
                let t = a + (b - a) * f64::from(s) / 32.0;
                let mut point = [0.0; 3];
                for (o, c) in point.iter_mut().zip(&p.coords) {
                    *o = c.value(t, &self.values);
                }
                if point.iter().all(|v| v.is_finite()) {
                    for ((l, h), v) in lo.iter_mut().zip(hi.iter_mut()).zip(point) {
                        *l = l.min(v);
                        *h = h.max(v);
                    }
                }
            }
        }
        let space = dist(&lo, &hi);
        let space = if space.is_finite() && space > 0.0 {
            space
        } else {
            1.0
        };
        (time, space)
    }

    /// Whether the enclosures of the order-k derivative from both sides are disjoint in some
    /// coordinate (k ≤ 2: what the interval jets reach).
    fn disjoint_at(&self, i: usize, t: f64, k: usize) -> bool {
        let (Some(a), Some(b)) = (self.pieces.get(i), self.pieces.get(i + 1)) else {
            return false;
        };
        a.coords.iter().zip(&b.coords).any(|(x, y)| {
            let (Some(u), Some(v)) = (
                enclose(x, t, k, &self.values),
                enclose(y, t, k, &self.values),
            ) else {
                return false;
            };
            u.hi < v.lo || v.hi < u.lo
        })
    }
}

/// The enclosure of the k-th derivative of `c` at the point t (k ≤ 2).
#[inline(never)]
fn enclose(c: &Coordinate, t: f64, k: usize, values: &[f64]) -> Option<Interval> {
    let mut out = [Interval::point(0.0); 3];
    let flags = c.interval_jet(t, t, 2, values, &mut out);
    if !flags.continuous {
        return None;
    }
    out.get(k).copied()
}

fn dot(a: &V, b: &V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: &V) -> f64 {
    dot(a, a).sqrt()
}

fn dist(a: &V, b: &V) -> f64 {
    norm(&[a[0] - b[0], a[1] - b[1], a[2] - b[2]])
}

/// The largest k ≤ 3 with G^k from the f64 derivatives (−1 when the pieces do not meet).
fn geometric(l: &[V], r: &[V], space: f64) -> i32 {
    let (Some(l0), Some(r0)) = (l.first(), r.first()) else {
        return -1;
    };
    let d0 = dist(l0, r0);
    if !(d0.is_finite() && d0 <= EPS * space) {
        return -1;
    }
    // G¹: the directions of the first non-vanishing derivative on each side.
    let dir = |side: &[V]| -> Option<V> {
        let lead = side.iter().skip(1).find(|d| norm(d) > 0.0)?;
        let n = norm(lead);
        Some(lead.map(|x| x / n))
    };
    let (Some(tl), Some(tr)) = (dir(l), dir(r)) else {
        return 0;
    };
    let d1 = dist(&tl, &tr);
    if d1.is_nan() || d1 > EPS {
        return 0;
    }
    // G², G³ need a regular point on both sides.
    let regular = |side: &[V]| side.get(1).is_some_and(|v| norm(v) > 0.0);
    if !(regular(l) && regular(r)) {
        return 1;
    }
    let (kl, kr) = (curvature_vector(l), curvature_vector(r));
    let d2 = dist(&kl.0, &kr.0) * space;
    if d2.is_nan() || d2 > EPS {
        return 1;
    }
    let d3 = dist(&kl.1, &kr.1) * space * space;
    if d3.is_nan() || d3 > EPS {
        return 2;
    }
    3
}

/// `(κN, d(κN)/ds)` from v, a, j: with `s = v·v`, `q = a·v`, `κN = (a s − q v)/s²` and
/// `d(κN)/dt = [(j s + 2 q a − (j·v + a·a) v − q a) s² − (a s − q v)·2s·2q]/s⁴`, divided by
/// `|v|` for the arc length.
fn curvature_vector(side: &[V]) -> (V, V) {
    let get = |k: usize| side.get(k).copied().unwrap_or_default();
    let (v, a, j) = (&get(1), &get(2), &get(3));
    let s = dot(v, v);
    let q = dot(a, v);
    let dq = dot(j, v) + dot(a, a);
    let speed = s.sqrt();
    let (mut k, mut dk) = ([0.0; 3], [0.0; 3]);
    for c in 0..3 {
        let n = a[c] * s - q * v[c];
        let dn = j[c] * s + a[c] * 2.0 * q - dq * v[c] - q * a[c];
        k[c] = n / (s * s);
        dk[c] = (dn * s - n * 4.0 * q) / (s * s * s) / speed;
    }
    (k, dk)
}

/// An exact verdict.
struct Exact {
    c: f64,
    g: f64,
    order: Option<usize>,
}

/// The verdict in exact fractions when every coordinate of both pieces is a polynomial with
/// rational coefficients; `None` otherwise (or when a fraction overflows).
fn exact_verdict(left: &[Coordinate], right: &[Coordinate], t: Rational) -> Option<Exact> {
    let mut sides = [[[Rational::ZERO; 3]; N]; 2]; // per side, per order, per coordinate
    let mut same_poly = true;
    for (c, (x, y)) in left.iter().zip(right).enumerate() {
        let p = x.poly.as_ref()?.exact.as_ref()?;
        let q = y.poly.as_ref()?.exact.as_ref()?;
        same_poly &= trimmed(p) == trimmed(q);
        for (side, poly) in sides.iter_mut().zip([p, q]) {
            exact_derivatives(poly, t, side, c)?;
        }
    }
    if same_poly {
        return Some(Exact {
            c: f64::INFINITY,
            g: f64::INFINITY,
            order: None,
        });
    }
    let [l, r] = &sides;
    let (l, r) = (opaque(&l[..]), opaque(&r[..]));
    let order = l.iter().zip(r).position(|(a, b)| !same(a, b));
    let c = match order {
        Some(k) if k <= C_MAX => k as f64 - 1.0,
        _ => C_MAX as f64,
    };
    let g = c.max(f64::from(exact_geometric(l, r)?));
    Some(Exact { c, g, order })
}

fn trimmed(p: &[Rational]) -> &[Rational] {
    let n = p.iter().rposition(|c| !c.is_zero()).map_or(0, |i| i + 1);
    p.get(..n).unwrap_or(p)
}

/// `p^(k)(t)` for k = 0..N into coordinate `c` of `out[k]`, exactly.
fn exact_derivatives(p: &[Rational], t: Rational, out: &mut [Q; N], c: usize) -> Option<()> {
    let mut coefficients = p.to_vec();
    for d in out.iter_mut() {
        let mut acc = Rational::ZERO;
        for a in coefficients.iter().rev() {
            acc = acc.checked_mul(t)?.checked_add(*a)?;
        }
        *d.get_mut(c)? = acc;
        // The derivative's coefficients: j·a_j moved down one place.
        for j in 1..coefficients.len() {
            let a = coefficients
                .get(j)?
                .checked_mul(Rational::integer(j as i128))?;
            *coefficients.get_mut(j - 1)? = a;
        }
        coefficients.pop();
    }
    Some(())
}

fn rdot(a: &Q, b: &Q) -> Option<Rational> {
    a.iter().zip(b).try_fold(Rational::ZERO, |acc, (x, y)| {
        acc.checked_add(x.checked_mul(*y)?)
    })
}

/// `a = b` (out of line: one copy of the i128 comparisons).
#[inline(never)]
fn same(a: &Q, b: &Q) -> bool {
    a == b
}

fn is_zero(v: &Q) -> bool {
    v.iter().all(|x| x.is_zero())
}

/// `u = λ w` with λ > 0 (same direction), exactly; λ when so.
fn positive_multiple(u: &Q, w: &Q) -> Option<Option<Rational>> {
    // λ from the first non-zero coordinate of w.
    let Some(k) = w.iter().position(|x| !x.is_zero()) else {
        return Some(None);
    };
    let lambda = u.get(k)?.checked_div(*w.get(k)?)?;
    if lambda <= Rational::ZERO {
        return Some(None);
    }
    for (a, b) in u.iter().zip(w) {
        if *a != b.checked_mul(lambda)? {
            return Some(None);
        }
    }
    Some(Some(lambda))
}

/// G^k in exact arithmetic (0 ≤ k ≤ 3; −1 when the pieces do not meet); `None` on overflow.
fn exact_geometric(l: &[Q], r: &[Q]) -> Option<i32> {
    if !same(l.first()?, r.first()?) {
        return Some(-1);
    }
    let lead = |side: &[Q]| side.iter().skip(1).position(|d| !is_zero(d));
    let (Some(a), Some(b)) = (lead(l), lead(r)) else {
        return Some(0);
    };
    // Directions of the first non-vanishing derivatives.
    if positive_multiple(r.get(b + 1)?, l.get(a + 1)?)?.is_none() {
        return Some(0);
    }
    if a != 0 || b != 0 {
        return Some(1); // a singular point: G² and G³ are not compared
    }
    // Regular on both sides: v_r = λ v_l, λ > 0.
    let lambda = positive_multiple(r.get(1)?, l.get(1)?)??;
    let (kl, dkl) = exact_curvature(l)?;
    let (kr, dkr) = exact_curvature(r)?;
    if !same(&kl, &kr) {
        return Some(1);
    }
    // d(κN)/ds = (d(κN)/dt)/|v|: with |v_r| = λ|v_l|, compare λ·d(κN)/dt|_l with d(κN)/dt|_r.
    for (x, y) in dkl.iter().zip(&dkr) {
        if x.checked_mul(lambda)? != *y {
            return Some(2);
        }
    }
    Some(3)
}

/// `(κN, d(κN)/dt)` exactly (no square root: see [`curvature_vector`]).
fn exact_curvature(side: &[Q]) -> Option<(Q, Q)> {
    let (v, a, j) = (side.get(1)?, side.get(2)?, side.get(3)?);
    let s = rdot(v, v)?;
    let q = rdot(a, v)?;
    let dq = rdot(j, v)?.checked_add(rdot(a, a)?)?;
    let s2 = s.checked_mul(s)?;
    let s3 = s2.checked_mul(s)?;
    let (mut k, mut dk) = ([Rational::ZERO; 3], [Rational::ZERO; 3]);
    let two = Rational::integer(2);
    let four = Rational::integer(4);
    for c in 0..3 {
        let (vc, ac, jc) = (v[c], a[c], j[c]);
        let n = ac.checked_mul(s)?.checked_sub(q.checked_mul(vc)?)?;
        let dn = jc
            .checked_mul(s)?
            .checked_add(ac.checked_mul(two)?.checked_mul(q)?)?
            .checked_sub(dq.checked_mul(vc)?)?
            .checked_sub(q.checked_mul(ac)?)?;
        k[c] = n.checked_div(s2)?;
        // d(n/s²)/dt = (dn·s − n·2s')/s³ with s' = 2q.
        let num = dn
            .checked_mul(s)?
            .checked_sub(n.checked_mul(four)?.checked_mul(q)?)?;
        dk[c] = num.checked_div(s3)?;
    }
    Some((k, dk))
}

impl Joint {
    fn none(t: f64) -> Self {
        Joint {
            t,
            c: -1.0,
            g: -1.0,
            exact: false,
            order: None,
            left: None,
            right: None,
            disjoint: false,
        }
    }
}
