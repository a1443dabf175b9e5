//! Subject A: "This teacher has many years of research experience with the
//! Keepaway task." Its 20 demonstration episodes lasted 10.4 s on average
//! (section 5.4).
//!
//! Style (our reading; the thesis describes no teacher's play): an expert
//! plays as the benchmark's designers coded it, holding until a taker is
//! within 5 m and then passing to the most open teammate, open meaning four
//! degrees of lane angle per metre of distance from the takers, with a
//! pass threshold of 90 (Stone, Sutton & Kuhlmann 2005's hand-coded policy).
//! Reaction delay: the one fitted for Subject B (see [`super::calibration`]);
//! perception noise: fitted to A's 10.4 s.

use super::calibration;
use super::{PANIC_DISTANCE, TeacherModel, TeacherStyle};

/// Subject A's style.
pub const STYLE: TeacherStyle = TeacherStyle {
    pressure_distance: 5.0,
    pass_threshold: 90.0,
    distance_weight: 4.0,
    near_preference: 0.0,
    panic_distance: PANIC_DISTANCE,
};

/// The calibrated model.
pub fn model() -> TeacherModel {
    TeacherModel {
        style: STYLE,
        reaction_delay_s: calibration::REACTION_DELAY_S,
        speedup: 1.0,
        perception_noise: calibration::A_PERCEPTION_NOISE,
        allow_pass2: true,
    }
}
