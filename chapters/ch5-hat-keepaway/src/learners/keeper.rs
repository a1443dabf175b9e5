//! One keeper's agent: SMDP Sarsa (the shared `SarsaLambda`, see the parent
//! module for the update) with one of HAT's ways of using a rule summary.
//!
//! At each decision, with `Q(s, ·)` the learned values and `ρ(s)` the rules'
//! action:
//!
//! - **No Prior**: ε-greedy on `Q(s, ·)` (ties at random, so with all
//!   weights 0 the first choices are uniform).
//! - **Value Bonus**: for the first C episodes `a = ρ(s)`; afterwards
//!   ε-greedy on `Q(s, ·) + B·1[· = ρ(s)]`. The bonus is the thesis's
//!   "effectively changing the initialization of the Q-value function, or,
//!   equivalently [Wiewiora 2003], providing a shaping reward": the learner
//!   learns from `r + Φ(s', a') − Φ(s, a)` with `Φ(s, a) = B·1[a = ρ(s)]`
//!   (`−Φ(s, a)` at the episode's end), so that `Q + Φ` is exactly what a
//!   learner whose values started at `Φ` would hold.
//! - **Extra Action**: a fourth action meaning `ρ(s)`, learned like the
//!   others; taken outright for the first C episodes, then ε-greedy over all four.
//! - **Probabilistic Policy Reuse**: with probability ψ, `a = ρ(s)`;
//!   otherwise ε-greedy on `Q(s, ·)` (π-reuse, Fernández & Veloso 2006); ψ
//!   decays per episode (or per decision).
//!
//! In every case the learner updates the action it took (the primitive one,
//! or the extra action). Nothing is allocated per decision.

use rand::Rng;
use rlfd_lfd::hat::{ExtraAction, ProbabilisticPolicyReuse, ValueBonus};
use rlfd_lfd::ripper::DecisionList;
use rlfd_rl::features::{ActiveFeatures, FeatureMap, RbfFeatures};
use rlfd_rl::policy::epsilon_greedy;
use rlfd_rl::{SarsaLambda, TdControl};

use super::{LearnerParams, Method};
use crate::keepaway::{KeeperAction, STATE_VARS};

/// The method's running state.
#[derive(Clone, Debug)]
enum MethodState {
    NoPrior,
    ValueBonus(ValueBonus),
    ExtraAction(ExtraAction),
    PolicyReuse(ProbabilisticPolicyReuse),
}

/// One keeper's learning agent (see the module docs).
#[derive(Clone, Debug)]
pub struct KeeperAgent {
    learner: SarsaLambda,
    method: MethodState,
    epsilon: f64,
    episode: usize,
    current: ActiveFeatures,
    previous: ActiveFeatures,
    q: Vec<f64>,
    select: Vec<f64>,
    previous_choice: Option<usize>,
    previous_potential: f64,
    greedy: bool,
}

impl KeeperAgent {
    /// A keeper with all weights 0, for features with `num_features` features.
    pub fn new(
        params: &LearnerParams,
        method: &Method,
        num_features: usize,
        max_active: usize,
    ) -> Result<Self, super::LearnerParamError> {
        params.check()?;
        method.check()?;
        let td = params.td()?;
        let (actions, state) = match *method {
            Method::NoPrior => (3, MethodState::NoPrior),
            Method::ValueBonus { bonus, forced_episodes } => {
                // The shared `ValueBonus` holds B; its episode limit is not
                // used here because the bonus stays for the whole trial.
                (3, MethodState::ValueBonus(ValueBonus { bonus, episodes: forced_episodes }))
            }
            Method::ExtraAction { forced_episodes } => {
                (4, MethodState::ExtraAction(ExtraAction { primitive_actions: 3, forced_episodes }))
            }
            Method::PolicyReuse { psi, decay, unit } => {
                (3, MethodState::PolicyReuse(ProbabilisticPolicyReuse::new(psi, decay, unit.shared())))
            }
        };
        Ok(KeeperAgent {
            learner: SarsaLambda::new(num_features, actions, td, params.traces),
            method: state,
            epsilon: params.epsilon,
            episode: 0,
            current: ActiveFeatures::with_capacity(max_active),
            previous: ActiveFeatures::with_capacity(max_active),
            q: vec![0.0; actions],
            select: vec![0.0; actions],
            previous_choice: None,
            previous_potential: 0.0,
            greedy: false,
        })
    }

    /// Episodes this agent has learned from.
    pub fn episodes(&self) -> usize {
        self.episode
    }

    /// The current reuse probability ψ (PPR), if the method has one.
    pub fn psi(&self) -> Option<f64> {
        match &self.method {
            MethodState::PolicyReuse(p) => Some(p.psi()),
            _ => None,
        }
    }

