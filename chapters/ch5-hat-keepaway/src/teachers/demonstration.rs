//! Recording demonstrations: a teacher controls the keeper with the ball for
//! a number of episodes; at every decision its (13 state variables, action)
//! pair is recorded, as the thesis recorded "all (s, a) pairs selected by
//! the teacher" (a decision with no key pressed records Hold).
//!
//! Also the thesis's derived sets (section 5.4): a random half of a set
//! ([`DemonstrationSet::random_subset`], "Subject A (10)") and the longest or
//! shortest episodes of two teachers together ([`DemonstrationSet::extremes`],
//! "Subjects A + C Best/Worst").

use rand::Rng;
use rlfd_rl::random::shuffle;
use serde::{Deserialize, Serialize};

use super::TeacherModel;
use crate::keepaway::{CYCLES_PER_SECOND, Keepaway, KeeperAction, STATE_VARS, Status};

/// One demonstrated episode.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DemoEpisode {
    /// Which teacher played it (its label).
    pub teacher: String,
    /// Its number in that teacher's recording (from 0).
    pub index: usize,
    /// Duration in cycles.
    pub duration: u32,
    /// The decision maker's 13 state variables at each decision.
    pub states: Vec<[f64; STATE_VARS]>,
    /// The action at each decision (0 Hold, 1 Pass1, 2 Pass2).
    pub actions: Vec<u8>,
}

/// A set of demonstrated episodes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DemonstrationSet {
    /// The set's name (the thesis's condition).
    pub name: String,
    /// The episodes.
    pub episodes: Vec<DemoEpisode>,
}

impl DemonstrationSet {
    /// Mean episode duration in seconds.
    pub fn mean_seconds(&self) -> f64 {
        if self.episodes.is_empty() {
            return f64::NAN;
        }
        self.episodes.iter().map(|e| f64::from(e.duration)).sum::<f64>()
            / self.episodes.len() as f64
            / CYCLES_PER_SECOND
    }

    /// Mean duration (s) of the episodes of one teacher in the set.
    pub fn mean_seconds_of(&self, teacher: &str) -> f64 {
        let d: Vec<f64> =
            self.episodes.iter().filter(|e| e.teacher == teacher).map(|e| f64::from(e.duration)).collect();
        if d.is_empty() { f64::NAN } else { d.iter().sum::<f64>() / d.len() as f64 / CYCLES_PER_SECOND }
    }

    /// Every recorded pair, in order.
    pub fn pairs(&self) -> impl Iterator<Item = (&[f64; STATE_VARS], u8)> {
        self.episodes.iter().flat_map(|e| e.states.iter().zip(e.actions.iter().copied()))
    }

    /// Number of recorded pairs.
    pub fn len(&self) -> usize {
        self.episodes.iter().map(|e| e.actions.len()).sum()
    }

    /// Whether no pair was recorded.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// How often each action was demonstrated (Hold, Pass1, Pass2).
    pub fn action_counts(&self) -> [usize; 3] {
        let mut c = [0; 3];
        for (_, a) in self.pairs() {
            c[usize::from(a)] += 1;
        }
        c
    }

    /// `count` episodes drawn at random without replacement, in their recorded order.
    pub fn random_subset<R: Rng + ?Sized>(&self, name: &str, count: usize, rng: &mut R) -> DemonstrationSet {
        let mut order: Vec<usize> = (0..self.episodes.len()).collect();
        shuffle(&mut order, rng);
        let mut chosen: Vec<usize> = order.into_iter().take(count).collect();
        chosen.sort_unstable();
        DemonstrationSet { name: name.into(), episodes: chosen.into_iter().map(|i| self.episodes[i].clone()).collect() }
    }

