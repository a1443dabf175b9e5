//! The chapter's open choices, declared as readings (see
//! [`rlfd_harness::Axis`]): how a Behavior Network is scored and how its
//! simultaneous motions are ordered (section 4.4 describes the networks its
//! users built, not the scoring code), and what CBA's confidence threshold
//! is computed on (Chernova & Veloso's thresholds; the thesis gives none);
//! and how the participants taught and judged where the thesis describes
//! them without a number: how often they controlled the bugs in BNets, who
//! moved both arms at once, how they read the table, and the form of their
//! satisfaction; and the
//! pace the thesis does not give: the robot's perception pause before each
//! action, Int-RL's ε and the window in which a reward is credited. Every
//! axis sets a field of both experiments' learner parameters, user model or
//! session parameters (a study trial is a participant's three sessions).

use rlfd_harness::{AnyAxis, Axis, Level, Reading};

use crate::LearnerParams;
use crate::bnets::{NodeOrder, PassScoring, WaitCredit};
use crate::cba::ThresholdData;
use crate::session::SessionParams;
use crate::users::UserModel;
use crate::users::kinesthetic::{BothArms, BugControl};
use crate::users::perception::TableReading;
use crate::users::satisfaction::SatisfactionForm;

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

/// How often a BNets participant controls the bugs.
pub static BNETS_BUG_CONTROL: Axis<BugControl> = Axis {
    name: "bnets-bug-control",
    question: "How often does a participant control the bugs (switch them off and displace one by hand) while teaching Behavior Networks?",
    levels: &[
        Level {
            name: "none",
            value: BugControl::None,
            meaning: "no participant: every participant demonstrates with the bugs roaming",
            source: "the thesis names controlling the bugs only for \"an expert roboticist who knew about the necessary order of preconditions\" (l. 582), the authors",
        },
        Level {
            name: "a-third",
            value: BugControl::AThird,
            meaning: "each participant controls the bugs with probability 1/3, whatever their expertise",
            source: "\"often met unintentionally if the user did not control the location of the hexbugs (e.g., by turning them off and displacing them manually)\" (l. 580): some did, most did not; 1/3 is the population mean of the round-3 rates fixed before any learner ran (0.9 / 0.25 / 0.1 over 6 / 14 / 11 participants: 10/31)",
        },
        Level {
            name: "two-thirds",
            value: BugControl::TwoThirds,
            meaning: "each participant controls the bugs with probability 2/3",
            source: "the other side of a half: most participants control the bugs, against \"often met unintentionally\"",
        },
    ],
    default: "a-third",
    why_default: "the thesis gives no share (l. 580 says only that preconditions were \"often\" met by chance when users did not control the bugs), and no cited paper does; by the third step, the value fixed before any learner ran: the round-3 model's own population rate (10 of 31), without its split by expertise, which has no text (the thesis tells participants apart by control, not by background)",
    report_only: false,
};

/// Who moves both arms at once when teaching Behavior Networks.
pub static BNETS_BOTH_ARMS: Axis<BothArms> = Axis {
    name: "bnets-both-arms",
    question: "Which participants move both of the robot's arms at once, and in which demonstrations? (a habit of the user, kept through erasing)",
    levels: &[
        Level {
            name: "with-sweep",
            value: BothArms::WithSweep,
            meaning: "every participant moves the pick-up arm with every sweep they demonstrate; a pick-up is demonstrated alone",
            source: "\"An example of an unintended dependency is executing a pickup action after every sweep … Similar unintended dependencies were taught by every user, in many occasions repeatedly\" (l. 582); \"Even when they erased the learned network and restarted teaching … they moved both arms at the same time\" (l. 606)",
        },
        Level {
            name: "half-the-users",
            value: BothArms::HalfTheUsers,
            meaning: "half the participants (one draw per user) move the pick-up arm with every sweep; the others one arm at a time",
            source: "\"Almost every study participant had an unintended behavior dependency\" (l. 582) read as: not all of them by this habit",
        },
        Level {
            name: "every-demonstration",
            value: BothArms::EveryDemonstration,
            meaning: "every participant moves both arms in every motion they demonstrate",
            source: "\"instead of adding behaviors one by one (such as teaching picking-up the hexbug in one demonstration, then teaching sweeping the hexbug in a second demonstration) they moved both arms at the same time\" (l. 606), read without the example of l. 582",
        },
    ],
    default: "with-sweep",
    why_default: "the thesis's literal text: the one dependency it spells out is a pickup tied to every sweep, and it says every user taught such dependencies, repeatedly (l. 582), and kept moving both arms after erasing (l. 606), so the habit is every user's and persists; l. 606 alone, without the example, is the every-demonstration level",
    report_only: false,
};

