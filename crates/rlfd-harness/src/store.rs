//! The result store: one JSON file per finished trial and identity, written
//! once, atomically.
//!
//! Layout: `<root>/<scale>/seed-<master>/[reading-<label>/]<chapter>/<experiment>/<condition>/trial-<NNN>.<fingerprint>.json`
//! (the reading's folder only for a non-default reading of the axes that
//! change the experiment).
//! The fingerprint in the name is the trial's identity (see [`crate::TrialPlan`]):
//! records of different behaviour versions, builds or parameters sit side by
//! side and never overwrite each other, so switching branches keeps both, and
//! two processes that compute the same trial write the same bytes to the same
//! name.
//!
//! Many processes may write one store at once, on one machine or on a shared
//! file system (a cluster's shards): a record is written to a temporary file
//! in its directory, named after the host, the process and a counter (so no
//! two writers anywhere share one), then linked into place only if no record
//! of that identity exists yet ([`ResultStore::save`]): the first writer wins,
//! a later one (which computed the same bytes) drops its copy, and a record,
//! once there, is never replaced under a reader, except an unreadable one
//! ([`ResultStore::replace`], a rename). A killed process leaves the whole
//! record or none; temporary files start with `.` and every reader ignores
//! them. No lock is taken, so none is left behind.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::sync::atomic::{AtomicU64, Ordering};

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::error::HarnessError;
use crate::readings::Reading;
use crate::scale::Scale;
use crate::seed::TrialKey;

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
    /// The build identity that made it (rustc release, dependency closure).
    pub build: String,
    /// Its identity: build, behaviour, parameters and inputs.
    pub fingerprint: String,
    /// What the trial computed.
    pub result: T,
}

/// The current record format.
pub const FORMAT: u32 = 2;

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

/// A record of the same trial made by another identity.
#[derive(Debug)]
pub struct OtherVersion<T> {
    /// The file.
    pub path: PathBuf,
    /// The record.
    pub stored: StoredTrial<T>,
}

static TEMP_COUNTER: AtomicU64 = AtomicU64::new(0);

impl ResultStore {
    /// A store rooted at `root` (created on first write).
    pub fn new(root: impl Into<PathBuf>) -> Self {
        ResultStore { root: root.into() }
    }

    /// The root directory.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// The directory of one condition's trials.
    fn condition_dir(&self, scale: Scale, master: u64, reading: &Reading, key: &TrialKey) -> PathBuf {
        let mut dir = self.root.join(scale.as_str()).join(format!("seed-{master}"));
        if !reading.is_default() {
            dir = dir.join(format!("reading-{}", reading.label()));
        }
        dir.join(&key.chapter).join(&key.experiment).join(&key.condition)
    }

    /// The file of a trial of identity `fingerprint`.
    pub fn path(&self, scale: Scale, master: u64, reading: &Reading, key: &TrialKey, fingerprint: &str) -> PathBuf {
        self.condition_dir(scale, master, reading, key).join(format!("trial-{:03}.{fingerprint}.json", key.trial))
    }

    /// Looks up the record of a trial's identity.
    ///
    /// Any bytes at `path` give `Fresh` or `Unreadable`, never a panic; the
    /// reason is one line (text from the file is escaped). Only a path that
    /// does not exist is `Missing`: one that cannot be read (a directory, no
    /// permission) is `Unreadable`, so it is reported rather than silently
    /// taken for a trial never run.
    pub fn lookup<T: DeserializeOwned>(&self, path: &Path, fingerprint: &str) -> Lookup<T> {
        let unreadable = |reason: String| Lookup::Unreadable { path: path.to_path_buf(), reason: one_line(&reason) };
        let bytes = match fs::read(path) {
            Ok(bytes) => bytes,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Lookup::Missing,
            Err(e) => return unreadable(format!("cannot read it: {e}")),
        };
        match serde_json::from_slice::<StoredTrial<T>>(&bytes) {
            Ok(stored) if stored.format == FORMAT && stored.fingerprint == fingerprint => Lookup::Fresh(stored.result),
            Ok(stored) => {
                unreadable(format!("it holds format {} and identity {:?}", stored.format, stored.fingerprint))
            }
            Err(e) => unreadable(e.to_string()),
        }
    }

