//! A clone of `java.util.Random` (test support only): the 48-bit linear
//! congruential generator of the Java API documentation, with `nextInt()`
//! and `nextInt(bound)`. With it the learner makes exactly the draws Weka
//! makes, so `weka_check.rs` can compare rules with Weka's own.
//!
//! It is not used outside tests: the library draws from `ChaCha8Rng`.
//!
//! Source: the algorithm specified in the Java SE documentation of
//! `java.util.Random` (`setSeed`, `next`, `nextInt`, `nextInt(int)`).

use super::table::JripRandom;

const MULTIPLIER: u64 = 0x5_DEEC_E66D;
const INCREMENT: u64 = 0xB;
const MASK: u64 = (1 << 48) - 1;

#[derive(Debug, Clone)]
pub(crate) struct JavaRandom {
    state: u64,
}

impl JavaRandom {
    /// `new Random(seed)`.
    pub fn new(seed: i64) -> Self {
        Self { state: (seed as u64 ^ MULTIPLIER) & MASK }
    }

    fn next(&mut self, bits: u32) -> i32 {
        self.state = self.state.wrapping_mul(MULTIPLIER).wrapping_add(INCREMENT) & MASK;
        (self.state >> (48 - bits)) as u32 as i32
    }

    /// `nextInt()`.
    pub fn next_int(&mut self) -> i32 {
        self.next(32)
    }

    /// `nextInt(bound)`, bound > 0.
    pub fn next_int_below(&mut self, bound: i32) -> i32 {
        if bound & bound.wrapping_neg() == bound {
            return ((i64::from(bound) * i64::from(self.next(31))) >> 31) as i32;
        }
        loop {
            let bits = self.next(31);
            let value = bits % bound;
            // Java rejects the draws that would bias the modulo (int overflow)
            if bits.wrapping_sub(value).wrapping_add(bound - 1) >= 0 {
                return value;
            }
        }
    }
}

impl JripRandom for JavaRandom {
    fn below(&mut self, bound: usize) -> usize {
        let bound = i32::try_from(bound).expect("Java bounds are ints");
        self.next_int_below(bound) as usize
    }

    fn fork(&mut self) -> Self {
        // ClassOrder.setSeed((long) m_Random.nextInt()), then new Random(seed)
        Self::new(i64::from(self.next_int()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values printed by OpenJDK 17:
    /// `Random r = new Random(42); r.nextInt(), r.nextInt(10), r.nextInt(16),
    /// r.nextInt(1000000007), r.nextInt(3)` and
    /// `Random s = new Random(-2017380557L); s.nextInt(), s.nextInt(85), s.nextInt(2)`.
    #[test]
    fn matches_java_util_random() {
        let mut r = JavaRandom::new(42);
        assert_eq!(r.next_int(), -1_170_105_035);
        assert_eq!(r.next_int_below(10), 3);
        assert_eq!(r.next_int_below(16), 10);
        assert_eq!(r.next_int_below(1_000_000_007), 102_948_884);
        assert_eq!(r.next_int_below(3), 0);
        let mut s = JavaRandom::new(-2_017_380_557);
        assert_eq!(s.next_int(), -229_004_988);
        assert_eq!(s.next_int_below(85), 14);
        assert_eq!(s.next_int_below(2), 0);
    }
}
