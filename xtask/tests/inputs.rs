//! Demonstration files that parse but cannot serve chapter 6's maze are
//! refused up front: one `error:` line naming the file and the problem, a
//! non-zero exit, no trial stored and nothing written to `--out`.
//!
//! Not here: files that do not parse (`cli.rs`) and the readers' own fuzzing
//! (`crates/rlfd-lfd/tests/demonstration_fuzz.rs`).

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

fn scratch(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/rlfd/tests").join(name);
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `reproduce --demonstrations file` at quick scale and checks for one
/// `error:` line naming the file and holding `expected`, a non-zero exit,
/// no panic, no output and no stored trial.
fn refused(dir: &Path, file: &Path, expected: &str) {
    let out_dir = dir.join("out");
    let results = dir.join("results");
    let mut c = Command::new(env!("CARGO_BIN_EXE_xtask"));
    c.args(["reproduce", "--scale", "quick", "--no-progress", "--chapter", "ch6", "--demonstrations"])
        .arg(file)
        .arg("--out")
        .arg(&out_dir)
        .arg("--results")
        .arg(&results);
    let out = c.output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{} was accepted", file.display());
    assert!(!stderr.contains("panicked"), "{stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "one line expected: {stderr}");
    let line = lines[0];
    assert!(line.starts_with("error: "), "{line}");
    assert!(line.contains(&file.display().to_string()), "{line:?} does not name the file");
    assert!(line.contains(expected), "{line:?} lacks {expected:?}");
    assert!(!out_dir.exists(), "no output may be left behind");
    assert!(!results.exists(), "no trial may be stored");
}

/// A CSV demonstration file of `walks`: each a start (hundredths) and moves
/// (0 left, 1 right, 2 up, 3 down) of 0.02, the last state without an action.
fn walks_csv(walks: &[((i32, i32), Vec<usize>)]) -> String {
    let mut csv = String::from("trajectory,step,x,y,action\n");
    for (t, (start, moves)) in walks.iter().enumerate() {
        let mut at = *start;
        for (k, &m) in moves.iter().enumerate() {
            csv.push_str(&format!("{t},{k},{},{},{m}\n", f64::from(at.0) / 100.0, f64::from(at.1) / 100.0));
            let (dx, dy) = [(-2, 0), (2, 0), (0, 2), (0, -2)][m];
            at = (at.0 + dx, at.1 + dy);
        }
        csv.push_str(&format!("{t},{},{},{},\n", moves.len(), f64::from(at.0) / 100.0, f64::from(at.1) / 100.0));
    }
    csv
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    fs::write(&p, text).unwrap();
    p
}

#[test]
fn files_that_cannot_serve_the_maze_are_refused_before_any_trial() {
    let d = scratch("inputs");
    let up = |n: usize| vec![2; n];

    // Too few demonstrated moves for RIPPER's 10-fold cross-validation.
    let few = write(&d, "few.csv", &walks_csv(&[((8, 60), up(4)), ((8, 60), up(3))]));
    refused(
        &d,
        &few,
        "demonstrations: only 7 states have an action (a demonstrated move), but RIPPER's 10-fold cross-validation needs at least 10",
    );

    // A one-state demonstration among good ones.
    let stub = write(&d, "stub.csv", &walks_csv(&[((8, 60), up(12)), ((8, 60), vec![])]));
    refused(
        &d,
        &stub,
        "demonstrations: trajectory 1 holds 1 state, but a demonstration needs at least 2 (a start and one move)",
    );

    // Coordinates outside the maze, and inside one of its walls.
    let outside = write(&d, "outside.csv", &walks_csv(&[((8, 80), up(12))]));
    refused(&d, &outside, "demonstrations: trajectory 0, step 10: state (0.08, 1) lies outside the unit square");
    let wall = write(&d, "wall.csv", &walks_csv(&[((16, 60), vec![1; 12])]));
    refused(&d, &wall, "demonstrations: trajectory 0, step 4: state (0.24, 0.6) lies inside a wall of the maze");

    // Actions outside 0..4 (the reader, with the field), none at all, or not 2 state variables.
    let mut bad_action = walks_csv(&[((8, 60), up(12))]);
    bad_action = bad_action.replacen("0,3,0.08,0.66,2", "0,3,0.08,0.66,4", 1);
    let bad_action = write(&d, "action.csv", &bad_action);
    refused(&d, &bad_action, "action.csv:5: field \"action\": 4 is out of range 0..4");
    let no_actions = write(&d, "no-actions.csv", "trajectory,step,x,y\n0,0,0.08,0.6\n0,1,0.08,0.62\n");
    refused(&d, &no_actions, "Maze demonstrations need their moves as actions 0..4");
    let three = write(&d, "three.csv", "trajectory,step,x,y,z,action\n0,0,0.08,0.6,0,2\n0,1,0.08,0.62,0,\n");
    refused(&d, &three, "Maze states have 2 values (x, y), these have 3");

    // The same refusals hold for JSON Lines.
    let few_jsonl = write(
        &d,
        "few.jsonl",
        "{\"state_names\":[\"x\",\"y\"],\"num_actions\":4}\n{\"states\":[[0.08,0.6],[0.08,0.62]],\"actions\":[2]}\n",
    );
    refused(&d, &few_jsonl, "only 1 states have an action");
}
