//! N environments stepped together in Rust: one call moves every instance
//! one step and writes observations, rewards and end flags into flat
//! buffers, so Python pays its call overhead once per batch, not per
//! environment.
//!
//! Episodes reset themselves in the same step (Gymnasium's "same-step"
//! autoreset): an instance whose episode ended reports the end (its reward,
//! `terminated` or `truncated`), keeps the last observation of the ended
//! episode in `final_observations` (flagged in `has_final`), and its row of
//! `observations` is already the first observation of the next episode.
//! Instance `i` of a batch reset with `seed` is seeded with `seed + i`
//! (Gymnasium's convention for vector environments), then continues its own
//! stream across episodes.
//!
//! Not here: Python objects (`py.rs`).

use crate::domain::{Domain, DomainSpec};

/// The buffers one batched step fills.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Batch {
    /// `n × dim` observations, row-major.
    pub observations: Vec<f64>,
    /// `n` rewards.
    pub rewards: Vec<f64>,
    /// `n` flags: the episode ended in the task.
    pub terminated: Vec<bool>,
    /// `n` flags: the episode hit the step cap.
    pub truncated: Vec<bool>,
    /// `n × dim`: the ended episodes' last observations (rows of instances
    /// that did not end are left as they were).
    pub final_observations: Vec<f64>,
    /// `n` flags: this instance's row of `final_observations` is this step's.
    pub has_final: Vec<bool>,
}

/// N instances of one environment.
#[derive(Clone, Debug)]
pub struct VectorDomain {
    envs: Vec<Domain>,
    dim: usize,
    /// The buffers of the last reset or step.
    pub batch: Batch,
}

impl VectorDomain {
    /// `n` instances of `spec` (at least one).
    pub fn new(spec: DomainSpec, n: usize) -> Result<VectorDomain, String> {
        if n == 0 {
            return Err("num_envs must be at least 1".into());
        }
        let dim = spec.state_dim();
        let envs = (0..n).map(|_| Domain::new(spec.clone())).collect::<Result<Vec<_>, _>>()?;
        let batch = Batch {
            observations: vec![0.0; n * dim],
            rewards: vec![0.0; n],
            terminated: vec![false; n],
            truncated: vec![false; n],
            final_observations: vec![0.0; n * dim],
            has_final: vec![false; n],
        };
        Ok(VectorDomain { envs, dim, batch })
    }

    /// Number of instances.
    pub fn len(&self) -> usize {
        self.envs.len()
    }

    /// Whether there are none (never: `new` refuses 0).
    pub fn is_empty(&self) -> bool {
        self.envs.is_empty()
    }

    /// Observation length.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The instances.
    pub fn envs(&self) -> &[Domain] {
        &self.envs
    }

    /// Resets every instance (instance `i` with `seed + i` when a seed is given).
    pub fn reset(&mut self, seed: Option<u64>) {
        for (i, env) in self.envs.iter_mut().enumerate() {
            env.reset(seed.map(|s| s.wrapping_add(i as u64)));
            self.batch.observations[i * self.dim..(i + 1) * self.dim].copy_from_slice(env.state());
        }
        self.batch.rewards.fill(0.0);
        self.batch.terminated.fill(false);
        self.batch.truncated.fill(false);
        self.batch.has_final.fill(false);
    }

    /// One step of every instance with `actions[i]`; every action is
    /// checked before any instance moves.
    pub fn step(&mut self, actions: &[i64]) -> Result<(), String> {
        if actions.len() != self.envs.len() {
            return Err(format!("expected {} actions (one per environment), got {}", self.envs.len(), actions.len()));
        }
        let mut checked = Vec::with_capacity(actions.len());
        for (i, (env, &a)) in self.envs.iter().zip(actions).enumerate() {
            checked.push(env.check_step(a).map_err(|e| format!("environment {i}: {e}"))?);
        }
        let d = self.dim;
        let b = &mut self.batch;
        for (i, (env, a)) in self.envs.iter_mut().zip(checked).enumerate() {
            let o = env.step(a);
            b.rewards[i] = o.reward;
            b.terminated[i] = o.terminated;
            b.truncated[i] = o.truncated;
            let row = i * d..(i + 1) * d;
            if o.terminated || o.truncated {
                b.final_observations[row.clone()].copy_from_slice(env.state());
                b.has_final[i] = true;
                env.reset(None);
            } else {
                b.has_final[i] = false;
            }
            b.observations[row].copy_from_slice(env.state());
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_batch_equals_the_instances_stepped_one_by_one() {
        let spec =
            DomainSpec::parse("maze", &[("max_episode_steps".into(), crate::domain::OptionValue::Int(5))]).unwrap();
        let mut v = VectorDomain::new(spec.clone(), 3).unwrap();
        v.reset(Some(10));
        let mut single: Vec<Domain> = (0..3).map(|_| Domain::new(spec.clone()).unwrap()).collect();
        for (i, s) in single.iter_mut().enumerate() {
            s.reset(Some(10 + i as u64));
        }
        for t in 0..12 {
            let actions = [t % 4, (t + 1) % 4, 2];
            v.step(&actions).unwrap();
            for (i, s) in single.iter_mut().enumerate() {
                let o = s.step(actions[i] as usize);
                assert_eq!(v.batch.rewards[i], o.reward);
                assert_eq!(v.batch.truncated[i], o.truncated);
                if o.truncated || o.terminated {
                    assert_eq!(&v.batch.final_observations[i * 2..i * 2 + 2], s.state());
                    s.reset(None);
                }
                assert_eq!(&v.batch.observations[i * 2..i * 2 + 2], s.state());
            }
        }
        assert_eq!(v.step(&[0, 1]).unwrap_err(), "expected 3 actions (one per environment), got 2");
        assert_eq!(v.step(&[0, 1, 7]).unwrap_err(), "environment 2: action 7 is out of range: expected 0 to 3");
    }
}