    /// The share of all `count`-episode subsets of this set whose mean
    /// duration is at most `seconds`: where a random half such as "Subject A
    /// (10)" falls among every half it could have been. Every subset is
    /// counted (184,756 halves of 20 episodes); `None` for a set of more
    /// than 24 episodes or a `count` of 0 or more than the set holds.
    pub fn subset_share_at_most(&self, count: usize, seconds: f64) -> Option<f64> {
        let n = self.episodes.len();
        if n > 24 || count == 0 || count > n {
            return None;
        }
        // In whole cycles, so that ties with a subset's own mean are exact.
        let limit = libm::floor(seconds * CYCLES_PER_SECOND * count as f64 + 1e-9);
        let durations: Vec<u64> = self.episodes.iter().map(|e| u64::from(e.duration)).collect();
        let (mut all, mut at_most) = (0u64, 0u64);
        // Every n-bit mask with `count` bits set, in increasing order (Gosper's hack).
        let mut mask: u32 = (1u32 << count) - 1;
        while mask < (1u32 << n) {
            let sum: u64 = (0..n).filter(|i| mask >> i & 1 == 1).map(|i| durations[i]).sum();
            all += 1;
            if sum as f64 <= limit {
                at_most += 1;
            }
            let low = mask & mask.wrapping_neg();
            let ripple = mask + low;
            mask = (((ripple ^ mask) >> 2) / low) | ripple;
        }
        Some(at_most as f64 / all as f64)
    }

    /// The `count` longest (`longest`) or shortest episodes of each set, together.
    /// Ties go to the earlier episode.
    pub fn extremes(name: &str, sets: &[&DemonstrationSet], count: usize, longest: bool) -> DemonstrationSet {
        let mut episodes = Vec::new();
        for set in sets {
            let mut order: Vec<usize> = (0..set.episodes.len()).collect();
            order.sort_by(|&a, &b| {
                let (da, db) = (set.episodes[a].duration, set.episodes[b].duration);
                let by = if longest { db.cmp(&da) } else { da.cmp(&db) };
                by.then(a.cmp(&b))
            });
            let mut chosen: Vec<usize> = order.into_iter().take(count).collect();
            chosen.sort_unstable();
            episodes.extend(chosen.into_iter().map(|i| set.episodes[i].clone()));
        }
        DemonstrationSet { name: name.into(), episodes }
    }
}

/// Records `episodes` episodes of `teacher` (named `label`) playing the keeper with the ball.
pub fn record<R: Rng + ?Sized>(teacher: &TeacherModel, label: &str, episodes: usize, rng: &mut R) -> DemonstrationSet {
    let mut game = Keepaway::benchmark();
    game.keep_history(teacher.history_needed());
    let mut out = Vec::with_capacity(episodes);
    for index in 0..episodes {
        out.push(demonstrate(&mut game, teacher, label, index, rng));
    }
    DemonstrationSet { name: label.into(), episodes: out }
}

/// One demonstrated episode on a game that keeps enough history.
pub fn demonstrate<R: Rng + ?Sized>(
    game: &mut Keepaway,
    teacher: &TeacherModel,
    label: &str,
    index: usize,
    rng: &mut R,
) -> DemoEpisode {
    let mut states = Vec::new();
    let mut actions = Vec::new();
    game.reset(rng);
    let mut status = game.run(rng);
    loop {
        match status {
            Status::Decision(k) => {
                let mut s = [0.0; STATE_VARS];
                game.state_vars(k, &mut s);
                let a = teacher.choose(game, k, rng);
                states.push(s);
                actions.push(a.index() as u8);
                status = game.act(a, rng);
            }
            Status::Ended(_) => {
                return DemoEpisode { teacher: label.into(), index, duration: game.cycle(), states, actions };
            }
        }
    }
}

/// The mean duration (cycles) of `episodes` episodes played by `teacher`,
/// without recording (for calibration).
pub fn mean_duration<R: Rng + ?Sized>(teacher: &TeacherModel, episodes: usize, rng: &mut R) -> f64 {
    let mut game = Keepaway::benchmark();
    game.keep_history(teacher.history_needed());
    let mut total = 0u64;
    for _ in 0..episodes {
        let (d, _) = game.play_episode(rng, |g, k, rng| teacher.choose(g, k, rng));
        total += u64::from(d);
    }
    total as f64 / episodes as f64
}

