//! Demonstration files from the outside: both formats read and written
//! through the public API, round trips that keep every bit (hand-made sets,
//! fixtures and random sets with awkward floats), every kind of bad input
//! with the exact one-line message a user sees, and the reshaping operations
//! RE-IRL needs on hand-made sets.
//!
//! Not here: the JSON tokenizer's and the number formatter's own cases, which
//! are unit tests beside them.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use rlfd_env::demonstration::{DemonstrationSet, Format, ReadErrorKind, Trajectory, ValidationError};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/demonstrations").join(name)
}

fn names(names: &[&str]) -> Vec<String> {
    names.iter().map(|s| (*s).to_owned()).collect()
}

/// Everything a set holds, with values as bits so `-0.0` and `0.0` differ.
type Bits = (Vec<String>, Option<usize>, Vec<(Vec<u64>, Option<Vec<usize>>)>);

fn bits(set: &DemonstrationSet) -> Bits {
    let trajectories = set
        .trajectories()
        .iter()
        .map(|t| (t.values().iter().map(|x| x.to_bits()).collect(), t.actions().map(<[usize]>::to_vec)))
        .collect();
    (set.state_names().to_vec(), set.num_actions(), trajectories)
}

fn written(set: &DemonstrationSet, format: Format) -> Vec<u8> {
    let mut out = Vec::new();
    set.write(&mut out, format).unwrap();
    out
}

fn read(bytes: &[u8], format: Format, num_actions: Option<usize>) -> Result<DemonstrationSet, String> {
    let name = match format {
        Format::Csv => "demos.csv",
        Format::JsonLines => "demos.jsonl",
    };
    DemonstrationSet::read(bytes, name, format, num_actions).map_err(|e| e.to_string())
}

/// The one check of every bad-input case: reading `input` fails with exactly `expected`.
#[track_caller]
fn check(format: Format, input: &str, num_actions: Option<usize>, expected: &str) {
    check_bytes(format, input.as_bytes(), num_actions, expected);
}

#[track_caller]
fn check_bytes(format: Format, input: &[u8], num_actions: Option<usize>, expected: &str) {
    match read(input, format, num_actions) {
        Ok(set) => panic!("expected the error {expected:?}, but read {} trajectories", set.len()),
        Err(message) => assert_eq!(message, expected),
    }
}

/// The two-trajectory Maze set of the fixtures: the first ends in a terminal
/// state without an action, the second was cut after an action.
fn maze_two() -> DemonstrationSet {
    let first = Trajectory::from_states(&[[0.08, 0.6], [0.1, 0.6], [0.1, 0.62]], Some(vec![1, 2])).unwrap();
    let second = Trajectory::from_states(&[[0.08, 0.6], [0.08, 0.62]], Some(vec![2, 1])).unwrap();
    DemonstrationSet::new(names(&["x", "y"]), Some(4), vec![first, second]).unwrap()
}

// Round trips.

#[test]
fn fixtures_read_to_the_same_set_and_are_written_byte_for_byte() {
    for (file, format) in [("maze_two.csv", Format::Csv), ("maze_two.jsonl", Format::JsonLines)] {
        let path = fixture(file);
        let set = DemonstrationSet::read_path(&path, Some(4)).unwrap();
        assert_eq!(bits(&set), bits(&maze_two()), "{file}");
        assert_eq!(written(&set, format), std::fs::read(&path).unwrap(), "{file}");
    }
}

#[test]
fn csv_without_an_action_count_infers_it_from_the_largest_action() {
    let set = DemonstrationSet::read_path(fixture("maze_two.csv"), None).unwrap();
    assert_eq!(set.num_actions(), Some(3));
}

