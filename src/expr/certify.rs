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

#[cfg(test)]
mod tests {
    use super::super::ast::Expr;
    use super::super::tape::build::*;
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    fn over(e: &Expr, lo: f64, hi: f64) -> (IntervalResult, IntervalFlags, [Interval; 3]) {
        let tape = Tape::compile(e);
        let mut s = Scratch::new();
        let r = tape.eval_interval(lo, hi, &[], &mut s);
        let mut out = [Interval::EMPTY; 3];
        let f = tape.eval_interval_jet(lo, hi, 2, &[], &mut s, &mut out);
        (r, f, out)
    }

    #[test]
    fn flags_at_poles_jumps_and_domain_edges() {
        let recip = div(n(1.0), t());
        let (r, f, _) = over(&recip, -1.0, 1.0);
        assert_eq!(
            (r.defined, r.continuous, f.smooth),
            (Defined::Partly, false, false)
        );
        let (r, f, d) = over(&recip, 0.5, 1.0);
        assert_eq!(
            (r.defined, r.continuous, f.smooth),
            (Defined::Everywhere, true, true)
        );
        assert!(r.value.lo <= 1.0 && r.value.hi >= 2.0 && r.value.hi < 2.0 + 1e-12);
        // x″ = 2/t³ ∈ [2, 16] on [0.5, 1].
        assert!(d[2].contains(2.0) && d[2].contains(16.0) && d[2].hi < 16.0 + 1e-9);

        let (r, _, _) = over(&call(Func::Tan, t()), 1.0, 2.0);
        assert!(!r.continuous && r.defined == Defined::Partly);
        assert!(over(&call(Func::Tan, t()), -1.0, 1.0).0.continuous);

        let (r, f, _) = over(&call(Func::Floor, t()), 0.5, 1.5);
        assert_eq!(
            (r.defined, r.continuous, f.smooth),
            (Defined::Everywhere, false, false)
        );
        assert_eq!(r.value, Interval::new(0.0, 1.0));
        assert!(over(&call(Func::Floor, t()), 1.0, 1.5).0.continuous); // right-continuous
        assert!(!over(&call(Func::Floor, t()), 0.5, 1.0).0.continuous);
        assert!(over(&call(Func::Ceil, t()), 0.5, 1.0).0.continuous); // left-continuous
        assert!(!over(&call(Func::Ceil, t()), 1.0, 1.5).0.continuous);
        assert!(!over(&call(Func::Sign, t()), 0.0, 1.0).0.continuous);

        let root = call(Func::Sqrt, t());
        let (r, _, _) = over(&root, -1.0, 1.0);
        assert_eq!((r.defined, r.continuous), (Defined::Partly, false));
        assert!(r.value.contains(0.0) && r.value.contains(1.0));
        let (r, f, d) = over(&root, -2.0, -1.0);
        assert_eq!(
            (r.defined, r.continuous, f.defined),
            (Defined::Nowhere, false, Defined::Nowhere)
        );
        assert!(r.value.is_empty() && d[1].is_empty());
        let (r, f, _) = over(&root, 0.0, 1.0);
        assert_eq!(
            (r.defined, r.continuous, f.smooth),
            (Defined::Everywhere, true, false)
        );
        assert!(over(&root, 0.25, 1.0).1.smooth);

        let (r, f, _) = over(&call(Func::Abs, t()), -1.0, 1.0);
        assert_eq!((r.continuous, f.smooth), (true, false));
        assert_eq!(
            over(&call(Func::Ln, t()), -1.0, 0.0).0.defined,
            Defined::Nowhere
        );
        assert_eq!(
            over(&call(Func::Asin, t()), 0.5, 2.0).0.defined,
            Defined::Partly
        );
        let (r, f, _) = over(&call(Func::Asin, t()), -1.0, 1.0);
        assert_eq!((r.continuous, f.smooth), (true, false));
        assert!(!over(&pow(t(), n(-0.5)), 0.0, 1.0).0.continuous);
        assert!(over(&pow(t(), n(1.5)), 0.0, 1.0).0.continuous);
        assert_eq!(over(&pow(t(), t()), -2.0, -1.0).0.defined, Defined::Nowhere);
        assert_eq!(
            over(&div(t(), n(0.0)), -2.0, -1.0).0.defined,
            Defined::Nowhere
        );
        // exp(exp(t)) overflows: defined, but not proven finite.
        let (r, _, _) = over(&call(Func::Exp, call(Func::Exp, t())), 6.0, 7.0);
        assert_eq!((r.defined, r.continuous), (Defined::Everywhere, false));
        assert!(over(&t(), 2.0, 1.0).0.value.is_empty());
    }

