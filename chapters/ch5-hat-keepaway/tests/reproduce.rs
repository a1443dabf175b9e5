//! End-to-end checks of the chapter at the quick scale: the same seed gives
//! the same report bytes whatever the number of threads, and a report
//! rebuilt from the stored trials alone is identical.

use std::path::PathBuf;

use ch5_hat_keepaway::{Experiment, report, reproduce};
use rlfd_harness::{ResultStore, RunOptions, Scale};
use rlfd_report::{Provenance, render_chapter};

fn scratch(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ch5-reproduce-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn mode(load_only: bool) -> rlfd_harness::RunMode {
    if load_only { rlfd_harness::RunMode::Load { any_version: false } } else { rlfd_harness::RunMode::Run }
}

fn options(dir: &PathBuf, jobs: usize, load_only: bool) -> RunOptions {
    RunOptions {
        jobs,
        progress: false,
        store: ResultStore::new(dir),
        master_seed: 20160501,
        scale: Scale::Quick,
        mode: mode(load_only),
        reading: Default::default(),
        tally: Default::default(),
    }
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
    let a = reproduce(&options(&one, 1, false), &experiments).unwrap();
    let b = reproduce(&options(&two, 2, false), &experiments).unwrap();
    assert_eq!(a.trial_counts().1, 0);
    assert!(a.trial_counts().0 > 10);
    let (ra, rb) = (rendered(&a), rendered(&b));
    assert_eq!(ra, rb, "the number of threads changed the report");
    let again = reproduce(&options(&one, 2, true), &experiments).unwrap();
    assert_eq!(again.trial_counts(), (0, a.trial_counts().0));
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
    let err = reproduce(&options(&dir, 1, true), &[Experiment::Validation]).unwrap_err().to_string();
    assert!(err.contains("keepaway-validation"), "{err}");
}
