// The build identity of a chapter's stored trials, shared by every chapter's
// `build.rs` through `include!`.
//
// A stored trial is keyed on what determines its result: its parameters and
// inputs, its experiment's declared behaviour version (see
// `rlfd_harness::experiments!`), and this build identity: the rustc release
// and the exact versions of the crates in the chapter's dependency closure.
// Source text is not part of it: comments, tests, report code, xtask and
// crates the chapter does not depend on never invalidate a trial. A change to
// what an experiment computes bumps that experiment's behaviour version; the
// golden record digests (`golden/records.tsv`) catch a forgotten bump.
//
// The closure is read from the manifests and `Cargo.lock`: the chapter's
// normal `[dependencies]` (not dev- or build-dependencies), followed through
// workspace members' manifests and through the lock file's entries for
// registry crates. `rlfd-report` and what only it pulls in are left out: it
// renders reports and never computes a trial. A build script runs in its
// crate's directory, so the paths are relative to the chapter crate.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Workspace crates that never compute a trial's result.
const REPORT_ONLY_CRATES: [&str; 1] = ["rlfd-report"];

fn read_toml(path: &Path) -> toml::Table {
    println!("cargo:rerun-if-changed={}", path.display());
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    text.parse::<toml::Table>().unwrap_or_else(|e| panic!("{} is not TOML: {e}", path.display()))
}

/// The names of a manifest's normal dependencies.
fn normal_dependencies(manifest: &toml::Table) -> Vec<String> {
    manifest.get("dependencies").and_then(|d| d.as_table()).map(|d| d.keys().cloned().collect()).unwrap_or_default()
}

/// `name version` of every crate this chapter's results can depend on, sorted.
fn dependency_closure(root: &Path) -> Vec<String> {
    let workspace = read_toml(&root.join("Cargo.toml"));
    let members: BTreeMap<String, PathBuf> = workspace["workspace"]["dependencies"]
        .as_table()
        .expect("[workspace.dependencies] is a table")
        .iter()
        .filter_map(|(name, spec)| spec.get("path").and_then(|p| p.as_str()).map(|p| (name.clone(), root.join(p))))
        .collect();
    let lock = read_toml(&root.join("Cargo.lock"));
    // (name, version) -> its dependencies as the lock file writes them.
    let mut packages: BTreeMap<(String, String), Vec<String>> = BTreeMap::new();
    for p in lock["package"].as_array().expect("Cargo.lock lists packages") {
        let name = p["name"].as_str().expect("a package has a name").to_string();
        let version = p["version"].as_str().expect("a package has a version").to_string();
        let deps = p
            .get("dependencies")
            .and_then(|d| d.as_array())
            .map(|d| d.iter().filter_map(|x| x.as_str().map(String::from)).collect())
            .unwrap_or_default();
        packages.insert((name, version), deps);
    }
    // A lock entry "name", "name version" or "name version (source)".
    let resolve = |entry: &str| -> (String, String) {
        let mut parts = entry.split(' ');
        let name = parts.next().unwrap_or_default().to_string();
        match parts.next() {
            Some(v) => (name, v.to_string()),
            None => packages
                .keys()
                .find(|(n, _)| *n == name)
                .cloned()
                .unwrap_or_else(|| panic!("Cargo.lock has no package {name}")),
        }
    };
    let chapter = read_toml(Path::new("Cargo.toml"));
    let mut todo: Vec<(String, String)> = Vec::new();
    let mut seen: BTreeSet<(String, String)> = BTreeSet::new();
    let add_member_deps = |manifest: &toml::Table, todo: &mut Vec<(String, String)>, own: &str| {
        let own_entry = packages.keys().find(|(n, _)| n == own).cloned().expect("the member is in Cargo.lock");
        for name in normal_dependencies(manifest) {
            if REPORT_ONLY_CRATES.contains(&name.as_str()) {
                continue;
            }
            let entry = packages[&own_entry]
                .iter()
                .find(|e| e.split(' ').next() == Some(name.as_str()))
                .unwrap_or_else(|| panic!("Cargo.lock lists no {name} for {own}"));
            todo.push(resolve(entry));
        }
    };
    let own = chapter["package"]["name"].as_str().expect("the chapter has a name").to_string();
    add_member_deps(&chapter, &mut todo, &own);
    while let Some(package) = todo.pop() {
        if !seen.insert(package.clone()) {
            continue;
        }
        if let Some(path) = members.get(&package.0) {
            let manifest = read_toml(&path.join("Cargo.toml"));
            add_member_deps(&manifest, &mut todo, &package.0);
        } else {
            for entry in &packages[&package] {
                todo.push(resolve(entry));
            }
        }
    }
    seen.into_iter().map(|(n, v)| format!("{n} {v}")).collect()
}

/// The compiler's release line, e.g. `rustc 1.95.0 (59807616e 2026-04-14)`.
fn rustc_release() -> String {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let out = std::process::Command::new(&rustc).arg("--version").output().expect("rustc --version runs");
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

/// Sets `RLFD_BUILD_IDENTITY` (`<rustc release>; <n> crates <FNV-1a 64 of the
/// closure>`) and writes the closure, one crate a line, to
/// `$OUT_DIR/dependency_closure.txt` for `RLFD_DEPENDENCY_CLOSURE`.
fn emit_build_identity() {
    let closure = dependency_closure(Path::new("../.."));
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for line in &closure {
        for &b in line.as_bytes().iter().chain(b"\n") {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    let list = out.join("dependency_closure.txt");
    std::fs::write(&list, closure.join("\n") + "\n").expect("OUT_DIR is writable");
    println!("cargo:rustc-env=RLFD_BUILD_IDENTITY={}; {} crates {h:016x}", rustc_release(), closure.len());
    println!("cargo:rustc-env=RLFD_DEPENDENCY_CLOSURE={}", list.display());
}
