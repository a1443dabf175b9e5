//! The result store: one JSON file per finished trial, written once,
//! atomically.
//!
//! Layout: `<root>/<scale>/seed-<master>/<chapter>/<experiment>/<condition>/trial-<NNN>.json`.
//! A file holds the trial's key, seed, fingerprint and result. It is written
//! to a temporary file in the same directory and renamed into place, so a
//! killed process leaves either the whole file or none (temporary files of a
//! killed run are ignored and replaced). A file whose fingerprint differs from
//! the current one was made by other code or parameters: it is never reused.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::error::HarnessError;
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
    /// Fingerprint of parameters, inputs and code.
    pub fingerprint: String,
    /// What the trial computed.
    pub result: T,
}

const FORMAT: u32 = 1;

/// Where finished trials live.
#[derive(Clone, Debug)]
pub struct ResultStore {
    root: PathBuf,
}

/// What a lookup found.
#[derive(Debug)]
pub enum Lookup<T> {
    /// A result of the same computation.
    Fresh(T),
    /// A file made by other code or parameters.
    Stale { found: String },
    /// No file.
    Missing,
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

    /// The file of a trial.
    pub fn path(&self, scale: Scale, master: u64, key: &TrialKey) -> PathBuf {
        self.root
            .join(scale.as_str())
            .join(format!("seed-{master}"))
            .join(&key.chapter)
            .join(&key.experiment)
            .join(&key.condition)
            .join(format!("trial-{:03}.json", key.trial))
    }

    /// Looks a trial up.
    pub fn lookup<T: DeserializeOwned>(&self, path: &Path, fingerprint: &str) -> Lookup<T> {
        let Ok(text) = fs::read(path) else {
            return Lookup::Missing;
        };
        match serde_json::from_slice::<StoredTrial<T>>(&text) {
            Ok(stored) if stored.format == FORMAT && stored.fingerprint == fingerprint => Lookup::Fresh(stored.result),
            Ok(stored) => Lookup::Stale { found: stored.fingerprint },
            // Unreadable: treat as made by other code (never reused).
            Err(_) => Lookup::Stale { found: "unreadable".into() },
        }
    }

    /// Writes a trial atomically.
    pub fn save<T: Serialize>(&self, path: &Path, stored: &StoredTrial<T>) -> Result<(), HarnessError> {
        let dir = path.parent().expect("trial files live in a directory");
        fs::create_dir_all(dir).map_err(|source| HarnessError::Io {
            action: "cannot create directory",
            path: dir.to_path_buf(),
            source,
        })?;
        let bytes = serde_json::to_vec(stored)
            .map_err(|source| HarnessError::Encode { trial: stored.key.to_string(), source })?;
        write_atomically(path, &bytes)
    }
}

/// Writes `bytes` to `path` through a temporary file in the same directory
/// and a rename, so that readers see the old file, or the whole new one.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), HarnessError> {
    let dir = path.parent().unwrap_or(Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let temp = dir.join(format!(".{name}.tmp-{}-{}", std::process::id(), TEMP_COUNTER.fetch_add(1, Ordering::Relaxed)));
    let result = (|| {
        let mut f = fs::File::create(&temp).map_err(|source| HarnessError::Io {
            action: "cannot create",
            path: temp.clone(),
            source,
        })?;
        f.write_all(bytes).map_err(|source| HarnessError::Io { action: "cannot write", path: temp.clone(), source })?;
        f.sync_data().map_err(|source| HarnessError::Io { action: "cannot flush", path: temp.clone(), source })?;
        fs::rename(&temp, path).map_err(|source| HarnessError::Io {
            action: "cannot rename into",
            path: path.to_path_buf(),
            source,
        })
    })();
    if result.is_err() {
        let _ = fs::remove_file(&temp);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("rlfd-store-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn save_then_lookup_round_trips_and_checks_fingerprints() {
        let store = ResultStore::new(temp_dir("roundtrip"));
        let key = TrialKey::new("ch", "exp", "cond", 7);
        let path = store.path(Scale::Quick, 42, &key);
        assert!(path.ends_with("quick/seed-42/ch/exp/cond/trial-007.json"));
        assert!(matches!(store.lookup::<Vec<f64>>(&path, "abc"), Lookup::Missing));
        let stored = StoredTrial { format: FORMAT, key, seed: 9, fingerprint: "abc".into(), result: vec![1.5, -2.0] };
        store.save(&path, &stored).unwrap();
        match store.lookup::<Vec<f64>>(&path, "abc") {
            Lookup::Fresh(r) => assert_eq!(r, vec![1.5, -2.0]),
            other => panic!("expected a fresh result, got {other:?}"),
        }
        assert!(matches!(store.lookup::<Vec<f64>>(&path, "other"), Lookup::Stale { .. }));
        // No temporary file is left behind.
        let names: Vec<_> = fs::read_dir(path.parent().unwrap()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("trial-007.json")]);
        fs::remove_dir_all(store.root()).unwrap();
    }

    #[test]
    fn unwritable_root_is_an_error_naming_the_path() {
        let file = temp_dir("unwritable");
        fs::write(&file, b"not a directory").unwrap();
        let store = ResultStore::new(&file);
        let key = TrialKey::new("ch", "exp", "cond", 0);
        let path = store.path(Scale::Quick, 1, &key);
        let e = store
            .save(&path, &StoredTrial { format: FORMAT, key, seed: 0, fingerprint: String::new(), result: 0 })
            .unwrap_err();
        assert!(e.to_string().starts_with("cannot create directory"), "{e}");
        fs::remove_file(&file).unwrap();
    }
}
