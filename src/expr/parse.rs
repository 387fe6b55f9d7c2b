//! The parser: tokens ([`super::lex`]) to a tree ([`Expr`]) by recursive descent.
//!
//! ```text
//! expr    = term (("+" | "-") term)*
//! term    = unary (("*" | "/") unary | power)*      implicit product: 2t, 3(t+1), pi t
//! unary   = "-" unary | power                        -t^2 = −(t²)
//! power   = primary ("^" unary)?                     right-associative: 2^3^2 = 2^9
//! primary = number | name | func ("^" n)? "(" expr ")" | "(" expr ")"
//! ```
//! An implicit factor starts with a name or `(`, never with a number (`2 3`, `(t+1)2`, `t2`
//! are refused), and never follows a division (`1/2t`: write `(1/2)t` or `1/(2t)`); a numeric
//! exponent directly followed by a name is refused too (`e^2t`: `(e^2)t` or `e^(2t)`).
//!
//! Budgets, so no input can exhaust the stack or the memory: the text is at most
//! [`MAX_LENGTH`] UTF-16 units (checked before anything else), every recursion (parentheses,
//! calls, unary minus, powers) passes `Parser::enter`, which refuses nesting deeper than
//! [`MAX_NESTING`], and the tree has at most [`MAX_NODES`] nodes. The loops each consume a
//! token per turn, so they end with the text.

use super::ast::{boxed, BinOp, Expr, Func, Node, Span};
use super::error::{ExprError, Problem};
use super::lex::{exact_decimal, is_letter, is_subscript, lex, Kind, Token, Word};
use super::{MAX_LENGTH, MAX_NESTING, MAX_NODES};

/// The tree of `text`, whose names other than `t`, `pi`, `π`, `e` and the functions must be
/// among `parameters` (`Node::Param(i)` is `parameters[i]`, the first if one is repeated).
///
/// Errors carry the characters to underline (UTF-16 code units): the unknown letter, the
/// function name without parentheses, the whole of `1/2t`, the unclosed `(`, …
#[allow(clippy::result_large_err)] // the family's error type; boxed inside, where it recurses
pub fn parse(text: &str, parameters: &[&str]) -> Result<Expr, ExprError> {
    match Parser::run(text, parameters, None) {
        Ok((expr, _)) => Ok(expr),
        Err(e) => Err(*e),
    }
}

/// The parameter names `text` uses, in order of first appearance, without repeats: every
/// parameter-shaped name ([`is_parameter_name`]) is accepted (never `t`, `e`, `pi`). A text
/// that does not parse gives the same error as [`parse`].
#[allow(clippy::result_large_err)] // as in `parse`
pub fn parameter_names(text: &str) -> Result<Vec<String>, ExprError> {
    match Parser::run(text, &[], Some(Vec::new())) {
        Ok((_, names)) => Ok(names.unwrap_or_default()),
        Err(e) => Err(*e),
    }
}

/// Refuses `1e-3`, `2.5E+4`, `6e3` written with no space: a number, `e`, an optional sign and
/// a number read as `1·e − 3` would silently be another curve than the student meant.
fn scientific(tokens: &[crate::expr::lex::Token<'_>]) -> Result<(), Fail> {
    use crate::expr::lex::Word;
    for (k, first) in tokens.iter().enumerate() {
        let Kind::Number { .. } = first.kind else {
            continue;
        };
        let rest = tokens.get(k + 1..).unwrap_or_default();
        let [e, next, after, ..] = rest else {
            continue;
        };
        let is_e = matches!(e.kind, Kind::Name(Word::Constant(crate::expr::Constant::E)))
            && e.text == "e"
            && !e.spaced;
        if !is_e {
            continue;
        }
        let last = match (next.kind, after.kind) {
            (Kind::Plus | Kind::Minus, Kind::Number { .. }) if !next.spaced && !after.spaced => {
                after
            }
            (Kind::Number { .. }, _) if !next.spaced => next,
            _ => continue,
        };
        let span = first.span.to(last.span);
        let text: String = tokens
            .get(k..)
            .unwrap_or_default()
            .iter()
            .take_while(|t| t.span.start < span.end)
            .map(|t| t.text)
            .collect();
        return Err(err(span, Problem::ScientificNotation { text }));
    }
    Ok(())
}

/// Whether `name` can be a parameter: one letter (Latin or Greek) other than `t`, `e` and
/// `π`, or a letter, `_` and a subscript of ASCII letters and digits (`a_1`, `ω_0`, `a_max`).
pub fn is_parameter_name(name: &str) -> bool {
    let mut chars = name.chars();
    let Some(first) = chars.next() else {
        return false;
    };
    if !is_letter(first) {
        return false;
    }
    match chars.next() {
        None => !matches!(first, 't' | 'e' | 'π'),
        Some('_') => {
            let rest = chars.as_str();
            !rest.is_empty() && rest.chars().all(is_subscript)
        }
        Some(_) => false,
    }
}

/// Errors are boxed while parsing: a small `Result` keeps the recursion's frames small.
type Fail = Box<ExprError>;
type Parsed = Result<Expr, Fail>;

/// The parser's state.
struct Parser<'a, 'p> {
    text: &'a str,
    tokens: Vec<Token<'a>>,
    pos: usize,
    parameters: &'p [&'p str],
    /// `Some` in [`parameter_names`]: every parameter-shaped name is collected here.
    collected: Option<Vec<String>>,
    depth: usize,
    nodes: usize,
}

