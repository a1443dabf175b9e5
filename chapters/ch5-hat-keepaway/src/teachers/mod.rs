//! Models of the thesis's human teachers (section 5.4): Subjects A, B and C,
//! and B handicapped (Fast, Limited). Each demonstrates by controlling the
//! keeper with the ball for 20 episodes (Hold, Pass1, Pass2; no key = Hold)
//! while every (state, action) pair is recorded.
//!
//! The thesis's humans watched a visualiser, not the 13 variables ("the
//! human has a very different representation of the state than the
//! learning agent"), so a model decides from **positions**, as it saw them
//! a **reaction delay** ago, misjudged by **perception noise**, in a
//! **style** of its own:
//!
//! 1. take the snapshot of the game a reaction time ago (`reaction_delay_s`
//!    plus `U(0, reaction_jitter_s)` seconds, drawn per decision), and jitter
//!    every player's position by independent Gaussian noise of sd
//!    `perception_noise` m;
//! 2. if the nearest taker is farther than `pressure_distance` from the
//!    keeper with the ball, hold;
//! 3. otherwise score each teammate: the smallest angle at the holder
//!    between it and a taker (degrees), plus `distance_weight` times its
//!    distance to the nearest taker (m), plus `near_preference` for the
//!    nearer one; press the key of the best (Pass1 = nearer, Pass2 = farther,
//!    as the keys mean) if its score exceeds `pass_threshold` (plus
//!    `centre_extra` when the holder is nearer the centre than
//!    `edge_distance`: where the ball cannot be pushed out, a person may
//!    hold on longer), or whatever the score if a taker is within
//!    [`PANIC_DISTANCE`];
//!    else hold. A teacher without the Pass2 key chooses the same way and,
//!    when it means to pass to the farther teammate, presses the only pass
//!    key it has (Pass1).
//!
//! The key acts on the game as it is now: Pass1 passes to whichever
//! teammate is nearer *now*. The delay is in simulator cycles:
//! `delay · 10 · speedup`, so the same human watching a simulator running
//! five times faster than real time (B Fast) reacts five times later in
//! simulated time.
//!
//! The structure of the rule is the benchmark's hand-coded policy (hold
//! until pressed, then pass to the most open teammate), which a person
//! playing keepaway also follows; what differs between teachers is the
//! style (chosen from the thesis's descriptions and, for A, its printed
//! rule list; see each subject's file) and how much longer A holds in the
//! middle of the field, fitted only to what the thesis reports of A's
//! demonstrations (see [`calibration`]), before any learner ran. The
//! perception noise is declared, the same for every teacher: 0 m, the
//! positions as the thesis's visualiser drew them ([`calibration`]'s docs);
//! it stays a parameter for the calibration's diagnostic.

pub mod calibration;
pub mod demonstration;
pub mod styles;
pub mod subject_a;
pub mod subject_b;
pub mod subject_b_fast;
pub mod subject_b_limited;
pub mod subject_c;

use rand::Rng;
use rlfd_rl::random::standard_normal;
use serde::{Deserialize, Serialize};

use crate::keepaway::geometry::{Vec2, angle_between};
use crate::keepaway::{Keepaway, KeeperAction, Snapshot, other_two};

pub use demonstration::{DemoEpisode, DemonstrationSet, record};
pub use styles::FrequentPasser;

/// Within this distance of a taker a teacher passes to the better teammate
/// whatever its score (m): a person under immediate pressure gets rid of the
/// ball. A fixed modelling choice (about two body lengths plus the kickable
/// margin), the same for every teacher, not calibrated.
pub const PANIC_DISTANCE: f64 = 2.0;

/// How a teacher plays (see the module docs).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TeacherStyle {
    /// Hold while the nearest taker is farther than this from the ball holder (m).
    pub pressure_distance: f64,
    /// Pass when the best teammate's score exceeds this.
    pub pass_threshold: f64,
    /// Weight of a teammate's distance from its nearest taker (score per m).
    pub distance_weight: f64,
    /// Added to the nearer teammate's score.
    pub near_preference: f64,
    /// With a taker this close, pass to the best teammate whatever its score (m).
    pub panic_distance: f64,
    /// Farther than this from the centre the keeper with the ball is near the edge (m).
    pub edge_distance: f64,
    /// Nearer the centre than `edge_distance`, the pass threshold rises by
    /// this much (where the ball cannot be pushed out, a person holds on).
    pub centre_extra: f64,
}

/// A teacher: a style, a reaction delay, perception noise and the keys it may use.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TeacherModel {
    /// How it plays.
    pub style: TeacherStyle,
    /// Shortest reaction delay in real seconds (fixed: a person's).
    pub reaction_delay_s: f64,
    /// How much longer than `reaction_delay_s` a reaction may take (s): each
    /// decision's delay is `reaction_delay_s + U(0, reaction_jitter_s)`.
    pub reaction_jitter_s: f64,
    /// Simulator speed relative to real time (1; B Fast: 5).
    pub speedup: f64,
    /// Sd of the teacher's misjudgement of each player's position (m; declared, [`calibration::PERCEPTION_NOISE`]).
    pub perception_noise: f64,
    /// Whether the Pass2 key is allowed (B Limited: no).
    pub allow_pass2: bool,
}

