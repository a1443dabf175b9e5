//! [`Trajectory`] and [`DemonstrationSet`]: demonstrations in memory, checked
//! once on construction, and the reshaping operations the thesis applies
//! before learning from them (padding, truncation, cutting to the k-th
//! longest length).
//!
//! Not here: files (see `csv_format.rs` and `jsonl.rs`) and anything that
//! learns from demonstrations (RE-IRL, SBS, HAT live in their own modules).
//!
//! ## The action convention
//!
//! `actions[i]` is the action the demonstrator took in `states[i]`, which led
//! to `states[i + 1]`. A trajectory has either one action per state
//! (`actions.len() == states.len()`: the last action led to a state that was
//! not recorded, or the trajectory was cut) or one fewer (`states.len() - 1`:
//! the last state is terminal and has no action). Within a set, either every
//! trajectory has actions or none has, and a set with actions knows its
//! number of actions, against which every action is checked.

use super::error::{TrajectoryError, ValidationError};

/// One demonstration: a sequence of states of a fixed dimension, stored flat,
/// with the demonstrator's actions when they are known.
///
/// Invariants (checked by [`Trajectory::new`]): at least one state, states of
/// at least one value, all values finite, and actions following the
/// convention of this module.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    dimension: usize,
    /// State `i` is `values[i * dimension..(i + 1) * dimension]`.
    values: Vec<f64>,
    actions: Option<Vec<usize>>,
}

impl Trajectory {
    /// A trajectory from a flat buffer of `values.len() / dimension` states.
    pub fn new(values: Vec<f64>, dimension: usize, actions: Option<Vec<usize>>) -> Result<Self, TrajectoryError> {
        if dimension == 0 {
            return Err(TrajectoryError::ZeroDimension);
        }
        if values.is_empty() {
            return Err(TrajectoryError::NoStates);
        }
        if !values.len().is_multiple_of(dimension) {
            return Err(TrajectoryError::Ragged { values: values.len(), dimension });
        }
        if let Some(position) = values.iter().position(|x| !x.is_finite()) {
            return Err(TrajectoryError::NotFinite {
                step: position / dimension,
                index: position % dimension,
                value: values[position],
            });
        }
        let states = values.len() / dimension;
        if let Some(actions) = &actions
            && actions.len() != states
            && actions.len() + 1 != states
        {
            return Err(TrajectoryError::ActionCount { states, actions: actions.len() });
        }
        Ok(Self { dimension, values, actions })
    }

    /// A trajectory from one vector per state; the first state sets the dimension.
    pub fn from_states<S: AsRef<[f64]>>(states: &[S], actions: Option<Vec<usize>>) -> Result<Self, TrajectoryError> {
        let first = states.first().ok_or(TrajectoryError::NoStates)?;
        let dimension = first.as_ref().len();
        let mut values = Vec::with_capacity(states.len() * dimension);
        for (step, state) in states.iter().enumerate() {
            let state = state.as_ref();
            if state.len() != dimension {
                return Err(TrajectoryError::StateLength { step, expected: dimension, found: state.len() });
            }
            values.extend_from_slice(state);
        }
        Self::new(values, dimension, actions)
    }

    /// The number of states (at least 1).
    pub fn len(&self) -> usize {
        self.values.len() / self.dimension
    }

    /// Always `false`: a trajectory holds at least one state.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// The number of values per state.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// State `step`. Panics if `step >= self.len()`, like slice indexing.
    pub fn state(&self, step: usize) -> &[f64] {
        &self.values[step * self.dimension..(step + 1) * self.dimension]
    }

    /// The last state (for a complete episode, the one it ended in).
    pub fn last_state(&self) -> &[f64] {
        self.state(self.len() - 1)
    }

    /// The states in order.
    pub fn states(&self) -> std::slice::ChunksExact<'_, f64> {
        self.values.chunks_exact(self.dimension)
    }

    /// All values, state after state.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The actions, one per state or one fewer (see the module doc).
    pub fn actions(&self) -> Option<&[usize]> {
        self.actions.as_deref()
    }

    /// The action taken in state `step`, if known.
    pub fn action(&self, step: usize) -> Option<usize> {
        self.actions.as_ref()?.get(step).copied()
    }

    /// Every state with the action taken in it, if known.
    pub fn steps(&self) -> impl ExactSizeIterator<Item = (&[f64], Option<usize>)> + '_ {
        self.states().enumerate().map(|(step, state)| (state, self.action(step)))
    }

    /// The first `len` states (all of them if there are fewer), with their actions.
    fn truncated(&self, len: usize) -> Self {
        let len = len.min(self.len());
        Self {
            dimension: self.dimension,
            values: self.values[..len * self.dimension].to_vec(),
            actions: self.actions.as_ref().map(|actions| actions[..len.min(actions.len())].to_vec()),
        }
    }

    /// The states extended to `len` by repeating the last one, without actions.
    fn padded(&self, len: usize) -> Self {
        let mut values = Vec::with_capacity(len.max(self.len()) * self.dimension);
        values.extend_from_slice(&self.values);
        for _ in self.len()..len {
            values.extend_from_slice(self.last_state());
        }
        Self { dimension: self.dimension, values, actions: None }
    }
}

