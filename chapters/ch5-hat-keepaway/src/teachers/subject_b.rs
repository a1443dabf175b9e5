//! Subject B: "This teacher is new to Keepaway, but practiced for
//! approximately 100 games before recording demonstrations." Its 20
//! demonstration episodes lasted 10.5 s on average (section 5.4).
//!
//! Style (our reading): the thesis observes that "some \[players\] prefer to
//! keep the ball in one location as long as possible, others pass frequently
//! between keepers" without saying who is who. We give the frequent-passing
//! style to B, whose practice was long enough to make quick passing a habit:
//! it starts looking for a pass when a taker comes within 7 m, passes at a
//! lower threshold (75) and prefers the nearer, shorter pass (+10).
//! It plays anywhere on the field alike (no edge term). The reaction time
//! is a person's (fixed); the perception noise is the declared one, as
//! every teacher's ([`super::calibration`]); nothing is fitted for B. B Fast
//! and B Limited are this model with the thesis's handicaps.

use super::calibration;
use super::{PANIC_DISTANCE, TeacherModel, TeacherStyle};

/// Subject B's style.
pub const STYLE: TeacherStyle = TeacherStyle {
    pressure_distance: 7.0,
    pass_threshold: 75.0,
    distance_weight: 4.0,
    near_preference: 10.0,
    panic_distance: PANIC_DISTANCE,
    edge_distance: 100.0,
    centre_extra: 0.0,
};

/// The calibrated model.
pub fn model() -> TeacherModel {
    TeacherModel {
        style: STYLE,
        reaction_delay_s: calibration::REACTION_DELAY_S,
        reaction_jitter_s: calibration::REACTION_JITTER_S,
        speedup: 1.0,
        perception_noise: calibration::PERCEPTION_NOISE,
        allow_pass2: true,
    }
}