impl TeacherModel {
    /// The reaction delay in simulator cycles (rounded to whole cycles).
    pub fn delay_cycles(&self) -> usize {
        (self.reaction_delay_s * crate::keepaway::CYCLES_PER_SECOND * self.speedup).round().max(0.0) as usize
    }

    /// The longest delay in simulator cycles.
    pub fn max_delay_cycles(&self) -> usize {
        ((self.reaction_delay_s + self.reaction_jitter_s) * crate::keepaway::CYCLES_PER_SECOND * self.speedup)
            .round()
            .max(0.0) as usize
    }

    /// History the game must keep for this teacher.
    pub fn history_needed(&self) -> usize {
        self.max_delay_cycles() + 1
    }

    /// The key the teacher presses for keeper `k`, which has the ball now
    /// (the game must keep at least [`TeacherModel::history_needed`] snapshots).
    pub fn choose<R: Rng + ?Sized>(&self, game: &Keepaway, k: usize, rng: &mut R) -> KeeperAction {
        let jitter = self.reaction_jitter_s * rlfd_rl::random::uniform01(rng);
        let delay =
            ((self.reaction_delay_s + jitter) * crate::keepaway::CYCLES_PER_SECOND * self.speedup).round() as usize;
        let seen = *game.snapshot_ago(delay).expect("the game keeps a history for the teacher");
        self.choose_from(&seen, k, rng)
    }

    /// The decision from a snapshot (see the module docs). Draws 10 normals
    /// (two per player) when the noise is positive.
    pub fn choose_from<R: Rng + ?Sized>(&self, seen: &Snapshot, k: usize, rng: &mut R) -> KeeperAction {
        let mut jitter = |p: Vec2| {
            if self.perception_noise > 0.0 {
                Vec2::new(
                    p.x + self.perception_noise * standard_normal(rng),
                    p.y + self.perception_noise * standard_normal(rng),
                )
            } else {
                p
            }
        };
        let (a, b) = other_two(k);
        let holder = jitter(seen.keepers[k]);
        let mates = [jitter(seen.keepers[a]), jitter(seen.keepers[b])];
        let takers = [jitter(seen.takers[0]), jitter(seen.takers[1])];
        let s = &self.style;
        let pressure = holder.dist(takers[0]).min(holder.dist(takers[1]));
        if pressure > s.pressure_distance {
            return KeeperAction::HOLD;
        }
        // Where it stands on the field a person reads off the field's lines,
        // which stand still: the edge test takes the seen position without
        // the misjudgement of moving players.
        let threshold =
            if seen.keepers[k].norm() < s.edge_distance { s.pass_threshold + s.centre_extra } else { s.pass_threshold };
        let near = if mates[1].dist2(holder) < mates[0].dist2(holder) { 1 } else { 0 };
        let mut best: Option<(KeeperAction, f64)> = None;
        for (key, mate) in [(KeeperAction::PASS1, mates[near]), (KeeperAction::PASS2, mates[1 - near])] {
            let lane = angle_between(mate - holder, takers[0] - holder)
                .min(angle_between(mate - holder, takers[1] - holder))
                .to_degrees();
            let open = mate.dist(takers[0]).min(mate.dist(takers[1]));
            let score =
                lane + s.distance_weight * open + if key == KeeperAction::PASS1 { s.near_preference } else { 0.0 };
            if best.is_none_or(|(_, b)| score > b) {
                best = Some((key, score));
            }
        }
        match best {
            // Without the Pass2 key the teacher still passes when it means to,
            // with the only pass key it has.
            Some((KeeperAction::PASS2, score))
                if !self.allow_pass2 && (score > threshold || pressure < s.panic_distance) =>
            {
                KeeperAction::PASS1
            }
            Some((key, score)) if score > threshold || pressure < s.panic_distance => key,
            _ => KeeperAction::HOLD,
        }
    }
}

/// The demonstration sets of the thesis's section 5.4.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Teacher {
    /// Subject A: years of Keepaway research.
    A,
    /// Subject B: new to Keepaway, about 100 practice games.
    B,
    /// Subject C: an LfD expert new to Keepaway, 10 practice games.
    C,
    /// Subject B with the simulator about five times faster than real time.
    BFast,
    /// Subject B allowed only Hold and Pass1.
    BLimited,
}

impl Teacher {
    /// The five recorded teachers.
    pub const ALL: [Teacher; 5] = [Teacher::A, Teacher::B, Teacher::C, Teacher::BFast, Teacher::BLimited];

    /// The model, B's and C's styles as `passer` assigns them (the
    /// `bc-styles` reading; A's model does not depend on it).
    pub fn model(self, passer: FrequentPasser) -> TeacherModel {
        match self {
            Teacher::A => subject_a::model(),
            Teacher::B => subject_b::model(passer),
            Teacher::C => subject_c::model(passer),
            Teacher::BFast => subject_b_fast::model(passer),
            Teacher::BLimited => subject_b_limited::model(passer),
        }
    }