#[test]
fn sets_without_actions_round_trip_in_both_formats() {
    let t = |states: &[[f64; 2]]| Trajectory::from_states(states, None).unwrap();
    let set = DemonstrationSet::new(
        names(&["x", "y"]),
        None,
        vec![t(&[[0.1 + 0.2, 1e-300], [-0.0, 5e-324]]), t(&[[f64::MAX, -1e16]])],
    )
    .unwrap();
    let csv = written(&set, Format::Csv);
    assert_eq!(
        String::from_utf8(csv.clone()).unwrap(),
        "trajectory,step,x,y\n0,0,0.30000000000000004,1e-300\n0,1,-0,5e-324\n1,0,1.7976931348623157e308,-1e16\n"
    );
    let jsonl = written(&set, Format::JsonLines);
    assert_eq!(
        String::from_utf8(jsonl.clone()).unwrap(),
        "{\"state_names\":[\"x\",\"y\"]}\n{\"states\":[[0.30000000000000004,1e-300],[-0,5e-324]]}\n{\"states\":[[1.7976931348623157e308,-1e16]]}\n"
    );
    for (bytes, format) in [(csv, Format::Csv), (jsonl, Format::JsonLines)] {
        assert_eq!(bits(&read(&bytes, format, None).unwrap()), bits(&set));
    }
}

#[test]
fn csv_quotes_awkward_state_names_and_reads_them_back() {
    let t = Trajectory::from_states(&[[1.0, 2.0, 3.0]], None).unwrap();
    let set = DemonstrationSet::new(names(&["a,b", "say \"hi\"", "vélo"]), None, vec![t]).unwrap();
    let csv = written(&set, Format::Csv);
    assert_eq!(String::from_utf8(csv.clone()).unwrap(), "trajectory,step,\"a,b\",\"say \"\"hi\"\"\",vélo\n0,0,1,2,3\n");
    assert_eq!(bits(&read(&csv, Format::Csv, None).unwrap()), bits(&set));
}

#[test]
fn readers_accept_what_other_tools_write() {
    // A byte order mark, CRLF line ends, spaces after commas, quoted cells,
    // whole-number actions written as floats, blank lines.
    let csv = "\u{feff}trajectory, step, x, action\r\n0, 0, 1.5, 2.0\r\n\r\n0,1,\"2\",\r\n";
    let set = read(csv.as_bytes(), Format::Csv, Some(4)).unwrap();
    assert_eq!(set.trajectories()[0].values(), &[1.5, 2.0]);
    assert_eq!(set.trajectories()[0].actions(), Some(&[2][..]));
    // Python's json.dumps spacing, no header, a blank last line.
    let jsonl = "{\"states\": [[1.5, 2], [3, 4]], \"actions\": [0]}\r\n\n";
    let set = read(jsonl.as_bytes(), Format::JsonLines, None).unwrap();
    assert_eq!(set.state_names(), &names(&["s0", "s1"])[..]);
    assert_eq!(set.num_actions(), Some(1));
}

fn awkward_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        prop::sample::select(vec![
            0.1 + 0.2,
            1e-300,
            -0.0,
            0.0,
            5e-324,
            -5e-324,
            f64::MAX,
            f64::MIN,
            f64::MIN_POSITIVE,
            f64::EPSILON,
            1e16,
            1e-4,
            9.999999999999999e-5,
            0.08,
            1.0 / 3.0,
            123_456_789.123_456_79,
        ]),
        any::<f64>().prop_filter("finite", |x| x.is_finite()),
        (-1000_i32..1000).prop_map(f64::from),
    ]
}

/// Random sets: 1–3 state variables with awkward names, 1–4 trajectories of
/// 1–6 states, with or without actions, each trajectory with or without an
/// action for its last state.
fn sets() -> impl Strategy<Value = DemonstrationSet> {
    let pool = names(&["x", "y", "a,b", "say \"hi\"", "vélo", "z w", "#"]);
    (1_usize..4, any::<bool>(), 1_usize..6).prop_flat_map(move |(dimension, with_actions, num_actions)| {
        let trajectory = (1_usize..7).prop_flat_map(move |len| {
            (
                prop::collection::vec(awkward_f64(), len * dimension),
                prop::collection::vec(0..num_actions, len),
                any::<bool>(),
            )
        });
        (prop::sample::subsequence(pool.clone(), dimension), prop::collection::vec(trajectory, 1..5)).prop_map(
            move |(state_names, raw)| {
                let trajectories = raw
                    .into_iter()
                    .map(|(values, mut actions, terminal)| {
                        if terminal {
                            actions.pop();
                        }
                        Trajectory::new(values, dimension, with_actions.then_some(actions)).unwrap()
                    })
                    .collect();
                DemonstrationSet::new(state_names, Some(num_actions), trajectories).unwrap()
            },
        )
    })
}

