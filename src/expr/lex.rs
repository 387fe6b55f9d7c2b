//! The lexer: typed text cut into tokens, each with the characters it came from.
//!
//! Spans count UTF-16 code units (what JavaScript counts): `π` is one unit, a character outside
//! the Basic Multilingual Plane two. Whitespace separates tokens and is remembered on the token
//! after it (`spaced`), because `t2` and `t 2` are refused differently and `e^2t` is ambiguous
//! where `e^2 t` is not.
//!
//! A run of letters is split here: a letter followed by `_` and `[A-Za-z0-9]+` is one name
//! (`a_1`, `a_max`); the other letters split by longest match into the function names and `pi`,
//! and single letters otherwise (`pit` = `pi` `t`, `sint` = `sin` `t`, `at` = `a` `t`).
//!
//! The lexer never fails: a character the language does not use, a malformed number (`1.2.3`)
//! or one that overflows to infinity ends the list as a [`Kind::Bad`] token, which the parser
//! reports when it reaches it (so the first problem in reading order is the one reported).

use super::ast::{Constant, Func, Span};
use super::error::{ExprError, Problem};
use super::rational::Rational;

/// What a name token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Word {
    /// The curve parameter `t`.
    T,
    /// `pi`, `π` or `e`.
    Constant(Constant),
    /// A function name: `sin`.
    Func(Func),
    /// A parameter-shaped name (one letter other than `t`, `e`, `π`, or a letter with a
    /// subscript); the token's text is the name.
    Letter,
}

/// Why a [`Kind::Bad`] token is bad.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
    /// A character the language does not use (`#`, `,`, `|`, a lone `_`).
    Character,
    /// Digits and points that are not a number: `1.2.3`, `.`.
    Number,
    /// A number whose nearest f64 is infinite (more than 308 digits).
    Infinite,
}

/// What a token is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A number: its correctly rounded f64 (its exact value is [`exact_decimal`] of the
    /// token's text, read by the parser where it builds the node: a token stays small).
    Number {
        /// The nearest f64 (`str::parse`).
        value: f64,
    },
    /// A name.
    Name(Word),
    /// `+`
    Plus,
    /// `-` or `−` (U+2212)
    Minus,
    /// `*`, `·`, `×` or `⋅`
    Times,
    /// `/` or `÷`
    Divide,
    /// `^` or `**`
    Power,
    /// `(`
    Open,
    /// `)`
    Close,
    /// The end of the text.
    End,
    /// Something the language refuses; always the last token.
    Bad(Fault),
}

/// One token: its kind, its text as typed, its span in UTF-16 code units, and whether
/// whitespace came right before it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Token<'a> {
    /// What it is.
    pub kind: Kind,
    /// The characters as typed (`""` for [`Kind::End`]).
    pub text: &'a str,
    /// Where, in UTF-16 code units.
    pub span: Span,
    /// Whitespace directly before it.
    pub spaced: bool,
}

impl Token<'_> {
    /// The error a [`Kind::Bad`] token stands for, at its span.
    pub fn problem(&self) -> Option<ExprError> {
        let problem = match self.kind {
            Kind::Bad(Fault::Character) => Problem::UnexpectedCharacter {
                character: self.text.to_string(),
            },
            Kind::Bad(Fault::Number) => Problem::InvalidNumber {
                text: self.text.to_string(),
            },
            Kind::Bad(Fault::Infinite) => Problem::NotFiniteValue {
                value: f64::INFINITY,
            },
            _ => return None,
        };
        Some(ExprError::at(self.span.start, self.span.end, problem))
    }
}

/// A letter of a name: ASCII `A`–`Z`, `a`–`z`, or Greek `Α`–`Ω`, `α`–`ω` (U+0391–U+03A9,
/// U+03B1–U+03C9; `π` among them, read as the constant).
pub fn is_letter(c: char) -> bool {
    c.is_ascii_alphabetic()
        || (('\u{391}'..='\u{3A9}').contains(&c) && c != '\u{3A2}')
        || ('\u{3B1}'..='\u{3C9}').contains(&c)
}

