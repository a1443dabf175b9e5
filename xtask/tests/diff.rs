//! End-to-end tests of `cargo xtask diff`: the real binary on copies of
//! `golden/` (a quick-scale report tree), edited in known ways, and on
//! `golden/` against the committed paper-scale `reports/`. Each test works
//! in its own scratch directory under `target/rlfd/tests/`.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Output;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

fn scratch(name: &str) -> PathBuf {
    let d = root().join("target/rlfd/tests").join(name);
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).unwrap();
    d
}

fn copy_tree(from: &Path, to: &Path) {
    fs::create_dir_all(to).unwrap();
    for e in fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        let target = to.join(p.file_name().unwrap());
        if p.is_dir() {
            copy_tree(&p, &target);
        } else {
            fs::copy(&p, &target).unwrap();
        }
    }
}

/// A copy of golden/ at `dir/name`.
fn golden_copy(dir: &Path, name: &str) -> PathBuf {
    let to = dir.join(name);
    copy_tree(&root().join("golden"), &to);
    to
}

fn diff(args: &[&Path], extra: &[&str]) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_xtask")).arg("diff").args(args).args(extra).output().unwrap()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn edit(path: &Path, f: impl FnOnce(String) -> String) {
    let before = fs::read_to_string(path).unwrap();
    let after = f(before.clone());
    assert_ne!(before, after, "the edit of {} changed nothing", path.display());
    fs::write(path, after).unwrap();
}

/// The provenance line golden/ carries (index.html's, without comment syntax).
const MADE_BY: &str = "cargo xtask reproduce --scale quick --seed 20160501 (rlfd 0.1.0)";

#[test]
fn identical_trees_and_provenance_only_changes_agree() {
    let dir = scratch("diff-agree");
    let (a, b) = (golden_copy(&dir, "a"), golden_copy(&dir, "b"));
    // Another command in every provenance line of every file, and a run.json.
    let mut rewritten = 0;
    for chapter in fs::read_dir(&b).unwrap() {
        let chapter = chapter.unwrap().path();
        let files: Vec<PathBuf> = if chapter.is_dir() {
            fs::read_dir(&chapter).unwrap().map(|e| e.unwrap().path()).collect()
        } else {
            vec![chapter]
        };
        for f in files {
            let Ok(t) = fs::read_to_string(&f) else { continue };
            let lines: Vec<String> = t
                .split('\n')
                .map(|l| {
                    if l.contains("do not edit") {
                        l.replace("--seed 20160501", "--seed 20160501 --jobs 1")
                    } else {
                        l.to_string()
                    }
                })
                .collect();
            if lines.join("\n") != t {
                rewritten += 1;
                fs::write(&f, lines.join("\n")).unwrap();
            }
        }
    }
    // Pages, figures, LaTeX, summaries and READMEs (CSV files carry no provenance line).
    assert!(rewritten > 50, "{rewritten}");
    fs::write(b.join("run.json"), "{\"host\": \"elsewhere\"}\n").unwrap();

    for (x, y) in [(&a, &a), (&a, &b)] {
        let out = diff(&[x, y], &[]);
        assert_eq!(out.status.code(), Some(0), "{}{}", text(&out.stdout), text(&out.stderr));
        let stdout = text(&out.stdout);
        assert_eq!(stdout.lines().count(), 1, "{stdout}");
        assert!(stdout.starts_with(&format!("reports agree: {} and {} (", x.display(), y.display())), "{stdout}");
        assert!(out.stderr.is_empty(), "{}", text(&out.stderr));
    }
}

/// Edits a copy of golden/ in five known ways; returns (old, new).
fn edited(dir: &Path) -> (PathBuf, PathBuf) {
    let (a, b) = (golden_copy(dir, "a"), golden_copy(dir, "b"));
    // A table cell changed, and another rewritten as the same number.
    edit(&b.join("ch6-irl-shaping/table_6_1.csv"), |t| {
        t.replace("SAR,-4681.75,", "SAR,-4000.5,").replace("SIS,-6015.75,", "SIS,\u{2212}6015.750,")
    });
    // A claim's verdict flipped.
    let summary = b.join("ch3-interactive-rl/summary.json");
    let mut json: serde_json::Value = serde_json::from_str(&fs::read_to_string(&summary).unwrap()).unwrap();
    let claim = &mut json["summary"]["claims"][0];
    assert_eq!((claim["id"].as_str(), claim["verdict"].as_str()), (Some("C3.1"), Some("not-evaluable")));
    claim["verdict"] = "reproduced".into();
    fs::write(&summary, serde_json::to_string_pretty(&json).unwrap() + "\n").unwrap();
    // Two figures redrawn, one with a data file named after it.
    for svg in ["ch4-dbug-study/figure_4_2.svg", "ch6-irl-shaping/figure_6_1.svg"] {
        edit(&b.join(svg), |t| t.replace("</svg>", "<circle cx=\"1\" cy=\"1\" r=\"1\"/>\n</svg>"));
    }
    // A file removed, one added.
    fs::remove_file(b.join("ch5-hat-keepaway/table_5_1_welch.csv")).unwrap();
    fs::write(b.join("ch6-irl-shaping/notes.txt"), "# generated by hand; do not edit\nnotes\n").unwrap();
    (a, b)
}

