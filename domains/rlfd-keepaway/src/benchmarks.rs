//! The keepaway benchmark's three fixed keeper policies (`HandCodedAgent.cc`
//! of the UT-Austin players; `domains.md` 1.6), used to validate the
//! simulator against the real server with the same players:
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
use rlfd_env::random::below;
use serde::{Deserialize, Serialize};

use crate::{KeeperAction, STATE_VARS};

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

    /// The action in a 3 vs 2 state (one uniform draw for Random, none otherwise).
    pub fn choose<R: Rng + ?Sized>(self, state: &[f64; STATE_VARS], rng: &mut R) -> KeeperAction {
        self.choose_in(state, 3, 2, rng)
    }

    /// The action with `keepers` keepers and `takers` takers (`state` holds
    /// their `4 K + 2 T − 3` variables): Random draws uniformly over the `K`
    /// actions (`rand() % numActions`).
    pub fn choose_in<R: Rng + ?Sized>(self, state: &[f64], keepers: usize, takers: usize, rng: &mut R) -> KeeperAction {
        match self {
            BenchmarkPolicy::AlwaysHold => KeeperAction::HOLD,
            BenchmarkPolicy::Random => KeeperAction(below(rng, keepers) as u8),
            BenchmarkPolicy::HandCoded => hand_coded_in(state, keepers, takers),
        }
    }
}

/// The hand-coded policy of Stone, Sutton & Kuhlmann (2005) on the 13 state variables.
pub fn hand_coded(state: &[f64; STATE_VARS]) -> KeeperAction {
    hand_coded_in(state, 3, 2)
}

/// The hand-coded policy with `keepers` and `takers` (`HandCodedAgent::handCoded`):
/// hold when the nearest taker is more than 5 m away; otherwise score Hold
/// 90 and teammate `i` `4 · (its distance to its nearest taker) + (its
/// smallest angle to a taker at the holder, degrees)` and take the best
/// (strictly better than the earlier ones).
pub fn hand_coded_in(state: &[f64], keepers: usize, takers: usize) -> KeeperAction {
    let mates = keepers - 1;
    // Layout: [C, K2..K_K, T1..T_T, K C, T C, K opp dist, K opp angle].
    let nearest_taker = state[1 + mates];
    if nearest_taker > 5.0 {
        return KeeperAction::HOLD;
    }
    let dist_at = 1 + mates + takers + mates + takers;
    let ang_at = dist_at + mates;
    let mut best = (0usize, 90.0);
    for i in 0..mates {
        let score = 4.0 * state[dist_at + i] + state[ang_at + i];
        if score > best.1 {
            best = (i + 1, score);
        }
    }
    KeeperAction(best.0 as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_coded_holds_when_free_and_passes_to_the_open_teammate() {
        let mut s = [0.0; STATE_VARS];
        s[3] = 6.0;
        s[9] = 100.0;
        assert_eq!(hand_coded(&s), KeeperAction::HOLD);
        s[3] = 4.0;
        // Pass1: 4·10 + 20 = 60 < 90; Pass2: 4·15 + 40 = 100 > 90.
        s[9] = 10.0;
        s[11] = 20.0;
        s[10] = 15.0;
        s[12] = 40.0;
        assert_eq!(hand_coded(&s), KeeperAction::PASS2);
        s[12] = 30.0; // exactly 90: the tie goes to Hold
        assert_eq!(hand_coded(&s), KeeperAction::HOLD);
    }
}
