//! End-to-end tests of `cargo xtask`: the golden comparison, determinism
//! across `--jobs` and runs, resuming a killed run, and bad input.
//!
//! They run the real binary at quick scale, each in its own scratch
//! directory under `target/rlfd/tests/`. A quick run of every chapter from
//! an empty store is about a minute of CPU, most of this suite's time, so
//! the tests that only read a finished run (or change a copy of its store)
//! share one, [`base_run`]; the tests of determinism and resuming make their
//! own runs and compare them with it.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

mod common;
use common::copy_tree;

fn xtask() -> Command {
    Command::new(env!("CARGO_BIN_EXE_xtask"))
}

/// How many trial records `dir` holds.
fn record_count(dir: &Path) -> usize {
    if !dir.exists() {
        return 0;
    }
    walkdir::WalkDir::new(dir)
        .into_iter()
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_file() && e.path().extension().is_some_and(|x| x == "json"))
        .count()
}

fn scratch(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/rlfd/tests").join(name);
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).unwrap();
    d
}

fn quick(dir: &Path, tag: &str, jobs: u32) -> Command {
    let mut c = xtask();
    c.args(["reproduce", "--scale", "quick", "--no-progress", "--jobs", &jobs.to_string()])
        .arg("--out")
        .arg(dir.join(format!("{tag}-report")))
        .arg("--results")
        .arg(dir.join(format!("{tag}-results")));
    c
}

/// The shared quick run of every chapter from an empty store, `--jobs 2`:
/// `base-report/` and `base-results/` in the returned directory, made once by
/// whichever test asks first. Tests never write there: one that changes
/// records works on a copy ([`copy_tree`]).
fn base_run() -> &'static Path {
    static BASE: OnceLock<PathBuf> = OnceLock::new();
    BASE.get_or_init(|| {
        let d = scratch("base");
        run_ok(quick(&d, "base", 2));
        d
    })
}

/// A copy of the shared run's store at `dir/{tag}-results`, to change.
fn base_results_copy(dir: &Path, tag: &str) {
    copy_tree(&base_run().join("base-results"), &dir.join(format!("{tag}-results")));
}

