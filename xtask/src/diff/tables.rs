//! Tables compared cell by cell: a CSV (or TSV) file of each tree, read
//! after its leading `#` lines (the provenance line every data file gets),
//! with cells matched by row key and column header, not by position.
//!
//! The row key is the first column (a table's stub: `agent`, `statistic`)
//! widened, in column order, by each identifier column (text or whole
//! numbers, such as `condition` and `trial` in a data file; never a
//! measurement with a fraction) that tells more rows apart, until every row
//! of both files has its own key: `mario / QLR / 1` in `mario_metrics.csv`,
//! `0 / 3 / bnets` (study, user, algorithm) in `dbug_users.csv`, where
//! `expertise` adds nothing and is left out. When no key is unique, a row
//! is keyed by its first cell and its occurrence (`SIS #2`), so one inserted
//! row does not shift every other. Columns are matched by
//! header (a repeated header by its occurrence); cells by [`number::same`].

use std::collections::{BTreeMap, BTreeSet};

use anyhow::{Context, Result};

use super::number;

/// A parsed table: its header and rows (each padded or cut to the header's length).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Csv {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

/// One difference between two versions of a table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Change {
    Cell { row: String, column: String, old: String, new: String },
    RowAdded(String),
    RowRemoved(String),
    ColumnAdded(String),
    ColumnRemoved(String),
}

/// Reads a table: leading lines starting with `#` are skipped, then the
/// header and records (`delimiter` is `,` or a tab).
pub fn parse(bytes: &[u8], delimiter: u8) -> Result<Csv> {
    let text = String::from_utf8_lossy(bytes);
    let mut body = text.as_ref();
    while body.starts_with('#') {
        body = body.find('\n').map_or("", |i| &body[i + 1..]);
    }
    let mut reader =
        csv::ReaderBuilder::new().delimiter(delimiter).has_headers(false).flexible(true).from_reader(body.as_bytes());
    let mut records = reader.records();
    let header: Vec<String> = match records.next() {
        Some(r) => r.context("unreadable header")?.iter().map(str::to_string).collect(),
        None => Vec::new(),
    };
    let mut rows = Vec::new();
    for r in records {
        let r = r.context("unreadable record")?;
        let mut row: Vec<String> = r.iter().map(str::to_string).collect();
        row.resize(header.len(), String::new());
        rows.push(row);
    }
    Ok(Csv { header, rows })
}

/// Column names made unique: a repeated header gets ` #2`, ` #3`….
fn column_names(header: &[String]) -> Vec<String> {
    let mut seen: BTreeMap<&str, usize> = BTreeMap::new();
    header
        .iter()
        .map(|h| {
            let n = seen.entry(h).or_insert(0);
            *n += 1;
            if *n == 1 { h.clone() } else { format!("{h} #{n}") }
        })
        .collect()
}

/// A column of identifiers: text or whole numbers only.
fn identifiers(t: &Csv, column: usize) -> bool {
    t.rows.iter().all(|r| {
        let cell = r[column].trim();
        number::parse(cell).is_none()
            || cell.trim_start_matches(['-', '+', '\u{2212}']).chars().all(|c| c.is_ascii_digit())
    })
}

/// How many distinct keys the rows have on `columns`.
fn distinct(t: &Csv, columns: &[usize]) -> usize {
    let keys: BTreeSet<Vec<&str>> = t.rows.iter().map(|r| columns.iter().map(|&c| r[c].as_str()).collect()).collect();
    keys.len()
}

