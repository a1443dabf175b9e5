// The code fingerprint of a chapter's results, shared by every chapter's
// `build.rs` through `include!` (a file, not a crate: a new workspace crate
// would change `Cargo.lock`, which the fingerprint itself hashes).
//
// It is a hash of every source file that can change what a trial computes:
// the chapter's `src/` and the `src/` of the library crates it runs on, plus
// `Cargo.lock`. Stored results carry it, so results made by other code are
// never reused silently. Report-only code (`rlfd-report` and the chapter's
// `src/report/`) is left out on purpose: a change of layout re-renders
// reports without rerunning trials. A build script runs in its crate's
// directory, so the paths are relative to the chapter crate.

/// Every directory hashed, relative to a chapter crate.
const FINGERPRINT_SOURCES: [&str; 5] = [
    "src",
    "../../crates/rlfd-rl/src",
    "../../crates/rlfd-lfd/src",
    "../../crates/rlfd-stats/src",
    "../../crates/rlfd-harness/src",
];

/// Directories whose code only renders reports.
const REPORT_ONLY: [&str; 1] = ["src/report"];

fn collect(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        if REPORT_ONLY.iter().any(|r| path == std::path::Path::new(r)) {
            continue;
        }
        if path.is_dir() {
            collect(&path, out);
        } else {
            out.push(path);
        }
    }
}

/// Hashes the sources (FNV-1a 64 over each path and its contents, in sorted
/// order), tells cargo when to rerun, and sets `RLFD_CODE_FINGERPRINT`.
fn emit_code_fingerprint() {
    let mut files = Vec::new();
    for dir in FINGERPRINT_SOURCES {
        println!("cargo:rerun-if-changed={dir}");
        collect(std::path::Path::new(dir), &mut files);
    }
    files.push(std::path::PathBuf::from("../../Cargo.lock"));
    println!("cargo:rerun-if-changed=../../Cargo.lock");
    files.sort();
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
        feed(&std::fs::read(f).unwrap_or_default());
        feed(&[0xff]);
    }
    println!("cargo:rustc-env=RLFD_CODE_FINGERPRINT={h:016x}");
}
