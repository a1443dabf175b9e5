//! Interactive Q-learning with human reward and guidance: the thesis's
//! Algorithm 1, line for line.
//!
//! ```text
//!  1: ε = initial value
//!  2: δε = ε / number of desired time steps to stop exploration
//!  3: Initialize Q-table with starting state
//!  4: while learning do
//!  5–9:  wait for guidance; g = guidanceTarget if received
//! 10–14: A = legal actions that contain g if guided, else legal actions of the current state
//! 15–20: rand ∈ [0, 1]; a = argmax_a Q[s, a] if rand > ε, else a random action of A
//! 21:    execute a and transition to s'
//! 22–24: add s' to the Q-table if new
//! 25–31: r = the human's reward, or 0
//! 32:    Q[s, a] ← Q[s, a] + α (r + γ max_a' Q[s', a'] − Q[s, a])
//! 33–35: if ε > 0 then ε ← ε − δε
//! ```
//!
//! with α = 0.3, γ = 0.75 and every new state's Q-values 0.5 ("We initialize
//! the Q-values for every new state that the agent discovers to 0.5"), ε =
//! 0.1 decaying by δε = 0.002 per step in the small space and 0.001 in the
//! large (section 3.3.2). [`InteractiveQ::select`] is lines 10–20,
//! [`InteractiveQ::learn`] lines 22–35; the session loop (`crate::session`)
//! supplies lines 5–9, 21 and 25–31 (world, teacher).
//!
//! Readings where the pseudocode is silent, all following the thesis's
//! "ε-greedy action selection over the legal actions":
//! - Line 17's argmax runs over `A` (the legal, and possibly guided,
//!   candidates), ties broken uniformly at random (every value starts at 0.5,
//!   so the first choice in a new state is a uniform one).
//! - Line 11: "the set of legal actions that only contain g" is the legal
//!   actions in g's row of Table 3.1; "If none of the actions specified by
//!   the guidance message are valid … the robot ignores the guidance message"
//!   and A is all legal actions ([`candidates`]).
//! - Line 32's max runs over the actions legal in `s'`: an impossible action
//!   is never taken, so its value would stay at 0.5 forever and put a floor
//!   under every bootstrap.
//! - ε is clamped at 0, so that 0.1 − 50 × 0.002 is 0 and not a rounding
//!   residue.
//!
//! The table is [`rlfd_rl::TabularQ`] (rows numbered as states are
//! discovered, new rows at 0.5), with a dense map from the state's number to
//! its row. `TabularQ`'s own update bootstraps over every action of `s'`; the
//! learner computes line 32's target over the legal ones and hands it to
//! `TabularQ`'s terminal form, `Q ← Q + α (target − Q)`, which is the same
//! arithmetic. Nothing is allocated per step (a new state grows the table).

use rand::Rng;
use rlfd_rl::TabularQ;
use rlfd_rl::policy::greedy;
use rlfd_rl::random::{below, uniform01};
use serde::{Deserialize, Serialize};

use crate::guidance::GuidanceRegion;
use crate::nao::{Action, ActionSet, StateSpace};

/// Algorithm 1's parameters.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LearnerParams {
    /// Step size α (thesis: 0.3).
    pub alpha: f64,
    /// Discount γ (thesis: 0.75).
    pub gamma: f64,
    /// Q-value of every action of a newly discovered state (thesis: 0.5).
    pub initial_q: f64,
    /// Initial exploration rate ε (thesis: 0.1).
    pub epsilon: f64,
    /// Decrease of ε per step, δε (thesis: 0.002 small space, 0.001 large).
    pub epsilon_decay: f64,
}

impl LearnerParams {
    /// The thesis's parameters for `space`.
    pub const fn thesis(space: StateSpace) -> LearnerParams {
        LearnerParams {
            alpha: 0.3,
            gamma: 0.75,
            initial_q: 0.5,
            epsilon: 0.1,
            epsilon_decay: match space {
                StateSpace::Small => 0.002,
                StateSpace::Large => 0.001,
            },
        }
    }

