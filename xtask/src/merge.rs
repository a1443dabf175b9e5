//! `merge STORE...`: result stores (each shard's, when the machines share no
//! file system) merged into one.
//!
//! Every source is checked whole before anything is written: it must be a
//! store (a directory of `<scale>/seed-<S>/…` folders, nothing else at those
//! two levels) of the run's scale, holding only the run's master seed and its
//! replication seeds; any other is refused in one line and nothing is
//! written. Within a store, a record is merged only if it reads as the trial
//! its path names (format, key, seed and identity agree with the folders and
//! the file name): a truncated or corrupt one is named in a warning and left
//! behind, so the report calls its trial missing and a rerun of its shard
//! recomputes it. Two readable records of one identity must hold the same
//! bytes; if they do not, the runs that made them disagree, and the merge is
//! refused. Records are copied atomically and never replace a readable one;
//! temporary files of interrupted writers (names starting with `.`) are
//! ignored.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use rlfd_harness::{FORMAT, Scale, StoredTrial, derive_seed};

/// What `merge` was asked.
#[derive(Clone, Debug)]
pub struct Options {
    /// The stores to merge.
    pub sources: Vec<PathBuf>,
    /// The store to merge into.
    pub into: PathBuf,
    /// The run's scale.
    pub scale: Scale,
    /// The run's master seed.
    pub seed: u64,
}

/// The largest `--seeds` the command line accepts: the replication seeds a
/// store of the run may hold are the first this many.
const MAX_REPLICATIONS: u32 = 1000;

/// One record found in a source.
struct Found {
    /// The file.
    path: PathBuf,
    /// Its path below the store's root.
    relative: PathBuf,
}

/// What a scan of the sources found.
#[derive(Default)]
struct Scan {
    /// Readable records, by path below the root (the first source's copy).
    records: BTreeMap<PathBuf, Found>,
    /// Records that do not read as the trial their path names, with why.
    unreadable: Vec<(PathBuf, String)>,
    /// Records found in more than one source (same bytes).
    duplicates: usize,
    /// Temporary files of interrupted writers.
    temporary: usize,
}

pub fn run(o: &Options) -> Result<()> {
    let seeds: BTreeSet<u64> = (0..MAX_REPLICATIONS).map(|k| crate::robustness::replication_seed(o.seed, k)).collect();
    let mut scan = Scan::default();
    for source in &o.sources {
        check_store(source, o, &seeds)?;
        scan_store(source, &mut scan)?;
    }
    // Against the destination: a readable record there must agree.
    let mut new = Vec::new();
    let mut replace = Vec::new();
    let mut present = 0;
    for found in scan.records.values() {
        let target = o.into.join(&found.relative);
        match fs::read(&target) {
            Err(_) => new.push((found, target)),
            Ok(bytes) => {
                let theirs = fs::read(&found.path)?;
                if bytes == theirs {
                    present += 1;
                } else if record_problem(&found.relative, &bytes).is_some() {
                    replace.push((found, target));
                } else {
                    bail!(
                        "{} and {} are different records of one trial identity: the runs that made them disagree; nothing merged",
                        found.path.display(),
                        target.display()
                    );
                }
            }
        }
    }
    for (found, target) in &new {
        let bytes = fs::read(&found.path)?;
        if let Some(dir) = target.parent() {
            fs::create_dir_all(dir).map_err(|e| anyhow::anyhow!("cannot create directory {}: {e}", dir.display()))?;
        }
        rlfd_harness::write_new(target, &bytes)?;
    }
    for (found, target) in &replace {
        rlfd_harness::write_atomically(target, &fs::read(&found.path)?)?;
    }
    for (path, reason) in &scan.unreadable {
        eprintln!(
            "warning: {} is not merged: {reason}; its trial is recomputed by a rerun of its shard",
            path.display()
        );
    }
    let mut line = format!(
        "merge: {} records from {} stores into {}: {} new, {} already there",
        scan.records.len(),
        o.sources.len(),
        o.into.display(),
        new.len(),
        present
    );
    if !replace.is_empty() {
        line.push_str(&format!(", {} unreadable ones there replaced", replace.len()));
    }
    if scan.duplicates > 0 {
        line.push_str(&format!(", {} found in more than one store", scan.duplicates));
    }
    if !scan.unreadable.is_empty() {
        line.push_str(&format!(", {} unreadable left out", scan.unreadable.len()));
    }
    if scan.temporary > 0 {
        line.push_str(&format!(", {} temporary files of interrupted writers ignored", scan.temporary));
    }
    eprintln!("{line}");
    Ok(())
}

