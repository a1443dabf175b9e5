//! Byte-level fuzzing of the demonstration readers: whatever a user hands
//! `read_csv`, `read_jsonl` or `read_path` (which picks the format by
//! extension), the reader returns a set or a one-line error naming the file,
//! the line where there is one, and the field where the problem is a field's.
//!
//! Inputs come from three kinds of strategies:
//!
//! - arbitrary bytes, and text drawn from the characters both formats are
//!   made of (so that random input gets past the first checks);
//! - valid files, written from random sets, then damaged: bits flipped,
//!   bytes inserted or deleted, lines duplicated, dropped or swapped, a
//!   number replaced by a huge one, NaN or infinity text, a non-UTF-8 byte,
//!   a byte order mark, CRLF line ends, the header alone, nothing at all;
//!   every truncation of a few files is tried;
//! - valid files that must round-trip, in both formats and across them.
//!
//! Every accepted input is itself checked: written back in either format,
//! it reads to the same set. The default run is a few hundred cases per
//! property; a long run sets `PROPTEST_CASES`, for example
//!
//! ```text
//! PROPTEST_CASES=200000 cargo test --release -p rlfd-lfd --test demonstration_fuzz
//! ```
//!
//! Not here: the exact messages of known bad inputs, which
//! `demonstration_files.rs` lists one by one.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use proptest::test_runner::Config;
use rlfd_env::demonstration::{DemonstrationSet, Format, ReadError, ReadErrorKind, Trajectory};

const CSV_NAME: &str = "demos.csv";
const JSONL_NAME: &str = "demos.jsonl";

fn name(format: Format) -> &'static str {
    match format {
        Format::Csv => CSV_NAME,
        Format::JsonLines => JSONL_NAME,
    }
}

/// Cases per property: `PROPTEST_CASES` if set, else `default`.
fn config(default: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(default);
    Config { cases, ..Config::default() }
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

/// The number of lines of `bytes` as the readers count them (1-based, the
/// last one possibly without an end).
fn line_count(bytes: &[u8]) -> usize {
    bytes.iter().filter(|&&b| b == b'\n').count() + 1
}

/// The one check of every read: an error is one line naming the file, with
/// a line number inside the file unless the problem is the whole file's, and
/// the field where the problem is one; a set, written back in either format,
/// reads back to itself.
fn check_read(bytes: &[u8], format: Format, num_actions: Option<usize>) -> Result<(), TestCaseError> {
    match DemonstrationSet::read(bytes, name(format), format, num_actions) {
        Ok(set) => check_accepted(&set, num_actions),
        Err(error) => check_error(&error, bytes, format),
    }
}

fn check_error(error: &ReadError, bytes: &[u8], format: Format) -> Result<(), TestCaseError> {
    let message = error.to_string();
    prop_assert!(!message.contains(['\n', '\r']), "not one line: {message:?}");
    prop_assert_eq!(&error.file, name(format));
    let whole_file = matches!(
        error.kind,
        ReadErrorKind::Empty | ReadErrorKind::NoTrajectories | ReadErrorKind::Io(_) | ReadErrorKind::UnknownFormat
    );
    match error.line {
        Some(line) => {
            prop_assert!(!whole_file, "a whole-file problem with a line: {message}");
            prop_assert!((1..=line_count(bytes)).contains(&line), "line {line} is not in the file: {message}");
            let prefix = format!("{}:{line}: ", name(format));
            prop_assert!(message.starts_with(&prefix), "{message:?} does not start with {prefix:?}");
        }
        None => {
            prop_assert!(whole_file, "no line for {message:?}");
            let prefix = format!("{}: ", name(format));
            prop_assert!(message.starts_with(&prefix), "{message:?} does not start with {prefix:?}");
        }
    }
    if let Some(field) = field_of(&error.kind) {
        prop_assert!(message.contains(&format!("field {field:?}")), "{message:?} does not name field {field:?}");
    }
    Ok(())
}

/// The field a kind is about, if it names one.
fn field_of(kind: &ReadErrorKind) -> Option<&str> {
    match kind {
        ReadErrorKind::MissingValue { field }
        | ReadErrorKind::NotANumber { field, .. }
        | ReadErrorKind::NotFinite { field, .. }
        | ReadErrorKind::TooLarge { field, .. }
        | ReadErrorKind::NotAnInteger { field, .. }
        | ReadErrorKind::NegativeAction { field, .. }
        | ReadErrorKind::FractionalAction { field, .. }
        | ReadErrorKind::ActionOutOfRange { field, .. }
        | ReadErrorKind::ActionTooLarge { field, .. }
        | ReadErrorKind::NoActionToCount { field, .. }
        | ReadErrorKind::WrongType { field, .. }
        | ReadErrorKind::EmptyState { field }
        | ReadErrorKind::StateLength { field, .. } => Some(field),
        _ => None,
    }
}

fn check_accepted(set: &DemonstrationSet, num_actions: Option<usize>) -> Result<(), TestCaseError> {
    if let Some(n) = num_actions {
        prop_assert_eq!(set.num_actions(), Some(n));
    }
    for format in [Format::Csv, Format::JsonLines] {
        let bytes = written(set, format);
        let back = DemonstrationSet::read(&bytes[..], name(format), format, set.num_actions());
        prop_assert!(back.is_ok(), "an accepted set does not read back from {format:?}: {back:?}");
        prop_assert_eq!(bits(&back.unwrap()), bits(set));
    }
    Ok(())
}

fn awkward_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        prop::sample::select(vec![0.1 + 0.2, 1e-300, -0.0, 0.0, 5e-324, f64::MAX, f64::MIN, 1e16, 1e-4, 0.08, 0.6]),
        any::<f64>().prop_filter("finite", |x| x.is_finite()),
        (0_i32..100).prop_map(|i| f64::from(i) / 100.0),
    ]
}

