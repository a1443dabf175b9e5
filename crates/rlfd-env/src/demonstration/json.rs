//! A small JSON parser for one line of a JSON Lines demonstration file.
//!
//! It exists because numbers must reach `str::parse::<f64>` as the text the
//! file holds: `serde_json` without its `float_roundtrip` feature may read a
//! float one unit in the last place off, and with it the crate graph would
//! change for everyone. Numbers are therefore kept as text slices here.
//!
//! It is strict JSON (RFC 8259) with one addition: the tokens `NaN`,
//! `Infinity` and `-Infinity`, which Python's `json` module writes, are read
//! as numbers so the caller can reject them with a clear message instead of a
//! syntax error. It is not a general JSON library: no serializer, objects keep
//! their keys in order with duplicates (the caller rejects those), and
//! nesting is limited to [`MAX_DEPTH`] so hostile input cannot overflow the
//! stack.

/// Deeper than any demonstration line needs (3: object, states, state).
const MAX_DEPTH: usize = 32;

/// A parsed JSON value; numbers are the text of their token.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Value<'a> {
    Null,
    Bool(bool),
    Number(&'a str),
    String(String),
    Array(Vec<Value<'a>>),
    Object(Vec<(String, Value<'a>)>),
}

impl Value<'_> {
    /// The value's kind, as an error message names it ("found a string").
    pub(crate) fn kind(&self) -> &'static str {
        match self {
            Value::Null => "null",
            Value::Bool(_) => "a boolean",
            Value::Number(_) => "a number",
            Value::String(_) => "a string",
            Value::Array(_) => "an array",
            Value::Object(_) => "an object",
        }
    }
}

/// Where the text stopped being JSON: a byte offset into the line and why.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SyntaxError {
    pub(crate) offset: usize,
    pub(crate) message: &'static str,
}

impl SyntaxError {
    /// The 1-based column, counting characters, as an editor shows it.
    pub(crate) fn column(&self, text: &str) -> usize {
        let offset = self.offset.min(text.len());
        // Offsets sit on character boundaries, except inside a bad escape,
        // where the count up to the previous boundary is as good.
        text.char_indices().take_while(|&(i, _)| i < offset).count() + 1
    }
}

/// Parses one complete JSON value, with nothing but whitespace around it.
pub(crate) fn parse(text: &str) -> Result<Value<'_>, SyntaxError> {
    let mut parser = Parser { text, pos: 0 };
    parser.skip_whitespace();
    let value = parser.value(0)?;
    parser.skip_whitespace();
    if parser.pos < text.len() {
        return Err(parser.error("unexpected text after the JSON value"));
    }
    Ok(value)
}

struct Parser<'a> {
    text: &'a str,
    pos: usize,
}

impl<'a> Parser<'a> {
    fn error(&self, message: &'static str) -> SyntaxError {
        SyntaxError { offset: self.pos, message }
    }

    fn peek(&self) -> Option<u8> {
        self.text.as_bytes().get(self.pos).copied()
    }

