//! `golden`: regenerate the quick-scale report from scratch and compare it
//! with `golden/` both ways (a missing or an extra file fails), showing a
//! diff; `--bless` replaces `golden/` with it.
//!
//! It also checks the raw records behind the report: `golden/records.tsv`
//! lists every quick-scale trial with the behaviour version that made it and
//! a digest of its result. A trial whose result changed while its
//! experiment's behaviour version did not is a forgotten bump (the store
//! would go on serving the old result at paper scale): it fails, naming the
//! trial and the experiment to bump.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use rlfd_harness::{Fingerprint, Scale, StoredTrial};

use rlfd_runner::plan::plan;
use rlfd_runner::{Command, Machine, Role, Selection};

use crate::chapters;
use crate::cli::{DEFAULT_SEED, RunSettings, workspace_root};
use crate::output::list_files;

/// Files that vary from run to run and are never compared.
const UNCOMPARED: [&str; 2] = ["run.json", RECORDS];

/// The record digests beside the golden report.
const RECORDS: &str = "records.tsv";

pub fn run(bless: bool) -> Result<()> {
    let root = workspace_root();
    let scratch = root.join("target/rlfd/golden-check");
    if scratch.exists() {
        fs::remove_dir_all(&scratch).with_context(|| format!("cannot clear {}", scratch.display()))?;
    }
    let settings = RunSettings {
        command: Command {
            chapter: None,
            experiment: None,
            scale: Scale::Quick,
            seed: DEFAULT_SEED,
            reading: None,
            robustness: None,
            demonstrations: None,
        },
        machine: Machine {
            jobs: std::thread::available_parallelism().map_or(1, |n| n.get()),
            progress: false,
            results: scratch.join("results"),
        },
        out: scratch.join("report"),
    };
    chapters::reproduce(&settings, chapters::Mode::Run)?;
    let records = record_digests(&settings)?;
    let golden = root.join("golden");
    if bless {
        if golden.exists() {
            fs::remove_dir_all(&golden).with_context(|| format!("cannot clear {}", golden.display()))?;
        }
        copy_tree(&settings.out, &golden)?;
        fs::write(golden.join(RECORDS), &records).context("cannot write golden/records.tsv")?;
        eprintln!("golden/ blessed from the regenerated quick-scale report and its records");
        return Ok(());
    }
    let committed = fs::read_to_string(golden.join(RECORDS)).unwrap_or_default();
    let problems = compare_records(&committed, &records);
    for p in problems.iter().take(20) {
        eprintln!("{p}");
    }
    let tree = compare(&golden, &settings.out);
    if !problems.is_empty() {
        bail!(
            "golden records: {} trials differ from golden/records.tsv ({}){}",
            problems.len(),
            problems[0],
            tree.err().map_or(String::new(), |e| format!("; and {e}"))
        );
    }
    tree
}

/// `trial<TAB>behaviour<TAB>digest` for every record of the command `s`
/// plans, sorted, after a header line. The digest is the fingerprint of the
/// result's JSON. A record that only a sweep's level makes (a trial whose
/// parameters that reading changes, e.g. chapter 6's SIS and DIS at another
/// `irl-scale` level) is named with ` [<reading>]` after the trial, so it
/// never shares a name with the headline's record of the same trial.
pub fn record_digests(s: &RunSettings) -> Result<String> {
    let registry = chapters::registry();
    let selection = Selection::new(s.command.clone(), &registry)?;
    let planned = plan(&selection, &s.machine.results)?;
    let mut owner: Vec<Option<&rlfd_runner::RunPoint>> = vec![None; planned.trials.len()];
    for g in &planned.groups {
        for &t in &g.trials {
            owner[t].get_or_insert(&g.point);
        }
    }
    let mut lines = Vec::new();
    for (t, point) in planned.trials.iter().zip(owner) {
        let label = match point.map(|p| p.role) {
            Some(Role::Headline) | None => String::new(),
            Some(_) => format!(" [{}]", point.expect("a point").reading.label()),
        };
        let bytes = fs::read(&t.path).with_context(|| format!("cannot read {}", t.path.display()))?;
        let stored: StoredTrial<serde_json::Value> =
            serde_json::from_slice(&bytes).with_context(|| format!("{} is not a trial record", t.path.display()))?;
        let result = serde_json::to_vec(&stored.result).expect("JSON values serialise");
        let k = &stored.key;
        lines.push(format!(
            "{}/{}/{}/{:03}{label}\t{}\t{}",
            k.chapter,
            k.experiment,
            k.condition,
            k.trial,
            stored.behaviour,
            Fingerprint::new().bytes(&result).hex()
        ));
    }
    lines.sort();
    Ok(format!(
        "# quick-scale trial\tbehaviour version\tdigest of its result; checked by `cargo xtask golden`\n{}\n",
        lines.join("\n")
    ))
}