proptest! {
    #[test]
    fn random_sets_round_trip_bit_for_bit(set in sets()) {
        for format in [Format::Csv, Format::JsonLines] {
            let bytes = written(&set, format);
            let back = read(&bytes, format, set.num_actions());
            prop_assert!(back.is_ok(), "{format:?}: {back:?}");
            let back = back.unwrap();
            prop_assert_eq!(bits(&back), bits(&set));
            prop_assert_eq!(written(&back, format), bytes);
        }
    }
}

/// Text made mostly of the characters both formats are built from, so that
/// random strings get past the first checks and reach the deeper ones.
fn file_like_text() -> impl Strategy<Value = Vec<u8>> {
    let alphabet: Vec<u8> = b"0123456789.,-+eE\n\r \"[]{}:aNInfstep\xff".to_vec();
    prop::collection::vec(prop::sample::select(alphabet), 0..120)
}

/// A fixture with a few bytes overwritten at random.
fn mutated_fixture() -> impl Strategy<Value = (Vec<u8>, Format)> {
    let files = [("maze_two.csv", Format::Csv), ("maze_two.jsonl", Format::JsonLines)]
        .map(|(file, format)| (std::fs::read(fixture(file)).unwrap(), format));
    (prop::sample::select(files.to_vec()), prop::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..4))
        .prop_map(|((mut bytes, format), edits)| {
            for (index, byte) in edits {
                let i = index.index(bytes.len());
                bytes[i] = byte;
            }
            (bytes, format)
        })
}

proptest! {
    // Readers never panic: they return a set or a one-line error naming the file.
    #[test]
    fn any_input_is_read_or_rejected_in_one_line(bytes in file_like_text(), num_actions in prop::option::of(1_usize..5)) {
        for format in [Format::Csv, Format::JsonLines] {
            if let Err(message) = read(&bytes, format, num_actions) {
                prop_assert!(message.starts_with("demos."), "{message}");
                prop_assert!(!message.contains('\n'), "{message}");
            }
        }
    }

    #[test]
    fn damaged_fixtures_are_read_or_rejected_in_one_line((bytes, format) in mutated_fixture()) {
        if let Err(message) = read(&bytes, format, Some(4)) {
            prop_assert!(message.starts_with("demos."), "{message}");
            prop_assert!(!message.contains('\n'), "{message}");
        }
    }
}

// Bad CSV input.

const HEADER: &str = "trajectory,step,x,y,action\n";

#[test]
fn csv_empty_and_header_only_files() {
    check(Format::Csv, "", None, "demos.csv: the file is empty");
    check(Format::Csv, "\n \n", None, "demos.csv: the file is empty");
    check(Format::Csv, HEADER, None, "demos.csv: the file holds no trajectories");
}

#[test]
fn csv_non_utf8() {
    check_bytes(
        Format::Csv,
        b"trajectory,step,x\n0,0,\xff\n",
        None,
        "demos.csv:2: the line is not valid UTF-8 (save the file as UTF-8)",
    );
    // UTF-16, as some spreadsheet programs save "Unicode text".
    check_bytes(
        Format::Csv,
        b"\xff\xfet\0r\0",
        None,
        "demos.csv:1: the line is not valid UTF-8 (save the file as UTF-8)",
    );
}

#[test]
fn csv_header_problems() {
    let check_header =
        |header: &str, expected: &str| check(Format::Csv, &format!("{header}\n0,0,1,2\n"), None, expected);
    check_header("trajectory,step,x,x", "demos.csv:1: duplicate column \"x\" (columns 3 and 4)");
    check_header(
        "trajectory,x,y,z",
        "demos.csv:1: missing column \"step\" (the header must read trajectory,step,<state names…>[,action])",
    );
    check_header(
        "x,y,z,w",
        "demos.csv:1: missing column \"trajectory\" (the header must read trajectory,step,<state names…>[,action])",
    );
    check_header("step,trajectory,x,y", "demos.csv:1: column \"trajectory\" must be column 1, found as column 2");
    check_header("trajectory,step,action,x", "demos.csv:1: column \"action\" must be column 4, found as column 3");
    check_header("trajectory,step,x,", "demos.csv:1: column 4 has no name");
    check_header(
        "trajectory,step,action",
        "demos.csv:1: no state columns (the header must read trajectory,step,<state names…>[,action])",
    );
}

