//! Tests of the shaping signals: Wiewiora's equivalence with
//! Q-initialisation, DIS's convergence to the expert reward, telescoping.

use rand::Rng;

use super::*;
use crate::SarsaLambda;
use crate::agent::Agent;
use crate::environment::{Environment, Step};
use crate::features::{FeatureMap, TileCoder, TileIndexing};
use crate::params::TdParams;
use crate::random::{seeded, uniform01};
use crate::traces::TraceKind;

/// A `size × size` grid: start (0, 0), goal (size−1, size−1), 4 actions, −1 per step.
struct Grid {
    size: usize,
    pos: (usize, usize),
    state: [f64; 2],
}

impl Environment for Grid {
    fn num_actions(&self) -> usize {
        4
    }
    fn state_dim(&self) -> usize {
        2
    }
    fn reset<R: Rng + ?Sized>(&mut self, _rng: &mut R) {
        self.pos = (0, 0);
        self.state = [0.0, 0.0];
    }
    fn state(&self) -> &[f64] {
        &self.state
    }
    fn step<R: Rng + ?Sized>(&mut self, action: usize, _rng: &mut R) -> Step {
        let (x, y) = self.pos;
        self.pos = match action {
            0 if x > 0 => (x - 1, y),
            1 if x + 1 < self.size => (x + 1, y),
            2 if y + 1 < self.size => (x, y + 1),
            3 if y > 0 => (x, y - 1),
            _ => (x, y),
        };
        self.state = [self.pos.0 as f64, self.pos.1 as f64];
        Step { reward: -1.0, terminal: self.pos == (self.size - 1, self.size - 1) }
    }
}

/// One feature per cell: a tabular representation through the linear machinery.
fn one_hot(size: usize) -> TileCoder {
    TileCoder::new(
        1,
        &[1.0, 1.0],
        TileIndexing::Dense { lower: vec![0.0, 0.0], upper: vec![size as f64 - 0.5, size as f64 - 0.5] },
    )
    .unwrap()
}

/// A fixed random table Φ(cell, a).
struct Table {
    size: usize,
    phi: Vec<f64>,
}

impl StateActionFunction for Table {
    fn values(&self, state: &[f64], out: &mut [f64]) {
        let cell = state[1] as usize * self.size + state[0] as usize;
        out.copy_from_slice(&self.phi[cell * 4..cell * 4 + 4]);
    }
}

#[test]
fn corrected_look_ahead_equals_q_initialisation() {
    let size = 6;
    let scale = 3.0;
    let mut rng = seeded(12);
    let mut phi: Vec<f64> = (0..size * size * 4).map(|_| 4.0 * uniform01(&mut rng) - 2.0).collect();
    // The goal cell is terminal: its potential is 0.
    let goal = (size * size - 1) * 4;
    phi[goal..goal + 4].fill(0.0);
    let params = TdParams { alpha: 0.2, gamma: 1.0, lambda: 0.6, epsilon: 0.1 }.check().unwrap();
    let features = one_hot(size);

    // A: no shaping, weights initialised to scale·Φ (one weight per cell and action).
    let mut learner_a = SarsaLambda::new(features.num_features(), 4, params, TraceKind::Replacing);
    for cell in 0..size * size {
        let mut f = crate::features::ActiveFeatures::default();
        features.features(&[(cell % size) as f64, (cell / size) as f64], &mut f);
        for a in 0..4 {
            let i = learner_a.action_values_table().weight_index(f.indices[0], a);
            learner_a.action_values_table_mut().weights_mut()[i] = scale * phi[cell * 4 + a];
        }
    }
    let mut agent_a = Agent::new(features.clone(), learner_a, NoShaping);
    // B: weights 0, look-ahead advice with Wiewiora's correction.
    let learner_b = SarsaLambda::new(features.num_features(), 4, params, TraceKind::Replacing);
    let mut agent_b = Agent::new(
        features.clone(),
        learner_b,
        LookAheadShaping::new(Table { size, phi: phi.clone() }, scale, Selection::Corrected),
    );

    let (mut env_a, mut env_b) =
        (Grid { size, pos: (0, 0), state: [0.0; 2] }, Grid { size, pos: (0, 0), state: [0.0; 2] });
    let (mut rng_a, mut rng_b) = (seeded(99), seeded(99));
    for episode in 0..60 {
        let a = agent_a.run_episode(&mut env_a, &mut rng_a, 10_000);
        let b = agent_b.run_episode(&mut env_b, &mut rng_b, 10_000);
        assert_eq!(a, b, "episode {episode} differs");
    }
    // And the values agree: Q_A = Q_B + scale·Φ.
    let wa = agent_a.learner().action_values_table().weights();
    let wb = agent_b.learner().action_values_table().weights();
    let mut f = crate::features::ActiveFeatures::default();
    for cell in 0..size * size {
        features.features(&[(cell % size) as f64, (cell / size) as f64], &mut f);
        for a in 0..4 {
            let i = f.indices[0] as usize * 4 + a;
            assert!((wa[i] - (wb[i] + scale * phi[cell * 4 + a])).abs() < 1e-9);
        }
    }
}

