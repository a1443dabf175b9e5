//! The chapter's open choices, declared as readings (see
//! [`rlfd_harness::Axis`]): how a Behavior Network is scored and how its
//! simultaneous motions are ordered (section 4.4 describes the networks its
//! users built, not the scoring code), and what CBA's confidence threshold
//! is computed on (Chernova & Veloso's thresholds; the thesis gives none).
//! Every axis sets a field of both experiments' learner parameters (a
//! study trial is a participant's three sessions).

use rlfd_harness::{AnyAxis, Axis, Level, Reading};

use crate::LearnerParams;
use crate::bnets::{NodeOrder, PassScoring, WaitCredit};
use crate::cba::ThresholdData;

/// How a network's policy in a zone is read.
pub static BNETS_SCORING: Axis<PassScoring> = Axis {
    name: "bnets-scoring",
    question: "Is a BNets zone correct when the network's first action there is the zone's, or only when every action of a pass from that state is?",
    levels: &[
        Level {
            name: "full-pass",
            value: PassScoring::FullPass,
            meaning: "a zone is correct only if every action the network takes in one pass from a state of it is the zone's action",
            source: "\"An example of an unintended dependency is executing a pickup action after every sweep, even if there is no bug in the pickup zone\" (section 4.4): the thesis counts that network's sweep as a failure",
        },
        Level {
            name: "first-action",
            value: PassScoring::FirstAction,
            meaning: "a zone is correct if the network's first action in a state of it is the zone's action",
            source: "the round-1 implementation; under it the thesis's example of a failure scores as a correct sweep",
        },
    ],
    default: "full-pass",
    why_default: "it is the only level under which the thesis's own example of a failure is one (the thesis's literal text)",
    report_only: false,
};

/// How two motions that start together are ordered.
pub static BNETS_ORDER: Axis<NodeOrder> = Axis {
    name: "bnets-order",
    question: "When a user moves both arms at once, which motion does the network put first?",
    levels: &[
        Level {
            name: "postcondition",
            value: NodeOrder::Postcondition,
            meaning: "by when each motion's postcondition (the motion completed) is met: the sweep, shorter, first",
            source: "Nicolescu & Mataric's robot \"watches every known behavior's postconditions\"; the thesis's example dependency, \"a pickup action after every sweep\", is this order",
        },
        Level {
            name: "pickup-first",
            value: NodeOrder::PickupFirst,
            meaning: "the pickup before the sweep, whatever their ends",
            source: "a fixed tie-break, the review's alternative (it turns the dependency round)",
        },
    ],
    default: "postcondition",
    why_default: "it follows the cited paper's rule (behaviours are observed through their postconditions) and the thesis's own example",
    report_only: false,
};

/// Whether a network that moves an arm earns the wait zone.
pub static BNETS_WAIT_CREDIT: Axis<WaitCredit> = Axis {
    name: "bnets-wait-credit",
    question: "Does a network that moves an arm earn the wait zone where it waits, or only the empty network?",
    levels: &[
        Level {
            name: "scored",
            value: WaitCredit::Scored,
            meaning: "the wait zone is scored as every zone: correct where the network waits",
            source: "\"evaluate its performance in selecting the correct action for each state\" (section 4.5), the same metric for the three algorithms",
        },
        Level {
            name: "empty-network-only",
            value: WaitCredit::EmptyNetworkOnly,
            meaning: "a network with an arm behaviour gets no credit in the wait zone",
            source: "the reading under which the thesis's three BNets levels (0 %, 10.4 %, 77.1 %) are the only ones a network with at most one correct arm can score: a pickup network scores 10.4 %",
        },
    ],
    default: "scored",
    why_default: "the thesis's metric, as written, is per state and the same for every algorithm",
    report_only: false,
};

/// What CBA's confidence threshold is computed on.
pub static CBA_THRESHOLD: Axis<ThresholdData> = Axis {
    name: "cba-threshold",
    question: "Is τ_conf the mean confidence of the demonstrations misclassified by a classifier fitted without them, or by the classifier fitted to them?",
    levels: &[
        Level {
            name: "held-out",
            value: ThresholdData::HeldOut,
            meaning: "two-fold cross-validation: each demonstration is classified by the mixtures fitted to the other fold",
            source: "Chernova & Veloso set τ_conf from the classifier's confident mistakes, which a mixture fitted to the point itself rarely makes (on the training points τ_conf is often 0)",
        },
        Level {
            name: "training",
            value: ThresholdData::Training,
            meaning: "each demonstration is classified by the mixtures fitted to all of them, itself included",
            source: "the round-1 implementation",
        },
    ],
    default: "held-out",
    why_default: "it follows the cited original (Chernova & Veloso 2009) as the review reads it; the thesis gives no threshold",
    report_only: false,
};

/// Every axis of the chapter.
pub static AXES: [&dyn AnyAxis; 4] = [&BNETS_SCORING, &BNETS_ORDER, &BNETS_WAIT_CREDIT, &CBA_THRESHOLD];

impl LearnerParams {
    /// The learners' parameters under `reading`.
    pub fn under(mut self, reading: &Reading) -> LearnerParams {
        self.bnets.scoring = *reading.value(&BNETS_SCORING);
        self.bnets.order = *reading.value(&BNETS_ORDER);
        self.bnets.wait_credit = *reading.value(&BNETS_WAIT_CREDIT);
        self.cba.threshold = *reading.value(&CBA_THRESHOLD);
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_reading_is_the_thesis_parameters_and_each_level_moves_one_field() {
        assert_eq!(LearnerParams::thesis().under(&Reading::defaults()), LearnerParams::thesis());
        let mut seen = Vec::new();
        for axis in AXES {
            axis.check().unwrap();
            for level in axis.alternatives() {
                let p = LearnerParams::thesis().under(&Reading::defaults().with(axis, level));
                assert_ne!(p, LearnerParams::thesis(), "{}={level} changes nothing", axis.name());
                assert!(!seen.contains(&p), "{}={level} repeats another level", axis.name());
                seen.push(p);
            }
        }
        assert_eq!(seen.len(), 4);
    }
}
