//! Subject C: "This teacher is an expert in LfD, but is new to Keepaway.
//! The teacher practiced 10 games before recording demonstrations"
//! (thesis.txt line 890). Its 20 demonstration episodes lasted 11.3 s on
//! average (lines 915–917).
//!
//! Style: one of the two the thesis names ([`super::styles`]), the other
//! than Subject B's (the `bc-styles` reading; by default C keeps the ball in
//! one location). Reaction time: a person's (fixed); perception noise: the
//! declared one, as every teacher's ([`super::calibration`]); nothing is
//! fitted for C.

use super::TeacherModel;
use super::calibration;
use super::styles::FrequentPasser;

/// The model, with the style `passer` gives C.
pub fn model(passer: FrequentPasser) -> TeacherModel {
    TeacherModel {
        style: passer.c_style(),
        reaction_delay_s: calibration::REACTION_DELAY_S,
        reaction_jitter_s: calibration::REACTION_JITTER_S,
        speedup: 1.0,
        perception_noise: calibration::PERCEPTION_NOISE,
        allow_pass2: true,
    }
}
