//! Numbers in demonstration files, shared by both formats: writing an `f64` so
//! that `str::parse::<f64>` reads back the same bits, and reading a cell's
//! text into a state value, a counter (`trajectory`, `step`) or an action,
//! with the checks and error kinds both formats report.
//!
//! Not a general number parser: it accepts what `str::parse::<f64>` accepts
//! (`1`, `-0.5`, `.5`, `1e-300`, `+2`) and nothing locale-specific (`1,5`).

use std::fmt::Write as _;

use super::error::ReadErrorKind;

/// Appends `x` in the shortest form that reads back to the same bits.
///
/// Rust prints the shortest digits that round-trip with both `{}` and `{:?}`;
/// `{:?}` is used because it switches to exponent notation outside
/// `1e-4..1e16` (`1e-300` rather than 302 characters of zeros). Its `.0` on
/// whole numbers is dropped (`1`, `-0`) to keep discrete state variables
/// short. Only finite values reach here: sets reject the others.
pub(crate) fn push_f64(out: &mut String, x: f64) {
    let start = out.len();
    // Writing to a `String` cannot fail.
    let _ = write!(out, "{x:?}");
    if out[start..].ends_with(".0") {
        out.truncate(out.len() - 2);
    }
}

/// Reads a state value: any finite `f64`.
pub(crate) fn parse_value(text: &str, field: impl FnOnce() -> String) -> Result<f64, ReadErrorKind> {
    if text.is_empty() {
        return Err(ReadErrorKind::MissingValue { field: field() });
    }
    match text.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) if names_non_finite(text) => Err(ReadErrorKind::NotFinite { field: field(), text: text.to_owned() }),
        Ok(_) => Err(ReadErrorKind::TooLarge { field: field(), text: text.to_owned() }),
        Err(_) => Err(ReadErrorKind::NotANumber { field: field(), text: text.to_owned() }),
    }
}

/// Whether `text` spells NaN or an infinity (as `str::parse` and Python's
/// `json` module write them), rather than a literal too large for `f64`.
fn names_non_finite(text: &str) -> bool {
    let unsigned = text.trim_start_matches(['+', '-']).to_ascii_lowercase();
    matches!(unsigned.as_str(), "nan" | "inf" | "infinity")
}

/// Reads a `trajectory` or `step` counter: digits only, no fraction.
pub(crate) fn parse_counter(text: &str, field: &str) -> Result<usize, ReadErrorKind> {
    if text.is_empty() {
        return Err(ReadErrorKind::MissingValue { field: field.to_owned() });
    }
    text.parse::<usize>().map_err(|_| ReadErrorKind::NotAnInteger { field: field.to_owned(), text: text.to_owned() })
}

/// Largest action read through `f64` (`3.0`): above 2^53 not every whole
/// number is representable, so `9007199254740993.0` would silently change.
const MAX_FLOAT_ACTION: f64 = 9_007_199_254_740_992.0;

/// Reads an action index. `3` and `3.0` both read as 3, because spreadsheet
/// and data-frame tools write whole numbers as floats once a column has an
/// empty cell (the last state's action). With `num_actions` known, the action
/// must be below it.
pub(crate) fn parse_action(
    text: &str,
    num_actions: Option<usize>,
    field: impl Fn() -> String,
) -> Result<usize, ReadErrorKind> {
    let action = match text.parse::<usize>() {
        Ok(action) => action,
        Err(_) => {
            let x = parse_value(text, String::new).map_err(|kind| with_field(kind, &field))?;
            if x < 0.0 {
                return Err(ReadErrorKind::NegativeAction { field: field(), text: text.to_owned() });
            }
            if x.fract() != 0.0 {
                return Err(ReadErrorKind::FractionalAction { field: field(), text: text.to_owned() });
            }
            if x > MAX_FLOAT_ACTION {
                return Err(match num_actions {
                    Some(num_actions) => {
                        ReadErrorKind::ActionOutOfRange { field: field(), text: text.to_owned(), num_actions }
                    }
                    None => ReadErrorKind::ActionTooLarge { field: field(), text: text.to_owned() },
                });
            }
            // Whole, non-negative and at most 2^53: exact as an integer.
            x as usize
        }
    };
    match num_actions {
        Some(num_actions) if action >= num_actions => {
            Err(ReadErrorKind::ActionOutOfRange { field: field(), text: text.to_owned(), num_actions })
        }
        // The same bound for integers as for floats: the readers infer the
        // count as the largest action + 1, which must not overflow.
        None if action > MAX_FLOAT_ACTION as usize => {
            Err(ReadErrorKind::ActionTooLarge { field: field(), text: text.to_owned() })
        }
        _ => Ok(action),
    }
}

