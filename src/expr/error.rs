//! What can be wrong with a typed expression, where, and the English words for it.
//!
//! An [`ExprError`] names the piece and the field (`pieces[1].y`) when it belongs to one, the
//! characters to underline (UTF-16 code units, as JavaScript counts) and a [`Problem`] with a
//! stable code of its own (`"unknown-name"`), so a page can underline the exact characters and
//! say why in its own language. It reaches JavaScript as [`crate::Error::Expression`].

use std::fmt;

/// What is wrong. Each variant has a stable kebab-case code ([`Problem::code`]) and its fields
/// become the thrown Error's `params` (camelCase) beside `piece`, `field`, `start` and `end`.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// Nothing typed: `""`, `"  "`.
    Empty {},
    /// Longer than [`super::MAX_LENGTH`] code units.
    TooLong {
        /// Its length.
        length: usize,
        /// The cap.
        max: usize,
    },
    /// Parentheses, powers or function calls nested deeper than [`super::MAX_NESTING`].
    TooDeep {
        /// The cap.
        max: usize,
    },
    /// More than [`super::MAX_NODES`] numbers, names and operations.
    TooManyNodes {
        /// The cap.
        max: usize,
    },
    /// A character the language does not use: `#`, `,` (a decimal comma: write `2.5`), `|`
    /// (write `abs(t)`), `=`.
    UnexpectedCharacter {
        /// The character.
        character: String,
    },
    /// A number, name or `(` was expected: `2+`, `*t`, `()`, `t+)`.
    ExpectedOperand {
        /// What was found instead (`"+"`, `")"`, or `""` at the end of the text).
        found: String,
    },
    /// Two operands with no operator where an implicit product is not allowed: `2 3`.
    MissingOperator {
        /// The second operand as typed.
        found: String,
    },
    /// A `(` never closed: `sin(t`.
    UnclosedParenthesis {},
    /// A `)` with no `(` before it: `t)`.
    UnmatchedParenthesis {},
    /// A name that is neither `t`, a constant, a function nor a declared parameter.
    UnknownName {
        /// The name as typed.
        name: String,
    },
    /// A function written without parentheses: `sin t` (write `sin(t)`).
    FunctionNeedsParentheses {
        /// The function's name.
        name: String,
    },
    /// A power of a function other than a whole number ≥ 1 before its argument: `sin^-1(t)`
    /// (write `asin(t)`), `sin^x(t)`. `sin^2(t)` is read as `(sin(t))^2`.
    FunctionPower {
        /// The function's name.
        name: String,
    },
    /// An implicit product right after a division: `1/2t` (write `(1/2)t` or `1/(2t)`).
    AmbiguousDivision {
        /// The typed text: `"1/2t"`.
        text: String,
        /// It read as a product: `"(1/2)t"`.
        product: String,
        /// It read as a quotient: `"1/(2t)"`.
        quotient: String,
    },
    /// A number right after a name: `t2` (write `2t` or `t^2`), `2e3`.
    NumberAfterName {
        /// The name.
        name: String,
        /// The number as typed.
        number: String,
    },
    /// A number in scientific notation: `1e-3` (write `0.001`).
    ScientificNotation {
        /// The text: `"1e-3"`.
        text: String,
    },
    /// A number that is not one: `1.2.3`, `.`.
    InvalidNumber {
        /// The text.
        text: String,
    },
    /// A parameter name that is not a single letter (other than `t` and `e`) or one letter
    /// with a subscript (`a_1`), or a name already taken by `t`, a constant or a function.
    InvalidParameterName {
        /// The name.
        name: String,
    },
    /// `setParameter` of a name the curve does not have.
    UnknownParameter {
        /// The name.
        name: String,
    },
    /// A parameter's value or an interval bound that is NaN or infinite: `from = "ln(0)"`.
    NotFiniteValue {
        /// The value.
        value: f64,
    },
    /// A piece whose interval is empty or reversed.
    EmptyInterval {
        /// Its start.
        from: f64,
        /// Its end.
        to: f64,
    },
    /// Piece i+1 does not start where piece i ends.
    PiecesDoNotJoin {
        /// Piece i's end.
        previous: f64,
        /// Piece i+1's start.
        from: f64,
    },
    /// `toBezier` of a piece that is not a polynomial in t.
    NotPolynomial {},
    /// An interval bound that reads t: `to = "2t"`.
    BoundUsesT {},
    /// A field that every piece needs is missing (`x`, `y`, `from`, `to`), or `z` on some
    /// pieces only.
    MissingField {},
    /// No pieces, or more than [`super::MAX_PIECES`].
    PieceCount {
        /// How many were given.
        count: usize,
        /// The cap.
        max: usize,
    },
}

