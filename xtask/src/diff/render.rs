//! The differences as text for a terminal or as Markdown for a pull-request
//! comment, in the same order: claims whose verdict changed, table cells,
//! figures, files added and removed, other files. Trees that agree print
//! one line.

use super::tables::Change;
use super::{Differences, Format, TableChanges, claims, number};

/// The report of `d` in `format`, showing at most `limit` changes per table (0: all).
pub fn render(d: &Differences, format: Format, limit: usize) -> String {
    if d.agree() {
        let line = format!(
            "reports agree: {} and {} ({} shared files; run.json and provenance lines ignored)",
            d.old, d.new, d.shared
        );
        return match format {
            Format::Text => format!("{line}\n"),
            Format::Markdown => format!("**{line}**\n"),
        };
    }
    match format {
        Format::Text => text(d, limit),
        Format::Markdown => markdown(d, limit),
    }
}

/// `1 file`, `2 files`.
fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// How many cell, row and column changes a table has.
fn counts(t: &TableChanges) -> (usize, usize, usize, usize, usize) {
    let mut n = (0, 0, 0, 0, 0);
    for c in &t.changes {
        match c {
            Change::Cell { .. } => n.0 += 1,
            Change::RowAdded(_) => n.1 += 1,
            Change::RowRemoved(_) => n.2 += 1,
            Change::ColumnAdded(_) => n.3 += 1,
            Change::ColumnRemoved(_) => n.4 += 1,
        }
    }
    n
}

/// `3 cells changed, 1 row added` for a table.
fn table_summary(t: &TableChanges) -> String {
    let (cells, added, removed, cols_added, cols_removed) = counts(t);
    let parts: Vec<String> = [
        (cells, "cell changed", "cells changed"),
        (added, "row added", "rows added"),
        (removed, "row removed", "rows removed"),
        (cols_added, "column added", "columns added"),
        (cols_removed, "column removed", "columns removed"),
    ]
    .iter()
    .filter(|(n, ..)| *n > 0)
    .map(|&(n, one, many)| plural(n, one, many))
    .collect();
    parts.join(", ")
}

fn total_cells(d: &Differences) -> usize {
    d.tables.iter().map(|t| counts(t).0).sum()
}

fn shown(t: &TableChanges, limit: usize) -> (&[Change], usize) {
    let n = if limit == 0 { t.changes.len() } else { limit.min(t.changes.len()) };
    (&t.changes[..n], t.changes.len() - n)
}

fn figure_note(data: &[(String, bool)]) -> String {
    if data.is_empty() {
        return String::new();
    }
    let files: Vec<String> = data
        .iter()
        .map(|(p, changed)| {
            let name = p.rsplit('/').next().unwrap_or(p);
            format!("{name}{}", if *changed { ", changed" } else { ", unchanged" })
        })
        .collect();
    format!(" (data: {})", files.join("; "))
}

fn made_by(d: &Differences) -> Vec<String> {
    match (&d.old_provenance, &d.new_provenance) {
        (Some(a), Some(b)) if a == b => vec![format!("both made by {a}")],
        (a, b) => vec![
            format!("old made by {}", a.as_deref().unwrap_or("(unknown)")),
            format!("new made by {}", b.as_deref().unwrap_or("(unknown)")),
        ],
    }
}

