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
//! Reaction delay and perception noise are fitted jointly on B's three
//! recordings (10.5 s, Fast 4.3 s, Limited 5.2 s; see [`super::calibration`]).

use super::calibration;
use super::{PANIC_DISTANCE, TeacherModel, TeacherStyle};

/// Subject B's style.
pub const STYLE: TeacherStyle = TeacherStyle {
    pressure_distance: 7.0,
    pass_threshold: 75.0,
    distance_weight: 4.0,
    near_preference: 10.0,
    panic_distance: PANIC_DISTANCE,
};

/// The calibrated model.
pub fn model() -> TeacherModel {
    TeacherModel {
        style: STYLE,
        reaction_delay_s: calibration::REACTION_DELAY_S,
        speedup: 1.0,
        perception_noise: calibration::B_PERCEPTION_NOISE,
        allow_pass2: true,
    }
}
