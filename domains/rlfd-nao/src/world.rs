//! The sorting-table simulator: the Nao, the objects arriving one at a time
//! in random order, and the camera, behind the robot's view of the state.
//!
//! One [`NaoSorting`] is one training session's world. It keeps the
//! physical configuration ([`Physical`]), which catalogue object is on the
//! table, the robot's current descriptor `I` and, after a drop, which cup the
//! previous object went into (shown until the next picture). "Objects were
//! presented to the robot in random order": the six objects of the
//! catalogue come in shuffled rounds, a fresh permutation each round, so
//! both classes keep arriving and no object is absent for long.
//!
//! There is no environment reward: "In Interactive RL, all reward input to
//! the robot comes from the human teacher instead of the environment." The
//! [`Environment`] implementation therefore returns 0 and never ends; the
//! chapter's session loop asks the teacher for the reward. The simulator
//! allocates nothing per step.
//!
//! What this is not: the learner or the teacher. It knows neither.

use rand::Rng;
use rlfd_env::random::{below, shuffle};
use rlfd_env::{Environment, Step};

use super::action::{Action, ActionSet};
use super::kinematics::{Cup, Effect, ObjectPosition, Physical, Zone};
use super::perception::{CATALOGUE, ObjectClass, Perception, SortingObject};
use super::state::{Placement, SortingState};

/// A finished object: which it was and where it went.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sorted {
    /// Its number in [`CATALOGUE`].
    pub object: usize,
    /// Its class.
    pub class: ObjectClass,
    /// The cup it fell into.
    pub cup: Cup,
}

impl Sorted {
    /// Whether it went into its class's cup.
    pub fn correct(&self) -> bool {
        self.class.cup() == self.cup
    }
}

/// What one action did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// The physical effect.
    pub effect: Effect,
    /// The object just dropped, if the action was a drop.
    pub sorted: Option<Sorted>,
}

/// The simulator.
#[derive(Clone, Debug)]
pub struct NaoSorting {
    perception: Perception,
    physical: Physical,
    object: usize,
    descriptor: usize,
    last_cup: Option<Cup>,
    order: [usize; CATALOGUE.len()],
    next_in_order: usize,
    vector: [f64; 6],
}

impl NaoSorting {
    /// A world seen through `perception`; call [`NaoSorting::reset`] before use.
    pub fn new(perception: Perception) -> NaoSorting {
        let mut w = NaoSorting {
            perception,
            physical: Physical::start(),
            object: 0,
            descriptor: perception.nothing_seen(),
            last_cup: None,
            order: std::array::from_fn(|i| i),
            next_in_order: CATALOGUE.len(),
            vector: [0.0; 6],
        };
        w.refresh_vector();
        w
    }

    /// Starts a session: hands beside their cups, the first object of a
    /// fresh random order placed in front, nothing seen yet.
    pub fn reset<R: Rng + ?Sized>(&mut self, rng: &mut R) {
        self.physical = Physical::start();
        self.descriptor = self.perception.nothing_seen();
        self.last_cup = None;
        self.next_in_order = CATALOGUE.len();
        self.place_next(rng);
        self.refresh_vector();
    }

    fn place_next<R: Rng + ?Sized>(&mut self, rng: &mut R) {
        if self.next_in_order == CATALOGUE.len() {
            shuffle(&mut self.order, rng);
            self.next_in_order = 0;
        }
        self.object = self.order[self.next_in_order];
        self.next_in_order += 1;
    }

    /// The perception model.
    pub fn perception(&self) -> &Perception {
        &self.perception
    }

    /// The physical configuration.
    pub fn physical(&self) -> Physical {
        self.physical
    }