fn text(d: &Differences, limit: usize) -> String {
    let mut o = format!("reports differ: {} → {}\n", d.old, d.new);
    for line in made_by(d) {
        o.push_str(&format!("  {line}\n"));
    }
    let c = &d.claims;
    if !c.verdicts.is_empty() {
        o.push_str(&format!("\nClaims whose verdict changed ({}):\n", c.verdicts.len()));
        for v in &c.verdicts {
            let reason = if v.reason.is_empty() { String::new() } else { format!(": {}", v.reason) };
            o.push_str(&format!("  {}  {} → {}{reason}\n", v.id, claims::label(v.old), claims::label(v.new)));
        }
    }
    if !c.evidence.is_empty() {
        o.push_str(&format!(
            "\nClaims with the same verdict whose text, key numbers or tests changed ({}): {}\n",
            c.evidence.len(),
            c.evidence.join(", ")
        ));
    }
    if !d.tables.is_empty() {
        let (cells, files) = (plural(total_cells(d), "cell", "cells"), plural(d.tables.len(), "file", "files"));
        o.push_str(&format!("\nTable cells changed ({cells} in {files}):\n"));
        for t in &d.tables {
            o.push_str(&format!("  {}: {}\n", t.path, table_summary(t)));
            let (changes, more) = shown(t, limit);
            for change in changes {
                let line = match change {
                    Change::Cell { row, column, old, new } => {
                        format!("[{row}] {column}: {}", number::describe(old, new))
                    }
                    Change::RowAdded(k) => format!("row added: {k}"),
                    Change::RowRemoved(k) => format!("row removed: {k}"),
                    Change::ColumnAdded(k) => format!("column added: {k}"),
                    Change::ColumnRemoved(k) => format!("column removed: {k}"),
                };
                o.push_str(&format!("    {line}\n"));
            }
            if more > 0 {
                o.push_str(&format!("    … {} (--limit 0 shows all)\n", plural(more, "more change", "more changes")));
            }
        }
    }
    if !d.figures.is_empty() {
        o.push_str(&format!("\nFigures changed ({}):\n", d.figures.len()));
        for f in &d.figures {
            o.push_str(&format!("  figure {} changed{}\n", f.path, figure_note(&f.data)));
        }
    }
    for (title, list) in [("Files added", &d.added), ("Files removed", &d.removed)] {
        if !list.is_empty() {
            o.push_str(&format!("\n{title} ({}):\n", list.len()));
            for p in list {
                o.push_str(&format!("  {p}\n"));
            }
        }
    }
    if !d.others.is_empty() {
        o.push_str(&format!("\nOther files changed ({}):\n", d.others.len()));
        for f in &d.others {
            let note = f.note.as_ref().map_or(String::new(), |n| format!("; {n}"));
            o.push_str(&format!("  {} ({} lines removed, {} added{note})\n", f.path, f.removed, f.added));
        }
    }
    o
}

/// A Markdown table cell: pipes escaped, one line.
fn cell(s: &str) -> String {
    s.replace('|', "\\|").replace(['\n', '\r'], " ")
}

fn markdown(d: &Differences, limit: usize) -> String {
    let mut o = format!("## Report diff: `{}` → `{}`\n\n", d.old, d.new);
    let made: Vec<String> = made_by(d)
        .into_iter()
        .map(|l| match l.split_once(" by ") {
            Some((who, cmd)) => format!("{who} by `{cmd}`"),
            None => l,
        })
        .collect();
    o.push_str(&format!("{}.\n", made.join("; ")));
    let c = &d.claims;
    if !c.verdicts.is_empty() {
        o.push_str(&format!("\n### Claims whose verdict changed ({})\n\n", c.verdicts.len()));
        o.push_str("| claim | old | new | reason |\n|---|---|---|---|\n");
        for v in &c.verdicts {
            o.push_str(&format!(
                "| {} | {} | **{}** | {} |\n",
                v.id,
                claims::label(v.old),
                claims::label(v.new),
                cell(&v.reason)
            ));
        }
    }
    if !c.evidence.is_empty() {
        o.push_str(&format!(
            "\nClaims with the same verdict whose text, key numbers or tests changed: {}.\n",
            c.evidence.join(", ")
        ));
    }
    if !d.tables.is_empty() {
        let (cells, files) = (plural(total_cells(d), "cell", "cells"), plural(d.tables.len(), "file", "files"));
        o.push_str(&format!("\n### Table cells changed ({cells} in {files})\n"));
        for t in &d.tables {
            o.push_str(&format!("\n#### `{}`: {}\n\n", t.path, table_summary(t)));
            let (changes, more) = shown(t, limit);
            let cells: Vec<&Change> = changes.iter().filter(|c| matches!(c, Change::Cell { .. })).collect();
            if !cells.is_empty() {
                o.push_str("| row | column | old | new | change |\n|---|---|---|---|---|\n");
                for change in cells {
                    if let Change::Cell { row, column, old, new } = change {
                        let rel = number::relative_change(old, new).map_or(String::new(), number::format_change);
                        let show = |s: &str| if s.trim().is_empty() { "(empty)".to_string() } else { cell(s) };
                        o.push_str(&format!(
                            "| {} | {} | {} | {} | {rel} |\n",
                            cell(row),
                            cell(column),
                            show(old),
                            show(new)
                        ));
                    }
                }
            }
            let mut others = Vec::new();
            for change in changes {
                match change {
                    Change::Cell { .. } => {}
                    Change::RowAdded(k) => others.push(format!("row added: {}", cell(k))),
                    Change::RowRemoved(k) => others.push(format!("row removed: {}", cell(k))),
                    Change::ColumnAdded(k) => others.push(format!("column added: `{k}`")),
                    Change::ColumnRemoved(k) => others.push(format!("column removed: `{k}`")),
                }
            }
            if !others.is_empty() {
                o.push('\n');
                for x in others {
                    o.push_str(&format!("- {x}\n"));
                }
            }
            if more > 0 {
                o.push_str(&format!("\n… {} (`--limit 0` shows all).\n", plural(more, "more change", "more changes")));
            }
        }
    }
    if !d.figures.is_empty() {
        o.push_str(&format!("\n### Figures changed ({})\n\n", d.figures.len()));
        for f in &d.figures {
            o.push_str(&format!("- `{}`{}\n", f.path, figure_note(&f.data)));
        }
    }
    for (title, list) in [("Files added", &d.added), ("Files removed", &d.removed)] {
        if !list.is_empty() {
            o.push_str(&format!("\n### {title} ({})\n\n", list.len()));
            for p in list {
                o.push_str(&format!("- `{p}`\n"));
            }
        }
    }
    if !d.others.is_empty() {
        o.push_str(&format!("\n### Other files changed ({})\n\n", d.others.len()));
        for f in &d.others {
            let note = f.note.as_ref().map_or(String::new(), |n| format!("; {}", cell(n)));
            o.push_str(&format!("- `{}` ({} lines removed, {} added{note})\n", f.path, f.removed, f.added));
        }
    }
    o
}

