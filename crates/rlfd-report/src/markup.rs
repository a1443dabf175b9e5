//! Escaping for HTML and LaTeX, and the tiny inline markup of report prose:
//! `*emphasis*` and `` `code` `` (nothing else; every other character is
//! text). Used for paragraphs, captions, notes, deviations and claims.
//!
//! Numbers in prose (not in code) are set as in the tables: a hyphen before
//! a number becomes a true minus sign (`-3.5` → `−3.5`) and exponent
//! notation becomes a power of ten (`1.408e-10` → `1.408 × 10⁻¹⁰`), see
//! [`typeset`].
//!
//! LaTeX escaping covers the ten specials `\ & % $ # _ { } ~ ^`, keeps `--`
//! from becoming a dash, and maps the few non-Latin characters our prose uses
//! (`± × ≤ ≥ − λ …`) to commands, so `chapter.tex` compiles with pdflatex.

/// Escapes `& < > " '` for HTML text and attribute values.
pub(crate) fn escape_html(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// Escapes text for LaTeX's text mode.
pub(crate) fn escape_latex(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + text.len() / 4);
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => out.push_str(r"\textbackslash{}"),
            '&' | '%' | '$' | '#' | '_' | '{' | '}' => {
                out.push('\\');
                out.push(c);
            }
            '~' => out.push_str(r"\textasciitilde{}"),
            '^' => out.push_str(r"\textasciicircum{}"),
            '<' => out.push_str(r"\textless{}"),
            '>' => out.push_str(r"\textgreater{}"),
            '|' => out.push_str(r"\textbar{}"),
            // Paths (`domains/rlfd-mario/examples/…`) have no hyphenation
            // points; a break after each slash keeps them inside a column.
            '/' => out.push_str(r"/\allowbreak{}"),
            // `--` and `---` are ligatures (dashes) in LaTeX: keep hyphens apart.
            '-' if chars.peek() == Some(&'-') => out.push_str("-{}"),
            '\u{a0}' => out.push('~'),
            '—' => out.push_str("---"),
            '–' => out.push_str("--"),
            '…' => out.push_str(r"\ldots{}"),
            '“' => out.push_str("``"),
            '”' => out.push_str("''"),
            '‘' => out.push('`'),
            '’' => out.push('\''),
            c => match (math_symbol(c), text_symbol(c)) {
                (Some(cmd), _) => {
                    out.push_str(r"\ensuremath{");
                    out.push_str(cmd);
                    out.push('}');
                }
                (None, Some(cmd)) => out.push_str(cmd),
                (None, None) => out.push(c),
            },
        }
    }
    out
}

/// Text-mode commands for the accented letters and symbols of report prose
/// (pdflatex's inputenc would need a font encoding for each of them).
fn text_symbol(c: char) -> Option<&'static str> {
    Some(match c {
        'ï' => r#"\"{\i}"#,
        'ë' => r#"\"{e}"#,
        'ä' => r#"\"{a}"#,
        'ö' => r#"\"{o}"#,
        'ü' => r#"\"{u}"#,
        'é' => r"\'{e}",
        'è' => r"\`{e}",
        'á' => r"\'{a}",
        'à' => r"\`{a}",
        'ó' => r"\'{o}",
        'í' => r"\'{\i}",
        'ú' => r"\'{u}",
        'ç' => r"\c{c}",
        'ñ' => r"\~{n}",
        'Ö' => r#"\"{O}"#,
        'Ü' => r#"\"{U}"#,
        'É' => r"\'{E}",
        '²' => r"\textsuperscript{2}",
        '³' => r"\textsuperscript{3}",
        '°' => r"\textdegree{}",
        '§' => r"\S{}",
        '″' => r"''",
        '⁰' => r"\textsuperscript{0}",
        '¹' => r"\textsuperscript{1}",
        '⁴' => r"\textsuperscript{4}",
        '⁵' => r"\textsuperscript{5}",
        '⁶' => r"\textsuperscript{6}",
        '⁷' => r"\textsuperscript{7}",
        '⁸' => r"\textsuperscript{8}",
        '⁹' => r"\textsuperscript{9}",
        '⁻' => r"\textsuperscript{\ensuremath{-}}",
        _ => return None,
    })
}