#[test]
fn csv_row_problems() {
    let check_rows = |rows: &str, expected: &str| check(Format::Csv, &format!("{HEADER}{rows}"), Some(4), expected);
    check_rows("0,0,1,2,0\n0,1,1,2\n", "demos.csv:3: expected 5 fields, found 4");
    check_rows("0,0,1,2,0,9\n", "demos.csv:2: expected 5 fields, found 6");
    check_rows("0,0,1,abc,0\n", "demos.csv:2: field \"y\": \"abc\" is not a number");
    check_rows("0,0,NaN,2,0\n", "demos.csv:2: field \"x\": NaN is not allowed");
    check_rows("0,0,1,-inf,0\n", "demos.csv:2: field \"y\": -inf is not allowed");
    check_rows("0,0,1e999,2,0\n", "demos.csv:2: field \"x\": 1e999 is too large for a 64-bit float");
    check_rows("0,0,,2,0\n", "demos.csv:2: field \"x\": the value is missing");
    check_rows("0,0,1,2,7\n", "demos.csv:2: field \"action\": 7 is out of range 0..4");
    check_rows("0,0,1,2,-1\n", "demos.csv:2: field \"action\": -1 is negative (actions are numbered from 0)");
    check_rows(
        "0,0,1,2,1.5\n",
        "demos.csv:2: field \"action\": 1.5 is not a whole number (actions are numbered from 0)",
    );
    check_rows("0,0,1,2,up\n", "demos.csv:2: field \"action\": \"up\" is not a number");
    check_rows(
        "0,0,1,2,\n0,1,1,2,0\n",
        "demos.csv:2: field \"action\": missing (only the last state of a trajectory may have no action)",
    );
    check_rows(
        "0,0,1,2,0\n0,1,1,2,0\n0,2,1,2,0\n0,5,1,2,0\n",
        "demos.csv:5: field \"step\": expected 3, found 5 (steps must count up from 0 within a trajectory)",
    );
    check_rows(
        "0,1,1,2,0\n",
        "demos.csv:2: field \"step\": expected 0, found 1 (steps must count up from 0 within a trajectory)",
    );
    check_rows("0,1.0,1,2,0\n", "demos.csv:2: field \"step\": \"1.0\" is not a non-negative integer");
    check_rows("a,0,1,2,0\n", "demos.csv:2: field \"trajectory\": \"a\" is not a non-negative integer");
}

#[test]
fn csv_trajectories_out_of_order() {
    let check_rows = |rows: &str, expected: &str| check(Format::Csv, &format!("{HEADER}{rows}"), Some(4), expected);
    check_rows(
        "1,0,1,2,0\n",
        "demos.csv:2: field \"trajectory\": expected 0, found 1 (trajectories are numbered from 0 and their rows are contiguous)",
    );
    check_rows(
        "0,0,1,2,0\n2,0,1,2,0\n",
        "demos.csv:3: field \"trajectory\": expected 0 or 1, found 2 (trajectories are numbered from 0 and their rows are contiguous)",
    );
    check_rows(
        "0,0,1,2,0\n1,0,1,2,0\n0,1,1,2,0\n",
        "demos.csv:4: field \"trajectory\": expected 1 or 2, found 0 (trajectories are numbered from 0 and their rows are contiguous)",
    );
}

#[test]
fn errors_are_structured_for_callers_to_match() {
    let error =
        DemonstrationSet::read_csv(format!("{HEADER}0,0,1,2,7\n").as_bytes(), "demos.csv", Some(4)).unwrap_err();
    assert_eq!(error.file, "demos.csv");
    assert_eq!(error.line, Some(2));
    assert!(matches!(
        &error.kind,
        ReadErrorKind::ActionOutOfRange { field, text, num_actions: 4 } if field == "action" && text == "7"
    ));
}

