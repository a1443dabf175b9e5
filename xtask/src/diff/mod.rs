//! `diff`: compares two report trees by meaning, for reviewers of generated
//! reports. In order of importance it finds the claims whose verdict changed
//! ([`claims`]), the table cells whose value changed ([`tables`], every CSV
//! or TSV the trees share, numbers compared as numbers by [`number`]), the
//! figures whose drawing changed (with the CSV behind each, by name), the
//! files added or removed, and last the other files (pages) whose text
//! changed. Provenance lines and `run.json` never count ([`tree`]).
//!
//! The exit code says whether the trees agree: 0 when they do, 1 when they
//! differ (not an error: no `error:` line), 2 on bad input (a missing
//! directory or one that is not a report tree), as one line on stderr.

mod claims;
mod number;
mod render;
mod tables;
mod tree;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};

use tree::Tree;

/// How the differences are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// For a terminal.
    Text,
    /// For a pull-request comment: headings and tables.
    Markdown,
}

impl std::str::FromStr for Format {
    type Err = String;
    fn from_str(s: &str) -> Result<Format, String> {
        match s {
            "text" => Ok(Format::Text),
            "markdown" => Ok(Format::Markdown),
            other => Err(format!("unknown format \"{other}\" (expected text or markdown)")),
        }
    }
}

/// The settings of `cargo xtask diff`.
#[derive(Clone, Debug)]
pub struct Options {
    pub old: PathBuf,
    pub new: PathBuf,
    pub format: Format,
    /// Changes shown per table (the rest are counted); 0 shows all.
    pub limit: usize,
}

/// The changes of one table file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TableChanges {
    pub path: String,
    pub changes: Vec<tables::Change>,
}

/// A figure whose drawing changed, and the data files named after it
/// (each with whether it changed too).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FigureChange {
    pub path: String,
    pub data: Vec<(String, bool)>,
}

/// Another shared file whose text changed: lines only in the old and only in the new.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileChange {
    pub path: String,
    pub removed: usize,
    pub added: usize,
    /// Why it is here rather than in a section above (e.g. a CSV that does not parse).
    pub note: Option<String>,
}

/// Everything that differs between two trees.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Differences {
    pub old: String,
    pub new: String,
    pub old_provenance: Option<String>,
    pub new_provenance: Option<String>,
    /// Files present in both trees.
    pub shared: usize,
    pub claims: claims::ClaimChanges,
    pub tables: Vec<TableChanges>,
    pub figures: Vec<FigureChange>,
    pub added: Vec<String>,
    pub removed: Vec<String>,
    pub others: Vec<FileChange>,
}

impl Differences {
    /// Whether the trees agree.
    pub fn agree(&self) -> bool {
        self.claims.verdicts.is_empty()
            && self.claims.evidence.is_empty()
            && self.tables.is_empty()
            && self.figures.is_empty()
            && self.added.is_empty()
            && self.removed.is_empty()
            && self.others.is_empty()
    }
}

/// Runs `cargo xtask diff`: prints the differences and returns the exit code.
pub fn run(options: &Options) -> ExitCode {
    match compare_dirs(&options.old, &options.new) {
        Ok(d) => {
            print!("{}", render::render(&d, options.format, options.limit));
            if d.agree() { ExitCode::SUCCESS } else { ExitCode::from(1) }
        }
        Err(e) => {
            let msg = format!("{e:#}").replace('\n', " ");
            eprintln!("error: {msg}");
            ExitCode::from(2)
        }
    }
}

/// Loads and compares the trees at two paths.
pub fn compare_dirs(old: &Path, new: &Path) -> Result<Differences> {
    let (a, b) = (Tree::load(old)?, Tree::load(new)?);
    compare(&a, &b)
}

fn extension(path: &str) -> &str {
    path.rsplit_once('.').map_or("", |(_, e)| e)
}

/// The data files of `tree` named after the figure at `svg`: in its
/// directory, `<stem>.csv`, `<stem>_*.csv`, or without the `figure_` prefix
/// (`figure_mario_dis_beta.svg` → `mario_dis_beta.csv`).
fn figure_data<'a>(svg: &str, trees: [&'a Tree; 2]) -> Vec<&'a str> {
    let (dir, file) = svg.rsplit_once('/').unwrap_or(("", svg));
    let stem = file.trim_end_matches(".svg");
    let bare = stem.strip_prefix("figure_");
    let mut found: Vec<&str> = trees
        .iter()
        .flat_map(|t| t.files.keys())
        .filter(|p| {
            let (d, f) = p.rsplit_once('/').unwrap_or(("", p));
            let Some(s) = f.strip_suffix(".csv") else { return false };
            d == dir && (s == stem || s.starts_with(&format!("{stem}_")) || bare == Some(s))
        })
        .map(String::as_str)
        .collect();
    found.sort();
    found.dedup();
    found
}

