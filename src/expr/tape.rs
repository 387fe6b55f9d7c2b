//! The compiled form of an expression: a flat list of instructions over registers, evaluated
//! in one loop without recursion or allocation.
//!
//! Instruction i writes register i and reads only earlier registers (single assignment).
//! Subtrees without `t` or a parameter are folded to one constant at compile time (with the
//! same `f64` functions the evaluator uses); parameters are read from a `&[f64]` at every
//! evaluation, so moving a slider never recompiles. Powers: an exponent that folds to an
//! integer compiles to [`Op::Powi`] (repeated products: exact sign for a negative base,
//! 0⁰ = 1); an exponent without `t` to [`Op::PowConst`] (integer at run time → the same as
//! `Powi`, otherwise IEEE `pow`: a negative base gives NaN); an exponent with `t` to
//! [`Op::PowVar`] = e^(b ln a), defined for a ≥ 0.

use super::ast::{BinOp, Expr, Func, Node};
use super::certify::IntervalFlags;
use super::interval::Interval;
use super::math;

/// One instruction; the `u32`s are earlier registers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    /// A folded constant.
    Const(f64),
    /// The curve parameter t.
    T,
    /// Parameter number i (NaN when the parameter slice is shorter).
    Param(u32),
    /// −a.
    Neg(u32),
    /// a + b.
    Add(u32, u32),
    /// a − b.
    Sub(u32, u32),
    /// a · b.
    Mul(u32, u32),
    /// a / b.
    Div(u32, u32),
    /// aⁿ for a compile-time integer n ([`math::powi`]).
    Powi(u32, i32),
    /// aᵇ with b independent of t ([`math::pow_const`]).
    PowConst(u32, u32),
    /// aᵇ with b depending on t ([`math::pow_var`]: e^(b ln a)).
    PowVar(u32, u32),
    /// f(a).
    Call(Func, u32),
}

/// A compiled expression (see the module documentation). Cheap to evaluate many times.
#[derive(Clone, Debug, PartialEq)]
pub struct Tape {
    /// The instructions; the value is the last register's.
    pub(crate) ops: Vec<Op>,
    /// Whether register i depends on t (otherwise it is a function of the parameters alone).
    pub(crate) varies: Vec<bool>,
}

/// Reusable working memory for [`Tape`] evaluations: it grows to the largest tape it has
/// served and is then reused, so repeated evaluations do not allocate.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    pub(crate) f: Vec<f64>,
    pub(crate) jet: Vec<f64>,
    pub(crate) interval: Vec<Interval>,
    pub(crate) flags: Vec<IntervalFlags>,
}

impl Scratch {
    /// Empty working memory.
    pub fn new() -> Self {
        Scratch::default()
    }
}

/// While compiling: a value known at compile time, or a register.
#[derive(Clone, Copy)]
enum Operand {
    Const(f64),
    Reg(u32),
}

