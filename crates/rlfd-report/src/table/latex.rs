//! A table as LaTeX that fits the text width without shrinking it: a
//! booktabs `longtable` (not a float, so it stays under its heading and may
//! break across pages) set in `\small`, or `\footnotesize` if that is what
//! fits, never smaller; text columns wrap in `p{}` columns; a table still too
//! wide is split into parts of whole columns, each repeating the row labels.
//! The caption is the thesis's numbering in the title (`Table 6.2: …`), with
//! no LaTeX number of its own.
//!
//! Widths are estimated from the text each cell shows, with Latin Modern's
//! character widths in ems (digits are exactly half an em); the estimate
//! errs wide, and CI's pdflatex check (no overfull box over 10 pt) holds it
//! to account.

use super::{Cell, ColumnGroup, ColumnKind, Num, NumFormat, Syntax, Table, cell_latex, value_text};
use crate::format;
use crate::markup::{self, escape_latex};

/// The text width of the reports' pages in points (A4, 2 cm margins).
pub(crate) const LINE_WIDTH_PT: f64 = 483.0;
/// `\tabcolsep` in points: each column is padded by this on both sides.
const TABCOLSEP_PT: f64 = 6.0;
/// A text column is never narrower than this, in points.
const MIN_TEXT_PT: f64 = 90.0;
/// The row labels wrap beyond this share of the line.
const MAX_STUB_SHARE: f64 = 0.3;

/// The two sizes a table may be set in: `\small` (10 pt) and `\footnotesize` (9 pt).
const SIZES: [(&str, f64); 2] = [("\\small", 10.0), ("\\footnotesize", 9.0)];

/// The estimated width of `text` in ems, in Latin Modern Roman.
pub(crate) fn em_width(text: &str) -> f64 {
    text.chars()
        .map(|c| match c {
            '0'..='9' | '*' | '$' | '#' | '?' => 0.5,
            '.' | ',' | ':' | ';' | '\'' | '!' | '|' => 0.28,
            ' ' => 0.33,
            '(' | ')' | '[' | ']' | '{' | '}' | '/' => 0.39,
            '-' | '‐' => 0.33,
            'i' | 'j' | 'l' | 't' | 'f' | 'r' => 0.33,
            'm' | 'w' => 0.8,
            'M' | 'W' => 1.0,
            '−' | '±' | '×' | '+' | '=' | '<' | '>' | '≤' | '≥' | '→' | '≈' => 0.78,
            '%' | '—' => 0.9,
            '–' => 0.5,
            c if c.is_ascii_uppercase() => 0.74,
            c if c.is_ascii_lowercase() => 0.52,
            _ => 0.75,
        })
        .sum()
}

/// The longest word of `text`, in ems.
fn longest_word(text: &str) -> f64 {
    text.split_whitespace().map(em_width).fold(0.0, f64::max)
}

/// What a number cell shows, as plain text (for its width).
fn num_plain(n: &Num) -> String {
    let mut s = value_text(n.value, n.format, Syntax::Html);
    if n.value.is_nan() {
        return s;
    }
    if let Some(sd) = n.spread {
        s.push_str(" ± ");
        s.push_str(&value_text(sd, n.format, Syntax::Html));
    }
    if n.format == NumFormat::PValue {
        s.push(' ');
        s.push_str(format::stars(n.value));
    }
    s
}

fn header_plain(column: &ColumnGroup) -> String {
    match &column.unit {
        Some(unit) => format!("{} ({unit})", column.header),
        None => column.header.clone(),
    }
}

/// One column group's natural widths in ems: `(first, second)` sub-column
/// widths (the second is zero for a single column) and the header.
struct Widths {
    data: Vec<f64>,
    header_word: f64,
    header: f64,
}

