//! A behaviour network learned from one demonstration (Nicolescu & Mataric
//! 2003; spec `algorithms.md` §8), and its execution.
//!
//! Learning: every behaviour whose postconditions become true during the
//! demonstration becomes a node, in temporal order: a perception behaviour
//! each time its zone goes from empty to holding a bug (and at START if it
//! already holds one), an arm behaviour for each motion. For each earlier
//! node A and later node B:
//! - A's effect true throughout B's interval: **permanent** link;
//! - true at B's start but not throughout: **enabling**;
//! - otherwise: **ordering** (A must have completed earlier).
//!
//! (A perception node has no duration; a link to it is enabling or ordering.)
//!
//! Order: a node's place is when the robot detects it: a perception
//! behaviour when its postcondition becomes true, an arm behaviour when the
//! teacher starts moving the arm. Two motions that start together (the
//! users who "moved both arms at the same time") are ordered by
//! [`NodeOrder`], a reading: by default by when each one's postcondition is
//! met (the sweep, shorter, first; the thesis's own example of the
//! dependency this creates is "a pickup action after every sweep").
//!
//! Execution: activation spreads backwards from DONE along the links; a node
//! runs when it is active, not yet done in this pass, and its links hold:
//! ordering predecessors done, enabling and permanent predecessors done with
//! their effects true now; a perception node also needs its own
//! precondition (a bug in its zone now). Perception nodes complete at once;
//! an arm node is the robot's action. When every node is done, the network
//! restarts (the thesis's "restart" pseudo-behaviour). Nothing runnable: the
//! robot waits.

use serde::{Deserialize, Serialize};

use super::behavior::{Behavior, EFFECT_HOLD_TICKS};
use super::demonstration::DemonstrationRecord;
use crate::dbug::{Action, Zone};

/// How two arm motions that start at the same tick are ordered (the
/// `bnets-order` reading, [`crate::readings::BNETS_ORDER`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum NodeOrder {
    /// By when each motion's postcondition ("the motion has just been
    /// completed") is met: the shorter first.
    #[default]
    Postcondition,
    /// The pickup before the sweep, whatever their ends (a fixed tie-break,
    /// the review's alternative).
    PickupFirst,
}

/// A node: a behaviour with its unique id (Figure 4.5's `P-UP_7`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Node {
    pub id: u32,
    pub behavior: Behavior,
    /// Its interval in the demonstration (ticks from START).
    pub start: u32,
    pub end: u32,
}

/// A link's type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum LinkKind {
    Permanent,
    Enabling,
    Ordering,
}

/// A precondition link from an earlier node to a later one (node indices).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Link {
    pub from: usize,
    pub to: usize,
    pub kind: LinkKind,
}

/// The network of one demonstration: START → nodes → DONE.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Branch {
    pub nodes: Vec<Node>,
    pub links: Vec<Link>,
    /// Nodes with a path to DONE (activation reaches them).
    pub active: Vec<bool>,
}

/// What the robot perceives at a decision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct World {
    /// The bug nearest the mark (the robot's state) is in the pickup zone.
    pub pickup: bool,
    /// The bug nearest the mark is in the sweep zone.
    pub sweep: bool,
    /// The current tick (for "just completed" effects).
    pub tick: u32,
}

impl World {
    /// The static world of one state's zone (one bug there, or none).
    pub fn of_zone(zone: Option<Zone>) -> World {
        World { pickup: zone == Some(Zone::Pickup), sweep: zone == Some(Zone::Sweep), tick: 0 }
    }

    fn holds(&self, zone: Zone) -> bool {
        match zone {
            Zone::Pickup => self.pickup,
            Zone::Sweep => self.sweep,
            Zone::Wait => false,
        }
    }
}

