//! The keeper's macro-actions and the 13 state variables of 3 vs 2 Keepaway,
//! from the decision-maker's view, in the order of `WorldModel::keeperStateVars`
//! (Stone, Sutton & Kuhlmann 2005; `domains.md` 1.3).
//!
//! K1 is the keeper with the ball (the decision maker), K2 and K3 its
//! teammates sorted by distance to K1, T1 and T2 the takers sorted by
//! distance to K1, C the region's centre:
//!
//! | idx | variable | idx | variable |
//! |---|---|---|---|
//! | 0 | dist(K1, C) | 7 | dist(T1, C) |
//! | 1 | dist(K1, K2) | 8 | dist(T2, C) |
//! | 2 | dist(K1, K3) | 9 | min(dist(K2, T1), dist(K2, T2)) |
//! | 3 | dist(K1, T1) | 10 | min(dist(K3, T1), dist(K3, T2)) |
//! | 4 | dist(K1, T2) | 11 | min_j ang(K2, K1, Tj), degrees |
//! | 5 | dist(K2, C) | 12 | min_j ang(K3, K1, Tj), degrees |
//! | 6 | dist(K3, C) | | |
//!
//! Perception is exact here (the keepers of the benchmark see with noise
//! and share what they see): a documented deviation.

use serde::{Deserialize, Serialize};

use super::geometry::{Vec2, angle_between};

/// Number of state variables in 3 vs 2.
pub const STATE_VARS: usize = 13;

/// The state variables' names as the thesis prints them (`state_k`).
pub const STATE_NAMES: [&str; STATE_VARS] = [
    "state_0", "state_1", "state_2", "state_3", "state_4", "state_5", "state_6", "state_7", "state_8", "state_9",
    "state_10", "state_11", "state_12",
];

/// What each variable measures.
pub const STATE_MEANINGS: [&str; STATE_VARS] = [
    "dist(K1, C)",
    "dist(K1, K2)",
    "dist(K1, K3)",
    "dist(K1, T1)",
    "dist(K1, T2)",
    "dist(K2, C)",
    "dist(K3, C)",
    "dist(T1, C)",
    "dist(T2, C)",
    "min dist(K2, T)",
    "min dist(K3, T)",
    "min ang(K2, K1, T)",
    "min ang(K3, K1, T)",
];

/// The benchmark's tile widths per variable (m or degrees), from
/// `keeperStateRangesAndResolutions` with its integer divisions evaluated.
pub const TILE_WIDTHS: [f64; STATE_VARS] = [2.0, 2.0, 3.0, 2.0, 3.0, 2.0, 3.0, 3.0, 3.0, 4.0, 4.0, 10.0, 10.0];

/// The benchmark's ranges per variable (`hypot(25, 25)` for distances from
/// K1, half that for distances to the centre and to the nearest taker, 180°
/// for angles); the features cover `[0, range]`.
pub const RANGES: [f64; STATE_VARS] = {
    const MAX: f64 = 35.355_339_059_327_38; // hypot(25, 25)
    [MAX / 2.0, MAX, MAX, MAX, MAX, MAX / 2.0, MAX / 2.0, MAX / 2.0, MAX / 2.0, MAX / 2.0, MAX / 2.0, 180.0, 180.0]
};

/// The macro-actions of the keeper with the ball.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum KeeperAction {
    /// `HoldBall`: keep the ball close, away from the takers (one cycle).
    Hold,
    /// `PassBall(K2)`: pass to the nearer teammate.
    Pass1,
    /// `PassBall(K3)`: pass to the farther teammate.
    Pass2,
}

impl KeeperAction {
    /// The three actions in index order (0 Hold, 1 Pass1, 2 Pass2).
    pub const ALL: [KeeperAction; 3] = [KeeperAction::Hold, KeeperAction::Pass1, KeeperAction::Pass2];

    /// The action's index (the learners' action number and the rules' class).
    #[inline]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The action of an index; `None` beyond 2.
    #[inline]
    pub fn from_index(i: usize) -> Option<KeeperAction> {
        KeeperAction::ALL.get(i).copied()
    }

    /// Whether it is a pass.
    #[inline]
    pub fn is_pass(self) -> bool {
        self != KeeperAction::Hold
    }
}

/// The two other keepers sorted by distance to `k1` (nearer first; the
/// first listed wins a tie), as indices into `mates`.
#[inline]
pub fn sort_by_distance(k1: Vec2, others: &[Vec2; 2]) -> [usize; 2] {
    if others[1].dist2(k1) < others[0].dist2(k1) { [1, 0] } else { [0, 1] }
}

