//! The chapter's open choices, declared as readings (see
//! [`rlfd_harness::Axis`]): which rule list stands for Subject A, and the
//! keepers' exploration rate.
//!
//! - `a-rules`: the thesis prints the decision list JRip made of Subject
//!   A's demonstrations (section 5.4); our Subject A model's demonstrations
//!   give a list of their own. The default is ours (the thesis's method run
//!   end to end: demonstrate, summarise, learn); `thesis` uses the printed
//!   list wherever A's 20 demonstrations feed a learner or are played alone.
//! - `epsilon`: "our Sarsa learners use α = 0.05, ε = 0.10" (section 5.3.2,
//!   the default, as written); Stone, Sutton & Kuhlmann's keepers, the
//!   "past work" the thesis cites for these values, explore with ε = 0.01.

use rlfd_harness::{Axis, Level, Reading};

use crate::learners::LearnerParams;

/// The conditions whose rules are Subject A's 20 demonstrations' (the
/// learning trials of Tables 5.1–5.3 and the rules played alone).
const A_RULE_TRIALS: &[&str] = &[
    "keepaway-learning:value-bonus-subject-a",
    "keepaway-learning:extra-action-subject-a",
    "keepaway-learning:ppr-subject-a",
    "keepaway-demonstrations:rules-only-subject-a",
    "keepaway-demonstrations:rules-explore-subject-a",
];

/// Which decision list stands for Subject A's 20 demonstrations.
pub static A_RULES: Axis = Axis {
    name: "a-rules",
    question: "Which rule list do the learners take from Subject A's 20 demonstrations: the one JRip makes of our Subject A model's demonstrations, or the one the thesis prints?",
    levels: &[
        Level {
            name: "ours",
            meaning: "JRip (Weka 3.6's, -S 1) on the Subject A model's 20 recorded episodes",
            source: "\"we used JRip to summarize the policy with a decision list\" (section 5.4): the thesis's method, applied to our demonstrations",
        },
        Level {
            name: "thesis",
            meaning: "the decision list printed in section 5.4 (three rules and the default, over state_0, state_3, state_4, state_8, state_11, state_12)",
            source: "\"The following rules were learned\" (section 5.4), the list itself",
        },
    ],
    default: "ours",
    why_default: "the thesis's procedure end to end; the printed list was learned from demonstrations on the real server, which our simulator approximates",
    experiments: A_RULE_TRIALS,
};

/// The keepers' exploration rate.
pub static EPSILON: Axis = Axis {
    name: "epsilon",
    question: "How often do the Sarsa keepers explore: ε = 0.10 as the thesis writes, or ε = 0.01 as the keepers of the cited past work?",
    levels: &[
        Level {
            name: "0.10",
            meaning: "ε = 0.10 at every decision",
            source: "\"our Sarsa learners use α = 0.05, ε = 0.10, and RBF function approximation\" (section 5.3.2)",
        },
        Level {
            name: "0.01",
            meaning: "ε = 0.01 at every decision",
            source: "Stone, Sutton & Kuhlmann 2005 explore with ε = 0.01; the thesis gives its values \"to be consistent with past work [92]\"",
        },
    ],
    default: "0.10",
    why_default: "the thesis's literal text",
    experiments: &["keepaway-learning", "keepaway-demonstrations:rules-explore"],
};

/// Every axis of the chapter.
pub static AXES: [&Axis; 2] = [&A_RULES, &EPSILON];

/// Whether a reading takes the thesis's printed list for Subject A.
pub fn thesis_a_rules(reading: &Reading) -> bool {
    reading.level_of(&A_RULES) == "thesis"
}

impl LearnerParams {
    /// The learners' parameters under `reading`.
    pub fn under(mut self, reading: &Reading) -> LearnerParams {
        self.epsilon = match reading.level_of(&EPSILON) {
            "0.01" => 0.01,
            _ => 0.10,
        };
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_reading_is_the_thesis_parameters_and_each_level_moves_something() {
        assert_eq!(LearnerParams::thesis().under(&Reading::defaults()), LearnerParams::thesis());
        let low = Reading::defaults().with(&EPSILON, EPSILON.level("0.01").unwrap());
        assert_eq!(LearnerParams::thesis().under(&low).epsilon, 0.01);
        let printed = Reading::defaults().with(&A_RULES, A_RULES.level("thesis").unwrap());
        assert!(thesis_a_rules(&printed) && !thesis_a_rules(&Reading::defaults()));
        // The rule reading changes A's trials only, not A (10)'s.
        assert!(A_RULES.changes("keepaway-learning", "ppr-subject-a"));
        assert!(!A_RULES.changes("keepaway-learning", "ppr-half-subject-a"));
        assert!(!A_RULES.changes("keepaway-learning", "no-prior"));
        assert!(EPSILON.changes("keepaway-learning", "no-prior"));
    }
}
