//! The minijinja environment holding the page templates of `templates/`,
//! embedded with `include_str!`. HTML templates auto-escape (by their
//! `.html` name); the LaTeX template uses `\BLOCK{…}`, `\VAR{…}` and
//! `\#{…}` delimiters, so LaTeX's own braces and `%` need no quoting, and a
//! formatter that escapes `\ & % $ # _ { } ~ ^` in every value not marked
//! `|safe`. Undefined values are errors (strict), so a misspelt field fails
//! the tests instead of rendering as nothing.

use std::sync::OnceLock;

use minijinja::syntax::SyntaxConfig;
use minijinja::{AutoEscape, Environment, UndefinedBehavior};
use serde::Serialize;

use crate::markup::escape_latex;
use crate::{Error, Result};

const LATEX: &str = "latex";

fn environment() -> &'static Environment<'static> {
    static ENV: OnceLock<Environment<'static>> = OnceLock::new();
    ENV.get_or_init(|| {
        let mut env = Environment::new();
        env.set_undefined_behavior(UndefinedBehavior::Strict);
        env.set_auto_escape_callback(|name| {
            if name.ends_with(".tex") {
                AutoEscape::Custom(LATEX.into())
            } else {
                minijinja::default_auto_escape_callback(name)
            }
        });
        env.set_formatter(|out, state, value| {
            let latex = matches!(state.auto_escape(), AutoEscape::Custom(name) if name == LATEX);
            if latex && !value.is_safe() {
                out.write_str(&escape_latex(&value.to_string())).map_err(minijinja::Error::from)
            } else {
                minijinja::escape_formatter(out, state, value)
            }
        });
        let html_syntax = SyntaxConfig::builder()
            .trim_blocks(true)
            .lstrip_blocks(true)
            .keep_trailing_newline(true)
            .build()
            .expect("default delimiters are valid");
        env.set_syntax(html_syntax);
        for (name, source) in [
            ("style.css", include_str!("../templates/style.css")),
            ("chapter.html", include_str!("../templates/chapter.html")),
            ("index.html", include_str!("../templates/index.html")),
        ] {
            env.add_template(name, source).expect("the embedded HTML templates parse (tested)");
        }
        // The syntax applies to templates added after it is set.
        let latex_syntax = SyntaxConfig::builder()
            .block_delimiters("\\BLOCK{", "}")
            .variable_delimiters("\\VAR{", "}")
            .comment_delimiters("\\#{", "}")
            .trim_blocks(true)
            .lstrip_blocks(true)
            .keep_trailing_newline(true)
            .build()
            .expect("the LaTeX delimiters are valid");
        env.set_syntax(latex_syntax);
        for (name, source) in [
            ("preamble.tex", include_str!("../templates/preamble.tex")),
            ("chapter.tex", include_str!("../templates/chapter.tex")),
            ("body.tex", include_str!("../templates/body.tex")),
            ("report.tex", include_str!("../templates/report.tex")),
        ] {
            env.add_template(name, source).expect("the embedded LaTeX templates parse (tested)");
        }
        env
    })
}

/// Renders the embedded template `name` with `context`.
pub(crate) fn render(name: &str, context: impl Serialize) -> Result<String> {
    let template_error = |source| Error::Template { name: name.into(), source };
    environment()
        .get_template(name)
        .map_err(template_error)?
        .render(minijinja::value::Serde(context))
        .map_err(template_error)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latex_values_are_escaped_unless_safe() {
        let env = environment();
        let t = env.template_from_named_str("x.tex", r"\VAR{a} \VAR{b|safe}\BLOCK{if c} yes\BLOCK{endif}").unwrap();
        let out = t.render(minijinja::context! { a => "50% & $x_1$", b => r"\textbf{b}", c => true }).unwrap();
        assert_eq!(out, r"50\% \& \$x\_1\$ \textbf{b} yes");
    }

    #[test]
    fn undefined_is_an_error() {
        assert!(render("chapter.html", minijinja::context! { title => "x" }).is_err());
    }
}
