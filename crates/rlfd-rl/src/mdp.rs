//! Finite MDPs, value iteration, and the shaping theorems checked on them.
//!
//! The thesis's claim C6.11 is that potential-based shaping leaves the optimal
//! policy unchanged (Ng, Harada & Russell 1999). [`check_potential_shaping`]
//! checks it on random MDPs: value iteration on `R` and on `R + F`,
//! `F(s, a, s') = γΦ(s') − Φ(s)` with `Φ(terminal) = 0`, must give
//! `Q′ = Q* − Φ` and the same greedy actions. The same function runs in the
//! property tests and, at report time, for the scorecard.

use rand::Rng;

use crate::random::{below, uniform01};

/// A finite MDP with dense transition and reward arrays and absorbing terminal states.
#[derive(Clone, Debug, PartialEq)]
pub struct FiniteMdp {
    n_states: usize,
    n_actions: usize,
    /// `p[(s * A + a) * S + s']`.
    p: Vec<f64>,
    /// `r[(s * A + a) * S + s']`.
    r: Vec<f64>,
    terminal: Vec<bool>,
}

impl FiniteMdp {
    /// A random MDP: `n_terminal` terminal states (the last ones), each
    /// non-terminal (s, a) reaching `branching` random successors with random
    /// probabilities and rewards in [−1, 1].
    pub fn random<R: Rng + ?Sized>(
        rng: &mut R,
        n_states: usize,
        n_actions: usize,
        n_terminal: usize,
        branching: usize,
    ) -> Self {
        Self::random_inner(rng, n_states, n_actions, n_terminal, branching, false)
    }

    /// A random episodic MDP whose transitions only move to higher-numbered
    /// states, so every policy ends in a terminal state: value iteration
    /// converges with γ = 1 (the thesis's Maze uses γ = 1).
    pub fn random_acyclic<R: Rng + ?Sized>(
        rng: &mut R,
        n_states: usize,
        n_actions: usize,
        n_terminal: usize,
        branching: usize,
    ) -> Self {
        Self::random_inner(rng, n_states, n_actions, n_terminal, branching, true)
    }

    fn random_inner<R: Rng + ?Sized>(
        rng: &mut R,
        n_states: usize,
        n_actions: usize,
        n_terminal: usize,
        branching: usize,
        acyclic: bool,
    ) -> Self {
        assert!(n_terminal >= 1 && n_terminal < n_states && n_actions >= 1 && branching >= 1);
        let s_n = n_states;
        let mut p = vec![0.0; s_n * n_actions * s_n];
        let mut r = vec![0.0; s_n * n_actions * s_n];
        let terminal: Vec<bool> = (0..s_n).map(|s| s >= s_n - n_terminal).collect();
        for s in 0..s_n {
            if terminal[s] {
                continue;
            }
            for a in 0..n_actions {
                let row = (s * n_actions + a) * s_n;
                let mut total = 0.0;
                for _ in 0..branching {
                    let next = if acyclic { s + 1 + below(rng, s_n - s - 1) } else { below(rng, s_n) };
                    let w = 0.1 + uniform01(rng);
                    p[row + next] += w;
                    total += w;
                    r[row + next] = 2.0 * uniform01(rng) - 1.0;
                }
                for x in &mut p[row..row + s_n] {
                    *x /= total;
                }
            }
        }
        FiniteMdp { n_states, n_actions, p, r, terminal }
    }

    /// A two-step episodic MDP from explicit parts (used by tests and examples).
    pub fn from_parts(n_states: usize, n_actions: usize, p: Vec<f64>, r: Vec<f64>, terminal: Vec<bool>) -> Self {
        assert_eq!(p.len(), n_states * n_actions * n_states);
        assert_eq!(r.len(), p.len());
        assert_eq!(terminal.len(), n_states);
        FiniteMdp { n_states, n_actions, p, r, terminal }
    }

    /// Number of states.
    pub fn n_states(&self) -> usize {
        self.n_states
    }

    /// Number of actions.
    pub fn n_actions(&self) -> usize {
        self.n_actions
    }

    /// Whether `s` is terminal.
    pub fn is_terminal(&self, s: usize) -> bool {
        self.terminal[s]
    }

