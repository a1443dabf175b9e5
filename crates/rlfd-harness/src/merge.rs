//! Merging result stores (each shard's, when the machines share no file
//! system) into one.
//!
//! Every source is checked whole before anything is written: it must be a
//! store (a directory of `<scale>/seed-<S>/…` folders, nothing else at those
//! two levels) of the run's scale, holding only the seeds the caller
//! accepts (the run's master seed and its replication seeds); any other is
//! refused and nothing is written. Within a store, a record is merged only
//! if it reads as the trial its path names (format, key, seed and identity
//! agree with the folders and the file name): a truncated or corrupt one is
//! listed and left behind, so the report calls its trial missing and a
//! rerun of its shard recomputes it. Two readable records of one identity
//! must hold the same bytes; if they do not, the runs that made them
//! disagree, and the merge is refused. Records are copied atomically and
//! never replace a readable one; temporary files of interrupted writers
//! (names starting with `.`) are ignored.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

use thiserror::Error;
use walkdir::WalkDir;

use crate::scale::Scale;
use crate::seed::derive_seed;
use crate::store::{FORMAT, StoredTrial, write_atomically, write_new};

/// Why stores could not be merged (nothing was written).
#[derive(Debug, Error)]
pub enum MergeError {
    /// A source is not a store of the expected shape.
    #[error("{path} is not a result store: {why} (a store holds <scale>/seed-<S>/ folders of trial records)")]
    NotAStore {
        /// The source.
        path: PathBuf,
        /// What is wrong with it.
        why: String,
    },
    /// A source holds another scale's results.
    #[error("{path} holds {found}-scale results, not {expected} (pass --scale {found})")]
    Scale {
        /// The source.
        path: PathBuf,
        /// Its scale.
        found: Scale,
        /// The run's.
        expected: Scale,
    },
    /// A source holds a seed the run does not have.
    #[error(
        "{path} holds results of master seed {seed}, which is neither {master} nor one of its replication seeds (pass --seed {seed} to merge a run of that seed)"
    )]
    Seed {
        /// The source.
        path: PathBuf,
        /// The seed found.
        seed: u64,
        /// The run's master seed.
        master: u64,
    },
    /// Two readable records of one identity differ.
    #[error(
        "{0} and {1} are different records of one trial identity: the runs that made them disagree; nothing merged"
    )]
    Disagree(PathBuf, PathBuf),
    /// A file or directory could not be read or written.
    #[error("cannot {action} {path}: {source}")]
    Io {
        /// What was being done.
        action: &'static str,
        /// The path.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Writing the merged store failed.
    #[error(transparent)]
    Harness(#[from] crate::error::HarnessError),
}

/// What a merge did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Merged {
    /// Readable records found in the sources (each identity once).
    pub records: usize,
    /// Records new to the destination.
    pub new: usize,
    /// Records the destination already held (same bytes).
    pub present: usize,
    /// Unreadable records at the destination replaced.
    pub replaced: usize,
    /// Records found in more than one source.
    pub duplicates: usize,
    /// Records that do not read as the trial their path names, with why (left out).
    pub unreadable: Vec<(PathBuf, String)>,
    /// Temporary files of interrupted writers, ignored.
    pub temporary: usize,
}

fn io<'a>(action: &'static str, path: &'a Path) -> impl FnOnce(std::io::Error) -> MergeError + 'a {
    move |source| MergeError::Io { action, path: path.to_path_buf(), source }
}

/// Merges `sources` into the store at `into`; the sources must be stores of
/// `scale` holding only the master seeds in `seeds` (`master` names the run
/// in errors).
pub fn merge(
    sources: &[PathBuf],
    into: &Path,
    scale: Scale,
    master: u64,
    seeds: &BTreeSet<u64>,
) -> Result<Merged, MergeError> {
    let mut merged = Merged::default();
    let mut records: BTreeMap<PathBuf, PathBuf> = BTreeMap::new();
    for source in sources {
        check_store(source, scale, master, seeds)?;
        for entry in WalkDir::new(source).sort_by_file_name() {
            let entry = entry.map_err(|e| MergeError::Io {
                action: "read",
                path: e.path().map_or_else(|| source.clone(), Path::to_path_buf),
                source: e.into(),
            })?;
            if !entry.file_type().is_file() {
                continue;
            }
            let path = entry.path().to_path_buf();
            let relative = path.strip_prefix(source).expect("walked below the source").to_path_buf();
            if entry.file_name().to_string_lossy().starts_with('.') {
                merged.temporary += 1;
                continue;
            }
            let bytes = fs::read(&path).map_err(io("read", &path))?;
            if let Some(reason) = record_problem(&relative, &bytes) {
                merged.unreadable.push((path, reason));
                continue;
            }
            match records.get(&relative) {
                None => {
                    records.insert(relative, path);
                }
                Some(first) => {
                    if fs::read(first).map_err(io("read", first))? != bytes {
                        return Err(MergeError::Disagree(first.clone(), path));
                    }
                    merged.duplicates += 1;
                }
            }
        }
    }
    merged.records = records.len();
    // Against the destination: a readable record there must agree.
    let mut new = Vec::new();
    let mut replace = Vec::new();
    for (relative, path) in &records {
        let target = into.join(relative);
        match fs::read(&target) {
            Err(_) => new.push((path, target)),
            Ok(bytes) => {
                if bytes == fs::read(path).map_err(io("read", path))? {
                    merged.present += 1;
                } else if record_problem(relative, &bytes).is_some() {
                    replace.push((path, target));
                } else {
                    return Err(MergeError::Disagree(path.clone(), target));
                }
            }
        }
    }
    for (path, target) in &new {
        write_new(target, &fs::read(path).map_err(io("read", path))?)?;
    }
    for (path, target) in &replace {
        write_atomically(target, &fs::read(path).map_err(io("read", path))?)?;
    }
    merged.new = new.len();
    merged.replaced = replace.len();
    Ok(merged)
}

