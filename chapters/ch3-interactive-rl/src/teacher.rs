//! The scripted expert teacher: the thesis's reward and guidance protocol,
//! followed exactly, by a teacher who always knows the correct action.
//!
//! Section 3.3.2: "All experiments were performed by author of this thesis.
//! The teacher used the following consistent guidance and reward shaping
//! protocol. For the first 20 actions of the experiments, all actions were
//! given reward and guidance (in case of experiments with guidance). After 20
//! actions, reward and guidance were given only after the incorrect action
//! that the robot performed. After each incorrect action, the following 5
//! actions were rewarded and guided. If the action was correct, no reward or
//! guidance was given until the next incorrect action."
//!
//! As implemented ([`ExpertTeacher`]):
//! - Action `k` (from 1) is *attended* when `k ≤ 20` or it is one of the 5
//!   actions after an incorrect one (a new mistake restarts the 5). An
//!   attended action is guided before it (guidance condition only) and
//!   rewarded after it.
//! - An incorrect action is always rewarded, attended or not: "reward … given
//!   only after the incorrect action". Guidance comes before an action, when
//!   the teacher cannot yet know it will be wrong, so a mistake outside the
//!   attended actions is not guided.
//! - Rewards: +1 for a correct action, −1 for an incorrect one. The
//!   interface's reward bar spans `r ∈ [−1, 1]`; an expert who judges
//!   actions as simply right or wrong fills it all the way (a documented
//!   choice: the thesis does not give the values used). They are the
//!   default of the `reward-sizes` reading ([`crate::readings::REWARD_SIZES`]),
//!   whose other levels change the ratio of praise to punishment.
//! - Correct: the action begins a shortest correct sorting plan from the
//!   current configuration ([`crate::nao::plan`]). The teacher sees the real
//!   table through the web-cam, so it judges by the object's true class and
//!   position, not by the robot's noisy reading.
//! - Guidance names a Table 3.1 region that contains a correct action. Of
//!   those, the teacher picks the one that leaves the robot the fewest
//!   legal wrong choices (ties: Table 3.1's order), as an expert who knows
//!   the interface would ([`choose_region`]).
//!
//! What this is not: a model of a non-expert, of delays or of a teacher's
//! mistakes; the thesis's teacher was "a roboticist after numerous practice
//! trials".

use serde::{Deserialize, Serialize};

use crate::guidance::GuidanceRegion;
use crate::nao::{Action, ActionSet, NaoSorting, SortingPlan};

/// The protocol's numbers.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TeacherProtocol {
    /// Actions attended from the start (thesis: 20).
    pub initial_actions: u32,
    /// Actions attended after each incorrect one (thesis: 5).
    pub follow_up_actions: u32,
    /// Reward for a correct action (our choice: +1, the top of `[−1, 1]`).
    pub correct_reward: f64,
    /// Reward for an incorrect action (our choice: −1).
    pub wrong_reward: f64,
}

impl TeacherProtocol {
    /// The thesis's protocol with rewards ±1.
    pub const fn thesis() -> TeacherProtocol {
        TeacherProtocol { initial_actions: 20, follow_up_actions: 5, correct_reward: 1.0, wrong_reward: -1.0 }
    }
}

/// What the teacher did about one action.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Judgement {
    /// Whether the action began a correct plan.
    pub correct: bool,
    /// Whether the action was one the protocol attends to.
    pub attended: bool,
    /// The reward given after it, if any.
    pub reward: Option<f64>,
}

/// The region that contains a correct action and leaves the fewest legal
/// wrong actions; ties go to the earlier row of Table 3.1. `None` when no
/// action is correct.
pub fn choose_region(correct: ActionSet, legal: ActionSet) -> Option<GuidanceRegion> {
    GuidanceRegion::ALL
        .into_iter()
        .filter(|r| !r.actions().intersection(correct).is_empty())
        .min_by_key(|r| r.actions().intersection(legal).difference(correct).len())
}

/// The scripted expert.
#[derive(Clone, Debug)]
pub struct ExpertTeacher {
    protocol: TeacherProtocol,
    guides: bool,
    plan: &'static SortingPlan,
    judged: u32,
    follow_up_left: u32,
}

impl ExpertTeacher {
    /// A teacher following `protocol`, guiding when `guides` (the guidance condition).
    pub fn new(protocol: TeacherProtocol, guides: bool) -> ExpertTeacher {
        ExpertTeacher { protocol, guides, plan: SortingPlan::shared(), judged: 0, follow_up_left: 0 }
    }

    /// Whether the coming action will be attended (guided and rewarded).
    pub fn attends(&self) -> bool {
        self.judged < self.protocol.initial_actions || self.follow_up_left > 0
    }

    /// The actions that are correct in `world` now.
    pub fn correct_actions(&self, world: &NaoSorting) -> ActionSet {
        self.plan.correct(&world.physical(), world.current_object().class)
    }

    /// Guidance for the coming action: a region when the teacher guides and
    /// attends to it, `None` otherwise.
    pub fn guidance(&self, world: &NaoSorting) -> Option<GuidanceRegion> {
        if self.guides && self.attends() { choose_region(self.correct_actions(world), world.legal()) } else { None }
    }