    /// Samples a successor and reward with a uniform draw `u` in [0, 1).
    pub fn sample(&self, s: usize, a: usize, u: f64) -> (usize, f64) {
        let row = (s * self.n_actions + a) * self.n_states;
        let mut acc = 0.0;
        let mut last = 0;
        for next in 0..self.n_states {
            let q = self.p[row + next];
            if q > 0.0 {
                acc += q;
                last = next;
                if u < acc {
                    return (next, self.r[row + next]);
                }
            }
        }
        (last, self.r[row + last])
    }

    /// The MDP with rewards `R + γΦ(s') − Φ(s)`, for a potential given per state.
    pub fn shaped_by(&self, phi: &[f64], gamma: f64) -> FiniteMdp {
        assert_eq!(phi.len(), self.n_states);
        let mut out = self.clone();
        for s in 0..self.n_states {
            for a in 0..self.n_actions {
                let row = (s * self.n_actions + a) * self.n_states;
                for next in 0..self.n_states {
                    out.r[row + next] += gamma * phi[next] - phi[s];
                }
            }
        }
        out
    }

    /// Optimal action values by value iteration (`Q(terminal, ·) = 0`), as `q[s * A + a]`.
    pub fn value_iteration(&self, gamma: f64, tolerance: f64, max_sweeps: usize) -> Vec<f64> {
        let (s_n, a_n) = (self.n_states, self.n_actions);
        let mut q = vec![0.0; s_n * a_n];
        let mut v = vec![0.0; s_n];
        for _ in 0..max_sweeps {
            let mut change: f64 = 0.0;
            for s in 0..s_n {
                if self.terminal[s] {
                    continue;
                }
                for a in 0..a_n {
                    let row = (s * a_n + a) * s_n;
                    let mut total = 0.0;
                    for next in 0..s_n {
                        let pr = self.p[row + next];
                        if pr > 0.0 {
                            total += pr * (self.r[row + next] + gamma * v[next]);
                        }
                    }
                    change = change.max((total - q[s * a_n + a]).abs());
                    q[s * a_n + a] = total;
                }
            }
            for s in 0..s_n {
                v[s] = if self.terminal[s] {
                    0.0
                } else {
                    q[s * a_n..(s + 1) * a_n].iter().copied().fold(f64::NEG_INFINITY, f64::max)
                };
            }
            if change < tolerance {
                break;
            }
        }
        q
    }
}

/// The greedy actions of state `s` (within `tolerance` of the maximum).
pub fn greedy_set(q: &[f64], n_actions: usize, s: usize, tolerance: f64) -> Vec<usize> {
    let row = &q[s * n_actions..(s + 1) * n_actions];
    let best = row.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (0..n_actions).filter(|&a| row[a] >= best - tolerance).collect()
}

/// What [`check_potential_shaping`] found.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapingInvarianceReport {
    /// MDPs checked (half with γ < 1 and cycles, half acyclic with γ = 1).
    pub mdps: usize,
    /// Largest `|Q′(s, a) − (Q*(s, a) − Φ(s))|` over all MDPs, states and actions.
    pub max_shift_error: f64,
    /// Number of non-terminal states whose greedy action sets differ.
    pub greedy_mismatches: usize,
    /// Number of non-terminal states compared.
    pub states_compared: usize,
}

