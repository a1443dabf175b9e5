//! The result store: one JSON file per finished trial and identity, written
//! once, atomically.
//!
//! Layout: `<root>/<scale>/seed-<master>/<chapter>/<experiment>/<condition>/trial-<NNN>.<params>.<code>.json`.
//! The two digests in the name are the trial's identity ([`RecordId`]):
//! `params` is what the harness computed from the trial's serialised
//! parameters and its set-up's determinants (so the same trial under two
//! readings that set different parameters has two records side by side, and
//! under two readings that leave it alone, one), `code` is the build
//! identity and the experiment's behaviour version (so "another version of
//! this trial" means the same `params` with another `code`). Records never
//! overwrite each other, so switching branches keeps both, and two processes
//! that compute the same trial write the same bytes to the same name.
//!
//! Many processes may write one store at once, on one machine or on a shared
//! file system (a cluster's shards): a record is written to a temporary file
//! in its directory (a name starting with `.`, which every reader ignores,
//! made unique by `tempfile`), then persisted only if no record of that
//! identity exists yet ([`ResultStore::save`]): the first writer wins, a later
//! one (which computed the same bytes) drops its copy, and a record, once
//! there, is never replaced under a reader, except an unreadable one
//! ([`ResultStore::replace`], a rename). A killed process leaves the whole
//! record or none. No lock is taken, so none is left behind.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::error::HarnessError;
use crate::scale::Scale;
use crate::seed::TrialKey;

/// A trial's identity, as two digests (16 hex digits each).
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct RecordId {
    /// The digest of the trial's parameters and of its set-up's determinants.
    pub params: String,
    /// The digest of the build identity and the experiment's behaviour version.
    pub code: String,
}

/// One stored trial.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StoredTrial<T> {
    /// Format version of the file.
    pub format: u32,
    /// The trial.
    pub key: TrialKey,
    /// Its seed.
    pub seed: u64,
    /// The behaviour version of its experiment that made it.
    pub behaviour: u32,
    /// The build identity that made it (rustc release, result crates).
    pub build: String,
    /// Its identity.
    pub id: RecordId,
    /// What the trial computed.
    pub result: T,
}

/// The current record format.
pub const FORMAT: u32 = 3;

/// Where finished trials live.
#[derive(Clone, Debug)]
pub struct ResultStore {
    root: PathBuf,
}

/// What a lookup found.
#[derive(Debug)]
pub enum Lookup<T> {
    /// A result of the same identity.
    Fresh(T),
    /// The record of this identity exists but cannot be read (truncated,
    /// edited, or of a result type this code cannot parse).
    Unreadable { path: PathBuf, reason: String },
    /// No record of this identity.
    Missing,
}

/// A record of the same trial (same parameters) made by other code.
#[derive(Debug)]
pub struct OtherVersion<T> {
    /// The file.
    pub path: PathBuf,
    /// The record.
    pub stored: StoredTrial<T>,
}

impl ResultStore {
    /// A store rooted at `root` (created on first write).
    pub fn new(root: impl Into<PathBuf>) -> Self {
        ResultStore { root: root.into() }
    }

    /// The root directory.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// The file of a trial of identity `id`.
    pub fn path(&self, scale: Scale, master: u64, key: &TrialKey, id: &RecordId) -> PathBuf {
        self.root
            .join(scale.as_str())
            .join(format!("seed-{master}"))
            .join(&key.chapter)
            .join(&key.experiment)
            .join(&key.condition)
            .join(format!("trial-{:03}.{}.{}.json", key.trial, id.params, id.code))
    }

