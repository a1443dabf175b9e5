//! A reference kernel: the Maze baseline (SARSA(λ), 32 dense tilings,
//! replacing traces, ε-greedy) written as one plain loop over flat arrays,
//! with none of the library's layers (no [`rlfd_rl::Agent`], no feature map
//! or learner traits, no shaping hooks).
//!
//! It exists to measure how close the library comes to the limit of this
//! learner (issue 30's target: the library's SARSA(λ) at ≥ 1.0× this kernel,
//! run in the same window; `cargo xtask bench` prints both lines, and
//! `cargo bench -p ch6-irl-shaping --bench maze` both benches). It is the
//! same learner bit for bit: the same random draws in the same order, the
//! same tile indices, the same sums in the same order, traces dropped at the
//! same threshold, so for a seed it plays the same episodes as
//! [`super::params::run_trial`] with [`crate::shaping::Agent::Baseline`] (a
//! test checks every return and step count). What it leaves out is what a
//! baseline trial never reaches: divergence checks (the learner's values stay
//! within ±10⁴ in every stored trial) and other trace kinds or layouts'
//! parameters than the paper's 32 tilings.
//!
//! Not used by any experiment.

use rlfd_rl::Environment;
use rlfd_rl::random::{SimRng, below, seeded, uniform01};

use super::params::MazeParams;
use super::{Maze, MazeLayout, MazeRewards};
use rlfd_rl::TraceKind;

/// The Maze's four moves.
const ACTIONS: usize = 4;

/// Returns and agent steps of one baseline trial of `params` from `seed`.
///
/// # Panics
/// If `params` asks for accumulating traces or other than 32 tilings (the
/// kernel has the thesis's Maze learner's alone).
pub fn run_trial(params: &MazeParams, seed: u64) -> (Vec<f64>, Vec<u32>) {
    assert_eq!(params.traces, TraceKind::Replacing, "the reference kernel has replacing traces only");
    assert_eq!(params.tilings, TILINGS, "the reference kernel has the thesis's 32 tilings only");
    let coder = DenseTiles::new(params.tile_width);
    let mut k = Kernel {
        w: vec![0.0; coder.features * ACTIONS],
        slot: vec![NO_SLOT; coder.features],
        live: Vec::with_capacity(1024),
        alpha: params.alpha,
        gamma: params.gamma,
        decay: params.gamma * params.lambda,
        epsilon: params.epsilon,
    };
    let mut env = Maze::new(MazeLayout::of(params.layout), 2, MazeRewards::THESIS);
    let mut rng = seeded(seed);
    let (mut f, mut next_f) = ([0u32; TILINGS], [0u32; TILINGS]);
    let (mut returns, mut steps) = (Vec::with_capacity(params.episodes), Vec::with_capacity(params.episodes));
    for _ in 0..params.episodes {
        env.reset(&mut rng);
        k.clear_traces();
        coder.tiles(env.state(), &mut f);
        let mut action = k.choose(&k.values(&f), &mut rng);
        let (mut ret, mut n) = (0.0, 0usize);
        while n < params.max_steps {
            let step = env.step(action, &mut rng);
            ret += step.reward;
            n += 1;
            let q_sa = k.mark(&f, action);
            if step.terminal {
                k.apply(params.alpha * (step.reward - q_sa), false);
                break;
            }
            coder.tiles(env.state(), &mut next_f);
            let next_q = k.values(&next_f);
            let next_action = k.choose(&next_q, &mut rng);
            let delta = step.reward + k.gamma * next_q[next_action] - q_sa;
            k.apply(k.alpha * delta, true);
            std::mem::swap(&mut f, &mut next_f);
            action = next_action;
        }
        returns.push(ret);
        steps.push(n as u32);
    }
    (returns, steps)
}

/// The thesis's tilings (the kernel is written for them alone).
const TILINGS: usize = 32;

/// The tile coder of `rlfd_rl::features::TileCoder` with dense indexing on
/// the unit square and 32 tilings: tiling `t` offsets dimension `i` by
/// `t·(2i + 1) mod 32` thirty-seconds of a tile.
struct DenseTiles {
    scale: f64,
    q_max: i64,
    row: usize,
    features: usize,
}

impl DenseTiles {
    fn new(width: f64) -> Self {
        let scale = 1.0 / width;
        let n = TILINGS as i64;
        let q_max = (1.0 * scale * n as f64).floor() as i64;
        let row = ((q_max + n - 1) / n + 1) as usize;
        DenseTiles { scale, q_max, row, features: TILINGS * row * row }
    }

    #[inline]
    fn tiles(&self, state: &[f64], out: &mut [u32; TILINGS]) {
        let quantise = |x: f64| {
            let v = x * self.scale * TILINGS as f64;
            let t = v as i64;
            (t - i64::from((t as f64) > v)).clamp(0, self.q_max) as usize
        };
        let (qx, qy) = (quantise(state[0]), quantise(state[1]));
        let per_tiling = self.row * self.row;
        for (t, out) in out.iter_mut().enumerate() {
            let x = (qx + t) / TILINGS;
            let y = (qy + (3 * t) % TILINGS) / TILINGS;
            *out = (t * per_tiling + x + y * self.row) as u32;
        }
    }
}

