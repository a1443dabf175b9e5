//! The thesis's published values and its findings as checkable claims: the
//! only place in the workspace that knows them. Both ship inside the crate
//! (`data/thesis-numbers.toml` and `data/claims.md`, copies of the spec) and
//! are parsed once, on first use, by [`published`].
//!
//! Values are addressed by dotted paths following the TOML's keys and the
//! thesis's own labels: `numbers("ch6.maze.table_6_1.initial")`, or one cell
//! through the table's label array with
//! `table_value("ch6.maze.table_6_2", "initial", "SIS vs HAT")`. A TOML `nan`
//! stays NaN (a cell the thesis leaves empty); the thesis's `"N/A"` marker
//! reads as NaN too.

use std::sync::OnceLock;

use crate::{Error, Result};

const NUMBERS_TOML: &str = include_str!("../data/thesis-numbers.toml");
const CLAIMS_MD: &str = include_str!("../data/claims.md");

/// The names a table's row-label array may have, in the order they are tried.
const LABEL_KEYS: [&str; 4] = ["agents", "pairs", "methods", "conditions"];

/// One claim of `claims.md`: what the thesis found and how we test it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SpecClaim {
    /// `C6.1`.
    pub id: String,
    /// The thesis chapter, from the `## Chapter N` heading above the claim.
    pub chapter: u8,
    /// The finding, as worded in `claims.md`.
    pub statement: String,
    /// The test that decides it.
    pub test: String,
}

/// The parsed published values and claims.
#[derive(Debug)]
pub struct Published {
    numbers: toml::Table,
    claims: Vec<SpecClaim>,
}

/// The thesis's published values and claims, parsed once from the embedded
/// data. Panics only if the embedded files are broken, which the tests below
/// rule out.
pub fn published() -> &'static Published {
    static PUBLISHED: OnceLock<Published> = OnceLock::new();
    PUBLISHED.get_or_init(|| {
        Published::parse(NUMBERS_TOML, CLAIMS_MD)
            .expect("the embedded thesis-numbers.toml and claims.md parse (tested)")
    })
}

impl Published {
    /// Parses a `thesis-numbers.toml` and a `claims.md`.
    pub fn parse(numbers_toml: &str, claims_md: &str) -> Result<Published> {
        let numbers: toml::Table = toml::from_str(numbers_toml)
            .map_err(|e| Error::Published { path: "thesis-numbers.toml".into(), reason: e.to_string() })?;
        let claims = parse_claims(claims_md)?;
        Ok(Published { numbers, claims })
    }

    /// The TOML value at a dotted `path`.
    pub fn value(&self, path: &str) -> Result<&toml::Value> {
        let mut keys = path.split('.');
        let first = keys.next().unwrap_or_default();
        let mut value = self.numbers.get(first).ok_or_else(|| missing(path, first))?;
        for key in keys {
            value = value.as_table().and_then(|t| t.get(key)).ok_or_else(|| missing(path, key))?;
        }
        Ok(value)
    }

    /// One number (an integer or a float).
    pub fn number(&self, path: &str) -> Result<f64> {
        as_number(self.value(path)?).ok_or_else(|| wrong_type(path, "a number"))
    }

    /// An array of numbers; `nan` and the thesis's `"N/A"` read as NaN.
    pub fn numbers(&self, path: &str) -> Result<Vec<f64>> {
        let array = self.value(path)?.as_array().ok_or_else(|| wrong_type(path, "an array"))?;
        array
            .iter()
            .map(|v| match v {
                toml::Value::String(s) if s == "N/A" => Some(f64::NAN),
                other => as_number(other),
            })
            .collect::<Option<Vec<f64>>>()
            .ok_or_else(|| wrong_type(path, "an array of numbers"))
    }

    /// One string.
    pub fn string(&self, path: &str) -> Result<&str> {
        self.value(path)?.as_str().ok_or_else(|| wrong_type(path, "a string"))
    }

