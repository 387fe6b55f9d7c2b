//! What is proven about an expression over an interval of t: defined everywhere, partly or
//! nowhere, continuous, C² ([`IntervalFlags`]), and the interval evaluations of a [`Tape`]
//! that compute them with enclosures of the value and its derivatives.
//!
//! Each instruction adds its own conditions, judged on the enclosures of its operands: a
//! division by an interval holding 0 (a pole), tan across π/2 + kπ, floor/ceil/sign across a
//! jump, ln/log/sqrt/asin/acos/a real power outside or at the edge of their domain, abs at 0
//! (a kink: continuous, not C²). They combine by [`IntervalFlags::and`], so a flag is a proof
//! (sufficient conditions) and `Partly` is the honest "not proven either way".

use super::ast::Func;
use super::interval::Interval;
use super::math;
use super::tape::{Op, Scratch, Tape};

/// Whether an expression is defined (finite, real) at the points of an interval.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Defined {
    /// Proven defined at every point.
    Everywhere,
    /// Neither proven defined everywhere nor proven undefined everywhere (an undefined point
    /// such as the pole of 1/t may lie inside).
    Partly,
    /// Proven undefined at every point (√t on [−2, −1]).
    Nowhere,
}

/// What is proven about an expression over an interval of t.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IntervalFlags {
    /// Where it is defined.
    pub defined: Defined,
    /// Proven defined, finite and continuous on the whole interval.
    pub continuous: bool,
    /// Proven C² (twice continuously differentiable) on the whole interval, with finite
    /// enclosures of the derivatives computed.
    pub smooth: bool,
}

impl IntervalFlags {
    /// Defined, continuous and smooth.
    pub const GOOD: IntervalFlags = IntervalFlags {
        defined: Defined::Everywhere,
        continuous: true,
        smooth: true,
    };

    fn new(defined: Defined, continuous: bool, smooth: bool) -> Self {
        IntervalFlags {
            defined,
            continuous: continuous && defined == Defined::Everywhere,
            smooth: smooth && continuous && defined == Defined::Everywhere,
        }
    }

    /// Both hold: Nowhere if either is, Everywhere if both are; continuous and smooth if
    /// both are.
    pub fn and(self, other: IntervalFlags) -> IntervalFlags {
        let defined = match (self.defined, other.defined) {
            (Defined::Nowhere, _) | (_, Defined::Nowhere) => Defined::Nowhere,
            (Defined::Everywhere, Defined::Everywhere) => Defined::Everywhere,
            _ => Defined::Partly,
        };
        IntervalFlags::new(
            defined,
            self.continuous && other.continuous,
            self.smooth && other.smooth,
        )
    }
}

/// The result of [`Tape::eval_interval`](super::Tape::eval_interval).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IntervalResult {
    /// Encloses every defined value (empty when `defined` is Nowhere).
    pub value: Interval,
    /// Where the expression is defined.
    pub defined: Defined,
    /// Proven defined, finite and continuous on the whole interval.
    pub continuous: bool,
}

/// What a step with its own domain adds: defined where x is in [lo, hi] (`open` excludes the
/// ends), continuous there, smooth (C²) where `smooth_inside`.
fn domain(x: Interval, lo: f64, hi: f64, open: bool, smooth_inside: bool) -> IntervalFlags {
    let inside = |v: f64| {
        if open {
            lo < v && v < hi
        } else {
            lo <= v && v <= hi
        }
    };
    let outside_all = if open {
        x.hi <= lo || x.lo >= hi
    } else {
        x.hi < lo || x.lo > hi
    };
    if x.is_empty() || outside_all {
        IntervalFlags::new(Defined::Nowhere, false, false)
    } else if inside(x.lo) && inside(x.hi) {
        IntervalFlags::new(Defined::Everywhere, true, smooth_inside)
    } else {
        IntervalFlags::new(Defined::Partly, false, false)
    }
}

