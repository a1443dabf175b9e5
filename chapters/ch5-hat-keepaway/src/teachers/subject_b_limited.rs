//! Subject B Limited Actions: "The teacher was limited to executing only
//! two actions, Hold and Pass1, disallowing passes to the further keeper:
//! average duration 5.2 seconds/episode" (section 5.4).
//!
//! The same person as [`super::subject_b`] without the Pass2 key: when the
//! farther teammate is the open one, it can only hold or pass to the nearer.
//! Nothing is fitted for it: the report shows its duration beside the
//! thesis's 5.2 s as an out-of-sample check of B's model.

use super::styles::FrequentPasser;
use super::{TeacherModel, subject_b};

/// The model: Subject B (its style as `passer` gives it) without Pass2.
pub fn model(passer: FrequentPasser) -> TeacherModel {
    TeacherModel { allow_pass2: false, ..subject_b::model(passer) }
}
