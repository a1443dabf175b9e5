//! One training session: the robot, the teacher and Algorithm 1 together,
//! from the first action until the teacher's stopping rule holds.
//!
//! Each step: the teacher decides whether it attends to the coming action
//! and, in the guidance condition, names a region (Algorithm 1, lines 5–9);
//! the learner picks an action (lines 10–20); the world executes it (line
//! 21); the teacher judges it and rewards it or stays silent (lines 25–31);
//! the learner updates (lines 22–24, 32–35). The clock advances by the
//! action's duration ([`crate::nao::timing`]).
//!
//! **When training ends.** "We terminate learning once the robot is able to
//! correctly sort three objects into each cup without guidance or reward."
//! We read it as: since the teacher last spoke (any reward or guidance), at
//! least three objects have gone into each cup, each one into its right
//! cup, and every action on each of them drew neither reward nor guidance.
//! An object's actions run from the one after the previous drop to its own
//! drop; any teacher input resets both counts. Objects arrive in random
//! order, so the run can hold more than six objects (e.g. four plain ones
//! before the third patterned one). Since the teacher speaks on every
//! mistake, in the first 20 actions and in the five actions after each
//! mistake, a clean run is a stretch of error-free sorting that starts after
//! all of those. A session that has not finished after
//! [`SessionSetup::max_actions`] actions stops and is recorded as unfinished.

use rand::Rng;
use serde::{Deserialize, Serialize};

use crate::learner::{InteractiveQ, LearnerParams};
use crate::nao::{Action, Durations, NaoSorting, Perception, StateSpace, state_count};
use crate::teacher::{ExpertTeacher, TeacherProtocol};

/// Everything a session depends on besides its seed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SessionSetup {
    /// The state space.
    pub space: StateSpace,
    /// Whether the teacher guides (the guidance condition).
    pub guidance: bool,
    /// Algorithm 1's parameters.
    pub learner: LearnerParams,
    /// The teacher's protocol.
    pub protocol: TeacherProtocol,
    /// Large-space reading noise (see `nao::perception`).
    pub shift_probability: f64,
    /// Seconds per action.
    pub durations: Durations,
    /// Clean objects into each cup that end training (thesis: 3).
    pub objects_per_cup: u32,
    /// Actions after which an unfinished session stops.
    pub max_actions: u32,
}

/// Bits of [`SessionRecord::flags`].
pub mod flag {
    /// The teacher rewarded the action.
    pub const REWARDED: u8 = 1;
    /// The teacher guided the action.
    pub const GUIDED: u8 = 2;
    /// The action was correct.
    pub const CORRECT: u8 = 4;
}

/// What a session did: Table 3.2's numbers and the per-action log behind Figure 3.4.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SessionRecord {
    /// States in the Q-table at the end (#States).
    pub states_discovered: u32,
    /// Actions performed (#Actions).
    pub actions: u32,
    /// Sum of the teacher's rewards (Cumul. Rew.).
    pub cumulative_reward: f64,
    /// Actions guided (Total #G.).
    pub guidance_given: u32,
    /// Actions rewarded (positive or negative).
    pub rewards_given: u32,
    /// Incorrect actions.
    pub mistakes: u32,
    /// Simulated seconds (training time).
    pub training_seconds: f64,
    /// Whether the stopping rule held before the action cap.
    pub finished: bool,
    /// Objects dropped into their own cup.
    pub objects_sorted: u32,
    /// Objects dropped into the other cup.
    pub objects_missorted: u32,
    /// Distinct descriptors `I` the robot read.
    pub descriptors_read: u32,
    /// Per action, its number (see `nao::Action`).
    pub action_log: Vec<u8>,
    /// Per action, [`flag`] bits.
    pub flags: Vec<u8>,
}

impl SessionRecord {
    /// Training time in minutes.
    pub fn training_minutes(&self) -> f64 {
        self.training_seconds / 60.0
    }
}

