//! The keeper's macro-actions and the state variables of Keepaway (13 in
//! 3 vs 2), from the decision-maker's view, in the order of
//! `WorldModel::keeperStateVars` (Stone, Sutton & Kuhlmann 2005; `domains.md` 1.3).
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
//! With K keepers and T takers the same list has `4 K + 2 T − 3` entries
//! ([`state_len`]). Perception is exact here (the keepers of the benchmark
//! see with quantisation noise every 150 ms): a documented deviation.

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

/// A macro-action of the keeper with the ball: 0 is `HoldBall`, `i ≥ 1`
/// `PassBall(K_{i+1})`, a pass to the `i`-th closest teammate (the players'
/// `interpretKeeperAction`). In 3 vs 2: Hold, Pass1, Pass2.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(transparent)]
pub struct KeeperAction(pub u8);

impl KeeperAction {
    /// `HoldBall`: keep the ball close, away from the takers (one cycle).
    pub const HOLD: KeeperAction = KeeperAction(0);
    /// A pass to the nearest teammate.
    pub const PASS1: KeeperAction = KeeperAction(1);
    /// A pass to the second nearest teammate.
    pub const PASS2: KeeperAction = KeeperAction(2);

    /// The three actions of 3 vs 2, in index order (0 Hold, 1 Pass1, 2 Pass2).
    pub const ALL: [KeeperAction; 3] = [KeeperAction::HOLD, KeeperAction::PASS1, KeeperAction::PASS2];

    /// The action's index (the learners' action number and the rules' class).
    #[inline]
    pub fn index(self) -> usize {
        usize::from(self.0)
    }

    /// The 3 vs 2 action of an index; `None` beyond 2.
    #[inline]
    pub fn from_index(i: usize) -> Option<KeeperAction> {
        KeeperAction::ALL.get(i).copied()
    }

    /// Whether it is a pass.
    #[inline]
    pub fn is_pass(self) -> bool {
        self.0 > 0
    }
}

/// The number of state variables with `keepers` keepers and `takers` takers
/// (`keeperStateVars`: `4 K + 2 T − 3`; 13 in 3 vs 2, 19 in 4 vs 3).
#[inline]
pub const fn state_len(keepers: usize, takers: usize) -> usize {
    4 * keepers + 2 * takers - 3
}

/// Sorts `idx` by the distance of `points[idx[·]]` to `from`, nearer first,
/// the earlier listed first on ties (`sortClosestTo`'s exchange sort).
#[inline]
pub fn sort_indices_by_distance(from: Vec2, points: &[Vec2], idx: &mut [usize]) {
    let n = idx.len();
    for i in 0..n.saturating_sub(1) {
        for j in i + 1..n {
            if points[idx[j]].dist2(from) < points[idx[i]].dist2(from) {
                idx.swap(i, j);
            }
        }
    }
}

/// The two other keepers sorted by distance to `k1` (nearer first; the
/// first listed wins a tie), as indices into `mates`.
#[inline]
pub fn sort_by_distance(k1: Vec2, others: &[Vec2; 2]) -> [usize; 2] {
    if others[1].dist2(k1) < others[0].dist2(k1) { [1, 0] } else { [0, 1] }
}

/// The most state variables (5 keepers, 4 takers).
pub const MAX_STATE_VARS: usize = state_len(5, 4);

/// Writes the state variables of K1 at `k1` with teammates `mates` and
/// takers `takers` (each in any order) around the centre `centre`, in the
/// order of `keeperStateVars`: dist(K1, C); dist(K1, Ki) for the teammates
/// nearest first; dist(K1, Tj) for the takers nearest first; dist(Ki, C);
/// dist(Tj, C); each teammate's distance to its nearest taker; each
/// teammate's smallest angle (degrees) at K1 to a taker. `out` must hold
/// [`state_len`] values.
pub fn state_vars_general(k1: Vec2, mates: &[Vec2], takers: &[Vec2], centre: Vec2, out: &mut [f64]) {
    const M: usize = 8;
    let (nm, nt) = (mates.len(), takers.len());
    let mut mi = [0usize, 1, 2, 3, 4, 5, 6, 7];
    let mut ti = [0usize, 1, 2, 3, 4, 5, 6, 7];
    sort_indices_by_distance(k1, mates, &mut mi[..nm.min(M)]);
    sort_indices_by_distance(k1, takers, &mut ti[..nt.min(M)]);
    let deg = 180.0 / std::f64::consts::PI;
    let mut j = 0;
    out[j] = k1.dist(centre);
    j += 1;
    for &i in &mi[..nm] {
        out[j] = k1.dist(mates[i]);
        j += 1;
    }
    for &i in &ti[..nt] {
        out[j] = k1.dist(takers[i]);
        j += 1;
    }
    for &i in &mi[..nm] {
        out[j] = mates[i].dist(centre);
        j += 1;
    }
    for &i in &ti[..nt] {
        out[j] = takers[i].dist(centre);
        j += 1;
    }
    for &i in &mi[..nm] {
        out[j] = takers.iter().map(|t| mates[i].dist(*t)).fold(f64::INFINITY, f64::min);
        j += 1;
    }
    for &i in &mi[..nm] {
        let m = mates[i] - k1;
        out[j] = deg * takers.iter().map(|t| angle_between(m, *t - k1)).fold(f64::INFINITY, f64::min);
        j += 1;
    }
}

/// Writes the 13 state variables of 3 vs 2 (see [`state_vars_general`]).
pub fn state_vars(k1: Vec2, mates: &[Vec2; 2], takers: &[Vec2; 2], centre: Vec2, out: &mut [f64; STATE_VARS]) {
    state_vars_general(k1, mates, takers, centre, out);
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
        assert!(!KeeperAction::HOLD.is_pass() && KeeperAction::PASS2.is_pass());
        assert_eq!(TILE_WIDTHS.len(), STATE_NAMES.len());
    }
}
