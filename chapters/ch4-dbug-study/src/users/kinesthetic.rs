//! How a user teaches Behavior Networks by moving the robot's arms.
//!
//! Section 4.4: the algorithm expects "a sequence of demonstrations …
//! beginning each demonstration with START, performing one or more actions
//! through kinesthetic teaching, and ending the demonstration with DONE";
//! "The pre-conditions for “found a bug in pick-up zone” or “found a bug in
//! sweep zone” behaviors were often met unintentionally if the user did not
//! control the location of the hexbugs"; "Although users tried to erase and
//! re-teach the task multiple times, none of them actually succeeded to
//! teach the sweep action in the correct states. On the other hand an
//! expert roboticist who knew about the necessary order of preconditions,
//! could teach the task with only two demonstrations (one for pick-up and
//! one of sweep) by controlling the location of hexbugs manually"; "instead
//! of adding behaviors one by one … they moved both arms at the same time";
//! "users … explored the behavior of the algorithm through trial and error";
//! "people giving up on trial and error process after a few demonstrations".
//!
//! The model. The authors (the scripted ideal teacher) teach their two
//! demonstrations: before each START they clear the table and place one bug,
//! switched off, in the pick-up and then the sweep zone, and move one arm
//! each ("an expert roboticist who knew about the necessary order of
//! preconditions, could teach the task with only two demonstrations (one
//! for pick-up and one of sweep) by controlling the location of hexbugs
//! manually", l. 582). That plan is theirs alone (`session::bnets`).
//!
//! A participant, expert or not, demonstrates as the thesis describes its
//! participants (l. 560–610), one START…DONE demonstration per round:
//! - after START, a participant who controls the bugs ("by turning them off
//!   and displacing them manually", l. 580) switches off the bugs on the
//!   table where they stand and displaces one, switched off, into the
//!   pick-up or the sweep zone (even odds, as a roaming user's nudge in
//!   [`super::hands`]); nothing is cleared first, so the other bugs stay
//!   where they stopped and may be what the robot perceives. How often a
//!   participant controls the bugs is the reading `bnets-bug-control`
//!   ([`BugControl`]). A participant who does not control them demonstrates
//!   with the bugs roaming ("met unintentionally if the user did not
//!   control the location of the hexbugs", l. 580);
//! - they then wait up to [`KinestheticModel::wait_for_bug_seconds`] for
//!   what they judge a bug to pick up or sweep and move the matching arm,
//!   1 to [`KinestheticModel::max_motions`] times, the other arm too as the
//!   user's both-arm habit says (the reading `bnets-both-arms`,
//!   [`BothArms`]): a property of the user, drawn once, that persists
//!   through erasing ("Even when they erased the learned network and
//!   restarted teaching … they moved both arms at the same time", l. 606).
//!
//! After each demonstration the user watches the robot for
//! [`KinestheticModel::watch_seconds`]; if it did not look right, they
//! erase and re-teach (probability [`KinestheticModel::erase_probability`])
//! or add a demonstration on top; when `patience` seconds have passed since
//! the last demonstration that changed what the robot does ("people giving
//! up … after a few demonstrations (because robot is now behaving
//! any differently)", the thesis's words, read as "not behaving any
//! differently"), they give up and watch.

use serde::{Deserialize, Serialize};

use super::traits::Expertise;

/// The BNets teaching model's constants (ours).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct KinestheticModel {
    /// Longest wait for a bug before demonstrating anyway (s).
    pub wait_for_bug_seconds: f64,
    /// Most arm motions in one demonstration of a user who lets the bugs roam.
    pub max_motions: u32,
    /// How often a participant controls the bugs (reading `bnets-bug-control`).
    pub bug_control: BugControl,
    /// Who moves both arms at once, and when (reading `bnets-both-arms`).
    pub both_arms: BothArms,
    /// Seconds of watching the robot after a demonstration.
    pub watch_seconds: f64,
    /// Probability of erasing before re-teaching (else adding on top), per expertise.
    pub erase_probability: [f64; 3],
    /// Share of watched actions judged right for "it works".
    pub satisfied_share: f64,
}

impl KinestheticModel {
    /// Our choices: wait up to 15 s, up to 3 motions, watch 40 s, erase
    /// 20 % / 60 % / 60 %, "it works" at 70 % judged right; the two readings
    /// at their defaults (a third of the participants control the bugs;
    /// every user moves the pick-up arm with every sweep).
    pub const fn thesis() -> KinestheticModel {
        KinestheticModel {
            wait_for_bug_seconds: 15.0,
            max_motions: 3,
            bug_control: BugControl::AThird,
            both_arms: BothArms::WithSweep,
            watch_seconds: 40.0,
            erase_probability: [0.2, 0.6, 0.6],
            satisfied_share: 0.7,
        }
    }

    /// A per-expertise value.
    pub fn of(values: [f64; 3], e: Expertise) -> f64 {
        match e {
            Expertise::Expert => values[0],
            Expertise::Novice => values[1],
            Expertise::None => values[2],
        }
    }
}

/// How often a participant controls the bugs in their BNets session (the
/// reading `bnets-bug-control`; levels and sources in `crate::readings`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BugControl {
    /// No participant: only the authors controlled the bugs.
    None,
    /// A third of the participants (the default).
    AThird,
    /// Two thirds of the participants.
    TwoThirds,
}

impl BugControl {
    /// The probability that a participant controls the bugs.
    pub fn share(self) -> f64 {
        match self {
            BugControl::None => 0.0,
            BugControl::AThird => 1.0 / 3.0,
            BugControl::TwoThirds => 2.0 / 3.0,
        }
    }
}

/// Which participants move both arms at once, and in which motions (the
/// reading `bnets-both-arms`; levels and sources in `crate::readings`). The
/// habit belongs to the user: drawn once per user, kept through erasing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BothArms {
    /// Every user moves the pick-up arm with every sweep (the default).
    WithSweep,
    /// Half the users (one draw per user) move the pick-up arm with every
    /// sweep; the others move one arm at a time.
    HalfTheUsers,
    /// Every user moves both arms in every motion.
    EveryDemonstration,
}

impl BothArms {
    /// Whether a user with `habit` (the per-user draw, true with
    /// probability 1/2) moves both arms when demonstrating `action`.
    pub fn both(self, habit: bool, action: crate::dbug::Action) -> bool {
        let sweep = action == crate::dbug::Action::Sweep;
        match self {
            BothArms::WithSweep => sweep,
            BothArms::HalfTheUsers => habit && sweep,
            BothArms::EveryDemonstration => true,
        }
    }
}
