//! The five guidance regions of the teaching interface and the actions each
//! allows (Table 3.1).
//!
//! "Our interface highlights five rectangular regions as potential guidance
//! targets. The teacher provides guidance by right-clicking within the
//! highlighted boxes." A guidance message restricts the learner's next
//! choice to the region's actions that are legal (Algorithm 1, line 11);
//! when none of them is legal the message is ignored.
//!
//! | guidance | action set |
//! |---|---|
//! | Zone 1 | LLeft, LDrop |
//! | Zone 2 | LPutDown, LPickUp, RPutDown, RPickUp, TakePicture |
//! | Zone 3 | RRight, RDrop |
//! | Left Shoulder | LPickUp, LRight, LLeft, LPutDown, LDrop |
//! | Right Shoulder | RPickUp, RRight, RLeft, RPutDown, RDrop |

use serde::{Deserialize, Serialize};

use crate::nao::{Action, ActionSet};

/// A guidance target (Table 3.1's rows).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum GuidanceRegion {
    Zone1,
    Zone2,
    Zone3,
    LeftShoulder,
    RightShoulder,
}

impl GuidanceRegion {
    /// The regions in Table 3.1's order.
    pub const ALL: [GuidanceRegion; 5] = [
        GuidanceRegion::Zone1,
        GuidanceRegion::Zone2,
        GuidanceRegion::Zone3,
        GuidanceRegion::LeftShoulder,
        GuidanceRegion::RightShoulder,
    ];

    /// Table 3.1's name.
    pub fn name(self) -> &'static str {
        match self {
            GuidanceRegion::Zone1 => "Zone 1",
            GuidanceRegion::Zone2 => "Zone 2",
            GuidanceRegion::Zone3 => "Zone 3",
            GuidanceRegion::LeftShoulder => "Left Shoulder",
            GuidanceRegion::RightShoulder => "Right Shoulder",
        }
    }

    /// The actions the region allows (Table 3.1).
    pub const fn actions(self) -> ActionSet {
        use Action::*;
        match self {
            GuidanceRegion::Zone1 => ActionSet::of(&[LLeft, LDrop]),
            GuidanceRegion::Zone2 => ActionSet::of(&[LPutDown, LPickUp, RPutDown, RPickUp, TakePicture]),
            GuidanceRegion::Zone3 => ActionSet::of(&[RRight, RDrop]),
            GuidanceRegion::LeftShoulder => ActionSet::of(&[LPickUp, LRight, LLeft, LPutDown, LDrop]),
            GuidanceRegion::RightShoulder => ActionSet::of(&[RPickUp, RRight, RLeft, RPutDown, RDrop]),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Table 3.1 as printed in the thesis (thesis.txt, lines 338–342),
    /// action names in the printed order.
    const TABLE_3_1: [(&str, &[&str]); 5] = [
        ("Zone 1", &["LLeft", "LDrop"]),
        ("Zone 2", &["LPutDown", "LPickUp", "RPutDown", "RPickUp", "TakePicture"]),
        ("Zone 3", &["RRight", "RDrop"]),
        ("Left Shoulder", &["LPickUp", "LRight", "LLeft", "LPutDown", "LDrop"]),
        ("Right Shoulder", &["RPickUp", "RRight", "RLeft", "RPutDown", "RDrop"]),
    ];

    #[test]
    fn every_region_allows_exactly_table_3_1_s_actions() {
        assert_eq!(GuidanceRegion::ALL.len(), TABLE_3_1.len());
        for (region, (name, printed)) in GuidanceRegion::ALL.into_iter().zip(TABLE_3_1) {
            assert_eq!(region.name(), name);
            let mut expected: Vec<&str> = printed.to_vec();
            expected.sort_unstable();
            let mut ours: Vec<&str> = region.actions().iter().map(Action::name).collect();
            ours.sort_unstable();
            assert_eq!(ours, expected, "{name}");
        }
    }

    #[test]
    fn every_action_is_in_some_region_and_no_region_is_a_single_action() {
        for a in Action::ALL {
            assert!(GuidanceRegion::ALL.iter().any(|r| r.actions().contains(a)), "{}", a.name());
        }
        // "Guidance … always restricts the list of available actions but never
        // reduces action selection to a single choice."
        for r in GuidanceRegion::ALL {
            assert!(r.actions().len() >= 2 && r.actions().len() < Action::COUNT);
        }
    }
}
