//! Feature indices renumbered in the order the features are first seen.
//!
//! A hashed tile coder scatters the 32 tiles of a state over its whole table
//! (Mario's: 2^18 features × 12 actions × 8 bytes = 24 MiB of weights), so
//! every state visit touches 32 distant weight rows, and a new learner
//! touches every page of its table within a few episodes. [`FirstTouch`]
//! gives each feature, the first time it is active, the next free number:
//! the tiles of a new state get neighbouring rows, and the weights a trial
//! uses lie together at the front of the table.
//!
//! A learner cannot tell the difference. It only ever asks whether two
//! active features are the same feature (they share a weight, a trace), and
//! the renumbering is one-to-one, so every sum, trace and update is the same
//! number in the same order as without it. Only reading the weights by the
//! inner map's indices would see the renumbering.

use std::cell::RefCell;

use super::{ActiveFeatures, FeatureMap};

/// Not numbered yet (numbers are stored plus one, so that the table starts
/// as zeroed memory the system hands out lazily).
const NONE: u32 = 0;

/// `inner`'s features, numbered in order of first appearance.
#[derive(Clone, Debug)]
pub struct FirstTouch<F> {
    inner: F,
    numbering: RefCell<Numbering>,
}

#[derive(Clone, Debug)]
struct Numbering {
    /// The number given to each of the inner map's features plus one, or [`NONE`].
    number: Vec<u32>,
    /// Numbers given so far.
    given: u32,
}

impl<F: FeatureMap> FirstTouch<F> {
    /// Renumbers `inner`'s features (all unnumbered yet).
    ///
    /// # Panics
    /// If `inner` has `u32::MAX` features or more.
    pub fn new(inner: F) -> Self {
        let n = inner.num_features();
        assert!(n < u32::MAX as usize, "too many features to renumber in u32");
        FirstTouch { inner, numbering: RefCell::new(Numbering { number: vec![NONE; n], given: 0 }) }
    }

    /// The renumbered map.
    pub fn inner(&self) -> &F {
        &self.inner
    }

    /// Features numbered so far (each has a number below this).
    pub fn numbered(&self) -> usize {
        self.numbering.borrow().given as usize
    }
}

impl<F: FeatureMap> FeatureMap for FirstTouch<F> {
    fn num_features(&self) -> usize {
        self.inner.num_features()
    }

    fn max_active(&self) -> usize {
        self.inner.max_active()
    }

    #[inline]
    fn features(&self, state: &[f64], out: &mut ActiveFeatures) {
        self.inner.features(state, out);
        let Numbering { number, given } = &mut *self.numbering.borrow_mut();
        for k in out.indices.iter_mut() {
            let n = &mut number[*k as usize];
            if *n == NONE {
                *given += 1;
                *n = *given;
            }
            *k = *n - 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::features::{TileCoder, TileIndexing};
    use proptest::prelude::*;

    #[test]
    fn numbers_follow_first_appearance() {
        let coder = TileCoder::new(4, &[1.0, 1.0], TileIndexing::Hashed { size: 1 << 16 }).unwrap();
        let f = FirstTouch::new(coder);
        let mut out = ActiveFeatures::default();
        f.features(&[0.0, 0.0], &mut out);
        assert_eq!(out.indices, vec![0, 1, 2, 3]);
        f.features(&[0.0, 0.0], &mut out);
        assert_eq!(out.indices, vec![0, 1, 2, 3]);
        assert_eq!(f.numbered(), 4);
        assert_eq!(f.num_features(), 1 << 16);
    }

    proptest! {
        // A learner on the renumbered features learns the same values, bit
        // for bit, as one on the inner map's.
        #[test]
        fn a_learner_cannot_tell(
            steps in proptest::collection::vec((proptest::collection::vec(-3.0f64..3.0, 2), 0usize..3, -1.0f64..1.0), 2..80),
        ) {
            use crate::agent::TdControl;
            use crate::{TdParams, TraceKind, WatkinsQLambda};
            // A small table: tilings collide, so shared features are exercised.
            let coder = TileCoder::new(8, &[1.0, 1.0], TileIndexing::Hashed { size: 64 }).unwrap();
            let renumbered = FirstTouch::new(coder.clone());
            let params = TdParams { alpha: 0.1, gamma: 0.9, lambda: 0.8, epsilon: 0.1 };
            let mut plain = WatkinsQLambda::new(64, 3, params, TraceKind::Replacing);
            let mut moved = WatkinsQLambda::new(64, 3, params, TraceKind::Replacing).traces_by_generation();
            let (mut fa, mut fb, mut na, mut nb) =
                (ActiveFeatures::default(), ActiveFeatures::default(), ActiveFeatures::default(), ActiveFeatures::default());
            let (mut qa, mut qb) = ([0.0; 3], [0.0; 3]);
            coder.features(&steps[0].0, &mut fa);
            renumbered.features(&steps[0].0, &mut fb);
            for w in steps.windows(2) {
                let ((_, action, reward), (next, next_action, _)) = ((&w[0].0, w[0].1, w[0].2), (&w[1].0, w[1].1, w[1].2));
                coder.features(next, &mut na);
                renumbered.features(next, &mut nb);
                plain.action_values(&na, &mut qa);
                moved.action_values(&nb, &mut qb);
                prop_assert_eq!(qa.map(f64::to_bits), qb.map(f64::to_bits));
                let target = plain.target_action(next_action, &qa);
                plain.learn(&fa, action, reward, Some((&qa, target, next_action)));
                moved.learn(&fb, action, reward, Some((&qb, target, next_action)));
                std::mem::swap(&mut fa, &mut na);
                std::mem::swap(&mut fb, &mut nb);
            }
        }

        // The renumbering is one-to-one: two active features are equal
        // after it exactly when they were before, over any sequence of states.
        #[test]
        fn renumbering_keeps_which_features_are_equal(
            states in proptest::collection::vec(proptest::collection::vec(-5.0f64..5.0, 3), 1..60),
            log_size in 4u32..12,
        ) {
            let coder = TileCoder::new(8, &[1.0, 0.5, 2.0], TileIndexing::Hashed { size: 1 << log_size }).unwrap();
            let renumbered = FirstTouch::new(coder.clone());
            let (mut a, mut b) = (ActiveFeatures::default(), ActiveFeatures::default());
            let mut seen: Vec<(u32, u32)> = vec![];
            for s in &states {
                coder.features(s, &mut a);
                renumbered.features(s, &mut b);
                prop_assert_eq!(a.len(), b.len());
                for (&x, &y) in a.indices.iter().zip(&b.indices) {
                    prop_assert!((y as usize) < renumbered.numbered());
                    for &(p, q) in &seen {
                        prop_assert_eq!(p == x, q == y);
                    }
                    seen.push((x, y));
                }
            }
        }
    }
}
