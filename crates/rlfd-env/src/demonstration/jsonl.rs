//! The JSON Lines demonstration format: reading with per-line, per-key
//! checks, and writing that reads back bit for bit.
//!
//! ```text
//! {"state_names":["x","y"],"num_actions":4}
//! {"states":[[0.08,0.6],[0.1,0.6]],"actions":[1]}
//! {"states":[[0.08,0.6]],"actions":[2]}
//! ```
//!
//! One JSON object per line. An optional first line is a header (an object
//! with `state_names` and/or `num_actions` and no `states`); every other line
//! is one trajectory: `states`, an array of states (arrays of numbers, all of
//! one length), and optionally `actions`, an array of action indices, one per
//! state or one fewer (see the action convention in `set.rs`). Either every
//! trajectory has `actions` or none has. Blank lines are skipped. Without a
//! header, states are named `s0`, `s1`, …
//!
//! Not here: JSON syntax (`json.rs`) and the number checks shared with CSV
//! (`number.rs`).

use std::io::{self, Write};

use super::Located;
use super::error::ReadErrorKind;
use super::json::{self, Value};
use super::number::{parse_action, parse_value, push_f64};
use super::set::{DemonstrationSet, Trajectory, check_state_names, default_state_names};

const HEADER_KEYS: &str = "\"state_names\" and \"num_actions\"";
const TRAJECTORY_KEYS: &str = "\"states\" and optionally \"actions\"";

/// What the lines read so far have settled.
struct Reading {
    /// The caller's action count, else the header's.
    num_actions: Option<usize>,
    state_names: Option<Vec<String>>,
    /// From the header's names, else from the first state.
    dimension: Option<usize>,
    /// Whether the first trajectory had actions, and its line.
    actions_on: Option<(bool, usize)>,
    max_action: Option<usize>,
    trajectories: Vec<Trajectory>,
}

pub(crate) fn read(bytes: &[u8], expected_actions: Option<usize>) -> Located<DemonstrationSet> {
    let mut reading = Reading {
        num_actions: expected_actions,
        state_names: None,
        dimension: None,
        actions_on: None,
        max_action: None,
        trajectories: Vec::new(),
    };
    let mut seen_content = false;
    for (index, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let line = index + 1;
        let at_line = |kind| (Some(line), kind);
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        let text = std::str::from_utf8(raw).map_err(|_| at_line(ReadErrorKind::NotUtf8))?;
        if text.trim().is_empty() {
            continue;
        }
        let first = !seen_content;
        seen_content = true;

        let value = json::parse(text).map_err(|e| {
            at_line(ReadErrorKind::InvalidJson { column: e.column(text), message: e.message.to_owned() })
        })?;
        let members = match value {
            Value::Object(members) => members,
            other => {
                return Err(at_line(ReadErrorKind::NotAnObject { found: other.kind() }));
            }
        };
        // A set, not a scan: a hostile line may hold a hundred thousand keys.
        let mut keys = std::collections::BTreeSet::new();
        if let Some((key, _)) = members.iter().find(|(key, _)| !keys.insert(key.as_str())) {
            return Err(at_line(ReadErrorKind::DuplicateKey { key: key.clone() }));
        }
        let has = |name: &str| members.iter().any(|(key, _)| key == name);
        if !has("states") && (has("state_names") || has("num_actions")) {
            if !first {
                return Err(at_line(ReadErrorKind::MisplacedHeader));
            }
            read_header(members, expected_actions, &mut reading).map_err(at_line)?;
        } else {
            read_trajectory(members, line, &mut reading).map_err(at_line)?;
        }
    }
    if !seen_content {
        return Err((None, ReadErrorKind::Empty));
    }
    if reading.trajectories.is_empty() {
        return Err((None, ReadErrorKind::NoTrajectories));
    }
    if let Some((true, line)) = reading.actions_on
        && reading.num_actions.is_none()
        && reading.max_action.is_none()
    {
        let hint = " (declare it in a header line, such as {\"num_actions\":4})";
        return Err((Some(line), ReadErrorKind::NoActionToCount { field: "actions".to_owned(), hint }));
    }
    // Parsing checks what `new` checks, so this error has no line; it is
    // not expected.
    let dimension = reading.dimension.unwrap_or(0);
    let state_names = reading.state_names.unwrap_or_else(|| default_state_names(dimension));
    let num_actions = reading.num_actions.or(reading.max_action.map(|a| a + 1));
    DemonstrationSet::new(state_names, num_actions, reading.trajectories).map_err(|e| (None, ReadErrorKind::Invalid(e)))
}