/// How the participants read the table when they judge the right action.
pub static TABLE_READING: Axis<TableReading> = Axis {
    name: "table-reading",
    question: "How does a participant read the table when judging the action the robot should take (every algorithm: demonstrations, labels, rewards, what they watch)?",
    levels: &[
        Level {
            name: "goal",
            value: TableReading::Goal,
            meaning: "every participant by the goal: a bug at the pick-up spot means pick up, else a bug in the sweep zone means sweep, else wait",
            source: "\"In general the users tried to demonstrate behaviors for the ultimate goal of sweeping and picking-up hexbugs\" (l. 582); \"It was hard for most users to realize which behavior was activated when\" (l. 580)",
        },
        Level {
            name: "experts-as-robot",
            value: TableReading::ExpertsAsRobot,
            meaning: "the expert participants read the table as the robot does (the bug nearest the pick-up mark decides); the others by the goal",
            source: "the round-1 to round-3 model, from \"an expert roboticist who knew about the necessary order of preconditions\" (l. 582), a sentence about the authors",
        },
    ],
    default: "goal",
    why_default: "the thesis's literal text: it describes the participants as teaching for the goal and not seeing the agent's state, with no exception for the self-identified experts; the sentence behind the alternative is about the authors, whom the scripted ideal teacher models",
    report_only: false,
};

/// How a user judges "How well did the robot learn the task?".
pub static SATISFACTION_FORM: Axis<SatisfactionForm> = Axis {
    name: "satisfaction-form",
    question: "From what the user watched in the session's second half, how do they judge \"How well did the robot learn the task?\" (all three algorithms)?",
    levels: &[
        Level {
            name: "pickup-count",
            value: SatisfactionForm::PickupCount,
            meaning: "one answer point per bug the user saw the robot pick up, up to the three on the table",
            source: "\"users evaluated performance based on the success of picking up as many hexbugs as possible\" (l. 681)",
        },
        Level {
            name: "success-count",
            value: SatisfactionForm::SuccessCount,
            meaning: "one answer point per pick-up or sweep the user judged right, up to three",
            source: "\"Hence, *waiting* at appropriate times was not considered as successful as *picking up* or *sweeping*\" (l. 681)",
        },
        Level {
            name: "ratio",
            value: SatisfactionForm::Ratio,
            meaning: "the weighted share of watched actions judged right, q = (S + W) / 2W (waits weigh 0.2, a lifted bug 1 more)",
            source: "the round-1 to round-3 form; it rates a robot that only waits, judged right, about 3 of 4",
        },
    ],
    default: "pickup-count",
    why_default: "the thesis's literal text: users judged by \"picking up as many hexbugs as possible\" (l. 681), a count of bugs picked up",
    report_only: false,
};

/// Int-RL's exploration rate.
pub static INTRL_EPSILON: Axis<f64> = Axis {
    name: "intrl-epsilon",
    question: "Which ε does Int-RL's ε-greedy selection use in the DBug study? (Section 4.5 names ε-greedy selection and gives Q0, α and γ, not ε.)",
    levels: &[
        Level {
            name: "0.05",
            value: 0.05,
            meaning: "ε = 0.05, held through the session",
            source: "half the default: less exploration",
        },
        Level {
            name: "0.1",
            value: 0.1,
            meaning: "ε = 0.1, held through the session",
            source: "the thesis's own Int-RL starts at \"ε = 0.1\" in both conditions of chapter 3 (l. 364); chapter 4 gives no decay schedule (Algorithm 1's δ_ε needs \"number of desired time steps\", l. 416, not given for the study)",
        },
        Level {
            name: "0.2",
            value: 0.2,
            meaning: "ε = 0.2, held through the session",
            source: "twice the default: more exploration",
        },
    ],
    default: "0.1",
    why_default: "the thesis is silent for chapter 4 (l. 618 names ε-greedy selection without a value); its own Int-RL implementation starts at ε = 0.1 (l. 364), the value fixed before any learner ran; held constant because the study gives no number of steps to decay over",
    report_only: false,
};