impl Problem {
    /// The stable code (`"unknown-name"`), one per variant.
    pub fn code(&self) -> &'static str {
        match self {
            Problem::Empty { .. } => "expression-empty",
            Problem::TooLong { .. } => "expression-too-long",
            Problem::TooDeep { .. } => "expression-too-deep",
            Problem::TooManyNodes { .. } => "expression-too-large",
            Problem::UnexpectedCharacter { .. } => "unexpected-character",
            Problem::ExpectedOperand { .. } => "expected-operand",
            Problem::MissingOperator { .. } => "missing-operator",
            Problem::UnclosedParenthesis { .. } => "unclosed-parenthesis",
            Problem::UnmatchedParenthesis { .. } => "unmatched-parenthesis",
            Problem::UnknownName { .. } => "unknown-name",
            Problem::FunctionNeedsParentheses { .. } => "function-needs-parentheses",
            Problem::FunctionPower { .. } => "function-power",
            Problem::AmbiguousDivision { .. } => "ambiguous-division",
            Problem::NumberAfterName { .. } => "number-after-name",
            Problem::ScientificNotation { .. } => "scientific-notation",
            Problem::InvalidNumber { .. } => "invalid-number",
            Problem::InvalidParameterName { .. } => "invalid-parameter-name",
            Problem::UnknownParameter { .. } => "unknown-parameter",
            Problem::NotFiniteValue { .. } => "not-finite-value",
            Problem::EmptyInterval { .. } => "empty-piece-interval",
            Problem::PiecesDoNotJoin { .. } => "pieces-do-not-join",
            Problem::NotPolynomial { .. } => "not-polynomial",
            Problem::BoundUsesT { .. } => "bound-uses-t",
            Problem::MissingField { .. } => "missing-field",
            Problem::PieceCount { .. } => "piece-count",
        }
    }
}

/// A [`Problem`] and where it is.
#[derive(Clone, Debug, PartialEq)]
pub struct ExprError {
    /// The piece (0-based), when the error belongs to one.
    pub piece: Option<usize>,
    /// The field: `"x"`, `"y"`, `"z"`, `"from"`, `"to"`, or a parameter's name for its value.
    pub field: Option<String>,
    /// First UTF-16 code unit to underline (0 with `end` 0: nothing to underline).
    pub start: usize,
    /// One past the last.
    pub end: usize,
    /// What is wrong.
    pub problem: Problem,
}

impl ExprError {
    /// An error at `start..end` of a text not yet placed in a piece (the parser's).
    #[inline(never)] // one copy for every error site (wasm size)
    pub fn at(start: usize, end: usize, problem: Problem) -> Self {
        ExprError {
            piece: None,
            field: None,
            start,
            end,
            problem,
        }
    }

    /// The same error, placed in piece `piece` (no field).
    pub fn in_piece(mut self, piece: usize) -> Self {
        self.piece = Some(piece);
        self
    }

    /// The same error, placed in `field` of piece `piece`.
    #[inline(never)]
    pub fn in_field(mut self, piece: usize, field: &str) -> Self {
        self.piece = Some(piece);
        self.field = Some(field.to_string());
        self
    }
}

impl From<ExprError> for crate::Error {
    fn from(error: ExprError) -> Self {
        crate::Error::Expression {
            error: Box::new(error),
        }
    }
}