#[test]
fn uncorrected_look_ahead_does_not_bias_selection() {
    let s = LookAheadShaping::new(Table { size: 2, phi: vec![0.0; 16] }, 1.0, Selection::Uncorrected);
    assert!(!s.biases_selection());
    let s = LookAheadShaping::new(Table { size: 2, phi: vec![0.0; 16] }, 1.0, Selection::Corrected);
    assert!(s.biases_selection());
}

#[test]
fn zero_potential_is_the_same_as_no_shaping() {
    let size = 5;
    let params = TdParams { alpha: 0.3, gamma: 1.0, lambda: 0.5, epsilon: 0.1 }.check().unwrap();
    let features = one_hot(size);
    let run = |shaped: bool| {
        let learner = SarsaLambda::new(features.num_features(), 4, params, TraceKind::Replacing);
        let mut env = Grid { size, pos: (0, 0), state: [0.0; 2] };
        let mut rng = seeded(3);
        if shaped {
            let mut agent = Agent::new(features.clone(), learner, StaticShaping::new(|_: &[f64]| 0.0, 100.0));
            (0..30).map(|_| agent.run_episode(&mut env, &mut rng, 5_000)).collect::<Vec<_>>()
        } else {
            let mut agent = Agent::new(features.clone(), learner, NoShaping);
            (0..30).map(|_| agent.run_episode(&mut env, &mut rng, 5_000)).collect::<Vec<_>>()
        }
    };
    assert_eq!(run(true), run(false));
}

#[test]
fn static_shaping_telescopes_to_the_terminal_minus_the_start_potential() {
    // With γ = 1, Σ_t F_t over a terminated episode = Φ(terminal) − Φ(s0):
    // −Φ(s0) with Φ(terminal) = 0, Φ(goal) − Φ(s0) under the literal reading.
    let phi = |s: &[f64]| 3.0 * s[0] - 2.0 * s[1] + 7.0;
    let path = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [2.0, 1.0], [2.0, 2.0]];
    for (terminal, expected) in [
        (TerminalPotential::Zero, -2.0 * phi(&[0.0, 0.0])),
        (TerminalPotential::Literal, 2.0 * (phi(&[2.0, 2.0]) - phi(&[0.0, 0.0]))),
    ] {
        let mut shaping = StaticShaping::new(phi, 2.0).with_terminal(terminal);
        let features = one_hot(4);
        let mut fs = crate::features::ActiveFeatures::default();
        let mut fn_ = crate::features::ActiveFeatures::default();
        let mut total = 0.0;
        for w in path.windows(2) {
            let (mut p, mut pn) = ([0.0; 4], [0.0; 4]);
            features.features(&w[0], &mut fs);
            features.features(&w[1], &mut fn_);
            shaping.potentials(&Visit { state: &w[0], features: &fs }, &mut p);
            shaping.potentials(&Visit { state: &w[1], features: &fn_ }, &mut pn);
            let last = w[1] == path[path.len() - 1];
            let next = Next { visit: Visit { state: &w[1], features: &fn_ }, action: 0, target: 0, potentials: &pn };
            total += shaping.reward(&Transition {
                from: Visit { state: &w[0], features: &fs },
                action: 1,
                potentials: &p,
                next: (!last).then_some(next),
                terminal_state: last.then_some(&w[1][..]),
                gamma: 1.0,
            });
        }
        assert_eq!(total, expected, "{terminal:?}");
    }
}

