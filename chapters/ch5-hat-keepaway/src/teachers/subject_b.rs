//! Subject B: "This teacher is new to Keepaway, but practiced for
//! approximately 100 games before recording demonstrations" (thesis.txt
//! line 889). Its 20 demonstration episodes lasted 10.5 s on average (line
//! 952).
//!
//! Style: one of the two the thesis names ([`super::styles`]); which one is
//! the `bc-styles` reading (default: B passes frequently, for what the
//! thesis says of B's handicapped demonstrations, [`crate::readings`]). The
//! reaction time is a person's (fixed); the perception noise is the declared
//! one, as every teacher's ([`super::calibration`]); nothing is fitted for
//! B. B Fast and B Limited are this model with the thesis's handicaps.

use super::TeacherModel;
use super::calibration;
use super::styles::FrequentPasser;

/// The model, with the style `passer` gives B.
pub fn model(passer: FrequentPasser) -> TeacherModel {
    TeacherModel {
        style: passer.b_style(),
        reaction_delay_s: calibration::REACTION_DELAY_S,
        reaction_jitter_s: calibration::REACTION_JITTER_S,
        speedup: 1.0,
        perception_noise: calibration::PERCEPTION_NOISE,
        allow_pass2: true,
    }
}
