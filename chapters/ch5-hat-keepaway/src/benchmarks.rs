//! The keepaway benchmark's three fixed keeper policies (`HandCodedAgent.cc`
//! of the UT-Austin players; `domains.md` 1.6), used to validate the
//! simulator against the published episode durations:
//!
//! - **Always Hold**: action 0 at every decision;
//! - **Random**: uniform over Hold, Pass1, Pass2 at every decision;
//! - **Hand-coded** (Stone, Sutton & Kuhlmann 2005): hold when the nearest
//!   taker is more than 5 m away; otherwise score Hold 90 and a pass to
//!   teammate `i` `4 · (its distance to the nearest taker, m) + (the
//!   smallest angle at the holder between it and a taker, degrees)`, and
//!   take the best (ties: the lower index, i.e. Hold).
//!
//! What it is not: a learner; they never change.

use rand::Rng;
use rlfd_rl::random::below;
use serde::{Deserialize, Serialize};

use crate::keepaway::{KeeperAction, STATE_VARS};

/// A benchmark policy.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum BenchmarkPolicy {
    /// Always Hold.
    AlwaysHold,
    /// Uniformly random.
    Random,
    /// The hand-coded policy of AB'05.
    HandCoded,
}

impl BenchmarkPolicy {
    /// In the published order (shortest to longest episodes).
    pub const ALL: [BenchmarkPolicy; 3] =
        [BenchmarkPolicy::AlwaysHold, BenchmarkPolicy::Random, BenchmarkPolicy::HandCoded];

    /// The condition name in result paths.
    pub fn slug(self) -> &'static str {
        match self {
            BenchmarkPolicy::AlwaysHold => "always-hold",
            BenchmarkPolicy::Random => "random",
            BenchmarkPolicy::HandCoded => "hand-coded",
        }
    }

    /// The name in tables.
    pub fn label(self) -> &'static str {
        match self {
            BenchmarkPolicy::AlwaysHold => "Always Hold",
            BenchmarkPolicy::Random => "Random",
            BenchmarkPolicy::HandCoded => "Hand-coded",
        }
    }

    /// The action in a state (one uniform draw for Random, none otherwise).
    pub fn choose<R: Rng + ?Sized>(self, state: &[f64; STATE_VARS], rng: &mut R) -> KeeperAction {
        match self {
            BenchmarkPolicy::AlwaysHold => KeeperAction::Hold,
            BenchmarkPolicy::Random => KeeperAction::ALL[below(rng, 3)],
            BenchmarkPolicy::HandCoded => hand_coded(state),
        }
    }
}

/// The hand-coded policy of Stone, Sutton & Kuhlmann (2005) on the 13 state variables.
pub fn hand_coded(state: &[f64; STATE_VARS]) -> KeeperAction {
    if state[3] > 5.0 {
        return KeeperAction::Hold;
    }
    let scores = [90.0, 4.0 * state[9] + state[11], 4.0 * state[10] + state[12]];
    let mut best = 0;
    for i in 1..3 {
        if scores[i] > scores[best] {
            best = i;
        }
    }
    KeeperAction::ALL[best]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_coded_holds_when_free_and_passes_to_the_open_teammate() {
        let mut s = [0.0; STATE_VARS];
        s[3] = 6.0;
        s[9] = 100.0;
        assert_eq!(hand_coded(&s), KeeperAction::Hold);
        s[3] = 4.0;
        // Pass1: 4·10 + 20 = 60 < 90; Pass2: 4·15 + 40 = 100 > 90.
        s[9] = 10.0;
        s[11] = 20.0;
        s[10] = 15.0;
        s[12] = 40.0;
        assert_eq!(hand_coded(&s), KeeperAction::Pass2);
        s[12] = 30.0; // exactly 90: the tie goes to Hold
        assert_eq!(hand_coded(&s), KeeperAction::Hold);
    }
}
