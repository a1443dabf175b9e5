//! An Int-RL session: the robot picks ε-greedily among the actions the
//! user's guidance leaves, the user rewards what they watched, and the
//! reward updates the action it is credited to.
//!
//! Credit (Sophie's Kitchen: the reward is "for the most recent (s, a),
//! after a short delay window"): a reward arriving at time `τ` goes to the
//! action that was under way at `τ − d` ([`super::SessionParams::credit_delay_seconds`]).
//! So a slow click after a one-second wait can land on the next action:
//! the noise reaction time puts into the rewards. Each action's Q-update
//! runs once its next state is known and either its reward came or its
//! credit window closed (reward 0).

use rand::Rng;
use rlfd_rl::random::bernoulli;

use super::{Details, SessionParams, SessionRecord, SpotPlan, SpotShow, Stage, Teacher};
use crate::dbug::{Action, seconds_to_ticks, zone_of};
use crate::intrl::{IntRl, IntRlParams, cell_of, score_grid};
use crate::users::perception::believed_action;
use crate::users::reward::RewardTeacher;
use crate::users::{Algorithm, UserModel};

#[derive(Clone, Copy, Debug)]
struct Pending {
    s: usize,
    a: Action,
    start: u32,
    next: Option<usize>,
    closes: u32,
    reward: Option<f64>,
}

/// Actions waiting for their reward and next state.
#[derive(Clone, Debug, Default)]
struct Credit {
    items: Vec<Pending>,
}

impl Credit {
    fn start(&mut self, s: usize, a: Action, tick: u32) {
        self.items.push(Pending { s, a, start: tick, next: None, closes: u32::MAX, reward: None });
    }

    fn decide(&mut self, s_next: usize, tick: u32, delay: u32, learner: &mut IntRl) {
        if let Some(last) = self.items.last_mut()
            && last.next.is_none()
        {
            last.next = Some(s_next);
            last.closes = tick + delay;
        }
        self.apply_ready(tick, learner);
    }

    fn reward(&mut self, r: f64, arrival: u32, delay: u32, learner: &mut IntRl) {
        if self.items.is_empty() {
            return;
        }
        let anchor = arrival.saturating_sub(delay);
        let i = self.items.iter().rposition(|p| p.start <= anchor).unwrap_or(0);
        self.items[i].reward = Some(self.items[i].reward.unwrap_or(0.0) + r);
        self.apply_ready(arrival, learner);
    }

    fn apply_ready(&mut self, tick: u32, learner: &mut IntRl) {
        self.items.retain(|p| match p.next {
            Some(next) if p.reward.is_some() || p.closes <= tick => {
                learner.update(p.s, p.a, p.reward.unwrap_or(0.0), next);
                false
            }
            _ => true,
        });
    }
}

/// A judgement the user will act on at `at`.
#[derive(Clone, Copy, Debug)]
struct Judgement {
    at: u32,
    action: Action,
    right: bool,
}

/// The ideal teacher's guidance: take out the first wrong action, so a
/// punished choice is never offered against an untried one.
fn ideal_guidance(correct: Action) -> [bool; 3] {
    let mut allowed = [true; 3];
    let first_wrong = (0..3).find(|&a| a != correct.index()).expect("two wrong actions");
    allowed[first_wrong] = false;
    allowed
}

