//! `golden`: regenerate the quick-scale report from scratch and compare it
//! with `golden/` both ways (a missing or an extra file fails), showing a
//! diff; `--bless` replaces `golden/` with it.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use rlfd_harness::Scale;

use crate::chapters;
use crate::cli::{DEFAULT_SEED, RunSettings, workspace_root};
use crate::output::list_files;

/// Files that vary from run to run and are never compared.
const UNCOMPARED: [&str; 1] = ["run.json"];

pub fn run(bless: bool) -> Result<()> {
    let root = workspace_root();
    let scratch = root.join("target/rlfd/golden-check");
    if scratch.exists() {
        fs::remove_dir_all(&scratch).with_context(|| format!("cannot clear {}", scratch.display()))?;
    }
    let settings = RunSettings {
        chapter: None,
        experiment: None,
        scale: Scale::Quick,
        jobs: std::thread::available_parallelism().map_or(1, |n| n.get()),
        seed: DEFAULT_SEED,
        out: scratch.join("report"),
        results: scratch.join("results"),
        demonstrations: None,
        progress: false,
    };
    chapters::reproduce(&settings, false)?;
    let golden = root.join("golden");
    if bless {
        if golden.exists() {
            fs::remove_dir_all(&golden).with_context(|| format!("cannot clear {}", golden.display()))?;
        }
        copy_tree(&settings.out, &golden)?;
        eprintln!("golden/ blessed from the regenerated quick-scale report");
        return Ok(());
    }
    compare(&golden, &settings.out)
}

fn relative(base: &Path) -> Result<Vec<PathBuf>> {
    Ok(list_files(base)?
        .into_iter()
        .filter_map(|p| p.strip_prefix(base).ok().map(Path::to_path_buf))
        .filter(|p| !UNCOMPARED.iter().any(|u| p == Path::new(u)))
        .collect())
}

fn copy_tree(from: &Path, to: &Path) -> Result<()> {
    for rel in relative(from)? {
        let target = to.join(&rel);
        fs::create_dir_all(target.parent().expect("a file has a parent"))
            .with_context(|| format!("cannot create {}", target.display()))?;
        fs::copy(from.join(&rel), &target).with_context(|| format!("cannot copy to {}", target.display()))?;
    }
    Ok(())
}

/// Compares two trees; the error names every difference and shows diffs.
pub fn compare(golden: &Path, fresh: &Path) -> Result<()> {
    let expected = relative(golden)?;
    let got = relative(fresh)?;
    let missing: Vec<_> = expected.iter().filter(|p| !got.contains(p)).collect();
    let extra: Vec<_> = got.iter().filter(|p| !expected.contains(p)).collect();
    let mut differing = Vec::new();
    for rel in expected.iter().filter(|p| got.contains(p)) {
        let (a, b) = (fs::read(golden.join(rel))?, fs::read(fresh.join(rel))?);
        if a != b {
            differing.push((rel.clone(), a, b));
        }
    }
    if missing.is_empty() && extra.is_empty() && differing.is_empty() {
        eprintln!("golden: {} files identical", expected.len());
        return Ok(());
    }
    for p in &missing {
        eprintln!("missing from the regenerated report: {}", p.display());
    }
    for p in &extra {
        eprintln!("not in golden/: {}", p.display());
    }
    for (rel, a, b) in differing.iter().take(5) {
        eprintln!("--- golden/{}\n+++ regenerated/{}", rel.display(), rel.display());
        eprint!("{}", line_diff(&String::from_utf8_lossy(a), &String::from_utf8_lossy(b), 12));
    }
    bail!(
        "golden mismatch: {} files differ, {} missing, {} extra (if the change is intended, run `cargo xtask golden --bless` and say why in the commit)",
        differing.len(),
        missing.len(),
        extra.len()
    )
}

/// The first `limit` differing lines of two texts, with their line numbers.
fn line_diff(a: &str, b: &str, limit: usize) -> String {
    let (la, lb): (Vec<&str>, Vec<&str>) = (a.lines().collect(), b.lines().collect());
    let mut out = String::new();
    let mut shown = 0;
    for i in 0..la.len().max(lb.len()) {
        let (x, y) = (la.get(i), lb.get(i));
        if x != y {
            if let Some(x) = x {
                out.push_str(&format!("{:>6} - {}\n", i + 1, clip(x)));
            }
            if let Some(y) = y {
                out.push_str(&format!("{:>6} + {}\n", i + 1, clip(y)));
            }
            shown += 1;
            if shown == limit {
                out.push_str("       … (more differences)\n");
                break;
            }
        }
    }
    out
}

fn clip(s: &str) -> String {
    if s.chars().count() > 160 { s.chars().take(160).collect::<String>() + "…" } else { s.to_string() }
}
