//! Demonstrations: episodic trajectories of state vectors, with the
//! demonstrator's actions where they are known, in memory and in files.
//!
//! A [`DemonstrationSet`] holds named state variables, the number of actions
//! (when known) and at least one [`Trajectory`]; it is checked once when
//! built, so learners can rely on it. Its operations reshape a set the way
//! the thesis does before RE-IRL: [`DemonstrationSet::pad_to_equal_length`]
//! (the Maze repeats the last observation),
//! [`DemonstrationSet::prune_to_kth_longest`] (Mario cuts all to the
//! 10th-longest length), [`DemonstrationSet::first_n_observations`] and
//! [`DemonstrationSet::truncate_to`], and
//! [`DemonstrationSet::require_equal_lengths`].
//!
//! **Actions**: `actions[i]` was taken in `states[i]`; a trajectory has one
//! action per state, or one fewer when its last state (terminal) has none.
//! Either every trajectory of a set has actions or none has.
//!
//! **Files**: two formats, both read and written, both exact for `f64` (values
//! are written in the shortest form that `str::parse::<f64>` reads back to
//! the same bits, e.g. `0.30000000000000004`, `1e-300`, `-0`):
//!
//! - CSV ([`DemonstrationSet::read_csv`]): header
//!   `trajectory,step,<state names…>[,action]`, one row per state.
//! - JSON Lines ([`DemonstrationSet::read_jsonl`]): an optional header line
//!   `{"state_names":[…],"num_actions":n}`, then one line per trajectory
//!   `{"states":[[…],…],"actions":[…]}`.
//!
//! Readers take the input as bytes from any [`Read`] with a display name, or
//! from a path ([`DemonstrationSet::read_path`], format by extension), and
//! reject bad input with a [`ReadError`] naming the file, the 1-based line
//! and the field, e.g. `demos.csv:17: field "y": "abc" is not a number`.
//! They never panic on input.
//!
//! Not here: learning from demonstrations (RE-IRL, SBS, HAT) and producing
//! them (the chapters' demonstrators).

mod csv_format;
mod error;
mod json;
mod jsonl;
mod number;
mod set;

use std::io::{self, Read, Write};
use std::path::Path;

pub use error::{ReadError, ReadErrorKind, TrajectoryError, ValidationError};
pub use set::{DemonstrationSet, RESERVED_NAMES, Trajectory, default_state_names};

/// A reader's result before the file's name is attached: on error, the line
/// (if any) and what is wrong.
type Located<T> = Result<T, (Option<usize>, ReadErrorKind)>;

/// A demonstration file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// `.csv`: one row per state.
    Csv,
    /// `.jsonl` (or `.ndjson`): one trajectory per line.
    JsonLines,
}

impl Format {
    /// The format a path's extension names (any case), if any.
    pub fn from_path(path: &Path) -> Option<Format> {
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        match extension.as_str() {
            "csv" => Some(Format::Csv),
            "jsonl" | "ndjson" => Some(Format::JsonLines),
            _ => None,
        }
    }

    /// The extension written files get, without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Csv => "csv",
            Format::JsonLines => "jsonl",
        }
    }
}