/// The robot's pause between actions.
pub static DECISION_GAP: Axis<f64> = Axis {
    name: "decision-gap",
    question: "How long does the robot's perception and decision take before each action, in all three algorithms? (the thesis: \"a constant cycle of perception–decision–execution\", perceived \"as lag\", no duration)",
    levels: &[
        Level {
            name: "0.25",
            value: 0.25,
            meaning: "0.25 s before each action",
            source: "half the default: a faster robot",
        },
        Level {
            name: "0.5",
            value: 0.5,
            meaning: "0.5 s before each action",
            source: "the round-1 value, fixed before any learner ran; half the 1 s wait action (l. 551)",
        },
        Level {
            name: "1",
            value: 1.0,
            meaning: "1 s before each action",
            source: "twice the default: as long as a wait action",
        },
    ],
    default: "0.5",
    why_default: "neither the thesis (l. 608: the cycle, no duration) nor a cited paper gives it; the value fixed before any learner ran",
    report_only: false,
};

/// When Int-RL credits a reward.
pub static INTRL_CREDIT_DELAY: Axis<f64> = Axis {
    name: "intrl-credit-delay",
    question: "A reward clicked at time τ is credited to the action under way at τ − d: which d?",
    levels: &[
        Level {
            name: "0.4",
            value: 0.4,
            meaning: "d = 0.4 s",
            source: "half the default: a reward lands on the action under way sooner",
        },
        Level {
            name: "0.8",
            value: 0.8,
            meaning: "d = 0.8 s",
            source: "the round-1 value, fixed before any learner ran: Sophie's Kitchen credits a reward to the most recent action after a short delay window (Thomaz & Breazeal, the thesis's [24]; we could not retrieve its length)",
        },
        Level { name: "1.5", value: 1.5, meaning: "d = 1.5 s", source: "a slow click: about twice the default" },
    ],
    default: "0.8",
    why_default: "the thesis gives no credit rule (l. 303 describes the reward interface, not its timing), and its cited original gives a delay window whose length we could not retrieve; the value fixed before any learner ran",
    report_only: false,
};

/// Every axis of the chapter.
pub static AXES: [&dyn AnyAxis; 11] = [
    &BNETS_SCORING,
    &BNETS_ORDER,
    &BNETS_WAIT_CREDIT,
    &CBA_THRESHOLD,
    &BNETS_BUG_CONTROL,
    &BNETS_BOTH_ARMS,
    &TABLE_READING,
    &SATISFACTION_FORM,
    &INTRL_EPSILON,
    &DECISION_GAP,
    &INTRL_CREDIT_DELAY,
];

impl SessionParams {
    /// The session's timing under `reading`.
    pub fn under(mut self, reading: &Reading) -> SessionParams {
        self.decision_gap_seconds = *reading.value(&DECISION_GAP);
        self.credit_delay_seconds = *reading.value(&INTRL_CREDIT_DELAY);
        self
    }
}

impl UserModel {
    /// The user model under `reading`.
    pub fn under(mut self, reading: &Reading) -> UserModel {
        self.kinesthetic.bug_control = *reading.value(&BNETS_BUG_CONTROL);
        self.kinesthetic.both_arms = *reading.value(&BNETS_BOTH_ARMS);
        self.satisfaction.form = *reading.value(&SATISFACTION_FORM);
        self.perception.table_reading = *reading.value(&TABLE_READING);
        self
    }
}

impl LearnerParams {
    /// The learners' parameters under `reading`.
    pub fn under(mut self, reading: &Reading) -> LearnerParams {
        self.bnets.scoring = *reading.value(&BNETS_SCORING);
        self.bnets.order = *reading.value(&BNETS_ORDER);
        self.bnets.wait_credit = *reading.value(&BNETS_WAIT_CREDIT);
        self.cba.threshold = *reading.value(&CBA_THRESHOLD);
        self.intrl.epsilon = *reading.value(&INTRL_EPSILON);
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_reading_is_the_thesis_parameters_and_each_level_moves_one_field() {
        let thesis = (LearnerParams::thesis(), UserModel::thesis(), SessionParams::thesis());
        let under = |r: &Reading| {
            (LearnerParams::thesis().under(r), UserModel::thesis().under(r), SessionParams::thesis().under(r))
        };
        assert_eq!(under(&Reading::defaults()), thesis);
        let mut seen = Vec::new();
        for axis in AXES {
            axis.check().unwrap();
            for level in axis.alternatives() {
                let p = under(&Reading::defaults().with(axis, level));
                assert_ne!(p, thesis, "{}={level} changes nothing", axis.name());
                assert!(!seen.contains(&p), "{}={level} repeats another level", axis.name());
                seen.push(p);
            }
        }
        assert_eq!(seen.len(), 17);
    }
}