fn run_ok(mut c: Command) -> Output {
    let out = c.output().unwrap();
    assert!(out.status.success(), "failed: {}", String::from_utf8_lossy(&out.stderr));
    out
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

/// Trials a run read (computed or reused), from its run.json.
fn trials_in(run_json: &Path) -> usize {
    let text = fs::read_to_string(run_json).unwrap();
    let count = |name: &str| -> usize {
        let field = text.split(&format!("\"{name}\": ")).nth(1).expect("run.json names the count");
        field.split(|c: char| !c.is_ascii_digit()).next().unwrap().parse().unwrap()
    };
    count("trials_computed") + count("trials_reused")
}

fn assert_same_tree(a: &Path, b: &Path) {
    let (ta, tb) = (tree(a), tree(b));
    let names = |t: &[(PathBuf, Vec<u8>)]| t.iter().map(|(p, _)| p.clone()).collect::<Vec<_>>();
    assert_eq!(names(&ta), names(&tb), "the file sets differ");
    for ((p, x), (_, y)) in ta.iter().zip(&tb) {
        assert!(x == y, "{} differs", p.display());
    }
    assert!(ta.len() > 10, "a report has more than ten files");
}

#[test]
fn golden_report_is_reproduced() {
    let out = xtask().arg("golden").output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn output_does_not_depend_on_jobs_or_on_the_run() {
    // Two runs from empty stores, in two processes, with 1 and 2 workers.
    let d = scratch("determinism");
    run_ok(quick(&d, "one", 1));
    let base = base_run();
    assert_same_tree(&d.join("one-report"), &base.join("base-report"));
    let meta = fs::read_to_string(base.join("base-report/run.json")).unwrap();
    assert!(meta.contains("\"jobs\": 2") && meta.contains("\"trials_reused\": 0"), "{meta}");
    assert!(!meta.contains("\"trials_computed\": 0,"), "{meta}");
    // Each chapter's part: every chapter, in run order, its trials adding up to the run's.
    let meta: rlfd_harness::RunMetadata = serde_json::from_str(&meta).unwrap();
    let chapters: Vec<&str> = meta.chapters.iter().map(|c| c.chapter.as_str()).collect();
    assert_eq!(chapters, ["ch3-interactive-rl", "ch4-dbug-study", "ch5-hat-keepaway", "ch6-irl-shaping"]);
    assert_eq!(meta.chapters.iter().map(|c| c.trials_computed).sum::<usize>(), meta.trials_computed);
    // A fresh run reuses only what its own sweeps share: chapter 3's small
    // space, which the swept perception noise does not reach, and chapter
    // 6's agents that the swept axis (irl-scale, dis-beta) does not reach
    // have one record for every level.
    assert!(meta.chapters.iter().all(|c| c.trials_computed > 0), "{:?}", meta.chapters);
    // The computing pass timed each chapter's trials (its CPU seconds).
    assert!(meta.chapters.iter().all(|c| c.trial_cpu_seconds > 0.0), "{:?}", meta.chapters);
    assert!(
        meta.chapters
            .iter()
            .all(|c| (c.trials_reused > 0) == ["ch3-interactive-rl", "ch6-irl-shaping"].contains(&c.chapter.as_str())),
        "{:?}",
        meta.chapters
    );
    let chapter_seconds: f64 = meta.chapters.iter().map(|c| c.wall_seconds).sum();
    assert!(chapter_seconds > 0.0 && chapter_seconds <= meta.wall_seconds, "{:?}", meta);
}

/// The last line a run printed: its totals.
fn totals_line(stderr: &[u8]) -> String {
    String::from_utf8_lossy(stderr).lines().last().unwrap_or_default().to_string()
}

#[test]
fn a_killed_run_resumes_to_the_same_bytes() {
    let d = scratch("resume");
    let clean = base_run().join("base-report");
    // Kill the process (SIGKILL, no clean-up) once it has stored 7 trials.
    let mut child = quick(&d, "killed", 2).stderr(std::process::Stdio::null()).spawn().unwrap();
    while record_count(&d.join("killed-results")) < 7 {
        assert!(child.try_wait().unwrap().is_none(), "the run ended before it could be killed");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    child.kill().unwrap();
    let status = child.wait().unwrap();
    assert!(!status.success(), "the kill must stop the run");
    assert!(!d.join("killed-report/ch6-irl-shaping").exists(), "no report is written before the trials finish");
    let stored =
        tree(&d.join("killed-results")).iter().filter(|(p, _)| p.extension().is_some_and(|e| e == "json")).count();
    assert!(stored >= 1, "some trials were stored before the kill");
    // Resume: finished trials are reused, not redone.
    let out = run_ok(quick(&d, "killed", 2));
    let msg = totals_line(&out.stderr);
    assert!(!msg.contains(" 0 reused"), "{msg}");
    assert_same_tree(&clean, &d.join("killed-report"));
    // A rerun of a finished run computes nothing and reuses every trial.
    let total = trials_in(&clean.join("run.json"));
    let out = run_ok(quick(&d, "killed", 1));
    let msg = totals_line(&out.stderr);
    assert!(msg.contains(&format!(": 0 trials computed, {total} reused")), "{msg}");
}

#[test]
fn report_rerenders_from_stored_results() {
    let d = scratch("report");
    base_results_copy(&d, "a");
    let mut c = xtask();
    c.args(["report", "--scale", "quick", "--no-progress"])
        .arg("--out")
        .arg(d.join("b-report"))
        .arg("--results")
        .arg(d.join("a-results"));
    run_ok(c);
    assert_same_tree(&base_run().join("base-report"), &d.join("b-report"));
    // Without stored results, `report` refuses instead of running trials.
    let mut c = xtask();
    c.args(["report", "--scale", "quick", "--no-progress"])
        .arg("--out")
        .arg(d.join("c-report"))
        .arg("--results")
        .arg(d.join("none"));
    let out = c.output().unwrap();
    assert!(!out.status.success());
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(said.contains("lacks ") && said.contains(" trials this report needs: "), "{said}");
}

/// The stored record files under `dir`, sorted.
fn records(dir: &Path) -> Vec<PathBuf> {
    let mut r: Vec<PathBuf> = tree(dir)
        .into_iter()
        .map(|(p, _)| dir.join(p))
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    r.sort();
    r
}

#[test]
fn verify_recomputes_a_sample_and_names_a_tampered_record() {
    let d = scratch("verify");
    base_results_copy(&d, "a");
    let verify = |sample: &str| {
        let mut c = xtask();
        c.args(["verify", "--scale", "quick", "--no-progress", "--sample", sample])
            .arg("--results")
            .arg(d.join("a-results"));
        c
    };
    let out = run_ok(verify("20"));
    let msg = String::from_utf8_lossy(&out.stderr);
    assert!(msg.contains("verify: 20 trials recomputed from"), "{msg}");
    // Alter one result by hand (a digit of a ch3 session), then verify every trial.
    let victim = records(&d.join("a-results"))
        .into_iter()
        .find(|p| p.to_string_lossy().contains("ch3-interactive-rl/sorting/small-guidance/trial-000"))
        .expect("a ch3 record");
    let text = fs::read_to_string(&victim).unwrap();
    let at = text.find("\"result\"").unwrap();
    let digit = at + text[at..].find(|c: char| c.is_ascii_digit() && c != '0').unwrap();
    let mut altered = text.clone();
    altered.replace_range(digit..digit + 1, if &text[digit..digit + 1] == "9" { "8" } else { "9" });
    fs::write(&victim, altered).unwrap();
    let out = verify("1000").output().unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("verification failed: ch3-interactive-rl/sorting/small-guidance/trial 0 recomputed differs"),
        "{err}"
    );
}

/// Rewrites the record `victim` (a trial 0) as if behaviour version 0 had
/// made it (same parameters, other code); returns the version that did.
fn make_look_old(victim: &Path) -> u32 {
    let text = fs::read_to_string(victim).unwrap();
    let field =
        |name: &str| text.split(&format!("\"{name}\":\"")).nth(1).unwrap().split('"').next().unwrap().to_string();
    let (params, code) = (field("params"), field("code"));
    let current: u32 = text.split("\"behaviour\":").nth(1).unwrap().split(',').next().unwrap().parse().unwrap();
    let old = text.replace(&format!("\"behaviour\":{current},"), "\"behaviour\":0,").replace(&code, "0000000000000000");
    fs::remove_file(victim).unwrap();
    fs::write(victim.with_file_name(format!("trial-000.{params}.0000000000000000.json")), old).unwrap();
    current
}

#[test]
fn a_record_of_another_version_is_rendered_with_a_banner_and_rerun_alone() {
    let d = scratch("versions");
    base_results_copy(&d, "a");
    // Make one Maze trial look as if an older behaviour version had made it.
    let victim = records(&d.join("a-results"))
        .into_iter()
        .find(|p| p.to_string_lossy().contains("ch6-irl-shaping/maze/sis/trial-000."))
        .expect("a maze record");
    let current = make_look_old(&victim);
    // `report` renders it, says so on stderr and in a banner of chapter 6 only.
    let mut c = xtask();
    c.args(["report", "--scale", "quick", "--no-progress"])
        .arg("--out")
        .arg(d.join("b-report"))
        .arg("--results")
        .arg(d.join("a-results"));
    let out = run_ok(c);
    let msg = String::from_utf8_lossy(&out.stderr);
    assert!(
        msg.contains("warning: *Not current.*") && msg.contains(&format!("maze (current version {current}): 1 of its")),
        "{msg}"
    );
    let page = fs::read_to_string(d.join("b-report/ch6-irl-shaping/index.html")).unwrap();
    assert!(page.contains("Records of another behaviour version") && page.contains("behaviour version 0"));
    let ch5 = fs::read_to_string(d.join("b-report/ch5-hat-keepaway/index.html")).unwrap();
    assert!(!ch5.contains("Records of another behaviour version"));
    // `reproduce` recomputes that trial and no other, and the report is current again.
    let out = run_ok(quick(&d, "a", 2));
    let msg = String::from_utf8_lossy(&out.stderr);
    assert!(msg.contains(": 1 trials computed,"), "{msg}");
    assert!(!fs::read_to_string(d.join("a-report/ch6-irl-shaping/index.html")).unwrap().contains("another behaviour"));
}

#[test]
fn a_robustness_record_of_another_version_is_named_in_the_banner() {
    let d = scratch("robustness-versions");
    let run = |command: &str| {
        let mut c = xtask();
        c.args([command, "--chapter", "ch3", "--scale", "quick", "--no-progress", "--robustness", "--seeds", "2"])
            .arg("--out")
            .arg(d.join("report"))
            .arg("--results")
            .arg(d.join("results"));
        run_ok(c)
    };
    run("reproduce");
    // One trial of the second replication (not the headline's seed) made by
    // an older version, in each of its four identities (the default rewards
    // and the three other `reward-sizes` levels).
    let victims: Vec<_> = records(&d.join("results"))
        .into_iter()
        .filter(|p| {
            let p = p.to_string_lossy();
            !p.contains("seed-20160501/") && p.contains("ch3-interactive-rl/sorting/small-guidance/trial-000.")
        })
        .collect();
    assert_eq!(victims.len(), 4, "{victims:?}");
    for victim in &victims {
        make_look_old(victim);
    }
    let msg = String::from_utf8_lossy(&run("report").stderr).to_string();
    assert!(
        msg.contains("warning: *Not current.*")
            && msg.contains("the robustness section's replications and readings (--robustness): of the ")
            // A record is read at every point that reads it: the default
            // rewards' at replication 1 and its three noise levels, which
            // leave the small space alone (4), each other reward size's at
            // its own point (3).
            && msg.contains(" trials they read, 7 from another behaviour version 0 built by "),
        "{msg}"
    );
    let page = fs::read_to_string(d.join("report/ch3-interactive-rl/index.html")).unwrap();
    assert!(page.contains("Records of another behaviour version"));
    // `reproduce` recomputes it, and the banner goes.
    let msg = String::from_utf8_lossy(&run("reproduce").stderr).to_string();
    assert!(!msg.contains("Not current"), "{msg}");
    let page = fs::read_to_string(d.join("report/ch3-interactive-rl/index.html")).unwrap();
    assert!(!page.contains("Records of another behaviour version"));
}

#[test]
fn robustness_reruns_verdicts_over_seeds_and_readings() {
    let d = scratch("robustness");
    let mut c = xtask();
    c.args(["reproduce", "--chapter", "ch3", "--scale", "quick", "--no-progress", "--robustness", "--seeds", "3"])
        .arg("--out")
        .arg(d.join("report"))
        .arg("--results")
        .arg(d.join("results"));
    let out = run_ok(c);
    let msg = String::from_utf8_lossy(&out.stderr);
    // The computing pass says each run point once: the headline and two
    // more seeds run every trial; the report's noise sweep runs the large
    // space's 100-trial experiment at each other level; each other level of
    // the noise axis reruns only the large space (at the master seed only
    // the 3-trial experiment's: the sweep ran the 100-trial one), and each
    // other reward size every trial.
    assert_eq!(msg.matches("reading default: 52 trials computed, 0 reused").count(), 3, "{msg}");
    assert_eq!(msg.matches(" (sweep): 20 trials computed, 20 reused").count(), 3, "{msg}");
    assert_eq!(msg.matches(": 26 trials computed, 26 reused").count(), 6, "{msg}");
    assert_eq!(msg.matches("seed 20160501, reading perception-noise=").count(), 6, "{msg}");
    assert_eq!(msg.matches(": 6 trials computed, 46 reused").count(), 3, "{msg}");
    assert_eq!(msg.matches("reading reward-sizes=").count(), 9, "{msg}");
    // Each experiment's measured cost, once, over the trials the points computed.
    let number_before = |line: &str, word: &str| -> usize {
        let head = &line[..line.find(word).unwrap_or_else(|| panic!("{word:?} in {line}"))];
        head.trim_end().rsplit([' ', ':']).next().unwrap().parse().unwrap()
    };
    let computed: usize = msg
        .lines()
        .filter(|l| l.contains(", reading ") && l.contains(" trials computed, "))
        .map(|l| number_before(l, " trials computed"))
        .sum();
    let measured: Vec<&str> = msg.lines().filter(|l| l.starts_with("measured ch3-interactive-rl ")).collect();
    assert_eq!(measured.len(), 2, "sorting and sorting-100: {msg}");
    assert!(measured.iter().all(|l| l.contains(" s a trial; declared ")), "{msg}");
    assert_eq!(measured.iter().map(|l| number_before(l, " trials, ")).sum::<usize>(), computed, "{msg}");
    let csv = fs::read_to_string(d.join("report/ch3-interactive-rl/robustness.csv")).unwrap();
    assert!(
        csv.contains("claim,headline,pooled,seeds,perception_noise_0_05,perception_noise_0_1,perception_noise_0_4,reward_sizes_0_5,reward_sizes_0_9,reward_sizes_2"),
        "{csv}"
    );
    assert_eq!(csv.lines().filter(|l| l.starts_with("C3.")).count(), 5, "{csv}");
    // Plan v2: each level beside the default pooled over the same
    // replications; with K = 3 every level ran all three, so that is the
    // default's own pooled verdict, and a level flips exactly when it differs.
    let pooled = fs::read_to_string(d.join("report/ch3-interactive-rl/robustness_pooled.csv")).unwrap();
    let mut lines = pooled.lines();
    assert!(lines.next().unwrap().ends_with(",verdict,claim_verdict,default_matched,flips"), "{pooled}");
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let mut levels = 0;
    for r in rows.iter().filter(|r| !r[1].is_empty()) {
        let default = rows.iter().find(|d| d[0] == r[0] && d[1].is_empty()).expect("the default's row");
        assert_eq!(r[r.len() - 2], default[default.len() - 3], "{r:?}");
        assert_eq!(r[r.len() - 1], if r[r.len() - 3] == r[r.len() - 2] { "no" } else { "yes" }, "{r:?}");
        levels += 1;
    }
    assert!(levels >= 6, "{pooled}");
    let index = fs::read_to_string(d.join("report/index.html")).unwrap();
    // Quick scale: not evaluable at every seed; the pool is shown, not used.
    assert!(index.contains("Robustness: pooled over 3 replications: "), "ch3's claims have estimates");
    assert!(index.contains("; holds in 0 of 3 seeds"), "quick scale: not evaluable at every seed");
    let tex = fs::read_to_string(d.join("report/ch3-interactive-rl/body.tex")).unwrap();
    assert!(tex.contains("Robustness: seeds and readings"));
    // A reading's trials sit beside the default's, one record per identity:
    // the large space has one per noise level and one per other reward size,
    // the small space (exact features) one per reward size.
    let trials = d.join("results/quick/seed-20160501/ch3-interactive-rl/sorting");
    assert_eq!(record_count(&trials.join("large-guidance")), 3 * (4 + 3));
    assert_eq!(record_count(&trials.join("small-guidance")), 3 * 4);
}

#[test]
fn a_reading_is_checked_against_the_declared_axes() {
    let d = scratch("bad-reading");
    bad(
        &d,
        &["reproduce", "--scale", "quick", "--reading", "perception-noise=0.3"],
        "unknown level \"0.3\" of reading axis perception-noise (expected one of: 0.05, 0.1, 0.2, 0.4)",
    );
    bad(&d, &["reproduce", "--scale", "quick", "--reading", "noise=0.1"], "unknown reading axis \"noise\"");
}

/// Runs xtask with `args` and checks for one `error:` line, a non-zero exit, no panic and no output.
fn bad(dir: &Path, args: &[&str], expected: &str) {
    let out_dir = dir.join("out");
    let mut c = xtask();
    c.args(args).arg("--out").arg(&out_dir).arg("--results").arg(dir.join("results"));
    let out = c.output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} succeeded");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "one line expected: {stderr}");
    assert!(lines[0].starts_with("error: ") && lines[0].contains(expected), "{:?} lacks {expected:?}", lines[0]);
    assert!(!out_dir.exists(), "no output may be left behind");
}

#[test]
fn bad_input_is_one_line_and_a_failure() {
    let d = scratch("bad");
    bad(&d, &["reproduce", "--chapter", "ch9"], "unknown chapter \"ch9\"");
    bad(&d, &["reproduce", "--scale", "huge"], "unknown scale \"huge\" (expected quick or paper)");
    bad(&d, &["reproduce", "--experiment", "labyrinth", "--scale", "quick"], "unknown experiment \"labyrinth\"");
    // With --chapter, the list names only that chapter's experiments.
    bad(
        &d,
        &["reproduce", "--chapter", "ch3", "--experiment", "maze", "--scale", "quick"],
        "unknown experiment \"maze\" for ch3 (expected one of: sorting, sorting-100)",
    );
    bad(&d, &["reproduce", "--jobs", "0"], "--jobs");
    bad(&d, &["reproduce", "--frobnicate"], "--frobnicate");

    let write = |name: &str, text: &str| {
        let p = d.join(name);
        fs::write(&p, text).unwrap();
        p.to_string_lossy().into_owned()
    };
    let malformed =
        write("malformed.csv", "trajectory,step,x,y,action\n0,0,0.08,0.6,1\n0,1,0.1,abc,1\n0,2,0.12,0.6,\n");
    bad(
        &d,
        &["reproduce", "--scale", "quick", "--demonstrations", &malformed],
        "malformed.csv:3: field \"y\": \"abc\" is not a number",
    );
    let empty = write("empty.csv", "");
    bad(&d, &["reproduce", "--scale", "quick", "--demonstrations", &empty], "empty.csv: the file is empty");
    let nan = write("nan.csv", "trajectory,step,x,y,action\n0,0,0.08,NaN,1\n0,1,0.1,0.6,\n");
    bad(&d, &["reproduce", "--scale", "quick", "--demonstrations", &nan], "nan.csv:2: field \"y\": NaN is not allowed");
    let short_row = write("short.csv", "trajectory,step,x,y,action\n0,0,0.08,0.6\n");
    bad(
        &d,
        &["reproduce", "--scale", "quick", "--demonstrations", &short_row],
        "short.csv:2: expected 5 fields, found 4",
    );
    let outside = write("outside.csv", "trajectory,step,x,y,action\n0,0,1.5,0.6,1\n0,1,1.52,0.6,\n");
    bad(&d, &["reproduce", "--scale", "quick", "--demonstrations", &outside], "outside the unit square");
    let missing = d.join("does-not-exist.csv").to_string_lossy().into_owned();
    bad(&d, &["reproduce", "--scale", "quick", "--demonstrations", &missing], "does-not-exist.csv: cannot read");

    // An output directory that cannot be created (its parent is a file).
    let blocker = d.join("blocker");
    fs::write(&blocker, "a file").unwrap();
    let out = xtask()
        .args(["reproduce", "--scale", "quick", "--no-progress", "--out"])
        .arg(blocker.join("report"))
        .arg("--results")
        .arg(d.join("results"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && stderr.lines().count() == 1 && stderr.contains("is not a directory"), "{stderr}");
    assert!(!d.join("results").exists(), "nothing runs when the report cannot be written");
}

#[test]
fn demonstrations_too_short_for_ripper_are_refused_in_one_sentence() {
    let d = scratch("short-demos");
    let file = d.join("short.csv");
    fs::write(&file, "trajectory,step,x,y,action\n0,0,0.08,0.6,2\n0,1,0.08,0.62,2\n0,2,0.08,0.64,\n").unwrap();
    let args = ["reproduce", "--scale", "quick", "--no-progress", "--experiment", "maze", "--demonstrations"];
    let mut all: Vec<&str> = args.to_vec();
    let path = file.to_string_lossy().into_owned();
    all.push(&path);
    bad(
        &d,
        &all,
        "demonstrations: only 2 states have an action (a demonstrated move), but RIPPER's 10-fold cross-validation needs at least 10",
    );
    // The cause is said once, not twice.
    let out =
        xtask().args(&all).arg("--out").arg(d.join("out")).arg("--results").arg(d.join("results")).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.matches("at least 10").count(), 1, "{err}");
}

#[test]
fn user_demonstrations_replace_the_synthetic_demonstrator() {
    let d = scratch("user-demos");
    // Two hand-made demonstrations along the maze's route at 0.02 per step.
    let mut csv = String::from("trajectory,step,x,y,action\n");
    for t in 0..2 {
        let mut path = vec![(8, 60)];
        let mut push = |dx: i32, dy: i32, n: usize| {
            for _ in 0..n {
                let (x, y) = *path.last().unwrap();
                path.push((x + dx, y + dy));
            }
        };
        push(0, 2, 16 + t); // up to y = 0.92 (0.94)
        push(2, 0, 20); // right to x = 0.48
        push(0, -2, 45 + t); // down to the bottom
        push(2, 0, 23); // right to x = 0.94
        push(0, 2, 46); // up into the goal region
        for (k, w) in path.windows(2).enumerate() {
            let a = match (w[1].0 - w[0].0, w[1].1 - w[0].1) {
                (-2, 0) => 0,
                (2, 0) => 1,
                (0, 2) => 2,
                _ => 3,
            };
            csv.push_str(&format!("{t},{k},{},{},{a}\n", w[0].0 as f64 / 100.0, w[0].1 as f64 / 100.0));
        }
        let last = path.last().unwrap();
        csv.push_str(&format!("{t},{},{},{},\n", path.len() - 1, last.0 as f64 / 100.0, last.1 as f64 / 100.0));
    }
    let file = d.join("mine.csv");
    fs::write(&file, csv).unwrap();
    // Only the experiment that reads them (the other chapters' runs are the shared run's).
    let mut c = quick(&d, "mine", 2);
    c.args(["--chapter", "ch6", "--experiment", "maze", "--demonstrations"]).arg(&file);
    run_ok(c);
    let page = fs::read_to_string(d.join("mine-report/ch6-irl-shaping/index.html")).unwrap();
    assert!(page.contains("mine.csv"), "the report names the demonstration file");
    assert!(page.contains("--demonstrations mine.csv"), "the provenance names it too");
}

#[test]
fn help_lists_every_task() {
    let out = xtask().arg("--help").output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for task in ["reproduce", "report", "golden", "bench"] {
        assert!(text.contains(task), "--help lacks {task}: {text}");
    }
}

#[test]
fn bench_prints_one_line_per_domain_and_agent() {
    let out = xtask().args(["bench", "--quick"]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    for what in ["simulator", "sarsa-lambda", "sis", "dis", "hat", "sbs", "sarsa-kernel"] {
        assert!(
            text.lines().any(|l| l.starts_with("maze") && l.contains(what) && l.contains("M steps/s")),
            "{what} missing: {text}"
        );
    }
    for (what, unit) in [("simulator", "M ticks/s"), ("q-lambda ", "M steps/s"), ("q-lambda-warm", "M steps/s")] {
        assert!(
            text.lines().any(|l| l.starts_with("mario") && l.contains(what) && l.contains(unit)),
            "mario {what} missing: {text}"
        );
    }
}

#[test]
fn latex_reports_need_no_unicode_support() {
    // pdflatex with inputenc refuses characters it has no definition for
    // (κ, ≡, …): outside comments, the generated LaTeX must be plain ASCII.
    let golden = Path::new(env!("CARGO_MANIFEST_DIR")).join("../golden");
    let mut checked = 0;
    let chapters = fs::read_dir(&golden).unwrap().flat_map(|e| {
        let dir = e.unwrap().path();
        [dir.join("chapter.tex"), dir.join("body.tex")]
    });
    for tex in chapters.chain([golden.join("report.tex")]) {
        if !tex.exists() {
            continue;
        }
        checked += 1;
        for (n, line) in fs::read_to_string(&tex).unwrap().lines().enumerate() {
            if line.trim_start().starts_with('%') {
                continue;
            }
            let bad: String = line.chars().filter(|c| !c.is_ascii()).collect();
            assert!(bad.is_empty(), "{}:{}: non-ASCII {bad:?} in {line:?}", tex.display(), n + 1);
        }
    }
    assert!(checked >= 9, "{checked} LaTeX files in golden/: every chapter's two and report.tex");
}
