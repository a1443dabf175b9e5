//! The errors of the demonstration module: what is wrong with a trajectory or
//! a set built in memory ([`TrajectoryError`], [`ValidationError`]), and what
//! is wrong with a file, with the file, line and field it was found at
//! ([`ReadError`]).
//!
//! Every `Display` is one line without a trailing period, ready for `xtask` to
//! print after "error: ". Text that came from the user (column names, cell
//! contents) is printed quoted and escaped (`{:?}`), so a stray newline or
//! quote in a file cannot break the line, and is clipped when very long. No
//! error returns another as its `source()`: each message already contains
//! everything, and a source would make `anyhow`'s `{:#}` print it twice.
//!
//! This file holds no checks; they live beside the data they check.

use std::fmt;

use thiserror::Error;

/// What is wrong with one trajectory, without knowing which trajectory it is
/// (a [`ValidationError::Trajectory`] adds that).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TrajectoryError {
    /// A trajectory holds at least one state.
    #[error("it has no states")]
    NoStates,
    /// States hold at least one value.
    #[error("states must have at least one value")]
    ZeroDimension,
    /// A flat buffer whose length is not a multiple of the dimension.
    #[error("{values} values do not split into states of {dimension}")]
    Ragged { values: usize, dimension: usize },
    /// A state of another length than the first one (or than the set's state names).
    #[error("step {step}: expected {expected} values, found {found}")]
    StateLength { step: usize, expected: usize, found: usize },
    /// NaN or an infinity.
    #[error("step {step}, value {index} is {value} (values must be finite)")]
    NotFinite { step: usize, index: usize, value: f64 },
    /// Actions are one per state, except that the last state may have none.
    #[error(
        "expected {} or {states} actions (one per state, the last state's optional), found {actions}",
        .states.saturating_sub(1)
    )]
    ActionCount { states: usize, actions: usize },
    /// An action index at or above the number of actions.
    #[error("step {step}: action {action} is out of range 0..{num_actions}")]
    ActionOutOfRange { step: usize, action: usize, num_actions: usize },
    /// The trajectory's states do not have one value per state name of the set.
    #[error("its states have {found} values, expected {expected} (one per state name)")]
    Dimension { expected: usize, found: usize },
}

/// What is wrong with a demonstration set, or why an operation on one
/// (truncation, the equal-length check) cannot be done.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ValidationError {
    /// A set holds at least one trajectory.
    #[error("the set holds no trajectories")]
    NoTrajectories,
    /// The state names give the dimension, which is at least 1.
    #[error("there are no state names (states need at least one value)")]
    NoStateNames,
    #[error("state name {index} is empty")]
    EmptyStateName { index: usize },
    /// Readers trim cells, so such a name would not survive a round trip.
    #[error("state name {index} ({name:?}) has leading or trailing spaces")]
    PaddedStateName { index: usize, name: String },
    /// `trajectory`, `step` and `action` are the CSV format's own columns.
    #[error("state name {index} ({name:?}) is reserved for the CSV format's own columns")]
    ReservedStateName { index: usize, name: String },
    #[error("duplicate state name {name:?} (state names {first} and {second})")]
    DuplicateStateName { name: String, first: usize, second: usize },
    #[error("the number of actions must be at least 1")]
    ZeroActions,
    /// Actions are only checked, and only meaningful, against a known action count.
    #[error("trajectory {trajectory} has actions, but the number of actions is not given")]
    ActionsWithoutCount { trajectory: usize },
    #[error(
        "trajectory {with} has actions but trajectory {without} has none (either every trajectory has actions or none)"
    )]
    MixedActions { with: usize, without: usize },
    /// A problem inside one trajectory (numbered from 0).
    #[error("trajectory {index}: {error}")]
    Trajectory { index: usize, error: TrajectoryError },
    /// The first trajectory whose length differs from trajectory 0's.
    #[error(
        "trajectory {trajectory} has length {length}, but trajectory 0 has length {expected} (the trajectories must have equal lengths)"
    )]
    UnequalLengths { trajectory: usize, length: usize, expected: usize },
    #[error("cannot cut trajectories to 0 states: a trajectory needs at least one")]
    ZeroLength,
    /// The first trajectory shorter than a requested common length.
    #[error("trajectory {trajectory} has length {length}, shorter than the {requested} observations requested")]
    TooShort { trajectory: usize, length: usize, requested: usize },
    #[error("there is no k-th longest trajectory for k = {k}: k counts from 1 and the set holds {count}")]
    NoKthLongest { k: usize, count: usize },
}

