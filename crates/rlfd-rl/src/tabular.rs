//! Tabular Q-learning over discrete states numbered as they appear.
//!
//! `Q(s, a) ← Q(s, a) + α [r + γ max_b Q(s', b) − Q(s, a)]` (Watkins 1989), with
//! `max_b Q(terminal, b) = 0`. The table grows when a new state number
//! appears, every new entry starting at the initial value (the thesis's
//! chapter 3 starts at 0.5: "initialize Q-table … as states are discovered").

/// A growing table of action values.
#[derive(Clone, Debug, PartialEq)]
pub struct TabularQ {
    q: Vec<f64>,
    num_actions: usize,
    initial: f64,
}

impl TabularQ {
    /// An empty table for `num_actions` actions whose entries start at `initial`.
    pub fn new(num_actions: usize, initial: f64) -> Self {
        assert!(num_actions > 0, "a table needs at least one action");
        TabularQ { q: Vec::new(), num_actions, initial }
    }

    /// Number of states with a row.
    pub fn num_states(&self) -> usize {
        self.q.len() / self.num_actions
    }

    /// Number of actions.
    pub fn num_actions(&self) -> usize {
        self.num_actions
    }

    /// Makes sure state `s` has a row; returns whether it was new.
    pub fn ensure(&mut self, s: usize) -> bool {
        let needed = (s + 1) * self.num_actions;
        if needed > self.q.len() {
            self.q.resize(needed, self.initial);
            true
        } else {
            false
        }
    }

    /// `Q(s, ·)`; the state must have a row.
    pub fn values(&self, s: usize) -> &[f64] {
        &self.q[s * self.num_actions..(s + 1) * self.num_actions]
    }

    /// `Q(s, a)`; the state must have a row.
    pub fn value(&self, s: usize, a: usize) -> f64 {
        self.q[s * self.num_actions + a]
    }

    /// One Q-learning update; `next = None` for a terminal transition.
    pub fn q_learning_update(&mut self, s: usize, a: usize, reward: f64, next: Option<usize>, alpha: f64, gamma: f64) {
        self.ensure(s);
        let bootstrap = match next {
            Some(n) => {
                self.ensure(n);
                self.values(n).iter().copied().fold(f64::NEG_INFINITY, f64::max)
            }
            None => 0.0,
        };
        let i = s * self.num_actions + a;
        self.q[i] += alpha * (reward + gamma * bootstrap - self.q[i]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mdp::FiniteMdp;
    use crate::random::{seeded, uniform01};

    #[test]
    fn grows_with_initial_values() {
        let mut t = TabularQ::new(3, 0.5);
        assert!(t.ensure(2));
        assert!(!t.ensure(1));
        assert_eq!(t.num_states(), 3);
        assert_eq!(t.values(1), &[0.5, 0.5, 0.5]);
    }

    #[test]
    fn update_matches_the_formula() {
        let mut t = TabularQ::new(2, 0.5);
        t.q_learning_update(0, 1, 1.0, Some(1), 0.3, 0.75);
        // 0.5 + 0.3 (1 + 0.75 * 0.5 - 0.5) = 0.7625
        assert!((t.value(0, 1) - 0.7625).abs() < 1e-15);
        t.q_learning_update(1, 0, -1.0, None, 0.3, 0.75);
        assert!((t.value(1, 0) - (0.5 + 0.3 * (-1.0 - 0.5))).abs() < 1e-15);
    }

    #[test]
    fn converges_to_value_iteration_on_a_random_mdp() {
        let mut rng = seeded(9);
        let mdp = FiniteMdp::random(&mut rng, 6, 3, 1, 3);
        let gamma = 0.9;
        let q_star = mdp.value_iteration(gamma, 1e-12, 100_000);
        let mut t = TabularQ::new(3, 0.0);
        for s in 0..6 {
            t.ensure(s);
        }
        // Asynchronous Q-learning from a generative model: every non-terminal
        // (s, a) is sampled uniformly, step sizes 1/n^0.7 per pair.
        let mut visits = [0u32; 6 * 3];
        for _ in 0..1_000_000u64 {
            let s = crate::random::below(&mut rng, 5);
            let a = crate::random::below(&mut rng, 3);
            visits[s * 3 + a] += 1;
            let alpha = 1.0 / (visits[s * 3 + a] as f64).powf(0.7);
            let (next, r) = mdp.sample(s, a, uniform01(&mut rng));
            t.q_learning_update(s, a, r, (!mdp.is_terminal(next)).then_some(next), alpha, gamma);
        }
        for st in 0..6 {
            if mdp.is_terminal(st) {
                continue;
            }
            for a in 0..3 {
                let d = (t.value(st, a) - q_star[st * 3 + a]).abs();
                // Sampling noise and Q-learning's maximisation bias leave a few hundredths.
                assert!(d < 0.06, "Q({st},{a}) = {} vs {}", t.value(st, a), q_star[st * 3 + a]);
            }
        }
    }
}
