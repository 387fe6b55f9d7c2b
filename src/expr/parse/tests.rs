//! The parser's tests: trees (by a fully parenthesised print and a small evaluator, against
//! hand-derived readings and values), exact numbers, spans, every refusal with its characters,
//! the budgets, and the parameter names.

use super::*;
use crate::expr::ast::Constant;
use crate::expr::Rational;
#[cfg(target_arch = "wasm32")]
use crate::platform::test;

/// The tree, fully parenthesised: `(2*(t^2))`; parameters by name.
fn show(e: &Expr, names: &[&str]) -> String {
    let ops = [BinOp::Add, BinOp::Sub, BinOp::Mul, BinOp::Div, BinOp::Pow];
    let op = |o: &BinOp| ["+", "-", "*", "/", "^"][ops.iter().position(|p| p == o).unwrap()];
    match &e.node {
        Node::Number { value, .. } => format!("{value}"),
        Node::T => "t".into(),
        Node::Param(i) => names[*i].into(),
        Node::Constant(c) => ["e", "pi"][usize::from(*c == Constant::Pi)].into(),
        Node::Neg(a) => format!("(-{})", show(a, names)),
        Node::Binary(o, a, b) => format!("({}{}{})", show(a, names), op(o), show(b, names)),
        Node::Call(f, a) => format!("{}({})", f.name(), show(a, names)),
    }
}

/// The value of the tree at `t` with parameter values `p` (a test-only reading of the tree).
fn eval(e: &Expr, t: f64, p: &[f64]) -> f64 {
    match &e.node {
        Node::Number { value, .. } => *value,
        Node::T => t,
        Node::Param(i) => p[*i],
        Node::Constant(c) => c.value(),
        Node::Neg(a) => -eval(a, t, p),
        Node::Binary(op, a, b) => {
            let (x, y) = (eval(a, t, p), eval(b, t, p));
            match op {
                BinOp::Add => x + y,
                BinOp::Sub => x - y,
                BinOp::Mul => x * y,
                BinOp::Div => x / y,
                BinOp::Pow => x.powf(y),
            }
        }
        Node::Call(f, a) => {
            let x = eval(a, t, p);
            match f {
                Func::Sin => x.sin(),
                Func::Cos => x.cos(),
                Func::Sqrt => x.sqrt(),
                Func::Ln => x.ln(),
                Func::Log => x.log10(),
                Func::Abs => x.abs(),
                _ => panic!("not used in these tests: {}", f.name()),
            }
        }
    }
}

fn fails(text: &str, names: &[&str]) -> (Problem, usize, usize) {
    match parse(text, names) {
        Ok(e) => panic!("{text:?} parsed as {}", show(&e, names)),
        Err(e) => (e.problem, e.start, e.end),
    }
}

#[test]
fn trees_follow_precedence_associativity_and_implicit_products() {
    let names = ["a", "b", "ω", "a_1"];
    let cases = [
        ("-2^2", "(-(2^2))"),
        ("2^3^2", "(2^(3^2))"),
        ("-t^2", "(-(t^2))"),
        ("2^-1", "(2^(-1))"),
        ("2t^2", "(2*(t^2))"),
        ("3(t+1)", "(3*(t+1))"),
        ("2pi", "(2*pi)"),
        ("pi t", "(pi*t)"),
        ("pit", "(pi*t)"),
        ("at", "(a*t)"),
        ("ab t", "((a*b)*t)"),
        ("sin^2(t)", "(sin(t)^2)"),
        ("(t+1)(t-1)", "((t+1)*(t-1))"),
        ("sin(t)cos(t)", "(sin(t)*cos(t))"),
        ("1-2-3", "((1-2)-3)"),
        ("8/4/2", "((8/4)/2)"),
        ("1+2*3", "(1+(2*3))"),
        ("2*3^2", "(2*(3^2))"),
        ("-2t", "((-2)*t)"),
        ("2*-t", "(2*(-t))"),
        ("t - -1", "(t-(-1))"),
        ("t−1", "(t-1)"),
        ("2×t·t⋅t", "(((2*t)*t)*t)"),
        ("t**2", "(t^2)"),
        ("6÷3", "(6/3)"),
        ("π", "pi"),
        ("2e", "(2*e)"),
        ("e^2 t", "((e^2)*t)"),
        ("e^(2)t", "((e^2)*t)"),
        ("e^(-2)t", "((e^(-2))*t)"),
        ("e^-(2)t", "((e^(-2))*t)"),
        ("t^2 sin(t)", "((t^2)*sin(t))"),
        ("t^2(t)", "((t^2)*t)"),
        ("t^a t", "((t^a)*t)"),
        ("a_1 t", "(a_1*t)"),
        ("ωt", "(ω*t)"),
        ("asin(t)+sinh(t)", "(asin(t)+sinh(t))"),
        ("(((t)))", "t"),
        ("2(3)", "(2*3)"),
        ("t/(2t)", "(t/(2*t))"),
        ("(1/2)t", "((1/2)*t)"),
        ("1/2*t", "((1/2)*t)"),
        ("sin (t)", "sin(t)"),
        ("sin^2.0(t)", "(sin(t)^2)"),
        ("  t\t", "t"),
        ("5.", "5"),
        (".5", "0.5"),
    ];
    for (text, want) in cases {
        match parse(text, &names) {
            Ok(e) => assert_eq!(show(&e, &names), want, "{text:?}"),
            Err(e) => panic!("{text:?}: {e}"),
        }
    }
}