#[test]
fn literal_look_ahead_uses_the_best_advice_at_the_terminal_state() {
    struct Advice;
    impl StateActionFunction for Advice {
        fn values(&self, state: &[f64], out: &mut [f64]) {
            out.copy_from_slice(&[state[0], 2.0 * state[0]]);
        }
    }
    let features = one_hot(4);
    let mut fs = crate::features::ActiveFeatures::default();
    features.features(&[1.0, 0.0], &mut fs);
    for (terminal, expected) in
        [(TerminalPotential::Zero, -10.0), (TerminalPotential::Literal, 10.0 * (2.0 * 3.0 - 1.0))]
    {
        let mut shaping = LookAheadShaping::new(Advice, 10.0, Selection::Corrected).with_terminal(terminal, 2);
        let mut p = [0.0; 2];
        shaping.potentials(&Visit { state: &[1.0, 0.0], features: &fs }, &mut p);
        let f = shaping.reward(&Transition {
            from: Visit { state: &[1.0, 0.0], features: &fs },
            action: 0,
            potentials: &p,
            next: None,
            terminal_state: Some(&[3.0, 0.0]),
            gamma: 1.0,
        });
        assert_eq!(f, expected, "{terminal:?}");
    }
}

#[test]
fn dynamic_shaping_delivers_the_expert_reward_after_convergence() {
    // A deterministic chain 0 → 1 → … → 9 (terminal) under a single action:
    // Φ† converges to Φ^π = −R† + γ Φ^π(next), and then F(s → s') = R†(s).
    let n = 10usize;
    let gamma = 0.9;
    let expert = |s: &[f64]| 1.0 + 0.5 * s[0];
    let features =
        TileCoder::new(1, &[1.0], TileIndexing::Dense { lower: vec![0.0], upper: vec![n as f64 - 0.5] }).unwrap();
    let mut dis = DynamicShaping::new(features.num_features(), 1, expert, 0.5, 1.0, Selection::Uncorrected);
    let mut f_s = crate::features::ActiveFeatures::default();
    let mut f_n = crate::features::ActiveFeatures::default();
    let mut last_f = vec![0.0; n - 1];
    for _episode in 0..400 {
        dis.begin_episode();
        for s in 0..n - 1 {
            let (x, xn) = ([s as f64], [(s + 1) as f64]);
            let (mut p, mut pn) = ([0.0], [0.0]);
            features.features(&x, &mut f_s);
            features.features(&xn, &mut f_n);
            dis.potentials(&Visit { state: &x, features: &f_s }, &mut p);
            dis.potentials(&Visit { state: &xn, features: &f_n }, &mut pn);
            let terminal = s + 1 == n - 1;
            let next = Next { visit: Visit { state: &xn, features: &f_n }, action: 0, target: 0, potentials: &pn };
            last_f[s] = dis.reward(&Transition {
                from: Visit { state: &x, features: &f_s },
                action: 0,
                potentials: &p,
                next: (!terminal).then_some(next),
                terminal_state: None,
                gamma,
            });
        }
    }
    for (s, &f) in last_f.iter().enumerate() {
        let r = expert(&[s as f64]);
        if s + 2 < n {
            assert!((f - r).abs() < 1e-6, "F({s}) = {f}, R†({s}) = {r}");
        }
    }
    // Φ† itself approaches −Σ_k γ^k R†(s + k) along the chain.
    let mut f = crate::features::ActiveFeatures::default();
    features.features(&[(n - 2) as f64], &mut f);
    let v = dis.secondary_values().value(&f, 0);
    assert!((v + expert(&[(n - 2) as f64])).abs() < 1e-6, "Φ†(n−2) = {v}");
}
