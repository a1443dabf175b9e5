//! Byte-level fuzzing of the result store's record reader: whatever bytes sit
//! at a record's path (arbitrary ones, a valid record damaged: bits flipped,
//! truncated at every position, bytes inserted or deleted, fields edited to
//! hold line breaks), `ResultStore::lookup` and `other_versions` never panic;
//! a record that is not the one asked for is `Unreadable`, with a one-line
//! reason, at its path; a saved record reads back to what was saved; and a
//! run in `RunMode::Run` recomputes a damaged record, names it in the tally
//! and gives the result an intact store gives.
//!
//! The default run is a few hundred cases per property; a long run sets
//! `PROPTEST_CASES`, for example
//!
//! ```text
//! PROPTEST_CASES=100000 cargo test --release -p rlfd-harness --test store_fuzz
//! ```

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use proptest::prelude::*;
use proptest::test_runner::Config;
use rlfd_harness::{
    Batch, ExperimentId, FORMAT, HarnessError, Lookup, RecordId, ResultStore, RunContext, RunMode, RunOptions, Scale,
    StoredTrial, TrialKey, TrialRunner,
};
use serde::{Deserialize, Serialize};

/// Cases per property: `PROPTEST_CASES` if set, else `default`.
fn config(default: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(default);
    Config { cases, ..Config::default() }
}

/// A result shaped like the chapters' (numbers, counts, text, an enum, an option).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct Outcome {
    returns: Vec<f64>,
    steps: Vec<u32>,
    label: String,
    kind: Kind,
    note: Option<String>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
enum Kind {
    Plain,
    Shaped { scale: f64 },
}

fn outcomes() -> impl Strategy<Value = Outcome> {
    (
        prop::collection::vec(any::<f64>().prop_filter("finite", |x| x.is_finite()), 0..8),
        prop::collection::vec(any::<u32>(), 0..4),
        ".{0,12}",
        prop_oneof![Just(Kind::Plain), (-1e6_f64..1e6).prop_map(|scale| Kind::Shaped { scale })],
        prop::option::of(".{0,6}"),
    )
        .prop_map(|(returns, steps, label, kind, note)| Outcome { returns, steps, label, kind, note })
}

static DIRS: AtomicUsize = AtomicUsize::new(0);

