//! Subject A: "This teacher has many years of research experience with the
//! Keepaway task." Its 20 demonstration episodes lasted 10.4 s on average,
//! and JRip summarised them in four rules with over 87 % cross-validated
//! accuracy (section 5.4).
//!
//! Style: an expert plays as the benchmark's designers coded it, holding
//! until a taker comes close and then passing to the most open teammate,
//! open meaning four degrees of lane angle per metre of distance from the
//! takers, with a pass threshold of 90 (Stone, Sutton & Kuhlmann 2005's
//! hand-coded policy). Two of its features are read from the rule list the
//! thesis prints for A's demonstrations (a property of the demonstrations,
//! so allowed as an input): it starts looking for a pass with a taker
//! within 6 m (`state_3 ≤ 5.99`), and its passes are conditioned on where
//! it stands: it passes as the hand-coded policy does near the edge of the
//! field, farther than 7.33 m from the centre (`state_0 ≥ 7.33`), and holds
//! on longer in the middle, where the ball cannot be pushed out. How much
//! longer is fitted on A's duration and rule list; its perception noise is
//! the declared one, as every teacher's ([`super::calibration`]).

use super::calibration;
use super::{PANIC_DISTANCE, TeacherModel, TeacherStyle};

/// Subject A's style (the extra threshold in the middle is the calibrated [`calibration::A_CENTRE_EXTRA`]).
pub const STYLE: TeacherStyle = TeacherStyle {
    pressure_distance: 6.0,
    pass_threshold: 90.0,
    distance_weight: 4.0,
    near_preference: 0.0,
    panic_distance: PANIC_DISTANCE,
    edge_distance: 7.33,
    centre_extra: calibration::A_CENTRE_EXTRA,
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