    /// The object on the table or in a hand.
    pub fn current_object(&self) -> &'static SortingObject {
        &CATALOGUE[self.object]
    }

    /// The actions physically possible now.
    pub fn legal(&self) -> ActionSet {
        self.physical.legal()
    }

    /// The robot's view of the state (see [`super::state`]).
    pub fn state(&self) -> SortingState {
        let p = &self.physical;
        let (object_zone, placement) = match self.last_cup {
            Some(cup) if !p.seen => (cup.zone(), Placement::in_cup(cup)),
            _ => (p.object_zone(), Placement::at(p.object_zone())),
        };
        SortingState {
            left: p.left,
            right: p.right,
            holding: p.holding(),
            descriptor: self.descriptor,
            object_zone,
            placement,
        }
    }

    /// The state's number in its space.
    pub fn state_index(&self) -> usize {
        self.state().index(self.perception.space())
    }

    /// Performs a legal `action`.
    pub fn act<R: Rng + ?Sized>(&mut self, action: Action, rng: &mut R) -> Outcome {
        let (next, effect) = self.physical.apply(action);
        let was_in_front = self.physical.object == ObjectPosition::Table(Zone::Z2);
        self.physical = next;
        let mut sorted = None;
        match effect {
            Effect::Picture { object: true } => {
                debug_assert!(was_in_front);
                self.descriptor = self.perception.read(&CATALOGUE[self.object], rng);
                self.last_cup = None;
            }
            Effect::Dropped(cup) => {
                sorted = Some(Sorted { object: self.object, class: CATALOGUE[self.object].class, cup });
                self.last_cup = Some(cup);
                self.place_next(rng);
            }
            Effect::Picture { object: false } | Effect::Motion => {}
        }
        self.refresh_vector();
        Outcome { effect, sorted }
    }

    fn refresh_vector(&mut self) {
        let s = self.state();
        let holding = match s.holding {
            None => 0.0,
            Some(h) => 1.0 + h as usize as f64,
        };
        self.vector = [
            s.left as usize as f64,
            s.right as usize as f64,
            holding,
            s.descriptor as f64,
            s.object_zone as usize as f64,
            s.placement as usize as f64,
        ];
    }
}

/// The common interface: the state vector is `(z_lh, z_rh, hand_o, I, o_z,
/// o_p)` as numbers (zones 0–2 for z1–z3; hand_o 0 none, 1 left, 2 right;
/// `I` the descriptor number; `o_p` in the thesis's order). The reward is
/// always 0 and no step is terminal: reward comes from the teacher, and
/// training ends by the teacher's criterion. `step` takes only legal actions
/// (see [`NaoSorting::legal`]); an impossible one is a logic error and panics
/// with a sentence naming it.
impl Environment for NaoSorting {
    fn num_actions(&self) -> usize {
        Action::COUNT
    }

    fn state_dim(&self) -> usize {
        6
    }

    fn reset<R: Rng + ?Sized>(&mut self, rng: &mut R) {
        NaoSorting::reset(self, rng);
    }

    fn state(&self) -> &[f64] {
        &self.vector
    }

    fn step<R: Rng + ?Sized>(&mut self, action: usize, rng: &mut R) -> Step {
        self.act(Action::from_index(action), rng);
        Step { reward: 0.0, terminal: false }
    }
}

