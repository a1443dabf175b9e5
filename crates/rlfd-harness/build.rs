//! Sets `RLFD_BUILD_IDENTITY`: the rustc release and the versions of the
//! crates whose bits enter a trial, read from the workspace's `Cargo.lock`
//! (the rules and the allowlist are in `build_identity.rs`).

include!("build_identity.rs");

fn main() {
    let lock_path = std::path::Path::new("../../Cargo.lock");
    println!("cargo:rerun-if-changed=../../Cargo.lock");
    println!("cargo:rerun-if-changed=build_identity.rs");
    let lock = std::fs::read_to_string(lock_path).expect("the workspace's Cargo.lock is readable");
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let out = std::process::Command::new(&rustc).arg("--version").output().expect("rustc --version runs");
    let release = String::from_utf8_lossy(&out.stdout).trim().to_string();
    println!("cargo:rustc-env=RLFD_BUILD_IDENTITY={}", build_identity(&release, &lock));
}