/// A set of demonstrations of one task: named state variables, the number of
/// actions (when known) and at least one trajectory.
///
/// Built only through [`DemonstrationSet::new`] (or a reader), which checks
/// everything, so code that receives a set can rely on it. The operations
/// return new sets and leave this one as it is.
#[derive(Debug, Clone, PartialEq)]
pub struct DemonstrationSet {
    state_names: Vec<String>,
    num_actions: Option<usize>,
    trajectories: Vec<Trajectory>,
}

/// Names the CSV format uses for its own columns.
pub const RESERVED_NAMES: [&str; 3] = ["trajectory", "step", "action"];

impl DemonstrationSet {
    /// Checks and builds a set.
    ///
    /// `state_names` give the dimension and are non-empty, unique, free of
    /// surrounding spaces and none of [`RESERVED_NAMES`]. `num_actions`, when
    /// given, is at least 1; it is required when the trajectories have
    /// actions. Every trajectory has one value per state name, and either
    /// all have actions, each below `num_actions`, or none has.
    pub fn new(
        state_names: Vec<String>,
        num_actions: Option<usize>,
        trajectories: Vec<Trajectory>,
    ) -> Result<Self, ValidationError> {
        check_state_names(&state_names)?;
        if num_actions == Some(0) {
            return Err(ValidationError::ZeroActions);
        }
        let first = trajectories.first().ok_or(ValidationError::NoTrajectories)?;
        let with_actions = first.actions.is_some();
        for (index, trajectory) in trajectories.iter().enumerate() {
            let in_trajectory = |error| ValidationError::Trajectory { index, error };
            if trajectory.dimension != state_names.len() {
                return Err(in_trajectory(TrajectoryError::Dimension {
                    expected: state_names.len(),
                    found: trajectory.dimension,
                }));
            }
            match (&trajectory.actions, with_actions) {
                (Some(_), false) => {
                    return Err(ValidationError::MixedActions { with: index, without: 0 });
                }
                (None, true) => {
                    return Err(ValidationError::MixedActions { with: 0, without: index });
                }
                (Some(actions), true) => {
                    let num_actions = num_actions.ok_or(ValidationError::ActionsWithoutCount { trajectory: index })?;
                    if let Some(step) = actions.iter().position(|&a| a >= num_actions) {
                        return Err(in_trajectory(TrajectoryError::ActionOutOfRange {
                            step,
                            action: actions[step],
                            num_actions,
                        }));
                    }
                }
                (None, false) => {}
            }
        }
        Ok(Self { state_names, num_actions, trajectories })
    }

    /// The names of the state variables, in the order of a state's values.
    pub fn state_names(&self) -> &[String] {
        &self.state_names
    }

    /// The number of values per state.
    pub fn dimension(&self) -> usize {
        self.state_names.len()
    }

    /// The number of actions, when known; always known when [`Self::has_actions`].
    pub fn num_actions(&self) -> Option<usize> {
        self.num_actions
    }

    /// Whether the trajectories carry actions (all do, or none).
    pub fn has_actions(&self) -> bool {
        self.trajectories[0].actions.is_some()
    }

    /// The number of trajectories (at least 1).
    pub fn len(&self) -> usize {
        self.trajectories.len()
    }

    /// Always `false`: a set holds at least one trajectory.
    pub fn is_empty(&self) -> bool {
        self.trajectories.is_empty()
    }

    pub fn trajectories(&self) -> &[Trajectory] {
        &self.trajectories
    }

    pub fn into_trajectories(self) -> Vec<Trajectory> {
        self.trajectories
    }

    /// The number of states of each trajectory, in order.
    pub fn lengths(&self) -> Vec<usize> {
        self.trajectories.iter().map(Trajectory::len).collect()
    }

    /// The number of states over all trajectories.
    pub fn total_states(&self) -> usize {
        self.trajectories.iter().map(Trajectory::len).sum()
    }