fn column_widths(table: &Table, j: usize, kind: ColumnKind) -> Widths {
    let cells = table.rows.iter().map(|r| r.cells.get(j).unwrap_or(&Cell::Empty));
    let mut data = match kind {
        ColumnKind::Compare { .. } => vec![em_width("ours"), em_width("thesis")],
        _ => vec![0.0],
    };
    for cell in cells {
        match cell {
            Cell::Compare { ours, thesis } => {
                data[0] = data[0].max(em_width(&num_plain(ours)));
                let t = thesis.as_ref().map_or_else(|| "—".to_owned(), num_plain);
                let last = data.len() - 1;
                data[last] = data[last].max(em_width(&t));
            }
            Cell::Num(n) => data[0] = data[0].max(em_width(&num_plain(n))),
            Cell::Text(t) => {
                let w = em_width(t);
                if data.len() == 2 {
                    // Spans both sub-columns: widen the first by what the pair lacks.
                    let lack = w - (data[0] + data[1] + 2.0 * TABCOLSEP_PT / 10.0);
                    if lack > 0.0 {
                        data[0] += lack;
                    }
                } else {
                    data[0] = data[0].max(w);
                }
            }
            Cell::Empty => {}
        }
    }
    let header = header_plain(&table.columns[j]);
    Widths { data, header_word: longest_word(&header), header: em_width(&header) }
}

/// The layout of one part of a table: which columns, at which size, and
/// the width of each wrapping (text) column in points.
#[derive(Debug, Clone, PartialEq)]
struct Layout {
    columns: Vec<usize>,
    size: usize,
    /// Per column of `columns`: `Some(width)` for a wrapped text column.
    wrap: Vec<Option<f64>>,
    /// The row labels' wrapping width, if they wrap.
    stub_wrap: Option<f64>,
}

/// Points a set of columns needs at `size_pt`, or `None` when even wrapped
/// text columns cannot fit; the layout's wrap widths when they can.
fn fit(
    table: &Table,
    kinds: &[ColumnKind],
    widths: &[Widths],
    columns: &[usize],
    size_pt: f64,
) -> Option<(Vec<Option<f64>>, Option<f64>)> {
    let pt = |em: f64| em * size_pt * 1.04;
    let sep = 2.0 * TABCOLSEP_PT;
    let stub_natural =
        table.rows.iter().map(|r| em_width(&r.label)).chain([em_width(&table.stub_header)]).fold(0.0, f64::max);
    let stub_cap = MAX_STUB_SHARE * LINE_WIDTH_PT;
    let stub_wrap = (pt(stub_natural) > stub_cap).then_some(stub_cap);
    let mut fixed = stub_wrap.unwrap_or(pt(stub_natural));
    let mut text_natural = Vec::new();
    for &j in columns {
        let w = &widths[j];
        match kinds[j] {
            ColumnKind::Text => text_natural.push((j, pt(w.data[0].max(w.header_word)))),
            ColumnKind::Compare { .. } => {
                let pair = pt(w.data[0]) + pt(w.data[1]) + sep;
                fixed += sep + pair.max(pt(w.header_word));
            }
            ColumnKind::Single { .. } => fixed += sep + pt(w.data[0].max(w.header_word)),
        }
    }
    let mut wrap = vec![None; columns.len()];
    let text_total: f64 = text_natural.iter().map(|(_, w)| w + sep).sum();
    if fixed + text_total <= LINE_WIDTH_PT {
        return Some((wrap, stub_wrap));
    }
    if text_natural.is_empty() {
        return None;
    }
    // Text columns share what is left, each at least MIN_TEXT_PT, in
    // proportion to their natural widths.
    let left = LINE_WIDTH_PT - fixed - sep * text_natural.len() as f64;
    if left < MIN_TEXT_PT * text_natural.len() as f64 {
        return None;
    }
    let natural: f64 = text_natural.iter().map(|(_, w)| w).sum();
    for (j, w) in &text_natural {
        let share = (left * w / natural).max(MIN_TEXT_PT).min(*w);
        let k = columns.iter().position(|c| c == j).expect("a column of this part");
        wrap[k] = Some(share.floor());
    }
    Some((wrap, stub_wrap))
}

/// The parts a table is set in: one if it fits at some size, else the
/// fewest runs of whole columns that each fit at `\footnotesize`.
fn layouts(table: &Table, kinds: &[ColumnKind]) -> Vec<Layout> {
    let widths: Vec<Widths> = (0..kinds.len()).map(|j| column_widths(table, j, kinds[j])).collect();
    let all: Vec<usize> = (0..kinds.len()).collect();
    for (size, (_, pt)) in SIZES.iter().enumerate() {
        if let Some((wrap, stub_wrap)) = fit(table, kinds, &widths, &all, *pt) {
            return vec![Layout { columns: all, size, wrap, stub_wrap }];
        }
    }
    let size = SIZES.len() - 1;
    let pt = SIZES[size].1;
    let mut parts = Vec::new();
    let mut current: Vec<usize> = Vec::new();
    for j in all {
        let mut trial = current.clone();
        trial.push(j);
        if current.is_empty() || fit(table, kinds, &widths, &trial, pt).is_some() {
            current = trial;
        } else {
            parts.push(std::mem::replace(&mut current, vec![j]));
        }
    }
    parts.push(current);
    parts
        .into_iter()
        .map(|columns| {
            // A single column too wide even alone is set as it is (it cannot be split).
            let (wrap, stub_wrap) =
                fit(table, kinds, &widths, &columns, pt).unwrap_or_else(|| (vec![None; columns.len()], None));
            Layout { columns, size, wrap, stub_wrap }
        })
        .collect()
}

