//! One coordinate of a piece (or a bound): its tree, its compiled tape, its polynomial form
//! when it has one, and a scratch space so evaluation allocates nothing.

use crate::expr::tape::{Scratch, Tape};
use crate::expr::{Expr, Polynomial, Rational};
use std::cell::RefCell;

pub(crate) use crate::expr::certify::{Defined, IntervalFlags};
pub(crate) use crate::expr::interval::Interval;

/// A parsed coordinate function `x(t)`.
#[derive(Clone, Debug)]
pub(crate) struct Coordinate {
    /// The tree (for TeX, the derivative and the polynomial form).
    pub(crate) tree: Expr,
    tape: Tape,
    /// Its power-basis form in t under the current parameters, when it is a polynomial.
    pub(crate) poly: Option<Polynomial>,
    uses_parameters: bool,
    scratch: RefCell<Scratch>,
}

/// What an interval evaluation proved, for the plot and the joints.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Proven {
    /// Undefined on the whole interval.
    pub(crate) nowhere: bool,
    /// Defined and continuous on the whole interval.
    pub(crate) continuous: bool,
    /// C² on the whole interval.
    pub(crate) smooth: bool,
}

impl From<IntervalFlags> for Proven {
    fn from(f: IntervalFlags) -> Self {
        Proven {
            nowhere: f.defined == Defined::Nowhere,
            continuous: f.continuous,
            smooth: f.smooth,
        }
    }
}

fn reads_parameters(e: &Expr) -> bool {
    use crate::expr::Node;
    match &e.node {
        Node::Param(_) => true,
        Node::Number { .. } | Node::T | Node::Constant(_) => false,
        Node::Neg(a) | Node::Call(_, a) => reads_parameters(a),
        Node::Binary(_, a, b) => reads_parameters(a) || reads_parameters(b),
    }
}

impl Coordinate {
    /// Compiles `tree`; `values` are the parameters' current values (for the polynomial form).
    #[inline(never)]
    pub(crate) fn new(tree: Expr, values: &[f64]) -> Self {
        let tape = Tape::compile(&tree);
        let poly = Polynomial::from_expr(&tree, values);
        Coordinate {
            uses_parameters: reads_parameters(&tree),
            tree,
            tape,
            poly,
            scratch: RefCell::new(Scratch::new()),
        }
    }

    /// The polynomial form again after a parameter changed (only when the tree reads one).
    pub(crate) fn parameters_changed(&mut self, values: &[f64]) {
        if self.uses_parameters {
            self.poly = Polynomial::from_expr(&self.tree, values);
        }
    }

    /// The value of a t-free expression (a bound) and its exact value when it is rational.
    pub(crate) fn constant(&self, values: &[f64]) -> (f64, Option<Rational>) {
        let exact = self.poly.as_ref().and_then(|p| match p.exact.as_deref() {
            Some([]) => Some(Rational::ZERO),
            Some([c]) => Some(*c),
            _ => None,
        });
        let value = exact.map_or_else(|| self.value(0.0, values), Rational::to_f64);
        (value, exact)
    }

    /// `f` with the coordinate's scratch space (a fresh one if it is in use: one call site
    /// of each evaluator, not two).
    #[inline(always)]
    fn with_scratch<R>(&self, f: impl FnOnce(&mut Scratch) -> R) -> R {
        let mut fresh = None;
        let mut held = self.scratch.try_borrow_mut().ok();
        let s = match held.as_deref_mut() {
            Some(s) => s,
            None => fresh.insert(Scratch::new()),
        };
        f(s)
    }

    /// x(t).
    pub(crate) fn value(&self, t: f64, values: &[f64]) -> f64 {
        // Two direct calls here (the hot path), not through `with_scratch`.
        match self.scratch.try_borrow_mut() {
            Ok(mut s) => self.tape.eval(t, values, &mut s),
            Err(_) => self.tape.eval(t, values, &mut Scratch::new()),
        }
    }

    /// x(t), x′(t), …, x^(n)(t) into `out` (`n + 1` numbers), by automatic differentiation.
    pub(crate) fn jet(&self, t: f64, n: usize, values: &[f64], out: &mut [f64]) {
        self.with_scratch(|s| self.tape.eval_jet(t, n, values, s, out))
    }

    /// Enclosures of `x, x′, x″` over `[lo, hi]` (`order ≤ 2`).
    pub(crate) fn interval_jet(
        &self,
        lo: f64,
        hi: f64,
        order: usize,
        values: &[f64],
        out: &mut [Interval],
    ) -> Proven {
        self.with_scratch(|s| self.tape.eval_interval_jet(lo, hi, order, values, s, out))
            .into()
    }
}
