//! The random-number conventions of the whole project.
//!
//! Every simulation draws from a [`SimRng`], a ChaCha8 generator seeded by the
//! harness from the trial's id, never from the OS or the clock. ChaCha's output
//! stream is specified (RFC 7539 core, 8 rounds), so the same seed gives the same
//! numbers on every platform. `rand` is pinned exactly in the workspace manifest
//! because a minor release may change how a float or a range is drawn; the tests
//! below pin the first values of every draw we use, so such a change fails loudly
//! instead of silently moving every golden file.
//!
//! Gaussian draws use the Marsaglia polar method with `libm`'s `log`, not
//! `rand_distr` (whose `Normal` goes through the platform's math library).

use rand::{Rng, RngExt, SeedableRng};

/// The generator every simulation and learner uses.
pub type SimRng = rand_chacha::ChaCha8Rng;

/// A generator seeded from a 64-bit seed (see `rlfd-harness` for how trial
/// seeds are derived).
pub fn seeded(seed: u64) -> SimRng {
    SimRng::seed_from_u64(seed)
}

/// A uniform draw in `[0, 1)` with 53 random bits.
#[inline]
pub fn uniform01<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    rng.random::<f64>()
}

/// A uniform integer in `0..n`. `n` must be positive.
#[inline]
pub fn below<R: Rng + ?Sized>(rng: &mut R, n: usize) -> usize {
    debug_assert!(n > 0, "below(0) has no value to return");
    rng.random_range(0..n)
}

/// `true` with probability `p`.
#[inline]
pub fn bernoulli<R: Rng + ?Sized>(rng: &mut R, p: f64) -> bool {
    uniform01(rng) < p
}

/// A standard normal draw (Marsaglia polar method, rejection on the unit disc).
///
/// One of the pair is discarded so the function is stateless; simulations are
/// not Gaussian-bound, and statelessness keeps every draw's position in the
/// stream obvious.
pub fn standard_normal<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    loop {
        let u = 2.0 * uniform01(rng) - 1.0;
        let v = 2.0 * uniform01(rng) - 1.0;
        let s = u * u + v * v;
        if s > 0.0 && s < 1.0 {
            return u * (-2.0 * libm::log(s) / s).sqrt();
        }
    }
}

/// Shuffles `items` in place (Fisher–Yates, from the back).
pub fn shuffle<T, R: Rng + ?Sized>(items: &mut [T], rng: &mut R) {
    for i in (1..items.len()).rev() {
        let j = below(rng, i + 1);
        items.swap(i, j);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // Value stability: these are the first draws of every kind we use, for a
    // fixed seed. If a dependency update changes any of them, every golden file
    // would change too; this test says why.
    #[test]
    fn draws_are_stable_across_releases() {
        let mut rng = seeded(42);
        let raw: Vec<u64> = (0..3).map(|_| rng.next_u64()).collect();
        let mut rng = seeded(42);
        let floats: Vec<f64> = (0..3).map(|_| uniform01(&mut rng)).collect();
        let mut rng = seeded(42);
        let ints: Vec<usize> = (0..6).map(|_| below(&mut rng, 7)).collect();
        let mut rng = seeded(42);
        let normals: Vec<f64> = (0..3).map(|_| standard_normal(&mut rng)).collect();
        let mut rng = seeded(42);
        let mut perm: Vec<u32> = (0..8).collect();
        shuffle(&mut perm, &mut rng);
        let got = format!("{raw:?}\n{floats:?}\n{ints:?}\n{normals:?}\n{perm:?}");
        let expected = include_str!("random_stability.txt");
        assert_eq!(got.trim(), expected.trim(), "the random stream changed:\n{got}");
    }

    #[test]
    fn uniform_is_in_unit_interval_and_below_in_range() {
        let mut rng = seeded(7);
        for _ in 0..10_000 {
            let u = uniform01(&mut rng);
            assert!((0.0..1.0).contains(&u));
            assert!(below(&mut rng, 3) < 3);
        }
    }

    #[test]
    fn standard_normal_has_unit_moments() {
        let mut rng = seeded(11);
        let n = 200_000;
        let xs: Vec<f64> = (0..n).map(|_| standard_normal(&mut rng)).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n - 1) as f64;
        assert!(mean.abs() < 0.01, "mean {mean}");
        assert!((var - 1.0).abs() < 0.01, "variance {var}");
    }

    #[test]
    fn shuffle_is_a_permutation() {
        let mut rng = seeded(3);
        let mut v: Vec<usize> = (0..100).collect();
        shuffle(&mut v, &mut rng);
        let mut sorted = v.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..100).collect::<Vec<_>>());
        assert_ne!(v, sorted);
    }
}
