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
//! demonstrations, one bug placed in each zone, one arm each. A participant,
//! expert or not, demonstrates as the thesis describes its participants:
//! one demonstration per round; a participant who controls the bugs
//! ([`super::hands`]) first places one bug, switched off, in the pick-up
//! and the sweep zone in turn, one who does not starts with the bugs
//! roaming; then they wait up to [`KinestheticModel::wait_for_bug_seconds`]
//! for what they judge a bug to pick up or sweep and move the matching arm,
//! 1 to [`KinestheticModel::max_motions`] times, the other arm too with
//! probability [`KinestheticModel::both_arms_probability`]. Expertise shows
//! in these rates and in perception, not in a plan. After each
//! demonstration the user watches the robot for
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
    /// Probability of moving both arms at once, per expertise.
    pub both_arms_probability: [f64; 3],
    /// Seconds of watching the robot after a demonstration.
    pub watch_seconds: f64,
    /// Probability of erasing before re-teaching (else adding on top), per expertise.
    pub erase_probability: [f64; 3],
    /// Share of watched actions judged right for "it works".
    pub satisfied_share: f64,
}

impl KinestheticModel {
    /// Our choices: wait up to 15 s, up to 3 motions, both arms 5 % / 40 % / 50 %,
    /// watch 40 s, erase 20 % / 60 % / 60 %, "it works" at 70 % judged right.
    pub const fn thesis() -> KinestheticModel {
        KinestheticModel {
            wait_for_bug_seconds: 15.0,
            max_motions: 3,
            both_arms_probability: [0.05, 0.4, 0.5],
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