/// State names: plain, awkward for CSV (commas, quotes, line breaks inside
/// the name), non-ASCII, and arbitrary strings the set accepts.
fn state_name() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec!["x", "y", "a,b", "say \"hi\"", "vélo", "z w", "#", "line\nbreak", "tab\tin", "日本"])
            .prop_map(str::to_owned),
        "[^\\s]{1,8}",
    ]
}

/// Random valid sets: 1–4 state variables, 1–5 trajectories of 1–8 states,
/// with or without actions (each trajectory with or without an action for
/// its last state), 1–6 actions or, without actions, sometimes no count.
fn sets() -> impl Strategy<Value = DemonstrationSet> {
    (1_usize..5, any::<bool>(), 1_usize..7, any::<bool>()).prop_flat_map(
        |(dimension, with_actions, num_actions, keep_count)| {
            let trajectory = (1_usize..9).prop_flat_map(move |len| {
                (
                    prop::collection::vec(awkward_f64(), len * dimension),
                    prop::collection::vec(0..num_actions, len),
                    any::<bool>(),
                )
            });
            let names = prop::collection::vec(state_name(), dimension).prop_filter("unique names", |names| {
                names.iter().enumerate().all(|(i, n)| !names[..i].contains(n))
                    && names.iter().all(|n| !["trajectory", "step", "action"].contains(&n.as_str()))
            });
            (names, prop::collection::vec(trajectory, 1..6)).prop_map(move |(state_names, raw)| {
                let trajectories = raw
                    .into_iter()
                    .map(|(values, mut actions, terminal)| {
                        if terminal {
                            actions.pop();
                        }
                        Trajectory::new(values, dimension, with_actions.then_some(actions)).unwrap()
                    })
                    .collect();
                let count = (with_actions || keep_count).then_some(num_actions);
                DemonstrationSet::new(state_names, count, trajectories).unwrap()
            })
        },
    )
}

fn formats() -> impl Strategy<Value = Format> {
    prop_oneof![Just(Format::Csv), Just(Format::JsonLines)]
}

