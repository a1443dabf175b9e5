//! A chapter's data files from typed rows: each row a `#[derive(Serialize)]`
//! struct whose field names are the header, written by the `csv` crate (its
//! quoting, its shortest round-trip floats), so no chapter writes CSV by hand.

use serde::Serialize;

/// The CSV of `rows`, with a header from the row type's field names (none
/// when there is no row: the header comes from the first row).
pub fn csv_of<T: Serialize>(rows: impl IntoIterator<Item = T>) -> Vec<u8> {
    let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
    for row in rows {
        w.serialize(row).expect("a flat row serialises to memory");
    }
    w.into_inner().expect("writing to memory")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Serialize)]
    struct Row<'a> {
        condition: &'a str,
        trial: usize,
        minutes: f64,
        censored: bool,
        note: Option<u32>,
    }

    #[test]
    fn rows_with_a_header_quoted_where_needed() {
        let csv = csv_of([
            Row { condition: "large, guided", trial: 0, minutes: 12.5, censored: false, note: None },
            Row { condition: "small", trial: 1, minutes: 3.0, censored: true, note: Some(4) },
        ]);
        assert_eq!(
            String::from_utf8(csv).unwrap(),
            "condition,trial,minutes,censored,note\n\"large, guided\",0,12.5,false,\n small,1,3.0,true,4\n"
                .replace("\n ", "\n")
        );
        assert!(csv_of(Vec::<Row>::new()).is_empty());
    }
}
