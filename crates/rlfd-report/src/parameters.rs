//! A chapter's parameter table: one row per parameter with its value and
//! where the value comes from (the thesis, our choice with why, a
//! calibration on an input, a cited source), built by [`Parameters`] and
//! shown in the "Parameters" section (also written as `<id>.csv`).

use crate::prose::fill;
use crate::table::{Cell, ColumnGroup, Row, Table};
use crate::{Error, Result};

/// Rows of `Parameter | Value | Source`, in the order they are added.
#[derive(Debug)]
pub struct Parameters {
    table: Table,
    /// The first placeholder that did not fill, reported by [`Parameters::table`].
    error: Option<Error>,
}

impl Parameters {
    /// An empty table with the columns `Value` and `Source`.
    pub fn new(id: &str, title: &str) -> Parameters {
        let mut table = Table::new(id, title, "Parameter");
        table.columns = vec![ColumnGroup::new("Value"), ColumnGroup::new("Source")];
        Parameters { table, error: None }
    }

    /// A value the thesis gives, as used: source `thesis`.
    pub fn thesis(&mut self, name: &str, value: impl ToString) -> &mut Parameters {
        self.row(name, value, "thesis")
    }

    /// A value with what the thesis says of it: source `thesis: <says>`,
    /// where `says` may name published values (`{ch6.maze.trials} (paper
    /// scale)`, see [`fill`]).
    pub fn thesis_says(&mut self, name: &str, value: impl ToString, says: &str) -> &mut Parameters {
        match fill(says, &[]) {
            Ok(says) => self.row(name, value, &format!("thesis: {says}")),
            Err(reason) => {
                let table = self.table.id.clone();
                self.error.get_or_insert(Error::Table { table, reason: format!("parameter `{name}`: {reason}") });
                self
            }
        }
    }

    /// A value calibrated on an input the thesis reports: source
    /// `calibrated on <input>`, or `calibrated` when `input` is empty.
    pub fn calibrated(&mut self, name: &str, value: impl ToString, input: &str) -> &mut Parameters {
        let source = if input.is_empty() { "calibrated".to_owned() } else { format!("calibrated on {input}") };
        self.row(name, value, &source)
    }

    /// Any other source, written as given: our choice and why (`our choice:
    /// half a tile`), or a cited paper or spec section.
    pub fn row(&mut self, name: &str, value: impl ToString, source: &str) -> &mut Parameters {
        self.table.rows.push(Row::new(name, vec![Cell::text(value.to_string()), Cell::text(source)]));
        self
    }

    /// The checked table, or the first placeholder that did not fill.
    pub fn table(self) -> Result<Table> {
        if let Some(e) = self.error {
            return Err(e);
        }
        self.table.check()?;
        Ok(self.table)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_carry_their_source() {
        let mut p = Parameters::new("parameters", "Parameters");
        p.thesis("α", 0.25)
            .thesis_says("Trials", 3, "{ch3.table_3_2.trials}")
            .calibrated("Unit", "0.5 s", "the 9.8 s")
            .calibrated("Slip", 0.1, "");
        p.row("ε", 0.1, "our choice");
        let t = p.table().unwrap();
        let sources: Vec<&Cell> = t.rows.iter().map(|r| &r.cells[1]).collect();
        assert_eq!(
            sources,
            [
                &Cell::text("thesis"),
                &Cell::text("thesis: 3"),
                &Cell::text("calibrated on the 9.8 s"),
                &Cell::text("calibrated"),
                &Cell::text("our choice")
            ]
        );
        assert_eq!(t.columns[0].key, "value");
        assert_eq!(t.stub_header, "Parameter");
        let mut p = Parameters::new("parameters", "Parameters");
        p.thesis_says("Trials", 3, "{ch3.nope}");
        assert!(p.table().unwrap_err().to_string().contains("parameter `Trials`"));
    }
}