/// A division-like step by x: a pole where x = 0.
fn pole_at_zero(x: Interval) -> IntervalFlags {
    if x.lo == 0.0 && x.hi == 0.0 {
        IntervalFlags::new(Defined::Nowhere, false, false)
    } else if x.contains(0.0) {
        IntervalFlags::new(Defined::Partly, false, false)
    } else {
        IntervalFlags::GOOD
    }
}

/// What f adds over an argument enclosed by x: its domain, its poles and jumps, its kinks.
pub fn func_flags(f: Func, x: Interval) -> IntervalFlags {
    let inf = f64::INFINITY;
    match f {
        Func::Sin | Func::Cos | Func::Atan | Func::Sinh | Func::Cosh | Func::Tanh | Func::Exp => {
            IntervalFlags::GOOD
        }
        Func::Tan if x.holds_tan_pole() => IntervalFlags::new(Defined::Partly, false, false),
        Func::Tan => IntervalFlags::GOOD,
        Func::Asin | Func::Acos => {
            let closed = domain(x, -1.0, 1.0, false, false);
            let open = domain(x, -1.0, 1.0, true, true);
            IntervalFlags {
                smooth: open.smooth,
                ..closed
            }
        }
        Func::Ln | Func::Log => domain(x, 0.0, inf, true, true),
        Func::Sqrt => IntervalFlags {
            smooth: x.lo > 0.0,
            ..domain(x, 0.0, inf, false, true)
        },
        Func::Abs => IntervalFlags::new(Defined::Everywhere, true, !x.contains(0.0)),
        Func::Floor | Func::Ceil | Func::Sign => {
            let still = math::apply(f, x.lo) == math::apply(f, x.hi);
            IntervalFlags::new(Defined::Everywhere, still, still)
        }
    }
}

/// What aⁿ adds (n an integer): a pole at a = 0 when n < 0.
pub fn powi_flags(a: Interval, n: i32) -> IntervalFlags {
    if n < 0 {
        pole_at_zero(a)
    } else {
        IntervalFlags::GOOD
    }
}

/// What aʳ adds for a real r that is not an integer: the domain a ≥ 0 (a > 0 for r < 0), C²
/// where a > 0.
pub fn powf_flags(a: Interval, r: f64) -> IntervalFlags {
    let f = domain(a, 0.0, f64::INFINITY, r < 0.0, true);
    IntervalFlags {
        smooth: f.smooth && a.lo > 0.0,
        ..f
    }
}

/// What aᵇ = e^(b ln a) adds (b varying with t): the domain a > 0.
pub fn pow_var_flags(a: Interval) -> IntervalFlags {
    domain(a, 0.0, f64::INFINITY, true, true)
}

/// What a / b adds: a pole where b = 0.
pub fn div_flags(b: Interval) -> IntervalFlags {
    pole_at_zero(b)
}

/// What instruction `op` adds, judged on the value enclosures `v` of the earlier registers
/// (`fixed`: the f64 values of the registers that do not depend on t).
fn op_flags(op: Op, v: impl Fn(u32) -> Interval, fixed: &[f64]) -> IntervalFlags {
    match op {
        Op::Div(_, b) => div_flags(v(b)),
        Op::Powi(a, n) => powi_flags(v(a), n),
        Op::PowConst(a, b) => {
            let r = fixed.get(b as usize).copied().unwrap_or(f64::NAN);
            match math::integer_exponent(r) {
                Some(n) => powi_flags(v(a), n),
                None if r.is_nan() => IntervalFlags::new(Defined::Nowhere, false, false),
                None => powf_flags(v(a), r),
            }
        }
        Op::PowVar(a, _) => pow_var_flags(v(a)),
        Op::Call(f, a) => func_flags(f, v(a)),
        _ => IntervalFlags::GOOD,
    }
}

