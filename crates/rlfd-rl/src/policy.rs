//! ε-greedy action selection with uniform random tie-breaking.
//!
//! The random stream is consumed in a fixed pattern: one uniform draw decides
//! between exploring and exploiting; exploring draws one action uniformly from
//! all actions; exploiting draws among the maximisers only when there is more
//! than one (exact ties, as when every value is still 0).

use rand::Rng;

use crate::random::{below, uniform01};

/// A greedy action of `values`, ties broken uniformly at random.
#[inline]
pub fn greedy<R: Rng + ?Sized>(values: &[f64], rng: &mut R) -> usize {
    // One pass finds the maximum, how many values reach it and where it
    // first occurs (NaN never does; a maximum of −∞ is found by `==`).
    let mut best = f64::NEG_INFINITY;
    let mut ties = 0usize;
    let mut first = usize::MAX;
    for (a, &v) in values.iter().enumerate() {
        if v > best {
            best = v;
            ties = 1;
            first = a;
        } else if v == best {
            ties += 1;
            if first == usize::MAX {
                first = a;
            }
        }
    }
    if ties <= 1 {
        // The first maximiser, or 0 when every value is NaN.
        return if first == usize::MAX { 0 } else { first };
    }
    let mut pick = below(rng, ties);
    for (a, &v) in values.iter().enumerate() {
        if v == best {
            if pick == 0 {
                return a;
            }
            pick -= 1;
        }
    }
    unreachable!("a tie was counted but not found")
}

#[inline]
fn first_max(values: &[f64], best: f64) -> usize {
    values.iter().position(|&v| v == best).unwrap_or(0)
}

/// ε-greedy: a uniformly random action with probability `epsilon`, else [`greedy`].
#[inline]
pub fn epsilon_greedy<R: Rng + ?Sized>(values: &[f64], epsilon: f64, rng: &mut R) -> usize {
    if uniform01(rng) < epsilon { below(rng, values.len()) } else { greedy(values, rng) }
}

/// Whether `action` is one of the maximisers of `values`.
#[inline]
pub fn is_greedy(values: &[f64], action: usize) -> bool {
    let best = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    values[action] == best
}

/// The greedy action, preferring `preferred` when it ties for the maximum
/// (Watkins's Q(λ): an exploratory-looking tie does not cut the traces).
#[inline]
pub fn greedy_preferring(values: &[f64], preferred: usize) -> usize {
    if is_greedy(values, preferred) {
        preferred
    } else {
        let best = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        first_max(values, best)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::random::seeded;

    #[test]
    fn greedy_picks_the_maximum() {
        let mut rng = seeded(1);
        assert_eq!(greedy(&[0.0, 3.0, 1.0], &mut rng), 1);
        assert_eq!(greedy(&[-5.0, -3.0, -4.0], &mut rng), 1);
    }

    #[test]
    fn ties_are_broken_uniformly() {
        let mut rng = seeded(2);
        let mut counts = [0usize; 4];
        for _ in 0..40_000 {
            counts[greedy(&[1.0, 0.0, 1.0, 1.0], &mut rng)] += 1;
        }
        assert_eq!(counts[1], 0);
        for &c in &[counts[0], counts[2], counts[3]] {
            assert!((c as f64 - 40_000.0 / 3.0).abs() < 400.0, "{counts:?}");
        }
    }

    #[test]
    fn epsilon_explores_at_the_right_rate() {
        let mut rng = seeded(3);
        let n = 100_000;
        let non_greedy = (0..n).filter(|_| epsilon_greedy(&[0.0, 1.0, 0.0, 0.0], 0.2, &mut rng) != 1).count();
        // Exploration picks a non-greedy action 3/4 of the time: 0.2 * 0.75 = 0.15.
        assert!((non_greedy as f64 / n as f64 - 0.15).abs() < 0.005);
    }

    /// [`greedy`] as first written: the maximum, then its first position.
    fn greedy_reference<R: Rng + ?Sized>(values: &[f64], rng: &mut R) -> usize {
        let mut best = f64::NEG_INFINITY;
        let mut ties = 0usize;
        for &v in values {
            if v > best {
                best = v;
                ties = 1;
            } else if v == best {
                ties += 1;
            }
        }
        if ties <= 1 {
            return first_max(values, best);
        }
        let mut pick = below(rng, ties);
        for (a, &v) in values.iter().enumerate() {
            if v == best {
                if pick == 0 {
                    return a;
                }
                pick -= 1;
            }
        }
        unreachable!()
    }

    use proptest::prelude::*;

    proptest! {
        // The one-pass greedy picks what the reference picks, drawing the same numbers.
        #[test]
        fn greedy_equals_the_reference(
            values in proptest::collection::vec(prop_oneof![
                (-3i32..3).prop_map(f64::from),
                Just(f64::NAN),
                Just(f64::NEG_INFINITY),
                Just(f64::INFINITY),
            ], 1..13),
            seed in 0u64..1000,
        ) {
            let (mut a, mut b) = (seeded(seed), seeded(seed));
            prop_assert_eq!(greedy(&values, &mut a), greedy_reference(&values, &mut b));
            prop_assert_eq!(uniform01(&mut a).to_bits(), uniform01(&mut b).to_bits());
        }
    }

    #[test]
    fn greedy_preferring_keeps_a_tied_choice() {
        assert_eq!(greedy_preferring(&[1.0, 2.0, 2.0], 2), 2);
        assert_eq!(greedy_preferring(&[1.0, 2.0, 2.0], 0), 1);
        assert!(is_greedy(&[1.0, 2.0, 2.0], 1));
        assert!(!is_greedy(&[1.0, 2.0, 2.0], 0));
    }
}
