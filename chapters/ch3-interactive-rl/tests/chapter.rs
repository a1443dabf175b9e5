//! The chapter end to end at quick scale: every experiment runs through the
//! harness, the results do not depend on the number of threads, a second
//! run reuses every stored trial, and the report renders with the thesis's
//! numbers beside ours and a verdict for each of C3.1–C3.5.

use ch3_interactive_rl::report::chapter_report;
use ch3_interactive_rl::{CHAPTER, Ch3, Condition, Results};
use rlfd_harness::{ResultStore, RunContext, RunMode, RunOptions, Scale};
use rlfd_report::claims::Verdict;
use rlfd_report::{Block, Provenance, render_chapter};

/// Runs (or with `load_only`, loads) every experiment; returns the results
/// and (computed, reused).
fn run(dir: &std::path::Path, jobs: usize, load_only: bool) -> (Results, (usize, usize)) {
    let mode = if load_only { RunMode::Load { any_version: false } } else { RunMode::Run };
    let options = RunOptions { mode, ..RunOptions::new(ResultStore::new(dir), jobs) };
    let results = rlfd_runner::run_all::<Ch3>(&RunContext::new(20160501, Scale::Quick), &options).unwrap();
    let (computed, reused, _, _) = options.tally.totals();
    (results, (computed, reused))
}

#[test]
fn quick_scale_runs_reuses_and_renders_the_same_for_any_jobs() {
    let base = std::env::temp_dir().join(format!("rlfd-ch3-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&base);
    let provenance = Provenance::new("test", "0");

    let (one, counts) = run(&base.join("a"), 1, false);
    let (two, _) = run(&base.join("b"), 2, false);
    // 4 conditions × 3 trials and 4 × 10 (the noise sweep's other levels
    // are the runner's, for the report).
    assert_eq!(counts, (12 + 40, 0));
    let files_one = render_chapter(&chapter_report(&one, &[], &provenance).unwrap()).unwrap();
    let files_two = render_chapter(&chapter_report(&two, &[], &provenance).unwrap()).unwrap();
    assert_eq!(files_one, files_two, "the report depends on --jobs");

    // Stored results are reused, and load-only gives the same report.
    let (again, counts) = run(&base.join("a"), 2, true);
    assert_eq!(counts, (0, 52));
    let files_again = render_chapter(&chapter_report(&again, &[], &provenance).unwrap()).unwrap();
    assert_eq!(files_again, files_one);

    // The report: Table 3.2 with the thesis's values, Figure 3.4 (four
    // panels in one grid) per sorting experiment, and a verdict for every claim (not evaluable at
    // quick scale).
    let report = chapter_report(&one, &[], &provenance).unwrap();
    assert_eq!(report.slug, CHAPTER);
    let names: Vec<&str> = files_one.iter().map(|f| f.path.as_str()).collect();
    for f in [
        "index.html",
        "chapter.tex",
        "table_3_2.csv",
        "table_3_1.csv",
        "figure_3_4.svg",
        "figure_3_4_10.svg",
        "figure_3_4.pdf",
    ] {
        assert!(names.iter().any(|n| n.ends_with(f)), "{f} missing from {names:?}");
    }
    let table = files_one.iter().find(|f| f.path.ends_with("table_3_2.csv")).unwrap().text().into_owned();
    assert!(table.contains("#States,") && table.contains(",11.33,") && table.contains(",366.67"), "{table}");
    let claims: Vec<_> = report
        .sections
        .iter()
        .flat_map(|s| &s.blocks)
        .filter_map(|b| if let Block::Claims(c) = b { Some(c) } else { None })
        .flatten()
        .collect();
    let ids: Vec<&str> = claims.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(ids, ["C3.1", "C3.2", "C3.3", "C3.4", "C3.5"]);
    assert!(claims.iter().all(|c| c.verdict == Verdict::NotEvaluable));

    // Every session finished, and the guidance conditions got guidance.
    let sorting = one.sorting.as_ref().unwrap();
    for c in Condition::ALL {
        for s in &sorting.trials[&c] {
            assert!(s.finished);
            assert_eq!(s.guidance_given > 0, c.guidance());
        }
    }
    std::fs::remove_dir_all(&base).unwrap();
}
