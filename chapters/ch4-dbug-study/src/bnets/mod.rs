//! Behavior Networks from kinesthetic demonstration (Nicolescu & Mataric
//! 2002, 2003), as the thesis ran them on DBug (sections 4.2, 4.4, 4.5).
//!
//! The teacher demonstrates between START and DONE by moving the robot's
//! arms; the robot learns a network of behaviours ([`network::Branch`])
//! from what it observed ([`demonstration::DemonstrationRecord`]). "Users
//! were given the option of deleting the whole network and re-teaching the
//! task, or keeping the current knowledge and adding new demonstrations on
//! top of the existing network", and "the user demonstrations do not
//! accumulate over time" in the sense that the policy is the plan of the
//! START…DONE sequences kept, not a statistic that grows with practice. So
//! the network here is the list of branches of the kept demonstrations,
//! rebuilt from them at each new demonstration, tried in the order they were
//! taught ([`BehaviorNetwork::decide`]); erasing drops them all. Nicolescu &
//! Mataric merge several demonstrations into one graph through their longest
//! common subsequence; the thesis does not say whether its implementation
//! did, and keeping branches apart is the simpler reading (listed in the
//! report).
//!
//! Waiting is implicit: when no branch can run a behaviour, the robot waits.

pub mod behavior;
pub mod demonstration;
pub mod network;

use serde::{Deserialize, Serialize};

use crate::dbug::{Action, Zone};
use crate::evaluation::{Accuracy, score_zones};
pub use behavior::Behavior;
pub use demonstration::DemonstrationRecord;
pub use network::{Branch, BranchRun, Link, LinkKind, Node, World};

/// The learned network: one branch per kept demonstration.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BehaviorNetwork {
    pub branches: Vec<Branch>,
    runs: Vec<BranchRun>,
    next_id: u32,
}

impl BehaviorNetwork {
    /// An empty network (the robot only waits).
    pub fn new() -> BehaviorNetwork {
        BehaviorNetwork { branches: Vec::new(), runs: Vec::new(), next_id: 1 }
    }

    /// A network of already learned branches (e.g. from a stored session).
    pub fn from_branches(branches: Vec<Branch>) -> BehaviorNetwork {
        let next_id = branches.iter().flat_map(|b| b.nodes.iter().map(|n| n.id + 1)).max().unwrap_or(1);
        let runs = branches.iter().map(BranchRun::new).collect();
        BehaviorNetwork { branches, runs, next_id }
    }

    /// Deletes the whole network (ids keep counting, as the thesis's unique ids).
    pub fn erase(&mut self) {
        self.branches.clear();
        self.runs.clear();
    }

    /// Adds a demonstration on top of the kept ones and rebuilds the network's runs.
    pub fn add(&mut self, demo: &DemonstrationRecord) {
        let b = Branch::learn(demo, self.next_id);
        self.next_id += b.nodes.len() as u32;
        self.branches.push(b);
        self.runs = self.branches.iter().map(BranchRun::new).collect();
    }

    /// Number of nodes over all branches.
    pub fn num_nodes(&self) -> usize {
        self.branches.iter().map(|b| b.nodes.len()).sum()
    }

    /// The robot's action at a decision: the first branch, in teaching order,
    /// that can run an arm behaviour; `None`: wait.
    pub fn decide(&mut self, world: &World) -> Option<Action> {
        for (b, run) in self.branches.iter().zip(self.runs.iter_mut()) {
            if let Some(a) = run.step(b, world) {
                return Some(a);
            }
        }
        None
    }

    /// What a fresh network does in a static state with one bug in `zone`
    /// (or none): its first action, `None` for wait.
    pub fn action_in(&self, zone: Option<Zone>) -> Option<Action> {
        let world = World::of_zone(zone);
        self.branches.iter().find_map(|b| BranchRun::new(b).step(b, &world))
    }

    /// The final policy per zone ([`Zone::ALL`] order), waiting made explicit.
    pub fn policy(&self) -> [Action; 3] {
        Zone::ALL.map(|z| self.action_in(if z == Zone::Wait { None } else { Some(z) }).unwrap_or(Action::Wait))
    }

    /// The final policy's accuracy: preconditions are zones, so it is a sum of whole-zone shares.
    pub fn accuracy(&self) -> Accuracy {
        score_zones(self.policy().map(Some))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_demonstrations_teach_the_whole_task() {
        // The expert of section 4.4: one demonstration for pick-up, one for sweep, bugs placed by hand.
        let mut pick = DemonstrationRecord::new();
        for t in 0..95 {
            pick.observe(t < 45, false);
        }
        pick.motion(Behavior::PickUp, 5, 94);
        let mut sweep = DemonstrationRecord::new();
        for t in 0..60 {
            sweep.observe(t >= 40, t < 40);
        }
        sweep.motion(Behavior::Sweep, 5, 54);
        let mut net = BehaviorNetwork::new();
        assert_eq!(net.accuracy().overall, score_zones([None, None, Some(Action::Wait)]).overall);
        net.add(&pick);
        assert_eq!(net.policy(), [Action::Pickup, Action::Wait, Action::Wait]);
        net.add(&sweep);
        assert_eq!(net.policy(), [Action::Pickup, Action::Sweep, Action::Wait]);
        assert_eq!(net.accuracy().overall, 100.0);
        let ids: Vec<u32> = net.branches.iter().flat_map(|b| b.nodes.iter().map(|n| n.id)).collect();
        assert_eq!(ids, [1, 2, 3, 4, 5]);
        net.erase();
        assert_eq!(net.policy(), [Action::Wait; 3]);
        assert_eq!(net.accuracy().overall, 77.083_333_333_333_33);
    }
}