    /// The readable records of the same trial (key and seed) made by other
    /// identities, newest behaviour version first (ties by file name, so the
    /// choice does not depend on the file system's order).
    pub fn other_versions<T: DeserializeOwned>(
        &self,
        scale: Scale,
        master: u64,
        reading: &Reading,
        key: &TrialKey,
        seed: u64,
        fingerprint: &str,
    ) -> Vec<OtherVersion<T>> {
        let path = self.path(scale, master, reading, key, fingerprint);
        Self::other_versions_beside(&path, key, seed)
    }

    /// The readable records of the same trial (key and seed) beside the
    /// record `path` (another identity's), as [`ResultStore::other_versions`].
    pub fn other_versions_beside<T: DeserializeOwned>(path: &Path, key: &TrialKey, seed: u64) -> Vec<OtherVersion<T>> {
        let Some(dir) = path.parent() else {
            return Vec::new();
        };
        let prefix = format!("trial-{:03}.", key.trial);
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
                (stored.format == FORMAT && &stored.key == key && stored.seed == seed)
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
        Self::create_dir(path)?;
        write_new(path, &Self::encode(stored)?)
    }

    /// Writes a trial atomically in place of whatever record is there (an
    /// unreadable one).
    pub fn replace<T: Serialize>(&self, path: &Path, stored: &StoredTrial<T>) -> Result<(), HarnessError> {
        Self::create_dir(path)?;
        write_atomically(path, &Self::encode(stored)?)
    }

    fn create_dir(path: &Path) -> Result<(), HarnessError> {
        let dir = path.parent().expect("trial files live in a directory");
        fs::create_dir_all(dir).map_err(|source| HarnessError::Io {
            action: "cannot create directory",
            path: dir.to_path_buf(),
            source,
        })
    }
}

/// This host's name as a file name can hold it (letters, digits, `-`, `_`),
/// read once: part of every temporary file's name, so that writers on
/// different machines of a shared file system never pick the same one.
fn host_tag() -> &'static str {
    static TAG: OnceLock<String> = OnceLock::new();
    TAG.get_or_init(|| {
        let name = fs::read_to_string("/proc/sys/kernel/hostname")
            .or_else(|_| fs::read_to_string("/etc/hostname"))
            .ok()
            .or_else(|| std::env::var("HOSTNAME").ok().or_else(|| std::env::var("COMPUTERNAME").ok()))
            .unwrap_or_default();
        let tag: String = name.trim().chars().filter(|c| c.is_ascii_alphanumeric() || *c == '-' || *c == '_').collect();
        if tag.is_empty() { "host".to_string() } else { tag }
    })
}

