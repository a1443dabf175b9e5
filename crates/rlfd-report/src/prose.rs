//! Report prose kept as data: a chapter's decisions and deviations
//! (`data/deviations.toml`) and the thesis's evidence beside each claim
//! (`data/evidence.toml`), embedded by the chapter with `include_str!` and
//! parsed here. Errors name the file and the entry.
//!
//! Text may hold placeholders, filled by [`fill`]:
//! - `{name}` (no dot): a value the chapter computes, passed in `values`;
//! - `{ch6.maze.demos.mean_steps}`: a published number
//!   ([`Published::number`](crate::published::Published::number)) or string
//!   (`{ch6.maze.params.alpha}` is `0.25/32`);
//! - `{ch3.table_3_2.states[small_guidance]}`: one published cell, column
//!   `states` of table `ch3.table_3_2` in the row labelled `small_guidance`
//!   ([`Published::table_value`](crate::published::Published::table_value)).
//!
//! A published number is written as Rust's `{}` does (shortest, `22` for
//! 22.0) unless a format follows a colon: `:.2` (two decimals), `:,1`
//! (thousands separators, one decimal), `:e1` (one decimal of mantissa and
//! a two-digit exponent, `5.5e-09`). A negative number gets a true minus
//! (`−`; an exponent keeps its hyphen). `{{` and `}}` are literal braces.
//!
//! The formats:
//! ```toml
//! # deviations.toml: one array of tables per list (`deviation`, or e.g. `maze`)
//! [[deviation]]
//! topic = "Reward values"
//! thesis = "Any value in [−1, 1] from a reward bar."
//! ours = "+1 for a correct action, −1 for an incorrect one."
//! why = "No magnitudes are reported."
//!
//! # evidence.toml: one table per claim id
//! ["C5.2"]
//! thesis = "Final: No Prior {ch5.table_5_1.final[No Prior]}; …"
//! ```

use std::collections::BTreeMap;

use crate::page::Deviation;
use crate::published::published;
use crate::{Error, Result};

/// A data file a chapter embeds: its path (for errors) and its text.
#[derive(Debug, Clone, Copy)]
pub struct DataFile<'a> {
    /// The path from the workspace root, e.g. `chapters/ch3-interactive-rl/data/deviations.toml`.
    pub path: &'a str,
    pub text: &'a str,
}

fn error(file: &str, entry: impl Into<String>, reason: impl Into<String>) -> Error {
    Error::DataFile { file: file.into(), entry: entry.into(), reason: reason.into() }
}

impl DataFile<'_> {
    fn error(&self, entry: impl Into<String>, reason: impl Into<String>) -> Error {
        error(self.path, entry, reason)
    }

    fn table(&self) -> Result<toml::Table> {
        toml::from_str(self.text).map_err(|e| self.error("(the file)", e.to_string()))
    }

    /// The deviations of the array of tables `list` (`deviation` in a
    /// chapter with one list), each with `topic`, `thesis`, `ours` and `why`,
    /// placeholders filled from the published numbers.
    pub fn deviations(&self, list: &str) -> Result<Vec<Deviation>> {
        let table = self.table()?;
        let rows = table.get(list).and_then(toml::Value::as_array).ok_or_else(|| self.error(list, "no such array"))?;
        let mut out = Vec::with_capacity(rows.len());
        for (i, row) in rows.iter().enumerate() {
            let entry = format!("{list}[{i}]");
            let row = row.as_table().ok_or_else(|| self.error(&entry, "is not a table"))?;
            if let Some(extra) = row.keys().find(|k| !["topic", "thesis", "ours", "why"].contains(&k.as_str())) {
                return Err(self.error(&entry, format!("unknown field `{extra}`")));
            }
            let field = |name: &str| -> Result<String> {
                let text = row
                    .get(name)
                    .and_then(toml::Value::as_str)
                    .ok_or_else(|| self.error(&entry, format!("no string field `{name}`")))?;
                fill(text, &[]).map_err(|reason| self.error(format!("{entry}.{name}"), reason))
            };
            out.push(Deviation {
                topic: field("topic")?,
                thesis: field("thesis")?,
                ours: field("ours")?,
                reason: field("why")?,
            });
        }
        Ok(out)
    }

    /// The evidence file: one table per claim id.
    pub fn evidence(&self) -> Result<Evidence> {
        let table = self.table()?;
        let mut texts = BTreeMap::new();
        for (id, entry) in table {
            let fields = entry.as_table().ok_or_else(|| self.error(&id, "is not a table"))?;
            for (field, text) in fields {
                let text = text.as_str().ok_or_else(|| self.error(format!("{id}.{field}"), "is not a string"))?;
                texts.insert((id.clone(), field.clone()), text.to_owned());
            }
        }
        Ok(Evidence { path: self.path.to_owned(), texts })
    }
}

/// The texts of an `evidence.toml`, by claim id and field.
#[derive(Debug, Clone)]
pub struct Evidence {
    path: String,
    texts: BTreeMap<(String, String), String>,
}