/// A file that could not be read as demonstrations: where, and what.
///
/// Displays as `<file>:<line>: <kind>`, or `<file>: <kind>` when the problem
/// has no line (an empty file, an I/O error). Lines are 1-based, as an
/// editor shows them; for CSV, the line a record starts on.
#[derive(Debug)]
pub struct ReadError {
    /// The display name given to the reader (the path, for `read_path`).
    pub file: String,
    /// 1-based line, when the problem is on one.
    pub line: Option<usize>,
    pub kind: ReadErrorKind,
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // A name with a line break or another control character (a path can
        // hold one) is escaped, so the message stays one line.
        let file = FileName(&self.file);
        match self.line {
            Some(line) => write!(f, "{file}:{line}: {}", self.kind),
            None => write!(f, "{file}: {}", self.kind),
        }
    }
}

/// A file's display name, as given unless it holds a control character.
struct FileName<'a>(&'a str);

impl fmt::Display for FileName<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.chars().any(char::is_control) { write!(f, "{:?}", self.0) } else { f.write_str(self.0) }
    }
}

impl std::error::Error for ReadError {}

/// What is wrong with a demonstration file. `field` is the CSV column name or
/// the JSON key path (`states[4][1]`, `actions[2]`); `text` is the offending
/// text as it appears in the file.
#[derive(Debug, Error)]
pub enum ReadErrorKind {
    #[error("cannot read: {0}")]
    Io(std::io::Error),
    #[error("unknown file format (expected a .csv or .jsonl file)")]
    UnknownFormat,
    /// No bytes, or only whitespace.
    #[error("the file is empty")]
    Empty,
    /// A header but no trajectory.
    #[error("the file holds no trajectories")]
    NoTrajectories,
    #[error("the line is not valid UTF-8 (save the file as UTF-8)")]
    NotUtf8,
    /// The `csv` crate rejected the input (not expected for in-memory data).
    #[error("invalid CSV: {message}")]
    InvalidCsv { message: String },

    // CSV header.
    #[error("missing column {column:?} (the header must read trajectory,step,<state names…>[,action])")]
    MissingColumn { column: String },
    /// `expected` and `found` are 1-based column positions.
    #[error("column {column:?} must be column {expected}, found as column {found}")]
    MisplacedColumn { column: String, expected: usize, found: usize },
    #[error("duplicate column {column:?} (columns {first} and {second})")]
    DuplicateColumn { column: String, first: usize, second: usize },
    #[error("column {position} has no name")]
    UnnamedColumn { position: usize },
    #[error("no state columns (the header must read trajectory,step,<state names…>[,action])")]
    NoStateColumns,

