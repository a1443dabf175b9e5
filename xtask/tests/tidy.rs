//! Rules of the architecture, checked as tests (see ARCHITECTURE.md):
//! the dependency direction between crates, domains that never import
//! agents, cores that never read the clock or an unseeded generator, and the
//! `//!` header every source file opens with.

use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// The workspace's crates: (name, directory).
fn crates() -> Vec<(String, PathBuf)> {
    let mut out = Vec::new();
    for group in ["crates", "chapters"] {
        for e in fs::read_dir(root().join(group)).unwrap() {
            let dir = e.unwrap().path();
            if dir.join("Cargo.toml").exists() {
                out.push((dir.file_name().unwrap().to_string_lossy().into_owned(), dir));
            }
        }
    }
    out.push(("xtask".into(), root().join("xtask")));
    out.sort();
    out
}

/// The workspace crates a manifest depends on (normal dependencies only).
fn internal_deps(manifest: &Path, names: &[String]) -> Vec<String> {
    let text = fs::read_to_string(manifest).unwrap();
    let mut in_deps = false;
    let mut deps = Vec::new();
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            in_deps = line == "[dependencies]";
            continue;
        }
        if in_deps
            && !line.starts_with('#')
            && let Some(name) = line.split(['=', '.']).next().map(str::trim)
            && names.iter().any(|n| n == name)
        {
            deps.push(name.to_string());
        }
    }
    deps.sort();
    deps
}

/// What each crate may depend on, from design.md's diagram:
/// xtask → chapters → rlfd-lfd → rlfd-rl; chapters → rlfd-harness → rlfd-stats;
/// xtask, chapters → rlfd-report → rlfd-stats.
fn allowed(name: &str, dep: &str) -> bool {
    let is_chapter = |n: &str| n.starts_with("ch") && n.chars().nth(2).is_some_and(|c| c.is_ascii_digit());
    match name {
        "rlfd-rl" | "rlfd-stats" => false,
        "rlfd-lfd" => dep == "rlfd-rl",
        "rlfd-harness" | "rlfd-report" => dep == "rlfd-stats",
        "xtask" => is_chapter(dep) || dep == "rlfd-harness" || dep == "rlfd-report",
        n if is_chapter(n) => !is_chapter(dep) && dep != "xtask",
        other => panic!("crate {other} is not in the dependency rules; add it to design.md and here"),
    }
}

#[test]
fn dependencies_point_the_right_way() {
    let all = crates();
    let names: Vec<String> = all.iter().map(|(n, _)| n.clone()).collect();
    let mut violations = Vec::new();
    for (name, dir) in &all {
        for dep in internal_deps(&dir.join("Cargo.toml"), &names) {
            if !allowed(name, &dep) {
                violations.push(format!("{name} → {dep}"));
            }
        }
    }
    assert!(violations.is_empty(), "dependencies against design.md: {violations:?}");
    assert!(names.contains(&"rlfd-rl".to_string()) && names.contains(&"ch6-irl-shaping".to_string()));
}

fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    if let Ok(entries) = fs::read_dir(dir) {
        for e in entries {
            let p = e.unwrap().path();
            if p.is_dir() {
                out.extend(rust_files(&p));
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The code of a file without comments and without its `#[cfg(test)]` tail
/// (tests may do what cores may not).
fn non_test_source(p: &Path) -> String {
    let text = fs::read_to_string(p).unwrap();
    let code = match text.find("#[cfg(test)]") {
        Some(i) => &text[..i],
        None => &text,
    };
    code.lines().filter(|l| !l.trim_start().starts_with("//")).collect::<Vec<_>>().join("\n")
}

#[test]
fn domains_never_import_agents() {
    // Simulators depend on the Environment trait, never on learners or shaping.
    let forbidden =
        ["SarsaLambda", "WatkinsQLambda", "rlfd_rl::Agent", "rlfd_rl::shaping", "crate::agents", "TdControl"];
    let mut bad = Vec::new();
    for (name, dir) in crates() {
        if !name.starts_with("ch") {
            continue;
        }
        for domain in ["maze", "mario", "keepaway", "nao", "dbug"] {
            for f in rust_files(&dir.join("src").join(domain)) {
                let src = non_test_source(&f);
                for word in forbidden {
                    if src.contains(word) {
                        bad.push(format!("{} uses {word}", f.display()));
                    }
                }
            }
        }
    }
    assert!(bad.is_empty(), "{bad:?}");
}

#[test]
fn cores_read_no_clock_and_no_unseeded_generator() {
    let forbidden = [
        "Instant::now",
        "SystemTime",
        "thread_rng",
        "rand::rng()",
        "from_entropy",
        "from_os_rng",
        "HashMap",
        "HashSet",
    ];
    let mut bad = Vec::new();
    for (name, dir) in crates() {
        if name == "xtask" || name == "rlfd-harness" {
            continue; // the command line and the runner time and report runs
        }
        for f in rust_files(&dir.join("src")) {
            let src = non_test_source(&f);
            for word in forbidden {
                if src.contains(word) {
                    bad.push(format!("{} uses {word}", f.display()));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{bad:?}");
}

#[test]
fn every_source_file_opens_with_a_doc_comment() {
    let mut bad = Vec::new();
    for (_, dir) in crates() {
        for sub in ["src", "tests", "benches", "examples"] {
            for f in rust_files(&dir.join(sub)) {
                let text = fs::read_to_string(&f).unwrap();
                if !text.trim_start().starts_with("//!") {
                    bad.push(f.display().to_string());
                }
            }
        }
    }
    assert!(bad.is_empty(), "files without a leading //! doc: {bad:?}");
}