impl Evidence {
    /// The `thesis` text of claim `id`, placeholders filled from `values`
    /// and the published numbers.
    pub fn thesis(&self, id: &str, values: &[(&str, String)]) -> Result<String> {
        self.text(id, "thesis", values)
    }

    /// The text of `field` of claim `id`, placeholders filled.
    pub fn text(&self, id: &str, field: &str, values: &[(&str, String)]) -> Result<String> {
        let entry = format!("{id}.{field}");
        let text = self
            .texts
            .get(&(id.to_owned(), field.to_owned()))
            .ok_or_else(|| error(&self.path, &entry, "no such entry"))?;
        fill(text, values).map_err(|reason| error(&self.path, entry, reason))
    }

    /// Every `(claim id, field)` of the file.
    pub fn entries(&self) -> impl Iterator<Item = (&str, &str)> {
        self.texts.keys().map(|(id, field)| (id.as_str(), field.as_str()))
    }

    /// Checks that the file gives a `thesis` text for every claim of
    /// `claims.md`'s chapter `chapter` and for nothing else (no other claim,
    /// no other field), so a claim added to the spec or misspelt here is
    /// named, not silently left without its evidence.
    pub fn check_chapter(&self, chapter: u8) -> Result<()> {
        let want: Vec<&str> =
            published().claims().iter().filter(|c| c.chapter == chapter).map(|c| c.id.as_str()).collect();
        for id in &want {
            if !self.texts.contains_key(&((*id).to_owned(), "thesis".to_owned())) {
                return Err(error(&self.path, *id, "no `thesis` text for this claim of claims.md"));
            }
        }
        match self.entries().find(|(id, field)| !want.contains(id) || *field != "thesis") {
            Some((id, field)) => Err(error(
                &self.path,
                format!("{id}.{field}"),
                format!("not the `thesis` text of a chapter {chapter} claim of claims.md"),
            )),
            None => Ok(()),
        }
    }
}

/// Fills the placeholders of `text` (see the module docs) from `values` and
/// the published numbers; the error is a sentence naming the placeholder.
pub fn fill(text: &str, values: &[(&str, String)]) -> std::result::Result<String, String> {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find(['{', '}']) {
        out.push_str(&rest[..i]);
        let (brace, after) = (rest.as_bytes()[i], &rest[i + 1..]);
        if after.as_bytes().first() == Some(&brace) {
            out.push(char::from(brace));
            rest = &after[1..];
            continue;
        }
        if brace == b'}' {
            return Err(format!("unmatched `}}` after `{}`", &text[..text.len() - rest.len() + i]));
        }
        let end = after.find('}').ok_or_else(|| format!("unclosed `{{` in `{after}`"))?;
        out.push_str(&placeholder(&after[..end], values)?);
        rest = &after[end + 1..];
    }
    out.push_str(rest);
    Ok(out)
}

/// One placeholder's text.
fn placeholder(spec: &str, values: &[(&str, String)]) -> std::result::Result<String, String> {
    let (path, format) = spec.split_once(':').map_or((spec, None), |(p, f)| (p, Some(f)));
    if !path.contains('.') {
        if format.is_some() {
            return Err(format!("`{{{spec}}}`: a chapter's value takes no format"));
        }
        return values
            .iter()
            .find(|(name, _)| *name == path)
            .map(|(_, v)| v.clone())
            .ok_or_else(|| format!("`{{{spec}}}`: no value named `{path}` was given"));
    }
    let x = match path.split_once('[') {
        Some((column_path, row)) => {
            let row = row.strip_suffix(']').ok_or_else(|| format!("`{{{spec}}}`: `[` without `]`"))?;
            let (table, column) = column_path.rsplit_once('.').unwrap_or(("", column_path));
            published().table_value(table, column, row)
        }
        None => match published().value(path) {
            Ok(toml::Value::String(text)) if format.is_none() => return Ok(text.clone()),
            _ => published().number(path),
        },
    }
    .map_err(|e| format!("`{{{spec}}}`: {e}"))?;
    let text = number(x, format).map_err(|e| format!("`{{{spec}}}`: {e}"))?;
    Ok(text.strip_prefix('-').map_or_else(|| text.clone(), |digits| format!("−{digits}")))
}