    /// Judges `action`, taken where `correct` were the correct actions, and
    /// moves the protocol on by one action.
    pub fn judge(&mut self, correct: ActionSet, action: Action) -> Judgement {
        let attended = self.attends();
        let is_correct = correct.contains(action);
        self.judged += 1;
        self.follow_up_left = self.follow_up_left.saturating_sub(1);
        if !is_correct {
            self.follow_up_left = self.protocol.follow_up_actions;
        }
        let reward = (attended || !is_correct).then_some(if is_correct {
            self.protocol.correct_reward
        } else {
            self.protocol.wrong_reward
        });
        Judgement { correct: is_correct, attended, reward }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nao::{Perception, StateSpace};
    use Action::*;

    /// Runs the protocol over a script of correct (true) / incorrect (false)
    /// actions; returns, per action, (rewarded, guided).
    fn protocol_over(script: &[bool]) -> Vec<(bool, bool)> {
        let mut rng = rlfd_rl::random::seeded(1);
        let mut world = NaoSorting::new(Perception::new(StateSpace::Small, 0.0));
        world.reset(&mut rng);
        let mut t = ExpertTeacher::new(TeacherProtocol::thesis(), true);
        let correct = ActionSet::of(&[TakePicture]);
        script
            .iter()
            .map(|&ok| {
                let guided = t.guidance(&world).is_some();
                let j = t.judge(correct, if ok { TakePicture } else { LRight });
                assert_eq!(j.correct, ok);
                (j.reward.is_some(), guided)
            })
            .collect()
    }

    #[test]
    fn the_first_20_actions_are_rewarded_and_guided_then_only_mistakes_and_5_after() {
        // 1..=20 correct, 21..=24 correct, 25 wrong, 26..=35 correct.
        let mut script = vec![true; 35];
        script[24] = false;
        let got = protocol_over(&script);
        for (k, &(rewarded, guided)) in got.iter().enumerate() {
            let n = k + 1;
            let (want_r, want_g) = match n {
                1..=20 => (true, true),
                21..=24 => (false, false),
                25 => (true, false), // the mistake: punished, not guided (guidance came before it)
                26..=30 => (true, true),
                _ => (false, false),
            };
            assert_eq!((rewarded, guided), (want_r, want_g), "action {n}");
        }
    }

    #[test]
    fn a_mistake_inside_the_follow_up_restarts_the_five() {
        let mut script = vec![true; 40];
        script[24] = false; // action 25
        script[27] = false; // action 28, inside 26..=30
        let got = protocol_over(&script);
        let attended: Vec<usize> = got.iter().enumerate().filter(|(_, g)| g.1).map(|(k, _)| k + 1).collect();
        let rewarded: Vec<usize> = got.iter().enumerate().filter(|(_, g)| g.0).map(|(k, _)| k + 1).collect();
        assert_eq!(attended, (1..=20).chain(26..=33).collect::<Vec<_>>());
        assert_eq!(rewarded, (1..=20).chain(25..=33).collect::<Vec<_>>());
    }

    #[test]
    fn a_mistake_in_the_first_20_extends_attention_past_them() {
        let mut script = vec![true; 30];
        script[17] = false; // action 18: actions 19..=23 attended
        let got = protocol_over(&script);
        let guided: Vec<usize> = got.iter().enumerate().filter(|(_, g)| g.1).map(|(k, _)| k + 1).collect();
        assert_eq!(guided, (1..=23).collect::<Vec<_>>());
    }

    #[test]
    fn rewards_are_plus_one_and_minus_one_and_the_no_guidance_teacher_never_guides() {
        let mut rng = rlfd_rl::random::seeded(2);
        let mut world = NaoSorting::new(Perception::new(StateSpace::Small, 0.0));
        world.reset(&mut rng);
        let mut t = ExpertTeacher::new(TeacherProtocol::thesis(), false);
        assert_eq!(t.guidance(&world), None);
        let correct = t.correct_actions(&world);
        assert_eq!(correct, ActionSet::of(&[TakePicture]));
        assert_eq!(t.judge(correct, TakePicture).reward, Some(1.0));
        assert_eq!(t.judge(correct, RLeft).reward, Some(-1.0));
        for _ in 0..30 {
            t.judge(correct, TakePicture);
        }
        let quiet = t.judge(correct, TakePicture);
        assert_eq!((quiet.attended, quiet.reward), (false, None));
    }

    #[test]
    fn guidance_names_the_tightest_region_holding_the_correct_action() {
        // Unseen object in front, hands at rest: only the picture is correct.
        let legal = ActionSet::of(&[TakePicture, LRight, RLeft]);
        assert_eq!(choose_region(ActionSet::of(&[TakePicture]), legal), Some(GuidanceRegion::Zone2));
        // Carrying to the right cup: Zone 3 holds RRight and nothing else legal.
        let legal = ActionSet::of(&[TakePicture, LRight, RRight, RPutDown]);
        assert_eq!(choose_region(ActionSet::of(&[RRight]), legal), Some(GuidanceRegion::Zone3));
        // RLeft is only in the right shoulder.
        let legal = ActionSet::of(&[TakePicture, LRight, RLeft]);
        assert_eq!(choose_region(ActionSet::of(&[RLeft]), legal), Some(GuidanceRegion::RightShoulder));
        // RPickUp with both hands in front: Zone 2 leaves LPickUp and the
        // picture, the right shoulder only RRight.
        let legal = ActionSet::of(&[TakePicture, LPickUp, RPickUp, LLeft, RRight]);
        assert_eq!(choose_region(ActionSet::of(&[RPickUp]), legal), Some(GuidanceRegion::RightShoulder));
        assert_eq!(choose_region(ActionSet::EMPTY, legal), None);
    }

    #[test]
    fn guidance_always_contains_a_legal_correct_action_in_every_reachable_configuration() {
        use crate::nao::{CATALOGUE, Physical, kinematics::CONFIGS};
        let plan = SortingPlan::new();
        for i in 0..CONFIGS {
            let p = Physical::from_config_index(i);
            if !SortingPlan::reachable(&p) {
                continue;
            }
            for o in &CATALOGUE {
                let correct = plan.correct(&p, o.class);
                let region = choose_region(correct, p.legal()).unwrap();
                assert!(!region.actions().intersection(correct).intersection(p.legal()).is_empty());
            }
        }
    }
}
