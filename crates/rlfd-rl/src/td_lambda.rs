//! Linear TD(λ) control with sparse traces: the machinery SARSA(λ)
//! ([`crate::SarsaLambda`]) and Watkins's Q(λ) ([`crate::WatkinsQLambda`])
//! share. They differ only in the action the target bootstraps from and in
//! whether an exploratory step cuts the traces: a [`TargetRule`].
//!
//! For a transition `(s, a, r, s', a')` with bootstrap action `b`:
//!
//! ```text
//! e(s, a) ← φ(s)            (replacing: other actions' traces at φ(s) cleared)
//! δ ← r + γ Q(s', b) − Q(s, a)         (δ ← r − Q(s, a) at a terminal s')
//! w ← w + α δ e
//! e ← γ λ e, traces below 0.01 dropped (or e ← 0 when the rule cuts them)
//! ```
//!
//! `Q(s, a)` is evaluated with the current weights at every step; `Q(s', ·)`
//! is the vector the agent evaluated when choosing `a'`, before this update.
//!
//! Traces are kept as a [`SparseTraces`] list, or, asked for with
//! [`LinearTdLambda::traces_by_generation`], by generation
//! ([`GenerationTraces`]): the same numbers either way (the tests below check
//! the weights bit for bit). Generations are faster when consecutive states
//! share few tiles or repeat exactly (Mario's 27 variables: half the marks
//! renew a repeated state); when most tiles carry over from one step to the
//! next (the Maze's small moves), moving them between generations costs more
//! than the list's in-place update. A learner whose traces stop fitting
//! generations (features with values, or steps without decay beyond the
//! ring) moves to the list for good, traces and all.

use std::marker::PhantomData;

use crate::agent::TdControl;
use crate::features::ActiveFeatures;
use crate::linear::LinearActionValues;
use crate::params::TdParams;
use crate::traces::{GenerationTraces, MIN_TRACE, SparseTraces, TraceKind};

/// How a TD control method picks its bootstrap action and treats its traces.
pub trait TargetRule {
    /// The action the target bootstraps from, given the behaviour's next
    /// action and the values it was selected with.
    fn target(next_action: usize, selection_values: &[f64]) -> usize;
    /// Whether the traces survive the step (else they are cut to 0).
    fn keeps_traces(target: usize, next_action: usize) -> bool;
}

/// Linear TD(λ) control over `num_features × num_actions` weights.
#[derive(Clone, Debug)]
pub struct LinearTdLambda<R> {
    q: LinearActionValues,
    traces: Traces,
    params: TdParams,
    kind: TraceKind,
    rule: PhantomData<R>,
}

/// The two ways of keeping the same traces.
#[derive(Clone, Debug)]
enum Traces {
    /// Replacing traces of binary features, by generation.
    Generations(GenerationTraces),
    /// Anything else.
    List(SparseTraces),
}

impl<R: TargetRule> LinearTdLambda<R> {
    /// A learner over `num_features` features with all weights 0, its traces as a list.
    pub fn new(num_features: usize, num_actions: usize, params: TdParams, kind: TraceKind) -> Self {
        let q = LinearActionValues::new(num_features, num_actions, 0.0);
        let traces = Traces::List(q.new_traces(kind, MIN_TRACE));
        LinearTdLambda { q, traces, params, kind, rule: PhantomData }
    }

    /// The same learner keeping replacing traces by generation (see the
    /// module docs for when that is faster); unchanged for accumulating
    /// traces, or a decay too slow for the generations (γλ ≥ 0.93). Call it
    /// before learning.
    pub fn traces_by_generation(mut self) -> Self {
        let features = self.q.num_weights() / self.q.num_actions();
        let factor = self.params.gamma * self.params.lambda;
        if self.kind == TraceKind::Replacing
            && self.trace_count() == 0
            && let Some(g) = GenerationTraces::new(features, factor, MIN_TRACE)
        {
            self.traces = Traces::Generations(g);
        }
        self
    }