#[test]
fn every_edit_is_listed_verdicts_first() {
    let dir = scratch("diff-edited");
    let (a, b) = edited(&dir);
    let out = diff(&[&a, &b], &[]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(out.stderr.is_empty(), "a difference is not an error: {}", text(&out.stderr));
    let reason = "Needs the 100-trial experiment (`sorting-100`) at paper scale: at least 20 trials per condition; the evidence is shown for the record.";
    let expected = format!(
        "reports differ: {} → {}
  both made by {MADE_BY}, decided by the {plan}

Claims whose verdict changed (1):
  C3.1  not evaluable → reproduced: {reason}

Table cells changed (1 cell in 1 file):
  ch6-irl-shaping/table_6_1.csv: 1 cell changed
    [SAR] initial_ours: -4681.75 → -4000.5 (+14.6 %)

Figures changed (2):
  figure ch4-dbug-study/figure_4_2.svg changed (data: figure_4_2_iqm.csv, unchanged; figure_4_2_medians.csv, unchanged)
  figure ch6-irl-shaping/figure_6_1.svg changed

Files added (1):
  ch6-irl-shaping/notes.txt

Files removed (1):
  ch5-hat-keepaway/table_5_1_welch.csv
",
        a.display(),
        b.display(),
        plan = rlfd_report::plan::analysis_plan().line()
    );
    assert_eq!(text(&out.stdout), expected);

    // The same in Markdown, in the same order.
    let out = diff(&[&a, &b], &["--format", "markdown"]);
    assert_eq!(out.status.code(), Some(1));
    let md = text(&out.stdout);
    assert!(md.starts_with(&format!("## Report diff: `{}` → `{}`\n", a.display(), b.display())), "{md}");
    let headings: Vec<&str> = md.lines().filter(|l| l.starts_with("### ")).collect();
    assert_eq!(
        headings,
        [
            "### Claims whose verdict changed (1)",
            "### Table cells changed (1 cell in 1 file)",
            "### Figures changed (2)",
            "### Files added (1)",
            "### Files removed (1)"
        ]
    );
    assert!(md.contains("| C3.1 | not evaluable | **reproduced** | Needs the 100-trial"), "{md}");
    assert!(md.contains("| SAR | initial_ours | -4681.75 | -4000.5 | +14.6 % |\n"), "{md}");
    assert!(md.contains("- `ch6-irl-shaping/notes.txt`\n"), "{md}");
}

#[test]
fn bad_input_is_one_line_and_exit_code_2() {
    let dir = scratch("diff-bad");
    let good = root().join("golden");
    let missing = dir.join("missing");
    let file = dir.join("a-file");
    fs::write(&file, "x").unwrap();
    let no_index = dir.join("no-index");
    fs::create_dir_all(no_index.join("ch6")).unwrap();
    fs::write(no_index.join("ch6/summary.json"), "{}").unwrap();
    let no_summary = dir.join("no-summary");
    fs::create_dir_all(&no_summary).unwrap();
    fs::write(no_summary.join("index.html"), "<!DOCTYPE html>\n").unwrap();
    let bad_summary = golden_copy(&dir, "bad-summary");
    fs::write(bad_summary.join("ch6-irl-shaping/summary.json"), "not json").unwrap();
    for (old, new, says) in [
        (&missing, &good, "no such directory"),
        (&good, &missing, "no such directory"),
        (&file, &good, "not a directory"),
        (&no_index, &good, "not a report tree (no index.html)"),
        (&good, &no_summary, "not a report tree (no chapter summary.json)"),
        (&good, &bad_summary, "not a chapter summary"),
    ] {
        let out = diff(&[old, new], &[]);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{old:?} {new:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(stderr.starts_with("error: ") && stderr.contains(says), "{stderr}");
        let bad = [old, new].into_iter().find(|p| *p != &good).unwrap();
        assert!(stderr.contains(&bad.display().to_string()), "names the path: {stderr}");
        assert!(out.stdout.is_empty());
    }
    // A bad flag is clap's one line and 2 as well.
    let out = diff(&[&good, &good], &["--format", "html"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(text(&out.stderr).lines().count(), 1, "{}", text(&out.stderr));
    let out = diff(&[&good], &[]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn quick_against_paper_scale_is_a_readable_difference() {
    let (golden, reports) = (root().join("golden"), root().join("reports"));
    let out = diff(&[&golden, &reports], &[]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(out.stderr.is_empty(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(stdout.contains("  old made by cargo xtask reproduce --scale quick"), "{stdout}");
    // The committed index names the last command that rendered into reports/.
    let new_line = stdout.lines().find(|l| l.starts_with("  new made by cargo xtask reproduce")).unwrap_or("");
    assert!(new_line.contains("--scale paper"), "{stdout}");
    let pos = |s: &str| stdout.find(s).unwrap_or_else(|| panic!("no {s:?} in {stdout}"));
    assert!(pos("Claims whose verdict changed") < pos("Table cells changed"));
    assert!(pos("Table cells changed") < pos("Figures changed"));
    assert!(pos("Figures changed") < pos("Files added"));
    // Different trial counts name different figure files.
    assert!(stdout.contains("  ch3-interactive-rl/figure_3_4_100.svg\n"), "{stdout}");
    // The per-table limit keeps the output to a reviewer's size.
    assert!(stdout.lines().count() < 2000, "{} lines", stdout.lines().count());
}
