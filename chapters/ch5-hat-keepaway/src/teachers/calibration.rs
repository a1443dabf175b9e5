//! Calibrating the teacher models on what the thesis says about their
//! demonstrations, and on nothing else (section 5.4): the mean demonstration
//! durations (A 10.4 s, B 10.5 s, C 11.3 s) and, for Subject A, the summary
//! JRip made of them ("summarized with only four rules, obtaining over 87%
//! accuracy" in stratified cross-validation). No learner runs here, and
//! nothing here was changed after a learner ran. B Fast (4.3 s) and B
//! Limited (5.2 s) are not fitted: they are Subject B's model with the
//! thesis's handicaps, and the report shows how far they land from the
//! thesis's values (out-of-sample checks).
//!
//! Fixed, not fitted:
//!
//! - a person's reaction time, a delay of 0.2 s plus `U(0, 0.2)` s per
//!   decision ([`REACTION_DELAY_S`], [`REACTION_JITTER_S`]: visual reaction
//!   times of 0.2–0.4 s);
//! - each subject's style (its file);
//! - the perception noise, [`PERCEPTION_NOISE`] = 0 m for every teacher
//!   (declared in issue 28, before the runs that use it). The thesis's
//!   teachers "watch the visualization" and "the human uses a visualizer
//!   (Figure 5.2)" (thesis.txt line 823). The visualiser draws what the
//!   server sends its monitors, the true positions of the ball and the
//!   players, rounded to 1/16 m (rcssserver 11.1.2, `field.C:1129–1139`;
//!   1/65536 m in the newer monitor protocol, `field.C:1165–1179`): unlike
//!   the players, the person watching sees the game as it is. The thesis
//!   says nothing of a person misjudging what is drawn, and what it reports
//!   of the demonstrations cannot pin a misjudgement either: the models'
//!   mean durations are flat or falling in the noise, within their sampling
//!   noise up to about 1 m (round-3 review, section 4), and lie below every
//!   target at every noise from 0 to 2 m (when the noise was declared: A
//!   8.02 s, B 8.57 s, C 9.43 s at 0 m, none above 8.1, 8.8 and 9.5 s at
//!   any noise; targets 10.4, 10.5, 11.3 s), so a fit chose sampling noise
//!   (B's 0.8 m was its curve's highest point, 8.72 s against 8.57 s at
//!   0 m), and the chosen value moved whenever the simulator changed
//!   (Subject B: 0.4 → 0 → 0.8 m over three simulator commits). What a
//!   person's slowness costs is in the reaction delay. Since the players'
//!   collision sensing and see phases (issue 28) the curves are higher (A
//!   9.74 s, B 10.95 s, C 10.67 s at 0 m) and still flat within their
//!   sampling noise up to about 0.8 m, falling beyond; the declaration
//!   stands.
//!
//! Fitted by grid search with common random numbers (every candidate plays
//! the same episodes' random stream from [`CALIBRATION_SEED`]), at the
//! declared noise: **Subject A**'s rise of the pass threshold in the middle
//! of the field ([`centre_extra_grid`]), minimising `(ln d − ln 10.4)² +
//! ((cv − 0.87)/0.05)² + ((r − 3)/2)² + (f − 2)²` where `d` is the mean
//! duration over [`CALIBRATION_EPISODES`] episodes, and `cv`, `r` and `f`
//! are the 10-fold CV accuracy, the number of rules (besides the default)
//! and the number of them that test the keeper's distance from the centre
//! (`state_0`; two of the thesis's three) of JRip on [`RULE_SETS`]
//! recordings of 20 episodes.
//!
//! The thesis's durations were played on the real soccer server, where the
//! benchmark Hand-coded keepers last 17.4 s; in our simulator they last
//! 17.3 s since issue 28's collision sensing and see phases (about 10 s
//! before; the report's validation). The models' calibration episodes then
//! last A 9.74 s, B 10.95 s and C 10.67 s (targets 10.4, 10.5, 11.3 s); A's
//! fit ends at the grid's largest rise, as it did before.
//!
//! A diagnostic, feeding no run: [`noise_curve`], a teacher's mean duration
//! at each noise of [`noise_grid`], printed by `cargo xtask calibrate
//! keepaway-teachers` beside the fit, to show how little the durations say
//! about the noise.
//!
//! [`calibrate`] reruns the fit; an ignored test checks that it returns the
//! shipped constants.

use rlfd_lfd::ripper::{Ripper, RipperParams, stratified_cross_validation};
use rlfd_rl::random::seeded;

use super::demonstration::{mean_duration, record};
use super::{FrequentPasser, Teacher, TeacherModel, subject_a};
use crate::keepaway::CYCLES_PER_SECOND;

/// The reaction delay (s), the shortest a person takes (fixed).
pub const REACTION_DELAY_S: f64 = 0.2;

/// How much longer a reaction may take (s), uniformly (fixed).
pub const REACTION_JITTER_S: f64 = 0.2;

/// Every teacher's perception noise (m): declared, not fitted (see the module docs).
pub const PERCEPTION_NOISE: f64 = 0.0;

/// Subject A's calibrated rise of the pass threshold in the middle of the field (pass score).
pub const A_CENTRE_EXTRA: f64 = 150.0;

/// The random stream of every calibration run (not any experiment's seed).
pub const CALIBRATION_SEED: u64 = 0x6b65_6570_6177_6179; // "keepaway"

/// Episodes per candidate for the mean duration.
pub const CALIBRATION_EPISODES: usize = 300;