impl DemonstrationSet {
    /// Reads a set in `format` from `reader`; `name` is the file's display
    /// name in error messages.
    ///
    /// `num_actions` is the domain's number of actions, if the caller knows
    /// it: every action is checked against it (with the line it is on) and
    /// the set records it; a JSON Lines header declaring another count is an
    /// error. Without it, the count is the file's declaration (JSON Lines),
    /// else the largest action + 1, else unknown (no actions).
    pub fn read<R: Read>(
        mut reader: R,
        name: &str,
        format: Format,
        num_actions: Option<usize>,
    ) -> Result<DemonstrationSet, ReadError> {
        let mut bytes = Vec::new();
        reader.read_to_end(&mut bytes).map_err(|e| located(name, (None, ReadErrorKind::Io(e))))?;
        // A UTF-8 byte order mark, as some spreadsheet programs write.
        let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&bytes);
        let result = match format {
            Format::Csv => csv_format::read(bytes, num_actions),
            Format::JsonLines => jsonl::read(bytes, num_actions),
        };
        result.map_err(|e| located(name, e))
    }

    /// Reads the CSV format:
    ///
    /// ```text
    /// trajectory,step,x,y,action
    /// 0,0,0.08,0.6,1
    /// 0,1,0.1,0.6,
    /// 1,0,0.08,0.6,2
    /// ```
    ///
    /// - The first line is the header: `trajectory`, `step`, then one column
    ///   per state variable (its name; unique, not `trajectory`, `step` or
    ///   `action`), then optionally `action`, last.
    /// - Then one row per state, with as many fields as the header.
    ///   `trajectory` is 0 on the first row and on each later row the same as
    ///   the row before or one more (trajectories are numbered from 0 and
    ///   their rows are contiguous). `step` is 0 on a trajectory's first row
    ///   and counts up by 1.
    /// - State values: any finite number `str::parse::<f64>` reads (`1`,
    ///   `-0.5`, `.5`, `1e-300`); NaN and infinities are rejected.
    /// - `action`: a non-negative whole number (`3` or `3.0`), below
    ///   `num_actions` when known; empty only on a trajectory's last row.
    /// - Cells are trimmed of surrounding spaces; fields may be quoted
    ///   (RFC 4180); empty lines are skipped; a UTF-8 byte order mark is
    ///   ignored; `\n` or `\r\n` line ends. The file must be UTF-8.
    pub fn read_csv<R: Read>(reader: R, name: &str, num_actions: Option<usize>) -> Result<DemonstrationSet, ReadError> {
        Self::read(reader, name, Format::Csv, num_actions)
    }

    /// Reads the JSON Lines format:
    ///
    /// ```text
    /// {"state_names":["x","y"],"num_actions":4}
    /// {"states":[[0.08,0.6],[0.1,0.6]],"actions":[1]}
    /// {"states":[[0.08,0.6]],"actions":[2]}
    /// ```
    ///
    /// - Each non-blank line is one JSON object (UTF-8, `\n` or `\r\n`).
    /// - The first line may be a header: an object without `states`, with
    ///   `state_names` (an array of strings, the names as in CSV) and/or
    ///   `num_actions` (an integer ≥ 1). No other keys. Without a header,
    ///   states are named `s0`, `s1`, ….
    /// - Every other line is one trajectory, with the keys `states` (required:
    ///   a non-empty array of states, each an array of numbers, one per state
    ///   name, or all of the first state's length) and `actions` (optional:
    ///   an array of non-negative whole numbers, one per state or one fewer).
    ///   No other keys, no duplicate keys. Either every trajectory has
    ///   `actions` or none has.
    /// - `NaN`, `Infinity` and `-Infinity` (as Python writes them) are read
    ///   only to be rejected with a clear message.
    pub fn read_jsonl<R: Read>(
        reader: R,
        name: &str,
        num_actions: Option<usize>,
    ) -> Result<DemonstrationSet, ReadError> {
        Self::read(reader, name, Format::JsonLines, num_actions)
    }

    /// Reads a file, in the format its extension names (`.csv`, `.jsonl`,
    /// `.ndjson`, any case); errors name the file as `path.display()` shows it.
    pub fn read_path(path: impl AsRef<Path>, num_actions: Option<usize>) -> Result<DemonstrationSet, ReadError> {
        let path = path.as_ref();
        let name = path.display().to_string();
        let format = Format::from_path(path).ok_or_else(|| located(&name, (None, ReadErrorKind::UnknownFormat)))?;
        let file = std::fs::File::open(path).map_err(|e| located(&name, (None, ReadErrorKind::Io(e))))?;
        Self::read(file, &name, format, num_actions)
    }

    /// Writes the set in `format` (see [`Self::write_csv`], [`Self::write_jsonl`]).
    pub fn write<W: Write>(&self, writer: W, format: Format) -> io::Result<()> {
        match format {
            Format::Csv => self.write_csv(writer),
            Format::JsonLines => self.write_jsonl(writer),
        }
    }
}

fn located(name: &str, (line, kind): (Option<usize>, ReadErrorKind)) -> ReadError {
    ReadError { file: name.to_owned(), line, kind }
}
