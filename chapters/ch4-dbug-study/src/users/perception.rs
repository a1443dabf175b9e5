//! What the user believes the robot should do now: the user's own reading
//! of the table, which is not the robot's state.
//!
//! The participants were told the task ("It was noted that the Nao would be
//! able to track the bugs with its own vision system and each of the three
//! preprogrammed actions were also explained"), not the state's definition,
//! and "were not told how much of the workspace was exactly covered by the
//! camera". So (our model, from those sentences):
//! - every participant goes by any bug: one at the pickup spot means pick
//!   up, else one on the left means sweep, else wait — "the users tried to
//!   demonstrate behaviors for the ultimate goal of sweeping and picking-up
//!   hexbugs" (l. 582), and "it was hard for most users to realize which
//!   behavior was activated when, because there was no visualization for
//!   the mental model of the agent" (l. 580), said of the participants with
//!   no exception for the self-identified experts ([`TableReading::Goal`],
//!   the default of the `table-reading` reading);
//! - the alternative [`TableReading::ExpertsAsRobot`]: the expert
//!   participants read the table as the robot does (the bug nearest the
//!   pickup mark decides), the model of rounds 1–3, which rested on "an
//!   expert roboticist who knew about the necessary order of
//!   preconditions" (l. 582), a sentence about the authors (the scripted
//!   ideal teacher reads the robot's state in every level);
//! - everyone sees the whole table, the strips the camera misses included
//!   (a bug there counts in the zone next to it), and places bugs by eye:
//!   the position they judge is off by a Gaussian error of
//!   [`PerceptionModel::position_error_px`] pixels, shrinking by
//!   [`PerceptionModel::familiarity`] per session already done ("we expected
//!   our participants to get better at demonstrating the task over time");
//! - with probability `1 − consistency` the judgement is noise (a uniformly
//!   random action): "human teachers often make noisy demonstrations".

use rand::Rng;
use rlfd_rl::random::{below, bernoulli, standard_normal};
use serde::{Deserialize, Serialize};

use super::traits::{Expertise, UserTraits};
use crate::dbug::table::NUM_BUGS;
use crate::dbug::zones::PICKUP_MARK;
use crate::dbug::{Action, IMAGE_HEIGHT, IMAGE_WIDTH, Table, Zone, zone_at};

/// How a participant reads the table (the `table-reading` reading).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TableReading {
    /// Every participant by the goal: any bug in a zone.
    Goal,
    /// Expert participants as the robot: the bug nearest the mark.
    ExpertsAsRobot,
}

/// The perception model's constants (our choices).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PerceptionModel {
    /// Error of a judged position (image px), per expertise in [`Expertise::ALL`] order.
    pub position_error_px: [f64; 3],
    /// Fraction of that error lost per session already done (0, 1, 2 sessions before).
    pub familiarity: f64,
    /// How the participants read the table.
    pub table_reading: TableReading,
}

impl PerceptionModel {
    /// 6 px for experts, 12 px for novices, 15 px without background; 20 % less per earlier session;
    /// every participant reads the table by the goal.
    pub const fn thesis() -> PerceptionModel {
        PerceptionModel { position_error_px: [6.0, 12.0, 15.0], familiarity: 0.2, table_reading: TableReading::Goal }
    }

    /// The position error of a user in their `session`-th session (from 0).
    pub fn error_px(&self, expertise: Expertise, session: usize) -> f64 {
        let e = match expertise {
            Expertise::Expert => 0,
            Expertise::Novice => 1,
            Expertise::None => 2,
        };
        self.position_error_px[e] * (1.0 - self.familiarity * session as f64).max(0.2)
    }
}

/// The zone a user judges a bug at image coordinates `(px, py)` to be in:
/// the image's zones extended to the table's edges.
pub fn judged_zone(px: f64, py: f64) -> Zone {
    let x = px.clamp(0.0, f64::from(IMAGE_WIDTH) - 1e-9);
    let y = py.clamp(0.0, f64::from(IMAGE_HEIGHT) - 1e-9);
    zone_at(x, y)
}