    /// The learned values of `state` (length 3, or 4 with the extra action).
    pub fn values(&mut self, features: &RbfFeatures, state: &[f64; STATE_VARS]) -> &[f64] {
        features.features(state, &mut self.current);
        self.learner.action_values(&self.current, &mut self.q);
        &self.q
    }

    /// Switches the greedy evaluation on or off: while on, the agent takes
    /// the best action of what it has learned (Value Bonus: with the bonus;
    /// Extra Action: over its four actions), without exploring, without
    /// forced periods or reuse, and must not learn.
    pub fn set_greedy(&mut self, on: bool) {
        self.greedy = on;
    }

    /// Called at the start of every episode.
    pub fn begin_episode(&mut self) {
        self.learner.begin_episode();
        self.previous_choice = None;
        self.previous_potential = 0.0;
    }

    /// Chooses the macro-action in `state`; with `learn`, first learns from
    /// the previous decision, `reward` cycles ago.
    pub fn decide<R: Rng + ?Sized>(
        &mut self,
        features: &RbfFeatures,
        state: &[f64; STATE_VARS],
        reward: f64,
        rules: Option<&DecisionList>,
        learn: bool,
        rng: &mut R,
    ) -> KeeperAction {
        features.features(state, &mut self.current);
        self.learner.action_values(&self.current, &mut self.q);
        let rule = || rules.map_or(0, |r| r.predict(state).min(2));
        let episode = self.episode;
        debug_assert!(!(learn && self.greedy), "a greedy evaluation does not learn");
        let (choice, potential) = if self.greedy {
            match &self.method {
                MethodState::ValueBonus(vb) => {
                    let r = rule();
                    self.select.copy_from_slice(&self.q);
                    self.select[r] += vb.bonus;
                    (epsilon_greedy(&self.select, 0.0, rng), 0.0)
                }
                _ => (epsilon_greedy(&self.q, 0.0, rng), 0.0),
            }
        } else {
            match &mut self.method {
                MethodState::NoPrior => (epsilon_greedy(&self.q, self.epsilon, rng), 0.0),
                MethodState::ValueBonus(vb) => {
                    let r = rule();
                    let c = if episode < vb.episodes {
                        r
                    } else {
                        self.select.copy_from_slice(&self.q);
                        self.select[r] += vb.bonus;
                        epsilon_greedy(&self.select, self.epsilon, rng)
                    };
                    (c, if c == r { vb.bonus } else { 0.0 })
                }
                MethodState::ExtraAction(ea) => {
                    let c = if ea.forced(episode) { ea.extra() } else { epsilon_greedy(&self.q, self.epsilon, rng) };
                    (c, 0.0)
                }
                MethodState::PolicyReuse(ppr) => {
                    let c = if ppr.reuse(rng) { rule() } else { epsilon_greedy(&self.q, self.epsilon, rng) };
                    if learn {
                        ppr.end_step();
                    }
                    (c, 0.0)
                }
            }
        };
        if learn && let Some(prev) = self.previous_choice {
            let shaped = reward + potential - self.previous_potential;
            self.learner.learn(&self.previous, prev, shaped, Some((&self.q, choice, choice)));
        }
        std::mem::swap(&mut self.previous, &mut self.current);
        self.previous_choice = Some(choice);
        self.previous_potential = potential;
        let primitive = match &self.method {
            MethodState::ExtraAction(ea) if choice == ea.extra() => rule(),
            _ => choice,
        };
        KeeperAction::ALL[primitive]
    }

