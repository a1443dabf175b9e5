//! [`JavaRandom`], a clone of `java.util.Random`: the 48-bit linear
//! congruential generator of the Java API documentation, with `setSeed`,
//! `nextInt()` and `nextInt(bound)`, the only draws Weka's JRip and
//! `Evaluation.crossValidateModel` make.
//!
//! What it is: the generator behind [`RipperRandom::Weka`](super::RipperRandom::Weka).
//! Seeded with Weka's seed, RIPPER makes exactly the draws Weka 3.6 makes,
//! so it prints Weka's rules; [`JavaRandom::for_instances`] seeds it as JRip
//! does (`Instances.getRandomNumberGenerator`, in `weka_seed.rs`).
//!
//! What it is not: a general-purpose or a good generator (Java's LCG has
//! short low-bit periods); use it to reproduce Weka, nothing else. Only the
//! draws Weka's RIPPER path makes are cloned (no `nextDouble`, no
//! `nextGaussian`).
//!
//! Source: the algorithm specified in the Java SE documentation of
//! `java.util.Random` (`Random(long)`, `setSeed`, `next`, `nextInt`,
//! `nextInt(int)`), checked against values printed by OpenJDK 17.

use super::table::JripRandom;

const MULTIPLIER: u64 = 0x5_DEEC_E66D;
const INCREMENT: u64 = 0xB;
const MASK: u64 = (1 << 48) - 1;

/// `java.util.Random`: see the module docs.
///
/// ```
/// use rlfd_lfd::ripper::JavaRandom;
///
/// // Java: new Random(42).nextInt() == -1170105035
/// assert_eq!(JavaRandom::new(42).next_int(), -1_170_105_035);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct JavaRandom {
    state: u64,
}

impl JavaRandom {
    /// `new Random(seed)`.
    pub fn new(seed: i64) -> Self {
        Self { state: scramble(seed) }
    }

    /// `setSeed(seed)`: the state `new Random(seed)` starts from.
    pub fn set_seed(&mut self, seed: i64) {
        self.state = scramble(seed);
    }

    fn next(&mut self, bits: u32) -> i32 {
        self.state = self.state.wrapping_mul(MULTIPLIER).wrapping_add(INCREMENT) & MASK;
        (self.state >> (48 - bits)) as u32 as i32
    }

    /// `nextInt()`: a uniform `int`.
    pub fn next_int(&mut self) -> i32 {
        self.next(32)
    }

    /// `nextInt(bound)`: a uniform value in `0..bound`.
    ///
    /// # Panics
    /// If `bound <= 0` (Java throws `IllegalArgumentException`).
    pub fn next_int_below(&mut self, bound: i32) -> i32 {
        assert!(bound > 0, "java.util.Random.nextInt(bound) needs a positive bound, got {bound}");
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

/// `Random.initialScramble`.
fn scramble(seed: i64) -> u64 {
    (seed as u64 ^ MULTIPLIER) & MASK
}

impl JripRandom for JavaRandom {
    fn below(&mut self, bound: usize) -> usize {
        let bound = i32::try_from(bound).expect("Weka indexes instances with a Java int");
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

    #[test]
    fn set_seed_restarts_the_stream() {
        let mut r = JavaRandom::new(7);
        r.next_int();
        r.set_seed(42);
        assert_eq!(r, JavaRandom::new(42));
    }
}
