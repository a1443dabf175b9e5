// The build identity every stored trial carries: the rustc release and the
// exact versions of an explicit allowlist of the crates whose code computes
// a trial's result or the bytes of its record.
//
// This file is the one place the identity is computed: `build.rs` includes
// it to set `RLFD_BUILD_IDENTITY` from the workspace's `Cargo.lock` and the
// compiler, and the crate compiles it as a module so tests can feed it
// other lock files. It reads the lock by crate name only, never its
// dependency lists: those hold optional dependencies that are never
// compiled (statrs's disabled nalgebra once moved every chapter's identity
// through a report-only crate) and the dependencies of other platforms.
//
// Everything else a trial runs is the workspace's own code, covered by the
// experiments' behaviour versions (bumped with any change that moves a
// result, and checked by the golden record digests). A crate that starts to
// compute something a trial's result depends on joins [`RESULT_CRATES`] in
// the same commit.

/// The crates whose bits enter a trial, with why.
///
/// - `rand`, `rand_core`: how a float or a range is drawn from the stream,
///   and `seed_from_u64`'s expansion of a trial's seed (in `rand_core`);
/// - `rand_chacha`, `ppv-lite86`: the ChaCha8 stream itself (its rounds are
///   computed in `ppv-lite86`);
/// - `libm`: every transcendental function of the simulators and learners
///   (the reason it is used instead of the platform's);
/// - `serde_json`, `zmij`, `itoa`: the record's bytes (numbers written as
///   the shortest text that reads back to the same value: `zmij` writes
///   floats, `itoa` integers), which `verify` compares byte for byte.
///
/// Not in it, on purpose: the statistics (`rlfd-stats`, `statrs`: reports
/// only), the renderers, the command line, `rayon` (results are gathered in
/// trial order whatever the threads do), `serde` (its data model fixes the
/// shape of a record by our types, not by its version), `csv` (a user's
/// demonstration file enters a trial by the digest of its contents).
pub const RESULT_CRATES: [&str; 8] =
    ["itoa", "libm", "ppv-lite86", "rand", "rand_chacha", "rand_core", "serde_json", "zmij"];

/// `name version` of each allowlisted crate the lock file holds (every
/// version of it, sorted), from `[[package]]` entries' `name` and `version`
/// lines.
pub fn result_crate_versions(lock: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut name: Option<&str> = None;
    for line in lock.lines() {
        let line = line.trim();
        if line == "[[package]]" {
            name = None;
        } else if let Some(v) = line.strip_prefix("name = ") {
            name = Some(v.trim_matches('"'));
        } else if let Some(v) = line.strip_prefix("version = ")
            && let Some(n) = name.take()
            && RESULT_CRATES.contains(&n)
        {
            out.push(format!("{n} {}", v.trim_matches('"')));
        }
    }
    out.sort();
    out.dedup();
    out
}

/// The identity: `<rustc release>; <name version>; …`.
pub fn build_identity(rustc_release: &str, lock: &str) -> String {
    let mut parts = vec![rustc_release.trim().to_string()];
    parts.extend(result_crate_versions(lock));
    parts.join("; ")
}
