//! A Behavior Networks session: the user demonstrates between START and
//! DONE by moving the arms, then watches the robot run the network, and
//! erases, adds on top or gives up ([`crate::users::kinesthetic`]).
//!
//! While the user demonstrates, the robot records what it perceives (which
//! zones hold a bug, through its camera) and which arm moves; the arms move
//! the real magnet and brush over the table. While the user watches, the
//! robot runs the network at each decision; with nothing to run, it waits.

use rand::Rng;
use rlfd_rl::random::{below, bernoulli};

use super::{Details, SessionParams, SessionRecord, SpotPlan, Stage, Teacher};
use crate::bnets::{Behavior, BehaviorNetwork, BnetsParams, DemonstrationRecord, World};
use crate::dbug::{Action, Zone, seconds_to_ticks, zone_of};
use crate::users::hands::spot_in_zone;
use crate::users::kinesthetic::KinestheticModel;
use crate::users::perception::believed_action;
use crate::users::{Algorithm, UserModel};

/// What the robot perceives now: the zone of the bug nearest the mark, as
/// every other state of the robot (at most one perception behaviour holds).
fn perceived(st: &Stage) -> (bool, bool) {
    let z = zone_of(st.table.observe());
    (z == Zone::Pickup, z == Zone::Sweep)
}

/// One tick of a demonstration: the table moves and the robot records its zones.
fn record_tick<R: Rng + ?Sized>(st: &mut Stage, rec: &mut DemonstrationRecord, rng: &mut R) {
    st.advance(rng);
    let (p, s) = perceived(st);
    rec.observe(p, s);
}

/// Moves the arm for `action` (and the other arm too when `both`), recording.
fn demonstrate_motion<R: Rng + ?Sized>(
    st: &mut Stage,
    rec: &mut DemonstrationRecord,
    start: u32,
    action: Action,
    both: bool,
    rng: &mut R,
) {
    let other = if action == Action::Pickup { Action::Sweep } else { Action::Pickup };
    let t = st.tick - start;
    st.table.start_action(action);
    rec.motion(Behavior::of_action(action).expect("an arm"), t, t + action.duration_ticks() - 1);
    let mut len = action.duration_ticks();
    if both {
        st.table.start_action(other);
        rec.motion(Behavior::of_action(other).expect("an arm"), t, t + other.duration_ticks() - 1);
        len = len.max(other.duration_ticks());
    }
    for _ in 0..len {
        if st.done() {
            return;
        }
        record_tick(st, rec, rng);
    }
}

