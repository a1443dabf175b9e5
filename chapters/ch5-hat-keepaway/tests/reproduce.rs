//! End-to-end checks of the chapter at the quick scale: the same seed gives
//! the same report bytes whatever the number of threads, and a report
//! rebuilt from the stored trials alone is identical.

use std::path::PathBuf;

use ch5_hat_keepaway::experiment::plan;
use ch5_hat_keepaway::{Ch5Error, Ch5Results, Experiment, report};
use rlfd_harness::{ResultStore, RunContext, RunMode, RunOptions, Scale};
use rlfd_report::{Provenance, render_chapter};

fn scratch(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ch5-reproduce-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Runs (or loads) `experiments`; the results and (computed, reused).
fn reproduce(
    dir: &PathBuf,
    jobs: usize,
    load_only: bool,
    experiments: &[Experiment],
) -> Result<(Ch5Results, (usize, usize)), Ch5Error> {
    let mode = if load_only { RunMode::Load { any_version: false } } else { RunMode::Run };
    let options = RunOptions { mode, ..RunOptions::new(ResultStore::new(dir), jobs) };
    let results = plan(&RunContext::new(20160501, Scale::Quick), experiments)?.execute(&options)?;
    let (computed, reused, _, _) = options.tally.totals();
    Ok((results, (computed, reused)))
}

fn rendered(results: &ch5_hat_keepaway::Ch5Results) -> Vec<(String, Vec<u8>)> {
    let provenance = Provenance::new("test", "0");
    let chapter = report::chapter_report(results, &provenance).expect("the report builds");
    render_chapter(&chapter).expect("the report renders").into_iter().map(|f| (f.path, f.bytes)).collect()
}

#[test]
fn quick_scale_is_deterministic_for_any_jobs_and_rerenders_from_the_store() {
    let experiments = [Experiment::Validation, Experiment::Demonstrations, Experiment::Hat];
    let (one, two) = (scratch("one"), scratch("two"));
    let (a, counts) = reproduce(&one, 1, false, &experiments).unwrap();
    let (b, _) = reproduce(&two, 2, false, &experiments).unwrap();
    assert_eq!(counts.1, 0);
    assert!(counts.0 > 10);
    let (ra, rb) = (rendered(&a), rendered(&b));
    assert_eq!(ra, rb, "the number of threads changed the report");
    let (again, again_counts) = reproduce(&one, 2, true, &experiments).unwrap();
    assert_eq!(again_counts, (0, counts.0));
    assert_eq!(rendered(&again), ra, "a report from stored results differs");
    // The tables the experiments promise are there.
    for file in [
        "table_5_1.csv",
        "figure_5_3.svg",
        "keepaway_validation_durations.csv",
        "keepaway_episode.svg",
        "figure_5_3_greedy.svg",
        "keepaway_curves.csv",
    ] {
        assert!(ra.iter().any(|(p, _)| p.ends_with(file)), "{file} missing");
    }
    let _ = std::fs::remove_dir_all(&one);
    let _ = std::fs::remove_dir_all(&two);
}

#[test]
fn load_only_without_stored_trials_names_what_is_missing() {
    let dir = scratch("missing");
    let err = reproduce(&dir, 1, true, &[Experiment::Validation]).err().unwrap().to_string();
    assert!(err.contains("keepaway-validation"), "{err}");
}
