//! One ten-minute training session: a user, an algorithm and the table, in
//! simulated time (section 4.3.1: "The training session for each algorithm
//! was limited to 10 minutes. Participants were allowed to end training
//! early, although none chose to do so").
//!
//! The robot is "in a constant cycle of “perception–decision–execution”":
//! each decision follows a perception pause of
//! [`SessionParams::decision_gap_seconds`], then the action runs for its
//! duration. The user acts on the table and on the interface in the same
//! time, with their reaction time. What each algorithm's session does is in
//! its own file ([`intrl`], [`bnets`], [`cba`]); [`Stage`] is what they
//! share: the table, the clock, the user's hands and impression.

pub mod bnets;
pub mod cba;
pub mod intrl;
mod plan;

use rand::Rng;
use serde::{Deserialize, Serialize};

use crate::bnets::Branch;
use crate::cba::classifier::GmmClassifier;
use crate::dbug::{Action, StepEvents, Table, TableParams, seconds_to_ticks};
use crate::evaluation::Accuracy;
use crate::users::hands::Hands;
use crate::users::satisfaction::Impression;
use crate::users::{Algorithm, UserModel, UserTraits};

pub use plan::{SpotPlan, SpotShow};

/// The session's timing constants.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SessionParams {
    /// Session length (thesis: 10 minutes).
    pub seconds: f64,
    /// Perception and decision before each action (ours: 0.5 s; reading `decision-gap`).
    pub decision_gap_seconds: f64,
    /// CBA's pause after each of its own actions, for corrections (ours: 1 s;
    /// the thesis: "added small wait commands to give people a time to do corrections").
    pub correction_pause_seconds: f64,
    /// Int-RL credits a reward to the action under way this long before it
    /// arrived (ours: 0.8 s; Sophie's Kitchen credits "the most recent
    /// action" after a short delay; reading `intrl-credit-delay`).
    pub credit_delay_seconds: f64,
    /// How long a user who controls the bugs leaves one spot before the next (ours: 10 s).
    pub dwell_seconds: f64,
}

impl SessionParams {
    /// Ten minutes.
    pub const fn thesis() -> SessionParams {
        SessionParams {
            seconds: 600.0,
            decision_gap_seconds: 0.5,
            correction_pause_seconds: 1.0,
            credit_delay_seconds: 0.8,
            dwell_seconds: 10.0,
        }
    }
}

/// Who teaches.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Teacher {
    pub traits: UserTraits,
    /// Sessions this user already did (0, 1 or 2).
    pub session: usize,
    /// The scripted ideal teacher (the thesis's authors): ideal traits and a systematic plan.
    pub ideal: bool,
}

impl Teacher {
    /// The scripted ideal teacher.
    pub const fn ideal() -> Teacher {
        Teacher { traits: UserTraits::ideal(), session: 0, ideal: true }
    }
}

/// What a session leaves: the final policy's score, the user's interactions
/// and answer, and what the report draws.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SessionRecord {
    pub algorithm: Algorithm,
    pub accuracy: Accuracy,
    /// Rewards (Int-RL), START…DONE demonstrations (BNets), demonstrations and corrections (CBA).
    pub interactions: u32,
    /// "How well did the robot learn the task?" 1…4.
    pub satisfaction: u8,
    /// The user controlled the bugs this session.
    pub controlled: bool,
    /// Bugs moved by hand.
    pub hand_moves: u32,
    pub details: Details,
}

/// Algorithm-specific results.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Details {
    IntRl {
        /// Each grid cell's untied greedy action (`None`: tied).
        policy: Vec<Option<Action>>,
        /// Cells not tied.
        untied: u32,
        positive_rewards: u32,
        negative_rewards: u32,
        guidance: u32,
        actions: u32,
        strategy_changes: u32,
    },
    BNets {
        /// The final network's branches.
        branches: Vec<Branch>,
        erasures: u32,
        both_arms: u32,
        actions: u32,
        gave_up: bool,
    },
    Cba {
        /// The final classifier (none when an action had fewer than 3 demonstrations).
        classifier: Option<Box<GmmClassifier>>,
        /// Demonstrations and corrections per action.
        counts: [u32; 3],
        requests: u32,
        corrections: u32,
        late_corrections: u32,
        autonomous: u32,
        /// Requests left unanswered (the user had given up).
        #[serde(default)]
        unanswered: u32,
        /// The user stopped answering.
        #[serde(default)]
        gave_up: bool,
    },
}

/// What every session shares: the table, the clock, the user's hands and impression.
pub struct Stage {
    pub table: Table,
    pub tick: u32,
    pub end: u32,
    pub hands: Hands,
    pub impression: Impression,
    /// Ticks from which the impression counts.
    pub impression_from: u32,
}

impl Stage {
    /// A fresh table and a user who controls the bugs or not.
    pub fn new<R: Rng + ?Sized>(
        params: &SessionParams,
        model: &UserModel,
        teacher: &Teacher,
        controls: bool,
        rng: &mut R,
    ) -> Stage {
        let end = seconds_to_ticks(params.seconds);
        Stage {
            table: Table::new(TableParams::thesis(), rng),
            tick: 0,
            end,
            hands: Hands::new(model.hands, &teacher.traits, controls),
            impression: Impression::default(),
            impression_from: (f64::from(end) * model.satisfaction.from_fraction) as u32,
        }
    }

    /// Whether the ten minutes are over.
    pub fn done(&self) -> bool {
        self.tick >= self.end
    }

    /// One tick of the table and the user's hands.
    pub fn advance<R: Rng + ?Sized>(&mut self, rng: &mut R) -> StepEvents {
        let e = self.table.step(rng);
        self.hands.tick(&mut self.table, self.tick, rng);
        self.tick += 1;
        e
    }

    /// Whether the impression counts now.
    pub fn counts_impression(&self) -> bool {
        self.tick >= self.impression_from
    }
}

/// Runs one session of `algorithm`.
pub fn run_session<R: Rng + ?Sized>(
    algorithm: Algorithm,
    teacher: &Teacher,
    model: &UserModel,
    params: &SessionParams,
    learners: &crate::LearnerParams,
    rng: &mut R,
) -> SessionRecord {
    match algorithm {
        Algorithm::IntRl => intrl::run(teacher, model, params, &learners.intrl, rng),
        Algorithm::BNets => bnets::run(teacher, model, params, &learners.bnets, rng),
        Algorithm::Cba => cba::run(teacher, model, params, &learners.cba, rng),
    }
}
