//! Number formatting for the table and figure renderers. P-values, stars and
//! thousands separators come from `rlfd_stats::format`, so every crate
//! writes them alike (p-values with four significant digits: `0.6293`,
//! `3.077e-94`, `1.422e-04`; `< 1e-300` below the floor; `n/a` outside
//! `[0, 1]`); this module adds what only rendering needs: plain fixed
//! decimals, the p-value split into mantissa and exponent (`× 10ⁿ` for
//! people, `\times10^{n}` for LaTeX), and full-precision numbers for CSV. Pure string work on Rust's correctly rounded
//! `{:.N}` / `{:.Ne}` formatting: no logarithm, so no platform math.

pub(crate) use rlfd_stats::format::{p_value, stars, thousands};

/// `v` with `decimals` digits after the point, ASCII minus, no grouping;
/// a negative value that rounds to zero loses its sign (`-0.00` → `0.00`).
pub(crate) fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_owned(),
        _ => s,
    }
}

/// [`p_value`]'s text, split for LaTeX.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum PValueText {
    /// `0.6293`, `0.05160`, `1.000`.
    Decimal(String),
    /// `3.077e-94` as mantissa `3.077` and exponent `-94`.
    Scientific { mantissa: String, exponent: i32 },
    /// A bound or marker: `< 1e-300`, `n/a`.
    Other(String),
}

/// Splits [`p_value`]`(p)` into its parts.
pub(crate) fn p_value_text(p: f64) -> PValueText {
    let text = p_value(p);
    if !text.starts_with(|c: char| c.is_ascii_digit()) {
        return PValueText::Other(text);
    }
    match text.split_once('e') {
        Some((mantissa, exponent)) => match exponent.parse() {
            Ok(exponent) => PValueText::Scientific { mantissa: mantissa.to_owned(), exponent },
            Err(_) => PValueText::Other(text),
        },
        None => PValueText::Decimal(text),
    }
}

/// `mantissa × 10^exponent` for people: `3.077 × 10⁻⁹⁴` (true minus sign,
/// superscript digits; no-break spaces around the `×`, so a narrow table
/// column or a printed page never breaks a number in two).
pub(crate) fn times_ten(mantissa: &str, exponent: i32) -> String {
    const SUPERSCRIPT: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut e = String::new();
    if exponent < 0 {
        e.push('⁻');
    }
    for d in exponent.unsigned_abs().to_string().bytes() {
        e.push(SUPERSCRIPT[usize::from(d - b'0')]);
    }
    format!("{}\u{a0}×\u{a0}10{e}", mantissa.replace('-', "−"))
}

/// `v` at full precision for CSV: the shortest text that parses back to the
/// same `f64` (Rust's `Display`, which never rounds), in exponent form below
/// 1e-5 and from 1e16 in magnitude so it stays short (`2.5e-90`); `0` for
/// either zero. Every CSV reader (pandas, R, ours) parses both forms.
pub(crate) fn shortest(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-5..1e16).contains(&a) { format!("{v}") } else { format!("{v:e}") }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_decimals() {
        assert_eq!(fixed(-0.001, 2), "0.00");
        assert_eq!(fixed(-0.006, 2), "-0.01");
        assert_eq!(fixed(2.665, 1), "2.7");
        assert_eq!(fixed(25725731.6, 1), "25725731.6");
    }

    #[test]
    fn p_values_split_for_latex() {
        assert_eq!(p_value_text(0.62928), PValueText::Decimal("0.6293".into()));
        assert_eq!(p_value_text(3.0772e-94), PValueText::Scientific { mantissa: "3.077".into(), exponent: -94 });
        assert_eq!(p_value_text(9.1049e-05), PValueText::Scientific { mantissa: "9.105".into(), exponent: -5 });
        assert_eq!(p_value_text(0.0), PValueText::Other("< 1e-300".into()));
        assert_eq!(p_value_text(f64::NAN), PValueText::Other("n/a".into()));
        assert_eq!(times_ten("3.077", -94), "3.077 × 10⁻⁹⁴");
        assert_eq!(times_ten("1.5", 12), "1.5 × 10¹²");
    }

    #[test]
    fn shortest_round_trips() {
        for v in [12.133333333333333, -0.1, 3.0, 2.5e-90, 1.0 / 3.0, 123456789.125, -7.25e20, 1e-5, 9.99e-6] {
            let s = shortest(v);
            assert_eq!(s.parse::<f64>().unwrap().to_bits(), v.to_bits(), "{s}");
        }
        assert_eq!(shortest(3.0), "3");
        assert_eq!(shortest(-0.0), "0");
        assert_eq!(shortest(2.5e-90), "2.5e-90");
        assert_eq!(shortest(0.1 + 0.2), "0.30000000000000004");
    }
}
