//! A table model in which every numeric cell can hold our value and the
//! thesis's side by side, and its three renderings: an HTML `<table>`
//! fragment ([`to_html`]), booktabs LaTeX longtables that fit the page
//! ([`to_latex`], see its module) and machine-readable CSV ([`to_csv`]).
//!
//! A column group holding any [`Cell::Compare`] is shown as two adjacent
//! sub-columns, *ours* and *thesis* (the thesis's in grey); a missing or NaN
//! value shows as an em dash (an empty field in CSV). A p-value table is an
//! ordinary table whose numbers use [`NumFormat::PValue`]: four significant
//! digits and the thesis's stars (`*` ≤ 0.05, `**` ≤ 0.01, `***` ≤ 0.001,
//! `****` ≤ 0.0001) in HTML and LaTeX.
//!
//! CSV has one header row, `<stub>,<key>_ours,<key>_sd,<key>_thesis,…` for a
//! compared column (`_sd` only when some cell has a spread, `_thesis_sd` only
//! when some thesis value has one) and `<key>[,<key>_sd]` for a plain one;
//! numbers are written at full precision, as the shortest text that reads
//! back to the same float (`12.133333333333333`, `3.3761e-7`), whatever
//! the table shows. The renderers do not check the
//! table: [`Table::check`] does, and `render_chapter` calls it.

mod latex;
pub mod statistics;

pub(crate) use latex::LINE_WIDTH_PT;
pub use latex::to_latex;

use crate::format::{self, PValueText};
use crate::markup::{self, escape_html, escape_latex};
use crate::{Error, Result};

/// A table of a chapter report, written as `<id>.csv` beside the pages.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Named after the thesis: `table_6_1`; also the CSV file's stem.
    pub id: String,
    /// `Maze: initial, asymptotic and cumulative reward (Table 6.1)`.
    pub title: String,
    /// Prose under the title (inline markup allowed).
    pub caption: String,
    /// The header of the row-label column: `Agent`.
    pub stub_header: String,
    pub columns: Vec<ColumnGroup>,
    pub rows: Vec<Row>,
    /// Footnotes (inline markup allowed).
    pub notes: Vec<String>,
}

/// A column: its header, its machine name for CSV and an optional unit.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ColumnGroup {
    /// The CSV name stem, `initial` (lower case, `[a-z0-9_]`).
    pub key: String,
    /// The header shown: `Initial`.
    pub header: String,
    /// Shown under the header: `reward`, `episodes`.
    pub unit: Option<String>,
}

/// A row: its label and one cell per column.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub label: String,
    pub cells: Vec<Cell>,
}

/// One cell.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// Ours beside the thesis's (`None` where the thesis has no value).
    Compare {
        ours: Num,
        thesis: Option<Num>,
    },
    /// A number with no published counterpart.
    Num(Num),
    /// Text, e.g. a parameter's value `0.25/32`.
    Text(String),
    Empty,
}

/// A number, its optional spread (± one standard deviation, or whatever the
/// table's caption says) and how to write it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Num {
    /// NaN (no value) is `null` in JSON, which has no NaN.
    #[serde(with = "nan_as_null")]
    pub value: f64,
    pub spread: Option<f64>,
    pub format: NumFormat,
}

/// An `f64` in JSON with NaN as `null` (and back).
mod nan_as_null {
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        if v.is_nan() { s.serialize_none() } else { s.serialize_f64(*v) }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
    }
}

/// How a number is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum NumFormat {
    /// `decimals` digits after the point; `thousands` groups the integer part
    /// with commas in HTML and LaTeX (never in CSV).
    Fixed { decimals: usize, thousands: bool },
    /// Four significant digits and significance stars (scientific in CSV).
    PValue,
    /// Rounded to a whole number, grouped by thousands in HTML and LaTeX.
    Integer,
    /// A value already in percent (`27.4` → `27.4%`).
    Percent { decimals: usize },
}

