//! The CSV demonstration format: reading with per-line, per-column checks,
//! and writing that reads back bit for bit.
//!
//! ```text
//! trajectory,step,x,y,action
//! 0,0,0.08,0.6,1
//! 0,1,0.1,0.6,
//! 1,0,0.08,0.6,2
//! ```
//!
//! One header line, then one row per state. `trajectory` counts from 0 and
//! each trajectory's rows are contiguous; `step` counts from 0 within each
//! trajectory. Then one column per state variable, then an optional
//! `action` column whose cell may be empty only on a trajectory's last row
//! (see the action convention in `set.rs`). The file does not record the
//! number of actions: the reader takes it from the caller or, failing that,
//! infers it as the largest action + 1.
//!
//! Not here: the data checks shared with JSON Lines (`number.rs`) and the
//! set's own checks (`set.rs`).

use std::io::{self, Write};

use super::Located;
use super::error::{ReadErrorKind, ValidationError};
use super::number::{parse_action, parse_counter, parse_value, push_f64};
use super::set::{DemonstrationSet, Trajectory, check_state_names};

/// The checked header: where the state columns are and whether there is an
/// action column.
struct Header {
    /// All column names, for field names in errors.
    columns: Vec<String>,
    has_action: bool,
}

impl Header {
    fn state_names(&self) -> &[String] {
        let end = self.columns.len() - usize::from(self.has_action);
        &self.columns[2..end]
    }
}

/// A trajectory being read.
struct Building {
    values: Vec<f64>,
    actions: Vec<usize>,
    /// The line of an empty action cell, allowed only if no row follows.
    empty_action_line: Option<usize>,
    rows: usize,
}

impl Building {
    fn new() -> Self {
        Self { values: Vec::new(), actions: Vec::new(), empty_action_line: None, rows: 0 }
    }
}

pub(crate) fn read(bytes: &[u8], num_actions: Option<usize>) -> Located<DemonstrationSet> {
    if bytes.iter().all(u8::is_ascii_whitespace) {
        return Err((None, ReadErrorKind::Empty));
    }
    let mut reader = csv::ReaderBuilder::new()
        // The header is checked here, with its line number and our messages.
        .has_headers(false)
        // Unequal row lengths are reported here, with the expected count.
        .flexible(true)
        // Spaces after commas are common in hand-written files.
        .trim(csv::Trim::All)
        .from_reader(bytes);
    let mut record = csv::ByteRecord::new();

    if !next_record(&mut reader, &mut record)? {
        return Err((None, ReadErrorKind::Empty));
    }
    let header_line = line_of(&record);
    let header = read_header(&record).map_err(|kind| (Some(header_line), kind))?;
    let dimension = header.state_names().len();

    let mut finished: Vec<Trajectory> = Vec::new();
    let mut current = Building::new();
    let mut max_action: Option<usize> = None;
    let mut first_row_line = None;
    while next_record(&mut reader, &mut record)? {
        let line = line_of(&record);
        first_row_line.get_or_insert(line);
        let at_line = |kind| (Some(line), kind);
        if record.len() != header.columns.len() {
            return Err(at_line(ReadErrorKind::FieldCount { expected: header.columns.len(), found: record.len() }));
        }
        let fields = record
            .iter()
            .map(std::str::from_utf8)
            .collect::<Result<Vec<&str>, _>>()
            .map_err(|_| at_line(ReadErrorKind::NotUtf8))?;

        let trajectory = parse_counter(fields[0], "trajectory").map_err(at_line)?;
        let current_index = (current.rows > 0).then_some(finished.len());
        match current_index {
            None if trajectory == 0 => {}
            Some(index) if trajectory == index => {
                if let Some(empty_line) = current.empty_action_line {
                    return Err((Some(empty_line), ReadErrorKind::ActionMissing));
                }
            }
            Some(index) if trajectory == index + 1 => {
                let done = std::mem::replace(&mut current, Building::new());
                finished.push(finish(done, dimension, header.has_action, index)?);
            }
            _ => {
                return Err(at_line(ReadErrorKind::TrajectoryNumber { current: current_index, found: trajectory }));
            }
        }

        let step = parse_counter(fields[1], "step").map_err(at_line)?;
        if step != current.rows {
            return Err(at_line(ReadErrorKind::StepNumber { expected: current.rows, found: step }));
        }

        for (text, name) in fields[2..2 + dimension].iter().zip(header.state_names()) {
            current.values.push(parse_value(text, || name.clone()).map_err(at_line)?);
        }
        if header.has_action {
            let text = fields[fields.len() - 1];
            if text.is_empty() {
                current.empty_action_line = Some(line);
            } else {
                let action = parse_action(text, num_actions, || "action".to_owned()).map_err(at_line)?;
                max_action = max_action.max(Some(action));
                current.actions.push(action);
            }
        }
        current.rows += 1;
    }
    if current.rows == 0 {
        return Err((None, ReadErrorKind::NoTrajectories));
    }
    let index = finished.len();
    finished.push(finish(current, dimension, header.has_action, index)?);

    if header.has_action && num_actions.is_none() && max_action.is_none() {
        let hint = " (pass it to the reader, or drop the empty \"action\" column)";
        return Err((first_row_line, ReadErrorKind::NoActionToCount { field: "action".to_owned(), hint }));
    }
    // Parsing checks what `new` checks (the header's names included), so
    // this error has no line; it is not expected.
    let num_actions = num_actions.or(max_action.map(|a| a + 1));
    DemonstrationSet::new(header.state_names().to_vec(), num_actions, finished)
        .map_err(|e| (None, ReadErrorKind::Invalid(e)))
}