    /// The thesis's mean demonstration duration (s), the calibration target.
    pub fn thesis_mean_seconds(self) -> f64 {
        match self {
            Teacher::A => 10.4,
            Teacher::B => 10.5,
            Teacher::C => 11.3,
            Teacher::BFast => 4.3,
            Teacher::BLimited => 5.2,
        }
    }

    /// The name in tables.
    pub fn label(self) -> &'static str {
        match self {
            Teacher::A => "Subject A",
            Teacher::B => "Subject B",
            Teacher::C => "Subject C",
            Teacher::BFast => "Subject B Fast",
            Teacher::BLimited => "Subject B Limited",
        }
    }

    /// The name in result paths.
    pub fn slug(self) -> &'static str {
        match self {
            Teacher::A => "subject-a",
            Teacher::B => "subject-b",
            Teacher::C => "subject-c",
            Teacher::BFast => "subject-b-fast",
            Teacher::BLimited => "subject-b-limited",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::keepaway::KEEPERS;
    use rlfd_rl::random::seeded;

    fn style() -> TeacherStyle {
        TeacherStyle {
            pressure_distance: 5.0,
            pass_threshold: 90.0,
            distance_weight: 4.0,
            near_preference: 0.0,
            panic_distance: 0.0,
            edge_distance: 100.0,
            centre_extra: 0.0,
        }
    }

    fn snapshot() -> Snapshot {
        let mut s = Snapshot { cycle: 10, ..Snapshot::default() };
        s.keepers[..3].copy_from_slice(&[Vec2::new(0.0, 0.0), Vec2::new(8.0, 0.0), Vec2::new(0.0, -9.0)]);
        s.takers[..2].copy_from_slice(&[Vec2::new(3.0, 0.5), Vec2::new(4.0, 1.0)]);
        s
    }

    #[test]
    fn holds_when_free_and_passes_away_from_the_takers() {
        let mut rng = seeded(1);
        let mut t = TeacherModel {
            style: style(),
            reaction_delay_s: 0.0,
            reaction_jitter_s: 0.0,
            speedup: 1.0,
            perception_noise: 0.0,
            allow_pass2: true,
        };
        // Takers toward the nearer teammate: pass to the farther, open one.
        assert_eq!(t.choose_from(&snapshot(), 0, &mut rng), KeeperAction::PASS2);
        let mut free = snapshot();
        free.takers[..2].copy_from_slice(&[Vec2::new(-8.0, 8.0), Vec2::new(-9.0, 9.0)]);
        assert_eq!(t.choose_from(&free, 0, &mut rng), KeeperAction::HOLD);
        // Without the Pass2 key the teacher still passes when it means to, with Pass1.
        t.allow_pass2 = false;
        assert_eq!(t.choose_from(&snapshot(), 0, &mut rng), KeeperAction::PASS1);
        // Under pressure but with no open lane: hold, unless a taker is within the panic distance.
        t.allow_pass2 = true;
        let mut crowded = snapshot();
        crowded.keepers[2] = Vec2::new(4.0, 1.5);
        crowded.takers[..2].copy_from_slice(&[Vec2::new(3.0, 0.5), Vec2::new(3.5, 1.2)]);
        assert_eq!(t.choose_from(&crowded, 0, &mut rng), KeeperAction::HOLD);
        t.style.panic_distance = 4.0;
        assert_ne!(t.choose_from(&crowded, 0, &mut rng), KeeperAction::HOLD);
        assert_eq!(KEEPERS, 3);
        // In the middle a higher score is needed: with the threshold at 20
        // the better lane (28) is enough 8 m out, not at the centre (20 + 70).
        t.style.panic_distance = 0.0;
        t.style.pass_threshold = 20.0;
        t.style.edge_distance = 7.33;
        t.style.centre_extra = 70.0;
        assert_eq!(t.choose_from(&crowded, 0, &mut rng), KeeperAction::HOLD);
        let mut edge = crowded;
        for p in edge.keepers.iter_mut().chain(edge.takers.iter_mut()) {
            *p += Vec2::new(8.0, 0.0);
        }
        assert_ne!(t.choose_from(&edge, 0, &mut rng), KeeperAction::HOLD);
    }

    #[test]
    fn the_delay_scales_with_the_simulator_speed() {
        let mut t = TeacherModel {
            style: style(),
            reaction_delay_s: 0.4,
            reaction_jitter_s: 0.0,
            speedup: 1.0,
            perception_noise: 0.0,
            allow_pass2: true,
        };
        assert_eq!(t.delay_cycles(), 4);
        t.speedup = 5.0;
        assert_eq!(t.delay_cycles(), 20);
        assert_eq!(t.history_needed(), 21);
        t.reaction_jitter_s = 0.2;
        assert_eq!(t.max_delay_cycles(), 30);
    }
}