/// Fills in the field name of a value error raised with a placeholder, so the
/// field name is only built when there is an error.
fn with_field(kind: ReadErrorKind, field: impl FnOnce() -> String) -> ReadErrorKind {
    match kind {
        ReadErrorKind::MissingValue { .. } => ReadErrorKind::MissingValue { field: field() },
        ReadErrorKind::NotANumber { text, .. } => ReadErrorKind::NotANumber { field: field(), text },
        ReadErrorKind::NotFinite { text, .. } => ReadErrorKind::NotFinite { field: field(), text },
        ReadErrorKind::TooLarge { text, .. } => ReadErrorKind::TooLarge { field: field(), text },
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn written(x: f64) -> String {
        let mut out = String::new();
        push_f64(&mut out, x);
        out
    }

    #[test]
    fn writes_short_forms_that_read_back_exactly() {
        let cases = [
            (0.1 + 0.2, "0.30000000000000004"),
            (1e-300, "1e-300"),
            (-0.0, "-0"),
            (0.0, "0"),
            (1.0, "1"),
            (-1.0, "-1"),
            (100.0, "100"),
            (0.08, "0.08"),
            (1e16, "1e16"),
            (1.5e16, "1.5e16"),
            (123_456_789_012_345.0, "123456789012345"),
            (5e-324, "5e-324"),
            (f64::MAX, "1.7976931348623157e308"),
        ];
        for (x, text) in cases {
            assert_eq!(written(x), text);
            assert_eq!(text.parse::<f64>().map(f64::to_bits), Ok(x.to_bits()), "{text}");
        }
    }

    #[test]
    fn values_distinguish_missing_garbage_non_finite_and_overflow() {
        let field = || "x".to_owned();
        assert_eq!(parse_value("-0.5", field).ok(), Some(-0.5));
        let message = |text: &str| parse_value(text, field).unwrap_err().to_string();
        assert_eq!(message(""), "field \"x\": the value is missing");
        assert_eq!(message("abc"), "field \"x\": \"abc\" is not a number");
        assert_eq!(message("1,5"), "field \"x\": \"1,5\" is not a number");
        assert_eq!(message("NaN"), "field \"x\": NaN is not allowed");
        assert_eq!(message("-inf"), "field \"x\": -inf is not allowed");
        assert_eq!(message("Infinity"), "field \"x\": Infinity is not allowed");
        assert_eq!(message("1e400"), "field \"x\": 1e400 is too large for a 64-bit float");
    }

    #[test]
    fn actions_accept_whole_floats_and_reject_the_rest() {
        let field = || "action".to_owned();
        assert_eq!(parse_action("3", Some(4), field).ok(), Some(3));
        assert_eq!(parse_action("3.0", Some(4), field).ok(), Some(3));
        assert_eq!(parse_action("-0", None, field).ok(), Some(0));
        assert_eq!(parse_action("1e3", None, field).ok(), Some(1000));
        let message = |text: &str, n| parse_action(text, n, field).unwrap_err().to_string();
        assert_eq!(message("7", Some(4)), "field \"action\": 7 is out of range 0..4");
        assert_eq!(message("4.0", Some(4)), "field \"action\": 4.0 is out of range 0..4");
        assert_eq!(message("1e30", Some(4)), "field \"action\": 1e30 is out of range 0..4");
        assert_eq!(message("1e30", None), "field \"action\": 1e30 is too large to be an action");
        // Found by fuzzing: usize::MAX read as an integer made the inferred
        // count (largest + 1) overflow to 0.
        assert_eq!(
            message("18446744073709551615", None),
            "field \"action\": 18446744073709551615 is too large to be an action"
        );
        assert_eq!(parse_action("9007199254740992", None, field).ok(), Some(9_007_199_254_740_992));
        assert_eq!(
            message("9007199254740993", None),
            "field \"action\": 9007199254740993 is too large to be an action"
        );
        assert_eq!(
            parse_action("18446744073709551615", Some(4), field).unwrap_err().to_string(),
            "field \"action\": 18446744073709551615 is out of range 0..4"
        );
        assert_eq!(message("-1", Some(4)), "field \"action\": -1 is negative (actions are numbered from 0)");
        assert_eq!(
            message("1.5", Some(4)),
            "field \"action\": 1.5 is not a whole number (actions are numbered from 0)"
        );
        assert_eq!(message("up", Some(4)), "field \"action\": \"up\" is not a number");
        assert_eq!(message("nan", Some(4)), "field \"action\": nan is not allowed");
    }

    #[test]
    fn counters_are_plain_integers() {
        assert_eq!(parse_counter("12", "step").ok(), Some(12));
        assert_eq!(
            parse_counter("1.0", "step").unwrap_err().to_string(),
            "field \"step\": \"1.0\" is not a non-negative integer"
        );
        assert_eq!(
            parse_counter("-1", "trajectory").unwrap_err().to_string(),
            "field \"trajectory\": \"-1\" is not a non-negative integer"
        );
    }
}