    /// The first field outside its domain, as `(name, value, expected)`.
    pub fn invalid(&self) -> Option<(&'static str, f64, &'static str)> {
        let unit = |v: f64| (0.0..=1.0).contains(&v);
        if !(self.alpha > 0.0 && self.alpha <= 1.0) {
            return Some(("alpha", self.alpha, "a step size in (0, 1]"));
        }
        if !(unit(self.gamma) && self.gamma < 1.0) {
            return Some(("gamma", self.gamma, "a discount in [0, 1)"));
        }
        if !self.initial_q.is_finite() {
            return Some(("initial_q", self.initial_q, "a finite number"));
        }
        if !unit(self.epsilon) {
            return Some(("epsilon", self.epsilon, "a probability in [0, 1]"));
        }
        if !(self.epsilon_decay.is_finite() && self.epsilon_decay >= 0.0) {
            return Some(("epsilon_decay", self.epsilon_decay, "a finite number ≥ 0"));
        }
        None
    }
}

/// Lines 10–14: the candidate actions, given the legal ones and the guidance.
pub fn candidates(legal: ActionSet, guidance: Option<GuidanceRegion>) -> ActionSet {
    match guidance {
        Some(g) => {
            let guided = legal.intersection(g.actions());
            if guided.is_empty() { legal } else { guided }
        }
        None => legal,
    }
}

const NO_ROW: u32 = u32::MAX;

/// The learner.
#[derive(Clone, Debug)]
pub struct InteractiveQ {
    params: LearnerParams,
    q: TabularQ,
    rows: Vec<u32>,
    epsilon: f64,
    values: [f64; Action::COUNT],
    actions: [Action; Action::COUNT],
}

impl InteractiveQ {
    /// An empty learner over a space of `state_count` numbered states
    /// (parameters checked by the caller, see [`LearnerParams::invalid`]).
    pub fn new(params: LearnerParams, state_count: usize) -> InteractiveQ {
        debug_assert!(params.invalid().is_none(), "unchecked learner parameters: {params:?}");
        InteractiveQ {
            params,
            q: TabularQ::new(Action::COUNT, params.initial_q),
            rows: vec![NO_ROW; state_count],
            epsilon: params.epsilon,
            values: [0.0; Action::COUNT],
            actions: [Action::TakePicture; Action::COUNT],
        }
    }

    /// The row of state `s`, added if new (lines 3 and 22–24).
    fn row(&mut self, s: usize) -> usize {
        if self.rows[s] == NO_ROW {
            let row = self.q.num_states();
            self.q.ensure(row);
            self.rows[s] = row as u32;
        }
        self.rows[s] as usize
    }

    /// Line 3: the table starts with the robot's current state.
    pub fn start(&mut self, s: usize) {
        self.row(s);
    }

    /// Lines 10–20: the action to take in `s`, among `legal`, under `guidance`.
    pub fn select<R: Rng + ?Sized>(
        &mut self,
        s: usize,
        legal: ActionSet,
        guidance: Option<GuidanceRegion>,
        rng: &mut R,
    ) -> Action {
        let a_set = candidates(legal, guidance);
        assert!(!a_set.is_empty(), "no legal action in state {s}: TakePicture is always possible");
        let row = self.row(s);
        let mut n = 0;
        for a in a_set.iter() {
            self.actions[n] = a;
            self.values[n] = self.q.value(row, a.index());
            n += 1;
        }
        let rand = uniform01(rng);
        if rand > self.epsilon { self.actions[greedy(&self.values[..n], rng)] } else { self.actions[below(rng, n)] }
    }

    /// Lines 22–35: the update after `a` took `s` to `s_next`, where
    /// `legal_next` are possible, with the teacher's reward `r` (0 if none).
    pub fn learn(&mut self, s: usize, a: Action, r: f64, s_next: usize, legal_next: ActionSet) {
        let row_next = self.row(s_next);
        let row = self.row(s);
        let max_next = legal_next.iter().map(|b| self.q.value(row_next, b.index())).fold(f64::NEG_INFINITY, f64::max);
        debug_assert!(max_next.is_finite(), "TakePicture is always legal");
        let target = r + self.params.gamma * max_next;
        // Q ← Q + α (target − Q): TabularQ's terminal form with the target as its reward.
        self.q.q_learning_update(row, a.index(), target, None, self.params.alpha, 0.0);
        if self.epsilon > 0.0 {
            self.epsilon -= self.params.epsilon_decay;
            if self.epsilon < 1e-12 {
                self.epsilon = 0.0;
            }
        }
    }