impl fmt::Display for ExprError {
    /// `pieces[1].y, characters 3–4: unknown name "q"; …`
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.piece, &self.field) {
            (Some(p), Some(field)) => write!(f, "pieces[{p}].{field}")?,
            (Some(p), None) => write!(f, "pieces[{p}]")?,
            (None, Some(field)) => write!(f, "{field}")?,
            (None, None) => f.write_str("expression")?,
        }
        if self.end > self.start {
            write!(f, ", characters {}–{}", self.start, self.end)?;
        }
        write!(f, ": {}", self.problem)
    }
}

/// One value of an error's params: nothing (`undefined`), a count, a number or a string.
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
#[derive(Clone, Copy)]
enum Param<'a> {
    None,
    Count(usize),
    Number(f64),
    Text(&'a str),
}

#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
impl serde::Serialize for Param<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match *self {
            Param::None => s.serialize_none(),
            Param::Count(n) => s.serialize_u64(n as u64),
            Param::Number(x) => s.serialize_f64(x),
            Param::Text(t) => s.serialize_str(t),
        }
    }
}

/// The params: `piece`, `field`, `start`, `end`, then the problem's fields (camelCase), one
/// map written by hand (a derive with a flattened untagged enum costs the wasm several KB).
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
impl serde::Serialize for ExprError {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        use Param::{Count, Number, Text};
        const NONE: (&str, Param) = ("", Param::None);
        let head = [
            ("piece", self.piece.map_or(Param::None, Count)),
            ("field", self.field.as_deref().map_or(Param::None, Text)),
            ("start", Count(self.start)),
            ("end", Count(self.end)),
        ];
        let (fields, n) = match &self.problem {
            Problem::Empty {}
            | Problem::UnclosedParenthesis {}
            | Problem::UnmatchedParenthesis {}
            | Problem::NotPolynomial {}
            | Problem::BoundUsesT {}
            | Problem::MissingField {} => ([NONE, NONE, NONE], 0),
            Problem::TooLong { length, max } => {
                ([("length", Count(*length)), ("max", Count(*max)), NONE], 2)
            }
            Problem::TooDeep { max } | Problem::TooManyNodes { max } => {
                ([("max", Count(*max)), NONE, NONE], 1)
            }
            Problem::UnexpectedCharacter { character } => {
                ([("character", Text(character)), NONE, NONE], 1)
            }
            Problem::ExpectedOperand { found } | Problem::MissingOperator { found } => {
                ([("found", Text(found)), NONE, NONE], 1)
            }
            Problem::UnknownName { name }
            | Problem::FunctionNeedsParentheses { name }
            | Problem::FunctionPower { name }
            | Problem::InvalidParameterName { name }
            | Problem::UnknownParameter { name } => ([("name", Text(name)), NONE, NONE], 1),
            Problem::AmbiguousDivision {
                text,
                product,
                quotient,
            } => (
                [
                    ("text", Text(text)),
                    ("product", Text(product)),
                    ("quotient", Text(quotient)),
                ],
                3,
            ),
            Problem::NumberAfterName { name, number } => {
                ([("name", Text(name)), ("number", Text(number)), NONE], 2)
            }
            Problem::ScientificNotation { text } => ([("text", Text(text)), NONE, NONE], 1),
            Problem::InvalidNumber { text } => ([("text", Text(text)), NONE, NONE], 1),
            Problem::NotFiniteValue { value } => ([("value", Number(*value)), NONE, NONE], 1),
            Problem::EmptyInterval { from, to } => {
                ([("from", Number(*from)), ("to", Number(*to)), NONE], 2)
            }
            Problem::PiecesDoNotJoin { previous, from } => (
                [
                    ("previous", Number(*previous)),
                    ("from", Number(*from)),
                    NONE,
                ],
                2,
            ),
            Problem::PieceCount { count, max } => {
                ([("count", Count(*count)), ("max", Count(*max)), NONE], 2)
            }
        };
        let fields = fields.get(..n).unwrap_or_default();
        let mut map = s.serialize_map(Some(head.len() + fields.len()))?;
        for (key, value) in head.iter().chain(fields) {
            map.serialize_entry(key, value)?;
        }
        map.end()
    }
}

