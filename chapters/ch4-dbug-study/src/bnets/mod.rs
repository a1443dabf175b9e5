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
//!
//! Scoring ([`BnetsParams`]): a network's policy in a zone is what it does
//! from a state with one bug there (none for the wait zone), held still.
//! By default the zone is correct only if every action the network takes
//! in one pass from that state is the zone's (the thesis counts "executing
//! a pickup action after every sweep, even if there is no bug in the pickup
//! zone" as a failure); the `bnets-scoring` reading scores the first action
//! alone, and `bnets-wait-credit` whether a network that moves an arm earns
//! the wait zone (see [`crate::readings`]).

pub mod behavior;
pub mod demonstration;
pub mod network;

use serde::{Deserialize, Serialize};

use crate::dbug::{Action, Zone};
use crate::evaluation::{Accuracy, score_zones};
pub use behavior::Behavior;
pub use demonstration::DemonstrationRecord;
pub use network::{Branch, BranchRun, Link, LinkKind, Node, NodeOrder, World};

/// How a zone's policy is read off a network (the `bnets-scoring` reading).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PassScoring {
    /// Correct only if every action of one pass from the zone's state is the zone's.
    #[default]
    FullPass,
    /// The network's first action in the zone's state.
    FirstAction,
}

/// Whether a network that moves an arm earns the wait zone (the `bnets-wait-credit` reading).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum WaitCredit {
    /// The wait zone is scored as every zone: correct where the network waits.
    #[default]
    Scored,
    /// A network with an arm behaviour earns no wait credit (only the empty network does).
    EmptyNetworkOnly,
}

/// Behavior Networks' readings: node order and how a final network is scored.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct BnetsParams {
    pub order: NodeOrder,
    pub scoring: PassScoring,
    pub wait_credit: WaitCredit,
}

/// The learned network: one branch per kept demonstration.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BehaviorNetwork {
    pub branches: Vec<Branch>,
    runs: Vec<BranchRun>,
    next_id: u32,
    order: NodeOrder,
}

impl BehaviorNetwork {
    /// An empty network (the robot only waits) whose branches order simultaneous motions by `order`.
    pub fn new(order: NodeOrder) -> BehaviorNetwork {
        BehaviorNetwork { branches: Vec::new(), runs: Vec::new(), next_id: 1, order }
    }

    /// A network of already learned branches (e.g. from a stored session).
    pub fn from_branches(branches: Vec<Branch>) -> BehaviorNetwork {
        let next_id = branches.iter().flat_map(|b| b.nodes.iter().map(|n| n.id + 1)).max().unwrap_or(1);
        let runs = branches.iter().map(BranchRun::new).collect();
        BehaviorNetwork { branches, runs, next_id, order: NodeOrder::default() }
    }

    /// Deletes the whole network (ids keep counting, as the thesis's unique ids).
    pub fn erase(&mut self) {
        self.branches.clear();
        self.runs.clear();
    }