// Bad JSON Lines input.

const JSON_HEADER: &str = "{\"state_names\":[\"x\",\"y\"],\"num_actions\":4}\n";

#[test]
fn jsonl_empty_header_only_and_non_utf8_files() {
    check(Format::JsonLines, "", None, "demos.jsonl: the file is empty");
    check(Format::JsonLines, "\n\n", None, "demos.jsonl: the file is empty");
    check(Format::JsonLines, JSON_HEADER, None, "demos.jsonl: the file holds no trajectories");
    check_bytes(
        Format::JsonLines,
        b"{\"states\":[[1]]}\n{\"states\":[[\xff]]}\n",
        None,
        "demos.jsonl:2: the line is not valid UTF-8 (save the file as UTF-8)",
    );
}

#[test]
fn jsonl_structure_problems() {
    let check_lines =
        |lines: &str, expected: &str| check(Format::JsonLines, &format!("{JSON_HEADER}{lines}"), None, expected);
    check_lines("{\"states\":[[1,2] [3,4]]}\n", "demos.jsonl:2: invalid JSON at column 18: expected ',' or ']'");
    check_lines("[[1,2]]\n", "demos.jsonl:2: expected a JSON object, found an array");
    check_lines(
        "{\"states\":[[1,2]],\"action\":[0]}\n",
        "demos.jsonl:2: unknown key \"action\" (expected \"states\" and optionally \"actions\")",
    );
    check_lines("{\"states\":[[1,2]],\"states\":[[1,2]]}\n", "demos.jsonl:2: duplicate key \"states\"");
    check_lines("{\"actions\":[0]}\n", "demos.jsonl:2: missing key \"states\"");
    check_lines("{\"states\":[]}\n", "demos.jsonl:2: field \"states\": the trajectory has no states");
    check_lines("{\"states\":3}\n", "demos.jsonl:2: field \"states\": expected an array of states, found a number");
    check_lines(
        "{\"states\":[1,2]}\n",
        "demos.jsonl:2: field \"states[0]\": expected an array of numbers, found a number",
    );
    check_lines(
        "{\"states\":[[1,2],[3,4],[5,6],[7,8],[9,10,11]]}\n",
        "demos.jsonl:2: field \"states[4]\": expected 2 values, found 3",
    );
    check_lines(
        "{\"states\":[[1,2]]}\n{\"state_names\":[\"x\",\"y\"]}\n",
        "demos.jsonl:3: a header line (with \"state_names\" or \"num_actions\") may only come first",
    );
    check(
        Format::JsonLines,
        "{\"states\":[[]]}\n",
        None,
        "demos.jsonl:1: field \"states[0]\": a state needs at least one value",
    );
}

#[test]
fn jsonl_value_problems() {
    let check_lines =
        |lines: &str, expected: &str| check(Format::JsonLines, &format!("{JSON_HEADER}{lines}"), None, expected);
    check_lines("{\"states\":[[1,NaN]]}\n", "demos.jsonl:2: field \"states[0][1]\": NaN is not allowed");
    check_lines("{\"states\":[[-Infinity,1]]}\n", "demos.jsonl:2: field \"states[0][0]\": -Infinity is not allowed");
    check_lines(
        "{\"states\":[[1,\"2\"]]}\n",
        "demos.jsonl:2: field \"states[0][1]\": expected a number, found a string",
    );
    check_lines(
        "{\"states\":[[1,2],[3,4]],\"actions\":[0,7]}\n",
        "demos.jsonl:2: field \"actions[1]\": 7 is out of range 0..4",
    );
    check_lines(
        "{\"states\":[[1,2]],\"actions\":[-1]}\n",
        "demos.jsonl:2: field \"actions[0]\": -1 is negative (actions are numbered from 0)",
    );
    check_lines(
        "{\"states\":[[1,2]],\"actions\":[0.5]}\n",
        "demos.jsonl:2: field \"actions[0]\": 0.5 is not a whole number (actions are numbered from 0)",
    );
    check_lines(
        "{\"states\":[[1,2]],\"actions\":[0,1,2]}\n",
        "demos.jsonl:2: field \"actions\": expected 0 or 1 actions (one per state, the last state's optional), found 3",
    );
    check_lines(
        "{\"states\":[[1,2]],\"actions\":[0]}\n{\"states\":[[1,2]]}\n",
        "demos.jsonl:3: field \"actions\": missing, but the trajectory on line 2 has actions (either every trajectory has actions or none)",
    );
    check_lines(
        "{\"states\":[[1,2]]}\n{\"states\":[[1,2]],\"actions\":[0]}\n",
        "demos.jsonl:3: field \"actions\": present, but the trajectory on line 2 has none (either every trajectory has actions or none)",
    );
}