/// A published number in a placeholder's format.
fn number(x: f64, format: Option<&str>) -> std::result::Result<String, String> {
    let digits = |s: &str| s.parse::<usize>().map_err(|_| format!("unknown format `{}`", format.unwrap_or("")));
    Ok(match format {
        None => format!("{x}"),
        Some(f) if f.starts_with('.') => format!("{x:.*}", digits(&f[1..])?),
        Some(f) if f.starts_with(',') => rlfd_stats::format::thousands(x, digits(&f[1..])?),
        Some(f) if f.starts_with('e') => {
            let sci = format!("{x:.*e}", digits(&f[1..])?);
            let (mantissa, exponent) = sci.split_once('e').unwrap_or((&sci, "0"));
            let (sign, exponent) = exponent.strip_prefix('-').map_or(("", exponent), |e| ("-", e));
            format!("{mantissa}e{sign}{exponent:0>2}")
        }
        Some(f) => return Err(format!("unknown format `{f}`")),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placeholders_fill_from_values_and_published() {
        let v = [("n", "25".to_string())];
        assert_eq!(fill("{n} trials, {ch6.maze.trials}", &v).unwrap(), "25 trials, 25");
        assert_eq!(fill("{ch3.table_3_2.states[small_guidance]}", &[]).unwrap(), "11.33");
        assert_eq!(fill("{ch3.table_3_2.states[small_no_guidance]}", &[]).unwrap(), "22");
        assert_eq!(fill("{ch3.table_3_2.cumulative_reward[small_no_guidance]}", &[]).unwrap(), "−44.67");
        assert_eq!(fill("{ch5.table_5_3.jumpstart[Subject A (20)]:.2}", &[]).unwrap(), "−0.30");
        assert_eq!(fill("{ch6.maze.table_6_1.cumulative[SIS]:,0}", &[]).unwrap(), "−93,592");
        assert_eq!(fill("{ch6.mario.table_6_4.cumulative[QLR vs DIS]:e1}", &[]).unwrap(), "5.5e-09");
        assert_eq!(fill("{ch6.maze.table_6_2.initial[SAR vs HAT]:e1}", &[]).unwrap(), "1.6e-13");
        assert_eq!(fill("{{literal}} -1", &[]).unwrap(), "{literal} -1");
        assert_eq!(fill("({ch6.maze.params.alpha})", &[]).unwrap(), "(0.25/32)");
    }

    #[test]
    fn bad_placeholders_are_named() {
        assert!(fill("{missing}", &[]).unwrap_err().contains("no value named `missing`"));
        assert!(fill("{ch6.maze.nope}", &[]).unwrap_err().contains("{ch6.maze.nope}"));
        assert!(fill("{ch6.maze.trials:x}", &[]).unwrap_err().contains("unknown format"));
        assert!(fill("open {ch6", &[]).unwrap_err().contains("unclosed"));
        assert!(fill("close }", &[]).unwrap_err().contains("unmatched"));
    }

    #[test]
    fn errors_name_the_file_and_the_entry() {
        let file = DataFile {
            path: "x/deviations.toml",
            text: "[[deviation]]\ntopic = \"t\"\nthesis = \"a\"\nours = \"b\"\n",
        };
        let err = file.deviations("deviation").unwrap_err().to_string();
        assert!(err.contains("x/deviations.toml") && err.contains("deviation[0]") && err.contains("`why`"), "{err}");
        let file = DataFile { path: "x/evidence.toml", text: "[\"C3.1\"]\nthesis = \"{nope}\"\n" };
        let err = file.evidence().unwrap().thesis("C3.1", &[]).unwrap_err().to_string();
        assert!(err.contains("x/evidence.toml") && err.contains("C3.1.thesis"), "{err}");
    }

    /// Every chapter's data files parse, and every placeholder that names a
    /// published value resolves (a chapter's own values are checked by its
    /// report's tests and the golden files).
    #[test]
    fn every_chapter_data_file_parses() {
        let chapters = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../chapters");
        let mut seen = 0;
        for dir in std::fs::read_dir(&chapters).unwrap() {
            let data = dir.unwrap().path().join("data");
            for name in ["deviations.toml", "evidence.toml"] {
                let Ok(text) = std::fs::read_to_string(data.join(name)) else { continue };
                let path = data.join(name).display().to_string();
                let file = DataFile { path: &path, text: &text };
                seen += 1;
                if name == "deviations.toml" {
                    let table = file.table().unwrap_or_else(|e| panic!("{e}"));
                    for list in table.keys() {
                        let rows = file.deviations(list).unwrap_or_else(|e| panic!("{e}"));
                        assert!(!rows.is_empty(), "{path}: `{list}` is empty");
                    }
                } else {
                    let evidence = file.evidence().unwrap_or_else(|e| panic!("{e}"));
                    for (id, field) in evidence.entries() {
                        published().claim(id).unwrap_or_else(|e| panic!("{path}: {e}"));
                        let text = &evidence.texts[&(id.to_owned(), field.to_owned())];
                        resolves_published(text).unwrap_or_else(|e| panic!("{path}: {id}.{field}: {e}"));
                    }
                }
            }
        }
        assert!(seen >= 4, "found {seen} chapter data files under {}", chapters.display());
    }

    /// Fills `text` with a stand-in for every chapter value, so only the
    /// published placeholders and the syntax are checked.
    fn resolves_published(text: &str) -> std::result::Result<String, String> {
        let names: Vec<(&str, String)> = text
            .split('{')
            .skip(1)
            .filter_map(|s| s.split_once('}').map(|(name, _)| name))
            .filter(|name| !name.contains('.') && !name.is_empty())
            .map(|name| (name, String::new()))
            .collect();
        fill(text, &names)
    }
}
