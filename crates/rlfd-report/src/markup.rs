//! Escaping for HTML and LaTeX, and the tiny inline markup of report prose:
//! `*emphasis*` and `` `code` `` (nothing else; every other character is
//! text). Used for paragraphs, captions, notes, deviations and claims.
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

/// Prose with inline markup as HTML.
pub(crate) fn to_html(text: &str) -> String {
    spans(text)
        .into_iter()
        .map(|s| match s {
            Span::Text(t) => escape_html(t),
            Span::Emphasis(t) => format!("<em>{}</em>", escape_html(t)),
            Span::Code(t) => format!("<code>{}</code>", escape_html(t)),
        })
        .collect()
}

/// Prose with inline markup as LaTeX.
pub(crate) fn to_latex(text: &str) -> String {
    spans(text)
        .into_iter()
        .map(|s| match s {
            Span::Text(t) => escape_latex(t),
            Span::Emphasis(t) => format!(r"\emph{{{}}}", escape_latex(t)),
            Span::Code(t) => format!(r"\texttt{{{}}}", escape_latex(t)),
        })
        .collect()
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
    }

    #[test]
    fn html_escapes() {
        assert_eq!(escape_html(r#"<a href="x">&'"#), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
    }

    #[test]
    fn inline_markup() {
        assert_eq!(to_html("run *all* with `--seed 7` & see"), "run <em>all</em> with <code>--seed 7</code> &amp; see");
        assert_eq!(to_latex("run *all* with `--seed 7`"), r"run \emph{all} with \texttt{-{}-seed 7}");
        // Stars that are not emphasis stay text.
        assert_eq!(to_html("* ≤ 0.05, ** ≤ 0.01"), "* ≤ 0.05, ** ≤ 0.01");
        assert_eq!(to_html("a * b * c"), "a * b * c");
        assert_eq!(to_html("`unclosed"), "`unclosed");
        assert_eq!(to_html("*<b>*"), "<em>&lt;b&gt;</em>");
    }
}