#[cfg(test)]
mod tests {
    use super::super::claims::{ClaimChanges, VerdictChange};
    use super::super::{FigureChange, FileChange};
    use super::*;
    use rlfd_report::claims::Verdict;

    fn differences() -> Differences {
        Differences {
            old: "a".into(),
            new: "b".into(),
            old_provenance: Some("cargo xtask reproduce --scale quick".into()),
            new_provenance: Some("cargo xtask reproduce --scale paper".into()),
            shared: 3,
            claims: ClaimChanges {
                verdicts: vec![VerdictChange {
                    id: "C6.1".into(),
                    old: Some(Verdict::NotEvaluable),
                    new: Some(Verdict::Reproduced),
                    reason: "holds | at p < 1e-4".into(),
                }],
                evidence: vec!["C6.2 (evidence)".into()],
            },
            tables: vec![TableChanges {
                path: "ch6/table_6_1.csv".into(),
                changes: vec![
                    Change::Cell {
                        row: "SIS".into(),
                        column: "initial".into(),
                        old: "-7000.0".into(),
                        new: "-6500".into(),
                    },
                    Change::RowAdded("HAT".into()),
                    Change::Cell { row: "DIS".into(), column: "initial".into(), old: "1".into(), new: "2".into() },
                ],
            }],
            figures: vec![FigureChange { path: "ch6/figure_6_1.svg".into(), data: vec![] }],
            added: vec!["ch6/new.csv".into()],
            removed: vec![],
            others: vec![FileChange { path: "ch6/index.html".into(), removed: 2, added: 2, note: None }],
        }
    }

    #[test]
    fn text_lists_verdicts_first() {
        let t = render(&differences(), Format::Text, 2);
        let expected = "reports differ: a → b
  old made by cargo xtask reproduce --scale quick
  new made by cargo xtask reproduce --scale paper

Claims whose verdict changed (1):
  C6.1  not evaluable → reproduced: holds | at p < 1e-4

Claims with the same verdict whose text, key numbers or tests changed (1): C6.2 (evidence)

Table cells changed (2 cells in 1 file):
  ch6/table_6_1.csv: 2 cells changed, 1 row added
    [SIS] initial: -7000.0 → -6500 (+7.1 %)
    row added: HAT
    … 1 more change (--limit 0 shows all)

Figures changed (1):
  figure ch6/figure_6_1.svg changed

Files added (1):
  ch6/new.csv

Other files changed (1):
  ch6/index.html (2 lines removed, 2 added)
";
        assert_eq!(t, expected);
    }

    #[test]
    fn markdown_has_headings_and_tables() {
        let m = render(&differences(), Format::Markdown, 0);
        assert!(
            m.starts_with(
                "## Report diff: `a` → `b`\n\nold made by `cargo xtask reproduce --scale quick`; new made by"
            ),
            "{m}"
        );
        assert!(m.contains("| C6.1 | not evaluable | **reproduced** | holds \\| at p < 1e-4 |\n"), "{m}");
        assert!(
            m.contains("| SIS | initial | -7000.0 | -6500 | +7.1 % |\n| DIS | initial | 1 | 2 | +100.0 % |\n"),
            "{m}"
        );
        assert!(m.contains("\n- row added: HAT\n"));
        assert!(m.find("### Claims").unwrap() < m.find("### Table").unwrap());
        assert!(m.find("### Table").unwrap() < m.find("### Figures").unwrap());
    }

    #[test]
    fn agreement_is_one_line() {
        let mut d = differences();
        d.claims = ClaimChanges::default();
        d.tables.clear();
        d.figures.clear();
        d.added.clear();
        d.others.clear();
        assert_eq!(
            render(&d, Format::Text, 20),
            "reports agree: a and b (3 shared files; run.json and provenance lines ignored)\n"
        );
    }
}