    /// Looks up the record of a trial's identity.
    ///
    /// Any bytes at `path` give `Fresh` or `Unreadable`, never a panic; the
    /// reason is one line (text from the file is escaped). Only a path that
    /// does not exist is `Missing`: one that cannot be read (a directory, no
    /// permission) is `Unreadable`, so it is reported rather than silently
    /// taken for a trial never run.
    pub fn lookup<T: DeserializeOwned>(&self, path: &Path, id: &RecordId) -> Lookup<T> {
        let unreadable = |reason: String| Lookup::Unreadable { path: path.to_path_buf(), reason: one_line(&reason) };
        let bytes = match fs::read(path) {
            Ok(bytes) => bytes,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Lookup::Missing,
            Err(e) => return unreadable(format!("cannot read it: {e}")),
        };
        match serde_json::from_slice::<StoredTrial<T>>(&bytes) {
            Ok(stored) if stored.format == FORMAT && stored.id == *id => Lookup::Fresh(stored.result),
            Ok(stored) => unreadable(format!(
                "it holds format {} and identity {:?}.{:?}",
                stored.format, stored.id.params, stored.id.code
            )),
            Err(e) => unreadable(e.to_string()),
        }
    }

    /// The readable records of the same trial (key, seed and parameters)
    /// beside the record `path` made by other code (another behaviour
    /// version or build), newest behaviour version first (ties by file
    /// name, so the choice does not depend on the file system's order).
    pub fn other_versions<T: DeserializeOwned>(
        path: &Path,
        key: &TrialKey,
        seed: u64,
        id: &RecordId,
    ) -> Vec<OtherVersion<T>> {
        let Some(dir) = path.parent() else {
            return Vec::new();
        };
        let prefix = format!("trial-{:03}.{}.", key.trial, id.params);
        let Ok(entries) = fs::read_dir(dir) else {
            return Vec::new();
        };
        let own = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let mut names: Vec<String> = entries
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| n.starts_with(&prefix) && n.ends_with(".json") && *n != own)
            .collect();
        names.sort();
        let mut found: Vec<OtherVersion<T>> = names
            .into_iter()
            .filter_map(|n| {
                let path = dir.join(n);
                let stored: StoredTrial<T> = serde_json::from_slice(&fs::read(&path).ok()?).ok()?;
                (stored.format == FORMAT && &stored.key == key && stored.seed == seed && stored.id.params == id.params)
                    .then_some(OtherVersion { path, stored })
            })
            .collect();
        found.sort_by_key(|o| std::cmp::Reverse(o.stored.behaviour));
        found
    }

    /// The bytes [`ResultStore::save`] writes for `stored`.
    pub fn encode<T: Serialize>(stored: &StoredTrial<T>) -> Result<Vec<u8>, HarnessError> {
        serde_json::to_vec(stored).map_err(|source| HarnessError::Encode { trial: stored.key.to_string(), source })
    }

    /// Writes a trial atomically, unless a record of its identity is already
    /// there (another process stored the same trial first: it keeps it).
    pub fn save<T: Serialize>(&self, path: &Path, stored: &StoredTrial<T>) -> Result<(), HarnessError> {
        write_new(path, &Self::encode(stored)?)
    }

    /// Writes a trial atomically in place of whatever record is there (an
    /// unreadable one).
    pub fn replace<T: Serialize>(&self, path: &Path, stored: &StoredTrial<T>) -> Result<(), HarnessError> {
        write_atomically(path, &Self::encode(stored)?)
    }
}

/// A fresh temporary file beside `path` holding `bytes`, flushed to disk;
/// its name starts with `.` (readers ignore it) and is unique among writers
/// of any thread, process or host (`tempfile`'s random names, created with
/// `O_EXCL`).
fn write_temp(path: &Path, bytes: &[u8]) -> Result<tempfile::NamedTempFile, HarnessError> {
    let dir = path.parent().expect("records and reports live in a directory");
    fs::create_dir_all(dir).map_err(|source| HarnessError::Io {
        action: "cannot create directory",
        path: dir.to_path_buf(),
        source,
    })?;
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let mut temp = tempfile::Builder::new().prefix(&format!(".{name}.tmp-")).tempfile_in(dir).map_err(|source| {
        HarnessError::Io { action: "cannot create a temporary file in", path: dir.to_path_buf(), source }
    })?;
    let at = temp.path().to_path_buf();
    temp.write_all(bytes).map_err(|source| HarnessError::Io { action: "cannot write", path: at.clone(), source })?;
    temp.as_file().sync_data().map_err(|source| HarnessError::Io { action: "cannot flush", path: at, source })?;
    Ok(temp)
}