fn wrapped(width: f64, align: &str) -> String {
    format!(">{{{align}\\arraybackslash}}p{{{width:.0}pt}}")
}

/// The table as one or more booktabs longtables (see the module doc);
/// needs `longtable`, `booktabs`, `array` and `xcolor`.
pub fn to_latex(table: &Table) -> String {
    let kinds = table.kinds();
    let parts = layouts(table, &kinds);
    let mut t = String::new();
    for (k, layout) in parts.iter().enumerate() {
        let (size_cmd, size_pt) = SIZES[layout.size];
        let pt = |em: f64| em * size_pt * 1.04;
        let widths: Vec<Widths> = layout.columns.iter().map(|&j| column_widths(table, j, kinds[j])).collect();
        let mut spec = String::from("@{}");
        spec.push_str(&match layout.stub_wrap {
            Some(w) => wrapped(w, "\\raggedright"),
            None => "l".into(),
        });
        for (i, &j) in layout.columns.iter().enumerate() {
            match (kinds[j], layout.wrap[i]) {
                (ColumnKind::Compare { .. }, _) => spec.push_str("rr"),
                (ColumnKind::Single { .. }, _) => spec.push('r'),
                (ColumnKind::Text, Some(w)) => spec.push_str(&wrapped(w, "\\raggedright")),
                (ColumnKind::Text, None) => spec.push('l'),
            }
        }
        spec.push_str("@{}");

        t.push_str(&format!("\\begingroup{size_cmd}\n\\begin{{longtable}}{{{spec}}}\n"));
        let mut title = markup::to_latex(&table.title);
        if parts.len() > 1 {
            let names: Vec<String> = layout.columns.iter().map(|&j| escape_latex(&table.columns[j].header)).collect();
            title.push_str(&format!(" (part {} of {}: {})", k + 1, parts.len(), names.join(", ")));
        }
        let caption = if k == 0 && !table.caption.is_empty() {
            format!(" {}", markup::to_latex(&table.caption))
        } else {
            String::new()
        };
        // No \\label: labels would clash between chapters in report.tex, and nothing refers to them.
        t.push_str(&format!("\\caption*{{\\textbf{{{title}}}{caption}}}\\\\\n\\toprule\n"));
        t.push_str(&header_rows(table, &kinds, layout, &widths, pt));
        t.push_str("\\midrule\n\\endhead\n\\bottomrule\n\\endfoot\n");
        for row in &table.rows {
            let mut cells = vec![escape_latex(&row.label)];
            for &j in &layout.columns {
                cells.push(cell_latex(row.cells.get(j).unwrap_or(&Cell::Empty), kinds[j]));
            }
            t.push_str(&format!("{} \\\\\n", cells.join(" & ")));
        }
        t.push_str("\\end{longtable}\n");
        if k + 1 == parts.len() {
            for note in &table.notes {
                t.push_str(&format!("{{\\footnotesize {}\\par}}\n", markup::to_latex(note)));
            }
        }
        t.push_str("\\endgroup\n");
    }
    t
}