impl NumFormat {
    /// `decimals` digits, no grouping.
    pub const fn fixed(decimals: usize) -> NumFormat {
        NumFormat::Fixed { decimals, thousands: false }
    }

    /// `decimals` digits, thousands grouped with commas.
    pub const fn grouped(decimals: usize) -> NumFormat {
        NumFormat::Fixed { decimals, thousands: true }
    }
}

impl Num {
    pub const fn new(value: f64, format: NumFormat) -> Num {
        Num { value, spread: None, format }
    }

    /// A p-value.
    pub const fn p_value(p: f64) -> Num {
        Num::new(p, NumFormat::PValue)
    }

    /// The same number with a spread (± sd).
    pub const fn with_spread(self, spread: f64) -> Num {
        Num { spread: Some(spread), ..self }
    }

    /// Another value in this number's format, without spread: how a
    /// published value is shown beside ours.
    pub const fn like(&self, value: f64) -> Num {
        Num::new(value, self.format)
    }
}

impl Cell {
    /// Ours beside a published value, written in our format (a NaN published
    /// value shows as an em dash).
    pub fn compare(ours: Num, thesis: f64) -> Cell {
        Cell::Compare { thesis: Some(ours.like(thesis)), ours }
    }

    /// Ours in a compared column where the thesis has no value.
    pub fn ours_only(ours: Num) -> Cell {
        Cell::Compare { ours, thesis: None }
    }

    pub fn text(text: impl Into<String>) -> Cell {
        Cell::Text(text.into())
    }
}

impl ColumnGroup {
    /// A column whose CSV key is derived from its header (`Initial reward` →
    /// `initial_reward`).
    pub fn new(header: impl Into<String>) -> ColumnGroup {
        let header = header.into();
        ColumnGroup { key: key_of(&header), header, unit: None }
    }

    pub fn with_unit(self, unit: impl Into<String>) -> ColumnGroup {
        ColumnGroup { unit: Some(unit.into()), ..self }
    }

    pub fn with_key(self, key: impl Into<String>) -> ColumnGroup {
        ColumnGroup { key: key.into(), ..self }
    }
}

impl Row {
    pub fn new(label: impl Into<String>, cells: Vec<Cell>) -> Row {
        Row { label: label.into(), cells }
    }
}

impl Table {
    /// An empty table; add columns and rows through the public fields.
    pub fn new(id: impl Into<String>, title: impl Into<String>, stub_header: impl Into<String>) -> Table {
        Table {
            id: id.into(),
            title: title.into(),
            caption: String::new(),
            stub_header: stub_header.into(),
            columns: Vec::new(),
            rows: Vec::new(),
            notes: Vec::new(),
        }
    }

