//! How Weka 3.6 seeds JRip: `Instances.getRandomNumberGenerator(seed)`
//! draws an instance with `new Random(seed).nextInt(n)`, and reseeds the
//! generator with the Java hash of that instance's text plus the seed. This
//! module reproduces the text ([`Dataset::weka_instance_text`], Weka's
//! `Instance.toStringNoWeight`) and the seeding
//! ([`JavaRandom::for_instances`]), so that [`RipperRandom::Weka`](super::RipperRandom::Weka)
//! starts from the very state Weka's JRip starts from.
//!
//! The text is the instance as Weka's ARFF loader holds it with the class as
//! the last attribute (Weka's default `-c last`): values joined by `,`,
//! a missing value as `?`, a numeric value by `Utils.doubleToString(v, 6)`
//! (rounded to 6 decimals, trailing zeros dropped), a nominal value (and the
//! class) by its name through `Utils.quote` (quoted and back-slashed when it
//! holds a space, a comma, a quote, …). A data set whose ARFF file lists the
//! class elsewhere gives Weka another text, hence other rules.
//!
//! What it is not: an ARFF writer, nor the text of Weka 3.7 and later, whose
//! `Instance.toString` formats numbers differently. One corner is not
//! reproduced bit for bit: a numeric value of magnitude 9.2·10¹² or more is
//! printed by Java's `Double.toString`, written here from the shortest
//! round-trip digits (Java ≥ 19); Java 8–18 print a few such values with one
//! more digit.
//!
//! Source: the bytecode of Weka 3.6.14 (Debian `weka` 3.6.14-3, `javap -c`):
//! `weka.core.Instances.getRandomNumberGenerator(long)`,
//! `weka.core.Instance.toStringNoWeight()` and `toString(int)`,
//! `weka.core.Utils.doubleToString(double, int)`, `quote` and
//! `backQuoteChars`; `java.lang.String.hashCode` from the Java SE
//! documentation.

use super::{AttributeKind, Dataset, JavaRandom};

impl JavaRandom {
    /// `Instances.getRandomNumberGenerator(seed)` on `data`, the generator
    /// Weka 3.6's JRip draws from with option `-S seed`: `new Random(seed)`
    /// picks instance `nextInt(data.len())`, then the generator is reseeded
    /// with `text.hashCode() + seed`, `text` being
    /// [`Dataset::weka_instance_text`].
    ///
    /// ```
    /// use rlfd_lfd::ripper::{Attribute, Dataset, JavaRandom};
    ///
    /// let data = Dataset::new(vec![Attribute::numeric("x")], vec![vec![0.5]], "c", vec!["a".into()], vec![0])?;
    /// // one instance: text "0.5,a", whose Java hash is 45_751_788
    /// assert_eq!(JavaRandom::for_instances(&data, 1), JavaRandom::new(45_751_789));
    /// # Ok::<(), rlfd_lfd::ripper::RipperError>(())
    /// ```
    pub fn for_instances(data: &Dataset, seed: i64) -> Self {
        let mut rng = Self::new(seed);
        let n = i32::try_from(data.len()).expect("Weka counts instances with a Java int");
        let picked = rng.next_int_below(n) as usize;
        let hash = java_string_hash(&data.weka_instance_text(picked));
        rng.set_seed(i64::from(hash).wrapping_add(seed));
        rng
    }
}

impl Dataset {
    /// Weka 3.6's `Instance.toStringNoWeight()` for instance `i`, the class
    /// written last (see the module docs): the text whose hash seeds JRip.
    ///
    /// ```
    /// use rlfd_lfd::ripper::{Attribute, Dataset};
    ///
    /// let colour = Attribute::nominal("colour", vec!["red".into(), "light blue".into()]);
    /// let data = Dataset::new(
    ///     vec![Attribute::numeric("x"), colour],
    ///     vec![vec![2.0 / 3.0, 1.0], vec![f64::NAN, 0.0]],
    ///     "class",
    ///     vec!["yes".into(), "no".into()],
    ///     vec![0, 1],
    /// )?;
    /// assert_eq!(data.weka_instance_text(0), "0.666667,'light blue',yes");
    /// assert_eq!(data.weka_instance_text(1), "?,red,no");
    /// # Ok::<(), rlfd_lfd::ripper::RipperError>(())
    /// ```
    ///
    /// # Panics
    /// If `i >= self.len()`.
    pub fn weka_instance_text(&self, i: usize) -> String {
        let mut text = String::new();
        for (attribute, &value) in self.attributes().iter().zip(self.row(i)) {
            if value.is_nan() {
                text.push('?');
            } else {
                match &attribute.kind {
                    AttributeKind::Numeric => text.push_str(&double_to_string_6(value)),
                    AttributeKind::Nominal { values } => text.push_str(&quote(&values[value as usize])),
                }
            }
            text.push(',');
        }
        text.push_str(&quote(&self.class_names()[self.labels()[i]]));
        text
    }
}

/// `java.lang.String.hashCode`: `s[0]·31^(n−1) + … + s[n−1]` over the UTF-16
/// code units, in wrapping 32-bit arithmetic.
pub(crate) fn java_string_hash(text: &str) -> i32 {
    text.encode_utf16().fold(0_i32, |hash, unit| hash.wrapping_mul(31).wrapping_add(i32::from(unit)))
}