    /// Every state of every trajectory, in order.
    pub fn states(&self) -> impl Iterator<Item = &[f64]> + '_ {
        self.trajectories.iter().flat_map(Trajectory::states)
    }

    /// Every demonstrated (state, action) pair, in order: the states that have
    /// an action (so not a terminal last state). Empty for a set without actions.
    pub fn state_action_pairs(&self) -> impl Iterator<Item = (&[f64], usize)> + '_ {
        self.trajectories.iter().flat_map(|t| t.steps().filter_map(|(state, action)| Some((state, action?))))
    }

    /// The common length of the trajectories, or an error naming the first
    /// trajectory whose length differs from trajectory 0's (RE-IRL needs equal
    /// lengths).
    pub fn require_equal_lengths(&self) -> Result<usize, ValidationError> {
        let expected = self.trajectories[0].len();
        match self.trajectories.iter().position(|t| t.len() != expected) {
            None => Ok(expected),
            Some(trajectory) => Err(ValidationError::UnequalLengths {
                trajectory,
                length: self.trajectories[trajectory].len(),
                expected,
            }),
        }
    }

    /// Every trajectory extended to the longest length by repeating its last
    /// observation (the thesis's Maze, for RE-IRL).
    ///
    /// The padded set has no actions, even where nothing was padded: a repeated
    /// observation has no demonstrated action, and a set has actions in every
    /// trajectory or in none. Take (state, action) pairs from the unpadded set.
    /// `num_actions` is kept.
    pub fn pad_to_equal_length(&self) -> DemonstrationSet {
        let len = self.trajectories.iter().map(Trajectory::len).max().unwrap_or(0);
        self.with_trajectories(self.trajectories.iter().map(|t| t.padded(len)).collect())
    }

    /// Every trajectory longer than `max_len` cut to its first `max_len`
    /// states; shorter ones are kept whole. Actions are cut with their states.
    pub fn truncate_to(&self, max_len: usize) -> Result<DemonstrationSet, ValidationError> {
        if max_len == 0 {
            return Err(ValidationError::ZeroLength);
        }
        Ok(self.with_trajectories(self.trajectories.iter().map(|t| t.truncated(max_len)).collect()))
    }

    /// The first `n` observations of every trajectory (the thesis's Figures
    /// 6.6–6.7: demonstrations cut to 100, 500 and 953 observations). Unlike
    /// [`Self::truncate_to`], every trajectory must have at least `n` states,
    /// so the result has equal lengths; the error names the first that has not.
    pub fn first_n_observations(&self, n: usize) -> Result<DemonstrationSet, ValidationError> {
        if n == 0 {
            return Err(ValidationError::ZeroLength);
        }
        if let Some(trajectory) = self.trajectories.iter().position(|t| t.len() < n) {
            return Err(ValidationError::TooShort {
                trajectory,
                length: self.trajectories[trajectory].len(),
                requested: n,
            });
        }
        self.truncate_to(n)
    }

    /// The length of the k-th longest trajectory, `k` counting from 1 (ties
    /// count separately: with lengths 9, 9, 5 the 2nd longest is 9).
    pub fn kth_longest_length(&self, k: usize) -> Result<usize, ValidationError> {
        let mut lengths = self.lengths();
        lengths.sort_unstable_by(|a, b| b.cmp(a));
        k.checked_sub(1)
            .and_then(|index| lengths.get(index).copied())
            .ok_or(ValidationError::NoKthLongest { k, count: lengths.len() })
    }

    /// All trajectories cut to the length of the k-th longest (the thesis's
    /// Mario: 10 demonstrations cut to the 10th-longest length, 953).
    ///
    /// The result has equal lengths. Trajectories shorter than that length
    /// are left out (in order, the others keep their order), which happens
    /// only when the set holds more than `k` trajectories; with exactly `k`,
    /// as in the thesis, all are kept.
    pub fn prune_to_kth_longest(&self, k: usize) -> Result<DemonstrationSet, ValidationError> {
        let len = self.kth_longest_length(k)?;
        Ok(self
            .with_trajectories(self.trajectories.iter().filter(|t| t.len() >= len).map(|t| t.truncated(len)).collect()))
    }

    /// This set's names and action count with other trajectories derived from
    /// its own (never empty, same dimension, actions still in range).
    fn with_trajectories(&self, trajectories: Vec<Trajectory>) -> DemonstrationSet {
        debug_assert!(!trajectories.is_empty(), "derived sets keep at least one trajectory");
        DemonstrationSet { state_names: self.state_names.clone(), num_actions: self.num_actions, trajectories }
    }
}

/// `s0`, `s1`, …: the names of a file that does not name its state variables.
pub fn default_state_names(dimension: usize) -> Vec<String> {
    (0..dimension).map(|i| format!("s{i}")).collect()
}