    // CSV rows.
    #[error("expected {expected} fields, found {found}")]
    FieldCount { expected: usize, found: usize },
    /// Rows of one trajectory are contiguous and trajectories count up from 0,
    /// so a row's trajectory is the current one or the next; `current` is
    /// `None` on the first row, which must be trajectory 0.
    #[error(
        "field \"trajectory\": expected {}, found {found} (trajectories are numbered from 0 and their rows are contiguous)",
        ExpectedTrajectory(*.current)
    )]
    TrajectoryNumber { current: Option<usize>, found: usize },
    #[error("field \"step\": expected {expected}, found {found} (steps must count up from 0 within a trajectory)")]
    StepNumber { expected: usize, found: usize },
    /// An empty action cell before the last row of its trajectory (the line is
    /// the empty cell's).
    #[error("field \"action\": missing (only the last state of a trajectory may have no action)")]
    ActionMissing,

    // Cells and JSON values, both formats.
    #[error("field {field:?}: the value is missing")]
    MissingValue { field: String },
    #[error("field {field:?}: {} is not a number", Quoted(.text))]
    NotANumber { field: String, text: String },
    /// NaN, inf, infinity (any case and sign) or JSON's non-standard `NaN`/`Infinity`.
    #[error("field {field:?}: {} is not allowed", Clipped(.text))]
    NotFinite { field: String, text: String },
    /// A literal that rounds to infinity, such as `1e400`.
    #[error("field {field:?}: {} is too large for a 64-bit float", Clipped(.text))]
    TooLarge { field: String, text: String },
    /// `trajectory` and `step` are non-negative integers written without a fraction.
    #[error("field {field:?}: {} is not a non-negative integer", Quoted(.text))]
    NotAnInteger { field: String, text: String },
    #[error("field {field:?}: {} is negative (actions are numbered from 0)", Clipped(.text))]
    NegativeAction { field: String, text: String },
    #[error("field {field:?}: {} is not a whole number (actions are numbered from 0)", Clipped(.text))]
    FractionalAction { field: String, text: String },
    #[error("field {field:?}: {} is out of range 0..{num_actions}", Clipped(.text))]
    ActionOutOfRange { field: String, text: String, num_actions: usize },
    /// An action above 2^53 while the number of actions is not known.
    #[error("field {field:?}: {} is too large to be an action", Clipped(.text))]
    ActionTooLarge { field: String, text: String },
    /// Actions are present but every one is empty (each trajectory is one
    /// terminal state), and the caller did not give the number of actions:
    /// there is nothing to count it from. `hint` says how the file can say it.
    #[error("field {field:?}: no trajectory has an action, so the number of actions is unknown{hint}")]
    NoActionToCount { field: String, hint: &'static str },

    // JSON Lines.
    /// `column` is 1-based and counts characters.
    #[error("invalid JSON at column {column}: {message}")]
    InvalidJson { column: usize, message: String },
    #[error("expected a JSON object, found {found}")]
    NotAnObject { found: &'static str },
    #[error("unknown key {key:?} (expected {expected})")]
    UnknownKey { key: String, expected: &'static str },
    #[error("duplicate key {key:?}")]
    DuplicateKey { key: String },
    #[error("missing key {key:?}")]
    MissingKey { key: &'static str },
    #[error("field {field:?}: expected {expected}, found {found}")]
    WrongType { field: String, expected: &'static str, found: &'static str },
    #[error("field {field:?}: a state needs at least one value")]
    EmptyState { field: String },
    #[error("field {field:?}: expected {expected} values, found {found}")]
    StateLength { field: String, expected: usize, found: usize },
    #[error("field \"states\": the trajectory has no states")]
    NoStates,
    #[error(
        "field \"actions\": expected {} or {states} actions (one per state, the last state's optional), found {actions}",
        .states.saturating_sub(1)
    )]
    ActionCount { states: usize, actions: usize },
    /// `has_actions` is this line's trajectory; `other_line` holds the first
    /// trajectory, which decided whether the file has actions.
    #[error(
        "field \"actions\": {}, but the trajectory on line {other_line} {} (either every trajectory has actions or none)",
        if *.has_actions { "present" } else { "missing" },
        if *.has_actions { "has none" } else { "has actions" }
    )]
    MixedActions { has_actions: bool, other_line: usize },
    #[error("a header line (with \"state_names\" or \"num_actions\") may only come first")]
    MisplacedHeader,
    #[error(
        "field \"num_actions\": {} is not a valid number of actions (expected a whole number, at least 1)",
        Clipped(.text)
    )]
    InvalidActionCount { text: String },
    #[error("field \"num_actions\": the file declares {declared} actions, but {expected} were expected")]
    ActionCountMismatch { declared: usize, expected: usize },

    /// A set-level problem found after parsing, such as invalid state names.
    #[error("{0}")]
    Invalid(ValidationError),
}

/// Longest user text shown in a message, in characters.
const CLIP: usize = 40;

/// User text, clipped; for text already known to be a number-like token.
struct Clipped<'a>(&'a str);

impl fmt::Display for Clipped<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.char_indices().nth(CLIP) {
            Some((end, _)) => write!(f, "{}…", &self.0[..end]),
            None => f.write_str(self.0),
        }
    }
}

/// User text, clipped, quoted and escaped: it may hold anything.
struct Quoted<'a>(&'a str);

impl fmt::Display for Quoted<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.char_indices().nth(CLIP) {
            Some((end, _)) => write!(f, "{:?}…", &self.0[..end]),
            None => write!(f, "{:?}", self.0),
        }
    }
}

struct ExpectedTrajectory(Option<usize>);

impl fmt::Display for ExpectedTrajectory {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            None => f.write_str("0"),
            Some(current) => write!(f, "{current} or {}", current + 1),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_user_text_is_clipped_and_quoted() {
        let text = format!("{}\n", "a".repeat(50));
        let kind = ReadErrorKind::NotANumber { field: "x".into(), text };
        assert_eq!(kind.to_string(), format!("field \"x\": \"{}\"… is not a number", "a".repeat(40)));
    }

    #[test]
    fn file_names_with_control_characters_are_escaped() {
        let error = ReadError { file: "a\nb.csv".into(), line: Some(2), kind: ReadErrorKind::ActionMissing };
        assert_eq!(
            error.to_string(),
            r#""a\nb.csv":2: field "action": missing (only the last state of a trajectory may have no action)"#
        );
        let error = ReadError { file: "plain é.csv".into(), line: None, kind: ReadErrorKind::Empty };
        assert_eq!(error.to_string(), "plain é.csv: the file is empty");
    }

    #[test]
    fn newlines_in_user_text_stay_escaped() {
        let kind = ReadErrorKind::NotANumber { field: "a\nb".into(), text: "1\n2".into() };
        assert_eq!(kind.to_string(), r#"field "a\nb": "1\n2" is not a number"#);
    }
}
