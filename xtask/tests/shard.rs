//! End-to-end tests of the cluster path without a cluster: `reproduce
//! --shard I/N` into separate stores merged with `merge`, or into one store
//! at once; `report` over the result against a single-process
//! `reproduce`, byte for byte; `report` over an incomplete store; the
//! scripts `slurm` writes, run by hand as Slurm would run them; and bad
//! input (one line, non-zero exit, nothing written). They run the real
//! binary at quick scale on chapters whose set-up is cheap (3 and 4; 5 for
//! its readings), each
//! in its own scratch directory under `target/rlfd/tests/`.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn xtask() -> Command {
    Command::new(env!("CARGO_BIN_EXE_xtask"))
}

fn scratch(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/rlfd/tests").join(name);
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).unwrap();
    d
}

fn run_ok(c: &mut Command) -> Output {
    let out = c.output().unwrap();
    assert!(out.status.success(), "failed: {}", String::from_utf8_lossy(&out.stderr));
    out
}

/// `reproduce` (or `report`) with `flags`, a store and, unless sharded, a report directory.
fn task(task: &str, flags: &[&str], results: &Path, out: Option<&Path>) -> Command {
    let mut c = xtask();
    c.args([task, "--no-progress", "--jobs", "2"]).args(flags).arg("--results").arg(results);
    if let Some(out) = out {
        c.arg("--out").arg(out);
    }
    c
}

/// Every file under `dir` but run.json, with its bytes, sorted by path.
fn tree(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    fn walk(base: &Path, dir: &Path, out: &mut Vec<(PathBuf, Vec<u8>)>) {
        for e in fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(base, &p, out);
            } else if p.file_name().unwrap() != "run.json" {
                out.push((p.strip_prefix(base).unwrap().to_path_buf(), fs::read(&p).unwrap()));
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, dir, &mut out);
    out.sort();
    out
}

fn assert_same_tree(a: &Path, b: &Path) {
    let (ta, tb) = (tree(a), tree(b));
    let names = |t: &[(PathBuf, Vec<u8>)]| t.iter().map(|(p, _)| p.clone()).collect::<Vec<_>>();
    assert_eq!(names(&ta), names(&tb), "the file sets differ");
    for ((p, x), (_, y)) in ta.iter().zip(&tb) {
        assert!(x == y, "{} differs", p.display());
    }
    assert!(ta.len() > 5, "a report has files");
}

/// Every file under `dir` whose name starts with `.` (temporary files).
fn hidden_files(dir: &Path) -> Vec<PathBuf> {
    tree(dir)
        .into_iter()
        .map(|(p, _)| p)
        .filter(|p| p.file_name().unwrap().to_string_lossy().starts_with('.'))
        .collect()
}

fn count_records(dir: &Path) -> usize {
    tree(dir).iter().filter(|(p, _)| p.extension().is_some_and(|x| x == "json")).count()
}