    /// Adds a demonstration on top of the kept ones and rebuilds the network's runs.
    pub fn add(&mut self, demo: &DemonstrationRecord) {
        let b = Branch::learn(demo, self.next_id, self.order);
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

    /// The actions of one pass of a fresh network in a static state with
    /// one bug in `zone` (or none), each decision at the tick the previous
    /// action ended: until it waits, or until it has taken as many actions
    /// as it has arm nodes (each arm node runs once per pass).
    pub fn pass_in(&self, zone: Option<Zone>) -> Vec<Action> {
        let arms = self.branches.iter().flat_map(|b| &b.nodes).filter(|n| n.behavior.action().is_some()).count();
        let mut runs: Vec<BranchRun> = self.branches.iter().map(BranchRun::new).collect();
        let mut world = World::of_zone(zone);
        let mut out = Vec::new();
        while out.len() < arms {
            let next = self.branches.iter().zip(runs.iter_mut()).find_map(|(b, r)| r.step(b, &world));
            let Some(a) = next else { break };
            out.push(a);
            world.tick += a.duration_ticks();
        }
        out
    }

    /// What the robot does per zone ([`Zone::ALL`] order): every action of one pass.
    pub fn behaviour(&self) -> [Vec<Action>; 3] {
        Zone::ALL.map(|z| self.pass_in(if z == Zone::Wait { None } else { Some(z) }))
    }

    /// The final policy per zone ([`Zone::ALL`] order), waiting made
    /// explicit, by its first action.
    pub fn policy(&self) -> [Action; 3] {
        Zone::ALL.map(|z| self.action_in(if z == Zone::Wait { None } else { Some(z) }).unwrap_or(Action::Wait))
    }

    /// The final policy per zone as `scoring` reads it: `None` where a full
    /// pass mixes actions (no single action of its own).
    pub fn scored_policy(&self, scoring: PassScoring) -> [Option<Action>; 3] {
        match scoring {
            PassScoring::FirstAction => self.policy().map(Some),
            PassScoring::FullPass => self.behaviour().map(|pass| match pass.first() {
                None => Some(Action::Wait),
                Some(&a) if pass.iter().all(|&b| b == a) => Some(a),
                Some(_) => None,
            }),
        }
    }

    /// The final policy's accuracy under the default readings.
    pub fn accuracy(&self) -> Accuracy {
        self.accuracy_with(&BnetsParams::default())
    }

    /// The final policy's accuracy: preconditions are zones, so it is a sum
    /// of whole-zone shares.
    pub fn accuracy_with(&self, params: &BnetsParams) -> Accuracy {
        let mut policy = self.scored_policy(params.scoring);
        let moves_an_arm = self.branches.iter().flat_map(|b| &b.nodes).any(|n| n.behavior.action().is_some());
        if params.wait_credit == WaitCredit::EmptyNetworkOnly && moves_an_arm {
            policy[Zone::Wait.index()] = None;
        }
        score_zones(policy)
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
        let mut net = BehaviorNetwork::new(NodeOrder::Postcondition);
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

    #[test]
    fn a_pickup_after_every_sweep_fails_the_sweep_zone_in_a_full_pass() {
        // The thesis's example: both arms at once while a bug is in the sweep zone.
        let mut d = DemonstrationRecord::new();
        for t in 0..100 {
            d.observe(false, t < 20);
        }
        d.motion(Behavior::Sweep, 2, 51);
        d.motion(Behavior::PickUp, 2, 91);
        let mut net = BehaviorNetwork::new(NodeOrder::Postcondition);
        net.add(&d);
        assert_eq!(net.behaviour()[Zone::Sweep.index()], [Action::Sweep, Action::Pickup]);
        let first = net.accuracy_with(&BnetsParams { scoring: PassScoring::FirstAction, ..BnetsParams::default() });
        assert_eq!(first.zone(Zone::Sweep), 100.0, "the first action alone calls it a correct sweep");
        assert_eq!(net.accuracy().zone(Zone::Sweep), 0.0, "a full pass sees the pickup after it");
        assert_eq!(net.accuracy().zone(Zone::Wait), 100.0);
        // A pickup network earns the wait zone unless arm networks get no wait credit.
        let mut p = DemonstrationRecord::new();
        for t in 0..95 {
            p.observe(t < 45, false);
        }
        p.motion(Behavior::PickUp, 5, 94);
        let mut pick = BehaviorNetwork::new(NodeOrder::Postcondition);
        pick.add(&p);
        assert_eq!(pick.accuracy().overall, 87.5);
        let strict = BnetsParams { wait_credit: WaitCredit::EmptyNetworkOnly, ..BnetsParams::default() };
        assert!((pick.accuracy_with(&strict).overall - 10.416_666).abs() < 1e-4);
        assert_eq!(
            BehaviorNetwork::new(NodeOrder::Postcondition).accuracy_with(&strict).overall,
            77.083_333_333_333_33
        );
    }
}
