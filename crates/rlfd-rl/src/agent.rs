//! The episode driver: a feature map, a TD learner, a shaping signal and the
//! ε-greedy behaviour policy, run through one episode of an [`Environment`].
//!
//! Per step, following the thesis's pseudocode order:
//!
//! ```text
//! take a in s, observe r, s'
//! if s' terminal: learn from (s, a, r + F(s, a, ⊥)); stop
//! φ(s'), potentials Φ(s', ·), Q(s', ·)
//! a' ← ε-greedy on Q(s', ·) (+ Φ(s', ·) when the shaping biases selection),
//!      unless the shaping forces an action there (HAT's forced episodes)
//! learn from (s, a, r + F(s, a, s', a'), s', a')
//! ```
//!
//! The episode's return is the sum of the environment's rewards only: shaping
//! changes what the agent learns from, never what it is scored on. Nothing is
//! allocated per step: every buffer lives in the [`Agent`].
//!
//! **Divergence.** A learner whose values or shaping rewards overflow (e.g.
//! dynamic shaping with too large a step) no longer learns anything: every
//! step checks the shaped reward and the next state's action values, and the
//! episode ends at once, [`EpisodeOutcome::diverged`], when one is not finite
//! or exceeds [`DIVERGENCE_BOUND`] in magnitude. Callers end the trial there
//! and record it as diverged, never as a result.

use rand::Rng;

use crate::environment::Environment;
use crate::features::{ActiveFeatures, FeatureMap};
use crate::params::TdParams;
use crate::policy::epsilon_greedy;
use crate::shaping::{Next, Shaping, Transition, Visit};

/// A linear TD control learner the [`Agent`] can drive.
pub trait TdControl {
    /// Number of actions.
    fn num_actions(&self) -> usize;
    /// The learner's parameters (γ and ε are read by the agent).
    fn params(&self) -> &TdParams;
    /// `Q(s, ·)` for the active features of `s`.
    fn action_values(&self, features: &ActiveFeatures, out: &mut [f64]);
    /// Called at the start of every episode (clears traces).
    fn begin_episode(&mut self);
    /// The action the TD target bootstraps from, given the behaviour's next
    /// action and the values the agent selected with.
    fn target_action(&self, next_action: usize, selection_values: &[f64]) -> usize;
    /// Learns from `(s, a, reward)` and, unless terminal, `next = (Q(s', ·) before
    /// this update, target action, behaviour's next action)`.
    fn learn(&mut self, features: &ActiveFeatures, action: usize, reward: f64, next: Option<(&[f64], usize, usize)>);
}

/// The magnitude beyond which a value or shaping reward counts as diverged:
/// far beyond any return of the thesis's tasks (at most about 10⁶ per
/// episode, times a shaping scale of at most 100), so reaching it means the
/// learner overflowed, not that it learned.
pub const DIVERGENCE_BOUND: f64 = 1e30;

#[inline]
fn diverged(x: f64) -> bool {
    x.is_nan() || x.abs() >= DIVERGENCE_BOUND
}

/// Whether any of `xs` [`diverged`]: every value tested, the verdicts
/// combined without a branch (it runs on every step's action values).
#[inline]
fn any_diverged(xs: &[f64]) -> bool {
    xs.iter().fold(false, |d, &x| d | x.is_nan() | (x.abs() >= DIVERGENCE_BOUND))
}

/// What an episode came to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EpisodeOutcome {
    /// Sum of the environment's rewards (unshaped).
    pub env_return: f64,
    /// Number of actions taken.
    pub steps: usize,
    /// Whether the episode reached a terminal state (else it hit the step cap
    /// or diverged).
    pub terminal: bool,
    /// Whether the learner diverged (see the module docs): the episode ended
    /// at the step where it did.
    pub diverged: bool,
}

/// A learning agent: features + learner + shaping + ε-greedy behaviour.
#[derive(Clone, Debug)]
pub struct Agent<F, L, S> {
    features: F,
    learner: L,
    shaping: S,
    buffers: Buffers,
}