/// The columns that key a row in both tables, as (old index, new index):
/// the old table's first column, then each later identifier column (in the
/// old order, present in both) that tells more rows apart, until every row
/// of each table has its own key. `None` when they never do (or the new
/// table lacks the old first column).
pub fn key_columns(old: &Csv, new: &Csv) -> Option<Vec<(usize, usize)>> {
    let (old_cols, new_cols) = (column_names(&old.header), column_names(&new.header));
    let candidates: Vec<(usize, usize)> = old_cols
        .iter()
        .enumerate()
        .filter_map(|(i, c)| new_cols.iter().position(|n| n == c).map(|j| (i, j)))
        .filter(|&(i, j)| i == 0 || (identifiers(old, i) && identifiers(new, j)))
        .collect();
    if candidates.first().is_none_or(|&(i, _)| i != 0) {
        return None;
    }
    let mut key: Vec<(usize, usize)> = Vec::new();
    let mut told_apart = 0;
    for column in candidates {
        let mut wider = key.clone();
        wider.push(column);
        let (a, b) = (
            distinct(old, &wider.iter().map(|c| c.0).collect::<Vec<_>>()),
            distinct(new, &wider.iter().map(|c| c.1).collect::<Vec<_>>()),
        );
        if key.is_empty() || a + b > told_apart {
            key = wider;
            told_apart = a + b;
        }
        if told_apart == old.rows.len() + new.rows.len() {
            return Some(key);
        }
    }
    None
}

/// Every row's key, in order: its cells in `columns` joined by ` / `, or
/// (without key columns) its first cell and, from the second time it
/// occurs, its occurrence.
fn keys(t: &Csv, columns: Option<&[usize]>) -> Vec<String> {
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    t.rows
        .iter()
        .map(|r| match columns {
            Some(cs) => cs.iter().map(|&c| r[c].as_str()).collect::<Vec<_>>().join(" / "),
            None => {
                let first = r.first().cloned().unwrap_or_default();
                let n = seen.entry(first.clone()).or_insert(0);
                *n += 1;
                if *n == 1 { first } else { format!("{first} #{n}") }
            }
        })
        .collect()
}

/// What changed from `old` to `new`: columns removed and added, then, in
/// the old table's order, each shared row's changed cells or its removal,
/// then the rows added.
pub fn compare(old: &Csv, new: &Csv) -> Vec<Change> {
    let key = key_columns(old, new);
    let (old_cols, new_cols) = (column_names(&old.header), column_names(&new.header));
    let mut changes = Vec::new();
    changes.extend(old_cols.iter().filter(|c| !new_cols.contains(c)).map(|c| Change::ColumnRemoved(c.clone())));
    changes.extend(new_cols.iter().filter(|c| !old_cols.contains(c)).map(|c| Change::ColumnAdded(c.clone())));
    let shared: Vec<(usize, usize, &String)> = old_cols
        .iter()
        .enumerate()
        .filter(|(i, _)| key.as_ref().is_none_or(|k| !k.iter().any(|c| c.0 == *i)))
        .filter_map(|(i, c)| new_cols.iter().position(|n| n == c).map(|j| (i, j, c)))
        .collect();
    let old_index: Option<Vec<usize>> = key.as_ref().map(|k| k.iter().map(|c| c.0).collect());
    let new_index: Option<Vec<usize>> = key.as_ref().map(|k| k.iter().map(|c| c.1).collect());
    let (old_keys, new_keys) = (keys(old, old_index.as_deref()), keys(new, new_index.as_deref()));
    let new_rows: BTreeMap<&String, &Vec<String>> = new_keys.iter().zip(&new.rows).collect();
    for (key, row) in old_keys.iter().zip(&old.rows) {
        let Some(other) = new_rows.get(key) else {
            changes.push(Change::RowRemoved(key.clone()));
            continue;
        };
        for &(i, j, column) in &shared {
            if !number::same(&row[i], &other[j]) {
                changes.push(Change::Cell {
                    row: key.clone(),
                    column: column.clone(),
                    old: row[i].clone(),
                    new: other[j].clone(),
                });
            }
        }
    }
    let old_set: BTreeSet<&String> = old_keys.iter().collect();
    changes.extend(new_keys.iter().filter(|k| !old_set.contains(k)).map(|k| Change::RowAdded(k.clone())));
    changes
}

#[cfg(test)]
mod tests {
    use super::*;

    fn csv(text: &str) -> Csv {
        parse(text.as_bytes(), b',').unwrap()
    }