/// Reads the next record; `false` at the end of the input.
fn next_record(reader: &mut csv::Reader<&[u8]>, record: &mut csv::ByteRecord) -> Located<bool> {
    reader.read_byte_record(record).map_err(|e| {
        let line = e.position().map(|p| usize::try_from(p.line()).unwrap_or(usize::MAX));
        (line, ReadErrorKind::InvalidCsv { message: e.to_string() })
    })
}

fn line_of(record: &csv::ByteRecord) -> usize {
    record.position().map_or(0, |p| usize::try_from(p.line()).unwrap_or(usize::MAX))
}

fn read_header(record: &csv::ByteRecord) -> Result<Header, ReadErrorKind> {
    let columns = record
        .iter()
        .map(|field| std::str::from_utf8(field).map(str::to_owned))
        .collect::<Result<Vec<String>, _>>()
        .map_err(|_| ReadErrorKind::NotUtf8)?;
    // Where each name was first seen (a map, not a scan: a hostile header
    // may hold a hundred thousand columns).
    let mut seen = std::collections::BTreeMap::new();
    for (index, name) in columns.iter().enumerate() {
        if name.is_empty() {
            return Err(ReadErrorKind::UnnamedColumn { position: index + 1 });
        }
        if let Some(first) = seen.insert(name.as_str(), index) {
            return Err(ReadErrorKind::DuplicateColumn { column: name.clone(), first: first + 1, second: index + 1 });
        }
    }
    let position = |name: &str| columns.iter().position(|c| c == name);
    for (expected, name) in [(0, "trajectory"), (1, "step")] {
        match position(name) {
            Some(found) if found == expected => {}
            Some(found) => {
                return Err(ReadErrorKind::MisplacedColumn {
                    column: name.to_owned(),
                    expected: expected + 1,
                    found: found + 1,
                });
            }
            None => {
                return Err(ReadErrorKind::MissingColumn { column: name.to_owned() });
            }
        }
    }
    let has_action = match position("action") {
        None => false,
        Some(found) if found + 1 == columns.len() => true,
        Some(found) => {
            return Err(ReadErrorKind::MisplacedColumn {
                column: "action".to_owned(),
                expected: columns.len(),
                found: found + 1,
            });
        }
    };
    let header = Header { columns, has_action };
    if header.state_names().is_empty() {
        return Err(ReadErrorKind::NoStateColumns);
    }
    // Cells are trimmed of ASCII spaces only, so a name may still start or
    // end with another space (a no-break space, a vertical tab): refused
    // here, on the header's line, rather than by the set without one.
    check_state_names(header.state_names()).map_err(ReadErrorKind::Invalid)?;
    Ok(header)
}

/// A finished trajectory; all its values were checked as they were read.
fn finish(building: Building, dimension: usize, has_action: bool, index: usize) -> Located<Trajectory> {
    let actions = has_action.then_some(building.actions);
    Trajectory::new(building.values, dimension, actions).map_err(|error| {
        // Unreachable: rows were checked one by one. Kept as an error, not a
        // panic, because it is still about the input.
        (None, ReadErrorKind::Invalid(ValidationError::Trajectory { index, error }))
    })
}

impl DemonstrationSet {
    /// Writes the set as CSV (see `DemonstrationSet::read_csv` for the format),
    /// with `\n` line ends. Every value reads back to the same bits. The
    /// number of actions is not written: pass it when reading back.
    pub fn write_csv<W: Write>(&self, writer: W) -> io::Result<()> {
        let mut out = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(writer);
        let has_actions = self.has_actions();
        let mut header: Vec<&str> = vec!["trajectory", "step"];
        header.extend(self.state_names().iter().map(String::as_str));
        if has_actions {
            header.push("action");
        }
        out.write_record(&header)?;

        let mut cell = String::new();
        for (index, trajectory) in self.trajectories().iter().enumerate() {
            for (step, (state, action)) in trajectory.steps().enumerate() {
                write_cell(&mut out, &mut cell, format_args!("{index}"))?;
                write_cell(&mut out, &mut cell, format_args!("{step}"))?;
                for &x in state {
                    cell.clear();
                    push_f64(&mut cell, x);
                    out.write_field(&cell)?;
                }
                match action {
                    Some(a) => write_cell(&mut out, &mut cell, format_args!("{a}"))?,
                    // The last state's missing action: an empty cell.
                    None if has_actions => out.write_field(b"")?,
                    None => {}
                }
                out.write_record(None::<&[u8]>)?;
            }
        }
        out.flush()?;
        Ok(())
    }
}

/// Writes one formatted cell through a reused buffer (no allocation per cell).
fn write_cell<W: Write>(out: &mut csv::Writer<W>, cell: &mut String, value: std::fmt::Arguments<'_>) -> io::Result<()> {
    use std::fmt::Write as _;
    cell.clear();
    // Writing to a `String` cannot fail.
    let _ = cell.write_fmt(value);
    out.write_field(cell.as_bytes())?;
    Ok(())
}