/// The action the user believes right for the table now.
pub fn believed_action<R: Rng + ?Sized>(
    table: &Table,
    traits: &UserTraits,
    reading: TableReading,
    error_px: f64,
    rng: &mut R,
) -> Action {
    let cam = table.params().camera;
    let mut judged: [Option<(f64, f64)>; NUM_BUGS] = [None; NUM_BUGS];
    for (i, j) in judged.iter_mut().enumerate() {
        if table.places()[i] == crate::dbug::BugPlace::OnTable {
            let b = &table.bugs()[i];
            let (px, py) = cam.project(b.x, b.y);
            *j = Some((px + error_px * standard_normal(rng), py + error_px * standard_normal(rng)));
        }
    }
    let rule = if traits.expertise == Expertise::Expert && reading == TableReading::ExpertsAsRobot {
        // The bug nearest the mark decides.
        judged
            .iter()
            .flatten()
            .min_by(|a, b| dist2(**a).total_cmp(&dist2(**b)))
            .map_or(Action::Wait, |&(x, y)| judged_zone(x, y).correct_action())
    } else {
        let zones = judged.iter().flatten().map(|&(x, y)| judged_zone(x, y));
        let mut any = [false; 3];
        for z in zones {
            any[z.index()] = true;
        }
        if any[Zone::Pickup.index()] {
            Action::Pickup
        } else if any[Zone::Sweep.index()] {
            Action::Sweep
        } else {
            Action::Wait
        }
    };
    if bernoulli(rng, traits.consistency) { rule } else { Action::from_index(below(rng, 3)) }
}

fn dist2((x, y): (f64, f64)) -> f64 {
    (x - PICKUP_MARK.0).powi(2) + (y - PICKUP_MARK.1).powi(2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dbug::TableParams;
    use rlfd_rl::random::seeded;

    #[test]
    fn participants_read_the_goal_and_experts_the_robots_state_only_as_the_alternative() {
        use TableReading::{ExpertsAsRobot, Goal};
        let mut rng = seeded(1);
        let mut t = Table::new(TableParams::thesis(), &mut rng);
        let p = *t.params();
        t.remove_to_hand(2);
        // One bug in the sweep zone, one in the wait zone nearer the mark.
        t.place(0, p.table_point(40.5, 220.5), false);
        t.place(1, p.table_point(170.5, 120.5), false);
        let expert = UserTraits::ideal();
        let novice = UserTraits { expertise: Expertise::Novice, ..expert };
        // By default the expert participant reads the goal, as everyone does.
        assert_eq!(believed_action(&t, &expert, Goal, 0.0, &mut rng), Action::Sweep);
        assert_eq!(believed_action(&t, &expert, ExpertsAsRobot, 0.0, &mut rng), Action::Wait);
        assert_eq!(believed_action(&t, &novice, ExpertsAsRobot, 0.0, &mut rng), Action::Sweep);
        // A bug in the left strip, out of the camera's view: the robot sees nothing, the user a bug to sweep.
        t.remove_to_hand(1);
        t.place(0, (0.6, 17.0), false);
        assert_eq!(t.observe(), crate::dbug::Pixel::NONE_SEEN);
        assert_eq!(believed_action(&t, &novice, Goal, 0.0, &mut rng), Action::Sweep);
        // Inconsistent users answer at random a share 1 − consistency of the time (2/3 of those differ).
        let noisy = UserTraits { consistency: 0.7, ..novice };
        let n = 30_000;
        let other = (0..n).filter(|_| believed_action(&t, &noisy, Goal, 0.0, &mut rng) != Action::Sweep).count();
        assert!((other as f64 / n as f64 - 0.2).abs() < 0.01, "{other}");
        assert_eq!(PerceptionModel::thesis().error_px(Expertise::None, 2), 15.0 * 0.6);
        assert_eq!(PerceptionModel::thesis().table_reading, Goal);
    }
}
