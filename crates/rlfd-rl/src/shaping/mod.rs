//! Potential-based reward shaping: the shaping reward `F` added to the
//! environment's reward, from a potential over states or state-action pairs.
//!
//! - [`StaticShaping`]: a fixed state potential, `F = γΦ(s') − Φ(s)` (Ng,
//!   Harada & Russell 1999; the thesis's eq. 6.2, SIS).
//! - [`LookAheadShaping`]: a fixed state-action potential, `F = γΦ(s', a') −
//!   Φ(s, a)` (Wiewiora, Cottrell & Elkan 2003; eq. 6.3), optionally with
//!   Wiewiora's action-selection correction (act greedily on `Q + Φ`). With the
//!   correction, learning is step for step the same as learning without
//!   shaping from `Q` initialised to `Φ` (tested below), which is how the
//!   thesis describes its HAT and SBS baselines.
//! - [`DynamicShaping`]: a potential `Φ†(s, a)` learned on-policy by a
//!   secondary SARSA on the reward `−R†(s)`, `F = γΦ†(s', a') − Φ†(s, a)`
//!   (Harutyunyan, Devlin, Vrancx & Nowé 2015; eqs. 6.6–6.8, DIS).
//!
//! Every potential is multiplied by a `scale` (the thesis's "scaling of 100");
//! the shaping reward and any selection bias are therefore scaled alike.
//!
//! **The potential of a terminal state** ([`TerminalPotential`]). Ng, Harada &
//! Russell (1999) set it to 0, which keeps the optimal policy of any episodic
//! task unchanged (claim C6.11, property-tested in [`crate::mdp`]). The
//! thesis's eq. 6.2 writes `F = γΦ(s') − Φ(s)` with no exception for a
//! terminal `s'`; read literally, the static potentials evaluate Φ at the
//! terminal state ([`TerminalPotential::Literal`]). With a single terminal
//! region (or a terminal potential that is constant over the terminal
//! states) and γ = 1 this adds the same constant to every complete episode's
//! shaped return, so the optimal policy is still kept. A state-action
//! potential has no next action at a terminal state; the literal reading
//! uses `max_a' Φ(s', a')` there (the value the advice offers at s'). Dynamic
//! shaping keeps 0 (eq. 6.8's potential is learned only where an action is
//! taken).

mod dynamic;
mod look_ahead;
mod state;

pub use dynamic::DynamicShaping;
pub use look_ahead::LookAheadShaping;
pub use state::StaticShaping;

use crate::features::ActiveFeatures;

/// A scalar function of the state vector (a potential `Φ(s)` or a reward `R(s)`).
pub trait StateFunction {
    /// The function's value at `state`.
    fn value(&self, state: &[f64]) -> f64;
}

impl<F: Fn(&[f64]) -> f64> StateFunction for F {
    fn value(&self, state: &[f64]) -> f64 {
        self(state)
    }
}

/// A function of the state vector and the action, evaluated for every action at once.
pub trait StateActionFunction {
    /// Writes the value of each action at `state` into `out` (length: number of actions).
    fn values(&self, state: &[f64], out: &mut [f64]);
}

/// Whether action selection uses the learned values alone or learned values plus potentials.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Selection {
    /// Greedy on `Q` (what the published DPBA and the thesis's DIS do).
    Uncorrected,
    /// Greedy on `Q + Φ` (Wiewiora's correction; equivalent to initialising `Q` with `Φ`).
    Corrected,
}

/// A state the agent visits: its vector and its active features.
#[derive(Clone, Copy, Debug)]
pub struct Visit<'a> {
    /// The state vector.
    pub state: &'a [f64],
    /// Its active features under the learner's feature map.
    pub features: &'a ActiveFeatures,
}

/// The next state of a non-terminal transition and the actions chosen there.
#[derive(Clone, Copy, Debug)]
pub struct Next<'a> {
    /// The next state.
    pub visit: Visit<'a>,
    /// The behaviour policy's next action `a'`.
    pub action: usize,
    /// The action the learner bootstraps from (`a'` for SARSA, the greedy action for Q-learning).
    pub target: usize,
    /// The scaled potentials of the next state, as [`Shaping::potentials`] returned them.
    pub potentials: &'a [f64],
}

/// One transition `(s, a) → s'`, with `s'` absent when terminal.
#[derive(Clone, Copy, Debug)]
pub struct Transition<'a> {
    /// The state left.
    pub from: Visit<'a>,
    /// The action taken.
    pub action: usize,
    /// The scaled potentials of `from`, as [`Shaping::potentials`] returned them.
    pub potentials: &'a [f64],
    /// The next state, or `None` if the transition ended the episode.
    pub next: Option<Next<'a>>,
    /// The terminal state's vector when the transition ended the episode
    /// (for [`TerminalPotential::Literal`]), else `None`.
    pub terminal_state: Option<&'a [f64]>,
    /// The learner's discount factor.
    pub gamma: f64,
}

/// What Φ is at a terminal state (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum TerminalPotential {
    /// `Φ(terminal) = 0` (Ng, Harada & Russell 1999).
    #[default]
    Zero,
    /// Φ evaluated at the terminal state, as eq. 6.2 writes `Φ(s')`.
    Literal,
}

/// A source of shaping rewards, driven by [`crate::Agent`].
///
/// Protocol: [`Shaping::begin_episode`] once per episode; [`Shaping::potentials`]
/// once for every visited state, in order; [`Shaping::reward`] once per
/// transition, after the potentials of its next state.
pub trait Shaping {
    /// Whether the potentials are added to the learned values when choosing actions.
    fn biases_selection(&self) -> bool;

    /// Called at the start of every episode.
    fn begin_episode(&mut self) {}

    /// The scaled potentials `scale · Φ(s, ·)` of every action at a visited state
    /// (a state potential repeats one value).
    fn potentials(&mut self, visit: &Visit<'_>, out: &mut [f64]);

    /// The scaled shaping reward `scale · F` of a transition. Dynamic shaping learns here.
    fn reward(&mut self, transition: &Transition<'_>) -> f64;

    /// An action the behaviour must take at a visited state instead of its
    /// ε-greedy choice, if any: HAT's forced episodes ("for the first C
    /// episodes, the learner is forced to execute the action suggested by
    /// the rule set", the thesis's section 5.2). Asked once per visited
    /// state, after [`Shaping::potentials`]; a forced action draws no random
    /// number. The default forces nothing.
    #[inline]
    fn forced_action(&mut self, _visit: &Visit<'_>) -> Option<usize> {
        None
    }
}

/// No shaping: `F = 0`.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoShaping;

impl Shaping for NoShaping {
    #[inline]
    fn biases_selection(&self) -> bool {
        false
    }

    #[inline]
    fn potentials(&mut self, _visit: &Visit<'_>, out: &mut [f64]) {
        out.fill(0.0);
    }

    #[inline]
    fn reward(&mut self, _transition: &Transition<'_>) -> f64 {
        0.0
    }
}

/// `γΦ(s', target) − Φ(s, a)` from already scaled potentials, with
/// `terminal` the scaled potential of a terminal `s'` (0 under
/// [`TerminalPotential::Zero`]).
#[inline]
pub(crate) fn potential_difference(t: &Transition<'_>, terminal: impl FnOnce(&[f64]) -> f64) -> f64 {
    let here = t.potentials[t.action];
    match (&t.next, t.terminal_state) {
        (Some(n), _) => t.gamma * n.potentials[n.target] - here,
        (None, Some(state)) => t.gamma * terminal(state) - here,
        (None, None) => -here,
    }
}

#[cfg(test)]
mod tests;