/// Text made mostly of the characters both formats are built from.
fn file_like_text() -> impl Strategy<Value = Vec<u8>> {
    let mut alphabet: Vec<u8> = b"0123456789.,-+eE\n\r \t\"[]{}:aNInfstep\\u".to_vec();
    alphabet.extend([0xff, 0xef, 0xbb, 0xbf, 0xc3, 0xa9, 0]);
    prop_oneof![
        prop::collection::vec(prop::sample::select(alphabet), 0..200),
        // The same after a valid header, so rows are reached more often.
        (formats(), prop::collection::vec(prop::sample::select(b"0123456789.,-+eE\n \"[]{}:aN".to_vec()), 0..200))
            .prop_map(|(format, tail)| {
                let mut bytes = match format {
                    Format::Csv => b"trajectory,step,x,y,action\n".to_vec(),
                    Format::JsonLines => b"{\"state_names\":[\"x\",\"y\"],\"num_actions\":4}\n".to_vec(),
                };
                bytes.extend(tail);
                bytes
            }),
    ]
}

/// One way of damaging a file.
#[derive(Clone, Debug)]
enum Damage {
    FlipBit(prop::sample::Index, u8),
    Overwrite(prop::sample::Index, u8),
    Insert(prop::sample::Index, Vec<u8>),
    Delete(prop::sample::Index, usize),
    Truncate(prop::sample::Index),
    DuplicateLine(prop::sample::Index),
    DropLine(prop::sample::Index),
    SwapLines(prop::sample::Index, prop::sample::Index),
    /// A number token replaced by another text (huge, NaN, inf, empty, …).
    ReplaceNumber(prop::sample::Index, &'static str),
    HeaderOnly,
    Empty,
}

/// Texts that replace a number: what other tools write, and what they should not.
const NUMBER_TEXTS: [&str; 24] = [
    "1e400",
    "-1e400",
    "1e-400",
    "NaN",
    "nan",
    "-NaN",
    "inf",
    "-inf",
    "Infinity",
    "-Infinity",
    "+Infinity",
    "",
    "18446744073709551615",
    "18446744073709551616",
    "99999999999999999999999999999",
    "9007199254740993",
    "4.0",
    "-0",
    "0x10",
    "1_000",
    "1,5",
    "\u{a0}1",
    "1e",
    "\"3\"",
];

fn damage() -> impl Strategy<Value = Damage> {
    use prop::sample::Index;
    prop_oneof![
        (any::<Index>(), 0_u8..8).prop_map(|(i, bit)| Damage::FlipBit(i, bit)),
        (any::<Index>(), any::<u8>()).prop_map(|(i, b)| Damage::Overwrite(i, b)),
        (any::<Index>(), prop::collection::vec(any::<u8>(), 1..4)).prop_map(|(i, b)| Damage::Insert(i, b)),
        (
            any::<Index>(),
            prop::sample::select(vec![&b","[..], b"\n", b"\r\n", b"\"", b"\xff", b"\xef\xbb\xbf", b"[", b"}", b"\\"])
        )
            .prop_map(|(i, b)| Damage::Insert(i, b.to_vec())),
        (any::<Index>(), 1_usize..6).prop_map(|(i, n)| Damage::Delete(i, n)),
        any::<Index>().prop_map(Damage::Truncate),
        any::<Index>().prop_map(Damage::DuplicateLine),
        any::<Index>().prop_map(Damage::DropLine),
        (any::<Index>(), any::<Index>()).prop_map(|(a, b)| Damage::SwapLines(a, b)),
        (any::<Index>(), prop::sample::select(NUMBER_TEXTS.to_vec())).prop_map(|(i, t)| Damage::ReplaceNumber(i, t)),
        Just(Damage::HeaderOnly),
        Just(Damage::Empty),
    ]
}

fn lines(bytes: &[u8]) -> Vec<Vec<u8>> {
    bytes.split_inclusive(|&b| b == b'\n').map(<[u8]>::to_vec).collect()
}

fn apply(bytes: &mut Vec<u8>, damage: &Damage) {
    let len = bytes.len();
    match damage {
        Damage::FlipBit(i, bit) if len > 0 => bytes[i.index(len)] ^= 1 << bit,
        Damage::Overwrite(i, b) if len > 0 => bytes[i.index(len)] = *b,
        Damage::Insert(i, b) => {
            let at = i.index(len + 1);
            bytes.splice(at..at, b.iter().copied());
        }
        Damage::Delete(i, n) if len > 0 => {
            let at = i.index(len);
            bytes.drain(at..(at + n).min(len));
        }
        Damage::Truncate(i) => bytes.truncate(i.index(len + 1)),
        Damage::DuplicateLine(i) | Damage::DropLine(i) | Damage::SwapLines(i, _) => {
            let mut lines = lines(bytes);
            if lines.is_empty() {
                return;
            }
            let a = i.index(lines.len());
            match damage {
                Damage::DuplicateLine(_) => {
                    let line = lines[a].clone();
                    lines.insert(a, line);
                }
                Damage::DropLine(_) => {
                    lines.remove(a);
                }
                Damage::SwapLines(_, j) => {
                    let b = j.index(lines.len());
                    lines.swap(a, b);
                }
                _ => unreachable!(),
            }
            *bytes = lines.concat();
        }
        Damage::ReplaceNumber(i, text) => {
            // Number tokens: maximal runs of digits, signs, dots and exponents.
            let is_number = |b: u8| b.is_ascii_digit() || b"+-.eE".contains(&b);
            let mut tokens = Vec::new();
            let mut start = None;
            for (k, &b) in bytes.iter().chain(std::iter::once(&b' ')).enumerate() {
                match (start, is_number(b)) {
                    (None, true) => start = Some(k),
                    (Some(s), false) => {
                        tokens.push(s..k);
                        start = None;
                    }
                    _ => {}
                }
            }
            if !tokens.is_empty() {
                let range = tokens[i.index(tokens.len())].clone();
                bytes.splice(range, text.bytes());
            }
        }
        Damage::HeaderOnly => {
            let end = bytes.iter().position(|&b| b == b'\n').map_or(len, |p| p + 1);
            bytes.truncate(end);
        }
        Damage::Empty => bytes.clear(),
        _ => {}
    }
}

/// A valid file of either format, damaged up to three times.
fn damaged_files() -> impl Strategy<Value = (Vec<u8>, Format, Option<usize>)> {
    (sets(), formats(), prop::collection::vec(damage(), 1..4), any::<bool>()).prop_map(
        |(set, format, damages, pass_count)| {
            let mut bytes = written(&set, format);
            for d in &damages {
                apply(&mut bytes, d);
            }
            (bytes, format, set.num_actions().filter(|_| pass_count))
        },
    )
}

/// Rewrites line ends as `\r\n` and optionally prepends a byte order mark.
fn as_other_tools_write(bytes: &[u8], crlf: bool, bom: bool) -> Vec<u8> {
    let mut out = Vec::new();
    if bom {
        out.extend_from_slice(b"\xEF\xBB\xBF");
    }
    for &b in bytes {
        if crlf && b == b'\n' {
            out.push(b'\r');
        }
        out.push(b);
    }
    out
}

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn arbitrary_bytes_are_read_or_rejected_in_one_line(
        bytes in prop::collection::vec(any::<u8>(), 0..300),
        num_actions in prop::option::of(1_usize..6),
    ) {
        for format in [Format::Csv, Format::JsonLines] {
            check_read(&bytes, format, num_actions)?;
        }
    }