/// The header rows: group headers (wrapping where longer than their
/// columns) and, where some column is compared, the ours/thesis row.
fn header_rows(
    table: &Table,
    kinds: &[ColumnKind],
    layout: &Layout,
    widths: &[Widths],
    pt: impl Fn(f64) -> f64,
) -> String {
    let any_compare = layout.columns.iter().any(|&j| matches!(kinds[j], ColumnKind::Compare { .. }));
    let stub = escape_latex(&table.stub_header);
    let sep = 2.0 * TABCOLSEP_PT;
    let mut first = vec![if any_compare { String::new() } else { stub.clone() }];
    let mut second = vec![stub];
    let mut rules = String::new();
    let mut col = 2;
    for (i, &j) in layout.columns.iter().enumerate() {
        let column = &table.columns[j];
        let w = &widths[i];
        let header = latex_header(column);
        match kinds[j] {
            ColumnKind::Compare { .. } => {
                let pair = pt(w.data[0]) + pt(w.data[1]) + sep;
                let width = pair.max(pt(w.header_word));
                let cell = if pt(w.header) > width {
                    format!("\\multicolumn{{2}}{{{}}}{{{header}}}", wrapped(width, "\\centering"))
                } else {
                    format!("\\multicolumn{{2}}{{c}}{{{header}}}")
                };
                first.push(cell);
                rules.push_str(&format!("\\cmidrule(lr){{{}-{}}}", col, col + 1));
                second.push("ours".into());
                second.push("\\textcolor{black!55}{thesis}".into());
                col += 2;
            }
            kind => {
                let data = match (kind, layout.wrap[i]) {
                    (ColumnKind::Text, Some(width)) => width,
                    _ => pt(w.data[0].max(w.header_word)),
                };
                let align = if kind == ColumnKind::Text { "\\raggedright" } else { "\\raggedleft" };
                let cell = if pt(w.header) > data {
                    format!("\\multicolumn{{1}}{{{}}}{{{header}}}", wrapped(data, align))
                } else if kind == ColumnKind::Text {
                    header
                } else {
                    format!("\\multicolumn{{1}}{{r}}{{{header}}}")
                };
                if any_compare {
                    first.push(String::new());
                    second.push(cell);
                } else {
                    first.push(cell);
                }
                col += 1;
            }
        }
    }
    if any_compare {
        format!("{} \\\\\n{rules}\n{} \\\\\n", first.join(" & "), second.join(" & "))
    } else {
        format!("{} \\\\\n", first.join(" & "))
    }
}

fn latex_header(column: &ColumnGroup) -> String {
    let header = escape_latex(&column.header);
    match &column.unit {
        Some(unit) => format!("{header} ({})", escape_latex(unit)),
        None => header,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::{ColumnGroup, Row};

    fn wide(columns: usize) -> Table {
        let mut t = Table::new("wide", "Table 9.9: a wide table", "Pair");
        t.columns = (0..columns).map(|k| ColumnGroup::new(format!("Column number {k}"))).collect();
        t.rows = vec![Row::new(
            "SAR vs SIS",
            (0..columns)
                .map(|k| {
                    Cell::compare(Num::new(-123_456.789 * k as f64, NumFormat::grouped(2)).with_spread(9_876.5), 1.0)
                })
                .collect(),
        )];
        t
    }

    #[test]
    fn a_narrow_table_is_one_small_longtable() {
        let l = to_latex(&wide(2));
        assert_eq!(l.matches("\\begin{longtable}").count(), 1, "{l}");
        assert!(l.starts_with("\\begingroup\\small\n"), "{l}");
        assert!(l.contains("\\caption*{\\textbf{Table 9.9: a wide table}}\\\\"), "{l}");
        assert!(!l.contains("resizebox"));
    }

    #[test]
    fn a_wide_table_is_split_into_parts_that_fit() {
        let t = wide(9);
        let l = to_latex(&t);
        let parts = l.matches("\\begin{longtable}").count();
        assert!(parts >= 2, "{l}");
        assert!(l.contains(&format!("(part 1 of {parts}: ")), "{l}");
        assert!(l.matches("\\begingroup\\footnotesize").count() == parts);
        // Every part fits by the estimate, and every column appears once.
        let kinds = t.kinds();
        let layouts = layouts(&t, &kinds);
        let columns: Vec<usize> = layouts.iter().flat_map(|p| p.columns.clone()).collect();
        assert_eq!(columns, (0..9).collect::<Vec<_>>());
    }

    #[test]
    fn text_columns_wrap() {
        let mut t = Table::new("deviations", "Parameters", "Parameter");
        t.columns = vec![ColumnGroup::new("Value"), ColumnGroup::new("Source")];
        t.rows = vec![Row::new("α", vec![Cell::text("0.25/32"), Cell::text("word ".repeat(80))])];
        let l = to_latex(&t);
        assert!(l.contains("p{"), "{l}");
        assert!(l.starts_with("\\begingroup\\small"), "{l}");
    }

    #[test]
    fn widths() {
        assert_eq!(em_width("1234"), 2.0);
        assert!(longest_word("a bbbbbbbb c") > em_width("bbbbbbb"));
    }
}