/// `Utils.doubleToString(value, 6)`, step for step: scale by 10⁶, round half
/// up in magnitude, place the point, drop trailing zeros (and a bare point).
/// Beyond the range of a Java `long` it falls back to `"" + value`.
pub(crate) fn double_to_string_6(value: f64) -> String {
    const AFTER_DECIMAL_POINT: isize = 6;
    let temp = value * 1e6;
    // Java compares with (double) Long.MAX_VALUE; NaN falls through too
    if temp.is_nan() || temp.abs() >= 9.223_372_036_854_776e18 {
        return java_double_to_string(value);
    }
    // Java's (long) cast truncates toward zero, as `as` does here
    let precision: i64 = if temp > 0.0 { (temp + 0.5) as i64 } else { -((temp.abs() + 0.5) as i64) };
    let mut text: Vec<u8> = precision.to_string().into_bytes();
    let mut dot = text.len() as isize - AFTER_DECIMAL_POINT;
    while (precision < 0 && dot < 1) || dot < 0 {
        if precision < 0 {
            text.insert(1, b'0');
        } else {
            text.insert(0, b'0');
        }
        dot += 1;
    }
    let dot = dot as usize;
    text.insert(dot, b'.');
    if precision < 0 && text[1] == b'.' {
        text.insert(1, b'0');
    } else if text[0] == b'.' {
        text.insert(0, b'0');
    }
    let mut position = text.len() - 1;
    while position > dot && text[position] == b'0' {
        text[position] = b' ';
        position -= 1;
    }
    if text[position] == b'.' {
        text[position] = b' ';
    }
    String::from_utf8(text).expect("digits, signs and points are ASCII").trim().to_string()
}

/// Java's `Double.toString` for a finite value of magnitude ≥ 10⁷ (the only
/// ones [`double_to_string_6`] hands over): computerized scientific notation,
/// `d.ddd…E±n` with at least one digit after the point, from the shortest
/// round-trip digits.
fn java_double_to_string(value: f64) -> String {
    let text = format!("{value:e}");
    let (mantissa, exponent) = text.split_once('e').expect("`{:e}` writes an exponent");
    let point = if mantissa.contains('.') { "" } else { ".0" };
    format!("{mantissa}{point}E{exponent}")
}

/// `Utils.quote`: back-slash the special characters (`backQuoteChars`) and
/// enclose in single quotes when the text held one of them, or holds `{`,
/// `}`, `,` or a space, or is `?` or empty.
pub(crate) fn quote(text: &str) -> String {
    const BACK_QUOTED: [(char, &str); 8] = [
        ('\\', "\\\\"),
        ('\'', "\\'"),
        ('\t', "\\t"),
        ('\n', "\\n"),
        ('\r', "\\r"),
        ('"', "\\\""),
        ('%', "\\%"),
        ('\u{1E}', "\\u001E"),
    ];
    let mut quoted = BACK_QUOTED.iter().any(|&(c, _)| text.contains(c));
    let mut text = text.to_string();
    if quoted {
        // `backQuoteChars` replaces one character after the other, in this order
        for (c, replacement) in BACK_QUOTED {
            text = text.replace(c, replacement);
        }
    }
    quoted |= text.contains(['{', '}', ',', ' ']) || text == "?" || text.is_empty();
    if quoted { format!("'{text}'") } else { text }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Utils.doubleToString(v, 6)` as printed by Weka 3.6.14 on OpenJDK 17
    /// (`java -cp /usr/share/java/weka.jar:. WekaText`, a loop printing
    /// `Utils.doubleToString(v, 6)` for each value below).
    #[test]
    fn double_to_string_places_the_point_like_weka() {
        let cases = [
            (0.0, "0"),
            (-0.0, "0"),
            (1.0, "1"),
            (2.96, "2.96"),
            (0.5, "0.5"),
            (-0.5, "-0.5"),
            (2.0 / 3.0, "0.666667"),
            (0.000_001, "0.000001"),
            (0.000_000_4, "0"),
            (-0.000_000_4, "0"),
            (-0.000_001, "-0.000001"),
            (123_456.789, "123456.789"),
            (-42.0, "-42"),
            (1e12, "1000000000000"),
            (9.3e12, "9.3E12"),
            (1e13, "1.0E13"),
            (1.5e20, "1.5E20"),
            (-2.5e15, "-2.5E15"),
            (123_456_789_012_345.0, "1.23456789012345E14"),
        ];
        for (value, expected) in cases {
            assert_eq!(double_to_string_6(value), expected, "{value}");
        }
    }

    /// `Utils.quote` as printed by the same program.
    #[test]
    fn quote_follows_utils_quote() {
        assert_eq!(quote("red"), "red");
        assert_eq!(quote("light blue"), "'light blue'");
        assert_eq!(quote("a,b"), "'a,b'");
        assert_eq!(quote("?"), "'?'");
        assert_eq!(quote(""), "''");
        assert_eq!(quote("it's"), "'it\\'s'");
        assert_eq!(quote("50%"), "'50\\%'");
        assert_eq!(quote("a\\b"), "'a\\\\b'");
        assert_eq!(quote("{x}"), "'{x}'");
        assert_eq!(quote("tab\there"), "'tab\\there'");
    }

    #[test]
    fn string_hash_is_javas() {
        // Java: "".hashCode() == 0, "a".hashCode() == 97, "hello".hashCode() == 99162322,
        // "0.5,a".hashCode() == 45751788
        assert_eq!(java_string_hash(""), 0);
        assert_eq!(java_string_hash("a"), 97);
        assert_eq!(java_string_hash("hello"), 99_162_322);
        assert_eq!(java_string_hash("0.5,a"), 45_751_788);
    }
}
