//! The chapter's open choices, declared as readings (see
//! [`rlfd_harness::Axis`]).
//!
//! The thesis says only that the large state space's perception is
//! "non-deterministic and variations in object placement will result in
//! slightly different state representations" (section 3.3.1): how often a
//! reading differs is not given. It changes the large space's conditions
//! only (the small space's features are exact).
//!
//! Nor does it give the sizes of the teacher's rewards: the interface's bar
//! spans "r = [−1, 1]" (section 3.2, l. 303 of the text), and the teacher
//! judged actions right or wrong. C3.4's signs turn on the size of praise
//! relative to punishment (with equal sizes the unguided sums stay just
//! above 0; at praise ≤ 0.93 × punishment all four signs are the
//! thesis's, review round 3 of chapters 3–4): [`REWARD_SIZES`] spans that
//! edge.

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

/// The teacher's two rewards, each within the interface's `[−1, 1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RewardSizes {
    /// After a correct action.
    pub praise: f64,
    /// After an incorrect action (negative).
    pub punishment: f64,
}

/// The size of praise relative to punishment. Level names are the ratio
/// praise / |punishment|; the larger of the two fills the bar (1), as an
/// expert who judges actions simply right or wrong would.
pub static REWARD_SIZES: Axis<RewardSizes> = Axis {
    name: "reward-sizes",
    question: "How large are the teacher's praise and punishment? The thesis gives the interface's range, \"r = [−1, 1]\", not the values its teacher gave.",
    levels: &[
        Level {
            name: "0.5",
            value: RewardSizes { praise: 0.5, punishment: -1.0 },
            meaning: "praise +0.5, punishment −1",
            source: "a teacher who drags the bar half-way up for a right action and all the way down for a wrong one",
        },
        Level {
            name: "0.9",
            value: RewardSizes { praise: 0.9, punishment: -1.0 },
            meaning: "praise +0.9, punishment −1",
            source: "just below equal sizes, across the edge where C3.4's unguided signs turn (about 0.94)",
        },
        Level {
            name: "1",
            value: RewardSizes { praise: 1.0, punishment: -1.0 },
            meaning: "praise +1, punishment −1",
            source: "the ends of the interface's range \"r = [−1, 1]\" (l. 303): the value fixed before any learner ran",
        },
        Level {
            name: "2",
            value: RewardSizes { praise: 1.0, punishment: -0.5 },
            meaning: "praise +1, punishment −0.5",
            source: "the mirror of 0.5: a teacher who praises fully and punishes half-way, so that the range is spanned on both sides of equal sizes",
        },
    ],
    default: "1",
    why_default: "the literal range r = [−1, 1] with both ends used, the value fixed before any learner ran; the thesis gives no sizes",
    report_only: false,
};

/// Every axis of the chapter.
pub static AXES: [&dyn AnyAxis; 2] = [&PERCEPTION_NOISE, &REWARD_SIZES];

/// The large space's shift probability under `reading`.
pub fn shift_probability(reading: &Reading) -> f64 {
    *reading.value(&PERCEPTION_NOISE)
}

/// The teacher's rewards under `reading`.
pub fn reward_sizes(reading: &Reading) -> RewardSizes {
    *reading.value(&REWARD_SIZES)
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

    #[test]
    fn reward_sizes_name_their_ratio_stay_in_the_bar_and_default_to_the_protocol() {
        REWARD_SIZES.check().unwrap();
        let d = reward_sizes(&Reading::defaults());
        let p = crate::teacher::TeacherProtocol::thesis();
        assert_eq!((d.praise, d.punishment), (p.correct_reward, p.wrong_reward));
        for level in REWARD_SIZES.levels {
            let v = level.value;
            assert!(v.praise > 0.0 && v.praise <= 1.0 && v.punishment < 0.0 && v.punishment >= -1.0);
            assert_eq!(v.praise.max(-v.punishment), 1.0, "{}: the larger reward fills the bar", level.name);
            assert_eq!((v.praise / -v.punishment).to_string(), level.name);
        }
    }
}