/// A fresh directory for one case.
fn scratch(name: &str) -> PathBuf {
    let n = DIRS.fetch_add(1, Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("store-fuzz").join(format!("{name}-{n}"));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// The store one property reuses for all its cases (each overwrites the
/// same two records), so that cases cost a write, not a directory tree.
fn reused_store(property: &str) -> ResultStore {
    let store = ResultStore::new(Path::new(env!("CARGO_TARGET_TMPDIR")).join("store-fuzz").join(property));
    std::fs::create_dir_all(store.path(Scale::Quick, 1, &key(), &id()).parent().unwrap()).unwrap();
    store
}

/// The test record's identity.
fn id() -> RecordId {
    RecordId { params: "00112233aabbccdd".into(), code: "0123456789abcdef".into() }
}

/// Another code version of the same parameters.
fn other_code() -> RecordId {
    RecordId { code: "ffffffffffffffff".into(), ..id() }
}

fn key() -> TrialKey {
    TrialKey::new("ch", "exp", "cond", 3)
}

fn record(result: Outcome) -> StoredTrial<Outcome> {
    StoredTrial { format: FORMAT, key: key(), seed: 9, behaviour: 1, build: "build".into(), id: id(), result }
}

/// Writes `bytes` at the record path of the test key and looks it up, and
/// checks what every lookup must give; returns the result, when fresh.
fn lookup_bytes(store: &ResultStore, bytes: &[u8]) -> Result<Option<Outcome>, TestCaseError> {
    let path = store.path(Scale::Quick, 1, &key(), &id());
    std::fs::write(&path, bytes).unwrap();
    // A sibling of another code version holding the same bytes.
    let sibling = store.path(Scale::Quick, 1, &key(), &other_code());
    std::fs::write(&sibling, bytes).unwrap();
    let found = match store.lookup::<Outcome>(&path, &id()) {
        Lookup::Fresh(result) => {
            let stored: Result<StoredTrial<Outcome>, _> = serde_json::from_slice(bytes);
            prop_assert!(stored.is_ok(), "fresh, but not a record");
            Some(result)
        }
        Lookup::Unreadable { path: at, reason } => {
            prop_assert_eq!(&at, &path);
            prop_assert!(!reason.is_empty() && !reason.contains(['\n', '\r']), "reason not one line: {reason:?}");
            None
        }
        Lookup::Missing => {
            prop_assert!(false, "a file that exists is not missing");
            None
        }
    };
    // The other identity's lookup sees the sibling only if it is a record of this trial.
    let others = ResultStore::other_versions::<Outcome>(&sibling, &key(), 9, &other_code());
    for other in &others {
        prop_assert_eq!(other.stored.format, FORMAT);
        prop_assert_eq!(&other.stored.key, &key());
    }
    Ok(found)
}

/// One way of damaging a record.
#[derive(Clone, Debug)]
enum Damage {
    FlipBit(prop::sample::Index, u8),
    Overwrite(prop::sample::Index, u8),
    Insert(prop::sample::Index, Vec<u8>),
    Delete(prop::sample::Index, usize),
    Truncate(prop::sample::Index),
}

fn damage() -> impl Strategy<Value = Damage> {
    use prop::sample::Index;
    prop_oneof![
        (any::<Index>(), 0_u8..8).prop_map(|(i, b)| Damage::FlipBit(i, b)),
        (any::<Index>(), any::<u8>()).prop_map(|(i, b)| Damage::Overwrite(i, b)),
        (any::<Index>(), prop::collection::vec(any::<u8>(), 1..4)).prop_map(|(i, b)| Damage::Insert(i, b)),
        (any::<Index>(), prop::sample::select(vec![&b"\\n"[..], b"\n", b"\"", b",", b"}", b"\xff", b"1e999", b"NaN"]))
            .prop_map(|(i, b)| Damage::Insert(i, b.to_vec())),
        (any::<Index>(), 1_usize..8).prop_map(|(i, n)| Damage::Delete(i, n)),
        any::<Index>().prop_map(Damage::Truncate),
    ]
}

fn apply(bytes: &mut Vec<u8>, damage: &Damage) {
    let len = bytes.len();
    if len == 0 {
        return;
    }
    match damage {
        Damage::FlipBit(i, bit) => bytes[i.index(len)] ^= 1 << bit,
        Damage::Overwrite(i, b) => bytes[i.index(len)] = *b,
        Damage::Insert(i, b) => {
            let at = i.index(len + 1);
            bytes.splice(at..at, b.iter().copied());
        }
        Damage::Delete(i, n) => {
            let at = i.index(len);
            bytes.drain(at..(at + n).min(len));
        }
        Damage::Truncate(i) => bytes.truncate(i.index(len)),
    }
}

/// Records whose text fields hold what a hand edit might put there.
fn edited_records() -> impl Strategy<Value = Vec<u8>> {
    let texts = prop::sample::select(vec!["a\nb", "\r", "é\u{2028}", "`\n`", "\u{0}", "Shaped\nx", ""]);
    (outcomes(), texts.clone(), texts, 0_usize..4).prop_map(|(outcome, text, variant, field)| {
        let mut value = serde_json::to_value(record(outcome)).unwrap();
        match field {
            0 => value["id"]["params"] = text.into(),
            1 => value["result"]["kind"] = variant.into(),
            2 => value["key"]["chapter"] = text.into(),
            _ => value["result"]["unknown\nfield"] = text.into(),
        }
        serde_json::to_vec(&value).unwrap()
    })
}

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn arbitrary_bytes_are_read_or_unreadable(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        lookup_bytes(&reused_store("arbitrary"), &bytes)?;
    }

    #[test]
    fn damaged_records_are_read_or_unreadable(
        outcome in outcomes(),
        damages in prop::collection::vec(damage(), 1..4),
    ) {
        let mut bytes = ResultStore::encode(&record(outcome)).unwrap();
        for d in &damages {
            apply(&mut bytes, d);
        }
        lookup_bytes(&reused_store("damaged"), &bytes)?;
    }

    #[test]
    fn hand_edited_records_are_read_or_unreadable(bytes in edited_records()) {
        lookup_bytes(&reused_store("edited"), &bytes)?;
    }
}

proptest! {
    // Fewer: each case syncs a file to disk.
    #![proptest_config(config(64))]

    #[test]
    fn saved_records_read_back_bit_for_bit(outcome in outcomes()) {
        let store = reused_store("saved");
        let path = store.path(Scale::Quick, 1, &key(), &id());
        // `save` keeps a record that is there (the first writer wins): start
        // each case from none.
        let _ = std::fs::remove_file(&path);
        store.save(&path, &record(outcome.clone())).unwrap();
        match store.lookup::<Outcome>(&path, &id()) {
            Lookup::Fresh(back) => {
                let bits = |o: &Outcome| o.returns.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                prop_assert_eq!(bits(&back), bits(&outcome));
                prop_assert_eq!(back, outcome);
            }
            other => prop_assert!(false, "{other:?}"),
        }
    }
}

/// Every strict prefix of a record is unreadable, never missing or fresh.
#[test]
fn every_truncation_of_a_record_is_unreadable() {
    let outcome = Outcome {
        returns: vec![0.1 + 0.2, -1e-300, 5.0],
        steps: vec![1, 2],
        label: "sis \"κ\"".into(),
        kind: Kind::Shaped { scale: 0.01 },
        note: Some("n".into()),
    };
    let bytes = ResultStore::encode(&record(outcome.clone())).unwrap();
    let store = reused_store("truncated");
    assert_eq!(lookup_bytes(&store, &bytes).unwrap(), Some(outcome));
    for end in 0..bytes.len() {
        assert_eq!(lookup_bytes(&store, &bytes[..end]).unwrap(), None, "cut at {end}");
    }
}

#[derive(Clone, Copy)]
struct Exp;

impl ExperimentId for Exp {
    fn name(self) -> &'static str {
        "exp"
    }
    fn behaviour(self) -> u32 {
        1
    }
}