/// A temporary file beside `path` that no other writer (thread, process or
/// host) names the same: `.<name>.tmp-<host>-<pid>-<counter>`.
fn temp_path(path: &Path) -> PathBuf {
    let dir = path.parent().unwrap_or(Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    dir.join(format!(
        ".{name}.tmp-{}-{}-{}",
        host_tag(),
        std::process::id(),
        TEMP_COUNTER.fetch_add(1, Ordering::Relaxed)
    ))
}

/// Writes `bytes` to a fresh temporary file beside `path`, flushed to disk.
fn write_temp(path: &Path, bytes: &[u8]) -> Result<PathBuf, HarnessError> {
    let temp = temp_path(path);
    let written = (|| {
        let mut f = fs::File::create_new(&temp).map_err(|source| HarnessError::Io {
            action: "cannot create",
            path: temp.clone(),
            source,
        })?;
        f.write_all(bytes).map_err(|source| HarnessError::Io { action: "cannot write", path: temp.clone(), source })?;
        f.sync_data().map_err(|source| HarnessError::Io { action: "cannot flush", path: temp.clone(), source })
    })();
    match written {
        Ok(()) => Ok(temp),
        Err(e) => {
            let _ = fs::remove_file(&temp);
            Err(e)
        }
    }
}

/// Writes `bytes` to `path` atomically unless `path` exists: the bytes go to
/// a temporary file that is hard-linked to `path` (which fails, leaving
/// `path` as it is, when a file is there) and then removed. Where the file
/// system has no hard links, it falls back to a rename (atomic, but the last
/// writer wins).
pub fn write_new(path: &Path, bytes: &[u8]) -> Result<(), HarnessError> {
    let temp = write_temp(path, bytes)?;
    let result = match fs::hard_link(&temp, path) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => Ok(()),
        Err(_) => {
            return fs::rename(&temp, path).map_err(|source| {
                let _ = fs::remove_file(&temp);
                HarnessError::Io { action: "cannot rename into", path: path.to_path_buf(), source }
            });
        }
    };
    let _ = fs::remove_file(&temp);
    result
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

/// Writes `bytes` to `path` through a temporary file in the same directory
/// and a rename, so that readers see the old file, or the whole new one.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), HarnessError> {
    let temp = write_temp(path, bytes)?;
    fs::rename(&temp, path).map_err(|source| {
        let _ = fs::remove_file(&temp);
        HarnessError::Io { action: "cannot rename into", path: path.to_path_buf(), source }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record<T>(key: TrialKey, behaviour: u32, fingerprint: &str, result: T) -> StoredTrial<T> {
        StoredTrial {
            format: FORMAT,
            key,
            seed: 9,
            behaviour,
            build: "b".into(),
            fingerprint: fingerprint.into(),
            result,
        }
    }

    fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("rlfd-store-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn save_then_lookup_round_trips_and_checks_fingerprints() {
        let store = ResultStore::new(temp_dir("roundtrip"));
        let key = TrialKey::new("ch", "exp", "cond", 7);
        let path = store.path(Scale::Quick, 42, &Reading::defaults(), &key, "abc");
        assert!(path.ends_with("quick/seed-42/ch/exp/cond/trial-007.abc.json"));
        assert!(matches!(store.lookup::<Vec<f64>>(&path, "abc"), Lookup::Missing));
        let stored = record(key.clone(), 1, "abc", vec![1.5, -2.0]);
        store.save(&path, &stored).unwrap();
        match store.lookup::<Vec<f64>>(&path, "abc") {
            Lookup::Fresh(r) => assert_eq!(r, vec![1.5, -2.0]),
            other => panic!("expected a fresh result, got {other:?}"),
        }
        assert!(matches!(store.lookup::<Vec<f64>>(&path, "other"), Lookup::Unreadable { .. }));
        // No temporary file is left behind.
        let names: Vec<_> = fs::read_dir(path.parent().unwrap()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("trial-007.abc.json")]);
        // A second identity sits beside the first; each sees the other.
        let newer = record(key.clone(), 2, "def", vec![3.0]);
        store.save(&store.path(Scale::Quick, 42, &Reading::defaults(), &key, "def"), &newer).unwrap();
        let others = store.other_versions::<Vec<f64>>(Scale::Quick, 42, &Reading::defaults(), &key, 9, "abc");
        assert_eq!(others.len(), 1);
        assert_eq!((others[0].stored.behaviour, others[0].stored.result.clone()), (2, vec![3.0]));
        let others = store.other_versions::<Vec<f64>>(Scale::Quick, 42, &Reading::defaults(), &key, 9, "def");
        assert_eq!(others[0].stored.fingerprint, "abc");
        // A truncated record is unreadable, not missing.
        fs::write(&path, b"{\"format\": 2, \"key\"").unwrap();
        assert!(matches!(store.lookup::<Vec<f64>>(&path, "abc"), Lookup::Unreadable { .. }));
        fs::remove_dir_all(store.root()).unwrap();
    }

    #[test]
    fn reasons_are_one_line_and_unreadable_paths_are_not_missing() {
        let store = ResultStore::new(temp_dir("reasons"));
        let key = TrialKey::new("ch", "exp", "cond", 0);
        let path = store.path(Scale::Quick, 1, &Reading::defaults(), &key, "abc");
        // Found by fuzzing: an edited identity put its line break in the reason.
        store.save(&path, &record(key.clone(), 1, "a\nb", 0_u32)).unwrap();
        match store.lookup::<u32>(&path, "abc") {
            Lookup::Unreadable { reason, .. } => assert_eq!(reason, r#"it holds format 2 and identity "a\nb""#),
            other => panic!("{other:?}"),
        }
        // Serde quotes an unknown variant as it is.
        #[derive(Debug, Deserialize)]
        enum Kind {
            Plain,
        }
        fs::write(&path, br#"{"format":2,"key":{"chapter":"ch","experiment":"exp","condition":"cond","trial":0},"seed":9,"behaviour":1,"build":"b","fingerprint":"abc","result":"Pl\nain"}"#).unwrap();
        match store.lookup::<Kind>(&path, "abc") {
            Lookup::Unreadable { reason, .. } => {
                assert!(!reason.contains('\n') && reason.contains(r"Pl\nain"), "{reason}");
            }
            other => panic!("{other:?}"),
        }
        // A directory where the record should be is unreadable, not missing.
        fs::remove_file(&path).unwrap();
        fs::create_dir(&path).unwrap();
        match store.lookup::<Kind>(&path, "abc") {
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
        let path = store.path(Scale::Quick, 1, &Reading::defaults(), &key, "f");
        let e = store.save(&path, &record(key.clone(), 1, "f", 0)).unwrap_err();
        assert!(e.to_string().starts_with("cannot create directory"), "{e}");
        fs::remove_file(&file).unwrap();
    }

    #[test]
    fn many_writers_of_one_identity_leave_one_whole_record_and_no_temporary_file() {
        let store = ResultStore::new(temp_dir("writers"));
        let key = TrialKey::new("ch", "exp", "cond", 3);
        let path = store.path(Scale::Quick, 42, &Reading::defaults(), &key, "abc");
        let stored = record(key, 1, "abc", vec![0.25; 2000]);
        std::thread::scope(|scope| {
            for _ in 0..8 {
                scope.spawn(|| {
                    for _ in 0..25 {
                        store.save(&path, &stored).unwrap();
                        match store.lookup::<Vec<f64>>(&path, "abc") {
                            Lookup::Fresh(r) => assert_eq!(r.len(), 2000),
                            other => panic!("a reader saw {other:?}"),
                        }
                    }
                });
            }
        });
        let names: Vec<_> = fs::read_dir(path.parent().unwrap()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("trial-003.abc.json")]);
        assert_eq!(fs::read(&path).unwrap(), ResultStore::encode(&stored).unwrap());
        fs::remove_dir_all(store.root()).unwrap();
    }

    #[test]
    fn save_keeps_the_first_record_and_replace_overwrites_it() {
        let dir = temp_dir("first");
        fs::create_dir_all(&dir).unwrap();
        let path = dir.join("trial-000.x.json");
        write_new(&path, b"first").unwrap();
        write_new(&path, b"second").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"first");
        write_atomically(&path, b"third").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"third");
        assert_eq!(fs::read_dir(&dir).unwrap().count(), 1);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn temporary_names_carry_host_process_and_counter() {
        let a = temp_path(Path::new("/s/trial-001.f.json"));
        let b = temp_path(Path::new("/s/trial-001.f.json"));
        assert_ne!(a, b);
        let name = a.file_name().unwrap().to_string_lossy().into_owned();
        let prefix = format!(".trial-001.f.json.tmp-{}-{}-", host_tag(), std::process::id());
        assert!(name.starts_with(&prefix), "{name}");
        assert!(
            !host_tag().is_empty() && host_tag().chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
        );
    }
}