/// Math-mode commands for the non-Latin characters report prose uses.
fn math_symbol(c: char) -> Option<&'static str> {
    Some(match c {
        '−' => "-",
        '±' => r"\pm",
        '×' => r"\times",
        '≤' => r"\leq",
        '≥' => r"\geq",
        '≠' => r"\neq",
        '≈' => r"\approx",
        '→' => r"\rightarrow",
        '✓' => r"\surd",
        '✗' => r"\times",
        '←' => r"\leftarrow",
        '∞' => r"\infty",
        '·' => r"\cdot",
        '₀' => r"_0",
        '₁' => r"_1",
        '₂' => r"_2",
        'α' => r"\alpha",
        'β' => r"\beta",
        'γ' => r"\gamma",
        'δ' => r"\delta",
        'ε' => r"\varepsilon",
        'θ' => r"\theta",
        'λ' => r"\lambda",
        'μ' => r"\mu",
        'π' => r"\pi",
        'σ' => r"\sigma",
        'ψ' => r"\psi",
        'ζ' => r"\zeta",
        'η' => r"\eta",
        'ι' => r"\iota",
        'κ' => r"\kappa",
        'ν' => r"\nu",
        'ξ' => r"\xi",
        'ρ' => r"\rho",
        'τ' => r"\tau",
        'φ' => r"\phi",
        'χ' => r"\chi",
        'ω' => r"\omega",
        'Γ' => r"\Gamma",
        'Θ' => r"\Theta",
        'Λ' => r"\Lambda",
        'Π' => r"\Pi",
        'Σ' => r"\Sigma",
        'Ψ' => r"\Psi",
        'Ω' => r"\Omega",
        'Δ' => r"\Delta",
        'Φ' => r"\Phi",
        '′' => r"\prime",
        '≡' => r"\equiv",
        '†' => r"\dagger",
        '∈' => r"\in",
        '∑' => r"\sum",
        '∝' => r"\propto",
        '√' => r"\surd",
        '‖' => r"\|",
        '∅' => r"\emptyset",
        '⊤' => r"\top",
        '≪' => r"\ll",
        '≫' => r"\gg",
        _ => return None,
    })
}

/// A piece of inline markup.
enum Span<'a> {
    Text(&'a str),
    Emphasis(&'a str),
    Code(&'a str),
}

/// Splits prose into text, `*emphasis*` and `` `code` `` spans. An emphasis
/// needs a closing `*`, and its content must be non-empty, hold no `*` and
/// neither start nor end with a space, so `p ≤ 0.05 (*)` or `** ≤ 0.01` stay
/// text. A backtick without a partner is text.
fn spans(text: &str) -> Vec<Span<'_>> {
    let mut out = Vec::new();
    let mut plain_start = 0;
    let mut i = 0;
    let bytes = text.as_bytes();
    while i < bytes.len() {
        let (marker, found) = match bytes[i] {
            b'`' => (b'`', text[i + 1..].find('`').map(|j| i + 1 + j)),
            b'*' => (b'*', emphasis_end(text, i)),
            _ => (0, None),
        };
        if let Some(end) = found {
            if plain_start < i {
                out.push(Span::Text(&text[plain_start..i]));
            }
            let inner = &text[i + 1..end];
            out.push(if marker == b'`' { Span::Code(inner) } else { Span::Emphasis(inner) });
            i = end + 1;
            plain_start = i;
        } else {
            i += 1;
        }
    }
    if plain_start < text.len() {
        out.push(Span::Text(&text[plain_start..]));
    }
    out
}

/// Where the `*` opening at `open` closes, if it opens an emphasis at all.
fn emphasis_end(text: &str, open: usize) -> Option<usize> {
    let rest = &text[open + 1..];
    let close = rest.find('*')?;
    let inner = &rest[..close];
    let ok = !inner.is_empty() && !inner.starts_with(char::is_whitespace) && !inner.ends_with(char::is_whitespace);
    ok.then_some(open + 1 + close)
}

/// Prose numbers as the tables write them: `-` before a digit (after a
/// space, an opening bracket, `=`, `,`, `/`, `;` or `:`, or at the start)
/// becomes `−`, and `1.408e-10` becomes `1.408 × 10⁻¹⁰`.
pub(crate) fn typeset(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len() + 8);
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let before = if i == 0 { None } else { Some(chars[i - 1]) };
        let opens = before.is_none_or(|b| b.is_whitespace() || "([=,/;:≈<>".contains(b));
        let digit_at = |k: usize| chars.get(k).is_some_and(char::is_ascii_digit);
        if c == '-' && opens && (digit_at(i + 1) || (chars.get(i + 1) == Some(&'.') && digit_at(i + 2))) {
            out.push('−');
            i += 1;
            continue;
        }
        // A number in exponent notation: digits[.digits]e[+-]digits, standing alone.
        let starts_number = c.is_ascii_digit() && before.is_none_or(|b| !(b.is_alphanumeric() || b == '.' || b == '_'));
        if starts_number {
            let mut j = i;
            while digit_at(j) {
                j += 1;
            }
            if chars.get(j) == Some(&'.') && digit_at(j + 1) {
                j += 1;
                while digit_at(j) {
                    j += 1;
                }
            }
            let mantissa_end = j;
            if chars.get(j) == Some(&'e') {
                let mut k = j + 1;
                let negative = chars.get(k) == Some(&'-');
                if matches!(chars.get(k), Some('-' | '+')) {
                    k += 1;
                }
                let exp_start = k;
                while digit_at(k) {
                    k += 1;
                }
                let alone = chars.get(k).is_none_or(|a| !(a.is_alphanumeric() || *a == '_'));
                if k > exp_start && alone {
                    let mantissa: String = chars[i..mantissa_end].iter().collect();
                    let digits: String = chars[exp_start..k].iter().collect();
                    let exponent: i32 = digits.parse().unwrap_or(0) * if negative { -1 } else { 1 };
                    out.push_str(&crate::format::times_ten(&mantissa, exponent));
                    i = k;
                    continue;
                }
            }
            out.extend(&chars[i..mantissa_end]);
            i = mantissa_end;
            continue;
        }
        out.push(c);
        i += 1;
    }
    out
}

