//! Rules of the architecture, checked as tests (see ARCHITECTURE.md):
//! the dependency direction between crates (read from the manifests with
//! the `toml` crate), domains that never import agents, cores that never
//! read the clock or an unseeded generator, transcendental functions only
//! through `libm`, and the `//!` header every source file opens with.

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
    let table: toml::Table = text.parse().unwrap_or_else(|e| panic!("{} is not TOML: {e}", manifest.display()));
    let mut deps: Vec<String> = table
        .get("dependencies")
        .and_then(|d| d.as_table())
        .map(|d| d.keys().filter(|k| names.contains(k)).cloned().collect())
        .unwrap_or_default();
    deps.sort();
    deps
}

/// What each crate may depend on, from ARCHITECTURE.md's "Dependencies point one way":
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
        other => panic!("crate {other} is not in the dependency rules; add it to ARCHITECTURE.md and here"),
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
    assert!(violations.is_empty(), "dependencies against ARCHITECTURE.md: {violations:?}");
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

/// Words that mark code as an agent (a learner, shaping, or the episode driver).
const AGENT_WORDS: [&str; 7] =
    ["SarsaLambda", "WatkinsQLambda", "TabularQ", "rlfd_rl::Agent", "rlfd_rl::shaping", "TdControl", "ripper::"];

/// A chapter's top-level modules: (name, files).
fn modules(src: &Path) -> Vec<(String, Vec<PathBuf>)> {
    let mut out = Vec::new();
    for e in fs::read_dir(src).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_stem().unwrap().to_string_lossy().into_owned();
        if p.is_dir() {
            out.push((name, rust_files(&p)));
        } else if p.extension().is_some_and(|x| x == "rs") && name != "lib" {
            out.push((name, vec![p]));
        }
    }
    out.sort();
    out
}

#[test]
fn domains_never_import_agents() {
    // Simulators depend on the Environment trait, never on learners or
    // shaping. The domains are the five simulator folders, and any module
    // that implements `Environment` is one too (so a new domain is covered);
    // agent modules are found by what they use.
    let mut bad = Vec::new();
    for (name, dir) in crates() {
        if !name.starts_with("ch") {
            continue;
        }
        let mods = modules(&dir.join("src"));
        let is_agent =
            |files: &[PathBuf]| files.iter().any(|f| AGENT_WORDS.iter().any(|w| non_test_source(f).contains(w)));
        let agents: Vec<&str> = mods.iter().filter(|(_, f)| is_agent(f)).map(|(n, _)| n.as_str()).collect();
        for (module, files) in &mods {
            let implements_env = files.iter().any(|f| non_test_source(f).contains("Environment for"));
            if !(["maze", "mario", "keepaway", "nao", "dbug"].contains(&module.as_str()) || implements_env) {
                continue;
            }
            for f in files {
                let src = non_test_source(f);
                for word in AGENT_WORDS {
                    if src.contains(word) {
                        bad.push(format!("{} uses {word}", f.display()));
                    }
                }
                for agent in &agents {
                    if src.contains(&format!("crate::{agent}::")) || src.contains(&format!("crate::{agent}{{")) {
                        bad.push(format!("{} imports the agent module crate::{agent}", f.display()));
                    }
                }
            }
        }
        assert!(!agents.is_empty(), "{name}: no agent module found; the rule would check nothing");
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

#[test]
fn transcendental_functions_go_through_libm() {
    // Platform libms differ in the last bit; `libm` gives the same bits on
    // every machine, so results and golden files do too (sqrt and the basic
    // operations are exact in IEEE 754 and may stay methods).
    let forbidden = [
        ".exp(",
        ".exp2(",
        ".exp_m1(",
        ".ln(",
        ".ln_1p(",
        ".log(",
        ".log2(",
        ".log10(",
        ".sin(",
        ".cos(",
        ".tan(",
        ".asin(",
        ".acos(",
        ".atan(",
        ".atan2(",
        ".sinh(",
        ".cosh(",
        ".tanh(",
        ".powf(",
        ".hypot(",
        ".cbrt(",
        ".sin_cos(",
    ];
    let mut bad = Vec::new();
    for (name, dir) in crates() {
        if name == "xtask" {
            continue; // the command line computes no result
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
    assert!(bad.is_empty(), "use libm's function instead: {bad:?}");
}