/// Checks Ng et al.'s theorem on `count` random MDPs drawn from `rng`: random
/// potentials, value iteration with and without shaping, `Q′ = Q* − Φ` and
/// equal greedy sets. `terminal` says what Φ is on terminal states: 0 (the
/// theorem's condition), or a random value like any other state's (Φ(s′)
/// as eq. 6.2 writes it, under which the theorem does not apply). The
/// MDPs and non-terminal potentials are the same draws under both.
pub fn check_potential_shaping<R: Rng + ?Sized>(
    rng: &mut R,
    count: usize,
    terminal: crate::shaping::TerminalPotential,
) -> ShapingInvarianceReport {
    let mut report =
        ShapingInvarianceReport { mdps: 0, max_shift_error: 0.0, greedy_mismatches: 0, states_compared: 0 };
    for k in 0..count {
        let n_states = 3 + below(rng, 10);
        let n_actions = 2 + below(rng, 4);
        let n_terminal = 1 + below(rng, 2.min(n_states - 2));
        let branching = 1 + below(rng, 3);
        let (mdp, gamma) = if k % 2 == 0 {
            (FiniteMdp::random(rng, n_states, n_actions, n_terminal, branching), 0.5 + 0.45 * uniform01(rng))
        } else {
            (FiniteMdp::random_acyclic(rng, n_states, n_actions, n_terminal, branching), 1.0)
        };
        let literal = terminal == crate::shaping::TerminalPotential::Literal;
        let phi: Vec<f64> = (0..n_states)
            .map(|s| {
                let drawn = 20.0 * uniform01(rng) - 10.0;
                if mdp.is_terminal(s) && !literal { 0.0 } else { drawn }
            })
            .collect();
        let q = mdp.value_iteration(gamma, 1e-13, 1_000_000);
        let q_shaped = mdp.shaped_by(&phi, gamma).value_iteration(gamma, 1e-13, 1_000_000);
        for s in 0..n_states {
            if mdp.is_terminal(s) {
                continue;
            }
            report.states_compared += 1;
            for a in 0..n_actions {
                let err = (q_shaped[s * n_actions + a] - (q[s * n_actions + a] - phi[s])).abs();
                report.max_shift_error = report.max_shift_error.max(err);
            }
            if greedy_set(&q, n_actions, s, 1e-9) != greedy_set(&q_shaped, n_actions, s, 1e-9) {
                report.greedy_mismatches += 1;
            }
        }
        report.mdps += 1;
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::random::seeded;
    use proptest::prelude::*;

    #[test]
    fn value_iteration_solves_a_hand_made_mdp() {
        // s0 --a0--> T (r = 1); s0 --a1--> s1 (r = 0); s1 --any--> T (r = 3).
        let (s, a) = (3, 2);
        let mut p = vec![0.0; s * a * s];
        let mut r = vec![0.0; s * a * s];
        p[2] = 1.0;
        r[2] = 1.0;
        p[s + 1] = 1.0;
        for act in 0..2 {
            p[(2 + act) * s + 2] = 1.0;
            r[(2 + act) * s + 2] = 3.0;
        }
        let mdp = FiniteMdp::from_parts(3, 2, p, r, vec![false, false, true]);
        let q = mdp.value_iteration(0.5, 1e-15, 100);
        assert_eq!(&q[..4], &[1.0, 1.5, 3.0, 3.0]);
        assert_eq!(greedy_set(&q, 2, 0, 1e-12), vec![1]);
    }

    #[test]
    fn nonzero_terminal_potential_can_change_the_optimal_policy() {
        // s0 --a0--> T1 (r = 1), s0 --a1--> T2 (r = 0), γ = 1: a0 is optimal.
        let mut p = vec![0.0; 3 * 2 * 3];
        let mut r = vec![0.0; 3 * 2 * 3];
        p[1] = 1.0;
        r[1] = 1.0;
        p[3 + 2] = 1.0;
        let mdp = FiniteMdp::from_parts(3, 2, p, r, vec![false, true, true]);
        let q = mdp.value_iteration(1.0, 1e-15, 100);
        assert_eq!(greedy_set(&q, 2, 0, 1e-12), vec![0]);
        // Φ = 0 on the terminals: unchanged.
        let ok = mdp.shaped_by(&[3.0, 0.0, 0.0], 1.0).value_iteration(1.0, 1e-15, 100);
        assert_eq!(greedy_set(&ok, 2, 0, 1e-12), vec![0]);
        // Φ(T2) = 5: the shaping pays for ending in T2, and the optimal action flips.
        let bad = mdp.shaped_by(&[3.0, 0.0, 5.0], 1.0).value_iteration(1.0, 1e-15, 100);
        assert_eq!(greedy_set(&bad, 2, 0, 1e-12), vec![1]);
    }

    #[test]
    fn the_theorem_needs_a_zero_terminal_potential() {
        // The same MDPs and potentials: with Φ(terminal) = 0 nothing changes;
        // with Φ(terminal) drawn like any other state's, some policies do.
        let zero = check_potential_shaping(&mut seeded(11), 40, crate::shaping::TerminalPotential::Zero);
        let literal = check_potential_shaping(&mut seeded(11), 40, crate::shaping::TerminalPotential::Literal);
        assert_eq!((zero.greedy_mismatches, zero.states_compared), (0, literal.states_compared));
        assert!(zero.max_shift_error < 1e-9);
        assert!(literal.greedy_mismatches > 0, "{literal:?}");
    }

    #[test]
    fn zero_potential_changes_nothing() {
        let mut rng = seeded(4);
        let mdp = FiniteMdp::random(&mut rng, 8, 3, 2, 3);
        let q = mdp.value_iteration(0.9, 1e-13, 100_000);
        let q0 = mdp.shaped_by(&[0.0; 8], 0.9).value_iteration(0.9, 1e-13, 100_000);
        assert_eq!(q, q0);
    }

    #[test]
    fn constant_potential_in_a_continuing_mdp_keeps_the_policy() {
        // Algorithms.md §4 (b): adding a constant to Φ (γ < 1) shifts values, not policies.
        let mut rng = seeded(8);
        let mdp = FiniteMdp::random(&mut rng, 9, 3, 1, 3);
        let phi: Vec<f64> = (0..9).map(|s| if s == 8 { 0.0 } else { s as f64 }).collect();
        let shifted: Vec<f64> = phi.iter().enumerate().map(|(s, &x)| if s == 8 { 0.0 } else { x + 7.0 }).collect();
        let q1 = mdp.shaped_by(&phi, 0.8).value_iteration(0.8, 1e-13, 100_000);
        let q2 = mdp.shaped_by(&shifted, 0.8).value_iteration(0.8, 1e-13, 100_000);
        for s in 0..8 {
            assert_eq!(greedy_set(&q1, 3, s, 1e-9), greedy_set(&q2, 3, s, 1e-9));
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        // Claim C6.11: Q′ = Q* − Φ and identical greedy actions, with cycles
        // (γ < 1) and episodic with γ = 1.
        #[test]
        fn potential_shaping_preserves_optimal_policies(seed in any::<u64>()) {
            let report = check_potential_shaping(&mut seeded(seed), 4, crate::shaping::TerminalPotential::Zero);
            prop_assert!(report.max_shift_error < 1e-9, "{:?}", report);
            prop_assert_eq!(report.greedy_mismatches, 0, "{:?}", report);
        }

        // The state-action (look-ahead) form: Q = Q* − Φ(s, a) solves the
        // advised Bellman equation when the greedy step is taken on Q + Φ.
        #[test]
        fn look_ahead_advice_shifts_by_the_potential(seed in any::<u64>()) {
            let mut rng = seeded(seed);
            let (s_n, a_n, gamma) = (7, 3, 0.9);
            let mdp = FiniteMdp::random(&mut rng, s_n, a_n, 1, 3);
            let phi: Vec<f64> = (0..s_n * a_n).map(|i| if mdp.is_terminal(i / a_n) { 0.0 } else { 10.0 * uniform01(&mut rng) - 5.0 }).collect();
            let q_star = mdp.value_iteration(gamma, 1e-13, 100_000);
            let q: Vec<f64> = q_star.iter().zip(&phi).map(|(q, f)| q - f).collect();
            for s in 0..s_n {
                if mdp.is_terminal(s) { continue; }
                for a in 0..a_n {
                    let mut rhs = 0.0;
                    for next in 0..s_n {
                        let pr = mdp.p[(s * a_n + a) * s_n + next];
                        if pr == 0.0 { continue; }
                        let (bootstrap, phi_next) = if mdp.is_terminal(next) {
                            (0.0, 0.0)
                        } else {
                            let b = (0..a_n).max_by(|&x, &y| (q[next * a_n + x] + phi[next * a_n + x]).total_cmp(&(q[next * a_n + y] + phi[next * a_n + y]))).unwrap();
                            (q[next * a_n + b], phi[next * a_n + b])
                        };
                        rhs += pr * (mdp.r[(s * a_n + a) * s_n + next] + gamma * phi_next - phi[s * a_n + a] + gamma * bootstrap);
                    }
                    prop_assert!((rhs - q[s * a_n + a]).abs() < 1e-9);
                }
            }
        }
    }
}