/// Runs one BNets session.
pub fn run<R: Rng + ?Sized>(
    teacher: &Teacher,
    model: &UserModel,
    params: &SessionParams,
    bnets: &BnetsParams,
    rng: &mut R,
) -> SessionRecord {
    let traits = teacher.traits;
    let km = model.kinesthetic;
    // The authors control the bugs; a participant as the reading
    // `bnets-bug-control` says, whatever their expertise (the thesis tells
    // its participants' ways apart by control, not by background, l. 580).
    let controls = teacher.ideal || bernoulli(rng, km.bug_control.share());
    // The user's both-arm habit, drawn once (it persists through erasing,
    // l. 606); drawn whatever the reading, so the stream is the same.
    let habit = !teacher.ideal && bernoulli(rng, 0.5);
    let mut st = Stage::new(params, model, teacher, controls, rng);
    let e = traits.expertise;
    let error = if teacher.ideal { 0.0 } else { model.perception.error_px(e, teacher.session) };
    let p_erase = if teacher.ideal { 0.0 } else { KinestheticModel::of(km.erase_probability, e) };
    let gap = seconds_to_ticks(params.decision_gap_seconds);
    let second = seconds_to_ticks(1.0);
    let watch = seconds_to_ticks(km.watch_seconds);
    let dwell = seconds_to_ticks(params.dwell_seconds);
    let patience = seconds_to_ticks(traits.patience.min(1e6));
    let wait_for_bug = seconds_to_ticks(km.wait_for_bug_seconds);
    let mut net = BehaviorNetwork::new(bnets.order);
    let (mut demos, mut erasures, mut both_arms, mut actions) = (0u32, 0u32, 0u32, 0u32);
    let (mut satisfied, mut gave_up, mut erase_next) = (false, false, false);
    let mut spots = SpotPlan::rotation();
    // Patience runs from the last demonstration that changed what the robot does.
    let mut last_change = 0u32;

    while !st.done() {
        if !satisfied && !gave_up {
            // Teach: the authors' two demonstrations (before each START, the
            // table cleared and one bug placed, switched off, in the pick-up
            // and then the sweep zone; one arm each: their plan, l. 582); a
            // participant's one, placing a bug only after START and only if
            // they control the bugs (see `users::kinesthetic`).
            let zones: &[Zone] = if teacher.ideal { &[Zone::Pickup, Zone::Sweep] } else { &[Zone::Wait] };
            let before = net.behaviour();
            for (k, &z) in zones.iter().enumerate() {
                if st.done() {
                    break;
                }
                let mut rec = DemonstrationRecord::new();
                if teacher.ideal {
                    st.hands.clear(&mut st.table);
                    let at = spot_in_zone(&st.table, z, rng);
                    st.hands.show(&mut st.table, at);
                }
                let start = st.tick;
                for _ in 0..second {
                    if !st.done() {
                        record_tick(&mut st, &mut rec, rng);
                    }
                }
                if !teacher.ideal && controls && !st.done() {
                    // "turning them off and displacing them manually" (l. 580), into
                    // the zone of an arm, as a roaming user's nudge (`users::hands`).
                    let zone = if bernoulli(rng, 0.5) { Zone::Pickup } else { Zone::Sweep };
                    let at = spot_in_zone(&st.table, zone, rng);
                    st.hands.switch_off_and_place(&mut st.table, at);
                }
                let motions = if teacher.ideal { 1 } else { 1 + below(rng, km.max_motions as usize) };
                for _ in 0..motions {
                    let action = if teacher.ideal {
                        z.correct_action()
                    } else {
                        // Wait for what the user takes for a bug to pick up or sweep.
                        let mut believed =
                            believed_action(&st.table, &traits, model.perception.table_reading, error, rng);
                        let mut waited = 0;
                        while believed == Action::Wait && waited < wait_for_bug && !st.done() {
                            record_tick(&mut st, &mut rec, rng);
                            waited += 1;
                            if waited % 5 == 0 {
                                believed =
                                    believed_action(&st.table, &traits, model.perception.table_reading, error, rng);
                            }
                        }
                        if believed == Action::Wait { Action::Pickup } else { believed }
                    };
                    let both = !teacher.ideal && km.both_arms.both(habit, action);
                    both_arms += u32::from(both);
                    demonstrate_motion(&mut st, &mut rec, start, action, both, rng);
                }
                for _ in 0..second {
                    if !st.done() {
                        record_tick(&mut st, &mut rec, rng);
                    }
                }
                if erase_next && k == 0 {
                    net.erase();
                    erasures += 1;
                }
                net.add(&rec);
                demos += 1;
            }
            if net.behaviour() != before {
                last_change = st.tick;
            }
            erase_next = false;
            if teacher.ideal {
                st.hands.clear(&mut st.table);
            }
        }
        // Watch the robot run the network.
        let watch_end = if satisfied || gave_up { st.end } else { (st.tick + watch).min(st.end) };
        let (mut seen, mut right, mut arm_right) = (0u32, 0u32, 0u32);
        let mut spot_until = st.tick;
        while st.tick < watch_end {
            for _ in 0..gap {
                if !st.done() {
                    st.advance(rng);
                }
            }
            if st.done() {
                break;
            }
            if controls && st.tick >= spot_until {
                let at = spots.next_spot(&st.table, rng);
                st.hands.show(&mut st.table, at);
                spot_until = st.tick + dwell;
            }
            let (pickup, sweep) = perceived(&st);
            let world = World { pickup, sweep, tick: st.tick };
            let a = net.decide(&world).unwrap_or(Action::Wait);
            let believed = if teacher.ideal {
                zone_of(st.table.observe()).correct_action()
            } else {
                believed_action(&st.table, &traits, model.perception.table_reading, error, rng)
            };
            st.table.start_action(a);
            actions += 1;
            let mut lifted = false;
            for _ in 0..a.duration_ticks() {
                if st.done() {
                    break;
                }
                lifted |= st.advance(rng).lifted.is_some();
            }
            if bernoulli(rng, traits.attention) {
                let ok = a == believed;
                seen += 1;
                right += u32::from(ok);
                arm_right += u32::from(ok && a != Action::Wait);
                if st.counts_impression() {
                    st.impression.saw(&model.satisfaction, a, ok);
                    if lifted {
                        st.impression.saw_lift(&model.satisfaction);
                    }
                }
            }
        }
        if !satisfied && !gave_up {
            let share = if seen > 0 { f64::from(right) / f64::from(seen) } else { 0.0 };
            if share >= km.satisfied_share && arm_right > 0 {
                satisfied = true;
            } else if st.tick - last_change >= patience {
                gave_up = true;
            } else {
                erase_next = bernoulli(rng, p_erase);
            }
        }
    }

    let satisfaction = st.impression.answer(&model.satisfaction, rng);
    SessionRecord {
        algorithm: Algorithm::BNets,
        accuracy: net.accuracy_with(bnets),
        interactions: demos,
        satisfaction,
        controlled: controls,
        hand_moves: st.hands.moves,
        details: Details::BNets { branches: net.branches.clone(), erasures, both_arms, actions, gave_up },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    #[test]
    fn the_ideal_teacher_teaches_the_whole_task() {
        let rec = run(
            &Teacher::ideal(),
            &UserModel::thesis(),
            &SessionParams::thesis(),
            &BnetsParams::default(),
            &mut seeded(12),
        );
        assert!(rec.accuracy.overall >= 90.0, "{:?}", rec.accuracy);
        assert_eq!(rec.interactions, 2, "two demonstrations, one for pick-up and one for sweep");
    }
}
