//! The robot's three preprogrammed actions (section 4.3.2) and simulated time.
//!
//! "The pickup action took ~9 seconds and the sweep action took ~5 seconds
//! from start to finish", and the wait action is "waiting for 1 second".
//! Time runs in ticks of 0.1 s, so every duration is a whole number of ticks.

use serde::{Deserialize, Serialize};

/// Ticks per simulated second.
pub const TICKS_PER_SECOND: u32 = 10;

/// `seconds` as whole ticks (rounded to the nearest tick, at least 0).
pub fn seconds_to_ticks(seconds: f64) -> u32 {
    (seconds * f64::from(TICKS_PER_SECOND)).round().max(0.0) as u32
}

/// An action of the robot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Action {
    /// Reach down with the magnet in the right hand at the pickup mark and lift.
    Pickup,
    /// Sweep inward, toward the pickup mark, with the brush in the left hand.
    Sweep,
    /// Do nothing for one second.
    Wait,
}

impl Action {
    /// In the thesis's order (Figure 4.2: pick-up, sweep, wait).
    pub const ALL: [Action; 3] = [Action::Pickup, Action::Sweep, Action::Wait];

    /// The index `0..3` (learners' action numbers).
    pub fn index(self) -> usize {
        match self {
            Action::Pickup => 0,
            Action::Sweep => 1,
            Action::Wait => 2,
        }
    }

    /// The action with index `i` (`i < 3`).
    pub fn from_index(i: usize) -> Action {
        Action::ALL[i]
    }

    /// Its duration in ticks: 9 s, 5 s, 1 s.
    pub fn duration_ticks(self) -> u32 {
        match self {
            Action::Pickup => 90,
            Action::Sweep => 50,
            Action::Wait => 10,
        }
    }

    /// The label the thesis's figures use.
    pub fn label(self) -> &'static str {
        match self {
            Action::Pickup => "pick-up",
            Action::Sweep => "sweep",
            Action::Wait => "wait",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_are_the_thesis_seconds() {
        assert_eq!(Action::Pickup.duration_ticks(), seconds_to_ticks(9.0));
        assert_eq!(Action::Sweep.duration_ticks(), seconds_to_ticks(5.0));
        assert_eq!(Action::Wait.duration_ticks(), seconds_to_ticks(1.0));
        for (i, a) in Action::ALL.iter().enumerate() {
            assert_eq!(a.index(), i);
            assert_eq!(Action::from_index(i), *a);
        }
    }
}