impl Branch {
    /// Learns a branch from a demonstration; node ids start at `first_id`.
    pub fn learn(demo: &DemonstrationRecord, first_id: u32, order: NodeOrder) -> Branch {
        let mut nodes: Vec<Node> = Vec::new();
        let mut prev = (false, false);
        for (t, &(p, s)) in demo.occupancy.iter().enumerate() {
            let t = t as u32;
            if p && (t == 0 || !prev.0) {
                nodes.push(Node { id: 0, behavior: Behavior::FoundBugInPickupZone, start: t, end: t });
            }
            if s && (t == 0 || !prev.1) {
                nodes.push(Node { id: 0, behavior: Behavior::FoundBugInSweepZone, start: t, end: t });
            }
            prev = (p, s);
        }
        for &(b, start, end) in &demo.motions {
            nodes.push(Node { id: 0, behavior: b, start, end });
        }
        // Temporal order; at equal starts perception first (it is what the
        // arm reacts to), then the motions as `order` says.
        let tie = |n: &Node| match order {
            NodeOrder::Postcondition => (n.end, 0),
            NodeOrder::PickupFirst => (u32::from(n.behavior != Behavior::PickUp), n.end),
        };
        nodes.sort_by_key(|n| (n.start, n.behavior.action().is_some(), tie(n), n.behavior));
        for (k, n) in nodes.iter_mut().enumerate() {
            n.id = first_id + k as u32;
        }
        let effect = |a: &Node, t: u32| -> bool {
            match a.behavior.zone() {
                Some(Zone::Pickup) => demo.occupancy.get(t as usize).is_some_and(|o| o.0),
                Some(Zone::Sweep) => demo.occupancy.get(t as usize).is_some_and(|o| o.1),
                _ => t > a.end && t <= a.end + EFFECT_HOLD_TICKS,
            }
        };
        let mut links = Vec::new();
        for j in 0..nodes.len() {
            for i in 0..j {
                let (a, b) = (&nodes[i], &nodes[j]);
                let at_start = effect(a, b.start);
                let kind = if !at_start {
                    LinkKind::Ordering
                } else if b.behavior.zone().is_none() && (b.start..=b.end).all(|t| effect(a, t)) {
                    LinkKind::Permanent
                } else {
                    LinkKind::Enabling
                };
                links.push(Link { from: i, to: j, kind });
            }
        }
        let active = spread_activation(nodes.len(), &links);
        Branch { nodes, links, active }
    }

    /// Links into node `j`.
    fn incoming(&self, j: usize) -> impl Iterator<Item = &Link> {
        self.links.iter().filter(move |l| l.to == j)
    }

    /// The links a drawing needs: each node to the next, plus every
    /// enabling and permanent link (ordering is transitive).
    pub fn drawn_links(&self) -> Vec<Link> {
        self.links.iter().filter(|l| l.to == l.from + 1 || l.kind != LinkKind::Ordering).copied().collect()
    }
}

/// Activation from DONE backwards: DONE follows every node (each must run
/// before the network ends), and activation passes from a node to its
/// predecessors. Returns which nodes it reaches.
fn spread_activation(n: usize, links: &[Link]) -> Vec<bool> {
    // DONE's predecessors are the nodes with no successor (the last ones).
    let mut active = vec![false; n];
    let mut frontier: Vec<usize> = (0..n).filter(|&i| !links.iter().any(|l| l.from == i)).collect();
    while let Some(i) = frontier.pop() {
        if active[i] {
            continue;
        }
        active[i] = true;
        frontier.extend(links.iter().filter(|l| l.to == i).map(|l| l.from));
    }
    active
}

/// A branch's progress through one pass.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct BranchRun {
    /// Per node: the tick it completed in this pass.
    pub done_at: Vec<Option<u32>>,
}

impl BranchRun {
    /// A fresh pass.
    pub fn new(branch: &Branch) -> BranchRun {
        BranchRun { done_at: vec![None; branch.nodes.len()] }
    }

