//! Writing report trees: every file atomically, stale generated files removed.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use rlfd_harness::write_atomically;
use rlfd_report::ReportFile;

/// Checks, before any trial runs, that the report directory can be created
/// and written, without creating anything: the nearest existing ancestor
/// must be a directory in which a file can be made (a probe, removed again).
pub fn check_writable(dir: &Path) -> Result<()> {
    let mut existing = dir;
    while !existing.exists() {
        match existing.parent() {
            Some(p) if !p.as_os_str().is_empty() => existing = p,
            _ => {
                existing = Path::new(".");
                break;
            }
        }
    }
    if !existing.is_dir() {
        bail!("cannot create the output directory {}: {} is not a directory", dir.display(), existing.display());
    }
    let probe = existing.join(format!(".rlfd-write-probe-{}", std::process::id()));
    fs::write(&probe, b"")
        .with_context(|| format!("cannot write the output directory {} (in {})", dir.display(), existing.display()))?;
    let _ = fs::remove_file(&probe);
    Ok(())
}

/// Writes `files` under `out`, each atomically, then removes files under the
/// `owned` subdirectories that this render did not produce (so a report tree
/// holds exactly what its last render made).
pub fn write_tree(out: &Path, files: &[ReportFile], owned: &[&str]) -> Result<()> {
    let mut written = BTreeSet::new();
    for f in files {
        let path = out.join(&f.path);
        if let Some(parent) = path.parent() {
            fs::create_dir_all(parent).with_context(|| format!("cannot create directory {}", parent.display()))?;
        }
        write_atomically(&path, &f.bytes)?;
        written.insert(path);
    }
    for dir in owned {
        for stale in list_files(&out.join(dir))? {
            if !written.contains(&stale) {
                fs::remove_file(&stale).with_context(|| format!("cannot remove the stale file {}", stale.display()))?;
            }
        }
    }
    Ok(())
}

/// Every file under `dir`, recursively, sorted (none if `dir` does not exist).
pub fn list_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    if dir.exists() {
        for entry in walkdir::WalkDir::new(dir) {
            let entry = entry.with_context(|| format!("cannot read directory {}", dir.display()))?;
            if entry.file_type().is_file() {
                out.push(entry.into_path());
            }
        }
    }
    out.sort();
    Ok(out)
}