/// Checks that `source` is a store of `scale` and `seeds`.
fn check_store(source: &Path, scale: Scale, master: u64, seeds: &BTreeSet<u64>) -> Result<(), MergeError> {
    let not = |why: String| MergeError::NotAStore { path: source.to_path_buf(), why };
    match fs::metadata(source) {
        Err(_) => return Err(not("it does not exist".into())),
        Ok(m) if !m.is_dir() => return Err(not("it is a file".into())),
        Ok(_) => {}
    }
    let scales = visible_entries(source)?;
    if scales.is_empty() {
        return Err(not("it is empty".into()));
    }
    for (name, path) in scales {
        let Ok(found) = name.parse::<Scale>() else {
            return Err(not(format!("it holds {name}")));
        };
        if !path.is_dir() {
            return Err(not(format!("{name} is a file")));
        }
        if found != scale {
            return Err(MergeError::Scale { path: source.to_path_buf(), found, expected: scale });
        }
        for (seed_dir, seed_path) in visible_entries(&path)? {
            let seed = seed_dir.strip_prefix("seed-").and_then(|n| n.parse::<u64>().ok());
            let Some(seed) = seed.filter(|_| seed_path.is_dir()) else {
                return Err(not(format!("{name}/ holds {seed_dir}")));
            };
            if !seeds.contains(&seed) {
                return Err(MergeError::Seed { path: source.to_path_buf(), seed, master });
            }
        }
    }
    Ok(())
}

/// The entries of `dir` whose names do not start with `.`, sorted.
fn visible_entries(dir: &Path) -> Result<Vec<(String, PathBuf)>, MergeError> {
    let mut out = Vec::new();
    for entry in fs::read_dir(dir).map_err(io("read", dir))? {
        let entry = entry.map_err(io("read", dir))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if !name.starts_with('.') {
            out.push((name, entry.path()));
        }
    }
    out.sort();
    Ok(out)
}

/// Why the file at `relative` (below a store's root) is not the record its
/// path names, or `None` when it is.
pub fn record_problem(relative: &Path, bytes: &[u8]) -> Option<String> {
    let parts: Vec<String> = relative.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    // <scale>/seed-<S>/<chapter>/<experiment>/<condition>/trial-NNN.<params>.<code>.json
    let [_, seed, chapter, experiment, condition, file] = parts.as_slice() else {
        return Some("its folders are not <scale>/seed-<S>/<chapter>/<experiment>/<condition>".into());
    };
    let Some(master) = seed.strip_prefix("seed-").and_then(|s| s.parse::<u64>().ok()) else {
        return Some("it is not inside a seed's folder".into());
    };
    let named = file.strip_prefix("trial-").and_then(|f| f.strip_suffix(".json")).and_then(|f| {
        let mut it = f.splitn(3, '.');
        Some((it.next()?.parse::<u32>().ok()?, it.next()?.to_string(), it.next()?.to_string()))
    });
    let Some((trial, params, code)) = named else {
        return Some("its name is not trial-<N>.<params>.<code>.json".into());
    };
    let stored: StoredTrial<serde::de::IgnoredAny> = match serde_json::from_slice(bytes) {
        Ok(s) => s,
        Err(e) => return Some(format!("it does not read as a record ({e})")),
    };
    let key = &stored.key;
    if stored.format != FORMAT {
        return Some(format!("it holds format {}, not {FORMAT}", stored.format));
    }
    if stored.id.params != params || stored.id.code != code {
        return Some(format!(
            "it holds identity {}.{}, not the {params}.{code} its name says",
            stored.id.params, stored.id.code
        ));
    }
    if (key.chapter.as_str(), key.experiment.as_str(), key.condition.as_str(), key.trial)
        != (chapter.as_str(), experiment.as_str(), condition.as_str(), trial)
    {
        return Some(format!("it holds trial {key}, not the one its path names"));
    }
    if stored.seed != derive_seed(master, key) {
        return Some(format!("its seed {} is not the one master seed {master} gives {key}", stored.seed));
    }
    None
}
