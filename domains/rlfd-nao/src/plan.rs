//! Correct sorting plans: from any physical configuration, the fewest
//! actions that put the current object into its class's cup, and which
//! actions begin such a plan.
//!
//! The thesis's teacher rewards and guides by whether the robot's action
//! was correct; we read "correct" as "the next action of a correct sorting
//! plan from the current state": an action is correct when it begins a
//! shortest plan that drops the object into the right cup. One rule of
//! order comes first: while the current object has not been seen, the only
//! correct action is TakePicture ("The robot must learn to use its camera at
//! the appropriate time to identify the characteristics of the object and
//! then to pick up and place the object"), so moving a hand towards the
//! object before looking at it is not counted as progress, even when it
//! would happen to be the right hand.
//!
//! Distances come from value iteration over the 40 physical configurations
//! (`d = 1` for a drop into the right cup, `d = 1 + d(next)` otherwise, a
//! drop into the wrong cup never counts), once per class.
//!
//! What this is not: the teacher's protocol (when it speaks; see
//! chapter 3's `teacher` module).

use super::action::{Action, ActionSet};
use super::kinematics::{CONFIGS, Effect, ObjectPosition, Physical, Zone};
use super::perception::ObjectClass;

/// No plan reaches the cup from here.
pub const UNREACHABLE: u8 = u8::MAX;

/// Shortest sorting plans for both classes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SortingPlan {
    distance: [[u8; CONFIGS]; 2],
    correct: [[ActionSet; CONFIGS]; 2],
}

/// The actions a plan may take in `p`: only the picture while unseen.
fn plan_actions(p: &Physical) -> ActionSet {
    if p.seen { p.legal() } else { p.legal().intersection(ActionSet::of(&[Action::TakePicture])) }
}

impl SortingPlan {
    /// The plans, computed once per process and shared (they depend on nothing).
    pub fn shared() -> &'static SortingPlan {
        static PLAN: std::sync::OnceLock<SortingPlan> = std::sync::OnceLock::new();
        PLAN.get_or_init(SortingPlan::new)
    }

    /// Computes the plans.
    pub fn new() -> SortingPlan {
        let mut distance = [[UNREACHABLE; CONFIGS]; 2];
        let mut correct = [[ActionSet::EMPTY; CONFIGS]; 2];
        for class in [ObjectClass::Plain, ObjectClass::Pattern] {
            let d = &mut distance[class as usize];
            let step = |p: &Physical, a: Action, d: &[u8; CONFIGS]| -> u8 {
                match p.apply(a) {
                    (_, Effect::Dropped(cup)) => {
                        if cup == class.cup() {
                            1
                        } else {
                            UNREACHABLE
                        }
                    }
                    (next, _) => d[next.config_index()].saturating_add(1),
                }
            };
            loop {
                let mut changed = false;
                for i in 0..CONFIGS {
                    let p = Physical::from_config_index(i);
                    let best = plan_actions(&p).iter().map(|a| step(&p, a, d)).min().unwrap_or(UNREACHABLE);
                    if best < d[i] {
                        d[i] = best;
                        changed = true;
                    }
                }
                if !changed {
                    break;
                }
            }
            for i in 0..CONFIGS {
                if d[i] == UNREACHABLE {
                    continue;
                }
                let p = Physical::from_config_index(i);
                for a in plan_actions(&p).iter() {
                    if step(&p, a, d) == d[i] {
                        correct[class as usize][i] = correct[class as usize][i].with(a);
                    }
                }
            }
        }
        SortingPlan { distance, correct }
    }

    /// Actions left to sort the object of `class` from `p`; [`UNREACHABLE`] if none.
    pub fn distance(&self, p: &Physical, class: ObjectClass) -> u8 {
        self.distance[class as usize][p.config_index()]
    }

    /// The actions that begin a shortest correct plan from `p`.
    pub fn correct(&self, p: &Physical, class: ObjectClass) -> ActionSet {
        self.correct[class as usize][p.config_index()]
    }

    /// The configurations a session can reach: every configuration except
    /// an unseen object anywhere but on the table in z2.
    pub fn reachable(p: &Physical) -> bool {
        p.seen || p.object == ObjectPosition::Table(Zone::Z2)
    }
}

