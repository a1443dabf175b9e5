//! The chapter's open choices, declared as readings (see
//! [`rlfd_harness::Axis`]).
//!
//! The thesis says only that the large state space's perception is
//! "non-deterministic and variations in object placement will result in
//! slightly different state representations" (section 3.3.1): how often a
//! reading differs is not given. It changes the large space's conditions
//! only (the small space's features are exact).

use rlfd_harness::{AnyAxis, Axis, Level, Reading};

use crate::nao::SHIFT_PROBABILITY;

/// How often a large-space reading shifts one feature.
pub static PERCEPTION_NOISE: Axis<f64> = Axis {
    name: "perception-noise",
    question: "How often does the large state space's perception read an object one category off in one feature? The thesis says the representation gives \"slightly different state representations\".",
    levels: &[
        Level {
            name: "0.05",
            value: 0.05,
            meaning: "one reading in twenty shifts",
            source: "a rarer reading of \"slightly different\"",
        },
        Level {
            name: "0.1",
            value: 0.1,
            meaning: "one reading in ten shifts",
            source: "a rarer reading of \"slightly different\"",
        },
        Level {
            name: "0.2",
            value: SHIFT_PROBABILITY,
            meaning: "one reading in five shifts",
            source: "\"most readings agree, a minority differ in one feature by one category\": the value fixed before any learner ran",
        },
        Level {
            name: "0.4",
            value: 0.4,
            meaning: "two readings in five shift",
            source: "a generous reading of \"slightly\", as an upper bound",
        },
    ],
    default: "0.2",
    why_default: "the thesis gives no rate, and 0.2 was fixed before any learner ran",
    report_only: false,
};

/// Every axis of the chapter.
pub static AXES: [&dyn AnyAxis; 1] = [&PERCEPTION_NOISE];

/// The large space's shift probability under `reading`.
pub fn shift_probability(reading: &Reading) -> f64 {
    *reading.value(&PERCEPTION_NOISE)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_level_maps_to_its_rate_and_the_default_is_the_constant() {
        assert_eq!(shift_probability(&Reading::defaults()), SHIFT_PROBABILITY);
        PERCEPTION_NOISE.check().unwrap();
        for level in PERCEPTION_NOISE.levels {
            let r = Reading::defaults().with(&PERCEPTION_NOISE, level.name);
            assert_eq!(shift_probability(&r).to_string(), level.name);
        }
    }
}