/// The action of a recorded index.
pub fn action_of(code: u8) -> KeeperAction {
    KeeperAction::ALL[usize::from(code).min(2)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::teachers::TeacherStyle;
    use rlfd_rl::random::seeded;

    fn teacher() -> TeacherModel {
        TeacherModel {
            style: TeacherStyle {
                pressure_distance: 5.0,
                pass_threshold: 90.0,
                distance_weight: 4.0,
                near_preference: 0.0,
                panic_distance: 0.0,
                edge_distance: 100.0,
                centre_extra: 0.0,
            },
            reaction_delay_s: 0.3,
            reaction_jitter_s: 0.0,
            speedup: 1.0,
            perception_noise: 0.5,
            allow_pass2: true,
        }
    }

    #[test]
    fn recordings_hold_one_pair_per_decision() {
        let set = record(&teacher(), "T", 5, &mut seeded(1));
        assert_eq!(set.episodes.len(), 5);
        for e in &set.episodes {
            assert_eq!(e.states.len(), e.actions.len());
            assert!(!e.actions.is_empty());
            assert!(e.duration as usize >= e.actions.len());
        }
        let counts = set.action_counts();
        assert_eq!(counts.iter().sum::<usize>(), set.len());
        assert!(counts[0] > counts[1] + counts[2], "mostly Hold: {counts:?}");
        assert_eq!(set, record(&teacher(), "T", 5, &mut seeded(1)));
    }

    #[test]
    fn derived_sets_pick_the_right_episodes() {
        let a = record(&teacher(), "A", 6, &mut seeded(2));
        let c = record(&teacher(), "C", 6, &mut seeded(3));
        let best = DemonstrationSet::extremes("best", &[&a, &c], 3, true);
        let worst = DemonstrationSet::extremes("worst", &[&a, &c], 3, false);
        assert_eq!(best.episodes.len(), 6);
        let min_best_a = best.episodes.iter().filter(|e| e.teacher == "A").map(|e| e.duration).min().unwrap();
        let max_worst_a = worst.episodes.iter().filter(|e| e.teacher == "A").map(|e| e.duration).max().unwrap();
        assert!(min_best_a >= max_worst_a);
        assert!(best.mean_seconds_of("A") >= a.mean_seconds() && worst.mean_seconds_of("C") <= c.mean_seconds());
        let half = a.random_subset("A (3)", 3, &mut seeded(4));
        assert_eq!(half.episodes.len(), 3);
        assert!(half.episodes.windows(2).all(|w| w[0].index < w[1].index));
    }

    #[test]
    fn subset_shares_count_every_subset() {
        let episode = |index: usize, duration: u32| DemoEpisode {
            teacher: "T".into(),
            index,
            duration,
            states: Vec::new(),
            actions: Vec::new(),
        };
        let set = DemonstrationSet {
            name: "toy".into(),
            episodes: [10, 20, 30, 40].iter().enumerate().map(|(i, &d)| episode(i, d)).collect(),
        };
        // Pairs' means: 1.5, 2, 2.5, 2.5, 3, 3.5 s.
        assert_eq!(set.subset_share_at_most(2, 2.5), Some(4.0 / 6.0));
        assert_eq!(set.subset_share_at_most(2, 1.4), Some(0.0));
        assert_eq!(set.subset_share_at_most(4, 2.5), Some(1.0));
        assert_eq!(set.subset_share_at_most(1, 2.0), Some(0.5));
        assert_eq!(set.subset_share_at_most(0, 2.0), None);
        assert_eq!(set.subset_share_at_most(5, 2.0), None);
        let twenty = DemonstrationSet {
            name: "twenty".into(),
            episodes: (0..20).map(|i| episode(i, 10 * (i as u32 + 1))).collect(),
        };
        // 184,756 halves (the shares are counts over it); a half and its
        // complement lie on either side of the mean 10.5 s, so as many lie
        // below it as above.
        let halves = 184_756.0;
        let count = |seconds: f64| {
            let c = twenty.subset_share_at_most(10, seconds).unwrap() * halves;
            assert!((c - c.round()).abs() < 1e-6, "{c}");
            c.round()
        };
        let (below, at_most) = (count(10.49), count(10.5));
        assert!(below > 0.0 && at_most > below);
        assert_eq!(below + at_most, halves);
    }
}