/// Writes `bytes` to `path` atomically unless `path` exists (`tempfile`'s
/// no-clobber persist: a hard link, or a rename that refuses to replace):
/// the first writer wins and a later one drops its copy.
pub fn write_new(path: &Path, bytes: &[u8]) -> Result<(), HarnessError> {
    let temp = write_temp(path, bytes)?;
    match temp.persist_noclobber(path) {
        Ok(_) => Ok(()),
        Err(e) if e.error.kind() == std::io::ErrorKind::AlreadyExists => Ok(()),
        Err(e) => Err(HarnessError::Io { action: "cannot persist", path: path.to_path_buf(), source: e.error }),
    }
}

/// Writes `bytes` to `path` through a temporary file in the same directory
/// and a rename, so that readers see the old file, or the whole new one.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), HarnessError> {
    let temp = write_temp(path, bytes)?;
    temp.persist(path).map(|_| ()).map_err(|e| HarnessError::Io {
        action: "cannot rename into",
        path: path.to_path_buf(),
        source: e.error,
    })
}

/// `text` with its control characters (line breaks, tabs, NUL) escaped, so
/// that a reason quoting a file's contents stays one line. Serde's messages
/// quote some of the input as it is (an unknown variant or field's name).
fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() {
            out.extend(c.escape_debug());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn id(params: &str, code: &str) -> RecordId {
        RecordId { params: params.into(), code: code.into() }
    }

    fn record<T>(key: TrialKey, behaviour: u32, id: RecordId, result: T) -> StoredTrial<T> {
        StoredTrial { format: FORMAT, key, seed: 9, behaviour, build: "b".into(), id, result }
    }

    fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("rlfd-store-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn save_then_lookup_round_trips_and_checks_identities() {
        let store = ResultStore::new(temp_dir("roundtrip"));
        let key = TrialKey::new("ch", "exp", "cond", 7);
        let (v1, v2) = (id("aaa", "c1"), id("aaa", "c2"));
        let path = store.path(Scale::Quick, 42, &key, &v1);
        assert!(path.ends_with("quick/seed-42/ch/exp/cond/trial-007.aaa.c1.json"));
        assert!(matches!(store.lookup::<Vec<f64>>(&path, &v1), Lookup::Missing));
        store.save(&path, &record(key.clone(), 1, v1.clone(), vec![1.5, -2.0])).unwrap();
        match store.lookup::<Vec<f64>>(&path, &v1) {
            Lookup::Fresh(r) => assert_eq!(r, vec![1.5, -2.0]),
            other => panic!("expected a fresh result, got {other:?}"),
        }
        assert!(matches!(store.lookup::<Vec<f64>>(&path, &v2), Lookup::Unreadable { .. }));
        // No temporary file is left behind.
        let names: Vec<_> = fs::read_dir(path.parent().unwrap()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("trial-007.aaa.c1.json")]);
        // Other code's record of the same parameters sits beside it; each sees the other.
        store.save(&store.path(Scale::Quick, 42, &key, &v2), &record(key.clone(), 2, v2.clone(), vec![3.0])).unwrap();
        // A record of other parameters (another reading) is not another version.
        let other_params = id("bbb", "c1");
        store
            .save(&store.path(Scale::Quick, 42, &key, &other_params), &record(key.clone(), 1, other_params, vec![0.0]))
            .unwrap();
        let others = ResultStore::other_versions::<Vec<f64>>(&path, &key, 9, &v1);
        assert_eq!(others.len(), 1);
        assert_eq!((others[0].stored.behaviour, others[0].stored.result.clone()), (2, vec![3.0]));
        let others = ResultStore::other_versions::<Vec<f64>>(&store.path(Scale::Quick, 42, &key, &v2), &key, 9, &v2);
        assert_eq!(others[0].stored.id, v1);
        // A truncated record is unreadable, not missing.
        fs::write(&path, b"{\"format\": 3, \"key\"").unwrap();
        assert!(matches!(store.lookup::<Vec<f64>>(&path, &v1), Lookup::Unreadable { .. }));
        fs::remove_dir_all(store.root()).unwrap();
    }

    #[test]
    fn reasons_are_one_line_and_unreadable_paths_are_not_missing() {
        let store = ResultStore::new(temp_dir("reasons"));
        let key = TrialKey::new("ch", "exp", "cond", 0);
        let good = id("abc", "def");
        let path = store.path(Scale::Quick, 1, &key, &good);
        // An edited identity puts its line break in the reason.
        store.save(&path, &record(key.clone(), 1, id("a\nb", "def"), 0_u32)).unwrap();
        match store.lookup::<u32>(&path, &good) {
            Lookup::Unreadable { reason, .. } => assert_eq!(reason, r#"it holds format 3 and identity "a\nb"."def""#),
            other => panic!("{other:?}"),
        }
        // Serde quotes an unknown variant as it is.
        #[derive(Debug, Deserialize)]
        enum Kind {
            Plain,
        }
        fs::write(&path, br#"{"format":3,"key":{"chapter":"ch","experiment":"exp","condition":"cond","trial":0},"seed":9,"behaviour":1,"build":"b","id":{"params":"abc","code":"def"},"result":"Pl\nain"}"#).unwrap();
        match store.lookup::<Kind>(&path, &good) {
            Lookup::Unreadable { reason, .. } => {
                assert!(!reason.contains('\n') && reason.contains(r"Pl\nain"), "{reason}");
            }
            other => panic!("{other:?}"),
        }
        // A directory where the record should be is unreadable, not missing.
        fs::remove_file(&path).unwrap();
        fs::create_dir(&path).unwrap();
        match store.lookup::<Kind>(&path, &good) {
            Lookup::Unreadable { reason, .. } => assert!(reason.starts_with("cannot read it: "), "{reason}"),
            other => panic!("{other:?}"),
        }
        fs::remove_dir_all(store.root()).unwrap();
    }

    #[test]
    fn unwritable_root_is_an_error_naming_the_path() {
        let file = temp_dir("unwritable");
        fs::write(&file, b"not a directory").unwrap();
        let store = ResultStore::new(&file);
        let key = TrialKey::new("ch", "exp", "cond", 0);
        let path = store.path(Scale::Quick, 1, &key, &id("f", "g"));
        let e = store.save(&path, &record(key.clone(), 1, id("f", "g"), 0)).unwrap_err();
        assert!(e.to_string().starts_with("cannot create directory"), "{e}");
        fs::remove_file(&file).unwrap();
    }

    #[test]
    fn many_writers_of_one_identity_leave_one_whole_record_and_no_temporary_file() {
        let store = ResultStore::new(temp_dir("writers"));
        let key = TrialKey::new("ch", "exp", "cond", 3);
        let path = store.path(Scale::Quick, 42, &key, &id("abc", "def"));
        let stored = record(key, 1, id("abc", "def"), vec![0.25; 2000]);
        std::thread::scope(|scope| {
            for _ in 0..8 {
                scope.spawn(|| {
                    for _ in 0..25 {
                        store.save(&path, &stored).unwrap();
                        match store.lookup::<Vec<f64>>(&path, &id("abc", "def")) {
                            Lookup::Fresh(r) => assert_eq!(r.len(), 2000),
                            other => panic!("a reader saw {other:?}"),
                        }
                    }
                });
            }
        });
        let names: Vec<_> = fs::read_dir(path.parent().unwrap()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("trial-003.abc.def.json")]);
        assert_eq!(fs::read(&path).unwrap(), ResultStore::encode(&stored).unwrap());
        fs::remove_dir_all(store.root()).unwrap();
    }

    #[test]
    fn save_keeps_the_first_record_and_replace_overwrites_it() {
        let dir = temp_dir("first");
        let path = dir.join("trial-000.x.y.json");
        write_new(&path, b"first").unwrap();
        write_new(&path, b"second").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"first");
        write_atomically(&path, b"third").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"third");
        assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
        fs::remove_dir_all(&dir).unwrap();
    }
}