/// Writes the 13 state variables of K1 at `k1` with teammates `mates` and
/// takers `takers` (each pair in any order) around the centre `centre`.
pub fn state_vars(k1: Vec2, mates: &[Vec2; 2], takers: &[Vec2; 2], centre: Vec2, out: &mut [f64; STATE_VARS]) {
    let [a, b] = sort_by_distance(k1, mates);
    let (k2, k3) = (mates[a], mates[b]);
    let [c, d] = sort_by_distance(k1, takers);
    let (t1, t2) = (takers[c], takers[d]);
    out[0] = k1.dist(centre);
    out[1] = k1.dist(k2);
    out[2] = k1.dist(k3);
    out[3] = k1.dist(t1);
    out[4] = k1.dist(t2);
    out[5] = k2.dist(centre);
    out[6] = k3.dist(centre);
    out[7] = t1.dist(centre);
    out[8] = t2.dist(centre);
    out[9] = k2.dist(t1).min(k2.dist(t2));
    out[10] = k3.dist(t1).min(k3.dist(t2));
    let deg = 180.0 / std::f64::consts::PI;
    out[11] = deg * angle_between(k2 - k1, t1 - k1).min(angle_between(k2 - k1, t2 - k1));
    out[12] = deg * angle_between(k3 - k1, t1 - k1).min(angle_between(k3 - k1, t2 - k1));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variables_follow_the_benchmark_order() {
        let k1 = Vec2::new(0.0, 0.0);
        let mates = [Vec2::new(0.0, 8.0), Vec2::new(4.0, 0.0)];
        let takers = [Vec2::new(4.0, 4.0), Vec2::new(2.0, 0.5)];
        let mut s = [0.0; STATE_VARS];
        state_vars(k1, &mates, &takers, Vec2::new(1.0, 0.0), &mut s);
        assert_eq!(s[0], 1.0);
        assert_eq!((s[1], s[2]), (4.0, 8.0));
        assert!((s[3] - 2.0f64.hypot(0.5)).abs() < 1e-12);
        assert!((s[4] - 32f64.sqrt()).abs() < 1e-12);
        assert_eq!(s[5], 3.0);
        assert!((s[6] - 65f64.sqrt()).abs() < 1e-12);
        assert!((s[9] - 2.0f64.hypot(0.5).min(4.0)).abs() < 1e-12);
        // K2 at 0°, T2 at atan(0.25) = 14.04°; K3 at 90°, T1 at 45°.
        assert!((s[11] - 0.25f64.atan().to_degrees()).abs() < 1e-9);
        assert!((s[12] - 45.0).abs() < 1e-9);
    }

    proptest::proptest! {
        // Distances are non-negative and ordered as the sorting says, angles
        // lie in [0°, 180°], and neither pair's input order matters.
        #[test]
        fn variables_are_ordered_and_order_free(
            c in proptest::collection::vec(-12.0f64..12.0, 10),
        ) {
            let p = |i: usize| Vec2::new(c[2 * i], c[2 * i + 1]);
            let (k1, mates, takers) = (p(0), [p(1), p(2)], [p(3), p(4)]);
            let mut s = [0.0; STATE_VARS];
            state_vars(k1, &mates, &takers, Vec2::ZERO, &mut s);
            proptest::prop_assert!(s.iter().all(|v| v.is_finite() && *v >= 0.0));
            proptest::prop_assert!(s[1] <= s[2] && s[3] <= s[4]);
            proptest::prop_assert!(s[11] <= 180.0 + 1e-9 && s[12] <= 180.0 + 1e-9);
            let mut t = [0.0; STATE_VARS];
            state_vars(k1, &[mates[1], mates[0]], &[takers[1], takers[0]], Vec2::ZERO, &mut t);
            if s[1] != s[2] && s[3] != s[4] {
                proptest::prop_assert_eq!(s, t);
            }
        }
    }

    #[test]
    fn actions_round_trip() {
        for a in KeeperAction::ALL {
            assert_eq!(KeeperAction::from_index(a.index()), Some(a));
        }
        assert_eq!(KeeperAction::from_index(3), None);
        assert!(!KeeperAction::Hold.is_pass() && KeeperAction::Pass2.is_pass());
        assert_eq!(TILE_WIDTHS.len(), STATE_NAMES.len());
    }
}