    /// An array of strings.
    pub fn strings(&self, path: &str) -> Result<Vec<String>> {
        let array = self.value(path)?.as_array().ok_or_else(|| wrong_type(path, "an array"))?;
        array
            .iter()
            .map(|v| v.as_str().map(str::to_owned))
            .collect::<Option<Vec<String>>>()
            .ok_or_else(|| wrong_type(path, "an array of strings"))
    }

    /// The row labels of a table: its `agents`, `pairs`, `methods` or
    /// `conditions` array, whichever comes first in that order.
    pub fn row_labels(&self, table_path: &str) -> Result<Vec<String>> {
        let table = self.value(table_path)?.as_table().ok_or_else(|| wrong_type(table_path, "a table"))?;
        let key = LABEL_KEYS.iter().find(|k| table.contains_key(**k)).ok_or_else(|| Error::Published {
            path: table_path.into(),
            reason: format!("has no label array (one of {})", LABEL_KEYS.join(", ")),
        })?;
        self.strings(&format!("{table_path}.{key}"))
    }

    /// One published cell: the `column` array of the table at `table_path`,
    /// at the position of `row_label` in the table's label array.
    /// `table_value("ch6.maze.table_6_2", "initial", "SIS vs HAT")` is 3.0772e-94.
    pub fn table_value(&self, table_path: &str, column: &str, row_label: &str) -> Result<f64> {
        let labels = self.row_labels(table_path)?;
        let row = labels.iter().position(|l| l == row_label).ok_or_else(|| Error::Published {
            path: table_path.into(),
            reason: format!("no row labelled `{row_label}` (rows: {})", labels.join(", ")),
        })?;
        let column_path = format!("{table_path}.{column}");
        let values = self.numbers(&column_path)?;
        values.get(row).copied().ok_or_else(|| Error::Published {
            path: column_path,
            reason: format!("has {} values, fewer than its {} labels", values.len(), labels.len()),
        })
    }

    /// Every claim of `claims.md`, in the file's order.
    pub fn claims(&self) -> &[SpecClaim] {
        &self.claims
    }

    /// The claim with this id.
    pub fn claim(&self, id: &str) -> Result<&SpecClaim> {
        self.claims.iter().find(|c| c.id == id).ok_or_else(|| Error::UnknownClaim(id.into()))
    }
}