/// What differs between two record listings, one sentence a trial.
pub fn compare_records(committed: &str, fresh: &str) -> Vec<String> {
    let parse = |text: &str| -> std::collections::BTreeMap<String, (String, String)> {
        text.lines()
            .filter(|l| !l.starts_with('#') && !l.is_empty())
            .filter_map(|l| {
                let mut f = l.split('\t');
                Some((f.next()?.to_string(), (f.next()?.to_string(), f.next()?.to_string())))
            })
            .collect()
    };
    let (old, new) = (parse(committed), parse(fresh));
    let mut problems = Vec::new();
    for (trial, (behaviour, digest)) in &new {
        let experiment = trial.split('/').take(2).collect::<Vec<_>>().join("/");
        match old.get(trial) {
            None => problems.push(format!("{trial}: a new trial (bless to record it)")),
            Some((b, d)) if b == behaviour && d != digest => problems.push(format!(
                "{trial}: its result changed but {experiment}'s behaviour version is still {behaviour}: bump it in the chapter's `experiments!` declaration, then bless"
            )),
            Some((b, _)) if b != behaviour => {
                problems.push(format!("{trial}: behaviour version {b} -> {behaviour} (bless to record the new results)"))
            }
            Some(_) => {}
        }
    }
    for trial in old.keys().filter(|t| !new.contains_key(*t)) {
        problems.push(format!("{trial}: in golden/records.tsv but no longer run (bless to drop it)"));
    }
    problems
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

/// The first `limit` changed lines of two texts as a line diff (`similar`'s
/// Myers diff, so an inserted line shows as one insertion, not as every line
/// after it changed), each with its line number in the old (`-`) or the new
/// (`+`) text.
fn line_diff(a: &str, b: &str, limit: usize) -> String {
    let diff = similar::TextDiff::from_lines(a, b);
    let mut out = String::new();
    let changes = diff.iter_all_changes().filter(|c| c.tag() != similar::ChangeTag::Equal);
    for (shown, change) in changes.enumerate() {
        if shown == limit {
            out.push_str("       … (more differences)\n");
            break;
        }
        let (sign, line) = match change.tag() {
            similar::ChangeTag::Delete => ('-', change.old_index()),
            _ => ('+', change.new_index()),
        };
        let text = change.value().trim_end_matches('\n');
        out.push_str(&format!("{:>6} {sign} {}\n", line.map_or(0, |i| i + 1), clip(text)));
    }
    out
}

fn clip(s: &str) -> String {
    if s.chars().count() > 160 { s.chars().take(160).collect::<String>() + "…" } else { s.to_string() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_diff_shows_an_insertion_as_one_line() {
        let old = "a\nb\nc\nd\n";
        assert_eq!(line_diff(old, old, 12), "");
        assert_eq!(line_diff(old, "a\nx\nb\nc\nd\n", 12), "     2 + x\n");
        assert_eq!(line_diff(old, "a\nc\nd\n", 12), "     2 - b\n");
        assert_eq!(line_diff(old, "A\nB\nC\nD\n", 2).lines().count(), 3, "two changes and the ellipsis");
    }

    #[test]
    fn a_changed_result_without_a_bump_is_named() {
        let old = "# h\nch/e/c/000\t1\taaaa\nch/e/c/001\t1\tbbbb\nch/f/c/000\t2\tcccc\n";
        assert!(compare_records(old, old).is_empty());
        let forgot = old.replace("bbbb", "bbbx");
        let p = compare_records(old, &forgot);
        assert_eq!(p.len(), 1);
        assert!(p[0].starts_with("ch/e/c/001: its result changed but ch/e's behaviour version is still 1"), "{}", p[0]);
        let bumped = old.replace("1\tbbbb", "2\tbbbx");
        assert!(compare_records(old, &bumped)[0].contains("behaviour version 1 -> 2"));
        let dropped = "# h\nch/e/c/000\t1\taaaa\nch/f/c/000\t2\tcccc\n";
        assert!(compare_records(old, dropped)[0].contains("no longer run"));
    }
}