    /// The changes from `old` to `new`, one line each.
    fn check(old: &str, new: &str, expected: &[&str]) {
        let got: Vec<String> = compare(&csv(old), &csv(new))
            .into_iter()
            .map(|c| match c {
                Change::Cell { row, column, old, new } => format!("{row} | {column}: {old} -> {new}"),
                Change::RowAdded(k) => format!("+row {k}"),
                Change::RowRemoved(k) => format!("-row {k}"),
                Change::ColumnAdded(c) => format!("+column {c}"),
                Change::ColumnRemoved(c) => format!("-column {c}"),
            })
            .collect();
        assert_eq!(got, expected);
    }

    const TABLE: &str = "# generated by x; do not edit\nagent,initial_ours,initial_thesis\nSAR,-4681.8,\"-3,730.36\"\nSIS,-7000.0,-164.68\n";

    #[test]
    fn the_provenance_line_is_skipped_and_cells_match_by_key_and_header() {
        let t = csv(TABLE);
        assert_eq!(t.header, ["agent", "initial_ours", "initial_thesis"]);
        assert_eq!(t.rows.len(), 2);
        check(TABLE, &TABLE.replace("# generated by x", "# generated by y"), &[]);
        check(TABLE, &TABLE.replace("-7000.0", "-6500"), &["SIS | initial_ours: -7000.0 -> -6500"]);
        // Rows reordered, a column moved, numbers rewritten: nothing changed.
        let moved = "initial_thesis,agent,initial_ours\n-164.68,SIS,-7000\n-3730.36,SAR,\u{2212}4681.80\n";
        check(TABLE, moved, &[]);
    }

    #[test]
    fn rows_and_columns_added_and_removed() {
        let new = "agent,initial_ours,asymptotic\nSIS,-7000.0,1\nHAT,-341.2,2\n";
        check(TABLE, new, &["-column initial_thesis", "+column asymptotic", "-row SAR", "+row HAT"]);
    }

    #[test]
    fn data_files_are_keyed_by_their_leading_identifier_columns() {
        let old = "experiment,condition,trial,initial\nmario,QLR,0,-512\nmario,QLR,1,-472\nmario,SIS,0,-500\n";
        assert_eq!(key_columns(&csv(old), &csv(old)), Some(vec![(0, 0), (1, 1), (2, 2)]));
        check(old, &old.replace("-472", "-470"), &["mario / QLR / 1 | initial: -472 -> -470"]);
        // A measurement never joins the key: duplicates fall back to occurrences.
        let dup = "agent,return\nSIS,-1.5\nSIS,-2.5\n";
        assert_eq!(key_columns(&csv(dup), &csv(dup)), None);
        check(dup, &dup.replace("-2.5", "-3.5"), &["SIS #2 | return: -2.5 -> -3.5"]);
        // A numeric stub is still a key.
        let stub = "noise,reduction\n0.1,30.5\n0.2,20.5\n";
        assert_eq!(key_columns(&csv(stub), &csv(stub)), Some(vec![(0, 0)]));
        // Identifier columns after a measurement, and one that tells nothing apart.
        let users = "study,user,expertise,reaction_s,algorithm,accuracy\n0,0,novice,1.2,intrl,22.5\n0,0,novice,1.2,cba,75.9\n0,1,expert,0.5,intrl,18.4\n";
        assert_eq!(key_columns(&csv(users), &csv(users)), Some(vec![(0, 0), (1, 1), (4, 4)]));
        check(users, &users.replace("75.9", "76.0"), &["0 / 0 / cba | accuracy: 75.9 -> 76.0"]);
        // A new table without the old first column has no key.
        assert_eq!(key_columns(&csv(users), &csv("user,accuracy\n0,1\n")), None);
    }

    #[test]
    fn ragged_and_repeated_columns_do_not_break_matching() {
        let t = csv("a,b,b\nx,1\n");
        assert_eq!(t.rows, [["x", "1", ""]]);
        check("a,b,b\nx,1,2\n", "a,b,b\nx,1,3\n", &["x | b #2: 2 -> 3"]);
        assert!(csv("").header.is_empty());
    }
}