/// A character of a subscript: `[A-Za-z0-9]`.
pub fn is_subscript(c: char) -> bool {
    c.is_ascii_alphanumeric()
}

/// The exact value of a decimal `digits[.digits]` as a fraction n / 10^k (trailing zeros after
/// the point dropped first); `None` when it does not fit an i128.
pub fn exact_decimal(text: &str) -> Option<Rational> {
    let (whole, fraction) = text.split_once('.').unwrap_or((text, ""));
    let fraction = fraction.trim_end_matches('0');
    let mut n: i128 = 0;
    for c in whole.chars().chain(fraction.chars()) {
        let digit = i128::from(c.to_digit(10)?);
        n = n.checked_mul(10)?.checked_add(digit)?;
    }
    let places = u32::try_from(fraction.len()).ok()?;
    Rational::new(n, 10i128.checked_pow(places)?)
}

/// The kind of a run of digits and points.
fn number(text: &str) -> Kind {
    let points = text.chars().filter(|&c| c == '.').count();
    if points > 1 || points == text.len() {
        return Kind::Bad(Fault::Number);
    }
    let value = crate::platform::parse_decimal(text);
    if value.is_finite() {
        Kind::Number { value }
    } else if value.is_nan() {
        Kind::Bad(Fault::Number)
    } else {
        Kind::Bad(Fault::Infinite)
    }
}

/// The words a run of letters is split into besides single letters.
#[inline(never)]
fn word(text: &str) -> Option<Word> {
    if text == "pi" {
        return Some(Word::Constant(Constant::Pi));
    }
    Func::from_name(text).map(Word::Func)
}

/// A single letter as a word.
fn letter(c: char) -> Word {
    match c {
        't' => Word::T,
        'e' => Word::Constant(Constant::E),
        'π' => Word::Constant(Constant::Pi),
        _ => Word::Letter,
    }
}

/// The lexer's state: the characters with their byte and UTF-16 offsets.
struct Lexer<'a> {
    text: &'a str,
    /// (byte offset, UTF-16 offset, character).
    chars: Vec<(usize, usize, char)>,
    /// UTF-16 length of the text.
    units: usize,
    tokens: Vec<Token<'a>>,
    spaced: bool,
}

impl<'a> Lexer<'a> {
    /// Byte and UTF-16 offsets of character `i` (the end of the text past the last).
    fn at(&self, i: usize) -> (usize, usize) {
        match self.chars.get(i) {
            Some(&(byte, unit, _)) => (byte, unit),
            None => (self.text.len(), self.units),
        }
    }

    fn char(&self, i: usize) -> Option<char> {
        self.chars.get(i).map(|&(_, _, c)| c)
    }

    /// Push a token made of characters `from..to`.
    fn push(&mut self, kind: Kind, from: usize, to: usize) {
        let ((b0, u0), (b1, u1)) = (self.at(from), self.at(to));
        self.tokens.push(Token {
            kind,
            text: self.text.get(b0..b1).unwrap_or(""),
            span: Span::new(u0, u1),
            spaced: self.spaced,
        });
        self.spaced = false;
    }

