//! Subject B Fast: "Simulator speed during training was increased to
//! approximately 5 times faster than real time: average duration 4.3
//! seconds/episode" (section 5.4, Impact of Teacher Ability).
//!
//! The same person as [`super::subject_b`], with the same style, reaction
//! delay (in real seconds) and perception noise; the simulator runs five
//! times faster, so the delay is five times longer in simulated cycles.
//! Nothing is fitted for it: the report shows its duration beside the
//! thesis's 4.3 s as an out-of-sample check of B's model.

use super::styles::FrequentPasser;
use super::{TeacherModel, subject_b};

/// How much faster than real time the simulator ran ("approximately 5 times").
pub const SPEEDUP: f64 = 5.0;

/// The model: Subject B (its style as `passer` gives it) at five times real time.
pub fn model(passer: FrequentPasser) -> TeacherModel {
    TeacherModel { speedup: SPEEDUP, ..subject_b::model(passer) }
}