    fn effect_now(&self, branch: &Branch, i: usize, world: &World) -> bool {
        match branch.nodes[i].behavior.zone() {
            Some(z) => world.holds(z),
            None => self.done_at[i].is_some_and(|t| world.tick.saturating_sub(t) <= EFFECT_HOLD_TICKS),
        }
    }

    fn runnable(&self, branch: &Branch, j: usize, world: &World) -> bool {
        if !branch.active[j] || self.done_at[j].is_some() {
            return false;
        }
        if let Some(z) = branch.nodes[j].behavior.zone()
            && !world.holds(z)
        {
            return false;
        }
        branch.incoming(j).all(|l| {
            self.done_at[l.from].is_some() && (l.kind == LinkKind::Ordering || self.effect_now(branch, l.from, world))
        })
    }

    /// Runs the branch at a decision: completes the perception nodes that
    /// can run and returns the first arm action that can, marking it done
    /// at `world.tick + duration` (when its motion ends). `None`: nothing to do now.
    pub fn step(&mut self, branch: &Branch, world: &World) -> Option<Action> {
        if branch.nodes.is_empty() {
            return None;
        }
        let mut restarted = false;
        loop {
            if self.done_at.iter().zip(&branch.active).all(|(d, &a)| d.is_some() || !a) {
                if restarted {
                    return None;
                }
                self.done_at.iter_mut().for_each(|d| *d = None);
                restarted = true;
            }
            let j = (0..branch.nodes.len()).find(|&j| self.runnable(branch, j, world))?;
            match branch.nodes[j].behavior.action() {
                None => self.done_at[j] = Some(world.tick),
                Some(a) => {
                    self.done_at[j] = Some(world.tick + a.duration_ticks());
                    return Some(a);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A demonstration: `occupancy` as (ticks, pickup, sweep) runs, then motions.
    fn demo(runs: &[(u32, bool, bool)], motions: &[(Behavior, u32, u32)]) -> DemonstrationRecord {
        let mut d = DemonstrationRecord::new();
        for &(n, p, s) in runs {
            for _ in 0..n {
                d.observe(p, s);
            }
        }
        for &(b, s, e) in motions {
            d.motion(b, s, e);
        }
        d
    }

    fn first_action(b: &Branch, zone: Option<Zone>) -> Option<Action> {
        BranchRun::new(b).step(b, &World::of_zone(zone))
    }

    #[test]
    fn a_correct_pickup_demonstration_is_figure_4_5_a() {
        // A bug sits in the pickup zone at START; the user lowers and lifts the right arm; the bug is lifted at 4.5 s.
        let d = demo(&[(45, true, false), (50, false, false)], &[(Behavior::PickUp, 5, 94)]);
        let b = Branch::learn(&d, 1, NodeOrder::Postcondition);
        let names: Vec<String> = b.nodes.iter().map(|n| format!("{}_{}", n.behavior.abbreviation(), n.id)).collect();
        assert_eq!(names, ["FBIPZ_1", "P-UP_2"]);
        assert_eq!(b.links, vec![Link { from: 0, to: 1, kind: LinkKind::Enabling }]);
        assert_eq!(b.active, vec![true, true]);
        assert_eq!(first_action(&b, Some(Zone::Pickup)), Some(Action::Pickup));
        assert_eq!(first_action(&b, Some(Zone::Sweep)), None);
        assert_eq!(first_action(&b, None), None);
    }

    #[test]
    fn simultaneous_arms_create_an_unintended_dependency() {
        // Both arms at once while a bug is in the sweep zone ("they moved both
        // arms at the same time thus creating simultaneous actions"): the
        // pickup now depends on the sweep, as in "executing a pickup action
        // after every sweep, even if there is no bug in the pickup zone".
        let d = demo(&[(20, false, true), (80, false, false)], &[(Behavior::Sweep, 2, 51), (Behavior::PickUp, 4, 93)]);
        let b = Branch::learn(&d, 10, NodeOrder::Postcondition);
        let kinds: Vec<(usize, usize, LinkKind)> = b.links.iter().map(|l| (l.from, l.to, l.kind)).collect();
        assert_eq!(
            kinds,
            [(0, 1, LinkKind::Enabling), (0, 2, LinkKind::Enabling), (1, 2, LinkKind::Ordering)],
            "FBISZ enables both arms; the pickup must wait for the sweep"
        );
        let mut run = BranchRun::new(&b);
        let w = World { pickup: false, sweep: true, tick: 0 };
        assert_eq!(run.step(&b, &w), Some(Action::Sweep));
        // After the sweep the bug has left the sweep zone: the pickup's enabling FBISZ is false now.
        let w = World { pickup: false, sweep: false, tick: 50 };
        assert_eq!(run.step(&b, &w), None);
        // The next bug in the sweep zone gets the pickup, not a sweep.
        let w = World { pickup: false, sweep: true, tick: 200 };
        assert_eq!(run.step(&b, &w), Some(Action::Pickup));
    }

    #[test]
    fn the_order_reading_decides_which_arm_waits_for_the_other() {
        // Both arms started together: by postcondition the sweep (50 ticks)
        // precedes the pickup (90); under pickup-first the dependency turns round.
        let d = demo(&[(20, false, true), (80, false, false)], &[(Behavior::PickUp, 2, 91), (Behavior::Sweep, 2, 51)]);
        let by_end = Branch::learn(&d, 1, NodeOrder::Postcondition);
        let names = |b: &Branch| b.nodes.iter().map(|n| n.behavior.abbreviation()).collect::<Vec<_>>();
        assert_eq!(names(&by_end), ["FBISZ", "SWEEP", "P-UP"]);
        let pickup_first = Branch::learn(&d, 1, NodeOrder::PickupFirst);
        assert_eq!(names(&pickup_first), ["FBISZ", "P-UP", "SWEEP"]);
        assert_eq!(first_action(&by_end, Some(Zone::Sweep)), Some(Action::Sweep));
        assert_eq!(first_action(&pickup_first, Some(Zone::Sweep)), Some(Action::Pickup));
    }

    #[test]
    fn an_unconditioned_arm_runs_everywhere_and_permanent_links_need_their_effect() {
        let d = demo(&[(100, false, false)], &[(Behavior::Sweep, 10, 59)]);
        let b = Branch::learn(&d, 1, NodeOrder::Postcondition);
        for z in [Some(Zone::Pickup), Some(Zone::Sweep), None] {
            assert_eq!(first_action(&b, z), Some(Action::Sweep));
        }
        // A bug held in the pickup zone throughout a sweep: FBIPZ → SWEEP is permanent,
        // so the sweep needs a bug in the pickup zone: never right for a lone bug in the sweep zone.
        let d = demo(&[(100, true, true)], &[(Behavior::Sweep, 10, 59)]);
        let b = Branch::learn(&d, 1, NodeOrder::Postcondition);
        assert!(b.links.iter().any(|l| l.kind == LinkKind::Permanent));
        assert_eq!(first_action(&b, Some(Zone::Sweep)), None);
        assert_eq!(first_action(&b, Some(Zone::Pickup)), None);
    }

    #[test]
    fn the_network_restarts_after_a_pass() {
        let d = demo(&[(45, true, false), (50, false, false)], &[(Behavior::PickUp, 5, 94)]);
        let b = Branch::learn(&d, 1, NodeOrder::Postcondition);
        let mut run = BranchRun::new(&b);
        let here = World { pickup: true, sweep: false, tick: 0 };
        assert_eq!(run.step(&b, &here), Some(Action::Pickup));
        assert_eq!(run.step(&b, &World { tick: 100, ..here }), Some(Action::Pickup), "restart, again");
        // Perception only: no action, and no endless loop.
        let p = Branch::learn(&demo(&[(10, true, false)], &[]), 1, NodeOrder::Postcondition);
        assert_eq!(BranchRun::new(&p).step(&p, &here), None);
    }
}