    /// Split the run of letters starting at character `i`; returns the index after it.
    fn letters(&mut self, i: usize) -> usize {
        // (first char, end char, has a subscript) per letter.
        let mut units: Vec<(usize, usize, bool)> = Vec::new();
        let mut j = i;
        while self.char(j).is_some_and(is_letter) {
            let start = j;
            j += 1;
            let sub = self.char(j) == Some('_') && self.char(j + 1).is_some_and(is_subscript);
            if sub {
                j += 1;
                while self.char(j).is_some_and(is_subscript) {
                    j += 1;
                }
            }
            units.push((start, j, sub));
        }
        let mut k = 0;
        while let Some(&(start, end, sub)) = units.get(k) {
            // The longest word over plain letters k..k+n (words are 2 to 5 letters).
            let mut best = None;
            for n in 2..=5 {
                let Some(plain) = units.get(k..k + n) else {
                    break;
                };
                if plain.iter().any(|u| u.2) {
                    break;
                }
                let (b0, _) = self.at(start);
                let (b1, _) = self.at(plain.last().map_or(end, |u| u.1));
                if let Some(w) = self.text.get(b0..b1).and_then(word) {
                    best = Some((w, n));
                }
            }
            match best {
                Some((w, n)) => {
                    let last = units.get(k + n - 1).map_or(end, |u| u.1);
                    self.push(Kind::Name(w), start, last);
                    k += n;
                }
                None => {
                    let w = match (sub, self.char(start)) {
                        (false, Some(c)) => letter(c),
                        _ => Word::Letter,
                    };
                    self.push(Kind::Name(w), start, end);
                    k += 1;
                }
            }
        }
        j
    }

    fn run(&mut self) {
        let mut i = 0;
        while let Some(c) = self.char(i) {
            if c.is_whitespace() {
                self.spaced = true;
                i += 1;
                continue;
            }
            if is_letter(c) {
                i = self.letters(i);
                continue;
            }
            let (kind, len) = match c {
                '0'..='9' | '.' => {
                    let mut j = i;
                    while self.char(j).is_some_and(|c| c.is_ascii_digit() || c == '.') {
                        j += 1;
                    }
                    let ((b0, _), (b1, _)) = (self.at(i), self.at(j));
                    (number(self.text.get(b0..b1).unwrap_or(".")), j - i)
                }
                '+' => (Kind::Plus, 1),
                '-' | '−' => (Kind::Minus, 1),
                '*' if self.char(i + 1) == Some('*') => (Kind::Power, 2),
                '*' | '·' | '×' | '⋅' => (Kind::Times, 1),
                '/' | '÷' => (Kind::Divide, 1),
                '^' => (Kind::Power, 1),
                '(' => (Kind::Open, 1),
                ')' => (Kind::Close, 1),
                _ => (Kind::Bad(Fault::Character), 1),
            };
            self.push(kind, i, i + len);
            if matches!(kind, Kind::Bad(_)) {
                return;
            }
            i += len;
        }
        let n = self.chars.len();
        self.push(Kind::End, n, n);
    }
}