    #[test]
    fn file_like_text_is_read_or_rejected_in_one_line(
        bytes in file_like_text(),
        num_actions in prop::option::of(1_usize..6),
    ) {
        for format in [Format::Csv, Format::JsonLines] {
            check_read(&bytes, format, num_actions)?;
        }
    }

    #[test]
    fn damaged_files_are_read_or_rejected_in_one_line((bytes, format, num_actions) in damaged_files()) {
        check_read(&bytes, format, num_actions)?;
        // The other format's reader must survive it too.
        let other = match format {
            Format::Csv => Format::JsonLines,
            Format::JsonLines => Format::Csv,
        };
        check_read(&bytes, other, num_actions)?;
    }

    #[test]
    fn valid_files_read_back_what_was_written(
        set in sets(),
        format in formats(),
        crlf in any::<bool>(),
        bom in any::<bool>(),
    ) {
        // A line break inside a quoted CSV name is data, not a line end.
        let crlf = crlf && !set.state_names().iter().any(|n| n.contains(['\n', '\r']));
        let bytes = as_other_tools_write(&written(&set, format), crlf, bom);
        let back = DemonstrationSet::read(&bytes[..], name(format), format, set.num_actions());
        prop_assert!(back.is_ok(), "{format:?}: {back:?}");
        let back = back.unwrap();
        prop_assert_eq!(bits(&back), bits(&set));
        // And across formats.
        check_accepted(&back, set.num_actions())?;
    }
}