/// Runs one Int-RL session.
pub fn run<R: Rng + ?Sized>(
    teacher: &Teacher,
    model: &UserModel,
    params: &SessionParams,
    learner_params: &IntRlParams,
    rng: &mut R,
) -> SessionRecord {
    let traits = teacher.traits;
    let controls = teacher.ideal || model.hands.draws_control(&traits, rng);
    let mut st = Stage::new(params, model, teacher, controls, rng);
    let mut learner = IntRl::new(*learner_params);
    let mut user = RewardTeacher::new(model.reward, &traits);
    let error = if teacher.ideal { 0.0 } else { model.perception.error_px(traits.expertise, teacher.session) };
    let gap = seconds_to_ticks(params.decision_gap_seconds);
    let delay = seconds_to_ticks(params.credit_delay_seconds);
    let rt = seconds_to_ticks(traits.reaction_time).max(1);
    let mut credit = Credit::default();
    let mut judgements: Vec<Judgement> = Vec::with_capacity(4);
    let plan = if teacher.ideal { SpotPlan::grid_cells() } else { SpotPlan::rotation() };
    let mut spots = SpotShow::new(plan, seconds_to_ticks(params.dwell_seconds), teacher.ideal);
    let (mut positive, mut negative, mut guidance, mut actions) = (0u32, 0u32, 0u32, 0u32);
    if controls {
        st.hands.clear(&mut st.table);
    }

    // Up to `n` ticks (fewer when the session ends): the table, then the
    // user's judgements that fall due. Returns whether a bug was lifted.
    let run = |n: u32,
               st: &mut Stage,
               learner: &mut IntRl,
               credit: &mut Credit,
               judgements: &mut Vec<Judgement>,
               user: &mut RewardTeacher,
               counts: (&mut u32, &mut u32),
               spot_taught: &mut bool,
               rng: &mut R| {
        let mut lifted = false;
        for _ in 0..n {
            if st.done() {
                break;
            }
            lifted |= st.advance(rng).lifted.is_some();
            let now = st.tick;
            let mut k = 0;
            while k < judgements.len() {
                if judgements[k].at <= now {
                    let j = judgements.swap_remove(k);
                    if st.counts_impression() {
                        st.impression.saw(&model.satisfaction, j.action, j.right);
                    }
                    let r = if teacher.ideal { Some(if j.right { 1.0 } else { -1.0 }) } else { user.reward(j.right) };
                    if let Some(r) = r {
                        if r > 0.0 {
                            *counts.0 += 1;
                        } else {
                            *counts.1 += 1;
                        }
                        credit.reward(r, now, delay, learner);
                    }
                    if teacher.ideal && j.right {
                        *spot_taught = true;
                    }
                } else {
                    k += 1;
                }
            }
            credit.apply_ready(now, learner);
        }
        lifted
    };

    while !st.done() {
        run(
            gap,
            &mut st,
            &mut learner,
            &mut credit,
            &mut judgements,
            &mut user,
            (&mut positive, &mut negative),
            &mut spots.taught,
            rng,
        );
        if st.done() {
            break;
        }
        if controls {
            spots.show(&mut st, rng);
        }
        let pixel = st.table.observe();
        let s = cell_of(pixel);
        credit.decide(s, st.tick, delay, &mut learner);
        let believed = if teacher.ideal {
            zone_of(pixel).correct_action()
        } else {
            believed_action(&st.table, &traits, model.perception.table_reading, error, rng)
        };
        let allowed = if teacher.ideal { ideal_guidance(believed) } else { user.guidance(&traits, believed, rng) };
        guidance += u32::from(allowed != [false; 3]);
        let a = learner.choose(s, allowed, rng);
        actions += 1;
        credit.start(s, a, st.tick);
        st.table.start_action(a);
        let watched = bernoulli(rng, traits.attention);
        if watched {
            judgements.push(Judgement {
                at: st.tick + model.reward.recognise_ticks(a) + rt,
                action: a,
                right: a == believed,
            });
        }
        let lifted = run(
            a.duration_ticks(),
            &mut st,
            &mut learner,
            &mut credit,
            &mut judgements,
            &mut user,
            (&mut positive, &mut negative),
            &mut spots.taught,
            rng,
        );
        if watched && lifted && st.counts_impression() {
            st.impression.saw_lift(&model.satisfaction);
        }
        if !teacher.ideal {
            user.check_progress(st.tick, rng);
        }
    }

    let policy = learner.policy();
    let satisfaction = st.impression.answer(&model.satisfaction, rng);
    SessionRecord {
        algorithm: Algorithm::IntRl,
        accuracy: score_grid(&policy),
        interactions: positive + negative,
        satisfaction,
        controlled: controls,
        hand_moves: st.hands.moves,
        details: Details::IntRl {
            untied: policy.iter().filter(|a| a.is_some()).count() as u32,
            policy: policy.to_vec(),
            positive_rewards: positive,
            negative_rewards: negative,
            guidance,
            actions,
            strategy_changes: user.changes,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::LearnerParams;
    use rlfd_rl::random::seeded;

    #[test]
    fn credit_goes_to_the_action_under_way_before_the_delay() {
        let mut l = IntRl::new(IntRlParams::thesis());
        let mut c = Credit::default();
        c.start(3, Action::Wait, 0);
        c.decide(4, 15, 8, &mut l); // next decision at 1.5 s
        c.start(4, Action::Pickup, 15);
        // A reward at 2.0 s: 1.2 s back is the wait.
        c.reward(1.0, 20, 8, &mut l);
        assert_eq!(l.greedy_action(3), Some(Action::Wait));
        // A reward at 2.5 s: 1.7 s back is the pickup, still without next state: it waits.
        c.reward(-1.0, 25, 8, &mut l);
        assert_eq!(l.greedy_action(4), None);
        c.decide(4, 115, 8, &mut l);
        assert_eq!(l.values(4)[0], 0.5 + 0.3 * (-1.0 + 0.75 * 0.5 - 0.5));
    }

    #[test]
    fn the_ideal_teacher_reaches_90_percent_in_ten_minutes() {
        let rec = run(
            &Teacher::ideal(),
            &UserModel::thesis(),
            &SessionParams::thesis(),
            &LearnerParams::thesis().intrl,
            &mut seeded(11),
        );
        assert!(rec.accuracy.overall >= 90.0, "{:?}", rec.accuracy);
        assert!(rec.accuracy.overall <= 96.6);
    }
}