enum Work<'a> {
    Visit(&'a Expr),
    Build(&'a Expr),
}

impl Tape {
    /// Compiles a tree (iteratively: no recursion, whatever its depth). Never fails: a
    /// malformed request (none can come from the parser) compiles to NaN.
    pub fn compile(expr: &Expr) -> Tape {
        let mut tape = Tape {
            ops: Vec::new(),
            varies: Vec::new(),
        };
        let mut work = vec![Work::Visit(expr)];
        let mut values: Vec<Operand> = Vec::new();
        let mut t_reg = None; // one register for t, however often it is written
        while let Some(item) = work.pop() {
            match item {
                Work::Visit(e) => match &e.node {
                    Node::Number { value, .. } => values.push(Operand::Const(*value)),
                    Node::Constant(c) => values.push(Operand::Const(c.value())),
                    Node::T => {
                        let r = *t_reg.get_or_insert_with(|| tape.emit(Op::T, true));
                        values.push(r)
                    }
                    Node::Param(i) => {
                        let i = u32::try_from(*i).unwrap_or(u32::MAX);
                        values.push(tape.emit(Op::Param(i), false))
                    }
                    Node::Neg(a) | Node::Call(_, a) => {
                        work.push(Work::Build(e));
                        work.push(Work::Visit(a));
                    }
                    Node::Binary(_, a, b) => {
                        work.push(Work::Build(e));
                        work.push(Work::Visit(b));
                        work.push(Work::Visit(a));
                    }
                },
                Work::Build(e) => {
                    let nan = Operand::Const(f64::NAN);
                    let result = match &e.node {
                        Node::Neg(_) => {
                            let a = values.pop().unwrap_or(nan);
                            tape.unary(a, Op::Neg, |x| -x)
                        }
                        Node::Call(f, _) => {
                            let (f, a) = (*f, values.pop().unwrap_or(nan));
                            tape.unary(a, |r| Op::Call(f, r), |x| math::apply(f, x))
                        }
                        Node::Binary(op, _, _) => {
                            let b = values.pop().unwrap_or(nan);
                            let a = values.pop().unwrap_or(nan);
                            tape.binary(*op, a, b)
                        }
                        _ => nan,
                    };
                    values.push(result);
                }
            }
        }
        let root = values.pop().unwrap_or(Operand::Const(f64::NAN));
        if let Operand::Const(v) = root {
            tape.emit(Op::Const(v), false);
        }
        tape
    }

    /// The number of instructions (registers).
    pub fn len(&self) -> usize {
        self.ops.len()
    }

    /// Whether there are no instructions (never true for a compiled tape).
    pub fn is_empty(&self) -> bool {
        self.ops.is_empty()
    }

    /// Whether the value depends on t (false for a constant or a function of the parameters).
    pub fn varies(&self) -> bool {
        self.varies.last().copied().unwrap_or(false)
    }

    /// The instructions, for inspection.
    pub fn ops(&self) -> &[Op] {
        &self.ops
    }

    fn emit(&mut self, op: Op, varies: bool) -> Operand {
        let reg = u32::try_from(self.ops.len()).unwrap_or(u32::MAX);
        self.ops.push(op);
        self.varies.push(varies);
        Operand::Reg(reg)
    }

    fn reg(&mut self, a: Operand) -> u32 {
        match a {
            Operand::Reg(r) => r,
            Operand::Const(v) => match self.emit(Op::Const(v), false) {
                Operand::Reg(r) => r,
                Operand::Const(_) => u32::MAX,
            },
        }
    }

    fn varies_at(&self, r: u32) -> bool {
        self.varies.get(r as usize).copied().unwrap_or(false)
    }

    fn unary(&mut self, a: Operand, op: impl Fn(u32) -> Op, fold: impl Fn(f64) -> f64) -> Operand {
        match a {
            Operand::Const(x) => Operand::Const(fold(x)),
            Operand::Reg(r) => {
                let v = self.varies_at(r);
                self.emit(op(r), v)
            }
        }
    }

    fn binary(&mut self, op: BinOp, a: Operand, b: Operand) -> Operand {
        if let (Operand::Const(x), Operand::Const(y)) = (a, b) {
            return Operand::Const(match op {
                BinOp::Add => x + y,
                BinOp::Sub => x - y,
                BinOp::Mul => x * y,
                BinOp::Div => x / y,
                BinOp::Pow => math::pow_const(x, y),
            });
        }
        if let (BinOp::Pow, Operand::Const(y)) = (op, b) {
            if let Some(n) = math::integer_exponent(y) {
                let ra = self.reg(a);
                let v = self.varies_at(ra);
                return self.emit(Op::Powi(ra, n), v);
            }
        }
        let (ra, rb) = (self.reg(a), self.reg(b));
        let v = self.varies_at(ra) || self.varies_at(rb);
        let instruction = match op {
            BinOp::Add => Op::Add(ra, rb),
            BinOp::Sub => Op::Sub(ra, rb),
            BinOp::Mul => Op::Mul(ra, rb),
            BinOp::Div => Op::Div(ra, rb),
            BinOp::Pow if self.varies_at(rb) => Op::PowVar(ra, rb),
            BinOp::Pow => Op::PowConst(ra, rb),
        };
        self.emit(instruction, v)
    }

    /// The value at `t` with parameter values `params` (parameter i is `params[i]`, NaN if
    /// missing). Undefined points give NaN or ±∞ as IEEE 754 does.
    pub fn eval(&self, t: f64, params: &[f64], scratch: &mut Scratch) -> f64 {
        let regs = &mut scratch.f;
        regs.resize(self.ops.len(), 0.0);
        for (i, op) in self.ops.iter().enumerate() {
            regs[i] = step(*op, t, params, regs);
        }
        regs.last().copied().unwrap_or(f64::NAN)
    }

    /// `out[i]` = the value at `ts[i]`, for i below the shorter length.
    pub fn eval_many(&self, ts: &[f64], params: &[f64], scratch: &mut Scratch, out: &mut [f64]) {
        for (o, &t) in out.iter_mut().zip(ts) {
            *o = self.eval(t, params, scratch);
        }
    }

    /// Fills `regs` with the value of every register that does not depend on t (the others
    /// are left as they were): the jets and intervals read these as exact points.
    pub(crate) fn eval_fixed(&self, params: &[f64], regs: &mut Vec<f64>) {
        regs.resize(self.ops.len(), 0.0);
        for (i, op) in self.ops.iter().enumerate() {
            if !self.varies[i] {
                regs[i] = step(*op, f64::NAN, params, regs);
            }
        }
    }
}

/// One instruction on f64 registers (`regs` holds every earlier register).
fn step(op: Op, t: f64, params: &[f64], regs: &[f64]) -> f64 {
    let r = |i: u32| regs.get(i as usize).copied().unwrap_or(f64::NAN);
    match op {
        Op::Const(v) => v,
        Op::T => t,
        Op::Param(i) => params.get(i as usize).copied().unwrap_or(f64::NAN),
        Op::Neg(a) => -r(a),
        Op::Add(a, b) => r(a) + r(b),
        Op::Sub(a, b) => r(a) - r(b),
        Op::Mul(a, b) => r(a) * r(b),
        Op::Div(a, b) => r(a) / r(b),
        Op::Powi(a, n) => math::powi(r(a), n),
        Op::PowConst(a, b) => math::pow_const(r(a), r(b)),
        Op::PowVar(a, b) => math::pow_var(r(a), r(b)),
        Op::Call(f, a) => math::apply(f, r(a)),
    }
}

/// Test-only tree builders (spans do not matter to the evaluators): the family's, with `n`
/// a number without an exact value.
#[cfg(test)]
pub(crate) mod build {
    pub use super::super::diff::build::{
        add, call, div, inexact as n, mul, ng as neg, notes_polynomial, p, pi, pow, sub, t,
    };
}

#[cfg(test)]
mod tests {
    use super::build::*;
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    fn value(e: &Expr, t: f64, params: &[f64]) -> f64 {
        Tape::compile(e).eval(t, params, &mut Scratch::new())
    }

    #[test]
    fn constant_subtrees_fold_and_parameters_do_not() {
        // 2·π·3 + sin(0) folds to one constant.
        let e = add(mul(mul(n(2.0), pi()), n(3.0)), call(Func::Sin, n(0.0)));
        let tape = Tape::compile(&e);
        assert_eq!(tape.ops(), &[Op::Const(6.0 * std::f64::consts::PI)]);
        assert!(!tape.varies());
        // (1 + 1)·t: one constant, t, one product.
        let tape = Tape::compile(&mul(add(n(1.0), n(1.0)), t()));
        assert_eq!(tape.len(), 3);
        assert!(tape.varies());
        // a·t reads a at evaluation: changing it needs no recompilation.
        let tape = Tape::compile(&mul(p(0), t()));
        let mut s = Scratch::new();
        assert_eq!(tape.eval(3.0, &[2.0], &mut s), 6.0);
        assert_eq!(tape.eval(3.0, &[-1.0], &mut s), -3.0);
        assert!(tape.eval(3.0, &[], &mut s).is_nan());
    }

    #[test]
    fn powers_compile_by_the_kind_of_exponent() {
        let tape = Tape::compile(&pow(t(), n(3.0)));
        assert_eq!(tape.ops(), &[Op::T, Op::Powi(0, 3)]);
        assert_eq!(value(&pow(t(), n(3.0)), -2.0, &[]), -8.0);
        assert_eq!(value(&pow(t(), neg(n(2.0))), -2.0, &[]), 0.25);
        assert_eq!(value(&pow(t(), n(0.0)), 0.0, &[]), 1.0);
        assert_eq!(value(&pow(n(0.0), n(0.0)), 0.0, &[]), 1.0);
        // A non-integer exponent: IEEE pow, a negative base is NaN.
        assert!(matches!(
            Tape::compile(&pow(t(), n(0.5))).ops()[2],
            Op::PowConst(0, 1)
        ));
        assert_eq!(value(&pow(t(), n(0.5)), 9.0, &[]), 3.0);
        assert!(value(&pow(t(), n(0.5)), -9.0, &[]).is_nan());
        // A parameter exponent that is an integer at run time keeps the sign.
        assert_eq!(value(&pow(t(), p(0)), -2.0, &[3.0]), -8.0);
        assert!(value(&pow(t(), p(0)), -2.0, &[2.5]).is_nan());
        // t^t: a variable exponent, NaN for a negative base.
        assert!(matches!(
            Tape::compile(&pow(t(), t())).ops()[1],
            Op::PowVar(0, 0)
        ));
        assert_eq!(value(&pow(t(), t()), 2.0, &[]), 4.0);
        assert!(value(&pow(t(), t()), -2.0, &[]).is_nan());
        assert_eq!(value(&pow(t(), t()), 0.0, &[]), 1.0);
        // Right-associative exponent tower 2^3^2 folds to 512.
        assert_eq!(value(&pow(n(2.0), pow(n(3.0), n(2.0))), 0.0, &[]), 512.0);
    }

    #[test]
    fn values_match_closed_forms() {
        let poly = notes_polynomial();
        for x in [-1.5f64, -0.3, 0.0, 0.7, 2.0] {
            let expected = 6.5 * x.powi(5) - 7.2 * x.powi(3) + 3.0 * x * x - 2.1 * x - 5.0;
            let got = value(&poly, x, &[]);
            assert!(
                (got - expected).abs() <= 1e-13 * (1.0 + expected.abs()),
                "{x}: {got}"
            );
        }
        assert_eq!(value(&poly, 1.0, &[]), 6.5 - 7.2 + 3.0 - 2.1 - 5.0);
        let e = div(call(Func::Ln, add(n(2.0), call(Func::Cos, t()))), n(2.0));
        assert!((value(&e, 1.0, &[]) - (2.0 + 1f64.cos()).ln() / 2.0).abs() < 1e-15);
        assert_eq!(value(&div(n(1.0), t()), 0.0, &[]), f64::INFINITY);
        assert!(value(&call(Func::Sqrt, t()), -1.0, &[]).is_nan());
        assert_eq!(value(&neg(pow(n(2.0), n(2.0))), 0.0, &[]), -4.0);
    }

    #[test]
    fn deep_trees_compile_without_recursion() {
        let mut e = t();
        for _ in 0..20_000 {
            e = add(e, n(1.0));
        }
        let tape = Tape::compile(&e);
        assert_eq!(value(&e, 0.5, &[]), 20_000.5);
        assert_eq!(tape.len(), 40_001);
        std::mem::forget(e); // dropping a 20 000-deep Box chain would recurse
    }

    #[test]
    fn many_values_at_once() {
        let tape = Tape::compile(&mul(t(), t()));
        let mut out = [0.0; 3];
        tape.eval_many(&[1.0, 2.0, 3.0], &[], &mut Scratch::new(), &mut out);
        assert_eq!(out, [1.0, 4.0, 9.0]);
    }

    /// Native micro-benchmark (`cargo test --release --lib expr::tape -- --ignored
    /// --nocapture`): 1M evaluations of the circle (x and y) and of the notes' polynomial.
    #[cfg(not(target_arch = "wasm32"))]
    #[test]
    #[ignore]
    fn bench_one_million_evaluations() {
        let mut s = Scratch::new();
        let cases = [
            (
                "circle x = cos t, y = sin t",
                vec![call(Func::Cos, t()), call(Func::Sin, t())],
            ),
            ("notes' polynomial", vec![notes_polynomial()]),
        ];
        for (name, exprs) in cases {
            let tapes: Vec<Tape> = exprs.iter().map(Tape::compile).collect();
            let start = std::time::Instant::now();
            let mut sum = 0.0;
            for i in 0..1_000_000 {
                let x = i as f64 * 1e-6;
                for tape in &tapes {
                    sum += tape.eval(x, &[], &mut s);
                }
            }
            let time = start.elapsed();
            let mut jet = [0.0; 3];
            let start = std::time::Instant::now();
            for i in 0..1_000_000 {
                for tape in &tapes {
                    tape.eval_jet(i as f64 * 1e-6, 2, &[], &mut s, &mut jet);
                    sum += jet[2];
                }
            }
            let jet_time = start.elapsed();
            println!("{name}: 1M points {time:?} (values), {jet_time:?} (order-2 jets) [{sum}]");
        }
    }
}
