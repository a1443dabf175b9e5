//! Computes the code fingerprint this chapter's stored results carry; the
//! rules (what is hashed, what is left out and why) are in
//! `chapters/code_fingerprint.rs`, shared by every chapter.

include!("../code_fingerprint.rs");

fn main() {
    println!("cargo:rerun-if-changed=../code_fingerprint.rs");
    emit_code_fingerprint();
}
