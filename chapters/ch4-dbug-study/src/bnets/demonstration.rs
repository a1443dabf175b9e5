//! One kinesthetic demonstration as the robot records it between START and
//! DONE: which zones held a bug at every tick (what the perception
//! behaviours watch) and when each arm was moved (what the arm behaviours
//! watch). Nicolescu & Mataric's robot "follows the teacher and watches
//! every known behavior's postconditions"; this is what it watches.

use serde::{Deserialize, Serialize};

use super::behavior::Behavior;

/// The record of one START…DONE.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DemonstrationRecord {
    /// Per tick from START: (a bug in the pickup zone, a bug in the sweep zone).
    pub occupancy: Vec<(bool, bool)>,
    /// Arm motions: behaviour, first tick, last tick (ticks from START).
    pub motions: Vec<(Behavior, u32, u32)>,
}

impl DemonstrationRecord {
    /// An empty record (START).
    pub fn new() -> DemonstrationRecord {
        DemonstrationRecord::default()
    }

    /// Records one tick's zone occupancy.
    pub fn observe(&mut self, pickup: bool, sweep: bool) {
        self.occupancy.push((pickup, sweep));
    }

    /// Records an arm motion over ticks `[start, end]`.
    pub fn motion(&mut self, behavior: Behavior, start: u32, end: u32) {
        self.motions.push((behavior, start, end));
    }

    /// Length in ticks.
    pub fn len(&self) -> u32 {
        self.occupancy.len() as u32
    }

    /// Whether nothing was recorded.
    pub fn is_empty(&self) -> bool {
        self.occupancy.is_empty()
    }
}