    /// The learned action values.
    pub fn action_values_table(&self) -> &LinearActionValues {
        &self.q
    }

    /// The learned action values, for initialisation schemes.
    pub fn action_values_table_mut(&mut self) -> &mut LinearActionValues {
        &mut self.q
    }

    /// Number of traces currently held (for tests and benches).
    pub fn trace_count(&self) -> usize {
        match &self.traces {
            Traces::Generations(g) => g.len(),
            Traces::List(l) => l.len(),
        }
    }

    /// One update with generation traces; false (nothing done) when they do
    /// not fit this step, and the caller moves to the list.
    #[inline]
    fn learn_by_generation(
        &mut self,
        features: &ActiveFeatures,
        action: usize,
        reward: f64,
        next: Option<(&[f64], usize, usize)>,
    ) -> bool {
        let Traces::Generations(traces) = &mut self.traces else { return false };
        if !features.is_binary() {
            return false;
        }
        let Some(q_sa) = self.q.value_and_mark_generation(traces, features, action) else { return false };
        let step = |delta: f64| self.params.alpha * delta;
        match next {
            Some((next_values, target, next_action)) => {
                let delta = reward + self.params.gamma * next_values[target] - q_sa;
                if R::keeps_traces(target, next_action) {
                    traces.apply_and_decay(self.q.weights_mut(), step(delta));
                } else {
                    traces.apply(self.q.weights_mut(), step(delta));
                    traces.clear();
                }
            }
            None => traces.apply(self.q.weights_mut(), step(reward - q_sa)),
        }
        true
    }

    /// The traces as a list, converting generation traces once.
    #[cold]
    fn switch_to_list(&mut self) {
        if let Traces::Generations(g) = &self.traces {
            self.traces = Traces::List(g.to_sparse());
        }
    }
}

impl<R: TargetRule> TdControl for LinearTdLambda<R> {
    fn num_actions(&self) -> usize {
        self.q.num_actions()
    }

    fn params(&self) -> &TdParams {
        &self.params
    }

    #[inline]
    fn action_values(&self, features: &ActiveFeatures, out: &mut [f64]) {
        self.q.values(features, out);
    }

    fn begin_episode(&mut self) {
        match &mut self.traces {
            Traces::Generations(g) => g.clear(),
            Traces::List(l) => l.clear(),
        }
    }

    #[inline]
    fn target_action(&self, next_action: usize, selection_values: &[f64]) -> usize {
        R::target(next_action, selection_values)
    }