/// The weights and the replacing traces: at most one trace per feature
/// (marking a feature with one action replaces its trace for the others),
/// the live ones in one array, each feature's place in it in `slot`.
struct Kernel {
    w: Vec<f64>,
    slot: Vec<u32>,
    live: Vec<Trace>,
    alpha: f64,
    gamma: f64,
    decay: f64,
    epsilon: f64,
}

/// A live trace: its feature, the weight it updates and its value.
#[derive(Clone, Copy)]
struct Trace {
    feature: u32,
    weight: u32,
    value: f64,
}

const NO_SLOT: u32 = u32::MAX;

impl Kernel {
    #[inline]
    fn values(&self, f: &[u32]) -> [f64; ACTIONS] {
        let mut q = [0.0; ACTIONS];
        for &k in f {
            let row = &self.w[k as usize * ACTIONS..k as usize * ACTIONS + ACTIONS];
            for a in 0..ACTIONS {
                q[a] += row[a];
            }
        }
        q
    }

    /// ε-greedy with ties broken uniformly, drawing as `rlfd_rl::policy` does.
    #[inline]
    fn choose(&self, q: &[f64; ACTIONS], rng: &mut SimRng) -> usize {
        if uniform01(rng) < self.epsilon {
            return below(rng, ACTIONS);
        }
        let best = q.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let ties = q.iter().filter(|&&v| v == best).count();
        let mut pick = if ties > 1 { below(rng, ties) } else { 0 };
        for (a, &v) in q.iter().enumerate() {
            if v == best {
                if pick == 0 {
                    return a;
                }
                pick -= 1;
            }
        }
        0
    }

    /// Q(s, a) of the active features, each marked with trace 1 for `a`.
    #[inline]
    fn mark(&mut self, f: &[u32], a: usize) -> f64 {
        let mut q = 0.0;
        for &k in f {
            let weight = k as usize * ACTIONS + a;
            q += self.w[weight];
            let trace = Trace { feature: k, weight: weight as u32, value: 1.0 };
            match self.slot[k as usize] {
                NO_SLOT => {
                    self.slot[k as usize] = self.live.len() as u32;
                    self.live.push(trace);
                }
                s => self.live[s as usize] = trace,
            }
        }
        q
    }

    /// Adds `step` times each live trace to its weight, then (if `decay`)
    /// decays the traces, dropping those below `rlfd_rl`'s threshold.
    #[inline]
    fn apply(&mut self, step: f64, decay: bool) {
        let mut s = 0;
        while s < self.live.len() {
            let t = self.live[s];
            self.w[t.weight as usize] += step * t.value;
            if !decay {
                s += 1;
                continue;
            }
            let v = t.value * self.decay;
            if v.abs() < rlfd_rl::traces::MIN_TRACE {
                self.slot[t.feature as usize] = NO_SLOT;
                self.live.swap_remove(s);
                if let Some(moved) = self.live.get(s) {
                    self.slot[moved.feature as usize] = s as u32;
                }
            } else {
                self.live[s].value = v;
                s += 1;
            }
        }
    }

    fn clear_traces(&mut self) {
        for t in &self.live {
            self.slot[t.feature as usize] = NO_SLOT;
        }
        self.live.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maze::params::MazeParams;
    use crate::shaping::Agent;

    #[test]
    fn the_kernel_plays_the_library_baselines_episodes_bit_for_bit() {
        let params = MazeParams { episodes: 40, ..MazeParams::paper() };
        for seed in [1, 2, 20160501] {
            let library = crate::shaping::run_trial(Agent::Baseline, &params, None, seed);
            let (returns, steps) = run_trial(&params, seed);
            assert_eq!(steps, library.steps, "seed {seed}");
            let bits = |r: &[f64]| r.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&returns), bits(&library.returns), "seed {seed}");
        }
    }

    #[test]
    fn its_tiles_are_the_library_coders() {
        use rlfd_rl::features::{ActiveFeatures, FeatureMap};
        let params = MazeParams::paper();
        let (lib, mine) = (params.tile_coder(), DenseTiles::new(params.tile_width));
        assert_eq!(lib.num_features(), mine.features);
        let (mut a, mut b) = (ActiveFeatures::with_capacity(32), [0u32; TILINGS]);
        for ix in 0..=100 {
            for iy in [0, 1, 37, 50, 99, 100] {
                let s = [f64::from(ix) / 100.0, f64::from(iy) / 100.0];
                lib.features(&s, &mut a);
                mine.tiles(&s, &mut b);
                assert_eq!(a.indices, b.to_vec(), "state {s:?}");
            }
        }
    }
}