#[test]
fn values_match_hand_computed_readings() {
    let poly = "6.5t^5 - 7.2t^3 + 3t^2 - 2.1t - 5";
    let pi = std::f64::consts::PI;
    // (text, t, a, expected)
    let cases = [
        ("-2^2", 0.0, 0.0, -4.0),
        ("2^3^2", 0.0, 0.0, 512.0),
        ("-t^2", 3.0, 0.0, -9.0),
        ("2^-1", 0.0, 0.0, 0.5),
        ("2t^2", 3.0, 0.0, 18.0),
        ("3(t+1)", 2.0, 0.0, 9.0),
        ("2pi", 0.0, 0.0, 2.0 * pi),
        ("pi t", 2.0, 0.0, 2.0 * pi),
        ("pit", 2.0, 0.0, 2.0 * pi),
        ("at", 3.0, 5.0, 15.0),
        ("sin^2(t)", pi / 6.0, 0.0, 0.25),
        // 6.5·32 − 7.2·8 + 3·4 − 2.1·2 − 5 = 208 − 57.6 + 12 − 4.2 − 5
        (poly, 2.0, 0.0, 153.2),
        ("t − 1", 3.0, 0.0, 2.0),
        ("2 × t", 3.0, 0.0, 6.0),
        ("t ÷ 4", 3.0, 0.0, 0.75),
        ("t**2", 3.0, 0.0, 9.0),
        ("π", 0.0, 0.0, pi),
        ("2^3 - 2*3^2/6", 0.0, 0.0, 5.0),
        ("-(t - 5)^2", 3.0, 0.0, -4.0),
        ("a^-2", 0.0, 4.0, 0.0625),
        ("sqrt(abs(-16))", 0.0, 0.0, 4.0),
        ("log(1000) + ln(e^2)", 0.0, 0.0, 5.0),
    ];
    for (text, t, a, want) in cases {
        let e = parse(text, &["a"]).unwrap_or_else(|e| panic!("{text:?}: {e}"));
        let got = eval(&e, t, &[a]);
        assert!(
            (got - want).abs() <= 1e-12 * want.abs().max(1.0),
            "{text:?}: {got} ≠ {want}"
        );
    }
}

#[test]
fn numbers_keep_their_exact_decimal_value() {
    let r = |n, d| Rational::new(n, d);
    let cases = [
        ("6.5", 6.5, r(13, 2)),
        (".5", 0.5, r(1, 2)),
        ("5.", 5.0, r(5, 1)),
        ("0.500", 0.5, r(1, 2)),
        ("007", 7.0, r(7, 1)),
        ("0.1", 0.1, r(1, 10)),
        ("1.25", 1.25, r(5, 4)),
        // Above i128 (10^40 > 1.7·10^38): no exact value, the f64 still correctly rounded.
        ("10000000000000000000000000000000000000000", 1e40, None),
        // The double nearest 0.1 written out: parses to exactly 0.1.
        (
            "0.1000000000000000055511151231257827",
            0.1,
            r(1000000000000000055511151231257827, 10i128.pow(34)),
        ),
    ];
    for (text, value, exact) in cases {
        let e = parse(text, &[]).unwrap();
        assert_eq!(e.node, Node::number(value, exact), "{text:?}");
        assert_eq!(e.span, Span::new(0, text.len()));
    }
}