#[derive(Clone, Debug)]
struct Buffers {
    state: Vec<f64>,
    next_state: Vec<f64>,
    feats: ActiveFeatures,
    next_feats: ActiveFeatures,
    pot: Vec<f64>,
    next_pot: Vec<f64>,
    next_q: Vec<f64>,
    select: Vec<f64>,
}

impl<F: FeatureMap, L: TdControl, S: Shaping> Agent<F, L, S> {
    /// Assembles an agent. The learner must have been built for `features.num_features()` features.
    pub fn new(features: F, learner: L, shaping: S) -> Self {
        let a = learner.num_actions();
        let cap = features.max_active();
        Agent {
            buffers: Buffers {
                state: Vec::with_capacity(64),
                next_state: Vec::with_capacity(64),
                feats: ActiveFeatures::with_capacity(cap),
                next_feats: ActiveFeatures::with_capacity(cap),
                pot: vec![0.0; a],
                next_pot: vec![0.0; a],
                next_q: vec![0.0; a],
                select: vec![0.0; a],
            },
            features,
            learner,
            shaping,
        }
    }

    /// The feature map.
    pub fn features(&self) -> &F {
        &self.features
    }

    /// The learner.
    pub fn learner(&self) -> &L {
        &self.learner
    }

    /// The learner, mutably (e.g. to initialise its weights).
    pub fn learner_mut(&mut self) -> &mut L {
        &mut self.learner
    }

    /// The shaping signal.
    pub fn shaping(&self) -> &S {
        &self.shaping
    }

    /// Runs one learning episode of at most `max_steps` actions.
    pub fn run_episode<E: Environment, R: Rng + ?Sized>(
        &mut self,
        env: &mut E,
        rng: &mut R,
        max_steps: usize,
    ) -> EpisodeOutcome {
        let gamma = self.learner.params().gamma;
        let epsilon = self.learner.params().epsilon;
        let bias = self.shaping.biases_selection();
        let b = &mut self.buffers;

        env.reset(rng);
        self.learner.begin_episode();
        self.shaping.begin_episode();
        b.state.clear();
        b.state.extend_from_slice(env.state());
        self.features.features(&b.state, &mut b.feats);
        self.shaping.potentials(&Visit { state: &b.state, features: &b.feats }, &mut b.pot);
        self.learner.action_values(&b.feats, &mut b.select);
        if bias {
            add_into(&mut b.select, &b.pot);
        }
        let forced = self.shaping.forced_action(&Visit { state: &b.state, features: &b.feats });
        let mut action = forced.unwrap_or_else(|| epsilon_greedy(&b.select, epsilon, rng));

        let mut env_return = 0.0;
        let mut steps = 0;
        while steps < max_steps {
            let step = env.step(action, rng);
            env_return += step.reward;
            steps += 1;
            if step.terminal {
                let f = self.shaping.reward(&Transition {
                    from: Visit { state: &b.state, features: &b.feats },
                    action,
                    potentials: &b.pot,
                    next: None,
                    terminal_state: Some(env.state()),
                    gamma,
                });
                self.learner.learn(&b.feats, action, step.reward + f, None);
                return EpisodeOutcome { env_return, steps, terminal: true, diverged: diverged(f) };
            }
            b.next_state.clear();
            b.next_state.extend_from_slice(env.state());
            self.features.features(&b.next_state, &mut b.next_feats);
            self.shaping.potentials(&Visit { state: &b.next_state, features: &b.next_feats }, &mut b.next_pot);
            self.learner.action_values(&b.next_feats, &mut b.next_q);
            for (s, q) in b.select.iter_mut().zip(&b.next_q) {
                *s = *q;
            }
            if bias {
                add_into(&mut b.select, &b.next_pot);
            }
            if any_diverged(&b.next_q) | any_diverged(&b.next_pot) {
                return EpisodeOutcome { env_return, steps, terminal: false, diverged: true };
            }
            let forced = self.shaping.forced_action(&Visit { state: &b.next_state, features: &b.next_feats });
            let next_action = forced.unwrap_or_else(|| epsilon_greedy(&b.select, epsilon, rng));
            let target = self.learner.target_action(next_action, &b.select);
            let f = self.shaping.reward(&Transition {
                from: Visit { state: &b.state, features: &b.feats },
                action,
                potentials: &b.pot,
                next: Some(Next {
                    visit: Visit { state: &b.next_state, features: &b.next_feats },
                    action: next_action,
                    target,
                    potentials: &b.next_pot,
                }),
                terminal_state: None,
                gamma,
            });
            if diverged(f) {
                return EpisodeOutcome { env_return, steps, terminal: false, diverged: true };
            }
            self.learner.learn(&b.feats, action, step.reward + f, Some((&b.next_q, target, next_action)));
            std::mem::swap(&mut b.state, &mut b.next_state);
            std::mem::swap(&mut b.feats, &mut b.next_feats);
            std::mem::swap(&mut b.pot, &mut b.next_pot);
            action = next_action;
        }
        EpisodeOutcome { env_return, steps, terminal: false, diverged: false }
    }
}

