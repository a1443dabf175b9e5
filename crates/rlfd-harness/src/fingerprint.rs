//! Fingerprints: a stable 64-bit hash of whatever determines a trial's
//! result (its parameters, its inputs, the code), so that a stored result is
//! reused only by the same computation.
//!
//! The hash is FNV-1a 64 (offset basis 0xcbf29ce484222325, prime
//! 0x100000001b3) over the bytes fed in, finished with the SplitMix64 mixer;
//! it is written here rather than taken from `std`'s `DefaultHasher`, whose
//! output may change between Rust releases.

use std::fmt;

/// An accumulating fingerprint.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Fingerprint(u64);

impl Fingerprint {
    /// The empty fingerprint.
    pub const fn new() -> Self {
        Fingerprint(0xcbf2_9ce4_8422_2325)
    }

    /// Feeds bytes.
    pub fn bytes(mut self, bytes: &[u8]) -> Self {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
        self
    }

    /// Feeds a string and a separator (so that "ab" + "c" differs from "a" + "bc").
    pub fn str(self, s: &str) -> Self {
        self.bytes(s.as_bytes()).bytes(&[0xff])
    }

    /// Feeds a number.
    pub fn u64(self, v: u64) -> Self {
        self.bytes(&v.to_le_bytes())
    }

    /// The mixed 64-bit value.
    pub fn value(&self) -> u64 {
        crate::seed::splitmix64(self.0)
    }

    /// As 16 lower-case hex digits.
    pub fn hex(&self) -> String {
        format!("{:016x}", self.value())
    }
}

impl Default for Fingerprint {
    fn default() -> Self {
        Self::new()
    }
}

impl fmt::Display for Fingerprint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.hex())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_values_and_separation() {
        // FNV-1a of the empty input is the offset basis; pin the mixed value.
        assert_eq!(Fingerprint::new().hex(), format!("{:016x}", crate::seed::splitmix64(0xcbf2_9ce4_8422_2325)));
        // FNV-1a 64 of "a" is 0xaf63dc4c8601ec8c (the published test vector).
        assert_eq!(Fingerprint::new().bytes(b"a").0, 0xaf63_dc4c_8601_ec8c);
        assert_ne!(Fingerprint::new().str("ab").str("c"), Fingerprint::new().str("a").str("bc"));
    }
}