    #[inline]
    fn learn(&mut self, features: &ActiveFeatures, action: usize, reward: f64, next: Option<(&[f64], usize, usize)>) {
        if self.learn_by_generation(features, action, reward, next) {
            return;
        }
        self.switch_to_list();
        let Traces::List(traces) = &mut self.traces else { unreachable!("converted to a list above") };
        let q_sa = self.q.value_and_mark(traces, features, action, self.kind);
        let step = |delta: f64| self.params.alpha * delta;
        match next {
            Some((next_values, target, next_action)) => {
                let delta = reward + self.params.gamma * next_values[target] - q_sa;
                if R::keeps_traces(target, next_action) {
                    self.q.apply_and_decay(traces, step(delta), self.params.gamma * self.params.lambda);
                } else {
                    self.q.apply(traces, step(delta));
                    traces.clear();
                }
            }
            None => self.q.apply(traces, step(reward - q_sa)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::q_lambda::Watkins;
    use crate::sarsa::OnPolicy;
    use proptest::prelude::*;

    /// One learning step: active features (the last step's again when
    /// `repeat`; with values when `valued`), action, reward, and the next
    /// step (`None` for a terminal one) with its target and behaviour actions.
    type Step = ((Vec<u32>, bool), bool, usize, f64, Option<(usize, usize)>);

    fn step_strategy(features: u32, actions: usize) -> impl Strategy<Value = Step> {
        (
            (proptest::collection::vec(0..features, 0..10), proptest::bool::weighted(0.3)),
            proptest::bool::weighted(0.05),
            0..actions,
            -3.0f64..3.0,
            proptest::option::weighted(0.95, (0..actions, 0..actions)),
        )
    }

    /// Runs the same steps through a learner with generation traces and one
    /// with listed traces and compares their weights bit for bit after every step.
    fn same_weights<R: TargetRule>(steps: &[Step], lambda: f64, episode_every: usize) -> Result<(), TestCaseError> {
        let (features, actions) = (40, 3);
        let params = TdParams { alpha: 0.3, gamma: 0.9, lambda, epsilon: 0.1 };
        let mut fast = LinearTdLambda::<R>::new(features, actions, params, TraceKind::Replacing).traces_by_generation();
        let mut reference = LinearTdLambda::<R>::new(features, actions, params, TraceKind::Replacing);
        prop_assert!(matches!(fast.traces, Traces::Generations(_)));
        let mut next_values = vec![0.0; actions];
        let mut indices = &vec![];
        for (n, ((fresh, repeat), valued, action, reward, next)) in steps.iter().enumerate() {
            if !repeat {
                indices = fresh;
            }
            if n % episode_every == 0 {
                fast.begin_episode();
                reference.begin_episode();
            }
            let values =
                if *valued { indices.iter().map(|&k| 0.25 + f64::from(k % 4) / 4.0).collect() } else { vec![] };
            let f = ActiveFeatures { indices: indices.clone(), values };
            fast.action_values(&f, &mut next_values);
            let next = next.map(|(target, behaviour)| (next_values.as_slice(), target, behaviour));
            fast.learn(&f, *action, *reward, next);
            reference.learn(&f, *action, *reward, next);
            let (a, b) = (fast.action_values_table().weights(), reference.action_values_table().weights());
            prop_assert!(a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits()), "step {}", n);
            prop_assert_eq!(fast.trace_count(), reference.trace_count());
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        #[test]
        fn watkins_generation_traces_equal_listed_traces(
            steps in proptest::collection::vec(step_strategy(40, 3), 1..150),
            lambda in 0.0f64..1.0,
            episode_every in 1usize..60,
        ) {
            same_weights::<Watkins>(&steps, lambda, episode_every)?;
        }

        #[test]
        fn sarsa_generation_traces_equal_listed_traces(
            steps in proptest::collection::vec(step_strategy(40, 3), 1..150),
            lambda in 0.0f64..1.0,
            episode_every in 1usize..60,
        ) {
            same_weights::<OnPolicy>(&steps, lambda, episode_every)?;
        }
    }

    #[test]
    fn generations_are_asked_for_and_slow_decays_keep_a_list() {
        let td = |lambda| TdParams { alpha: 0.01 / 32.0, gamma: 0.9, lambda, epsilon: 0.05 };
        let plain = LinearTdLambda::<Watkins>::new(64, 12, td(0.5), TraceKind::Replacing);
        assert!(matches!(plain.traces, Traces::List(_)));
        let mario = plain.traces_by_generation();
        assert!(matches!(mario.traces, Traces::Generations(_)));
        let slow = LinearTdLambda::<Watkins>::new(64, 12, td(1.0), TraceKind::Replacing).traces_by_generation();
        assert!(matches!(slow.traces, Traces::Generations(_)), "γλ = 0.9 falls below 0.01 in 44 steps");
        let never = LinearTdLambda::<OnPolicy>::new(64, 4, TdParams { gamma: 1.0, ..td(1.0) }, TraceKind::Replacing)
            .traces_by_generation();
        assert!(matches!(never.traces, Traces::List(_)));
        let accumulating =
            LinearTdLambda::<OnPolicy>::new(64, 4, td(0.5), TraceKind::Accumulating).traces_by_generation();
        assert!(matches!(accumulating.traces, Traces::List(_)));
    }
}
