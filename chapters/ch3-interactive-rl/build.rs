//! Computes the build identity this chapter's stored trials carry (the rustc
//! release and the versions of the crates the chapter's results depend on);
//! the rules are in `chapters/build_identity.rs`, shared by every chapter.

include!("../build_identity.rs");

fn main() {
    println!("cargo:rerun-if-changed=../build_identity.rs");
    emit_build_identity();
}