/// A number as JavaScript's `String(x)` writes it (the crate's messages all do).
fn num(x: f64) -> String {
    crate::platform::number_text(x)
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Problem::Empty {} => f.write_str("nothing is typed; write an expression in t, such as cos(t)"),
            Problem::TooLong { length, max } => write!(f, "the expression has {length} characters; at most {max} are allowed"),
            Problem::TooDeep { max } => write!(f, "parentheses, powers and functions are nested more than {max} deep"),
            Problem::TooManyNodes { max } => write!(f, "the expression has more than {max} numbers, names and operations"),
            Problem::UnexpectedCharacter { character } => match character.as_str() {
                "," => f.write_str("\",\" is not used: write decimals with a point (2.5)"),
                "|" => f.write_str("\"|\" is not used: write abs(t)"),
                c => write!(f, "\"{c}\" is not part of the language; use numbers, t, + − * / ^ and parentheses"),
            },
            Problem::ExpectedOperand { found } if found.is_empty() => f.write_str("the expression ends where a number, a name or \"(\" is needed"),
            Problem::ExpectedOperand { found } => write!(f, "a number, a name or \"(\" is needed before \"{found}\""),
            Problem::MissingOperator { found } => write!(f, "an operator is missing before \"{found}\" (write * or + between them)"),
            Problem::UnclosedParenthesis {} => f.write_str("this \"(\" is never closed; add \")\""),
            Problem::UnmatchedParenthesis {} => f.write_str("this \")\" has no \"(\" before it"),
            Problem::UnknownName { name } => write!(f, "unknown name \"{name}\"; use t, pi, e, a function such as sin(t), or a parameter"),
            Problem::FunctionNeedsParentheses { name } => write!(f, "{name} needs parentheses: write {name}(t)"),
            Problem::FunctionPower { name } => match name.as_str() {
                "sin" | "cos" | "tan" => write!(f, "{name}^ needs a whole number ≥ 1 (sin^2(t)); the inverse is a{name}(t)"),
                _ => write!(f, "{name}^ needs a whole number ≥ 1 before the parentheses: {name}^2(t) means ({name}(t))^2"),
            },
            Problem::AmbiguousDivision { text, product, quotient } => write!(f, "\"{text}\" is ambiguous: write {product} or {quotient}"),
            Problem::NumberAfterName { name, number } => write!(f, "a number after a name: write {number}{name} or {name}^{number}"),
            Problem::ScientificNotation { text } => write!(f, "\"{text}\" is not read as a power of ten (e is Euler's number): write the decimal, such as 0.001, or a product such as 2.5*10^3"),
            Problem::InvalidNumber { text } => write!(f, "\"{text}\" is not a number"),
            Problem::InvalidParameterName { name } => write!(f, "\"{name}\" cannot be a parameter: use one letter other than t and e (a, b, ω) or a letter with a subscript (a_1)"),
            Problem::UnknownParameter { name } => write!(f, "the curve has no parameter \"{name}\""),
            Problem::NotFiniteValue { value } => write!(f, "the value is {}; it must be a finite number", num(*value)),
            Problem::EmptyInterval { from, to } => write!(f, "the interval [{}, {}] is empty; it needs from < to", num(*from), num(*to)),
            Problem::PiecesDoNotJoin { previous, from } => write!(f, "starts at {} but the previous piece ends at {}; pieces join in t", num(*from), num(*previous)),
            Problem::NotPolynomial {} => f.write_str("this piece is not a polynomial in t, so it has no Bézier form"),
            Problem::BoundUsesT {} => f.write_str("a bound is a number and cannot depend on t; write it with numbers, pi, e and parameters"),
            Problem::MissingField {} => f.write_str("this field is missing; every piece needs x, y, from and to (and z on every piece or none)"),
            Problem::PieceCount { count, max } => write!(f, "a curve needs 1 to {max} pieces, got {count}"),
        }
    }
}
