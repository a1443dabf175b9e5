//! How long each action takes, so that training time comes out in minutes.
//!
//! The thesis gives one number about the robot's pace: "each action had an
//! average time of 9.8 seconds" (section 3.5, the large state space with
//! guidance). Training time (Table 3.2) is an outcome and is never used here.
//!
//! **The time model.** A step of Algorithm 1 is a wait for guidance (lines
//! 5–9), the action, and a wait for reward (lines 25–31). The waits are the
//! same in every step and every condition (the robot waits whether or not
//! the teacher speaks); the action's own time depends on what it moves. In
//! relative units ([`Durations::nominal`], our choice, fixed before any
//! learner ran):
//!
//! | part | units | why |
//! |---|---|---|
//! | both waiting windows, every step | 1 | fixed by the interface, not by the action |
//! | TakePicture | 1 | capture, transfer to the PC, SURF and contour extraction |
//! | xLeft, xRight | 1 | one zone-to-zone swing of the arm: the unit |
//! | xPickUp, xPutDown | 1.5 | lower to the table, make or break the magnet's contact, lift |
//! | xDrop | 1 | tilt over the cup and release |
//!
//! **Calibration.** One number, the length of a unit in seconds, is set so
//! that the actions of a correct sorting (the scripted expert's plan from
//! the start, over many objects) average 9.8 s ([`calibrate_unit`]). The
//! shipped [`UNIT_SECONDS`] is its result and a test reruns it. A correct
//! sort from rest is always TakePicture, a move in, a pick-up, a move out and
//! a drop (2.1 units per action on average), so the unit is 9.8 / 2.1 ≈
//! 4.67 s: a swing takes 9.3 s with the waits, a pick-up 11.7 s. The
//! learner's own mix of actions (with its mistakes) then gives its mean
//! seconds per action, which the report compares with 9.8 s.

use rand::Rng;
use serde::{Deserialize, Serialize};

use super::action::{Action, ActionKind};
use super::perception::{Perception, StateSpace};
use super::plan::SortingPlan;
use super::world::NaoSorting;

/// "Each action had an average time of 9.8 seconds."
pub const THESIS_MEAN_ACTION_SECONDS: f64 = 9.8;

/// Seconds per unit: the calibration's result (see [`calibrate_unit`]).
pub const UNIT_SECONDS: f64 = 4.666_666_666_666_667;

/// The seed of the calibration run (no experiment uses it).
pub const CALIBRATION_SEED: u64 = 0x6e61_6f74_696d_6521; // "naotime!"

/// Objects sorted in the calibration run.
pub const CALIBRATION_OBJECTS: usize = 600;

/// Per-action durations: units per part and the unit's length.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Durations {
    /// Seconds per unit (calibrated: [`UNIT_SECONDS`]).
    pub unit_seconds: f64,
    /// The waits for guidance and reward, every step.
    pub wait_units: f64,
    /// TakePicture.
    pub picture_units: f64,
    /// xLeft and xRight.
    pub move_units: f64,
    /// xPickUp.
    pub pick_up_units: f64,
    /// xPutDown.
    pub put_down_units: f64,
    /// xDrop.
    pub drop_units: f64,
}

impl Durations {
    /// The relative units of the module docs, with a unit of one second.
    pub const fn nominal() -> Durations {
        Durations {
            unit_seconds: 1.0,
            wait_units: 1.0,
            picture_units: 1.0,
            move_units: 1.0,
            pick_up_units: 1.5,
            put_down_units: 1.5,
            drop_units: 1.0,
        }
    }

    /// The calibrated model: nominal units, unit of [`UNIT_SECONDS`].
    pub const fn thesis() -> Durations {
        Durations { unit_seconds: UNIT_SECONDS, ..Durations::nominal() }
    }

    /// Units of one step with `action`.
    pub fn units(&self, action: Action) -> f64 {
        let own = match action.kind() {
            ActionKind::Picture => self.picture_units,
            ActionKind::MoveLeft | ActionKind::MoveRight => self.move_units,
            ActionKind::PickUp => self.pick_up_units,
            ActionKind::PutDown => self.put_down_units,
            ActionKind::Drop => self.drop_units,
        };
        self.wait_units + own
    }

    /// Seconds of one step with `action`.
    pub fn seconds(&self, action: Action) -> f64 {
        self.units(action) * self.unit_seconds
    }

    /// Seconds per action, by action number.
    pub fn table(&self) -> [f64; Action::COUNT] {
        std::array::from_fn(|i| self.seconds(Action::from_index(i)))
    }

    /// Whether every part is a finite positive number.
    pub fn is_valid(&self) -> bool {
        [
            self.unit_seconds,
            self.wait_units,
            self.picture_units,
            self.move_units,
            self.pick_up_units,
            self.put_down_units,
            self.drop_units,
        ]
        .iter()
        .all(|v| v.is_finite() && *v > 0.0)
    }
}

/// Mean units per action when `objects` objects are sorted by always taking
/// the first correct action of a shortest plan, from the session's start.
pub fn expert_mean_units<R: Rng + ?Sized>(units: &Durations, objects: usize, rng: &mut R) -> f64 {
    let plan = SortingPlan::shared();
    let mut world = NaoSorting::new(Perception::new(StateSpace::Large, 0.0));
    world.reset(rng);
    let (mut total, mut actions, mut sorted) = (0.0, 0usize, 0usize);
    while sorted < objects {
        let a = plan
            .correct(&world.physical(), world.current_object().class)
            .iter()
            .next()
            .expect("every reachable configuration has a plan");
        total += units.units(a);
        actions += 1;
        if world.act(a, rng).sorted.is_some() {
            sorted += 1;
        }
    }
    total / actions as f64
}

/// The unit length that makes a correct sorting's actions average 9.8 s.
pub fn calibrate_unit(objects: usize) -> f64 {
    let mut rng = rlfd_env::random::seeded(CALIBRATION_SEED);
    THESIS_MEAN_ACTION_SECONDS / expert_mean_units(&Durations::nominal(), objects, &mut rng)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_unit_is_the_calibrated_one() {
        let unit = calibrate_unit(CALIBRATION_OBJECTS);
        assert!((unit - UNIT_SECONDS).abs() < 1e-12, "calibration gives {unit}, shipped {UNIT_SECONDS}");
    }

    #[test]
    fn a_correct_sorting_averages_9_8_seconds_per_action() {
        // Another seed and length than the calibration's: the mean is the same.
        let mut rng = rlfd_env::random::seeded(99);
        let seconds = expert_mean_units(&Durations::nominal(), 200, &mut rng) * UNIT_SECONDS;
        assert!((seconds - THESIS_MEAN_ACTION_SECONDS).abs() < 1e-9, "{seconds}");
    }

    #[test]
    fn seconds_follow_the_table() {
        let d = Durations::thesis();
        assert!(d.is_valid());
        assert!((d.seconds(Action::TakePicture) - 2.0 * UNIT_SECONDS).abs() < 1e-12);
        assert!((d.seconds(Action::LPickUp) - 2.5 * UNIT_SECONDS).abs() < 1e-12);
        assert_eq!(d.seconds(Action::RPutDown), d.seconds(Action::LPickUp));
        assert_eq!(d.seconds(Action::RRight), d.seconds(Action::LDrop));
        assert_eq!(d.table()[Action::RDrop.index()], d.seconds(Action::RDrop));
        let bad = Durations { drop_units: 0.0, ..d };
        assert!(!bad.is_valid());
    }
}