/// Recordings of 20 episodes per candidate for Subject A's rule list.
pub const RULE_SETS: usize = 4;

/// The thesis's Subject A rule list: four rules (three and the default), over 87 % CV accuracy.
pub const A_RULES: f64 = 3.0;

/// See [`A_RULES`].
pub const A_CV_ACCURACY: f64 = 0.87;

/// Rules of the thesis's list for A that test `state_0` (the second and the third).
pub const A_FIELD_RULES: f64 = 2.0;

/// The noises (m) of the diagnostic [`noise_curve`]: 0 to 2 m in steps of 0.2.
pub fn noise_grid() -> impl Iterator<Item = f64> {
    (0..=10).map(|k| f64::from(k) / 5.0)
}

/// Candidate rises of Subject A's pass threshold in the middle (pass score; 150: it passes there only when a taker is within the panic distance, lane scores rarely reaching 240).
pub fn centre_extra_grid() -> [f64; 5] {
    [0.0, 30.0, 60.0, 90.0, 150.0]
}

/// The calibrated value.
#[derive(Clone, Debug, PartialEq)]
pub struct Calibration {
    /// Subject A's rise of the pass threshold in the middle.
    pub a_centre_extra: f64,
}

impl Calibration {
    /// A teacher's model with this value (its style as `passer` assigns
    /// it, its handicaps and the declared noise unchanged).
    pub fn model(&self, teacher: Teacher, passer: FrequentPasser) -> TeacherModel {
        let mut m = teacher.model(passer);
        if teacher == Teacher::A {
            m.style.centre_extra = self.a_centre_extra;
        }
        m
    }

    /// The constant this crate ships.
    pub fn shipped() -> Calibration {
        Calibration { a_centre_extra: A_CENTRE_EXTRA }
    }
}

/// The mean demonstration duration (s) of a model over `episodes` calibration episodes.
pub fn model_mean_seconds(model: &TeacherModel, episodes: usize) -> f64 {
    mean_duration(model, episodes, &mut seeded(CALIBRATION_SEED)) / CYCLES_PER_SECOND
}

/// What JRip makes of a model's recordings: the mean 10-fold CV accuracy
/// and the mean number of rules (the default not counted) over [`RULE_SETS`]
/// recordings of 20 episodes, and the mean number of those rules that test
/// the keeper's distance from the centre (`state_0`).
pub fn rule_properties(model: &TeacherModel) -> (f64, f64, f64) {
    let params = RipperParams::weka_3_6();
    let (mut cv, mut rules, mut field) = (0.0, 0.0, 0.0);
    for s in 0..RULE_SETS {
        let set = record(model, "A", 20, &mut seeded(CALIBRATION_SEED ^ (s as u64 + 1)));
        let Ok(data) = crate::inputs::dataset(&set) else { continue };
        let (Ok(list), Ok(c)) = (Ripper::fit(&params, &data), stratified_cross_validation(&params, &data, 10, 1))
        else {
            continue;
        };
        cv += c.accuracy;
        rules += list.rules.len() as f64;
        field += list.rules.iter().filter(|r| r.conditions.iter().any(|c| c.attribute == 0)).count() as f64;
    }
    let n = RULE_SETS as f64;
    (cv / n, rules / n, field / n)
}

/// The fit: Subject A's rise of the threshold in the middle, at the declared noise (see the module docs).
pub fn calibrate() -> Calibration {
    let target = Teacher::A.thesis_mean_seconds();
    let mut best = (f64::INFINITY, 0.0);
    for bonus in centre_extra_grid() {
        let mut m = subject_a::model();
        m.style.centre_extra = bonus;
        let d = model_mean_seconds(&m, CALIBRATION_EPISODES);
        let (cv, rules, field) = rule_properties(&m);
        let e = libm::log(d) - libm::log(target);
        let loss = e * e
            + ((cv - A_CV_ACCURACY) / 0.05).powi(2)
            + ((rules - A_RULES) / 2.0).powi(2)
            + (field - A_FIELD_RULES).powi(2);
        if loss < best.0 {
            best = (loss, bonus);
        }
    }
    Calibration { a_centre_extra: best.1 }
}

/// The diagnostic: a teacher's mean duration (s) over the calibration
/// episodes at each noise of [`noise_grid`], its model otherwise as shipped
/// (B's and C's styles as `passer` assigns them). It feeds no run (the
/// noise is declared, [`PERCEPTION_NOISE`]).
pub fn noise_curve(teacher: Teacher, passer: FrequentPasser) -> Vec<(f64, f64)> {
    noise_grid()
        .map(|noise| {
            let m = TeacherModel { perception_noise: noise, ..teacher.model(passer) };
            (noise, model_mean_seconds(&m, CALIBRATION_EPISODES))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fit takes about half a minute; `cargo xtask calibrate
    /// keepaway-teachers` runs it too.
    #[test]
    #[ignore = "about half a minute; run with --ignored or cargo xtask calibrate keepaway-teachers"]
    fn the_shipped_constant_is_the_calibrated_one() {
        assert_eq!(calibrate(), Calibration::shipped());
    }

    #[test]
    fn every_teacher_sees_with_the_declared_noise() {
        for passer in [FrequentPasser::B, FrequentPasser::C] {
            for t in Teacher::ALL {
                assert_eq!(t.model(passer).perception_noise, PERCEPTION_NOISE, "{t:?}");
            }
            assert_eq!(Calibration::shipped().model(Teacher::A, passer), subject_a::model());
        }
        assert_eq!(PERCEPTION_NOISE, 0.0);
    }
}