    fn skip_whitespace(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.pos += 1;
        }
    }

    fn value(&mut self, depth: usize) -> Result<Value<'a>, SyntaxError> {
        if depth >= MAX_DEPTH {
            return Err(self.error("nesting too deep"));
        }
        match self.peek() {
            None => Err(self.error("unexpected end of line, expected a value")),
            Some(b'{') => self.object(depth),
            Some(b'[') => self.array(depth),
            Some(b'"') => Ok(Value::String(self.string()?)),
            Some(b'-' | b'0'..=b'9') => self.number(),
            Some(b'N') => self.literal("NaN", Value::Number("NaN")),
            Some(b'I') => self.literal("Infinity", Value::Number("Infinity")),
            Some(b't') => self.literal("true", Value::Bool(true)),
            Some(b'f') => self.literal("false", Value::Bool(false)),
            Some(b'n') => self.literal("null", Value::Null),
            Some(_) => Err(self.error("expected a value")),
        }
    }

    fn literal(&mut self, word: &'static str, value: Value<'a>) -> Result<Value<'a>, SyntaxError> {
        if self.text[self.pos..].starts_with(word) {
            self.pos += word.len();
            Ok(value)
        } else {
            Err(self.error("expected a value"))
        }
    }

    /// `-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`, or `-Infinity`.
    fn number(&mut self) -> Result<Value<'a>, SyntaxError> {
        let start = self.pos;
        if self.peek() == Some(b'-') {
            self.pos += 1;
            if self.text[self.pos..].starts_with("Infinity") {
                self.pos += "Infinity".len();
                return Ok(Value::Number(&self.text[start..self.pos]));
            }
        }
        match self.peek() {
            Some(b'0') => self.pos += 1,
            Some(b'1'..=b'9') => self.digits(),
            _ => return Err(self.error("invalid number")),
        }
        if self.peek() == Some(b'.') {
            self.pos += 1;
            if !matches!(self.peek(), Some(b'0'..=b'9')) {
                return Err(self.error("invalid number: expected a digit after '.'"));
            }
            self.digits();
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            self.pos += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.pos += 1;
            }
            if !matches!(self.peek(), Some(b'0'..=b'9')) {
                return Err(self.error("invalid number: expected a digit in the exponent"));
            }
            self.digits();
        }
        Ok(Value::Number(&self.text[start..self.pos]))
    }

    fn digits(&mut self) {
        while matches!(self.peek(), Some(b'0'..=b'9')) {
            self.pos += 1;
        }
    }

    fn string(&mut self) -> Result<String, SyntaxError> {
        // Skip the opening quote.
        self.pos += 1;
        let mut out = String::new();
        loop {
            let run_start = self.pos;
            while let Some(b) = self.peek() {
                if b == b'"' || b == b'\\' || b < 0x20 {
                    break;
                }
                self.pos += 1;
            }
            // The run stops at an ASCII byte or the end: a character boundary.
            out.push_str(&self.text[run_start..self.pos]);
            match self.peek() {
                None => return Err(self.error("unterminated string")),
                Some(b'"') => {
                    self.pos += 1;
                    return Ok(out);
                }
                Some(b'\\') => {
                    self.pos += 1;
                    let escaped = match self.peek() {
                        Some(b'"') => '"',
                        Some(b'\\') => '\\',
                        Some(b'/') => '/',
                        Some(b'b') => '\u{8}',
                        Some(b'f') => '\u{c}',
                        Some(b'n') => '\n',
                        Some(b'r') => '\r',
                        Some(b't') => '\t',
                        Some(b'u') => {
                            self.pos += 1;
                            out.push(self.unicode_escape()?);
                            continue;
                        }
                        _ => return Err(self.error("invalid escape in a string")),
                    };
                    self.pos += 1;
                    out.push(escaped);
                }
                Some(_) => return Err(self.error("control character in a string (escape it)")),
            }
        }
    }

    /// After `\u`: four hex digits, and a second escape for a surrogate pair.
    fn unicode_escape(&mut self) -> Result<char, SyntaxError> {
        let high = self.hex4()?;
        let code = if (0xD800..0xDC00).contains(&high) {
            if !self.text[self.pos..].starts_with("\\u") {
                return Err(self.error("unpaired surrogate in a \\u escape"));
            }
            self.pos += 2;
            let low = self.hex4()?;
            if !(0xDC00..0xE000).contains(&low) {
                return Err(self.error("unpaired surrogate in a \\u escape"));
            }
            0x10000 + ((high - 0xD800) << 10) + (low - 0xDC00)
        } else {
            high
        };
        char::from_u32(code).ok_or_else(|| self.error("unpaired surrogate in a \\u escape"))
    }

    fn hex4(&mut self) -> Result<u32, SyntaxError> {
        let digits = self
            .text
            .get(self.pos..self.pos + 4)
            .filter(|d| d.bytes().all(|b| b.is_ascii_hexdigit()))
            .ok_or_else(|| self.error("expected four hex digits after \\u"))?;
        self.pos += 4;
        // Four hex digits always fit.
        Ok(u32::from_str_radix(digits, 16).unwrap_or(0))
    }

    fn array(&mut self, depth: usize) -> Result<Value<'a>, SyntaxError> {
        self.pos += 1;
        let mut items = Vec::new();
        self.skip_whitespace();
        if self.peek() == Some(b']') {
            self.pos += 1;
            return Ok(Value::Array(items));
        }
        loop {
            self.skip_whitespace();
            items.push(self.value(depth + 1)?);
            self.skip_whitespace();
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b']') => {
                    self.pos += 1;
                    return Ok(Value::Array(items));
                }
                _ => return Err(self.error("expected ',' or ']'")),
            }
        }
    }

    fn object(&mut self, depth: usize) -> Result<Value<'a>, SyntaxError> {
        self.pos += 1;
        let mut members = Vec::new();
        self.skip_whitespace();
        if self.peek() == Some(b'}') {
            self.pos += 1;
            return Ok(Value::Object(members));
        }
        loop {
            self.skip_whitespace();
            if self.peek() != Some(b'"') {
                return Err(self.error("expected a key in double quotes"));
            }
            let key = self.string()?;
            self.skip_whitespace();
            if self.peek() != Some(b':') {
                return Err(self.error("expected ':'"));
            }
            self.pos += 1;
            self.skip_whitespace();
            let value = self.value(depth + 1)?;
            members.push((key, value));
            self.skip_whitespace();
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b'}') => {
                    self.pos += 1;
                    return Ok(Value::Object(members));
                }
                _ => return Err(self.error("expected ',' or '}'")),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(text: &str) -> (usize, &'static str) {
        let e = parse(text).unwrap_err();
        (e.column(text), e.message)
    }

    #[test]
    fn keeps_number_text_and_structure() {
        let value = parse(r#" {"states": [[0.1, -2e-300], []], "a": [true, false, null, "\u00e9\n"]} "#).unwrap();
        let expected = Value::Object(vec![
            (
                "states".into(),
                Value::Array(vec![
                    Value::Array(vec![Value::Number("0.1"), Value::Number("-2e-300")]),
                    Value::Array(vec![]),
                ]),
            ),
            (
                "a".into(),
                Value::Array(vec![Value::Bool(true), Value::Bool(false), Value::Null, Value::String("é\n".into())]),
            ),
        ]);
        assert_eq!(value, expected);
    }

    #[test]
    fn reads_python_non_finite_tokens_and_surrogate_pairs() {
        assert_eq!(
            parse("[NaN, Infinity, -Infinity]").unwrap(),
            Value::Array(vec![Value::Number("NaN"), Value::Number("Infinity"), Value::Number("-Infinity"),])
        );
        assert_eq!(parse(r#""\ud83d\ude00""#).unwrap(), Value::String("😀".into()));
    }

    #[test]
    fn reports_the_column_of_syntax_errors() {
        assert_eq!(error("[1, 2"), (6, "expected ',' or ']'"));
        assert_eq!(error("[1 2]"), (4, "expected ',' or ']'"));
        assert_eq!(error("{\"é\": 01}"), (8, "expected ',' or '}'"));
        assert_eq!(error("[1.]"), (4, "invalid number: expected a digit after '.'"));
        assert_eq!(error("[+1]"), (2, "expected a value"));
        assert_eq!(error("[1] x"), (5, "unexpected text after the JSON value"));
        assert_eq!(error("{states: 1}"), (2, "expected a key in double quotes"));
        assert_eq!(error("\"abc"), (5, "unterminated string"));
        assert_eq!(error(r#""\x""#), (3, "invalid escape in a string"));
        assert_eq!(error(r#""\ud800""#), (8, "unpaired surrogate in a \\u escape"));
        assert_eq!(error(""), (1, "unexpected end of line, expected a value"));
        let deep = "[".repeat(100);
        assert_eq!(error(&deep), (33, "nesting too deep"));
    }
}