/// The error at `span` (out of line, as [`fail`]: errors are the cold path).
#[inline(never)]
fn err(span: Span, problem: Problem) -> Fail {
    fail(ExprError::at(span.start, span.end, problem))
}

/// `Box::new(e)`, one copy for every error site.
#[inline(never)]
fn fail(e: ExprError) -> Fail {
    Box::new(e)
}

impl<'a, 'p> Parser<'a, 'p> {
    fn run(
        text: &'a str,
        parameters: &'p [&'p str],
        collected: Option<Vec<String>>,
    ) -> Result<(Expr, Option<Vec<String>>), Fail> {
        let length = text.encode_utf16().count();
        if length > MAX_LENGTH {
            let problem = Problem::TooLong {
                length,
                max: MAX_LENGTH,
            };
            return Err(fail(ExprError::at(MAX_LENGTH, length, problem)));
        }
        if text.trim().is_empty() {
            return Err(fail(ExprError::at(0, 0, Problem::Empty {})));
        }
        let tokens = lex(text);
        scientific(&tokens)?;
        let mut parser = Parser {
            text,
            tokens,
            pos: 0,
            parameters,
            collected,
            depth: 0,
            nodes: 0,
        };
        let expr = parser.expr()?;
        let next = parser.peek()?;
        match next.kind {
            Kind::End => Ok((expr, parser.collected)),
            Kind::Close => Err(err(next.span, Problem::UnmatchedParenthesis {})),
            _ => Err(err(
                next.span,
                Problem::MissingOperator {
                    found: next.text.to_string(),
                },
            )),
        }
    }

    /// The next token (the error of a bad one). Out of line: called from every rule.
    #[inline(never)]
    fn peek(&self) -> Result<Token<'a>, Fail> {
        let token = self
            .tokens
            .get(self.pos)
            .or(self.tokens.last())
            .copied()
            .unwrap_or(Token {
                kind: Kind::End,
                text: "",
                span: Span::default(),
                spaced: false,
            });
        match token.problem() {
            Some(e) => Err(fail(e)),
            None => Ok(token),
        }
    }

    fn bump(&mut self) {
        if self.pos + 1 < self.tokens.len() {
            self.pos += 1;
        }
    }

    /// The span of the token before the next one (the whole text's end if none).
    fn previous_span(&self) -> Span {
        match self.pos.checked_sub(1).and_then(|i| self.tokens.get(i)) {
            Some(t) => t.span,
            None => Span::default(),
        }
    }

    /// One more node, within [`MAX_NODES`].
    fn node(&mut self, node: Node, span: Span) -> Parsed {
        self.nodes += 1;
        if self.nodes > MAX_NODES {
            let problem = Problem::TooManyNodes { max: MAX_NODES };
            return Err(err(self.previous_span(), problem));
        }
        Ok(Expr::new(node, span))
    }

    fn binary(&mut self, op: BinOp, a: Expr, b: Expr) -> Parsed {
        let span = a.span.to(b.span);
        self.node(Node::Binary(op, boxed(a), boxed(b)), span)
    }

    /// One level deeper (at `span`, the token that opens it), within [`MAX_NESTING`].
    fn enter(&mut self, span: Span) -> Result<(), Fail> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            return Err(err(span, Problem::TooDeep { max: MAX_NESTING }));
        }
        Ok(())
    }

    fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    /// The typed text between two UTF-16 offsets.
    fn slice(&self, start: usize, end: usize) -> &'a str {
        let (mut unit, mut from, mut to) = (0, self.text.len(), self.text.len());
        for (byte, c) in self.text.char_indices() {
            if unit == start {
                from = byte;
            }
            if unit == end {
                to = byte;
            }
            unit += c.len_utf16();
        }
        self.text.get(from..to).unwrap_or("")
    }

    /// Whether an exponent is a bare number as typed (`2`, `-1`; not `(2)`, whose node is a
    /// number too but whose span starts at the parenthesis).
    fn numeric(&self, e: &Expr) -> bool {
        let starts = |e: &Expr, first: fn(char) -> bool| {
            let text = self.slice(e.span.start, e.span.end);
            text.chars().next().is_some_and(first)
        };
        let digit = |c: char| c.is_ascii_digit() || c == '.';
        match &e.node {
            Node::Number { .. } => starts(e, digit),
            Node::Neg(a) => {
                matches!(a.node, Node::Number { .. })
                    && starts(e, |c| c == '-' || c == '−')
                    && starts(a, digit)
            }
            _ => false,
        }
    }

    /// The error for an implicit product after `start..inner` (`1/2` with `inner` = `2`,
    /// `e^2` with `inner` = `2`): parse the rest of the product to find its end, then offer
    /// both readings.
    #[inline(never)]
    fn ambiguous(&mut self, start: usize, inner: Span) -> Fail {
        let mut end = inner.end;
        while let Ok(Token {
            kind: Kind::Name(_) | Kind::Open,
            ..
        }) = self.peek()
        {
            match self.power() {
                Ok(factor) => end = factor.span.end,
                Err(e) => return e,
            }
        }
        let problem = Problem::AmbiguousDivision {
            text: self.slice(start, end).to_string(),
            product: format!(
                "({}){}",
                self.slice(start, inner.end),
                self.slice(inner.end, end)
            ),
            quotient: format!(
                "{}({})",
                self.slice(start, inner.start),
                self.slice(inner.start, end)
            ),
        };
        err(Span::new(start, end), problem)
    }

    fn expr(&mut self) -> Parsed {
        let mut left = self.term()?;
        loop {
            let op = match self.peek()?.kind {
                Kind::Plus => BinOp::Add,
                Kind::Minus => BinOp::Sub,
                _ => return Ok(left),
            };
            self.bump();
            let right = self.term()?;
            left = self.binary(op, left, right)?;
        }
    }

    fn term(&mut self) -> Parsed {
        let mut left = self.unary()?;
        // The divisor's span when the last factor followed a "/".
        let mut divisor: Option<Span> = None;
        loop {
            let next = self.peek()?;
            match next.kind {
                Kind::Times | Kind::Divide => {
                    self.bump();
                    let right = self.unary()?;
                    let op = if next.kind == Kind::Times {
                        divisor = None;
                        BinOp::Mul
                    } else {
                        divisor = Some(right.span);
                        BinOp::Div
                    };
                    left = self.binary(op, left, right)?;
                }
                Kind::Name(_) | Kind::Open => {
                    if let Some(inner) = divisor {
                        return Err(self.ambiguous(left.span.start, inner));
                    }
                    let right = self.power()?;
                    left = self.binary(BinOp::Mul, left, right)?;
                }
                Kind::Number { .. } => return Err(self.number_after_operand(next)),
                _ => return Ok(left),
            }
        }
    }

    /// A number where an operator is needed: `t2` (right after a name) or `2 3`.
    #[inline(never)]
    fn number_after_operand(&self, number: Token) -> Fail {
        match self.pos.checked_sub(1).and_then(|i| self.tokens.get(i)) {
            Some(name) if matches!(name.kind, Kind::Name(_)) && !number.spaced => {
                let problem = Problem::NumberAfterName {
                    name: name.text.to_string(),
                    number: number.text.to_string(),
                };
                err(name.span.to(number.span), problem)
            }
            _ => {
                let found = number.text.to_string();
                err(number.span, Problem::MissingOperator { found })
            }
        }
    }

    fn unary(&mut self) -> Parsed {
        let minus = self.peek()?;
        if minus.kind != Kind::Minus {
            return self.power();
        }
        self.bump();
        self.enter(minus.span)?;
        let operand = self.unary()?;
        self.leave();
        let span = minus.span.to(operand.span);
        self.node(Node::Neg(boxed(operand)), span)
    }

    fn power(&mut self) -> Parsed {
        let base = self.primary()?;
        let caret = self.peek()?;
        if caret.kind != Kind::Power {
            return Ok(base);
        }
        self.bump();
        self.enter(caret.span)?;
        let exponent = self.unary()?;
        self.leave();
        let next = self.peek()?;
        if self.numeric(&exponent) && matches!(next.kind, Kind::Name(_)) && !next.spaced {
            return Err(self.ambiguous(base.span.start, exponent.span));
        }
        self.binary(BinOp::Pow, base, exponent)
    }

    fn primary(&mut self) -> Parsed {
        let token = self.peek()?;
        let leaf = match token.kind {
            Kind::Number { value } => Node::number(value, exact_decimal(token.text)),
            Kind::Name(Word::T) => Node::T,
            Kind::Name(Word::Constant(c)) => Node::Constant(c),
            Kind::Name(Word::Letter) => Node::Param(self.parameter(token)?),
            Kind::Name(Word::Func(f)) => return self.call(f, token),
            Kind::Open => return self.group(token),
            Kind::End => {
                let found = String::new();
                return Err(err(
                    self.previous_span(),
                    Problem::ExpectedOperand { found },
                ));
            }
            _ => {
                let found = token.text.to_string();
                return Err(err(token.span, Problem::ExpectedOperand { found }));
            }
        };
        self.bump();
        self.node(leaf, token.span)
    }

    /// The index of a parameter-shaped name.
    fn parameter(&mut self, token: Token) -> Result<usize, Fail> {
        let name = token.text;
        if let Some(i) = self.parameters.iter().position(|p| *p == name) {
            return Ok(i);
        }
        match &mut self.collected {
            Some(names) => Ok(match names.iter().position(|p| p == name) {
                Some(i) => i,
                None => {
                    names.push(name.to_string());
                    names.len() - 1
                }
            }),
            None => {
                let name = name.to_string();
                Err(err(token.span, Problem::UnknownName { name }))
            }
        }
    }

    /// `( expr )`: the inner tree, its span widened to the parentheses.
    fn group(&mut self, open: Token) -> Parsed {
        self.bump();
        self.enter(open.span)?;
        let inner = self.expr()?;
        self.leave();
        let close = self.close(open)?;
        Ok(Expr::new(inner.node, open.span.to(close)))
    }

    /// The `)` matching `open`.
    fn close(&mut self, open: Token) -> Result<Span, Fail> {
        let close = self.peek()?;
        if close.kind != Kind::Close {
            return Err(err(open.span, Problem::UnclosedParenthesis {}));
        }
        self.bump();
        Ok(close.span)
    }

    /// `f(expr)` or `f^n(expr)` = (f(expr))^n with n a whole number ≥ 1.
    fn call(&mut self, f: Func, name: Token) -> Parsed {
        self.bump();
        let mut power = None;
        if self.peek()?.kind == Kind::Power {
            self.bump();
            power = Some(self.function_power(f, name)?);
        }
        let open = self.peek()?;
        if open.kind != Kind::Open {
            let problem = Problem::FunctionNeedsParentheses {
                name: f.name().to_string(),
            };
            return Err(err(name.span, problem));
        }
        self.bump();
        self.enter(name.span.to(open.span))?;
        let argument = self.expr()?;
        self.leave();
        let span = name.span.to(self.close(open)?);
        let call = self.node(Node::Call(f, boxed(argument)), span)?;
        match power {
            Some(n) => self.node(Node::Binary(BinOp::Pow, boxed(call), boxed(n)), span),
            None => Ok(call),
        }
    }

    /// The `n` of `f^n(…)` (the `^` read): a whole number ≥ 1, else [`Problem::FunctionPower`]
    /// over `f^` and what follows it (`sin^-1`).
    fn function_power(&mut self, f: Func, name: Token) -> Parsed {
        let token = self.peek()?;
        let end = match token.kind {
            Kind::Number { value } => {
                let exact = exact_decimal(token.text);
                if exact.is_some_and(|r| r.is_integer() && r.numer() >= 1) {
                    self.bump();
                    return self.node(Node::number(value, exact), token.span);
                }
                token.span
            }
            Kind::End => {
                let found = String::new();
                return Err(err(
                    self.previous_span(),
                    Problem::ExpectedOperand { found },
                ));
            }
            Kind::Minus => {
                self.bump();
                match self.peek()? {
                    next if matches!(next.kind, Kind::Number { .. }) => next.span,
                    _ => token.span,
                }
            }
            _ => token.span,
        };
        let problem = Problem::FunctionPower {
            name: f.name().to_string(),
        };
        Err(err(name.span.to(end), problem))
    }
}

// The tests are many (every refusal with its exact characters): they live in parse/tests.rs
// to keep this file under the house limit of 500 lines.
#[cfg(test)]
mod tests;
