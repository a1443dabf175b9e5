//! The behaviours of the thesis's Behavior Networks on DBug (section 4.4)
//! with their preconditions and effects (postconditions).
//!
//! "for the agent to understand that there was a hexbug to pick-up, we used
//! a “found a bug in pick-up zone” behavior. Likewise … a “found a bug in
//! sweep zone” behavior. The precondition for these behaviors to be
//! activated was to detect a hexbug in the pick-up or sweep zone." The two
//! arm behaviours are the robot's pickup and sweep; waiting is not a
//! behaviour ("the wait action was implicitly taught").
//!
//! Effects, the programmer's pre-coded knowledge the thesis says BNets
//! needs: a perception behaviour's effect is "a bug is in its zone" (true
//! while one is); an arm behaviour's effect is "the motion has just been
//! completed", true for [`EFFECT_HOLD_TICKS`] after it ends (one perception
//! cycle of the robot, our choice).

use serde::{Deserialize, Serialize};

use crate::dbug::{Action, Zone};

/// How long an arm behaviour's effect stays true after the motion (ticks).
pub const EFFECT_HOLD_TICKS: u32 = 10;

/// A behaviour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Behavior {
    /// "Found a bug in pick-up zone" (FBIPZ).
    FoundBugInPickupZone,
    /// "Found a bug in sweep zone" (FBISZ).
    FoundBugInSweepZone,
    /// The pickup motion (P-UP).
    PickUp,
    /// The sweep motion (SWEEP).
    Sweep,
}

impl Behavior {
    /// The thesis's abbreviation (Figure 4.5).
    pub fn abbreviation(self) -> &'static str {
        match self {
            Behavior::FoundBugInPickupZone => "FBIPZ",
            Behavior::FoundBugInSweepZone => "FBISZ",
            Behavior::PickUp => "P-UP",
            Behavior::Sweep => "SWEEP",
        }
    }

    /// The zone a perception behaviour detects.
    pub fn zone(self) -> Option<Zone> {
        match self {
            Behavior::FoundBugInPickupZone => Some(Zone::Pickup),
            Behavior::FoundBugInSweepZone => Some(Zone::Sweep),
            _ => None,
        }
    }

    /// The robot action an arm behaviour performs.
    pub fn action(self) -> Option<Action> {
        match self {
            Behavior::PickUp => Some(Action::Pickup),
            Behavior::Sweep => Some(Action::Sweep),
            _ => None,
        }
    }

    /// The arm behaviour of an action (none for wait).
    pub fn of_action(a: Action) -> Option<Behavior> {
        match a {
            Action::Pickup => Some(Behavior::PickUp),
            Action::Sweep => Some(Behavior::Sweep),
            Action::Wait => None,
        }
    }
}
