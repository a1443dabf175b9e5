//! Rendering of statistics for reports: p-values to 4 significant digits, significance stars, thousands separators, and a two-sample test in full (t, df, p, the difference with its interval, Hedges' g).
//!
//! All rounding goes through Rust's `format!`, which rounds the exact binary
//! value to nearest (ties to even) and is the same on every platform. Rounding
//! to 4 significant digits also hides the last-bit differences that platform
//! math may leave in a p-value (see [`crate::tdist`]).

/// Smallest p-value rendered as a number; anything below prints as `"< 1e-300"`.
///
/// Below about `1e-300` the incomplete beta function's `exp` underflows
/// towards subnormals and loses digits, so such values (and an exact `0`,
/// e.g. from `|r| = 1`) are reported as a bound rather than a number.
pub const P_FLOOR: f64 = 1e-300;

/// Renders a p-value with 4 significant digits in the style of the thesis's tables.
///
/// Rule, applied to the value after rounding to 4 significant digits:
/// - at least `1e-3`: fixed point, `"0.9967"`, `"0.05160"`, `"0.001234"`,
///   `"1.000"`;
/// - below `1e-3`: scientific with a two-digit exponent like MATLAB's
///   `%g`, `"3.077e-94"`, `"1.459e-44"`, `"5.517e-09"`;
/// - below [`P_FLOOR`] (including `0`): `"< 1e-300"`;
/// - NaN or outside `[0, 1]`: `"n/a"`.
pub fn p_value(p: f64) -> String {
    if !(0.0..=1.0).contains(&p) {
        return "n/a".to_owned();
    }
    if p < P_FLOOR {
        return "< 1e-300".to_owned();
    }
    let sci = format!("{p:.3e}");
    let Some((mantissa, exponent)) = sci.split_once('e') else {
        return sci;
    };
    let Ok(exponent) = exponent.parse::<i32>() else {
        return sci;
    };
    if exponent >= -3 {
        // exponent is in -3..=0 here, so 3..=6 decimals give 4 significant digits.
        let decimals = (3 - exponent) as usize;
        format!("{p:.decimals$}")
    } else {
        format!("{mantissa}e-{:02}", -exponent)
    }
}

/// Significance stars as in the thesis's tables: `"****"` for `p ≤ 0.0001`,
/// `"***"` for `p ≤ 0.001`, `"**"` for `p ≤ 0.01`, `"*"` for `p ≤ 0.05`, and
/// `""` otherwise (including NaN).
pub fn stars(p: f64) -> &'static str {
    if p <= 1e-4 {
        "****"
    } else if p <= 1e-3 {
        "***"
    } else if p <= 1e-2 {
        "**"
    } else if p <= 0.05 {
        "*"
    } else {
        ""
    }
}