#[test]
fn every_node_spans_its_whole_subexpression() {
    let span = |e: &Expr| (e.span.start, e.span.end);
    let e = parse("3(t+1)", &[]).unwrap();
    let Node::Binary(BinOp::Mul, three, group) = &e.node else {
        panic!()
    };
    assert_eq!(
        (span(&e), span(three), span(group)),
        ((0, 6), (0, 1), (1, 6))
    );
    let Node::Binary(BinOp::Add, t, one) = &group.node else {
        panic!()
    };
    assert_eq!((span(t), span(one)), ((2, 3), (4, 5)));

    let e = parse("-t^2", &[]).unwrap();
    let Node::Neg(pow) = &e.node else { panic!() };
    assert_eq!((span(&e), span(pow)), ((0, 4), (1, 4)));

    let e = parse("sin^2(t)", &[]).unwrap();
    let Node::Binary(BinOp::Pow, call, two) = &e.node else {
        panic!()
    };
    let Node::Call(Func::Sin, t) = &call.node else {
        panic!()
    };
    assert_eq!(
        (span(&e), span(call), span(two), span(t)),
        ((0, 8), (0, 8), (4, 5), (6, 7))
    );

    // π is one UTF-16 unit: "π t" is 0..3 with t at 2..3.
    let e = parse("π t", &[]).unwrap();
    let Node::Binary(BinOp::Mul, p, t) = &e.node else {
        panic!()
    };
    assert_eq!((span(&e), span(p), span(t)), ((0, 3), (0, 1), (2, 3)));

    // A Greek parameter, a subscript, and the function name's span inside a call.
    let e = parse("ω_0 cos(t)", &["ω_0"]).unwrap();
    let Node::Binary(BinOp::Mul, w, cos) = &e.node else {
        panic!()
    };
    assert_eq!((span(w), span(cos)), ((0, 3), (4, 10)));
}