#[test]
fn jsonl_header_problems() {
    check(
        Format::JsonLines,
        &format!("{JSON_HEADER}{{\"states\":[[1,2]]}}\n"),
        Some(5),
        "demos.jsonl:1: field \"num_actions\": the file declares 4 actions, but 5 were expected",
    );
    check(
        Format::JsonLines,
        "{\"num_actions\":0}\n{\"states\":[[1]]}\n",
        None,
        "demos.jsonl:1: field \"num_actions\": 0 is not a valid number of actions (expected a whole number, at least 1)",
    );
    check(
        Format::JsonLines,
        "{\"state_names\":[\"x\",\"action\"]}\n{\"states\":[[1,2]]}\n",
        None,
        "demos.jsonl:1: state name 1 (\"action\") is reserved for the CSV format's own columns",
    );
    check(
        Format::JsonLines,
        "{\"state_names\":[\"x\",2]}\n{\"states\":[[1,2]]}\n",
        None,
        "demos.jsonl:1: field \"state_names[1]\": expected a string, found a number",
    );
    check(
        Format::JsonLines,
        "{\"state_names\":[\"x\"],\"seed\":3}\n{\"states\":[[1]]}\n",
        None,
        "demos.jsonl:1: unknown key \"seed\" (expected \"state_names\" and \"num_actions\")",
    );
    check(
        Format::JsonLines,
        "{\"state_names\":[\"x\",\"y\",\"z\"]}\n{\"states\":[[1,2]]}\n",
        None,
        "demos.jsonl:2: field \"states[0]\": expected 3 values, found 2",
    );
}

#[test]
fn paths_name_the_file_in_errors() {
    let missing = fixture("no_such_file.csv");
    let message = DemonstrationSet::read_path(&missing, None).unwrap_err().to_string();
    assert_eq!(message, format!("{}: cannot read: No such file or directory (os error 2)", missing.display()));
    let message = DemonstrationSet::read_path("demos.txt", None).unwrap_err().to_string();
    assert_eq!(message, "demos.txt: unknown file format (expected a .csv or .jsonl file)");
    assert_eq!(Format::from_path(Path::new("a/B.JSONL")), Some(Format::JsonLines));
    assert_eq!(Format::from_path(Path::new("a/b.ndjson")), Some(Format::JsonLines));
}

// Reshaping.

/// Three one-variable trajectories of lengths 3, 1 and 2, with actions (the
/// first without one for its terminal last state).
fn ragged() -> DemonstrationSet {
    let trajectories = vec![
        Trajectory::from_states(&[[0.0], [1.0], [2.0]], Some(vec![1, 1])).unwrap(),
        Trajectory::from_states(&[[10.0]], Some(vec![3])).unwrap(),
        Trajectory::from_states(&[[20.0], [21.0]], Some(vec![0, 2])).unwrap(),
    ];
    DemonstrationSet::new(names(&["x"]), Some(4), trajectories).unwrap()
}

fn values(set: &DemonstrationSet) -> Vec<Vec<f64>> {
    set.trajectories().iter().map(|t| t.values().to_vec()).collect()
}

fn actions(set: &DemonstrationSet) -> Vec<Option<Vec<usize>>> {
    set.trajectories().iter().map(|t| t.actions().map(<[usize]>::to_vec)).collect()
}