/// Checks that `source` is a store of the run's scale and seeds.
fn check_store(source: &Path, o: &Options, seeds: &BTreeSet<u64>) -> Result<()> {
    let shown = source.display();
    let layout = "a store holds <scale>/seed-<S>/ folders of trial records";
    match fs::metadata(source) {
        Err(_) => bail!("{shown} does not exist"),
        Ok(m) if !m.is_dir() => bail!("{shown} is not a result store: it is a file ({layout})"),
        Ok(_) => {}
    }
    let scales = visible_entries(source)?;
    if scales.is_empty() {
        bail!("{shown} is not a result store: it is empty ({layout})");
    }
    for (name, path) in scales {
        let Ok(scale) = name.parse::<Scale>() else {
            bail!("{shown} is not a result store: it holds {name} ({layout})");
        };
        if !path.is_dir() {
            bail!("{shown} is not a result store: {name} is a file ({layout})");
        }
        if scale != o.scale {
            bail!("{shown} holds {scale}-scale results, not {} (pass --scale {scale})", o.scale);
        }
        for (seed_dir, seed_path) in visible_entries(&path)? {
            let seed = seed_dir.strip_prefix("seed-").and_then(|n| n.parse::<u64>().ok());
            let Some(seed) = seed.filter(|_| seed_path.is_dir()) else {
                bail!("{shown} is not a result store: {name}/ holds {seed_dir} ({layout})");
            };
            if !seeds.contains(&seed) {
                bail!(
                    "{shown} holds results of master seed {seed}, which is neither {} nor one of its replication seeds (pass --seed {seed} to merge a run of that seed)",
                    o.seed
                );
            }
        }
    }
    Ok(())
}

/// The entries of `dir` whose names do not start with `.`, sorted.
fn visible_entries(dir: &Path) -> Result<Vec<(String, PathBuf)>> {
    let mut out = Vec::new();
    let entries = fs::read_dir(dir).map_err(|e| anyhow::anyhow!("cannot read {}: {e}", dir.display()))?;
    for entry in entries {
        let entry = entry.map_err(|e| anyhow::anyhow!("cannot read {}: {e}", dir.display()))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if !name.starts_with('.') {
            out.push((name, entry.path()));
        }
    }
    out.sort();
    Ok(out)
}

/// Adds `source`'s records to `scan`.
fn scan_store(source: &Path, scan: &mut Scan) -> Result<()> {
    let mut files = Vec::new();
    walk(source, &mut files)?;
    for path in files {
        let relative = path.strip_prefix(source).expect("walked below the source").to_path_buf();
        let name = relative.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        if name.starts_with('.') {
            scan.temporary += 1;
            continue;
        }
        let bytes = fs::read(&path).map_err(|e| anyhow::anyhow!("cannot read {}: {e}", path.display()))?;
        if let Some(reason) = record_problem(&relative, &bytes) {
            scan.unreadable.push((path, reason));
            continue;
        }
        match scan.records.get(&relative) {
            None => {
                scan.records.insert(relative.clone(), Found { path, relative });
            }
            Some(first) => {
                if fs::read(&first.path)? != bytes {
                    bail!(
                        "{} and {} are different records of one trial identity: the runs that made them disagree; nothing merged",
                        first.path.display(),
                        path.display()
                    );
                }
                scan.duplicates += 1;
            }
        }
    }
    Ok(())
}

fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> Result<()> {
    let mut entries: Vec<PathBuf> = fs::read_dir(dir)
        .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", dir.display()))?
        .flatten()
        .map(|e| e.path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            walk(&path, out)?;
        } else {
            out.push(path);
        }
    }
    Ok(())
}

/// Why the file at `relative` (below a store's root) is not the record its
/// path names, or `None` when it is.
fn record_problem(relative: &Path, bytes: &[u8]) -> Option<String> {
    let parts: Vec<String> = relative.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    // <scale>/seed-<S>/[reading-<label>/]<chapter>/<experiment>/<condition>/trial-NNN.<fingerprint>.json
    let (master, rest) = match parts.as_slice() {
        [_, seed, rest @ ..] => (seed.strip_prefix("seed-").and_then(|s| s.parse::<u64>().ok())?, rest),
        _ => return Some("it is not inside a seed's folder".into()),
    };
    let rest = match rest.first() {
        Some(r) if r.starts_with("reading-") => &rest[1..],
        _ => rest,
    };
    let [chapter, experiment, condition, file] = rest else {
        return Some("its folders are not <chapter>/<experiment>/<condition>".into());
    };
    let Some((trial, fingerprint)) = file
        .strip_prefix("trial-")
        .and_then(|f| f.strip_suffix(".json"))
        .and_then(|f| f.split_once('.'))
        .and_then(|(t, fp)| Some((t.parse::<u32>().ok()?, fp)))
    else {
        return Some("its name is not trial-<N>.<identity>.json".into());
    };
    let stored: StoredTrial<serde::de::IgnoredAny> = match serde_json::from_slice(bytes) {
        Ok(s) => s,
        Err(e) => return Some(format!("it does not read as a record ({e})")),
    };
    let key = &stored.key;
    if stored.format != FORMAT {
        return Some(format!("it holds format {}, not {FORMAT}", stored.format));
    }
    if stored.fingerprint != *fingerprint {
        return Some(format!("it holds identity {:?}, not the {fingerprint:?} its name says", stored.fingerprint));
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
