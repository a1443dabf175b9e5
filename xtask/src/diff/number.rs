//! Cells read as numbers: `1,234.5`, `−3` (with a real minus sign), `12.3 %`,
//! `6.481e-04` are numbers; anything else (`never (thesis: 110)`, `0.25/32`,
//! an empty cell) is text. Two cells are the same when both are numbers of
//! the same kind (percent or not) whose values agree to the precision the
//! coarser of the two was written at (`12.1333` and `12.133333333333333`
//! are the same number, written with 4 and 15 decimals; `4.538e-1` and
//! `0.45379` too; whole numbers are exact), or else when their texts are
//! equal; a changed number is shown with its relative change.
//!
//! This is not a locale-aware parser: a comma is read only as a thousands
//! separator in well-formed groups (`12,345`, not `1,5`).

/// A number read from a cell: its value and whether it was written in percent.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Number {
    pub value: f64,
    pub percent: bool,
}

/// The number a cell holds, if it holds one (finite, nothing else in the cell).
pub fn parse(cell: &str) -> Option<Number> {
    let mut s = cell.trim();
    let percent = s.ends_with('%');
    if percent {
        s = s[..s.len() - 1].trim_end();
    }
    let s = s.replace('\u{2212}', "-");
    if !s.chars().any(|c| c.is_ascii_digit())
        || !s.chars().all(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '+' | '-' | ','))
    {
        return None;
    }
    let plain = if s.contains(',') { ungroup(&s)? } else { s };
    let value: f64 = plain.parse().ok()?;
    value.is_finite().then_some(Number { value, percent })
}

/// `-1,234,567.5` → `-1234567.5`; `None` unless the commas group the
/// integer part by thousands.
fn ungroup(s: &str) -> Option<String> {
    let (sign, rest) = match s.strip_prefix(['-', '+']) {
        Some(rest) => (&s[..1], rest),
        None => ("", s),
    };
    let end = rest.find(['.', 'e', 'E']).unwrap_or(rest.len());
    let (integer, tail) = rest.split_at(end);
    if tail.contains(',') {
        return None;
    }
    let groups: Vec<&str> = integer.split(',').collect();
    let first_ok = (1..=3).contains(&groups[0].len());
    let others_ok = groups[1..].iter().all(|g| g.len() == 3);
    (first_ok && others_ok).then(|| format!("{sign}{}{tail}", groups.concat()))
}

/// Half the last written digit of a number's text: `0.005` for `1.23`,
/// `0.0005` for `4.538e-1`, zero for a whole number (exact).
fn half_unit(cell: &str) -> f64 {
    let s = cell.trim().trim_end_matches('%').trim_end();
    let (mantissa, exponent) = match s.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (s, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len() as i32);
    if decimals == 0 && exponent == 0 {
        return 0.0;
    }
    0.5 * 10f64.powi(exponent - decimals)
}

/// Whether two cells say the same thing (equal as numbers at the coarser
/// one's written precision, or equal as text).
pub fn same(old: &str, new: &str) -> bool {
    match (parse(old), parse(new)) {
        (Some(a), Some(b)) if a.percent == b.percent => {
            let tolerance = half_unit(old).max(half_unit(new));
            a.value == b.value || (a.value - b.value).abs() <= tolerance * (1.0 + 1e-9)
        }
        _ => old.trim() == new.trim(),
    }
}

/// The relative change from `old` to `new` in percent of `|old|`, when both
/// cells are numbers of the same kind and `old` is not zero.
pub fn relative_change(old: &str, new: &str) -> Option<f64> {
    match (parse(old), parse(new)) {
        (Some(a), Some(b)) if a.percent == b.percent && a.value != 0.0 => {
            Some((b.value - a.value) / a.value.abs() * 100.0)
        }
        _ => None,
    }
}

/// `+7.1 %`, `-50.0 %`; small changes keep two significant digits
/// (`+0.0030 %`), so a change never shows as `+0.0 %`.
pub fn format_change(percent: f64) -> String {
    let a = percent.abs();
    let decimals = if a >= 0.05 || a == 0.0 { 1 } else { ((-a.log10()).ceil() as usize + 1).min(15) };
    format!("{percent:+.decimals$} %")
}

/// `old → new (+x.x %)` for two cells, `(empty)` for an empty one.
pub fn describe(old: &str, new: &str) -> String {
    let show = |s: &str| if s.trim().is_empty() { "(empty)".to_string() } else { s.to_string() };
    let change = match relative_change(old, new) {
        Some(p) => format!(" ({})", format_change(p)),
        None if parse(old).is_some_and(|n| n.value == 0.0) && parse(new).is_some() => " (from zero)".to_string(),
        None => String::new(),
    };
    format!("{} → {}{change}", show(old), show(new))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_agree_at_the_coarser_precision() {
        assert!(same("12.1333", "12.133333333333333"));
        assert!(same("4.538e-1", "0.45379581"));
        assert!(same("-330.00", "-330"));
        assert!(!same("12.1333", "12.1340"));
        assert!(!same("108", "108.4"), "whole numbers are exact");
        assert!(!same("4.538e-1", "0.4539"));
    }

    fn check(cell: &str, expected: Option<(f64, bool)>) {
        assert_eq!(parse(cell).map(|n| (n.value, n.percent)), expected, "{cell:?}");
    }

    #[test]
    fn numbers_in_the_forms_reports_write() {
        check("1,234.5", Some((1234.5, false)));
        check("-1,234,567", Some((-1234567.0, false)));
        check("\u{2212}3", Some((-3.0, false)));
        check("12.3 %", Some((12.3, true)));
        check("12.3%", Some((12.3, true)));
        check("6.481e-04", Some((6.481e-4, false)));
        check("+2", Some((2.0, false)));
        check(" 7 ", Some((7.0, false)));
        check("1,5", None);
        check("12,34", None);
        check("1,234.5,6", None);
        check("", None);
        check("-", None);
        check("inf", None);
        check("NaN", None);
        check("1e999", None);
        check("0.25/32", None);
        check("never (thesis: 110)", None);
        check("20,000 (paper scale)", None);
    }

    #[test]
    fn equal_as_numbers_is_the_same() {
        assert!(same("1.50", "1.5"));
        assert!(same("1,234.5", "1234.5"));
        assert!(same("\u{2212}3", "-3.0"));
        assert!(same("1e-3", "0.001"));
        assert!(same("12.3 %", "12.3%"));
        assert!(!same("12.3 %", "12.3"));
        assert!(!same("1.5", "1.6"));
        assert!(same("SIS", "SIS"));
        assert!(!same("SIS", "DIS"));
        assert!(!same("", "0"));
    }

    #[test]
    fn changes_are_described_with_their_relative_size() {
        assert_eq!(describe("-7000.0", "-6500.0"), "-7000.0 → -6500.0 (+7.1 %)");
        assert_eq!(describe("200", "100"), "200 → 100 (-50.0 %)");
        assert_eq!(describe("1,000", "1,000.03"), "1,000 → 1,000.03 (+0.0030 %)");
        assert_eq!(describe("0", "5"), "0 → 5 (from zero)");
        assert_eq!(describe("", "5"), "(empty) → 5");
        assert_eq!(describe("never", "12"), "never → 12");
        assert_eq!(describe("12 %", "12"), "12 % → 12");
    }
}
