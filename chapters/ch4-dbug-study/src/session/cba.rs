//! A CBA session: the robot acts when confident and asks otherwise; the user
//! answers requests and corrects mistakes ([`crate::users::labelling`]).
//!
//! "the environment did not pause when the robot requested help": while the
//! robot waits for an answer the bugs move on, and the answer is filed under
//! the state the robot asked about. After each of its own actions the robot
//! pauses ([`super::SessionParams::correction_pause_seconds`]) so a
//! correction can come in; a correction that arrives after the next action
//! began labels that action's state ("The delay between the transition time
//! of the real world … and the state that the users wanted to give
//! correction for … led to a mismatch between states and labels").

use rand::Rng;
use rlfd_rl::random::bernoulli;

use super::{Details, SessionParams, SessionRecord, SpotPlan, SpotShow, Stage, Teacher};
use crate::cba::{Cba, CbaParams, Decision};
use crate::dbug::{Action, Pixel, seconds_to_ticks, zone_of};
use crate::users::perception::believed_action;
use crate::users::{Algorithm, UserModel};

/// A correction on its way.
#[derive(Clone, Copy, Debug)]
struct Correction {
    at: u32,
    label: Action,
    /// The state of the action it is meant for, and that action's number.
    state: Pixel,
    action_number: u32,
}

/// Runs one CBA session.
pub fn run<R: Rng + ?Sized>(
    teacher: &Teacher,
    model: &UserModel,
    params: &SessionParams,
    cba_params: &CbaParams,
    rng: &mut R,
) -> SessionRecord {
    let traits = teacher.traits;
    let controls = teacher.ideal || model.hands.draws_control(&traits, rng);
    let mut st = Stage::new(params, model, teacher, controls, rng);
    let mut learner = Cba::new(*cba_params);
    let error = if teacher.ideal { 0.0 } else { model.perception.error_px(traits.expertise, teacher.session) };
    let gap = seconds_to_ticks(params.decision_gap_seconds);
    let pause = seconds_to_ticks(params.correction_pause_seconds);
    let rt = seconds_to_ticks(traits.reaction_time).max(1);
    let pick = seconds_to_ticks(model.labelling.correction_seconds);
    let (mut requests, mut corrections, mut late, mut autonomous) = (0u32, 0u32, 0u32, 0u32);
    // Giving up: patience runs out since the robot last acted on its own.
    let patience = if teacher.ideal {
        u32::MAX
    } else {
        seconds_to_ticks((traits.patience * model.labelling.patience_scale).min(1e6))
    };
    let timeout = seconds_to_ticks(model.labelling.request_timeout_seconds).max(1);
    let (mut last_progress, mut gave_up, mut unanswered) = (0u32, false, 0u32);
    let mut pending: Option<Correction> = None;
    let (mut action_number, mut current_state) = (0u32, Pixel::NONE_SEEN);
    let plan = if teacher.ideal { SpotPlan::zone_lattice() } else { SpotPlan::rotation() };
    let mut spots = SpotShow::new(plan, seconds_to_ticks(params.dwell_seconds), teacher.ideal);
    if controls {
        st.hands.clear(&mut st.table);
    }

    // Up to `n` ticks (fewer when the session ends): the table, and each
    // correction that falls due. Returns whether a bug was lifted.
    let run = |n: u32,
               st: &mut Stage,
               learner: &mut Cba,
               pending: &mut Option<Correction>,
               counts: (&mut u32, &mut u32),
               action_number: u32,
               current_state: Pixel,
               rng: &mut R| {
        let mut lifted = false;
        for _ in 0..n {
            if st.done() {
                break;
            }
            lifted |= st.advance(rng).lifted.is_some();
            if let Some(c) = *pending
                && c.at <= st.tick
            {
                *pending = None;
                *counts.0 += 1;
                if c.action_number == action_number {
                    learner.add(c.state, c.label);
                } else {
                    *counts.1 += 1;
                    learner.add(current_state, c.label);
                }
            }
        }
        lifted
    };

    while !st.done() {
        run(gap, &mut st, &mut learner, &mut pending, (&mut corrections, &mut late), action_number, current_state, rng);
        if st.done() {
            break;
        }
        if controls {
            spots.show(&mut st, rng);
        }
        let s = st.table.observe();
        let (a, own) = match learner.decide(s) {
            Decision::Request => {
                requests += 1;
                gave_up |= st.tick - last_progress >= patience;
                if gave_up {
                    unanswered += 1;
                    run(
                        timeout,
                        &mut st,
                        &mut learner,
                        &mut pending,
                        (&mut corrections, &mut late),
                        action_number,
                        current_state,
                        rng,
                    );
                    continue;
                }
                let wait = if teacher.ideal { rt } else { model.labelling.response_ticks(&traits, rng) };
                run(
                    wait,
                    &mut st,
                    &mut learner,
                    &mut pending,
                    (&mut corrections, &mut late),
                    action_number,
                    current_state,
                    rng,
                );
                if st.done() {
                    break;
                }
                let label = if teacher.ideal {
                    zone_of(s).correct_action()
                } else {
                    believed_action(&st.table, &traits, model.perception.table_reading, error, rng)
                };
                learner.add(s, label);
                spots.taught = true;
                (label, false)
            }
            Decision::Act(k) => {
                last_progress = st.tick;
                (k.action, true)
            }
        };
        action_number += 1;
        current_state = s;
        st.table.start_action(a);
        let watched = own && !gave_up && bernoulli(rng, traits.attention);
        let mut judged_right = true;
        if watched {
            let believed = if teacher.ideal {
                zone_of(s).correct_action()
            } else {
                believed_action(&st.table, &traits, model.perception.table_reading, error, rng)
            };
            judged_right = a == believed;
            if teacher.ideal && judged_right {
                spots.taught = true;
            }
            if !judged_right && pending.is_none() {
                let at = st.tick + model.reward.recognise_ticks(a) + rt + pick;
                pending = Some(Correction { at, label: believed, state: s, action_number });
            }
        }
        autonomous += u32::from(own);
        let lifted = run(
            a.duration_ticks(),
            &mut st,
            &mut learner,
            &mut pending,
            (&mut corrections, &mut late),
            action_number,
            current_state,
            rng,
        );
        if watched && st.counts_impression() {
            st.impression.saw(&model.satisfaction, a, judged_right);
            if lifted {
                st.impression.saw_lift(&model.satisfaction);
            }
        }
        if own {
            run(
                pause,
                &mut st,
                &mut learner,
                &mut pending,
                (&mut corrections, &mut late),
                action_number,
                current_state,
                rng,
            );
        }
    }

    let satisfaction = st.impression.answer(&model.satisfaction, rng);
    let counts = learner.counts();
    SessionRecord {
        algorithm: Algorithm::Cba,
        accuracy: learner.accuracy(),
        interactions: counts.iter().sum(),
        satisfaction,
        controlled: controls,
        hand_moves: st.hands.moves,
        details: Details::Cba {
            classifier: learner.classifier().cloned().map(Box::new),
            counts,
            requests,
            corrections,
            late_corrections: late,
            autonomous,
            unanswered,
            gave_up,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn the_ideal_teacher_reaches_90_percent_in_ten_minutes() {
        let rec = run(
            &Teacher::ideal(),
            &UserModel::thesis(),
            &SessionParams::thesis(),
            &CbaParams::thesis(),
            &mut seeded(13),
        );
        assert!(rec.accuracy.overall >= 90.0, "{:?}", rec.accuracy);
    }
}