    #[test]
    fn the_circle_and_the_polynomial_have_tight_enclosures() {
        let (r, f, d) = over(&call(Func::Cos, t()), 0.0, std::f64::consts::PI);
        assert!(f.smooth && r.value.lo == -1.0 && r.value.hi == 1.0);
        assert!(d[1].lo <= -1.0 && d[1].lo > -1.0 - 1e-14 && d[1].hi >= 0.0);
        let (r, _, _) = over(&notes_polynomial(), 0.0, 0.0);
        assert!(r.value.contains(-5.0) && r.value.hi - r.value.lo < 1e-14);
    }

    fn containment_trees() -> Vec<Expr> {
        let sq = |a: Expr| pow(a, n(2.0));
        vec![
            notes_polynomial(),
            call(Func::Cos, t()),
            call(Func::Sin, mul(n(3.0), t())),
            call(Func::Tan, t()),
            div(n(1.0), t()),
            call(Func::Sqrt, t()),
            call(Func::Ln, add(n(2.0), call(Func::Cos, t()))),
            call(Func::Exp, call(Func::Sin, sq(t()))),
            div(call(Func::Atan, t()), add(n(1.0), t())),
            pow(t(), t()),
            call(Func::Asin, div(t(), n(2.0))),
            add(call(Func::Acos, div(t(), n(3.0))), call(Func::Log, t())),
            mul(call(Func::Abs, t()), call(Func::Sin, mul(n(3.0), t()))),
            add(call(Func::Floor, t()), call(Func::Sign, sub(t(), n(1.0)))),
            sub(
                call(Func::Cosh, t()),
                mul(call(Func::Tanh, t()), call(Func::Sinh, t())),
            ),
            add(
                pow(add(n(1.0), sq(t())), n(2.5)),
                pow(add(n(2.0), t()), n(-1.0 / 3.0)),
            ),
            mul(pow(t(), p(0)), call(Func::Ceil, mul(p(1), t()))),
            div(sq(sub(t(), n(1.0))), pow(t(), n(-3.0))),
        ]
    }

    /// Every f64 evaluation (value, x′, x″) at points of a random sub-interval lies in the
    /// enclosure; an undefined point is never inside an "Everywhere" interval.
    #[test]
    fn enclosures_contain_every_point_evaluation() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut random = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let params = [3.0, 1.5];
        let mut s = Scratch::new();
        let mut jet = [0.0; 3];
        let mut enclosure = [Interval::EMPTY; 3];
        for e in containment_trees() {
            let tape = Tape::compile(&e);
            for _ in 0..200 {
                let lo = -4.0 + 8.0 * random();
                let hi = lo + 10f64.powf(-6.0 + 6.5 * random());
                let r = tape.eval_interval(lo, hi, &params, &mut s);
                let f = tape.eval_interval_jet(lo, hi, 2, &params, &mut s, &mut enclosure);
                assert_eq!((r.defined, r.continuous), (f.defined, f.continuous));
                for i in 0..=16 {
                    let x = if i == 16 {
                        hi
                    } else {
                        lo + (hi - lo) * random()
                    };
                    tape.eval_jet(x, 2, &params, &mut s, &mut jet);
                    let where_ = format!("{e:?} on [{lo}, {hi}] at {x}");
                    if jet[0].is_finite() {
                        assert!(r.defined != Defined::Nowhere, "{where_}");
                        assert!(
                            r.value.contains(jet[0]),
                            "{where_}: {} ∉ {:?}",
                            jet[0],
                            r.value
                        );
                    } else if jet[0].is_nan() {
                        assert!(r.defined != Defined::Everywhere, "{where_}");
                    } else {
                        assert!(!r.continuous, "{where_}");
                    }
                    for k in 1..3 {
                        if jet[k].is_finite() && f.defined != Defined::Nowhere {
                            assert!(enclosure[k].contains(jet[k]), "{where_}: d{k}");
                        }
                    }
                }
            }
        }
    }
}