#[test]
fn each_refusal_names_its_problem_and_characters() {
    let unexpected = |c: &str| Problem::UnexpectedCharacter {
        character: c.into(),
    };
    let expected = |c: &str| Problem::ExpectedOperand { found: c.into() };
    let missing = |c: &str| Problem::MissingOperator { found: c.into() };
    let unknown = |c: &str| Problem::UnknownName { name: c.into() };
    let needs = |c: &str| Problem::FunctionNeedsParentheses { name: c.into() };
    let power = |c: &str| Problem::FunctionPower { name: c.into() };
    let after = |n: &str, k: &str| Problem::NumberAfterName {
        name: n.into(),
        number: k.into(),
    };
    let ambiguous = |t: &str, p: &str, q: &str| Problem::AmbiguousDivision {
        text: t.into(),
        product: p.into(),
        quotient: q.into(),
    };
    let sci = |t: &str| Problem::ScientificNotation { text: t.into() };
    let big = format!("1{}", "0".repeat(400));
    let cases: Vec<(&str, Problem, usize, usize)> = vec![
        ("", Problem::Empty {}, 0, 0),
        (" \t ", Problem::Empty {}, 0, 0),
        ("1 + q", unknown("q"), 4, 5),
        ("π + q", unknown("q"), 4, 5),
        ("foo", unknown("f"), 0, 1),
        ("T", unknown("T"), 0, 1),
        ("a_1 + b", unknown("b"), 6, 7),
        // A subscript runs on over letters and digits: `a_1t` is one (undeclared) name.
        ("a_1t", unknown("a_1t"), 0, 4),
        ("q + #", unknown("q"), 0, 1),
        ("sin t", needs("sin"), 0, 3),
        ("sint", needs("sin"), 0, 3),
        ("sin", needs("sin"), 0, 3),
        ("2sqrt", needs("sqrt"), 1, 5),
        ("sin^2 t", needs("sin"), 0, 3),
        ("sin^-1(t)", power("sin"), 0, 6),
        ("sin^x(t)", power("sin"), 0, 5),
        ("sin^0(t)", power("sin"), 0, 5),
        ("cos^1.5(t)", power("cos"), 0, 7),
        ("1/2t", ambiguous("1/2t", "(1/2)t", "1/(2t)"), 0, 4),
        ("t/2pi", ambiguous("t/2pi", "(t/2)pi", "t/(2pi)"), 0, 5),
        ("1 + 1/2 t", ambiguous("1/2 t", "(1/2) t", "1/(2 t)"), 4, 9),
        (
            "3t/2t^2 + 1",
            ambiguous("3t/2t^2", "(3t/2)t^2", "3t/(2t^2)"),
            0,
            7,
        ),
        (
            "1/t(t+1)",
            ambiguous("1/t(t+1)", "(1/t)(t+1)", "1/(t(t+1))"),
            0,
            8,
        ),
        ("e^2t", ambiguous("e^2t", "(e^2)t", "e^(2t)"), 0, 4),
        ("2e^-2t", ambiguous("e^-2t", "(e^-2)t", "e^(-2t)"), 1, 6),
        (
            "e^−2.5t",
            ambiguous("e^−2.5t", "(e^−2.5)t", "e^(−2.5t)"),
            0,
            7,
        ),
        ("t**2t", ambiguous("t**2t", "(t**2)t", "t**(2t)"), 0, 5),
        (
            "t^2sin(t)",
            ambiguous("t^2sin(t)", "(t^2)sin(t)", "t^(2sin(t))"),
            0,
            9,
        ),
        ("t2", after("t", "2"), 0, 2),
        ("2e3", sci("2e3"), 0, 3),
        ("t + 1e-3", sci("1e-3"), 4, 8),
        ("2.5e+4t", sci("2.5e+4"), 0, 6),
        ("1.5E-3", unknown("E"), 3, 4),
        ("pi2", after("pi", "2"), 0, 3),
        ("2 3", missing("3"), 2, 3),
        ("(t+1)2", missing("2"), 5, 6),
        ("t 2", missing("2"), 2, 3),
        ("2,5", unexpected(","), 1, 2),
        ("|t|", unexpected("|"), 0, 1),
        ("t + 😀", unexpected("😀"), 4, 6),
        ("π + #", unexpected("#"), 4, 5),
        ("t_", unexpected("_"), 1, 2),
        ("t = 1", unexpected("="), 2, 3),
        (
            "1.2.3",
            Problem::InvalidNumber {
                text: "1.2.3".into(),
            },
            0,
            5,
        ),
        ("t + .", Problem::InvalidNumber { text: ".".into() }, 4, 5),
        (
            &big,
            Problem::NotFiniteValue {
                value: f64::INFINITY,
            },
            0,
            401,
        ),
        ("2+", expected(""), 1, 2),
        ("t^", expected(""), 1, 2),
        ("sin^", expected(""), 3, 4),
        ("*t", expected("*"), 0, 1),
        ("+t", expected("+"), 0, 1),
        ("()", expected(")"), 1, 2),
        ("t+)", expected(")"), 2, 3),
        ("sin()", expected(")"), 4, 5),
        ("sin(t", Problem::UnclosedParenthesis {}, 3, 4),
        ("((t)", Problem::UnclosedParenthesis {}, 0, 1),
        ("t)", Problem::UnmatchedParenthesis {}, 1, 2),
        ("(t))", Problem::UnmatchedParenthesis {}, 3, 4),
    ];
    for (text, problem, start, end) in cases {
        assert_eq!(fails(text, &["a_1"]), (problem, start, end), "{text:?}");
    }
}

#[test]
fn budgets_refuse_long_deep_and_large_texts_without_recursing() {
    let too_long = |length| Problem::TooLong { length, max: 1000 };
    for c in ["(", "-"] {
        let text = c.repeat(100_000);
        assert_eq!(fails(&text, &[]), (too_long(100_000), 1000, 100_000));
    }
    // π counts one unit, 😀 two: 1000 units pass, 1001 do not.
    let pad = " ".repeat(998);
    assert!(parse(&format!("t{pad}π"), &[]).is_ok());
    assert_eq!(
        fails(&format!("t{pad}😀"), &[]),
        (too_long(1001), 1000, 1001)
    );

    let deep = Problem::TooDeep { max: 64 };
    let nest =
        |open: &str, n: usize, close: &str| format!("{}t{}", open.repeat(n), close.repeat(n));
    for (open, close, width) in [
        ("(", ")", 1),
        ("-", "", 1),
        ("sin(", ")", 4),
        ("-(", ")", 1),
    ] {
        let levels = if open == "-(" { 32 } else { 64 };
        assert!(
            parse(&nest(open, levels, close), &[]).is_ok(),
            "{open} ×{levels}"
        );
        // The level-65 opener is underlined (for "-(" the '-' of the 33rd pair).
        let at = if open == "-(" { 64 } else { 64 * open.len() };
        let text = nest(open, levels + 1, close);
        assert_eq!(fails(&text, &[]), (deep.clone(), at, at + width), "{open}");
    }
    assert_eq!(
        fails(&format!("{}t", "-".repeat(999)), &[]),
        (deep.clone(), 64, 65)
    );
    assert_eq!(
        fails(&format!("{}t", "(".repeat(999)), &[]),
        (deep.clone(), 64, 65)
    );
    assert!(parse(&format!("2{}", "^2".repeat(64)), &[]).is_ok());
    assert_eq!(
        fails(&format!("2{}", "^2".repeat(65)), &[]),
        (deep, 129, 130)
    );

    // 499 additions of 500 ones: 999 nodes. 1000 t's: node 1001 is the product after the 501st.
    assert!(parse(&format!("{}1", "1+".repeat(499)), &[]).is_ok());
    let many = Problem::TooManyNodes { max: 1000 };
    assert_eq!(fails(&"t".repeat(1000), &[]), (many, 500, 501));
}