/// `x` rounded to `decimals` places with commas between thousands:
/// `thousands(-151525.957, 2) == "-151,525.96"`.
///
/// The sign is the ASCII hyphen-minus, and is dropped when the rounded value
/// is zero (`thousands(-0.001, 2) == "0.00"`). NaN and infinities print as
/// `"NaN"`, `"inf"`, `"-inf"`.
pub fn thousands(x: f64, decimals: usize) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    let digits = format!("{:.decimals$}", x.abs());
    let (int_part, frac_part) = match digits.split_once('.') {
        Some((i, f)) => (i, Some(f)),
        None => (digits.as_str(), None),
    };
    let negative = x < 0.0 && digits.bytes().any(|b| (b'1'..=b'9').contains(&b));
    let mut out = String::with_capacity(digits.len() + digits.len() / 3 + 1);
    if negative {
        out.push('-');
    }
    for (i, c) in int_part.chars().enumerate() {
        if i > 0 && (int_part.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    if let Some(f) = frac_part {
        out.push('.');
        out.push_str(f);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn p_values_in_the_thesis_style() {
        // The thesis's Table 6.2 values (MATLAB, 5 digits) at 4 digits.
        let cases = [
            (3.0772e-94, "3.077e-94"),
            (1.4592e-44, "1.459e-44"),
            (0.051603, "0.05160"),
            (0.99673, "0.9967"),
            (0.62928, "0.6293"),
            (0.00014223, "1.422e-04"),
            (5.5167e-09, "5.517e-09"),
            (0.022387, "0.02239"),
            (0.001234, "0.001234"),
            (1.0, "1.000"),
            (0.99996, "1.000"),
            (0.099996, "0.1000"),
            (0.00099996, "0.001000"),
            (0.00099949, "9.995e-04"),
            (1e-300, "1.000e-300"),
            (2.923376319893952e-93, "2.923e-93"),
        ];
        for (p, s) in cases {
            assert_eq!(p_value(p), s, "p = {p:e}");
        }
    }

    #[test]
    fn p_value_edges() {
        assert_eq!(p_value(0.0), "< 1e-300");
        assert_eq!(p_value(5e-324), "< 1e-300");
        assert_eq!(p_value(f64::NAN), "n/a");
        assert_eq!(p_value(-0.1), "n/a");
        assert_eq!(p_value(1.5), "n/a");
    }

    #[test]
    fn stars_follow_the_thesis() {
        let cases = [
            (1e-94, "****"),
            (1e-4, "****"),
            (1.0001e-4, "***"),
            (1e-3, "***"),
            (0.0099, "**"),
            (0.01, "**"),
            (0.022387, "*"),
            (0.05, "*"),
            (0.050229, ""),
            (1.0, ""),
            (f64::NAN, ""),
        ];
        for (p, s) in cases {
            assert_eq!(stars(p), s, "p = {p:e}");
        }
    }

    #[test]
    fn thousands_separators() {
        let cases = [
            (-151525.957, 2, "-151,525.96"),
            (-151525.96, 2, "-151,525.96"),
            (1234567.0, 0, "1,234,567"),
            (999.999, 2, "1,000.00"),
            (999.0, 1, "999.0"),
            (100000.0, 0, "100,000"),
            (0.0, 2, "0.00"),
            (-0.001, 2, "0.00"),
            (-0.005001, 2, "-0.01"),
            (12.5, 0, "12"),
            (13.5, 0, "14"),
            (-1e15, 0, "-1,000,000,000,000,000"),
            (f64::NAN, 2, "NaN"),
            (f64::NEG_INFINITY, 2, "-inf"),
        ];
        for (x, d, s) in cases {
            assert_eq!(thousands(x, d), s, "x = {x}");
        }
    }

    proptest! {
        #[test]
        fn p_value_round_trips_to_four_digits(p in 1e-300..=1.0_f64) {
            let s = p_value(p);
            let back: f64 = s.parse().unwrap();
            prop_assert!((back - p).abs() <= 5.1e-4 * p, "{} -> {}", p, s);
        }

        #[test]
        fn p_value_round_trips_in_the_tail(e in -299.0..-3.0_f64) {
            let p = libm::pow(10.0, e);
            let back: f64 = p_value(p).parse().unwrap();
            prop_assert!((back - p).abs() <= 5.1e-4 * p);
        }

        #[test]
        fn thousands_round_trips(x in -1e12..1e12_f64, d in 0usize..4) {
            let s = thousands(x, d);
            let back: f64 = s.replace(',', "").parse().unwrap();
            prop_assert!((back - x).abs() <= 0.5 * libm::pow(10.0, -(d as f64)) + 1e-3);
            prop_assert!(!s.contains(".,") && !s.starts_with(','));
        }
    }
}

/// A two-sample test in full, as a reader checks it:
/// `"t(198) = −12.31, p = 3.077e-26, difference −17.10 [−19.84, −14.36], g = −1.74"`,
/// with the chosen variance model's test (df to two decimals for Welch),
/// the difference and its interval at the level `two` was computed with, to
/// `decimals` places; `holm`, when given, adds the Holm-adjusted p of the
/// claim's family after the raw one. Signs are the Unicode minus.
pub fn comparison(two: &crate::TwoSample, variance: crate::Variance, decimals: usize, holm: Option<f64>) -> String {
    comparison_for(two, variance, crate::Alternative::TwoSided, decimals, holm)
}

/// [`comparison`] for the test of `alternative`: a one-sided test prints its
/// one-sided p (`one-sided p = …`); the interval stays the two-sided one at
/// the level `two` was computed with.
pub fn comparison_for(
    two: &crate::TwoSample,
    variance: crate::Variance,
    alternative: crate::Alternative,
    decimals: usize,
    holm: Option<f64>,
) -> String {
    let c = two.comparison(variance);
    let df = match variance {
        crate::Variance::Pooled => format!("{}", c.df),
        crate::Variance::Welch => format!("{:.2}", c.df),
    };
    let num = |x: f64, d: usize| minus(&format!("{x:.d$}"));
    let holm = holm.map_or(String::new(), |h| format!(", Holm p = {}", p_value(h)));
    let sided = if alternative == crate::Alternative::TwoSided { "" } else { "one-sided " };
    format!(
        "t({df}) = {}, {sided}p = {}{holm}, difference {} [{}, {}], g = {}",
        num(c.t, 2),
        p_value(c.p_value(alternative)),
        num(c.difference, decimals),
        num(c.lower, decimals),
        num(c.upper, decimals),
        num(two.hedges_g, 2)
    )
}

/// `x` to `decimals` places with the Unicode minus sign for a negative
/// value (as tables write interval bounds: `−3.03`).
pub fn signed(x: f64, decimals: usize) -> String {
    format!("{x:.decimals$}").replace('-', "\u{2212}")
}

/// `s` with a leading ASCII hyphen as the Unicode minus sign, and no sign on a zero.
fn minus(s: &str) -> String {
    match s.strip_prefix('-') {
        Some(rest) if rest.bytes().any(|b| (b'1'..=b'9').contains(&b)) => format!("\u{2212}{rest}"),
        Some(rest) => rest.to_string(),
        None => s.to_string(),
    }
}

#[cfg(test)]
mod comparison_tests {
    use super::*;

    #[test]
    fn a_comparison_prints_every_figure_a_reader_needs() {
        // The crate example's samples: scipy 1.17.1 ttest_ind gives
        // t = -7.0988…, p = 1.289e-06, CI [-14.6447, -7.9553]; g = -3.04.
        let shaped = [41.0, 38.0, 45.0, 36.0, 40.0, 43.0, 39.0, 37.0, 44.0, 42.0];
        let plain = [52.0, 47.0, 55.0, 49.0, 58.0, 46.0, 51.0, 53.0, 50.0, 57.0];
        let two = crate::TwoSample::of(&shaped, &plain, 0.95).unwrap();
        assert_eq!(
            comparison(&two, crate::Variance::Pooled, 2, Some(2.578e-6)),
            "t(18) = \u{2212}7.10, p = 1.289e-06, Holm p = 2.578e-06, difference \u{2212}11.30 [\u{2212}14.64, \u{2212}7.96], g = \u{2212}3.04"
        );
        // scipy: ttest_ind(equal_var=False) df = 16.720453152064888, p = 1.9648672407042505e-06.
        assert!(
            comparison(&two, crate::Variance::Welch, 1, None)
                .starts_with("t(16.72) = \u{2212}7.10, p = 1.965e-06, difference \u{2212}11.3 [")
        );
        // scipy: ttest_ind(equal_var=False, alternative='less').pvalue = 9.824336203521252e-07.
        assert_eq!(
            comparison_for(&two, crate::Variance::Welch, crate::Alternative::Less, 2, None),
            "t(16.72) = \u{2212}7.10, one-sided p = 9.824e-07, difference \u{2212}11.30 [\u{2212}14.66, \u{2212}7.94], g = \u{2212}3.04"
        );
        assert_eq!(minus("-0.00"), "0.00");
        assert_eq!(signed(-3.034, 2), "\u{2212}3.03");
        assert_eq!(signed(10.868, 2), "10.87");
    }
}
