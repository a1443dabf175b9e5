//! Number formatting for the table and figure renderers. P-values, stars and
//! thousands separators come from `rlfd_stats::format`, so every crate
//! writes them alike (p-values with four significant digits: `0.6293`,
//! `3.077e-94`, `1.422e-04`; `< 1e-300` below the floor; `n/a` outside
//! `[0, 1]`); this module adds what only rendering needs: plain fixed
//! decimals, the p-value split into mantissa and exponent for LaTeX, and
//! scientific p-values for CSV. Pure string work on Rust's correctly rounded
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

/// A p-value in scientific notation with four significant digits, for CSV:
/// `6.293e-1`, `3.077e-94` (parseable by any CSV reader's float parser).
pub(crate) fn p_value_scientific(p: f64) -> String {
    format!("{p:.3e}")
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
        assert_eq!(p_value_scientific(0.62928), "6.293e-1");
        assert_eq!(p_value_scientific(3.0772e-94), "3.077e-94");
    }
}