impl Default for SortingPlan {
    fn default() -> Self {
        SortingPlan::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::action::Hand;
    use crate::kinematics::Cup;
    use Action::*;

    #[test]
    fn every_reachable_configuration_has_a_plan() {
        let plan = SortingPlan::new();
        for i in 0..CONFIGS {
            let p = Physical::from_config_index(i);
            for class in [ObjectClass::Plain, ObjectClass::Pattern] {
                if SortingPlan::reachable(&p) {
                    assert!(plan.distance(&p, class) < UNREACHABLE, "{p:?} {class:?}");
                    let c = plan.correct(&p, class);
                    assert!(!c.is_empty() && c.difference(p.legal()).is_empty(), "{p:?}");
                } else {
                    assert_eq!(plan.distance(&p, class), UNREACHABLE);
                }
            }
        }
    }

    #[test]
    fn the_shared_plan_is_the_computed_one() {
        assert_eq!(SortingPlan::shared(), &SortingPlan::new());
    }

    #[test]
    fn from_rest_a_sort_takes_five_actions_and_begins_with_the_picture() {
        let plan = SortingPlan::new();
        let start = Physical::start();
        for class in [ObjectClass::Plain, ObjectClass::Pattern] {
            assert_eq!(plan.distance(&start, class), 5);
            assert_eq!(plan.correct(&start, class), ActionSet::of(&[TakePicture]));
        }
        let seen = start.apply(TakePicture).0;
        assert_eq!(plan.correct(&seen, ObjectClass::Plain), ActionSet::of(&[LRight]));
        assert_eq!(plan.correct(&seen, ObjectClass::Pattern), ActionSet::of(&[RLeft]));
    }

    #[test]
    fn following_correct_actions_sorts_into_the_right_cup() {
        let plan = SortingPlan::new();
        for i in 0..CONFIGS {
            let p = Physical::from_config_index(i);
            if !SortingPlan::reachable(&p) {
                continue;
            }
            for class in [ObjectClass::Plain, ObjectClass::Pattern] {
                let mut q = p;
                let mut steps = 0;
                loop {
                    let c = plan.correct(&q, class);
                    // Take the last correct action, to vary from the first.
                    let a = c.iter().last().unwrap();
                    steps += 1;
                    match q.apply(a) {
                        (_, Effect::Dropped(cup)) => {
                            assert_eq!(cup, class.cup());
                            break;
                        }
                        (next, _) => {
                            assert_eq!(plan.distance(&next, class) + 1, plan.distance(&q, class));
                            q = next;
                        }
                    }
                }
                assert_eq!(steps, plan.distance(&p, class));
            }
        }
    }

    #[test]
    fn a_wrong_hand_is_corrected_by_putting_down_and_picking_up() {
        let plan = SortingPlan::new();
        // A plain object in the right hand above z3 (the right cup).
        let p = Physical::new(Zone::Z1, Zone::Z3, ObjectPosition::Held(Hand::Right), true).unwrap();
        let c = plan.correct(&p, ObjectClass::Plain);
        assert!(!c.contains(RDrop), "dropping into the right cup is never correct for a plain object");
        // RLeft (carry to z2) and LRight (bring the left hand) both begin a shortest plan.
        assert_eq!(c, ActionSet::of(&[LRight, RLeft]));
        assert_eq!(plan.distance(&p, ObjectClass::Plain), 6); // RLeft, RPutDown, LRight, LPickUp, LLeft, LDrop
        assert_eq!(Cup::Left.hand(), Hand::Left);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// Wherever random legal actions lead, the plan has a correct legal
        /// action, and a correct action always brings the right cup one step closer.
        #[test]
        fn correct_actions_always_exist_and_make_progress(
            seed in 0u64..1_000_000,
            choices in proptest::collection::vec(0usize..11, 1..300),
        ) {
            use crate::{NaoSorting, Perception, StateSpace};
            let plan = SortingPlan::new();
            let mut rng = rlfd_env::random::seeded(seed);
            let mut world = NaoSorting::new(Perception::new(StateSpace::Large, 0.2));
            world.reset(&mut rng);
            for c in choices {
                let p = world.physical();
                let class = world.current_object().class;
                let correct = plan.correct(&p, class);
                proptest::prop_assert!(SortingPlan::reachable(&p));
                proptest::prop_assert!(!correct.is_empty() && correct.difference(world.legal()).is_empty());
                let good = correct.iter().next().unwrap();
                match p.apply(good) {
                    (_, Effect::Dropped(cup)) => proptest::prop_assert_eq!(cup, class.cup()),
                    (next, _) => proptest::prop_assert_eq!(plan.distance(&next, class) + 1, plan.distance(&p, class)),
                }
                let legal: Vec<Action> = world.legal().iter().collect();
                world.act(legal[c % legal.len()], &mut rng);
            }
        }
    }

    #[test]
    fn a_second_picture_of_a_seen_object_is_never_correct() {
        let plan = SortingPlan::new();
        for i in 0..CONFIGS {
            let p = Physical::from_config_index(i);
            if p.seen {
                for class in [ObjectClass::Plain, ObjectClass::Pattern] {
                    assert!(!plan.correct(&p, class).contains(TakePicture), "{p:?}");
                }
            }
        }
    }
}