/// Prose with inline markup as HTML.
pub(crate) fn to_html(text: &str) -> String {
    spans(text)
        .into_iter()
        .map(|s| match s {
            Span::Text(t) => escape_html(&typeset(t)),
            Span::Emphasis(t) => format!("<em>{}</em>", escape_html(&typeset(t))),
            Span::Code(t) => format!("<code>{}</code>", escape_html(t)),
        })
        .collect()
}

/// Prose with inline markup as LaTeX.
pub(crate) fn to_latex(text: &str) -> String {
    spans(text)
        .into_iter()
        .map(|s| match s {
            Span::Text(t) => escape_latex(&typeset(t)),
            Span::Emphasis(t) => format!(r"\emph{{{}}}", escape_latex(&typeset(t))),
            Span::Code(t) => code_latex(t),
        })
        .collect()
}

/// Code as LaTeX: typewriter, breakable after the punctuation of
/// identifiers and rules (`_ - . , = ( ) /`), so a long name or rule wraps
/// instead of running into the margin.
fn code_latex(code: &str) -> String {
    let mut out = String::from(r"\texttt{");
    let mut chars = code.chars().peekable();
    while let Some(c) = chars.next() {
        let next = chars.peek().copied();
        if c == '-' && next == Some('-') {
            // `--` stays one option prefix: no ligature, no break inside.
            out.push_str("-{}");
            continue;
        }
        out.push_str(&escape_latex(c.encode_utf8(&mut [0; 4])));
        if matches!(c, '_' | '-' | '.' | ',' | '=' | '(' | ')' | '/') && next.is_some() {
            out.push_str(r"\allowbreak{}");
        }
    }
    out.push('}');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latex_escapes_every_special_character() {
        assert_eq!(
            escape_latex(r"\ & % $ # _ { } ~ ^"),
            r"\textbackslash{} \& \% \$ \# \_ \{ \} \textasciitilde{} \textasciicircum{}"
        );
        assert_eq!(escape_latex("--seed"), "-{}-seed");
        assert_eq!(escape_latex("Q(λ) ± 2 ≤ 3"), r"Q(\ensuremath{\lambda}) \ensuremath{\pm} 2 \ensuremath{\leq} 3");
        assert_eq!(
            escape_latex("naïve, 16 px², 90°, §1.6"),
            r#"na\"{\i}ve, 16 px\textsuperscript{2}, 90\textdegree{}, \S{}1.6"#
        );
        assert_eq!(escape_latex("a—b"), "a---b");
        assert_eq!(escape_latex("a/b.rs"), r"a/\allowbreak{}b.rs");
    }

    #[test]
    fn prose_numbers_are_typeset() {
        assert_eq!(typeset("SIS -226030.7, p = 1.408e-10"), "SIS −226030.7, p = 1.408 × 10⁻¹⁰");
        assert_eq!(typeset("p < 1e-4 (x=-0.5) [-.5]"), "p < 1 × 10⁻⁴ (x=−0.5) [−.5]");
        // Hyphens between words or numbers, and names with an e, stay.
        assert_eq!(typeset("10-fold, C3.1-C3.5, x-dir, 2e5x, v1e-3"), "10-fold, C3.1-C3.5, x-dir, 2e5x, v1e-3");
        assert_eq!(typeset("3e5 steps"), "3 × 10⁵ steps");
        assert_eq!(to_html("`-3e5` and -3e5"), "<code>-3e5</code> and −3 × 10⁵");
        assert_eq!(
            to_latex("-1e-2"),
            r"\ensuremath{-}1~\ensuremath{\times}~10\textsuperscript{\ensuremath{-}}\textsuperscript{2}"
        );
    }

    #[test]
    fn html_escapes() {
        assert_eq!(escape_html(r#"<a href="x">&'"#), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
    }

    #[test]
    fn inline_markup() {
        assert_eq!(to_html("run *all* with `--seed 7` & see"), "run <em>all</em> with <code>--seed 7</code> &amp; see");
        assert_eq!(to_latex("run *all* with `--seed 7`"), r"run \emph{all} with \texttt{-{}-\allowbreak{}seed 7}");
        // Stars that are not emphasis stay text.
        assert_eq!(to_html("* ≤ 0.05, ** ≤ 0.01"), "* ≤ 0.05, ** ≤ 0.01");
        assert_eq!(to_html("a * b * c"), "a * b * c");
        assert_eq!(to_html("`unclosed"), "`unclosed");
        assert_eq!(to_html("*<b>*"), "<em>&lt;b&gt;</em>");
    }
}