    /// Ends the episode: with `learn`, learns from the last decision
    /// (`reward` cycles before the end, if it decided at all) and advances the
    /// method's schedule (forced periods, ψ).
    pub fn end_episode(&mut self, reward: Option<f64>, learn: bool) {
        if !learn {
            self.previous_choice = None;
            return;
        }
        if let (Some(prev), Some(r)) = (self.previous_choice, reward) {
            self.learner.learn(&self.previous, prev, r - self.previous_potential, None);
        }
        self.previous_choice = None;
        self.episode += 1;
        if let MethodState::PolicyReuse(ppr) = &mut self.method {
            ppr.end_episode();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::learners::{PsiDecayUnit, RbfLayout};
    use rlfd_lfd::ripper::{Attribute, Dataset, Ripper, RipperParams};
    use rlfd_rl::random::seeded;

    fn agent(method: Method) -> (KeeperAgent, RbfFeatures) {
        let f = RbfLayout::reconstruction().features();
        (KeeperAgent::new(&LearnerParams::thesis(), &method, f.num_features(), f.max_active()).unwrap(), f)
    }

    /// Rules that pass to the nearer teammate when state_3 < 5, else hold.
    fn rules() -> DecisionList {
        let rows: Vec<Vec<f64>> =
            (0..60).map(|i| (0..13).map(|v| if v == 3 { f64::from(i % 10) } else { 1.0 }).collect()).collect();
        let labels = rows.iter().map(|r| usize::from(r[3] < 5.0)).collect();
        let attrs = (0..13).map(|i| Attribute::numeric(format!("state_{i}"))).collect();
        let data = Dataset::new(attrs, rows, "Action", vec!["0".into(), "1".into(), "2".into()], labels).unwrap();
        Ripper::fit(&RipperParams::weka_defaults(), &data).unwrap()
    }

    fn state(s3: f64) -> [f64; STATE_VARS] {
        let mut s = [5.0; STATE_VARS];
        s[3] = s3;
        s
    }

    #[test]
    fn no_prior_starts_uniform_and_learns_the_smdp_target() {
        let (mut a, f) = agent(Method::NoPrior);
        let mut rng = seeded(1);
        let mut counts = [0usize; 3];
        for _ in 0..3000 {
            counts[a.decide(&f, &state(3.0), 0.0, None, false, &mut rng).index()] += 1;
        }
        assert!(counts.iter().all(|&c| (c as f64 - 1000.0).abs() < 120.0), "{counts:?}");
        // Learning: reward 20 cycles then the end 10 cycles later; Q(s, a) rises.
        let s = state(3.0);
        a.begin_episode();
        let first = a.decide(&f, &s, 0.0, None, true, &mut rng);
        let _ = a.decide(&f, &s, 20.0, None, true, &mut rng);
        a.end_episode(Some(10.0), true);
        assert!(a.values(&f, &s)[first.index()] > 0.0);
        assert_eq!(a.episodes(), 1);
    }

    #[test]
    fn hat_methods_follow_the_rules_at_first() {
        let r = rules();
        let mut rng = seeded(2);
        for method in [Method::VALUE_BONUS, Method::EXTRA_ACTION, Method::POLICY_REUSE] {
            let (mut a, f) = agent(method);
            a.begin_episode();
            for i in 0..200 {
                let s3 = f64::from(i % 10);
                let act = a.decide(&f, &state(s3), 1.0, Some(&r), true, &mut rng);
                let expected = if s3 < 5.0 { KeeperAction::PASS1 } else { KeeperAction::HOLD };
                assert_eq!(act, expected, "{method:?} at state_3 = {s3}");
            }
        }
    }

    #[test]
    fn policy_reuse_decays_per_episode_and_value_bonus_shapes() {
        let r = rules();
        let (mut a, f) = agent(Method::POLICY_REUSE);
        let mut rng = seeded(3);
        for _ in 0..1000 {
            a.begin_episode();
            let _ = a.decide(&f, &state(7.0), 0.0, Some(&r), true, &mut rng);
            a.end_episode(Some(5.0), true);
        }
        assert!((a.psi().unwrap() - 0.999f64.powi(1000)).abs() < 1e-12);
        let (mut step, f) = agent(Method::PolicyReuse { psi: 1.0, decay: 0.5, unit: PsiDecayUnit::Step });
        step.begin_episode();
        let _ = step.decide(&f, &state(7.0), 0.0, Some(&r), true, &mut rng);
        let _ = step.decide(&f, &state(7.0), 0.0, Some(&r), true, &mut rng);
        assert_eq!(step.psi(), Some(0.25));
        // Value Bonus learns Q − Φ: after the rule's action ends an episode with
        // reward 5, Q(s, Hold) moves toward 5 − 10 < 0.
        let (mut vb, f) = agent(Method::VALUE_BONUS);
        for _ in 0..50 {
            vb.begin_episode();
            assert_eq!(vb.decide(&f, &state(7.0), 0.0, Some(&r), true, &mut rng), KeeperAction::HOLD);
            vb.end_episode(Some(5.0), true);
        }
        assert!(vb.values(&f, &state(7.0))[0] < 0.0);
    }

    #[test]
    fn evaluation_does_not_learn_or_advance_schedules() {
        let r = rules();
        let (mut a, f) = agent(Method::EXTRA_ACTION);
        let mut rng = seeded(4);
        for _ in 0..10 {
            a.begin_episode();
            let _ = a.decide(&f, &state(2.0), 3.0, Some(&r), false, &mut rng);
            a.end_episode(Some(3.0), false);
        }
        assert_eq!(a.episodes(), 0);
        assert!(a.values(&f, &state(2.0)).iter().all(|&q| q == 0.0));
    }
}