#[test]
fn padding_repeats_the_last_observation_and_drops_actions() {
    let padded = ragged().pad_to_equal_length();
    assert_eq!(values(&padded), vec![vec![0.0, 1.0, 2.0], vec![10.0, 10.0, 10.0], vec![20.0, 21.0, 21.0]]);
    assert!(!padded.has_actions());
    assert_eq!(padded.num_actions(), Some(4));
    assert_eq!(padded.require_equal_lengths(), Ok(3));
}

#[test]
fn truncation_cuts_states_and_their_actions() {
    let set = ragged().truncate_to(2).unwrap();
    assert_eq!(values(&set), vec![vec![0.0, 1.0], vec![10.0], vec![20.0, 21.0]]);
    assert_eq!(actions(&set), vec![Some(vec![1, 1]), Some(vec![3]), Some(vec![0, 2])]);
    assert_eq!(ragged().truncate_to(0), Err(ValidationError::ZeroLength));
    // Cutting at or beyond every length changes nothing.
    assert_eq!(ragged().truncate_to(3).unwrap(), ragged());
}

#[test]
fn first_n_observations_needs_every_trajectory_that_long() {
    let set = ragged().first_n_observations(1).unwrap();
    assert_eq!(values(&set), vec![vec![0.0], vec![10.0], vec![20.0]]);
    assert_eq!(actions(&set), vec![Some(vec![1]), Some(vec![3]), Some(vec![0])]);
    assert_eq!(
        ragged().first_n_observations(2).unwrap_err().to_string(),
        "trajectory 1 has length 1, shorter than the 2 observations requested"
    );
}

#[test]
fn pruning_cuts_to_the_kth_longest_and_leaves_out_shorter_ones() {
    let set = ragged();
    assert_eq!(set.kth_longest_length(1), Ok(3));
    assert_eq!(set.kth_longest_length(2), Ok(2));
    let pruned = set.prune_to_kth_longest(2).unwrap();
    assert_eq!(values(&pruned), vec![vec![0.0, 1.0], vec![20.0, 21.0]]);
    let pruned = set.prune_to_kth_longest(3).unwrap();
    assert_eq!(values(&pruned), vec![vec![0.0], vec![10.0], vec![20.0]]);
    assert_eq!(
        set.prune_to_kth_longest(4).unwrap_err().to_string(),
        "there is no k-th longest trajectory for k = 4: k counts from 1 and the set holds 3"
    );
    assert!(set.prune_to_kth_longest(0).is_err());
}

#[test]
fn pruning_ten_demonstrations_to_the_tenth_longest_keeps_all_ten() {
    // Mario: 10 demonstrations, all cut to the 10th-longest length.
    let lengths = [1200, 953, 3000, 1500, 999, 2000, 1001, 954, 2500, 1800];
    let trajectories =
        lengths.iter().map(|&len| Trajectory::new((0..len).map(f64::from).collect(), 1, None).unwrap()).collect();
    let set = DemonstrationSet::new(names(&["x"]), None, trajectories).unwrap();
    let pruned = set.prune_to_kth_longest(10).unwrap();
    assert_eq!(pruned.lengths(), vec![953; 10]);
    assert_eq!(pruned.require_equal_lengths(), Ok(953));
}

#[test]
fn unequal_lengths_name_the_first_offender() {
    assert_eq!(
        ragged().require_equal_lengths().unwrap_err().to_string(),
        "trajectory 1 has length 1, but trajectory 0 has length 3 (the trajectories must have equal lengths)"
    );
}

#[test]
fn accessors_describe_the_set() {
    let set = ragged();
    assert_eq!((set.len(), set.dimension(), set.total_states()), (3, 1, 6));
    assert_eq!(set.lengths(), vec![3, 1, 2]);
    let pairs: Vec<(f64, usize)> = set.state_action_pairs().map(|(s, a)| (s[0], a)).collect();
    assert_eq!(pairs, vec![(0.0, 1), (1.0, 1), (10.0, 3), (20.0, 0), (21.0, 2)]);
    let steps: Vec<Option<usize>> = set.trajectories()[0].steps().map(|(_, a)| a).collect();
    assert_eq!(steps, vec![Some(1), Some(1), None]);
}
