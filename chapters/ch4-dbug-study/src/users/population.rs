//! The 31 participants of one study: who has which expertise and in which
//! order they used the three algorithms (section 4.3).
//!
//! "Six of the participants self-identified as an expert roboticist, while
//! 14 were novice and 11 had no robotics background"; the orders were
//! "Int-RL/BNets/CBA (10 participants), BNets/CBA/Int-RL (10 participants),
//! and CBA/Int-RL/BNets (11 participants)". The thesis does not say how
//! expertise fell across the orders; here the study's expertise list is
//! shuffled with the study's own seed and participant `k` takes the `k`-th
//! entry, the first ten the first order, the next ten the second, the last
//! eleven the third.

use rand::Rng;
use rlfd_rl::random::shuffle;
use serde::{Deserialize, Serialize};

use super::traits::Expertise;

/// The three algorithms of the study.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Algorithm {
    /// Interactive Reinforcement Learning.
    IntRl,
    /// Behavior Networks.
    BNets,
    /// Confidence-Based Autonomy.
    Cba,
}

impl Algorithm {
    /// In the thesis's figure order.
    pub const ALL: [Algorithm; 3] = [Algorithm::IntRl, Algorithm::BNets, Algorithm::Cba];

    /// The thesis's name.
    pub fn label(self) -> &'static str {
        match self {
            Algorithm::IntRl => "Int-RL",
            Algorithm::BNets => "BNets",
            Algorithm::Cba => "CBA",
        }
    }

    /// The key in `thesis-numbers.toml` and CSV files.
    pub fn key(self) -> &'static str {
        match self {
            Algorithm::IntRl => "intrl",
            Algorithm::BNets => "bnets",
            Algorithm::Cba => "cba",
        }
    }

    /// Index `0..3` in [`Algorithm::ALL`].
    pub fn index(self) -> usize {
        match self {
            Algorithm::IntRl => 0,
            Algorithm::BNets => 1,
            Algorithm::Cba => 2,
        }
    }
}

/// The three orders and how many participants used each.
pub const ORDERS: [([Algorithm; 3], usize); 3] = [
    ([Algorithm::IntRl, Algorithm::BNets, Algorithm::Cba], 10),
    ([Algorithm::BNets, Algorithm::Cba, Algorithm::IntRl], 10),
    ([Algorithm::Cba, Algorithm::IntRl, Algorithm::BNets], 11),
];

/// Participants per expertise, in [`Expertise::ALL`] order.
pub const EXPERTISE_COUNTS: [usize; 3] = [6, 14, 11];

/// Participants in a study.
pub const PARTICIPANTS: usize = 31;

/// A study's roster: expertise and order per participant.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Roster {
    pub expertise: Vec<Expertise>,
    pub orders: Vec<[Algorithm; 3]>,
}

impl Roster {
    /// Draws a study's roster.
    pub fn draw<R: Rng + ?Sized>(rng: &mut R) -> Roster {
        let mut expertise: Vec<Expertise> =
            Expertise::ALL.iter().zip(EXPERTISE_COUNTS).flat_map(|(&e, n)| std::iter::repeat_n(e, n)).collect();
        shuffle(&mut expertise, rng);
        let orders = ORDERS.iter().flat_map(|&(o, n)| std::iter::repeat_n(o, n)).collect();
        Roster { expertise, orders }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn the_roster_has_the_thesis_counts() {
        let r = Roster::draw(&mut seeded(4));
        assert_eq!(r.expertise.len(), PARTICIPANTS);
        for (e, n) in Expertise::ALL.iter().zip(EXPERTISE_COUNTS) {
            assert_eq!(r.expertise.iter().filter(|&&x| x == *e).count(), n);
        }
        assert_eq!(r.orders.iter().filter(|o| o[0] == Algorithm::IntRl).count(), 10);
        assert_eq!(r.orders.iter().filter(|o| o[0] == Algorithm::BNets).count(), 10);
        assert_eq!(r.orders.iter().filter(|o| o[0] == Algorithm::Cba).count(), 11);
        assert_ne!(r, Roster::draw(&mut seeded(5)), "another seed, another shuffle");
    }
}