pub(crate) fn check_state_names(names: &[String]) -> Result<(), ValidationError> {
    if names.is_empty() {
        return Err(ValidationError::NoStateNames);
    }
    // Where each name was first seen: a map, because a file's header may
    // hold any number of names.
    let mut seen = std::collections::BTreeMap::new();
    for (index, name) in names.iter().enumerate() {
        if name.is_empty() {
            return Err(ValidationError::EmptyStateName { index });
        }
        if name.trim() != name {
            return Err(ValidationError::PaddedStateName { index, name: name.clone() });
        }
        if RESERVED_NAMES.contains(&name.as_str()) {
            return Err(ValidationError::ReservedStateName { index, name: name.clone() });
        }
        if let Some(first) = seen.insert(name.as_str(), index) {
            return Err(ValidationError::DuplicateStateName { name: name.clone(), first, second: index });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(names: &[&str]) -> Vec<String> {
        names.iter().map(|s| (*s).to_owned()).collect()
    }

    #[test]
    fn trajectory_checks_its_own_shape() {
        let message = |r: Result<Trajectory, TrajectoryError>| r.unwrap_err().to_string();
        assert_eq!(message(Trajectory::new(vec![], 2, None)), "it has no states");
        assert_eq!(message(Trajectory::new(vec![1.0], 0, None)), "states must have at least one value");
        assert_eq!(message(Trajectory::new(vec![1.0, 2.0, 3.0], 2, None)), "3 values do not split into states of 2");
        assert_eq!(
            message(Trajectory::new(vec![1.0, 2.0, 3.0, f64::NAN], 2, None)),
            "step 1, value 1 is NaN (values must be finite)"
        );
        assert_eq!(
            message(Trajectory::new(vec![1.0, 2.0, 3.0, 4.0], 2, Some(vec![0, 1, 2]))),
            "expected 1 or 2 actions (one per state, the last state's optional), found 3"
        );
        assert_eq!(
            message(Trajectory::from_states(&[vec![1.0, 2.0], vec![3.0]], None)),
            "step 1: expected 2 values, found 1"
        );
    }

    #[test]
    fn set_checks_names_actions_and_dimensions() {
        let t = |actions| Trajectory::new(vec![0.0, 1.0], 2, actions).unwrap();
        let message = |names, n, ts| DemonstrationSet::new(names, n, ts).unwrap_err().to_string();
        assert_eq!(message(names(&["x", "y"]), None, vec![]), "the set holds no trajectories");
        assert_eq!(
            message(names(&["x", "x"]), None, vec![t(None)]),
            "duplicate state name \"x\" (state names 0 and 1)"
        );
        assert_eq!(
            message(names(&["x", "step"]), None, vec![t(None)]),
            "state name 1 (\"step\") is reserved for the CSV format's own columns"
        );
        assert_eq!(
            message(names(&["x", " y"]), None, vec![t(None)]),
            "state name 1 (\" y\") has leading or trailing spaces"
        );
        assert_eq!(
            message(names(&["x"]), None, vec![t(None)]),
            "trajectory 0: its states have 2 values, expected 1 (one per state name)"
        );
        assert_eq!(
            message(names(&["x", "y"]), None, vec![t(Some(vec![1]))]),
            "trajectory 0 has actions, but the number of actions is not given"
        );
        assert_eq!(
            message(names(&["x", "y"]), Some(4), vec![t(Some(vec![1])), t(None)]),
            "trajectory 0 has actions but trajectory 1 has none (either every trajectory has actions or none)"
        );
        assert_eq!(
            message(names(&["x", "y"]), Some(4), vec![t(None), t(Some(vec![1]))]),
            "trajectory 1 has actions but trajectory 0 has none (either every trajectory has actions or none)"
        );
        assert_eq!(
            message(names(&["x", "y"]), Some(4), vec![t(Some(vec![1])), t(Some(vec![4]))]),
            "trajectory 1: step 0: action 4 is out of range 0..4"
        );
        assert_eq!(message(names(&["x", "y"]), Some(0), vec![t(None)]), "the number of actions must be at least 1");
    }

    #[test]
    fn pairs_skip_states_without_actions() {
        let t = Trajectory::from_states(&[[0.0], [1.0], [2.0]], Some(vec![3, 1])).unwrap();
        let set = DemonstrationSet::new(names(&["x"]), Some(4), vec![t]).unwrap();
        let pairs: Vec<(Vec<f64>, usize)> = set.state_action_pairs().map(|(s, a)| (s.to_vec(), a)).collect();
        assert_eq!(pairs, vec![(vec![0.0], 3), (vec![1.0], 1)]);
        assert_eq!(set.states().count(), 3);
    }
}
