//! The state the robot learns over: the thesis's `S = S_r ∪ S_o`.
//!
//! "The robot state is defined by S_r = (z_lh, z_rh, hand_o), where z_lh,
//! z_rh ∈ Z correspond to the current zone of the left and right hands … and
//! hand_o ∈ {left, right, none} represents whether an object is located in
//! either of the robot's hands." "The object state is defined by S_o = (I,
//! o_z, o_p), where I is an object descriptor … o_z ∈ Z is the current zone
//! of the object, and o_p ∈ P is the placement of the object such that P =
//! {z1, z2, z3, right_cup, left_cup}."
//!
//! The state space is the product of those ranges: hands 2 × 2 (each hand
//! has two zones within reach), hand_o 3, I 2 or 36, o_z 3, o_p 5, which is
//! the thesis's 360 states in the small space and 6,480 in the large (the
//! tests enumerate both). Many of them cannot occur (an object in the right
//! cup is in z3, never z1), as in the thesis's count.
//!
//! How the robot's view maps onto the world (our reading; the thesis gives
//! the variables, not their updates):
//! - `I` is the last picture's reading, kept until the next picture that
//!   sees an object; before the first, the reading of nothing
//!   ([`super::perception::NOTHING_SEEN`]).
//! - An object on the table or in a hand has `o_z = o_p` = its zone (the
//!   thesis's example: an object held in the right hand above z3 is
//!   "(pattern, z3, z3)").
//! - After a drop the object state shows the object in its cup (`o_p` the
//!   cup, `o_z` the cup's zone) until a picture sees the next object, which
//!   the experimenter has placed in z2 meanwhile: the robot learns of a new
//!   object only through its camera. This is what makes the cup placements
//!   states of the task and TakePicture the first action on every object.
//!
//! Whether the current object has been seen (which PickUp needs) is not a
//! state variable: the thesis's counts leave no room for it. It is known
//! to the simulator, which hands the learner the set of legal actions.

use serde::{Deserialize, Serialize};

use super::action::Hand;
use super::kinematics::{Cup, Zone};
use super::perception::{Perception, StateSpace};

/// The object's placement `o_p`, in the thesis's order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Placement {
    Z1,
    Z2,
    Z3,
    RightCup,
    LeftCup,
}

impl Placement {
    /// Every placement, in the thesis's order.
    pub const ALL: [Placement; 5] =
        [Placement::Z1, Placement::Z2, Placement::Z3, Placement::RightCup, Placement::LeftCup];

    /// The placement of an object lying or held in `zone`.
    pub const fn at(zone: Zone) -> Placement {
        match zone {
            Zone::Z1 => Placement::Z1,
            Zone::Z2 => Placement::Z2,
            Zone::Z3 => Placement::Z3,
        }
    }

    /// The placement of an object in `cup`.
    pub const fn in_cup(cup: Cup) -> Placement {
        match cup {
            Cup::Left => Placement::LeftCup,
            Cup::Right => Placement::RightCup,
        }
    }

    /// The thesis's name.
    pub fn name(self) -> &'static str {
        match self {
            Placement::Z1 => "z1",
            Placement::Z2 => "z2",
            Placement::Z3 => "z3",
            Placement::RightCup => "right_cup",
            Placement::LeftCup => "left_cup",
        }
    }
}

/// One state `(z_lh, z_rh, hand_o, I, o_z, o_p)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct SortingState {
    /// `z_lh` (z1 or z2).
    pub left: Zone,
    /// `z_rh` (z2 or z3).
    pub right: Zone,
    /// `hand_o`: the hand holding the object, `None` for none.
    pub holding: Option<Hand>,
    /// `I`: a descriptor number of the state space.
    pub descriptor: usize,
    /// `o_z`.
    pub object_zone: Zone,
    /// `o_p`.
    pub placement: Placement,
}

/// The number of states of a space: 360 (small) or 6,480 (large).
pub const fn state_count(space: StateSpace) -> usize {
    2 * 2 * 3 * space.descriptors() * 3 * 5
}