/// A trial that returns its parameter and a function of its seed.
#[derive(serde::Serialize)]
struct Work;

impl TrialRunner for Work {
    type Setup = ();
    type Params = u64;
    type Result = Vec<u64>;
    type Error = HarnessError;
    fn setup(&self) -> Result<(), HarnessError> {
        Ok(())
    }
    fn run(&self, _: &(), params: &u64, seed: u64) -> Vec<u64> {
        vec![*params, seed % 1000]
    }
}

proptest! {
    // Fewer: each case runs a batch and syncs five records to disk.
    #![proptest_config(config(16))]

    /// `reproduce` (RunMode::Run) recomputes a damaged record, says which,
    /// and returns what an intact store returns; `report` (RunMode::Load)
    /// refuses it by name.
    #[test]
    fn a_run_recomputes_damaged_records_and_names_them(
        victim in 0_u32..4,
        damages in prop::collection::vec(damage(), 1..4),
    ) {
        let dir = scratch("run");
        let options = RunOptions::new(ResultStore::new(&dir), 1);
        let mut batch = Batch::new(&RunContext::new(5, Scale::Quick), "ch", Exp, Work);
        for t in 0..4 {
            batch.trial("c", t, u64::from(t) * 10);
        }
        let first = batch.execute(&options).unwrap();
        let spec = &batch.trials()[victim as usize];
        let path = batch.path(&options.store, spec);
        let mut bytes = std::fs::read(&path).unwrap();
        for d in &damages {
            apply(&mut bytes, d);
        }
        std::fs::write(&path, &bytes).unwrap();
        // A damage may leave a record of the same identity (a space added, a
        // digit of the result changed): the store cannot tell, and reuses it.
        let still_fresh = match options.store.lookup::<Vec<u64>>(&path, &spec.id) {
            Lookup::Fresh(result) => Some(result),
            _ => None,
        };
        let mut expected = first.results.clone();
        if let Some(result) = &still_fresh {
            expected[victim as usize] = result.clone();
        }
        let still_fresh = still_fresh.is_some();

        let load = options.with_mode(RunMode::Load { any_version: false });
        match batch.execute(&load) {
            Ok(_) => prop_assert!(still_fresh && load.tally.totals().0 == 0),
            Err(e) => {
                let message = e.to_string();
                prop_assert!(!still_fresh);
                prop_assert!(!message.contains('\n'), "{message:?}");
                prop_assert!(message.contains(&spec.key.to_string()), "{message}");
                prop_assert!(message.contains(&path.display().to_string()), "{message}");
            }
        }

        let run = options.with_mode(RunMode::Run);
        let again = batch.execute(&run).unwrap();
        let tally = run.tally.experiments()[&("ch".to_string(), "exp".to_string())].clone();
        if still_fresh {
            prop_assert_eq!(tally.computed, 0);
            prop_assert!(tally.replaced.is_empty());
        } else {
            prop_assert_eq!(tally.computed, 1);
            prop_assert_eq!(tally.replaced.len(), 1);
            prop_assert_eq!(&tally.replaced[0].0, &path);
            prop_assert!(!tally.replaced[0].1.contains('\n'));
            // The replacement is a whole record again.
            prop_assert!(matches!(options.store.lookup::<Vec<u64>>(&path, &spec.id), Lookup::Fresh(_)));
        }
        prop_assert_eq!(again.results, expected);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
