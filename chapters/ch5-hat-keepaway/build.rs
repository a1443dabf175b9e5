//! Computes the code fingerprint of the chapter's results: a hash of every
//! source file that can change what a trial computes (this crate's `src/`
//! and the `src/` of the library crates it runs on, plus `Cargo.lock`).
//! Stored results carry it, so results made by other code are never reused
//! silently. Report-only code (`rlfd-report` and this crate's `src/report/`)
//! is left out on purpose: a change of layout re-renders reports without
//! rerunning trials.

use std::fs;
use std::path::{Path, PathBuf};

const SOURCES: [&str; 5] = [
    "src",
    "../../crates/rlfd-rl/src",
    "../../crates/rlfd-lfd/src",
    "../../crates/rlfd-stats/src",
    "../../crates/rlfd-harness/src",
];

/// Directories whose code only renders reports.
const REPORT_ONLY: [&str; 1] = ["src/report"];

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        if REPORT_ONLY.iter().any(|r| path == Path::new(r)) {
            continue;
        }
        if path.is_dir() {
            collect(&path, out);
        } else {
            out.push(path);
        }
    }
}

fn main() {
    let mut files = Vec::new();
    for dir in SOURCES {
        println!("cargo:rerun-if-changed={dir}");
        collect(Path::new(dir), &mut files);
    }
    files.push(PathBuf::from("../../Cargo.lock"));
    println!("cargo:rerun-if-changed=../../Cargo.lock");
    files.sort();
    // FNV-1a 64 over each path and its contents, in sorted order.
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut feed = |bytes: &[u8]| {
        for &b in bytes {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
    };
    for f in &files {
        feed(f.to_string_lossy().replace('\\', "/").as_bytes());
        feed(&[0xff]);
        feed(&fs::read(f).unwrap_or_default());
        feed(&[0xff]);
    }
    println!("cargo:rustc-env=RLFD_CODE_FINGERPRINT={h:016x}");
}
