//! Rules of the architecture, checked as tests (see ARCHITECTURE.md):
//! the dependency direction between crates (read from the manifests with
//! the `toml` crate), domains that never import agents, cores that never
//! read the clock or an unseeded generator, transcendental functions only
//! through `libm`, and the `//!` header every source file opens with.

use std::fs;
use std::path::{Path, PathBuf};

#[path = "tidy/module_graph.rs"]
mod module_graph;

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

/// The domains a chapter declares in its manifest,
/// `[package.metadata.rlfd] domains = ["maze", …]` (module paths, `::`-separated).
fn declared_domains(manifest: &Path) -> Vec<Vec<String>> {
    let table: toml::Table = fs::read_to_string(manifest).unwrap().parse().unwrap();
    let list = table
        .get("package")
        .and_then(|p| p.get("metadata"))
        .and_then(|m| m.get("rlfd"))
        .and_then(|r| r.get("domains"))
        .and_then(|d| d.as_array())
        .unwrap_or_else(|| panic!("{}: no [package.metadata.rlfd] domains list", manifest.display()));
    list.iter().map(|d| d.as_str().unwrap().split("::").map(str::to_string).collect()).collect()
}

/// What a simulator may name from the learning crates: the environment
/// interface, the seeded generator, and the demonstration format its
/// demonstrators record in. Never a learner, a shaping, a feature map, RIPPER
/// or an IRL fit.
const DOMAIN_MAY_NAME: [&[&str]; 5] = [
    &["rlfd_rl", "Environment"],
    &["rlfd_rl", "Step"],
    &["rlfd_rl", "environment"],
    &["rlfd_rl", "random"],
    &["rlfd_lfd", "demonstration"],
];

/// Where a chapter crate's domains name what they may not: (violations,
/// domain modules checked). See [`domains_never_import_agents`].
fn domain_violations(name: &str, dir: &Path) -> (Vec<String>, usize) {
    let mut bad = Vec::new();
    let mut checked = 0;
    let domains = declared_domains(&dir.join("Cargo.toml"));
    let graph = module_graph::parse_crate(&dir.join("src/lib.rs"));
    let in_domain = |m: &[String]| domains.iter().any(|d| m.starts_with(d));
    let label = |p: &[String]| p.join("::");
    for d in &domains {
        if !graph.contains_key(d) {
            bad.push(format!("{name}: declared domain {} is not a module", label(d)));
        }
    }
    for (module, m) in &graph {
        if m.implements.iter().any(|t| t.last().is_some_and(|l| l == "Environment")) && !in_domain(module) {
            bad.push(format!(
                "{name}: {} implements Environment but is not a declared domain (package.metadata.rlfd.domains)",
                label(module)
            ));
        }
        if !in_domain(module) {
            continue;
        }
        checked += 1;
        for n in &m.names {
            // A relative path through a child module (`env::Move`).
            let child = |first: &String| graph.contains_key(&[module.clone(), vec![first.clone()]].concat());
            let n: Vec<String> = match n.first() {
                Some(first) if first != "crate" && child(first) => {
                    [vec!["crate".to_string()], module.clone(), n.clone()].concat()
                }
                _ => n.clone(),
            };
            match n.first().map(String::as_str) {
                Some("crate") => {
                    let path = &n[1..];
                    // The longest module prefix of the path.
                    let target = (0..=path.len()).rev().map(|k| &path[..k]).find(|p| graph.contains_key(*p)).unwrap();
                    if !target.is_empty() && !in_domain(target) {
                        bad.push(format!("{}: {} names crate::{}", m.file.display(), label(module), label(path)));
                    }
                }
                Some("rlfd_rl" | "rlfd_lfd")
                    if !DOMAIN_MAY_NAME
                        .iter()
                        .any(|ok| n.len() >= ok.len() && n.iter().zip(*ok).all(|(a, b)| a == b)) =>
                {
                    bad.push(format!("{}: {} names {}", m.file.display(), label(module), label(&n)));
                }
                _ => {}
            }
        }
    }
    bad.dedup();
    (bad, checked)
}

#[test]
fn domains_never_import_agents() {
    // Parsed, not matched as text: every chapter's module graph
    // (module_graph.rs), every path each module's non-test code names,
    // resolved. A domain (a simulator with its perception and its synthetic
    // humans) is a module the chapter declares in its manifest; any module
    // that implements `Environment` must lie inside one, so a new simulator
    // cannot escape the rule. A domain names only other domain modules of its
    // crate (or the crate root's items) and, of the learning crates, only
    // what DOMAIN_MAY_NAME lists.
    let mut bad = Vec::new();
    let mut checked = 0;
    for (name, dir) in crates() {
        if name.starts_with("ch") {
            let (b, c) = domain_violations(&name, &dir);
            bad.extend(b);
            checked += c;
        }
    }
    assert!(checked >= 5, "the rule checked only {checked} domain modules: the graph was not read");
    assert!(bad.is_empty(), "{bad:#?}");
}

#[test]
fn the_domain_rule_finds_every_kind_of_breach() {
    // A fixture crate whose domain breaks the rule in each way the graph
    // must see: a use of an agent module, a path in an expression through
    // `super::`, a renamed import of a learner, a path inside a macro, a
    // child-relative path, and an Environment implemented outside a domain.
    let dir = root().join("xtask/tests/tidy/fixture");
    let (bad, checked) = domain_violations("fixture", &dir);
    let found = |s: &str| bad.iter().any(|b| b.contains(s));
    assert_eq!(checked, 2, "{bad:#?}");
    for needle in [
        "sim names crate::agent::Learner",
        "sim names crate::agent::step",
        "sim names rlfd_rl::SarsaLambda",
        "sim names rlfd_lfd::ripper::Ripper",
        "sim::inner names crate::agent::Learner",
        "rogue implements Environment but is not a declared domain",
    ] {
        assert!(found(needle), "missed {needle:?} in {bad:#?}");
    }
    assert_eq!(bad.len(), 6, "{bad:#?}");
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