/// The flags of every register after [`run`](super::jet::run) has filled `buf` (stride m).
fn flags_pass(
    tape: &Tape,
    m: usize,
    fixed: &[f64],
    buf: &[Interval],
    flags: &mut Vec<IntervalFlags>,
) {
    flags.clear();
    for (i, op) in tape.ops.iter().enumerate() {
        let f = if !tape.varies[i] {
            let x = fixed.get(i).copied().unwrap_or(f64::NAN);
            if x.is_finite() {
                IntervalFlags::GOOD
            } else {
                IntervalFlags::new(Defined::Nowhere, false, false)
            }
        } else {
            let get = |r: u32| {
                flags
                    .get(r as usize)
                    .copied()
                    .unwrap_or(IntervalFlags::GOOD)
            };
            let inputs = match *op {
                Op::Neg(a) | Op::Powi(a, _) | Op::Call(_, a) => get(a),
                Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) | Op::Div(a, b) => get(a).and(get(b)),
                Op::PowConst(a, b) | Op::PowVar(a, b) => get(a).and(get(b)),
                Op::Const(_) | Op::T | Op::Param(_) => IntervalFlags::GOOD,
            };
            let value = |r: u32| buf.get(r as usize * m).copied().unwrap_or(Interval::ENTIRE);
            inputs.and(op_flags(*op, value, fixed))
        };
        flags.push(f);
    }
}

impl Tape {
    /// An enclosure of the values for t in [lo, hi] (parameters as points), with whether the
    /// expression is proven defined and continuous there (see the module documentation). The
    /// value is empty when `defined` is Nowhere; `continuous` also requires a finite
    /// enclosure. lo > hi or NaN ends give an empty, Nowhere result.
    pub fn eval_interval(
        &self,
        lo: f64,
        hi: f64,
        params: &[f64],
        scratch: &mut Scratch,
    ) -> IntervalResult {
        let mut value = [Interval::EMPTY];
        let f = self.eval_interval_jet(lo, hi, 0, params, scratch, &mut value);
        IntervalResult {
            value: value[0],
            defined: f.defined,
            continuous: f.continuous,
        }
    }

    /// Enclosures of the derivatives dᵏx/dtᵏ over t ∈ [lo, hi] for k = 0 ..= `order`
    /// (capped at [`MAX_JET_ORDER`](super::MAX_JET_ORDER) and `out.len() − 1`; the plotter
    /// uses order 2: the chord error of a step Δt is at most (Δt²/8)·max|x″|), by the same
    /// recurrences as [`Tape::eval_jet`] in interval arithmetic, with the flags: `defined`,
    /// `continuous` (finite value enclosure), `smooth` = proven C² with finite enclosures of
    /// every derivative computed.
    pub fn eval_interval_jet(
        &self,
        lo: f64,
        hi: f64,
        order: usize,
        params: &[f64],
        scratch: &mut Scratch,
        out: &mut [Interval],
    ) -> IntervalFlags {
        let nowhere = IntervalFlags::new(Defined::Nowhere, false, false);
        let t = Interval::new(lo, hi);
        if out.is_empty() || self.ops.is_empty() || t.is_empty() {
            out.fill(Interval::EMPTY);
            return nowhere;
        }
        let m = order.min(super::MAX_JET_ORDER).min(out.len() - 1) + 1;
        self.eval_fixed(params, &mut scratch.f);
        super::jet::run(self, t, m, &scratch.f, &mut scratch.interval);
        flags_pass(self, m, &scratch.f, &scratch.interval, &mut scratch.flags);
        let mut flags = scratch.flags.last().copied().unwrap_or(nowhere);
        let last = &scratch.interval[(self.ops.len() - 1) * m..];
        for (i, (o, &c)) in out.iter_mut().zip(last).enumerate() {
            *o = if i == 0 {
                c
            } else {
                c * Interval::point(super::jet::factorial(i))
            };
        }
        if flags.defined == Defined::Nowhere {
            out[..m].fill(Interval::EMPTY);
        }
        let finite = |s: &[Interval]| s.iter().all(|x| x.is_finite());
        flags.continuous &= finite(&out[..1]);
        flags.smooth &= flags.continuous && finite(&out[..m]);
        flags
    }
}