    /// The current ε.
    pub fn epsilon(&self) -> f64 {
        self.epsilon
    }

    /// Number of states in the table ("#States").
    pub fn states_discovered(&self) -> usize {
        self.q.num_states()
    }

    /// `Q[s, a]`, if `s` has been discovered.
    pub fn value(&self, s: usize, a: Action) -> Option<f64> {
        let row = *self.rows.get(s)?;
        (row != NO_ROW).then(|| self.q.value(row as usize, a.index()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use Action::*;
    use rlfd_rl::random::seeded;

    fn learner(space: StateSpace) -> InteractiveQ {
        InteractiveQ::new(LearnerParams::thesis(space), 100)
    }

    #[test]
    fn the_table_grows_as_states_appear_with_values_of_one_half() {
        let mut l = learner(StateSpace::Small);
        l.start(7);
        assert_eq!(l.states_discovered(), 1);
        assert_eq!(l.value(7, RDrop), Some(0.5));
        assert_eq!(l.value(8, RDrop), None);
        l.learn(7, TakePicture, 0.0, 9, ActionSet::ALL);
        assert_eq!(l.states_discovered(), 2);
        l.learn(9, TakePicture, 0.0, 7, ActionSet::ALL);
        assert_eq!(l.states_discovered(), 2);
    }

    #[test]
    fn the_update_is_line_32_with_the_max_over_legal_actions() {
        let mut l = learner(StateSpace::Small);
        l.start(0);
        // s' = 1 new: max over legal = 0.5. Q = 0.5 + 0.3 (1 + 0.75·0.5 − 0.5) = 0.7625.
        l.learn(0, LRight, 1.0, 1, ActionSet::of(&[TakePicture, LLeft]));
        assert!((l.value(0, LRight).unwrap() - 0.7625).abs() < 1e-15);
        // Punish LLeft in 1: 0.5 + 0.3 (−1 + 0.75·0.7625 − 0.5) with s' = 0 where LRight is legal.
        l.learn(1, LLeft, -1.0, 0, ActionSet::of(&[LRight, TakePicture]));
        let want = 0.5 + 0.3 * (-1.0 + 0.75 * 0.7625 - 0.5);
        assert!((l.value(1, LLeft).unwrap() - want).abs() < 1e-15);
        // Only legal actions bootstrap: with only LLeft legal in 1, the max is its value.
        l.learn(0, TakePicture, 0.0, 1, ActionSet::of(&[LLeft]));
        let want = 0.5 + 0.3 * (0.75 * l.value(1, LLeft).unwrap() - 0.5);
        assert!((l.value(0, TakePicture).unwrap() - want).abs() < 1e-15);
    }

    #[test]
    fn epsilon_decays_linearly_to_zero_after_50_or_100_steps() {
        for (space, steps) in [(StateSpace::Small, 50), (StateSpace::Large, 100)] {
            let mut l = learner(space);
            l.start(0);
            assert_eq!(l.epsilon(), 0.1);
            for k in 1..=steps + 5 {
                l.learn(0, TakePicture, 0.0, 0, ActionSet::ALL);
                if k < steps {
                    assert!(l.epsilon() > 0.0, "{space:?} step {k}");
                    let want = 0.1 - k as f64 * LearnerParams::thesis(space).epsilon_decay;
                    assert!((l.epsilon() - want).abs() < 1e-12);
                } else {
                    assert_eq!(l.epsilon(), 0.0, "{space:?} step {k}");
                }
            }
        }
    }

    #[test]
    fn guidance_restricts_to_legal_actions_of_the_region_or_is_ignored() {
        let legal = ActionSet::of(&[TakePicture, LRight, RLeft]);
        assert_eq!(candidates(legal, None), legal);
        assert_eq!(candidates(legal, Some(GuidanceRegion::Zone2)), ActionSet::of(&[TakePicture]));
        assert_eq!(candidates(legal, Some(GuidanceRegion::RightShoulder)), ActionSet::of(&[RLeft]));
        // Zone 3 (RRight, RDrop): nothing legal, so the guidance is ignored.
        assert_eq!(candidates(legal, Some(GuidanceRegion::Zone3)), legal);
    }

    #[test]
    fn selection_is_greedy_over_candidates_and_explores_within_them() {
        let mut rng = seeded(4);
        let mut l = learner(StateSpace::Small);
        l.start(0);
        // Make RLeft clearly best, LRight worst.
        l.learn(0, RLeft, 1.0, 0, ActionSet::ALL);
        l.learn(0, LRight, -1.0, 0, ActionSet::ALL);
        let legal = ActionSet::of(&[TakePicture, LRight, RLeft]);
        let mut counts = [0usize; Action::COUNT];
        for _ in 0..10_000 {
            counts[l.select(0, legal, None, &mut rng).index()] += 1;
        }
        // ε is 0.1 − 2 × 0.002 = 0.096: RLeft ≈ 1 − 0.096 · 2/3.
        let share = counts[RLeft.index()] as f64 / 10_000.0;
        assert!((share - (1.0 - 0.096 * 2.0 / 3.0)).abs() < 0.01, "{share}");
        assert!(counts.iter().enumerate().all(|(i, &c)| c == 0 || legal.contains(Action::from_index(i))));
        // Guided to the left shoulder, only LRight is a candidate, however bad.
        for _ in 0..100 {
            assert_eq!(l.select(0, legal, Some(GuidanceRegion::LeftShoulder), &mut rng), LRight);
        }
    }

    #[test]
    fn ties_in_a_new_state_are_broken_uniformly() {
        let mut rng = seeded(5);
        let mut l = learner(StateSpace::Small);
        let legal = ActionSet::of(&[TakePicture, LRight, RLeft]);
        let mut counts = [0usize; Action::COUNT];
        for _ in 0..30_000 {
            counts[l.select(3, legal, None, &mut rng).index()] += 1;
        }
        for a in legal.iter() {
            assert!((counts[a.index()] as f64 / 30_000.0 - 1.0 / 3.0).abs() < 0.01);
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// With rewards in [−1, 1], γ = 0.75 and values starting at 0.5,
        /// every Q-value stays within ±1/(1 − γ) = ±4, and ε never goes below 0.
        #[test]
        fn values_stay_bounded_and_epsilon_non_negative(
            steps in proptest::collection::vec((0usize..6, 0usize..11, -1.0f64..=1.0, 0usize..6, 1u16..2048), 1..400),
        ) {
            let mut l = learner(StateSpace::Large);
            l.start(0);
            let mut rng = seeded(1);
            for (s, a, r, s2, legal_bits) in steps {
                let legal = ActionSet::of(&[Action::from_index(a)]).with(TakePicture);
                let _ = l.select(s, legal, None, &mut rng);
                let next_legal: ActionSet = Action::ALL
                    .into_iter()
                    .filter(|b| legal_bits & (1 << b.index()) != 0)
                    .fold(ActionSet::EMPTY, ActionSet::with);
                let next_legal = if next_legal.is_empty() { ActionSet::of(&[TakePicture]) } else { next_legal };
                l.learn(s, Action::from_index(a), r, s2, next_legal);
                proptest::prop_assert!(l.epsilon() >= 0.0);
            }
            for s in 0..6 {
                for a in Action::ALL {
                    if let Some(q) = l.value(s, a) {
                        proptest::prop_assert!((-4.0..=4.0).contains(&q), "Q({s}, {a:?}) = {q}");
                    }
                }
            }
        }
    }

    #[test]
    fn parameters_are_checked() {
        assert_eq!(LearnerParams::thesis(StateSpace::Large).invalid(), None);
        let bad = LearnerParams { gamma: 1.0, ..LearnerParams::thesis(StateSpace::Small) };
        assert_eq!(bad.invalid().map(|e| e.0), Some("gamma"));
        let bad = LearnerParams { alpha: 0.0, ..LearnerParams::thesis(StateSpace::Small) };
        assert_eq!(bad.invalid().map(|e| e.0), Some("alpha"));
        let bad = LearnerParams { epsilon_decay: f64::NAN, ..LearnerParams::thesis(StateSpace::Small) };
        assert_eq!(bad.invalid().map(|e| e.0), Some("epsilon_decay"));
    }
}