impl SortingState {
    /// A dense number in `0..state_count(space)`.
    pub fn index(&self, space: StateSpace) -> usize {
        let d = space.descriptors();
        debug_assert!(self.descriptor < d, "descriptor {} outside the {} space", self.descriptor, space.name());
        let left = self.left as usize; // z1, z2 → 0, 1
        let right = self.right as usize - 1; // z2, z3 → 0, 1
        let holding = match self.holding {
            None => 0,
            Some(Hand::Left) => 1,
            Some(Hand::Right) => 2,
        };
        ((((left * 2 + right) * 3 + holding) * d + self.descriptor) * 3 + self.object_zone as usize) * 5
            + self.placement as usize
    }

    /// The state with number `i < state_count(space)`.
    pub fn from_index(i: usize, space: StateSpace) -> SortingState {
        assert!(i < state_count(space), "state number {i} is outside the {} space", space.name());
        let d = space.descriptors();
        let placement = Placement::ALL[i % 5];
        let object_zone = Zone::ALL[(i / 5) % 3];
        let descriptor = (i / 15) % d;
        let rest = i / (15 * d);
        let holding = [None, Some(Hand::Left), Some(Hand::Right)][rest % 3];
        let right = [Zone::Z2, Zone::Z3][(rest / 3) % 2];
        let left = [Zone::Z1, Zone::Z2][rest / 6];
        SortingState { left, right, holding, descriptor, object_zone, placement }
    }

    /// Every state of `space`, by number.
    pub fn all(space: StateSpace) -> impl Iterator<Item = SortingState> {
        (0..state_count(space)).map(move |i| SortingState::from_index(i, space))
    }

    /// The state as the thesis writes it: `(z1, z3, right | pattern, z3, z3)`.
    pub fn label(&self, perception: &Perception) -> String {
        let hand = match self.holding {
            None => "none",
            Some(Hand::Left) => "left",
            Some(Hand::Right) => "right",
        };
        format!(
            "({}, {}, {hand} | {}, {}, {})",
            self.left.name(),
            self.right.name(),
            perception.label(self.descriptor),
            self.object_zone.name(),
            self.placement.name()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_small_space_has_360_states_and_the_large_6480() {
        assert_eq!(state_count(StateSpace::Small), 360);
        assert_eq!(state_count(StateSpace::Large), 6480);
        for space in StateSpace::ALL {
            // Enumerate from the types: every combination once, numbers dense.
            let mut count = 0;
            let mut numbers = Vec::new();
            for left in [Zone::Z1, Zone::Z2] {
                for right in [Zone::Z2, Zone::Z3] {
                    for holding in [None, Some(Hand::Left), Some(Hand::Right)] {
                        for descriptor in 0..space.descriptors() {
                            for object_zone in Zone::ALL {
                                for placement in Placement::ALL {
                                    let s = SortingState { left, right, holding, descriptor, object_zone, placement };
                                    let i = s.index(space);
                                    assert_eq!(SortingState::from_index(i, space), s);
                                    numbers.push(i);
                                    count += 1;
                                }
                            }
                        }
                    }
                }
            }
            numbers.sort_unstable();
            numbers.dedup();
            assert_eq!(numbers.len(), count);
            assert_eq!(count, state_count(space));
            assert_eq!(numbers.last().copied(), Some(count - 1));
            assert_eq!(SortingState::all(space).count(), count);
        }
    }

    #[test]
    fn labels_read_like_the_thesis() {
        let p = Perception::new(StateSpace::Small, 0.0);
        let s = SortingState {
            left: Zone::Z1,
            right: Zone::Z3,
            holding: Some(Hand::Right),
            descriptor: 1,
            object_zone: Zone::Z3,
            placement: Placement::Z3,
        };
        assert_eq!(s.label(&p), "(z1, z3, right | pattern, z3, z3)");
    }
}
