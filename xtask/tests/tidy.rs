//! Rules of the architecture, checked as tests (see ARCHITECTURE.md):
//! the dependency direction between crates (read from the manifests with
//! the `toml` crate; domains are crates that depend on `rlfd-env` alone, so
//! Cargo keeps agents out of them), no declared dependency left unused,
//! `Environment` implemented only in domains, cores that never read the
//! clock or an unseeded generator, transcendental functions only through
//! `libm`, and the `//!` header every source file opens with.

use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// The workspace's crates: (name, directory).
fn crates() -> Vec<(String, PathBuf)> {
    let mut out = Vec::new();
    for group in ["crates", "domains", "chapters"] {
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
/// xtask → chapters → domains → rlfd-env; chapters → rlfd-lfd → rlfd-rl →
/// rlfd-env; xtask, chapters → rlfd-runner → rlfd-harness, rlfd-report;
/// xtask, chapters → rlfd-report → rlfd-stats. A domain depends on `rlfd-env` alone: it cannot name an agent.
fn allowed(name: &str, dep: &str) -> bool {
    let is_chapter = |n: &str| n.starts_with("ch") && n.chars().nth(2).is_some_and(|c| c.is_ascii_digit());
    let is_domain = |n: &str| DOMAINS.contains(&n);
    match name {
        "rlfd-env" | "rlfd-stats" | "rlfd-harness" => false,
        "rlfd-rl" => dep == "rlfd-env",
        "rlfd-lfd" => dep == "rlfd-rl" || dep == "rlfd-env",
        "rlfd-report" => dep == "rlfd-stats",
        "rlfd-runner" => ["rlfd-harness", "rlfd-report", "rlfd-stats"].contains(&dep),
        n if is_domain(n) => dep == "rlfd-env",
        "xtask" => is_chapter(dep) || ["rlfd-harness", "rlfd-report", "rlfd-runner"].contains(&dep),
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

/// The domain crates (`domains/*`).
const DOMAINS: [&str; 5] = ["rlfd-nao", "rlfd-dbug", "rlfd-keepaway", "rlfd-maze", "rlfd-mario"];

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

/// The dependency names of a manifest's `section` (`dependencies`,
/// `dev-dependencies`, `build-dependencies`).
fn section_deps(manifest: &Path, section: &str) -> Vec<String> {
    let table: toml::Table = fs::read_to_string(manifest).unwrap().parse().unwrap();
    let mut deps: Vec<String> =
        table.get(section).and_then(|d| d.as_table()).map(|d| d.keys().cloned().collect()).unwrap_or_default();
    deps.sort();
    deps
}

/// Whether `code` names the crate `dep` (as `dep::…`, `use dep`, or a
/// derive from it, e.g. `serde`'s), `-` read as `_`.
fn names_crate(code: &str, dep: &str) -> bool {
    let ident = dep.replace('-', "_");
    let bytes = code.as_bytes();
    let mut from = 0;
    while let Some(i) = code[from..].find(&ident) {
        let at = from + i;
        let end = at + ident.len();
        let before_ok = at == 0 || !(bytes[at - 1].is_ascii_alphanumeric() || bytes[at - 1] == b'_');
        let rest = &code[end..];
        let after_ok =
            rest.starts_with("::") || rest.starts_with(';') || rest.starts_with(" as ") || rest.starts_with(',');
        if before_ok && after_ok {
            return true;
        }
        from = end;
    }
    false
}

#[test]
fn every_declared_dependency_is_used() {
    // The equivalent of `cargo machete`: a normal dependency is named in the
    // crate's library or binary code, a build dependency in `build.rs`, a dev
    // dependency somewhere in the crate (tests, benches, examples, test
    // modules). An unused one makes the graph (and, for a trial's code
    // path, its reviewers) believe in an edge that is not there.
    let mut bad = Vec::new();
    for (name, dir) in crates() {
        let manifest = dir.join("Cargo.toml");
        let src: String = rust_files(&dir.join("src")).iter().map(|f| fs::read_to_string(f).unwrap()).collect();
        let all: String = ["src", "tests", "benches", "examples"]
            .iter()
            .flat_map(|s| rust_files(&dir.join(s)))
            .map(|f| fs::read_to_string(f).unwrap())
            .collect();
        let build = fs::read_to_string(dir.join("build.rs")).unwrap_or_default();
        for (section, code) in [("dependencies", &src), ("dev-dependencies", &all), ("build-dependencies", &build)] {
            for dep in section_deps(&manifest, section) {
                if !names_crate(code, &dep) {
                    bad.push(format!("{name}: [{section}] {dep} is never named"));
                }
            }
        }
    }
    assert!(bad.is_empty(), "remove the unused dependencies: {bad:#?}");
    assert!(names_crate("use serde::{Deserialize};", "serde") && !names_crate("serde_json::to_string", "serde"));
    assert!(names_crate("rlfd_rl::random", "rlfd-rl") && !names_crate("my_rlfd_rl::x", "rlfd-rl"));
}

#[test]
fn environments_are_implemented_only_in_domains() {
    // Domains are crates that depend on `rlfd-env` alone among the
    // workspace's libraries (see `dependencies_point_the_right_way`), so
    // Cargo keeps agents out of them. A simulator written elsewhere would
    // escape that: no crate outside `domains/` implements `Environment` in
    // its library code.
    let mut bad = Vec::new();
    for (name, dir) in crates() {
        if dir.parent().is_some_and(|p| p.ends_with("domains")) {
            continue;
        }
        // (A file named `tests.rs` is a test module: test doubles may implement anything.)
        for f in rust_files(&dir.join("src")).into_iter().filter(|f| !f.ends_with("tests.rs")) {
            let src = non_test_source(&f);
            if src.lines().any(|l| l.contains("Environment for ") && l.trim_start().starts_with("impl")) {
                bad.push(format!("{name}: {} implements Environment outside domains/", f.display()));
            }
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
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
        if ["xtask", "rlfd-harness", "rlfd-runner"].contains(&name.as_str()) {
            continue; // the command line, the harness and the runner time and report runs
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

/// The README's list of the thesis's open choices is the declared one:
/// every axis every chapter declares is named there in backticks, with each
/// of its levels in the entry that follows (up to the parenthesis that
/// closes it).
#[test]
fn the_readme_lists_every_declared_reading() {
    use rlfd_runner::Chapter;
    let readme = fs::read_to_string(root().join("README.md")).unwrap().replace('\n', " ");
    let axes = [
        ch3_interactive_rl::Ch3::readings(),
        ch4_dbug_study::Ch4::readings(),
        ch5_hat_keepaway::Ch5::readings(),
        ch6_irl_shaping::Ch6::readings(),
    ];
    let mut missing = Vec::new();
    for axis in axes.into_iter().flatten() {
        let name = format!("`{}`", axis.name());
        let Some(at) = readme.find(&name) else {
            missing.push(format!("{name} is not in the README"));
            continue;
        };
        let entry = &readme[at..];
        // The entry ends at the parenthesis that closes it: one followed by
        // a comma or a full stop (a formula's parentheses are not).
        let end = [entry.find("), "), entry.find(").")].into_iter().flatten().min().unwrap_or(entry.len());
        let entry = &entry[..end];
        for level in axis.level_names() {
            if !entry.contains(level) {
                missing.push(format!("{name}'s level {level} is not in its README entry"));
            }
        }
    }
    assert!(missing.is_empty(), "{missing:#?}");
}