#[inline]
fn add_into(out: &mut [f64], add: &[f64]) {
    for (o, a) in out.iter_mut().zip(add) {
        *o += a;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::Step;
    use crate::features::{TileCoder, TileIndexing};
    use crate::random::seeded;
    use crate::shaping::NoShaping;
    use crate::traces::TraceKind;
    use crate::{SarsaLambda, WatkinsQLambda};

    /// A corridor of `len` cells; start at 0, goal at `len - 1`; actions left/right; −1 per step.
    pub(crate) struct Corridor {
        len: usize,
        pos: usize,
        state: [f64; 1],
    }

    impl Corridor {
        pub(crate) fn new(len: usize) -> Self {
            Corridor { len, pos: 0, state: [0.0] }
        }
    }

    impl Environment for Corridor {
        fn num_actions(&self) -> usize {
            2
        }
        fn state_dim(&self) -> usize {
            1
        }
        fn reset<R: Rng + ?Sized>(&mut self, _rng: &mut R) {
            self.pos = 0;
            self.state[0] = 0.0;
        }
        fn state(&self) -> &[f64] {
            &self.state
        }
        fn step<R: Rng + ?Sized>(&mut self, action: usize, _rng: &mut R) -> Step {
            if action == 1 {
                self.pos += 1;
            } else if self.pos > 0 {
                self.pos -= 1;
            }
            self.state[0] = self.pos as f64;
            Step { reward: -1.0, terminal: self.pos == self.len - 1 }
        }
    }

    fn coder(len: usize) -> TileCoder {
        TileCoder::new(1, &[1.0], TileIndexing::Dense { lower: vec![0.0], upper: vec![len as f64] }).unwrap()
    }

    fn params() -> TdParams {
        TdParams { alpha: 0.5, gamma: 1.0, lambda: 0.5, epsilon: 0.05 }.check().unwrap()
    }

    #[test]
    fn sarsa_lambda_learns_the_corridor() {
        let len = 20;
        let f = coder(len);
        let learner = SarsaLambda::new(f.num_features(), 2, params(), TraceKind::Replacing);
        let mut agent = Agent::new(f, learner, NoShaping);
        let mut env = Corridor::new(len);
        let mut rng = seeded(5);
        let first = agent.run_episode(&mut env, &mut rng, 10_000);
        assert!(first.terminal);
        let mut last = first;
        for _ in 0..200 {
            last = agent.run_episode(&mut env, &mut rng, 10_000);
        }
        assert!(first.steps > 40, "a random walk needs many steps, took {}", first.steps);
        assert!(last.steps <= 22, "after learning the corridor takes ~19 steps, took {}", last.steps);
        assert_eq!(last.env_return, -(last.steps as f64));
    }

    #[test]
    fn an_overflowing_shaping_ends_the_episode_as_diverged() {
        use crate::shaping::StaticShaping;
        let len = 20;
        let f = coder(len);
        let learner = SarsaLambda::new(f.num_features(), 2, params(), TraceKind::Replacing);
        // A potential that overflows once the agent leaves the start.
        let potential = |s: &[f64]| if s[0] > 0.0 { f64::INFINITY } else { 0.0 };
        let mut agent = Agent::new(f, learner, StaticShaping::new(potential, 1.0));
        let mut env = Corridor::new(len);
        let mut rng = seeded(5);
        let out = agent.run_episode(&mut env, &mut rng, 10_000);
        assert!(out.diverged && !out.terminal, "{out:?}");
        assert!(out.steps < 10_000);
        // A finite potential of the same shape does not diverge.
        let f = coder(len);
        let learner = SarsaLambda::new(f.num_features(), 2, params(), TraceKind::Replacing);
        let mut agent = Agent::new(f, learner, StaticShaping::new(|s: &[f64]| s[0], 1.0));
        assert!(!agent.run_episode(&mut env, &mut rng, 10_000).diverged);
    }

    /// Forces "right" for its first `episodes` episodes, else nothing.
    struct ForceRight {
        episodes: usize,
        begun: usize,
    }

    impl Shaping for ForceRight {
        fn biases_selection(&self) -> bool {
            false
        }
        fn begin_episode(&mut self) {
            self.begun += 1;
        }
        fn potentials(&mut self, _visit: &Visit<'_>, out: &mut [f64]) {
            out.fill(0.0);
        }
        fn reward(&mut self, _transition: &Transition<'_>) -> f64 {
            0.0
        }
        fn forced_action(&mut self, _visit: &Visit<'_>) -> Option<usize> {
            (self.begun <= self.episodes).then_some(1)
        }
    }

    #[test]
    fn a_forced_action_replaces_the_epsilon_greedy_choice() {
        let len = 20;
        let f = coder(len);
        // ε = 1: without forcing every action is random.
        let p = TdParams { epsilon: 1.0, ..params() };
        let learner = SarsaLambda::new(f.num_features(), 2, p, TraceKind::Replacing);
        let mut agent = Agent::new(f, learner, ForceRight { episodes: 3, begun: 0 });
        let mut env = Corridor::new(len);
        let mut rng = seeded(8);
        for _ in 0..3 {
            let forced = agent.run_episode(&mut env, &mut rng, 10_000);
            assert_eq!((forced.steps, forced.terminal), (len - 1, true), "forced straight to the goal");
        }
        // The learner learned along the way from the forced actions only:
        // right has a value at the start, left was never taken.
        let mut q = [0.0; 2];
        let mut feats = ActiveFeatures::default();
        agent.features().features(&[0.0], &mut feats);
        agent.learner().action_values(&feats, &mut q);
        assert!(q[0] == 0.0 && q[1] < 0.0, "{q:?}");
        // After the forced episodes, the random walk is back.
        let free = agent.run_episode(&mut env, &mut rng, 10_000);
        assert!(free.steps > len - 1, "{}", free.steps);
    }

    #[test]
    fn watkins_q_lambda_learns_the_corridor() {
        let len = 20;
        let f = coder(len);
        let learner = WatkinsQLambda::new(f.num_features(), 2, params(), TraceKind::Replacing);
        let mut agent = Agent::new(f, learner, NoShaping);
        let mut env = Corridor::new(len);
        let mut rng = seeded(6);
        let mut last = agent.run_episode(&mut env, &mut rng, 10_000);
        for _ in 0..200 {
            last = agent.run_episode(&mut env, &mut rng, 10_000);
        }
        assert!(last.steps <= 22, "took {}", last.steps);
    }

    #[test]
    fn step_cap_truncates() {
        let f = coder(1000);
        let learner = SarsaLambda::new(f.num_features(), 2, params(), TraceKind::Replacing);
        let mut agent = Agent::new(f, learner, NoShaping);
        let mut env = Corridor::new(1000);
        let out = agent.run_episode(&mut env, &mut seeded(1), 50);
        assert_eq!(out, EpisodeOutcome { env_return: -50.0, steps: 50, terminal: false, diverged: false });
    }

    #[test]
    fn same_seed_same_episodes() {
        let run = || {
            let f = coder(30);
            let learner = SarsaLambda::new(f.num_features(), 2, params(), TraceKind::Accumulating);
            let mut agent = Agent::new(f, learner, NoShaping);
            let mut env = Corridor::new(30);
            let mut rng = seeded(77);
            (0..20).map(|_| agent.run_episode(&mut env, &mut rng, 5000).steps).collect::<Vec<_>>()
        };
        assert_eq!(run(), run());
    }
}