    /// Checks what the renderers assume: an id usable as a file stem, one
    /// cell per column in every row, CSV keys that are non-empty, made of
    /// `[a-z0-9_]` and distinct once expanded (`initial_ours`, `initial_sd`…).
    pub fn check(&self) -> Result<()> {
        let bad = |reason: String| Error::Table { table: self.id.clone(), reason };
        if self.id.is_empty() || !self.id.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
            return Err(bad("the id must be a non-empty [A-Za-z0-9_-] file stem".into()));
        }
        for column in &self.columns {
            if column.key.is_empty()
                || !column.key.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
            {
                return Err(bad(format!(
                    "column `{}` has key `{}`, not a non-empty [a-z0-9_] name",
                    column.header, column.key
                )));
            }
        }
        for row in &self.rows {
            if row.cells.len() != self.columns.len() {
                return Err(bad(format!(
                    "row `{}` has {} cells for {} columns",
                    row.label,
                    row.cells.len(),
                    self.columns.len()
                )));
            }
        }
        let header = self.csv_header();
        for (i, name) in header.iter().enumerate() {
            if header[..i].contains(name) {
                return Err(bad(format!("CSV column `{name}` appears twice")));
            }
        }
        Ok(())
    }

    fn kinds(&self) -> Vec<ColumnKind> {
        (0..self.columns.len()).map(|j| self.kind(j)).collect()
    }

    /// What column `j` holds, looking at every row.
    fn kind(&self, j: usize) -> ColumnKind {
        let cells = || self.rows.iter().filter_map(move |r| r.cells.get(j));
        let compare = cells().any(|c| matches!(c, Cell::Compare { .. }));
        let numeric = cells().any(|c| matches!(c, Cell::Compare { .. } | Cell::Num(_)));
        let ours_sd = cells().any(|c| match c {
            Cell::Compare { ours: n, .. } | Cell::Num(n) => n.spread.is_some(),
            _ => false,
        });
        let thesis_sd = cells().any(|c| matches!(c, Cell::Compare { thesis: Some(n), .. } if n.spread.is_some()));
        match (compare, numeric) {
            (true, _) => ColumnKind::Compare { ours_sd, thesis_sd },
            (false, true) => ColumnKind::Single { sd: ours_sd },
            (false, false) => ColumnKind::Text,
        }
    }

    fn csv_header(&self) -> Vec<String> {
        let mut header = vec![key_of(&self.stub_header)];
        for (column, kind) in self.columns.iter().zip(self.kinds()) {
            let k = &column.key;
            match kind {
                ColumnKind::Compare { ours_sd, thesis_sd } => {
                    header.push(format!("{k}_ours"));
                    if ours_sd {
                        header.push(format!("{k}_sd"));
                    }
                    header.push(format!("{k}_thesis"));
                    if thesis_sd {
                        header.push(format!("{k}_thesis_sd"));
                    }
                }
                ColumnKind::Single { sd } => {
                    header.push(k.clone());
                    if sd {
                        header.push(format!("{k}_sd"));
                    }
                }
                ColumnKind::Text => header.push(k.clone()),
            }
        }
        header
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ColumnKind {
    /// Two sub-columns, ours and the thesis's.
    Compare { ours_sd: bool, thesis_sd: bool },
    /// One numeric column.
    Single { sd: bool },
    /// Text only.
    Text,
}

/// `Initial reward (×1000)` → `initial_reward_1000`; `Agent` → `agent`.
fn key_of(header: &str) -> String {
    let mut key = String::new();
    for c in header.chars() {
        if c.is_ascii_alphanumeric() {
            key.push(c.to_ascii_lowercase());
        } else if !key.is_empty() && !key.ends_with('_') {
            key.push('_');
        }
    }
    while key.ends_with('_') {
        key.pop();
    }
    key
}

// ---------------------------------------------------------------------------
// Numbers as text

/// The text of a number in one of the three output syntaxes.
#[derive(Clone, Copy)]
enum Syntax {
    Html,
    Latex,
    Csv,
}

/// The value's digits in the format (no stars, no spread). HTML uses the
/// true minus sign; LaTeX is math-mode material (without the `$`).
fn value_text(v: f64, format: NumFormat, syntax: Syntax) -> String {
    if v.is_nan() {
        return match syntax {
            Syntax::Html => "—".into(),
            Syntax::Latex => "---".into(),
            Syntax::Csv => String::new(),
        };
    }
    if v.is_infinite() {
        let sign = if v < 0.0 { "-" } else { "" };
        return match syntax {
            Syntax::Html => format!("{}∞", if v < 0.0 { "−" } else { "" }),
            Syntax::Latex => format!(r"{sign}\infty"),
            Syntax::Csv => format!("{sign}inf"),
        };
    }
    if let Syntax::Csv = syntax {
        return format::shortest(v);
    }
    let plain = match (format, syntax) {
        (NumFormat::PValue, Syntax::Latex) => {
            return match format::p_value_text(v) {
                PValueText::Decimal(s) => s,
                PValueText::Scientific { mantissa, exponent } => {
                    format!(r"{mantissa}\times10^{{{exponent}}}")
                }
                PValueText::Other(s) if s.starts_with('<') => r"<10^{-300}".into(),
                PValueText::Other(s) => format!(r"\mathrm{{{}}}", escape_latex(&s)),
            };
        }
        (NumFormat::PValue, _) => match format::p_value_text(v) {
            PValueText::Scientific { mantissa, exponent } => return format::times_ten(&mantissa, exponent),
            PValueText::Decimal(s) | PValueText::Other(s) => s,
        },
        (NumFormat::Fixed { decimals, thousands }, _) => {
            if thousands {
                format::thousands(v, decimals)
            } else {
                format::fixed(v, decimals)
            }
        }
        (NumFormat::Integer, _) => format::thousands(v, 0),
        (NumFormat::Percent { decimals }, _) => format::fixed(v, decimals),
    };
    let percent = matches!(format, NumFormat::Percent { .. });
    match syntax {
        Syntax::Html => {
            let s = plain.replace('-', "−");
            if percent { s + "%" } else { s }
        }
        Syntax::Latex => {
            let s = plain.replace(',', "{,}");
            if percent { s + r"\%" } else { s }
        }
        Syntax::Csv => unreachable!("CSV returned above"),
    }
}

/// A number's digits without spread or stars, as HTML text (`1.5 × 10⁻¹⁰`).
pub(crate) fn plain_html(n: &Num) -> String {
    value_text(n.value, n.format, Syntax::Html)
}

/// A number's digits without spread or stars, as LaTeX math material.
pub(crate) fn plain_latex(n: &Num) -> String {
    value_text(n.value, n.format, Syntax::Latex)
}

/// A number as the HTML of a table cell (for the scorecard).
pub(crate) fn num_html_text(n: &Num) -> String {
    num_html(n)
}

/// A number as the LaTeX of a table cell (for the scorecard).
pub(crate) fn num_latex_text(n: &Num) -> String {
    num_latex(n)
}

/// A number with its spread and stars, as HTML.
fn num_html(n: &Num) -> String {
    let mut s = escape_html(&value_text(n.value, n.format, Syntax::Html));
    if n.value.is_nan() {
        return s;
    }
    if n.format == NumFormat::PValue {
        let stars = format::stars(n.value);
        if !stars.is_empty() {
            s.push_str(&format!("<span class=\"stars\">{stars}</span>"));
        }
    }
    if let Some(sd) = n.spread {
        let sd = value_text(sd, n.format, Syntax::Html);
        s.push_str(&format!("<span class=\"sd\"> ± {}</span>", escape_html(&sd)));
    }
    s
}

/// A number with its spread and stars, as LaTeX text (math inside `$…$`).
fn num_latex(n: &Num) -> String {
    let v = value_text(n.value, n.format, Syntax::Latex);
    if n.value.is_nan() {
        return v;
    }
    let mut s = match n.spread {
        Some(sd) => format!(r"${v} \pm {}$", value_text(sd, n.format, Syntax::Latex)),
        None => format!("${v}$"),
    };
    if n.format == NumFormat::PValue {
        let stars = format::stars(n.value);
        if !stars.is_empty() {
            s.push_str(r"\,");
            s.push_str(stars);
        }
    }
    s
}

// ---------------------------------------------------------------------------
// HTML

/// The table as an HTML `<table class="data">` fragment (its caption, a
/// header with ours/thesis sub-columns where compared, the body and the notes
/// in a `<tfoot>`). Classes `ours`, `thesis`, `sd`, `stars`, `num` and `text`
/// are styled by the page's stylesheet.
pub fn to_html(table: &Table) -> String {
    let kinds = table.kinds();
    let any_compare = kinds.iter().any(|k| matches!(k, ColumnKind::Compare { .. }));
    let width = 1 + kinds
        .iter()
        .map(|k| match k {
            ColumnKind::Compare { .. } => 2,
            _ => 1,
        })
        .sum::<usize>();
    let mut h = String::new();
    h.push_str(&format!("<table class=\"data\" id=\"{}\">\n", escape_html(&table.id)));
    h.push_str(&format!("<caption><span class=\"title\">{}</span>", markup::to_html(&table.title)));
    if !table.caption.is_empty() {
        h.push(' ');
        h.push_str(&markup::to_html(&table.caption));
    }
    h.push_str("</caption>\n<thead>\n<tr>");
    let span2 = if any_compare { " rowspan=\"2\"" } else { "" };
    h.push_str(&format!("<th{span2} class=\"stub\">{}</th>", escape_html(&table.stub_header)));
    for (column, kind) in table.columns.iter().zip(&kinds) {
        let mut header = escape_html(&column.header);
        if let Some(unit) = &column.unit {
            header.push_str(&format!("<br><span class=\"unit\">{}</span>", escape_html(unit)));
        }
        match kind {
            ColumnKind::Compare { .. } => h.push_str(&format!("<th colspan=\"2\" class=\"group\">{header}</th>")),
            ColumnKind::Single { .. } => h.push_str(&format!("<th{span2} class=\"num\">{header}</th>")),
            ColumnKind::Text => h.push_str(&format!("<th{span2} class=\"text\">{header}</th>")),
        }
    }
    h.push_str("</tr>\n");
    if any_compare {
        h.push_str("<tr>");
        for kind in &kinds {
            if let ColumnKind::Compare { .. } = kind {
                h.push_str("<th class=\"ours\">ours</th><th class=\"thesis\">thesis</th>");
            }
        }
        h.push_str("</tr>\n");
    }
    h.push_str("</thead>\n<tbody>\n");
    for row in &table.rows {
        h.push_str(&format!("<tr><th scope=\"row\">{}</th>", escape_html(&row.label)));
        for (j, kind) in kinds.iter().enumerate() {
            let cell = row.cells.get(j).unwrap_or(&Cell::Empty);
            h.push_str(&cell_html(cell, *kind));
        }
        h.push_str("</tr>\n");
    }
    h.push_str("</tbody>\n");
    if !table.notes.is_empty() {
        h.push_str("<tfoot>\n");
        for note in &table.notes {
            h.push_str(&format!("<tr><td colspan=\"{width}\">{}</td></tr>\n", markup::to_html(note)));
        }
        h.push_str("</tfoot>\n");
    }
    h.push_str("</table>\n");
    h
}

fn cell_html(cell: &Cell, kind: ColumnKind) -> String {
    let compared = matches!(kind, ColumnKind::Compare { .. });
    let thesis_td = |n: Option<&Num>| {
        let text = n.map_or_else(|| "—".to_owned(), num_html);
        format!("<td class=\"thesis\">{text}</td>")
    };
    match cell {
        Cell::Compare { ours, thesis } => {
            format!("<td class=\"ours\">{}</td>{}", num_html(ours), thesis_td(thesis.as_ref()))
        }
        Cell::Num(n) if compared => {
            format!("<td class=\"ours\">{}</td>{}", num_html(n), thesis_td(None))
        }
        Cell::Num(n) => format!("<td class=\"num\">{}</td>", num_html(n)),
        Cell::Text(t) if compared => {
            format!("<td colspan=\"2\" class=\"text\">{}</td>", escape_html(t))
        }
        Cell::Text(t) => format!("<td class=\"text\">{}</td>", escape_html(t)),
        Cell::Empty if compared => "<td class=\"ours\"></td><td class=\"thesis\"></td>".into(),
        Cell::Empty => "<td></td>".into(),
    }
}

// ---------------------------------------------------------------------------
// LaTeX

fn cell_latex(cell: &Cell, kind: ColumnKind) -> String {
    let compared = matches!(kind, ColumnKind::Compare { .. });
    let thesis = |n: Option<&Num>| {
        let text = n.map_or_else(|| "---".to_owned(), num_latex);
        format!("\\textcolor{{black!55}}{{{text}}}")
    };
    match cell {
        Cell::Compare { ours, thesis: t } => {
            format!("{} & {}", num_latex(ours), thesis(t.as_ref()))
        }
        Cell::Num(n) if compared => format!("{} & {}", num_latex(n), thesis(None)),
        Cell::Num(n) => num_latex(n),
        Cell::Text(s) if compared => format!("\\multicolumn{{2}}{{l}}{{{}}}", escape_latex(s)),
        Cell::Text(s) => escape_latex(s),
        Cell::Empty if compared => " & ".into(),
        Cell::Empty => String::new(),
    }
}

// ---------------------------------------------------------------------------
// CSV

/// The table as CSV: one header row, then one record per row (see the
/// module doc for the columns). No provenance line: `render_chapter` adds it.
pub fn to_csv(table: &Table) -> String {
    let kinds = table.kinds();
    let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
    // Writing to memory cannot fail, and every record has the header's
    // length (cells are laid out by the same column kinds).
    const WRITE: &str = "CSV records of the header's length written to memory";
    w.write_record(table.csv_header()).expect(WRITE);
    let num = |n: Option<&Num>| n.map_or_else(String::new, |n| value_text(n.value, n.format, Syntax::Csv));
    let sd =
        |n: Option<&Num>| n.and_then(|n| n.spread.map(|s| value_text(s, n.format, Syntax::Csv))).unwrap_or_default();
    for row in &table.rows {
        let mut record = vec![row.label.clone()];
        for (j, kind) in kinds.iter().enumerate() {
            let cell = row.cells.get(j).unwrap_or(&Cell::Empty);
            let (ours, thesis, text) = match cell {
                Cell::Compare { ours, thesis } => (Some(ours), thesis.as_ref(), None),
                Cell::Num(n) => (Some(n), None, None),
                Cell::Text(t) => (None, None, Some(t.clone())),
                Cell::Empty => (None, None, None),
            };
            let main = text.unwrap_or_else(|| num(ours));
            match *kind {
                ColumnKind::Compare { ours_sd, thesis_sd } => {
                    record.push(main);
                    if ours_sd {
                        record.push(sd(ours));
                    }
                    record.push(num(thesis));
                    if thesis_sd {
                        record.push(sd(thesis));
                    }
                }
                ColumnKind::Single { sd: has_sd } => {
                    record.push(main);
                    if has_sd {
                        record.push(sd(ours));
                    }
                }
                ColumnKind::Text => record.push(main),
            }
        }
        w.write_record(&record).expect(WRITE);
    }
    let bytes = w.into_inner().expect(WRITE);
    String::from_utf8(bytes).expect("CSV of UTF-8 strings is UTF-8")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two agents of Table 6.1 (initial and cumulative, ours made up) and a
    /// plain column.
    fn small() -> Table {
        let g = NumFormat::grouped(2);
        let mut t = Table::new("table_6_1", "Maze rewards", "Agent");
        t.caption = "Mean ± sd over 25 trials.".into();
        t.columns = vec![
            ColumnGroup::new("Initial"),
            ColumnGroup::new("Cumulative").with_unit("reward"),
            ColumnGroup::new("Episodes to surpass"),
        ];
        t.rows = vec![
            Row::new(
                "SAR",
                vec![
                    Cell::compare(Num::new(-3701.5, g).with_spread(812.25), -3730.36),
                    Cell::compare(Num::new(-150000.0, g).with_spread(1234.5), -151525.96),
                    Cell::Num(Num::new(108.0, NumFormat::Integer)),
                ],
            ),
            Row::new(
                "HMN",
                vec![
                    Cell::compare(Num::new(-330.0, g), -327.5),
                    Cell::compare(Num::new(f64::NAN, g), f64::NAN),
                    Cell::Empty,
                ],
            ),
        ];
        t.notes = vec!["HMN is the *demonstrator*.".into()];
        t
    }

    #[test]
    fn csv_is_exact() {
        let t = small();
        t.check().unwrap();
        assert_eq!(
            to_csv(&t),
            "agent,initial_ours,initial_sd,initial_thesis,cumulative_ours,cumulative_sd,cumulative_thesis,episodes_to_surpass\n\
             SAR,-3701.5,812.25,-3730.36,-150000,1234.5,-151525.96,108\n\
             HMN,-330,,-327.5,,,,\n"
        );
    }

    #[test]
    fn html_has_sub_columns_dashes_and_grouping() {
        let h = to_html(&small());
        assert!(h.starts_with("<table class=\"data\" id=\"table_6_1\">\n"), "{h}");
        assert!(h.contains("<th rowspan=\"2\" class=\"stub\">Agent</th>"), "{h}");
        assert!(h.contains("<th colspan=\"2\" class=\"group\">Cumulative<br><span class=\"unit\">reward</span></th>"));
        assert_eq!(h.matches("<th class=\"ours\">ours</th><th class=\"thesis\">thesis</th>").count(), 2);
        assert!(h.contains(
            "<td class=\"ours\">−3,701.50<span class=\"sd\"> ± 812.25</span></td><td class=\"thesis\">−3,730.36</td>"
        ), "{h}");
        assert!(h.contains("<td class=\"ours\">—</td><td class=\"thesis\">—</td>"), "{h}");
        assert!(h.contains("<td class=\"num\">108</td>"));
        assert!(h.contains("<tfoot>\n<tr><td colspan=\"6\">HMN is the <em>demonstrator</em>.</td></tr>"), "{h}");
        assert!(h.ends_with("</table>\n"));
    }

    #[test]
    fn latex_is_booktabs_with_math_numbers() {
        let l = to_latex(&small());
        assert!(l.starts_with("\\begingroup\\small\n\\begin{longtable}{@{}lrrrrr@{}}\n"), "{l}");
        assert!(l.contains(
            " & \\multicolumn{2}{c}{Initial} & \\multicolumn{2}{c}{Cumulative (reward)} &  \\\\\n\
             \\cmidrule(lr){2-3}\\cmidrule(lr){4-5}\n\
             Agent & ours & \\textcolor{black!55}{thesis} & ours & \\textcolor{black!55}{thesis} & \\multicolumn{1}{>{\\raggedleft\\arraybackslash}p{44pt}}{Episodes to surpass} \\\\\n\
             \\midrule\n\\endhead\n"
        ), "{l}");
        assert!(l.contains(
            "SAR & $-3{,}701.50 \\pm 812.25$ & \\textcolor{black!55}{$-3{,}730.36$} & $-150{,}000.00 \\pm 1{,}234.50$ & \\textcolor{black!55}{$-151{,}525.96$} & $108$ \\\\\n"
        ), "{l}");
        assert!(
            l.contains(
                "HMN & $-330.00$ & \\textcolor{black!55}{$-327.50$} & --- & \\textcolor{black!55}{---} &  \\\\\n"
            ),
            "{l}"
        );
        assert!(
            l.contains("\\caption*{\\textbf{Maze rewards} Mean \\ensuremath{\\pm} sd over 25 trials.}\\\\\n"),
            "{l}"
        );
        assert!(
            l.ends_with("\\end{longtable}\n{\\footnotesize HMN is the \\emph{demonstrator}.\\par}\n\\endgroup\n"),
            "{l}"
        );
    }

    #[test]
    fn latex_escapes_every_special_character_in_cells() {
        let mut t = Table::new("specials", r"50% of $x_1$ & {y}", "Name");
        t.columns = vec![ColumnGroup::new("Value")];
        t.rows = vec![Row::new(r"a\b&c%d$e#f_g{h}i~j^k", vec![Cell::text("#1 & ~")])];
        let l = to_latex(&t);
        assert!(l.contains(
            r"a\textbackslash{}b\&c\%d\$e\#f\_g\{h\}i\textasciitilde{}j\textasciicircum{}k & \#1 \& \textasciitilde{} \\"
        ), "{l}");
        assert!(l.contains(r"\textbf{50\% of \$x\_1\$ \& \{y\}}"), "{l}");
        assert!(l.contains("{longtable}{@{}ll@{}}"), "{l}");
    }

    #[test]
    fn p_values_through_the_table() {
        let mut t = Table::new("table_6_2", "Maze p-values", "Pair");
        t.columns = vec![ColumnGroup::new("Initial"), ColumnGroup::new("Asymptotic")];
        t.rows = vec![
            Row::new(
                "SIS vs HAT",
                vec![
                    Cell::compare(Num::p_value(2.5e-90), 3.0772e-94),
                    Cell::compare(Num::p_value(0.0123456), 0.060007),
                ],
            ),
            Row::new(
                "SAR vs DIS",
                vec![Cell::compare(Num::p_value(0.62928), 0.62928), Cell::compare(Num::p_value(0.000999), 0.00005)],
            ),
        ];
        t.check().unwrap();
        assert_eq!(
            to_csv(&t),
            "pair,initial_ours,initial_thesis,asymptotic_ours,asymptotic_thesis\n\
             SIS vs HAT,2.5e-90,3.0772e-94,0.0123456,0.060007\n\
             SAR vs DIS,0.62928,0.62928,0.000999,0.00005\n"
        );
        let h = to_html(&t);
        assert!(h.contains(
            "<td class=\"ours\">2.500 × 10⁻⁹⁰<span class=\"stars\">****</span></td><td class=\"thesis\">3.077 × 10⁻⁹⁴<span class=\"stars\">****</span></td>"
        ), "{h}");
        assert!(
            h.contains(
                "<td class=\"ours\">0.01235<span class=\"stars\">*</span></td><td class=\"thesis\">0.06001</td>"
            ),
            "{h}"
        );
        assert!(h.contains("<td class=\"ours\">0.6293</td>"), "{h}");
        assert!(h.contains("<td class=\"ours\">9.990 × 10⁻⁴<span class=\"stars\">***</span></td>"), "{h}");
        let l = to_latex(&t);
        assert!(l.contains(
            "SIS vs HAT & $2.500\\times10^{-90}$\\,**** & \\textcolor{black!55}{$3.077\\times10^{-94}$\\,****} & $0.01235$\\,* & \\textcolor{black!55}{$0.06001$} \\\\"
        ), "{l}");
    }

    #[test]
    fn check_rejects_bad_shapes() {
        let mut t = small();
        t.rows[1].cells.pop();
        assert!(t.check().unwrap_err().to_string().contains("row `HMN` has 2 cells for 3 columns"));
        let mut t = small();
        t.id = "../x".into();
        assert!(t.check().is_err());
        let mut t = small();
        t.columns[2].key = "initial_sd".into();
        assert!(t.check().unwrap_err().to_string().contains("`initial_sd` appears twice"));
    }

    #[test]
    fn keys_and_percent() {
        assert_eq!(key_of("Initial reward (×1000)"), "initial_reward_1000");
        assert_eq!(key_of("Agent"), "agent");
        let n = Num::new(27.4, NumFormat::Percent { decimals: 1 });
        assert_eq!(num_html(&n), "27.4%");
        assert_eq!(num_latex(&n), "$27.4\\%$");
        assert_eq!(num_html(&Num::new(-0.004, NumFormat::fixed(2))), "0.00");
        assert_eq!(num_html(&Num::new(f64::NEG_INFINITY, NumFormat::fixed(2))), "−∞");
    }
}