/// `steps` uniformly random legal actions from a fresh session (the
/// simulator's benchmark); returns `steps`.
pub fn random_walk_steps(seed: u64, steps: u64) -> u64 {
    let mut rng = rlfd_env::random::seeded(seed);
    let mut world = NaoSorting::new(Perception::new(super::StateSpace::Large, super::SHIFT_PROBABILITY));
    world.reset(&mut rng);
    let mut actions = [Action::TakePicture; Action::COUNT];
    for _ in 0..steps {
        let legal = world.legal();
        let mut n = 0;
        for a in legal.iter() {
            actions[n] = a;
            n += 1;
        }
        world.act(actions[below(&mut rng, n)], &mut rng);
    }
    steps
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{StateSpace, state_count};
    use Action::*;
    use rlfd_env::random::seeded;

    fn world(space: StateSpace) -> (NaoSorting, rlfd_env::random::SimRng) {
        let mut rng = seeded(5);
        let mut w = NaoSorting::new(Perception::new(space, 0.0));
        w.reset(&mut rng);
        (w, rng)
    }

    /// The correct plan for the object on the table from hands at rest.
    fn sort(w: &mut NaoSorting, rng: &mut rlfd_env::random::SimRng) -> Sorted {
        w.act(TakePicture, rng);
        let plan = match w.current_object().class {
            ObjectClass::Plain => [LRight, LPickUp, LLeft, LDrop],
            ObjectClass::Pattern => [RLeft, RPickUp, RRight, RDrop],
        };
        let mut last = None;
        for a in plan {
            last = w.act(a, rng).sorted;
        }
        last.expect("the plan ends with a drop")
    }

    #[test]
    fn the_start_state_is_hands_at_rest_and_nothing_seen() {
        let (w, _) = world(StateSpace::Large);
        let s = w.state();
        assert_eq!((s.left, s.right, s.holding), (Zone::Z1, Zone::Z3, None));
        assert_eq!((s.object_zone, s.placement), (Zone::Z2, Placement::Z2));
        assert_eq!(s.descriptor, crate::perception::NOTHING_SEEN.index());
        assert_eq!(w.legal(), ActionSet::of(&[TakePicture, LRight, RLeft]));
    }

    #[test]
    fn objects_come_in_shuffled_rounds_of_the_catalogue() {
        let (mut w, mut rng) = world(StateSpace::Small);
        let mut seen = Vec::new();
        for _ in 0..3 * CATALOGUE.len() {
            let sorted = sort(&mut w, &mut rng);
            assert!(sorted.correct());
            seen.push(sorted.object);
        }
        for round in seen.chunks(CATALOGUE.len()) {
            let mut r = round.to_vec();
            r.sort_unstable();
            assert_eq!(r, (0..CATALOGUE.len()).collect::<Vec<_>>());
        }
        assert_ne!(seen[..6], seen[6..12], "rounds are reshuffled");
    }

    #[test]
    fn after_a_drop_the_robot_sees_the_cup_until_it_takes_a_picture() {
        let (mut w, mut rng) = world(StateSpace::Small);
        let sorted = sort(&mut w, &mut rng);
        let s = w.state();
        assert_eq!(s.placement, Placement::in_cup(sorted.cup));
        assert_eq!(s.object_zone, sorted.cup.zone());
        assert!(!w.legal().contains(LPickUp) && !w.legal().contains(RPickUp));
        w.act(TakePicture, &mut rng);
        let s = w.state();
        assert_eq!((s.object_zone, s.placement), (Zone::Z2, Placement::Z2));
        assert_eq!(s.descriptor, w.current_object().class as usize);
    }

    #[test]
    fn a_wrong_cup_is_reported_as_such() {
        let (mut w, mut rng) = world(StateSpace::Small);
        w.act(TakePicture, &mut rng);
        let class = w.current_object().class;
        let plan = match class {
            ObjectClass::Pattern => [LRight, LPickUp, LLeft, LDrop],
            ObjectClass::Plain => [RLeft, RPickUp, RRight, RDrop],
        };
        let mut last = None;
        for a in plan {
            last = w.act(a, &mut rng).sorted;
        }
        assert!(!last.unwrap().correct());
    }

    #[test]
    fn random_walks_stay_inside_the_state_space_and_are_reproducible() {
        for space in StateSpace::ALL {
            let mut rng = seeded(11);
            let mut w = NaoSorting::new(Perception::new(space, 0.2));
            w.reset(&mut rng);
            let mut trace = Vec::new();
            for _ in 0..5_000 {
                let legal: Vec<Action> = w.legal().iter().collect();
                let a = legal[below(&mut rng, legal.len())];
                w.act(a, &mut rng);
                let i = w.state_index();
                assert!(i < state_count(space));
                assert_eq!(Environment::state(&w)[3] as usize, w.state().descriptor);
                trace.push(i);
            }
            let mut rng = seeded(11);
            let mut again = NaoSorting::new(Perception::new(space, 0.2));
            again.reset(&mut rng);
            for &expected in &trace {
                let legal: Vec<Action> = again.legal().iter().collect();
                let a = legal[below(&mut rng, legal.len())];
                again.act(a, &mut rng);
                assert_eq!(again.state_index(), expected);
            }
        }
        assert_eq!(random_walk_steps(1, 1000), 1000);
    }
}