/// Compares two loaded trees.
fn compare(old: &Tree, new: &Tree) -> Result<Differences> {
    let summaries = |t: &Tree| -> Result<Vec<rlfd_report::ChapterSummary>> {
        t.files
            .iter()
            .filter(|(p, _)| tree::is_chapter_summary(p))
            .map(|(p, bytes)| claims::parse(bytes).with_context(|| format!("{}", t.root.join(p).display())))
            .collect()
    };
    let (old_summaries, new_summaries) = (summaries(old)?, summaries(new)?);
    let mut d = Differences {
        old: old.root.display().to_string(),
        new: new.root.display().to_string(),
        old_provenance: old.provenance(),
        new_provenance: new.provenance(),
        shared: 0,
        claims: claims::compare(&old_summaries, &new_summaries),
        tables: Vec::new(),
        figures: Vec::new(),
        added: new.files.keys().filter(|p| !old.files.contains_key(*p)).cloned().collect(),
        removed: old.files.keys().filter(|p| !new.files.contains_key(*p)).cloned().collect(),
        others: Vec::new(),
    };
    let mut svgs = Vec::new();
    for (path, a) in &old.files {
        let Some(b) = new.files.get(path) else { continue };
        d.shared += 1;
        if a == b {
            continue;
        }
        if tree::is_chapter_summary(path) {
            // Claims are compared above; anything else a summary holds (the title).
            let (sa, sb) = (claims::parse(a)?, claims::parse(b)?);
            if (sa.slug, sa.title) != (sb.slug, sb.title) {
                d.others.push(FileChange { path: path.clone(), removed: 1, added: 1, note: Some("title".into()) });
            }
            continue;
        }
        let (la, lb) = (tree::content(a), tree::content(b));
        if la == lb {
            continue;
        }
        let delimiter = match extension(path) {
            "csv" => Some(b','),
            "tsv" => Some(b'\t'),
            _ => None,
        };
        if let Some(delimiter) = delimiter {
            match (tables::parse(a, delimiter), tables::parse(b, delimiter)) {
                (Ok(ta), Ok(tb)) => {
                    let changes = tables::compare(&ta, &tb);
                    if !changes.is_empty() {
                        d.tables.push(TableChanges { path: path.clone(), changes });
                    }
                    continue;
                }
                (Err(e), _) | (_, Err(e)) => {
                    let (removed, added) = tree::lines_changed(&la, &lb);
                    d.others.push(FileChange { path: path.clone(), removed, added, note: Some(format!("{e:#}")) });
                    continue;
                }
            }
        }
        if extension(path) == "svg" {
            svgs.push(path.clone());
            continue;
        }
        let (removed, added) = tree::lines_changed(&la, &lb);
        d.others.push(FileChange { path: path.clone(), removed, added, note: None });
    }
    for path in svgs {
        let data = figure_data(&path, [old, new])
            .into_iter()
            .map(|csv| {
                (
                    csv.to_string(),
                    d.tables.iter().any(|t| t.path == csv)
                        || !old.files.contains_key(csv)
                        || !new.files.contains_key(csv),
                )
            })
            .collect();
        d.figures.push(FigureChange { path, data });
    }
    Ok(d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    const SUMMARY: &str = r#"{"generated_by": "generated by A; do not edit", "summary": {"slug": "ch6-irl-shaping", "title": "T", "claims": [
      {"id": "C6.1", "statement": "s", "test": "t", "thesis_evidence": "e", "our_evidence": "o", "verdict": "reproduced", "reason": "holds"}]}}"#;

    fn tree(files: &[(&str, &str)]) -> Tree {
        let files: BTreeMap<String, Vec<u8>> =
            files.iter().map(|(p, t)| (p.to_string(), t.as_bytes().to_vec())).collect();
        Tree { root: PathBuf::from("t"), files }
    }

    fn base() -> Vec<(&'static str, &'static str)> {
        vec![
            ("index.html", "<!DOCTYPE html>\n<!-- generated by A (rlfd 0.1.0); do not edit -->\n<p>x</p>\n"),
            ("ch6-irl-shaping/summary.json", SUMMARY),
            ("ch6-irl-shaping/table_6_1.csv", "# generated by A; do not edit\nagent,initial\nSIS,-7000.0\n"),
            (
                "ch6-irl-shaping/figure_6_1.svg",
                "<!-- generated by A; do not edit -->\n<svg>\n<path d=\"M0 0\"/>\n</svg>\n",
            ),
            ("ch6-irl-shaping/figure_6_1_data.csv", "# generated by A; do not edit\nx,y\n1,2\n"),
        ]
    }

    fn replace(files: &mut [(&'static str, &'static str)], path: &str, with: &'static str) {
        files.iter_mut().find(|(p, _)| *p == path).unwrap().1 = with;
    }

    #[test]
    fn provenance_only_changes_agree() {
        let old = tree(&base());
        let new_files: Vec<(String, String)> =
            base().iter().map(|(p, t)| (p.to_string(), t.replace("generated by A", "generated by B"))).collect();
        let new =
            Tree { root: PathBuf::from("u"), files: new_files.into_iter().map(|(p, t)| (p, t.into_bytes())).collect() };
        let d = compare(&old, &new).unwrap();
        assert!(d.agree(), "{d:?}");
        assert_eq!(d.shared, 5);
        assert_eq!(d.new_provenance.as_deref(), Some("B (rlfd 0.1.0)"));
    }

    #[test]
    fn each_kind_of_change_lands_in_its_section() {
        let old = tree(&base());
        let summary = SUMMARY.replace("\"reproduced\"", "\"not-reproduced\"");
        let mut new_files = base();
        replace(
            &mut new_files,
            "ch6-irl-shaping/table_6_1.csv",
            "# generated by B; do not edit\nagent,initial\nSIS,-6500\n",
        );
        replace(&mut new_files, "ch6-irl-shaping/figure_6_1.svg", "<svg>\n<path d=\"M0 1\"/>\n</svg>\n");
        replace(&mut new_files, "index.html", "<!DOCTYPE html>\n<p>y</p>\n");
        new_files.retain(|(p, _)| *p != "ch6-irl-shaping/figure_6_1_data.csv");
        new_files.push(("ch6-irl-shaping/new.csv", "a\n1\n"));
        let mut new = tree(&new_files);
        new.files.insert("ch6-irl-shaping/summary.json".into(), summary.into_bytes());
        let d = compare(&old, &new).unwrap();
        assert!(!d.agree());
        assert_eq!(d.claims.verdicts.len(), 1);
        assert_eq!(d.tables.len(), 1);
        assert_eq!(
            d.tables[0].changes,
            [tables::Change::Cell {
                row: "SIS".into(),
                column: "initial".into(),
                old: "-7000.0".into(),
                new: "-6500".into()
            }]
        );
        assert_eq!(
            d.figures,
            [FigureChange {
                path: "ch6-irl-shaping/figure_6_1.svg".into(),
                data: vec![("ch6-irl-shaping/figure_6_1_data.csv".into(), true)]
            }]
        );
        assert_eq!(d.added, ["ch6-irl-shaping/new.csv"]);
        assert_eq!(d.removed, ["ch6-irl-shaping/figure_6_1_data.csv"]);
        assert_eq!(d.others, [FileChange { path: "index.html".into(), removed: 1, added: 1, note: None }]);
    }

    #[test]
    fn figure_data_by_name() {
        let t = tree(&[
            ("c/figure_4_2_medians.csv", ""),
            ("c/mario_dis_beta.csv", ""),
            ("c/figure_4_2b.csv", ""),
            ("d/figure_4_2.csv", ""),
        ]);
        assert_eq!(figure_data("c/figure_4_2.svg", [&t, &t]), ["c/figure_4_2_medians.csv"]);
        assert_eq!(figure_data("c/figure_mario_dis_beta.svg", [&t, &t]), ["c/mario_dis_beta.csv"]);
        assert!(figure_data("c/figure_6_1.svg", [&t, &t]).is_empty());
    }

    #[test]
    fn formats_parse() {
        assert_eq!("text".parse::<Format>(), Ok(Format::Text));
        assert_eq!("markdown".parse::<Format>(), Ok(Format::Markdown));
        assert!("html".parse::<Format>().is_err());
    }
}