#[test]
fn parameter_names_lists_each_used_name_once_in_order() {
    let cases: [(&str, &[&str]); 6] = [
        ("a t + b sin(ω t) + a", &["a", "b", "ω"]),
        ("pi e t + π", &[]),
        ("a_1 + a_max + a_1", &["a_1", "a_max"]),
        ("at", &["a"]),
        ("t_0 + T", &["t_0", "T"]),
        ("c(t - d)^2", &["c", "d"]),
    ];
    for (text, want) in cases {
        assert_eq!(parameter_names(text).unwrap(), want, "{text:?}");
    }
    let error = |text| parameter_names(text).map_err(|e| (e.problem, e.start, e.end));
    let found = Problem::ExpectedOperand {
        found: String::new(),
    };
    assert_eq!(error("q +"), Err((found, 2, 3)));
    let sin = Problem::FunctionNeedsParentheses { name: "sin".into() };
    assert_eq!(error("sinx"), Err((sin, 0, 3)));
}

#[test]
fn parameter_names_are_single_letters_or_subscripted() {
    for name in ["a", "ω", "Ω", "T", "E", "a_1", "a_max", "t_0", "e_1", "ω_0"] {
        assert!(is_parameter_name(name), "{name}");
    }
    for name in [
        "", "t", "e", "π", "ab", "pi", "sin", "a_", "_a", "a_ω", "1", "a_1!", "é", "ϖ",
    ] {
        assert!(!is_parameter_name(name), "{name}");
    }
}

/// Each child's span lies inside its parent's; returns the node count.
fn check_spans(e: &Expr, outer: Span) -> usize {
    assert!(outer.start <= e.span.start && e.span.end <= outer.end && e.span.start < e.span.end);
    1 + match &e.node {
        Node::Neg(a) | Node::Call(_, a) => check_spans(a, e.span),
        Node::Binary(_, a, b) => check_spans(a, e.span) + check_spans(b, e.span),
        _ => 0,
    }
}

#[test]
fn random_texts_parse_or_fail_cleanly_with_nested_spans() {
    let alphabet = [
        "t", "2", ".5", "(", ")", "-", "^", "*", "/", "+", " ", "sin", "pi", "e", "a", "π", "😀",
        "_1", "**", "−",
    ];
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = |n: usize| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % n as u64) as usize
    };
    let (mut ok, mut refused) = (0, 0);
    for _ in 0..3000 {
        let length = 1 + next(12);
        let text: String = (0..length)
            .map(|_| alphabet[next(alphabet.len())])
            .collect();
        let units = text.encode_utf16().count();
        let parsed = parse(&text, &["a"]);
        let names = parameter_names(&text);
        match (&parsed, &names) {
            (Ok(e), Ok(names)) => {
                assert!(check_spans(e, Span::new(0, units)) <= MAX_NODES);
                assert!(names.iter().all(|n| n == "a"), "{text:?}");
                ok += 1;
            }
            // An undeclared name (`a_1`, `e_1`): parameter_names reads on past it.
            (Err(e), _) if matches!(e.problem, Problem::UnknownName { .. }) => refused += 1,
            (Err(e), Err(f)) => {
                assert_eq!(e, f, "{text:?}");
                assert!(e.start <= e.end && e.end <= units, "{text:?}: {e:?}");
                refused += 1;
            }
            _ => panic!("{text:?}: {parsed:?} but {names:?}"),
        }
    }
    // Both outcomes are exercised.
    assert!(ok > 100 && refused > 100, "{ok} parsed, {refused} refused");
}