/// A few small files of each format, every one of their truncations read.
#[test]
fn every_truncation_is_read_or_rejected_in_one_line() {
    let sets = [
        DemonstrationSet::new(
            vec!["x".into(), "y".into()],
            Some(4),
            vec![
                Trajectory::from_states(&[[0.08, 0.6], [0.1, 0.6], [0.1, 0.62]], Some(vec![1, 2])).unwrap(),
                Trajectory::from_states(&[[0.08, 0.6], [0.08, 0.62]], Some(vec![2, 1])).unwrap(),
            ],
        )
        .unwrap(),
        DemonstrationSet::new(
            vec!["a,b".into(), "say \"hi\"".into(), "vélo".into()],
            None,
            vec![Trajectory::from_states(&[[1e-300, -0.0, 0.1 + 0.2], [f64::MAX, 5e-324, 1.0]], None).unwrap()],
        )
        .unwrap(),
    ];
    for set in &sets {
        for format in [Format::Csv, Format::JsonLines] {
            let bytes = written(set, format);
            for crlf in [false, true] {
                let bytes = as_other_tools_write(&bytes, crlf, false);
                for end in 0..=bytes.len() {
                    for num_actions in [None, set.num_actions()] {
                        if let Err(e) = check_read(&bytes[..end], format, num_actions) {
                            panic!("{format:?} cut at {end} of {:?}: {e}", String::from_utf8_lossy(&bytes));
                        }
                    }
                }
            }
        }
    }
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("demonstration-fuzz").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `read_path` picks the format by extension; whatever the bytes and the
/// extension, it reads them or fails in one line naming the path.
#[test]
fn paths_of_any_extension_and_content_are_read_or_rejected_in_one_line() {
    let dir = scratch("paths");
    let contents: [&[u8]; 5] = [
        b"",
        b"trajectory,step,x,action\n0,0,1,2\n",
        b"{\"states\":[[1]],\"actions\":[0]}\n",
        b"\xff\xfe\x00garbage",
        b"trajectory,step,x\n0,0,1\n",
    ];
    for extension in ["csv", "CSV", "jsonl", "ndjson", "Jsonl", "txt", "json", ""] {
        for (k, bytes) in contents.iter().enumerate() {
            let path = dir.join(format!("demos{k}.{extension}"));
            std::fs::write(&path, bytes).unwrap();
            let shown = path.display().to_string();
            match DemonstrationSet::read_path(&path, Some(4)) {
                Ok(set) => assert!(Format::from_path(&path).is_some() && !set.is_empty()),
                Err(e) => {
                    let message = e.to_string();
                    assert!(message.starts_with(&format!("{shown}:")), "{message}");
                    assert!(!message.contains('\n'), "{message:?}");
                }
            }
        }
    }
    // A directory where a file is expected.
    let message = DemonstrationSet::read_path(dir.join(""), None).unwrap_err().to_string();
    assert!(!message.contains('\n'), "{message:?}");
    let sub = dir.join("sub.csv");
    std::fs::create_dir_all(&sub).unwrap();
    let message = DemonstrationSet::read_path(&sub, None).unwrap_err().to_string();
    assert!(message.starts_with(&format!("{}: cannot read", sub.display())), "{message}");
}

// What fuzzing found, kept as plain cases.

#[track_caller]
fn rejects(format: Format, input: &[u8], num_actions: Option<usize>, expected: &str) {
    let message = DemonstrationSet::read(input, name(format), format, num_actions).unwrap_err().to_string();
    assert_eq!(message, expected);
}

#[test]
fn all_empty_actions_without_a_count_are_refused_on_a_line() {
    // Was "demos.csv: trajectory 0 has actions, but the number of actions is not given".
    rejects(
        Format::Csv,
        b"trajectory,step,x,y,action\n0,0,0.08,0.6,\n1,0,0.1,0.6,\n",
        None,
        "demos.csv:2: field \"action\": no trajectory has an action, so the number of actions is unknown (pass it to the reader, or drop the empty \"action\" column)",
    );
    rejects(
        Format::JsonLines,
        b"{\"states\":[[1]],\"actions\":[]}\n",
        None,
        "demos.jsonl:1: field \"actions\": no trajectory has an action, so the number of actions is unknown (declare it in a header line, such as {\"num_actions\":4})",
    );
    // With the count given, such files are fine.
    let set =
        DemonstrationSet::read(&b"trajectory,step,x,action\n0,0,1,\n"[..], CSV_NAME, Format::Csv, Some(4)).unwrap();
    assert_eq!((set.num_actions(), set.trajectories()[0].actions()), (Some(4), Some(&[][..])));
}

#[test]
fn csv_names_padded_with_non_ascii_spaces_are_refused_on_the_header_line() {
    // Was refused without a line: the CSV reader trims ASCII spaces only.
    rejects(
        Format::Csv,
        "trajectory,step,\u{a0}x\n0,0,1\n".as_bytes(),
        None,
        "demos.csv:1: state name 0 (\"\\u{a0}x\") has leading or trailing spaces",
    );
    rejects(
        Format::Csv,
        b"trajectory,step,x,y\x0b\n0,0,1,2\n",
        None,
        "demos.csv:1: state name 1 (\"y\\u{b}\") has leading or trailing spaces",
    );
}

#[test]
fn the_largest_integer_action_does_not_wrap_the_inferred_count() {
    // Was read as usize::MAX, and the count (largest + 1) wrapped to 0:
    // "demos.csv: the number of actions must be at least 1".
    rejects(
        Format::Csv,
        b"trajectory,step,x,action\n0,0,1,18446744073709551615\n",
        None,
        "demos.csv:2: field \"action\": 18446744073709551615 is too large to be an action",
    );
    rejects(
        Format::JsonLines,
        b"{\"states\":[[1]],\"actions\":[18446744073709551615]}\n",
        None,
        "demos.jsonl:1: field \"actions[0]\": 18446744073709551615 is too large to be an action",
    );
}

#[test]
fn wide_headers_and_lines_are_checked_in_near_linear_time() {
    // Duplicate names and keys were found by comparing each with all before
    // it: 100,000 distinct names took billions of comparisons.
    let n = 100_000;
    let names: Vec<String> = (0..n).map(|i| format!("v{i}")).collect();
    let mut csv = format!("trajectory,step,{}\n0,0", names.join(","));
    csv.push_str(&",1".repeat(n));
    csv.push('\n');
    let set = DemonstrationSet::read(csv.as_bytes(), CSV_NAME, Format::Csv, None).unwrap();
    assert_eq!(set.dimension(), n);
    let keys: Vec<String> = (0..n).map(|i| format!("\"k{i}\":0")).collect();
    let jsonl = format!("{{\"states\":[[1]],{}}}\n", keys.join(","));
    rejects(
        Format::JsonLines,
        jsonl.as_bytes(),
        None,
        "demos.jsonl:1: unknown key \"k0\" (expected \"states\" and optionally \"actions\")",
    );
    let header = format!(
        "{{\"state_names\":[{}]}}\n{{\"states\":[[1]]}}\n",
        names.iter().map(|n| format!("{n:?}")).collect::<Vec<_>>().join(",")
    );
    rejects(
        Format::JsonLines,
        header.as_bytes(),
        None,
        &format!("demos.jsonl:2: field \"states[0]\": expected {n} values, found 1"),
    );
}