fn read_header(
    members: Vec<(String, Value<'_>)>,
    expected_actions: Option<usize>,
    reading: &mut Reading,
) -> Result<(), ReadErrorKind> {
    for (key, value) in members {
        match key.as_str() {
            "state_names" => {
                let items = match value {
                    Value::Array(items) => items,
                    other => {
                        return Err(wrong_type("state_names".into(), "an array of strings", &other));
                    }
                };
                let names = items
                    .into_iter()
                    .enumerate()
                    .map(|(i, item)| match item {
                        Value::String(name) => Ok(name),
                        other => Err(wrong_type(format!("state_names[{i}]"), "a string", &other)),
                    })
                    .collect::<Result<Vec<String>, _>>()?;
                check_state_names(&names).map_err(ReadErrorKind::Invalid)?;
                reading.dimension = Some(names.len());
                reading.state_names = Some(names);
            }
            "num_actions" => {
                let text = match value {
                    Value::Number(text) => text,
                    other => return Err(wrong_type("num_actions".into(), "a number", &other)),
                };
                let declared = text
                    .parse::<usize>()
                    .ok()
                    .filter(|&n| n >= 1)
                    .ok_or_else(|| ReadErrorKind::InvalidActionCount { text: text.to_owned() })?;
                if let Some(expected) = expected_actions
                    && declared != expected
                {
                    return Err(ReadErrorKind::ActionCountMismatch { declared, expected });
                }
                reading.num_actions = Some(declared);
            }
            _ => {
                return Err(ReadErrorKind::UnknownKey { key, expected: HEADER_KEYS });
            }
        }
    }
    Ok(())
}

fn read_trajectory(members: Vec<(String, Value<'_>)>, line: usize, reading: &mut Reading) -> Result<(), ReadErrorKind> {
    let mut states = None;
    let mut actions = None;
    for (key, value) in members {
        match key.as_str() {
            "states" => states = Some(value),
            "actions" => actions = Some(value),
            _ => {
                return Err(ReadErrorKind::UnknownKey { key, expected: TRAJECTORY_KEYS });
            }
        }
    }

    let rows = match states {
        None => return Err(ReadErrorKind::MissingKey { key: "states" }),
        Some(Value::Array(rows)) => rows,
        Some(other) => return Err(wrong_type("states".into(), "an array of states", &other)),
    };
    if rows.is_empty() {
        return Err(ReadErrorKind::NoStates);
    }
    let mut values = Vec::new();
    for (step, row) in rows.iter().enumerate() {
        let items = match row {
            Value::Array(items) => items,
            other => {
                return Err(wrong_type(format!("states[{step}]"), "an array of numbers", other));
            }
        };
        let dimension = match reading.dimension {
            Some(dimension) => dimension,
            None if items.is_empty() => {
                return Err(ReadErrorKind::EmptyState { field: format!("states[{step}]") });
            }
            None => *reading.dimension.insert(items.len()),
        };
        if items.len() != dimension {
            return Err(ReadErrorKind::StateLength {
                field: format!("states[{step}]"),
                expected: dimension,
                found: items.len(),
            });
        }
        for (i, item) in items.iter().enumerate() {
            let field = || format!("states[{step}][{i}]");
            match item {
                Value::Number(text) => values.push(parse_value(text, field)?),
                other => return Err(wrong_type(field(), "a number", other)),
            }
        }
    }

    let has_actions = actions.is_some();
    match reading.actions_on {
        None => reading.actions_on = Some((has_actions, line)),
        Some((first_has, other_line)) if first_has != has_actions => {
            return Err(ReadErrorKind::MixedActions { has_actions, other_line });
        }
        Some(_) => {}
    }
    let actions = match actions {
        None => None,
        Some(Value::Array(items)) => {
            if items.len() != rows.len() && items.len() + 1 != rows.len() {
                return Err(ReadErrorKind::ActionCount { states: rows.len(), actions: items.len() });
            }
            let mut actions = Vec::with_capacity(items.len());
            for (k, item) in items.iter().enumerate() {
                let field = || format!("actions[{k}]");
                match item {
                    Value::Number(text) => {
                        let action = parse_action(text, reading.num_actions, field)?;
                        reading.max_action = reading.max_action.max(Some(action));
                        actions.push(action);
                    }
                    other => return Err(wrong_type(field(), "a number", other)),
                }
            }
            Some(actions)
        }
        Some(other) => return Err(wrong_type("actions".into(), "an array of actions", &other)),
    };

    let dimension = reading.dimension.unwrap_or(1);
    let index = reading.trajectories.len();
    let trajectory = Trajectory::new(values, dimension, actions).map_err(|error| {
        // Unreachable: every value and the action count were checked above.
        ReadErrorKind::Invalid(super::ValidationError::Trajectory { index, error })
    })?;
    reading.trajectories.push(trajectory);
    Ok(())
}

fn wrong_type(field: String, expected: &'static str, found: &Value<'_>) -> ReadErrorKind {
    ReadErrorKind::WrongType { field, expected, found: found.kind() }
}

impl DemonstrationSet {
    /// Writes the set as JSON Lines (see `DemonstrationSet::read_jsonl` for
    /// the format): a header line with the state names (and the number of
    /// actions, when known), then one compact line per trajectory, each ended
    /// by `\n`. Every value reads back to the same bits.
    pub fn write_jsonl<W: Write>(&self, mut writer: W) -> io::Result<()> {
        let mut line = String::from("{\"state_names\":[");
        for (i, name) in self.state_names().iter().enumerate() {
            if i > 0 {
                line.push(',');
            }
            line.push_str(&serde_json::to_string(name).map_err(io::Error::other)?);
        }
        line.push(']');
        if let Some(n) = self.num_actions() {
            line.push_str(&format!(",\"num_actions\":{n}"));
        }
        line.push_str("}\n");
        writer.write_all(line.as_bytes())?;

        for trajectory in self.trajectories() {
            line.clear();
            line.push_str("{\"states\":[");
            for (step, state) in trajectory.states().enumerate() {
                if step > 0 {
                    line.push(',');
                }
                line.push('[');
                for (i, &x) in state.iter().enumerate() {
                    if i > 0 {
                        line.push(',');
                    }
                    push_f64(&mut line, x);
                }
                line.push(']');
            }
            line.push(']');
            if let Some(actions) = trajectory.actions() {
                line.push_str(",\"actions\":[");
                for (k, a) in actions.iter().enumerate() {
                    if k > 0 {
                        line.push(',');
                    }
                    line.push_str(&a.to_string());
                }
                line.push(']');
            }
            line.push_str("}\n");
            writer.write_all(line.as_bytes())?;
        }
        writer.flush()
    }
}