/// Runs one session.
pub fn run_session<R: Rng + ?Sized>(setup: &SessionSetup, rng: &mut R) -> SessionRecord {
    let perception = Perception::new(setup.space, setup.shift_probability);
    let mut world = NaoSorting::new(perception);
    world.reset(rng);
    let mut teacher = ExpertTeacher::new(setup.protocol, setup.guidance);
    let mut learner = InteractiveQ::new(setup.learner, state_count(setup.space));
    let seconds = setup.durations.table();

    let mut record = SessionRecord {
        states_discovered: 0,
        actions: 0,
        cumulative_reward: 0.0,
        guidance_given: 0,
        rewards_given: 0,
        mistakes: 0,
        training_seconds: 0.0,
        finished: false,
        objects_sorted: 0,
        objects_missorted: 0,
        descriptors_read: 0,
        action_log: Vec::with_capacity(1024),
        flags: Vec::with_capacity(1024),
    };
    let mut descriptors_read = [false; crate::nao::Features::COUNT];
    // Clean objects per cup since the teacher last spoke; whether the
    // current object has drawn any input so far.
    let mut clean = [0u32; 2];
    let mut object_clean = true;

    let mut s = world.state_index();
    learner.start(s);
    while record.actions < setup.max_actions {
        let legal = world.legal();
        let correct = teacher.correct_actions(&world);
        let guidance = teacher.guidance(&world);
        let a = learner.select(s, legal, guidance, rng);
        let outcome = world.act(a, rng);
        let judgement = teacher.judge(correct, a);
        let r = judgement.reward.unwrap_or(0.0);
        let s_next = world.state_index();
        learner.learn(s, a, r, s_next, world.legal());
        s = s_next;

        record.actions += 1;
        record.training_seconds += seconds[a.index()];
        let mut bits = 0;
        if judgement.reward.is_some() {
            bits |= flag::REWARDED;
            record.rewards_given += 1;
            record.cumulative_reward += r;
        }
        if guidance.is_some() {
            bits |= flag::GUIDED;
            record.guidance_given += 1;
        }
        if judgement.correct {
            bits |= flag::CORRECT;
        } else {
            record.mistakes += 1;
        }
        record.action_log.push(a.index() as u8);
        record.flags.push(bits);
        if a == Action::TakePicture && world.physical().seen {
            descriptors_read[world.state().descriptor] = true;
        }

        if bits & (flag::REWARDED | flag::GUIDED) != 0 {
            clean = [0, 0];
            object_clean = false;
        }
        if let Some(sorted) = outcome.sorted {
            if sorted.correct() {
                record.objects_sorted += 1;
                if object_clean {
                    clean[sorted.cup as usize] += 1;
                }
            } else {
                record.objects_missorted += 1;
            }
            object_clean = true;
            if clean.iter().all(|&c| c >= setup.objects_per_cup) {
                record.finished = true;
                break;
            }
        }
    }
    record.states_discovered = learner.states_discovered() as u32;
    record.descriptors_read = descriptors_read.iter().filter(|&&d| d).count() as u32;
    record
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nao::{ActionSet, SHIFT_PROBABILITY};
    use rlfd_rl::random::seeded;

    fn setup(space: StateSpace, guidance: bool) -> SessionSetup {
        SessionSetup {
            space,
            guidance,
            learner: LearnerParams::thesis(space),
            protocol: TeacherProtocol::thesis(),
            shift_probability: SHIFT_PROBABILITY,
            durations: Durations::thesis(),
            objects_per_cup: 3,
            max_actions: 20_000,
        }
    }

    fn check_consistency(setup: &SessionSetup, r: &SessionRecord) {
        assert_eq!(r.action_log.len(), r.actions as usize);
        assert_eq!(r.flags.len(), r.actions as usize);
        let rewarded = r.flags.iter().filter(|&&f| f & flag::REWARDED != 0).count() as u32;
        let guided = r.flags.iter().filter(|&&f| f & flag::GUIDED != 0).count() as u32;
        let wrong = r.flags.iter().filter(|&&f| f & flag::CORRECT == 0).count() as u32;
        assert_eq!((rewarded, guided, wrong), (r.rewards_given, r.guidance_given, r.mistakes));
        // Cumulative reward: +1 per rewarded correct action, −1 per mistake (all mistakes are rewarded).
        let plus = r.flags.iter().filter(|&&f| f & flag::REWARDED != 0 && f & flag::CORRECT != 0).count();
        assert_eq!(r.cumulative_reward, plus as f64 - f64::from(r.mistakes));
        // The first 20 actions are all rewarded (and guided in the guidance condition).
        for &f in r.flags.iter().take(20) {
            assert!(f & flag::REWARDED != 0);
            assert_eq!(f & flag::GUIDED != 0, setup.guidance);
        }
        if !setup.guidance {
            assert_eq!(r.guidance_given, 0);
        }
        // Time is the sum of the actions' durations.
        let t: f64 = r.action_log.iter().map(|&a| setup.durations.seconds(Action::from_index(a as usize))).sum();
        assert!((t - r.training_seconds).abs() < 1e-6);
        assert!(r.states_discovered as usize <= state_count(setup.space));
    }

    #[test]
    fn sessions_finish_and_their_records_add_up() {
        for space in StateSpace::ALL {
            for guidance in [true, false] {
                let s = setup(space, guidance);
                for seed in 0..5 {
                    let r = run_session(&s, &mut seeded(seed));
                    assert!(r.finished, "{space:?} guidance {guidance} seed {seed}: {} actions", r.actions);
                    assert!(r.objects_sorted >= 6);
                    check_consistency(&s, &r);
                }
            }
        }
    }

    #[test]
    fn a_session_ends_after_three_clean_objects_into_each_cup() {
        let s = setup(StateSpace::Small, true);
        let r = run_session(&s, &mut seeded(3));
        assert!(r.finished);
        // Walk back from the end: the last teacher input is followed by at
        // least six correct drops, none of them with input, with ≥ 3 per cup.
        let last_input = r.flags.iter().rposition(|&f| f & (flag::REWARDED | flag::GUIDED) != 0).unwrap();
        let tail = &r.action_log[last_input + 1..];
        let drops: Vec<u8> =
            tail.iter().copied().filter(|&a| a == Action::LDrop as u8 || a == Action::RDrop as u8).collect();
        let left = drops.iter().filter(|&&a| a == Action::LDrop as u8).count();
        let right = drops.len() - left;
        assert!(left >= 3 && right >= 3, "{left} left, {right} right");
        // Nothing after the last input was a mistake, and the session ended on a drop.
        assert!(r.flags[last_input + 1..].iter().all(|&f| f & flag::CORRECT != 0));
        let last = Action::from_index(*r.action_log.last().unwrap() as usize);
        assert!(ActionSet::of(&[Action::LDrop, Action::RDrop]).contains(last));
    }

    #[test]
    fn the_same_seed_gives_the_same_session() {
        let s = setup(StateSpace::Large, false);
        assert_eq!(run_session(&s, &mut seeded(9)), run_session(&s, &mut seeded(9)));
        assert_ne!(run_session(&s, &mut seeded(9)), run_session(&s, &mut seeded(10)));
    }

    #[test]
    fn the_action_cap_stops_an_unfinished_session() {
        let s = SessionSetup { max_actions: 15, ..setup(StateSpace::Small, false) };
        let r = run_session(&s, &mut seeded(1));
        assert!(!r.finished);
        assert_eq!(r.actions, 15);
    }
}