/// The tokens of `text`, ending with [`Kind::End`] or with the first [`Kind::Bad`] token.
pub fn lex(text: &str) -> Vec<Token<'_>> {
    let mut unit = 0;
    let chars = text
        .char_indices()
        .map(|(byte, c)| {
            let at = (byte, unit, c);
            unit += c.len_utf16();
            at
        })
        .collect();
    let mut lexer = Lexer {
        text,
        chars,
        units: unit,
        tokens: Vec::new(),
        spaced: false,
    };
    lexer.run();
    lexer.tokens
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    /// A token's text and span.
    type Piece<'a> = (&'a str, usize, usize);

    /// (text, span) of every token.
    fn pieces(text: &str) -> Vec<Piece<'_>> {
        lex(text)
            .iter()
            .map(|t| (t.text, t.span.start, t.span.end))
            .collect()
    }

    fn kinds(text: &str) -> Vec<Kind> {
        lex(text).iter().map(|t| t.kind).collect()
    }

    #[test]
    fn tokens_carry_utf16_spans_and_the_whitespace_before_them() {
        let tokens = lex("2·t − π**2");
        let want = [
            ("2", 0, 1, false),
            ("·", 1, 2, false),
            ("t", 2, 3, false),
            ("−", 4, 5, true),
            ("π", 6, 7, true),
            ("**", 7, 9, false),
            ("2", 9, 10, false),
            ("", 10, 10, false),
        ];
        let got: Vec<_> = tokens
            .iter()
            .map(|t| (t.text, t.span.start, t.span.end, t.spaced))
            .collect();
        assert_eq!(got, want);
        let two = Kind::Number { value: 2.0 };
        assert_eq!(exact_decimal("2"), Some(Rational::integer(2)));
        let pi = Kind::Name(Word::Constant(Constant::Pi));
        let want = [
            two,
            Kind::Times,
            Kind::Name(Word::T),
            Kind::Minus,
            pi,
            Kind::Power,
            two,
            Kind::End,
        ];
        assert_eq!(kinds("2·t − π**2"), want);
        assert_eq!(
            kinds("×⋅÷^()+")[..7],
            [
                Kind::Times,
                Kind::Times,
                Kind::Divide,
                Kind::Power,
                Kind::Open,
                Kind::Close,
                Kind::Plus
            ]
        );
    }

    #[test]
    fn letter_runs_split_by_longest_match_and_subscripts() {
        let end = |n: usize| ("", n, n);
        let cases: [(&str, &[Piece]); 8] = [
            (
                "sinhasinpit",
                &[
                    ("sinh", 0, 4),
                    ("asin", 4, 8),
                    ("pi", 8, 10),
                    ("t", 10, 11),
                    end(11),
                ],
            ),
            ("expe", &[("exp", 0, 3), ("e", 3, 4), end(4)]),
            ("tana", &[("tan", 0, 3), ("a", 3, 4), end(4)]),
            ("signt", &[("sign", 0, 4), ("t", 4, 5), end(5)]),
            ("pi_1", &[("p", 0, 1), ("i_1", 1, 4), end(4)]),
            ("ba_max2", &[("b", 0, 1), ("a_max2", 1, 7), end(7)]),
            ("ωα_0", &[("ω", 0, 1), ("α_0", 1, 4), end(4)]),
            ("a_ t", &[("a", 0, 1), ("_", 1, 2)]),
        ];
        for (text, want) in cases {
            assert_eq!(pieces(text), want, "{text:?}");
        }
        let words = kinds("sinhpite");
        let want = [
            Kind::Name(Word::Func(Func::Sinh)),
            Kind::Name(Word::Constant(Constant::Pi)),
            Kind::Name(Word::T),
            Kind::Name(Word::Constant(Constant::E)),
            Kind::End,
        ];
        assert_eq!(words, want);
        assert_eq!(
            kinds("Ωt_1")[..2],
            [Kind::Name(Word::Letter), Kind::Name(Word::Letter)]
        );
    }

    #[test]
    fn the_first_bad_character_or_number_ends_the_tokens() {
        let bad = |f| Kind::Bad(f);
        assert_eq!(pieces("1 # 2"), [("1", 0, 1), ("#", 2, 3)]);
        assert_eq!(kinds("1 # 2")[1], bad(Fault::Character));
        assert_eq!(pieces("😀t"), [("😀", 0, 2)]);
        assert_eq!(kinds("1.2.3 t"), [bad(Fault::Number)]);
        assert_eq!(kinds("."), [bad(Fault::Number)]);
        assert_eq!(kinds(&"9".repeat(400)), [bad(Fault::Infinite)]);
        // The largest finite literal is still a number.
        let max = format!("{}", f64::MAX);
        assert!(matches!(kinds(&max)[0], Kind::Number { value } if value == f64::MAX));
        assert_eq!(exact_decimal(&max), None);
        assert_eq!(kinds("ϖ"), [bad(Fault::Character)]);
        let problem = lex("t,5")[1].problem().map(|e| (e.problem, e.start, e.end));
        let comma = Problem::UnexpectedCharacter {
            character: ",".into(),
        };
        assert_eq!(problem, Some((comma, 1, 2)));
        assert_eq!(lex("t")[0].problem(), None);
    }
}