fn as_number(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

fn missing(path: &str, key: &str) -> Error {
    Error::Published { path: path.into(), reason: format!("no key `{key}`") }
}

fn wrong_type(path: &str, wanted: &str) -> Error {
    Error::Published { path: path.into(), reason: format!("is not {wanted}") }
}

/// Reads the `| id | claim | test |` rows under each `## Chapter N` heading.
fn parse_claims(md: &str) -> Result<Vec<SpecClaim>> {
    let bad = |line: usize, reason: String| Error::Published { path: format!("claims.md:{line}"), reason };
    let mut chapter: Option<u8> = None;
    let mut claims = Vec::new();
    for (i, line) in md.lines().enumerate() {
        let line_no = i + 1;
        let line = line.trim();
        if let Some(heading) = line.strip_prefix("## Chapter ") {
            let n = heading.trim().parse().map_err(|_| bad(line_no, format!("chapter heading `{line}`")))?;
            chapter = Some(n);
            continue;
        }
        let Some(row) = line.strip_prefix('|').and_then(|r| r.strip_suffix('|')) else {
            continue;
        };
        let cells: Vec<&str> = row.split('|').map(str::trim).collect();
        let id = cells[0];
        if !(id.starts_with('C') && id[1..].starts_with(|c: char| c.is_ascii_digit())) {
            continue; // the header row and the `|---|` separator
        }
        let [id, statement, test] = cells[..] else {
            return Err(bad(line_no, format!("claim row has {} cells, not 3", cells.len())));
        };
        let chapter = chapter.ok_or_else(|| bad(line_no, "claim before any chapter".into()))?;
        if !id.starts_with(&format!("C{chapter}.")) {
            return Err(bad(line_no, format!("claim {id} under chapter {chapter}")));
        }
        if claims.iter().any(|c: &SpecClaim| c.id == id) {
            return Err(bad(line_no, format!("claim {id} listed twice")));
        }
        claims.push(SpecClaim { id: id.into(), chapter, statement: statement.into(), test: test.into() });
    }
    Ok(claims)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spot_checks_of_published_values() {
        let p = published();
        assert_eq!(p.table_value("ch6.maze.table_6_2", "initial", "SIS vs HAT").unwrap(), 3.0772e-94);
        assert_eq!(p.table_value("ch6.maze.table_6_1", "cumulative", "SIS").unwrap(), -93591.96);
        assert!(p.table_value("ch6.maze.table_6_1", "cumulative", "HMN").unwrap().is_nan());
        assert_eq!(p.table_value("ch6.mario.table_6_4", "asymptotic", "DIS vs SBS").unwrap(), 9.1049e-05);
        assert_eq!(p.table_value("ch5.table_5_3", "total", "Subjects A + C Best").unwrap(), 431.0);
        assert_eq!(
            p.numbers("ch6.maze.table_6_1.initial").unwrap(),
            [-3730.36, -7973.16, -3494.08, -164.68, -324.04, -327.5]
        );
        assert!(p.numbers("ch5.table_5_1.jumpstart").unwrap()[0].is_nan());
        assert_eq!(p.number("ch6.maze.demos.mean_steps").unwrap(), 337.5);
        assert_eq!(p.number("ch6.maze.trials").unwrap(), 25.0);
        assert_eq!(p.string("ch6.maze.params.alpha").unwrap(), "0.25/32");
        assert_eq!(p.strings("ch3.table_3_2.conditions").unwrap()[3], "large_no_guidance");
        assert_eq!(p.row_labels("ch6.mario.table_6_3").unwrap()[0], "QLR");
    }

    #[test]
    fn bad_paths_and_types_are_errors() {
        let p = published();
        let err = p.number("ch6.maze.nope").unwrap_err().to_string();
        assert!(err.contains("no key `nope`"), "{err}");
        assert!(p.number("ch6.maze.table_6_1.agents").is_err());
        assert!(p.numbers("ch6.maze.table_6_1.agents").is_err());
        assert!(p.strings("ch6.maze.table_6_1.initial").is_err());
        assert!(p.table_value("ch6.maze.table_6_1", "initial", "QLR").is_err());
        assert!(p.table_value("ch6.maze", "initial", "SAR").is_err());
    }

    #[test]
    fn every_claim_parses_in_order() {
        let claims = published().claims();
        let ids: Vec<&str> = claims.iter().map(|c| c.id.as_str()).collect();
        let mut want = Vec::new();
        for (chapter, count) in [(3, 5), (4, 9), (5, 10), (6, 13)] {
            for i in 1..=count {
                want.push(format!("C{chapter}.{i}"));
            }
        }
        assert_eq!(ids, want);
        // 5 + 9 + 10 + 13: round 3 added C6.12 and C6.13.
        assert_eq!(claims.len(), 37);
        let c61 = published().claim("C6.1").unwrap();
        assert_eq!(c61.chapter, 6);
        assert_eq!(c61.statement, "Maze: SIS and DIS collect more cumulative reward than SARSA, HAT and SBS");
        assert_eq!(c61.test, "t-tests, p < 1e-4");
        assert!(matches!(published().claim("C7.1"), Err(Error::UnknownClaim(_))));
    }

    #[test]
    fn the_embedded_files_are_the_spec() {
        // The crate ships copies of the spec; the copies must not drift.
        let spec = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/spec");
        for (name, embedded) in [("thesis-numbers.toml", NUMBERS_TOML), ("claims.md", CLAIMS_MD)] {
            if let Ok(text) = std::fs::read_to_string(spec.join(name)) {
                assert_eq!(text, embedded, "data/{name} differs from shared/spec/{name}");
            }
        }
    }
}
