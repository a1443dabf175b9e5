//! Placeholder bench: this chapter is being built.

fn main() {}
