//! Calibrating the teacher models on what the thesis says about their
//! demonstrations, and on nothing else: the mean demonstration durations of
//! section 5.4 (A 10.4 s, B 10.5 s, C 11.3 s, B Fast 4.3 s, B Limited 5.2 s).
//! No learner runs here, and nothing here was changed after a learner ran.
//!
//! Two kinds of parameter are fitted, by grid search with common random
//! numbers (every candidate plays the same [`CALIBRATION_EPISODES`] episodes'
//! random stream from [`CALIBRATION_SEED`]):
//!
//! 1. **The reaction delay** (real seconds, on [`delay_grid`]) and
//!    **Subject B's perception noise** (m, on [`noise_grid`]), jointly, on
//!    B's three recordings: the pair minimising
//!    `Σ (ln mean_model − ln mean_thesis)²` over B, B Fast (the same person,
//!    the simulator five times faster) and B Limited (no Pass2). The three
//!    durations pin the delay, because speeding the simulator up multiplies
//!    it by five in simulated time.
//! 2. **Subjects A's and C's perception noise**, each on its own mean
//!    duration with the delay fitted in step 1 (people differ more in how
//!    well they read a game than in how fast they press a key).
//!
//! [`calibrate`] reruns the whole procedure; a test checks that it returns
//! the constants shipped below. The report shows each model's mean over the
//! calibration episodes beside the thesis's value, and the 20 episodes each
//! model recorded for the experiments.

use rlfd_rl::random::seeded;

use super::demonstration::mean_duration;
use super::{TeacherModel, TeacherStyle, subject_a, subject_b, subject_b_fast, subject_c};
use crate::keepaway::CYCLES_PER_SECOND;

/// The calibrated reaction delay (s), shared by every teacher.
pub const REACTION_DELAY_S: f64 = 0.2;

/// Subject B's calibrated perception noise (m).
pub const B_PERCEPTION_NOISE: f64 = 1.4;

/// Subject A's calibrated perception noise (m).
pub const A_PERCEPTION_NOISE: f64 = 1.2;

/// Subject C's calibrated perception noise (m).
pub const C_PERCEPTION_NOISE: f64 = 0.8;

/// The random stream of every calibration run (not any experiment's seed).
pub const CALIBRATION_SEED: u64 = 0x6b65_6570_6177_6179; // "keepaway"

/// Episodes per candidate.
pub const CALIBRATION_EPISODES: usize = 400;

/// Candidate reaction delays (s): 0.1 to 0.5 s, whole simulator cycles.
pub fn delay_grid() -> [f64; 5] {
    [0.1, 0.2, 0.3, 0.4, 0.5]
}

/// Candidate perception noises (m): 0 to 3 m in steps of 0.2.
pub fn noise_grid() -> impl Iterator<Item = f64> {
    (0..=15).map(|k| f64::from(k) / 5.0)
}

/// The calibrated values.
#[derive(Clone, Debug, PartialEq)]
pub struct Calibration {
    /// Reaction delay (s).
    pub reaction_delay_s: f64,
    /// Perception noise of A, B and C (m).
    pub noise: [f64; 3],
}

impl Calibration {
    /// A teacher's model with these values (its style and handicaps unchanged).
    pub fn model(&self, teacher: super::Teacher) -> TeacherModel {
        let noise = match teacher {
            super::Teacher::A => self.noise[0],
            super::Teacher::C => self.noise[2],
            _ => self.noise[1],
        };
        TeacherModel { reaction_delay_s: self.reaction_delay_s, perception_noise: noise, ..teacher.model() }
    }

    /// The constants this crate ships.
    pub fn shipped() -> Calibration {
        Calibration {
            reaction_delay_s: REACTION_DELAY_S,
            noise: [A_PERCEPTION_NOISE, B_PERCEPTION_NOISE, C_PERCEPTION_NOISE],
        }
    }
}

/// The mean demonstration duration (s) of a model over the calibration episodes.
pub fn model_mean_seconds(model: &TeacherModel, episodes: usize) -> f64 {
    mean_duration(model, episodes, &mut seeded(CALIBRATION_SEED)) / CYCLES_PER_SECOND
}

fn with(style: &TeacherStyle, delay: f64, noise: f64) -> TeacherModel {
    TeacherModel {
        style: style.clone(),
        reaction_delay_s: delay,
        speedup: 1.0,
        perception_noise: noise,
        allow_pass2: true,
    }
}

/// Step 1: the reaction delay and B's noise (see the module docs).
pub fn calibrate_b(episodes: usize) -> (f64, f64) {
    let targets =
        [super::Teacher::B, super::Teacher::BFast, super::Teacher::BLimited].map(super::Teacher::thesis_mean_seconds);
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for delay in delay_grid() {
        for noise in noise_grid() {
            let b = with(&subject_b::STYLE, delay, noise);
            let fast = TeacherModel { speedup: subject_b_fast::SPEEDUP, ..b.clone() };
            let limited = TeacherModel { allow_pass2: false, ..b.clone() };
            let loss: f64 = [b, fast, limited]
                .iter()
                .zip(targets)
                .map(|(m, t)| {
                    let e = libm::log(model_mean_seconds(m, episodes)) - libm::log(t);
                    e * e
                })
                .sum();
            if loss < best.0 {
                best = (loss, delay, noise);
            }
        }
    }
    (best.1, best.2)
}

/// Step 2: the noise of a style whose mean duration should be `target` s.
pub fn calibrate_noise(style: &TeacherStyle, delay: f64, target: f64, episodes: usize) -> f64 {
    let mut best = (f64::INFINITY, 0.0);
    for noise in noise_grid() {
        let e = (libm::log(model_mean_seconds(&with(style, delay, noise), episodes)) - libm::log(target)).abs();
        if e < best.0 {
            best = (e, noise);
        }
    }
    best.1
}

/// The whole procedure.
pub fn calibrate(episodes: usize) -> Calibration {
    let (delay, b) = calibrate_b(episodes);
    let a = calibrate_noise(&subject_a::STYLE, delay, super::Teacher::A.thesis_mean_seconds(), episodes);
    let c = calibrate_noise(&subject_c::STYLE, delay, super::Teacher::C.thesis_mean_seconds(), episodes);
    Calibration { reaction_delay_s: delay, noise: [a, b, c] }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_constants_are_the_calibrated_ones() {
        assert_eq!(calibrate(CALIBRATION_EPISODES), Calibration::shipped());
    }
}