/// Runs `c`, expects failure with exit code `code` and one line on stderr
/// containing `expected`; returns the line.
fn refused(c: &mut Command, code: i32, expected: &str) -> String {
    let out = c.output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(code), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
    assert!(stderr.contains(expected), "expected {expected:?} in: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    stderr.trim_end().to_string()
}

const CH3_ROBUST: [&str; 8] = ["--chapter", "ch3", "--scale", "quick", "--robustness", "--seeds", "2", "--seed"];

#[test]
fn shards_merged_from_separate_stores_report_what_one_process_reports() {
    let dir = scratch("shard-merge");
    let flags: Vec<&str> = CH3_ROBUST.iter().copied().chain(["20160501"]).collect();
    run_ok(&mut task("reproduce", &flags, &dir.join("single-results"), Some(&dir.join("single-report"))));
    let mut stores = Vec::new();
    let mut seen = 0;
    for i in 1..=3 {
        let store = dir.join(format!("shard-{i}"));
        let out = run_ok(task("reproduce", &flags, &store, None).arg("--shard").arg(format!("{i}/3")));
        let said = String::from_utf8_lossy(&out.stderr);
        assert!(said.contains(&format!("shard {i}/3: ")), "{said}");
        assert!(!dir.join("report").exists());
        seen += count_records(&store);
        assert!(hidden_files(&store).is_empty());
        stores.push(store);
    }
    // The shards split the trials: together they hold every trial once.
    assert_eq!(seen, count_records(&dir.join("single-results")));
    let merged = dir.join("merged");
    let out = run_ok(xtask().arg("merge").args(&stores).arg("--results").arg(&merged).args(["--scale", "quick"]));
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(said.contains(&format!("merge: {seen} records from 3 stores")), "{said}");
    assert!(said.contains(&format!("{seen} new, 0 already there")), "{said}");
    // Merging again adds nothing.
    let out = run_ok(xtask().arg("merge").args(&stores).arg("--results").arg(&merged).args(["--scale", "quick"]));
    assert!(String::from_utf8_lossy(&out.stderr).contains(&format!("0 new, {seen} already there")));
    run_ok(&mut task("report", &flags, &merged, Some(&dir.join("merged-report"))));
    assert_same_tree(&dir.join("merged-report"), &dir.join("single-report"));
    // A shard run again finds all of its trials stored and computes none.
    let out = run_ok(task("reproduce", &flags, &stores[1], None).arg("--shard").arg("2/3"));
    let again = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(again.contains("shard 2/3: 0 trials computed"));
    // The share's digest is its trials' listing, whatever the store holds:
    // the dry run's against an empty store, and sha256sum's of that listing.
    let out = run_ok(task("reproduce", &flags, &dir.join("empty"), None).args(["--shard", "2/3", "--dry-run"]));
    let listed = String::from_utf8_lossy(&out.stdout).into_owned();
    let digest = share_digest(&String::from_utf8_lossy(&out.stderr));
    assert_eq!(digest, share_digest(&again));
    assert_eq!(digest, rlfd_runner::shard::listing_digest(listed.lines().map(Path::new)));
    assert!(listed.lines().count() > 0 && listed.lines().all(|l| l.starts_with("quick/seed-")), "{listed}");
    let other = run_ok(task("reproduce", &flags, &dir.join("empty"), None).args(["--shard", "1/3", "--dry-run"]));
    assert_ne!(share_digest(&String::from_utf8_lossy(&other.stderr)), digest);
}

/// The digest a shard's first line names (`…; share 0123456789abcdef`).
fn share_digest(stderr: &str) -> String {
    let at = stderr.find("; share ").unwrap_or_else(|| panic!("no share digest in: {stderr}"));
    stderr[at + 8..].chars().take_while(char::is_ascii_hexdigit).collect()
}

#[test]
fn shards_writing_one_store_at_once_report_what_one_process_reports() {
    let dir = scratch("shard-shared");
    let flags = ["--chapter", "ch4", "--scale", "quick"];
    let store = dir.join("results");
    // Four shards and a fifth process computing shard 2 again, all at once.
    let mut children = Vec::new();
    for shard in ["1/4", "2/4", "3/4", "4/4", "2/4"] {
        let mut c = task("reproduce", &flags, &store, None);
        c.arg("--shard").arg(shard).stderr(std::process::Stdio::null());
        children.push(c.spawn().unwrap());
    }
    for mut c in children {
        assert!(c.wait().unwrap().success());
    }
    assert!(hidden_files(&store).is_empty(), "no temporary or lock file is left");
    run_ok(&mut task("report", &flags, &store, Some(&dir.join("report"))));
    run_ok(&mut task("reproduce", &flags, &dir.join("single-results"), Some(&dir.join("single-report"))));
    assert_same_tree(&dir.join("report"), &dir.join("single-report"));
    assert_eq!(count_records(&store), count_records(&dir.join("single-results")));
}

/// The plan must list every trial a run makes, or shards alone leave the
/// store `report` reads incomplete (the Slurm run once did): chapter 5's
/// learning tables store their trials under one experiment name of their
/// own ("keepaway-learning"), whose Subject A trials the `a-rules` reading
/// changes; chapter 6's Maze sweeps `irl-scale` (SIS and DIS at every
/// level), besides its five agents. Each such trial has one record per
/// identity, side by side.
#[test]
fn shards_plan_every_trial_a_robustness_run_makes() {
    let cases: [(&str, &[&str], &str, usize); 2] = [
        ("ch5", &["--chapter", "ch5"], "ch5-hat-keepaway/keepaway-learning/ppr-subject-a", 3),
        ("ch6-maze", &["--chapter", "ch6", "--experiment", "maze"], "ch6-irl-shaping/maze/sis", 9),
    ];
    for (name, chapter, condition, identities) in cases {
        let dir = scratch(&format!("shard-plan-{name}"));
        let store = dir.join("results");
        let flags: Vec<&str> =
            chapter.iter().copied().chain(["--scale", "quick", "--robustness", "--seeds", "1"]).collect();
        for shard in ["1/2", "2/2"] {
            run_ok(task("reproduce", &flags, &store, None).args(["--shard", shard]));
        }
        let trial_0 = fs::read_dir(store.join("quick/seed-20160501").join(condition))
            .unwrap()
            .filter(|e| e.as_ref().unwrap().file_name().to_string_lossy().starts_with("trial-000."))
            .count();
        assert_eq!(trial_0, identities, "{name}: one record of trial 0 per identity the readings give it");
        let out = run_ok(&mut task("report", &flags, &store, Some(&dir.join("report"))));
        let said = String::from_utf8_lossy(&out.stderr);
        assert!(said.lines().last().is_some_and(|l| l.contains(": 0 trials computed")), "{name}: {said}");
    }
}

#[test]
fn a_report_over_an_incomplete_store_names_what_is_missing_or_renders_what_is_there() {
    let dir = scratch("shard-incomplete");
    let store = dir.join("results");
    run_ok(&mut task(
        "reproduce",
        &["--chapter", "ch3", "--experiment", "sorting", "--scale", "quick"],
        &store,
        Some(&dir.join("sorting")),
    ));
    let flags = ["--chapter", "ch3", "--scale", "quick"];
    let line = refused(&mut task("report", &flags, &store, Some(&dir.join("report"))), 1, "lacks ");
    assert!(line.contains("ch3-interactive-rl/sorting-100: "), "{line}");
    assert!(line.contains("pass --partial"), "{line}");
    assert!(!line.contains("ch3-interactive-rl/sorting: "), "{line}");
    assert!(!dir.join("report").exists(), "nothing written");
    let out = run_ok(task("report", &flags, &store, Some(&dir.join("report"))).arg("--partial"));
    assert!(String::from_utf8_lossy(&out.stderr).contains("rendering what is there (--partial)"));
    let page = fs::read_to_string(dir.join("report/ch3-interactive-rl/index.html")).unwrap();
    assert!(page.contains("Incomplete store") && page.contains("is left out"), "the report says it is partial");
    assert!(page.contains("sorting-100"));
}

#[test]
fn the_slurm_scripts_run_by_hand_give_the_single_process_report() {
    let dir = scratch("shard-scripts");
    let flags = ["--chapter", "ch3", "--scale", "quick", "--robustness", "--seeds", "2"];
    let (store, report, scripts) = (dir.join("results"), dir.join("report"), dir.join("slurm"));
    let out = run_ok(
        xtask()
            .args(["slurm", "--shards", "3", "--cpus-per-task", "2", "--sbatch=--partition=short"])
            .args(flags)
            .arg("--results")
            .arg(&store)
            .arg("--out")
            .arg(&report)
            .arg("--dir")
            .arg(&scripts),
    );
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(said.contains("slurm: 3 shards of "), "{said}");
    let shards = fs::read_to_string(scripts.join("shards.sbatch")).unwrap();
    for line in ["#SBATCH --array=1-3", "#SBATCH --cpus-per-task=2", "#SBATCH --partition=short", "--plan "] {
        assert!(shards.contains(line), "{line} in {shards}");
    }
    assert!(shards.contains("reproduce --shard \"$SLURM_ARRAY_TASK_ID/3\""), "{shards}");
    assert!(shards.lines().any(|l| l.starts_with("#SBATCH --time=") && l.ends_with(":00")), "{shards}");
    assert!(shards.lines().any(|l| l.starts_with("#SBATCH --mem=") && l.ends_with('M')), "{shards}");
    let submit = fs::read_to_string(scripts.join("submit.sh")).unwrap();
    assert!(submit.contains("--dependency=afterok:\"$shards\""), "{submit}");
    // Run as Slurm would: each array task, then the report job.
    for i in 1..=3 {
        run_ok(Command::new("bash").arg(scripts.join("shards.sbatch")).env("SLURM_ARRAY_TASK_ID", i.to_string()));
        assert!(!report.exists(), "a shard writes no report");
    }
    run_ok(Command::new("bash").arg(scripts.join("report.sbatch")));
    run_ok(&mut task("reproduce", &flags, &dir.join("single-results"), Some(&dir.join("single-report"))));
    assert_same_tree(&report, &dir.join("single-report"));
    // A plan is refused for another command.
    let mut other = task("reproduce", &["--chapter", "ch3", "--scale", "quick"], &store, None);
    other.args(["--shard", "1/3", "--plan"]).arg(scripts.join("plan.json"));
    refused(&mut other, 1, "rerun `cargo xtask slurm` with these flags");
    // A damaged plan is refused in one line.
    let plan = fs::read(scripts.join("plan.json")).unwrap();
    let damaged = dir.join("damaged.json");
    for bytes in [&plan[..plan.len() / 2], b"\x00\xff not json", b"{\"command\": 7}"] {
        fs::write(&damaged, bytes).unwrap();
        let mut c = task("reproduce", &flags, &store, None);
        c.args(["--shard", "1/3", "--plan"]).arg(&damaged);
        refused(&mut c, 1, "is not a plan written by `cargo xtask slurm`");
    }
}

#[test]
fn bad_shards_merges_and_scripts_are_refused_in_one_line_writing_nothing() {
    let dir = scratch("shard-bad");
    let results = dir.join("results");
    let shard = |value: &str| {
        let mut c = task("reproduce", &["--chapter", "ch3", "--scale", "quick"], &results, None);
        c.args(["--shard", value]);
        c
    };
    refused(&mut shard("0/4"), 2, "shard 0 does not exist: shards are numbered 1 to 4");
    refused(&mut shard("5/4"), 2, "shard 5 does not exist: shards are numbered 1 to 4");
    refused(&mut shard("x"), 2, "expected I/N, shard I of N (e.g. 2/8)");
    refused(&mut shard("1/0"), 2, "a run needs at least 1 shard");
    assert!(!results.exists(), "nothing written");

    // Stores to merge: a file, a folder of something else, an empty folder,
    // a store of another seed, a store of another scale.
    let into = dir.join("merged");
    let merge = |source: &Path, extra: &[&str]| {
        let mut c = xtask();
        c.arg("merge").arg(source).arg("--results").arg(&into).args(extra);
        c
    };
    let file = dir.join("notes.txt");
    fs::write(&file, "not a store").unwrap();
    refused(&mut merge(&file, &[]), 1, "is not a result store: it is a file");
    let junk = dir.join("junk");
    fs::create_dir_all(junk.join("photos")).unwrap();
    refused(&mut merge(&junk, &[]), 1, "is not a result store: it holds photos");
    let empty = dir.join("empty");
    fs::create_dir_all(&empty).unwrap();
    refused(&mut merge(&empty, &[]), 1, "is not a result store: it is empty");
    refused(&mut merge(&dir.join("nowhere"), &[]), 1, "does not exist");
    let seven = dir.join("seed-7");
    run_ok(&mut task(
        "reproduce",
        &["--chapter", "ch3", "--experiment", "sorting", "--scale", "quick", "--seed", "7"],
        &seven,
        Some(&dir.join("seed-7-report")),
    ));
    refused(
        &mut merge(&seven, &["--scale", "quick"]),
        1,
        "holds results of master seed 7, which is neither 20160501 nor one of its replication seeds (pass --seed 7",
    );
    refused(&mut merge(&seven, &[]), 1, "holds quick-scale results, not paper (pass --scale quick)");
    assert!(!into.exists(), "nothing written");

    // A truncated record in a source is named and left behind; the rest merge.
    let record = tree(&seven)
        .into_iter()
        .map(|(p, _)| seven.join(p))
        .find(|p| p.extension().is_some_and(|x| x == "json"))
        .unwrap();
    let bytes = fs::read(&record).unwrap();
    fs::write(&record, &bytes[..bytes.len() / 2]).unwrap();
    let out = run_ok(&mut merge(&seven, &["--scale", "quick", "--seed", "7"]));
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(
        said.contains(&format!("warning: {} is not merged: it does not read as a record", record.display())),
        "{said}"
    );
    assert!(said.contains("1 unreadable left out"), "{said}");
    assert_eq!(count_records(&into), count_records(&seven) - 1);

    refused(
        xtask().args(["slurm", "--shards", "0", "--dir"]).arg(dir.join("scripts")),
        2,
        "invalid value '0' for '--shards <SHARDS>'",
    );
    assert!(!dir.join("scripts").exists(), "nothing written");
}
