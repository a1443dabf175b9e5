//! The Nao's eleven actions (section 3.3.1) and small sets of them.
//!
//! "The robot has eleven possible actions, TakePicture, xPickUp, xPutDown,
//! xDrop, xLeft, and xRight where x ∈ {L, R} determines the arm with which
//! the action is performed." Actions are numbered 0..11 in that order, left
//! arm before right; an [`ActionSet`] is a bit set over those numbers, so
//! legality masks, guidance regions and the teacher's correct actions are
//! one `u16` each and cost nothing to combine.
//!
//! What this is not: the effect of an action (see [`super::kinematics`]) or
//! its duration (see [`super::timing`]).

use serde::{Deserialize, Serialize};

/// An arm of the robot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Hand {
    Left,
    Right,
}

/// What an action does, whatever the arm.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum ActionKind {
    /// A snapshot of the table in front and its features.
    Picture,
    /// Grasp the object in the hand's zone.
    PickUp,
    /// Set the held object down on the table in the hand's zone.
    PutDown,
    /// Release the held object into the cup below the hand.
    Drop,
    /// Move the hand one zone to the robot's left (towards z1).
    MoveLeft,
    /// Move the hand one zone to the robot's right (towards z3).
    MoveRight,
}

/// One of the eleven actions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Action {
    TakePicture,
    LPickUp,
    LPutDown,
    LDrop,
    LLeft,
    LRight,
    RPickUp,
    RPutDown,
    RDrop,
    RLeft,
    RRight,
}

impl Action {
    /// Number of actions.
    pub const COUNT: usize = 11;

    /// Every action, by number.
    pub const ALL: [Action; Action::COUNT] = [
        Action::TakePicture,
        Action::LPickUp,
        Action::LPutDown,
        Action::LDrop,
        Action::LLeft,
        Action::LRight,
        Action::RPickUp,
        Action::RPutDown,
        Action::RDrop,
        Action::RLeft,
        Action::RRight,
    ];

    /// The action's number (its position in [`Action::ALL`]).
    #[inline]
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The action with number `i` (`i < 11`).
    #[inline]
    pub fn from_index(i: usize) -> Action {
        Action::ALL[i]
    }

    /// The thesis's name, e.g. `LPickUp`.
    pub fn name(self) -> &'static str {
        match self {
            Action::TakePicture => "TakePicture",
            Action::LPickUp => "LPickUp",
            Action::LPutDown => "LPutDown",
            Action::LDrop => "LDrop",
            Action::LLeft => "LLeft",
            Action::LRight => "LRight",
            Action::RPickUp => "RPickUp",
            Action::RPutDown => "RPutDown",
            Action::RDrop => "RDrop",
            Action::RLeft => "RLeft",
            Action::RRight => "RRight",
        }
    }

    /// The arm that performs it (`None` for the camera).
    pub fn hand(self) -> Option<Hand> {
        match self {
            Action::TakePicture => None,
            Action::LPickUp | Action::LPutDown | Action::LDrop | Action::LLeft | Action::LRight => Some(Hand::Left),
            _ => Some(Hand::Right),
        }
    }

    /// What it does.
    pub fn kind(self) -> ActionKind {
        match self {
            Action::TakePicture => ActionKind::Picture,
            Action::LPickUp | Action::RPickUp => ActionKind::PickUp,
            Action::LPutDown | Action::RPutDown => ActionKind::PutDown,
            Action::LDrop | Action::RDrop => ActionKind::Drop,
            Action::LLeft | Action::RLeft => ActionKind::MoveLeft,
            Action::LRight | Action::RRight => ActionKind::MoveRight,
        }
    }

    /// The action of `kind` done by `hand` (`kind` must not be `Picture`).
    pub fn of(hand: Hand, kind: ActionKind) -> Action {
        use ActionKind::*;
        match (hand, kind) {
            (Hand::Left, PickUp) => Action::LPickUp,
            (Hand::Left, PutDown) => Action::LPutDown,
            (Hand::Left, Drop) => Action::LDrop,
            (Hand::Left, MoveLeft) => Action::LLeft,
            (Hand::Left, MoveRight) => Action::LRight,
            (Hand::Right, PickUp) => Action::RPickUp,
            (Hand::Right, PutDown) => Action::RPutDown,
            (Hand::Right, Drop) => Action::RDrop,
            (Hand::Right, MoveLeft) => Action::RLeft,
            (Hand::Right, MoveRight) => Action::RRight,
            (_, Picture) => panic!("the camera is not an arm: TakePicture has no hand"),
        }
    }
}

/// A set of actions, as a bit set over their numbers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct ActionSet(u16);

impl ActionSet {
    /// No action.
    pub const EMPTY: ActionSet = ActionSet(0);

    /// All eleven.
    pub const ALL: ActionSet = ActionSet((1 << Action::COUNT) - 1);

    /// The set of the listed actions.
    pub const fn of(actions: &[Action]) -> ActionSet {
        let mut bits = 0u16;
        let mut i = 0;
        while i < actions.len() {
            bits |= 1 << actions[i] as usize;
            i += 1;
        }
        ActionSet(bits)
    }

    /// The raw bits (bit `i` = action number `i`).
    #[inline]
    pub const fn bits(self) -> u16 {
        self.0
    }

    /// Whether `a` is in the set.
    #[inline]
    pub const fn contains(self, a: Action) -> bool {
        self.0 & (1 << a as usize) != 0
    }

    /// The set with `a` added.
    #[inline]
    pub const fn with(self, a: Action) -> ActionSet {
        ActionSet(self.0 | (1 << a as usize))
    }

    /// Actions in both sets.
    #[inline]
    pub const fn intersection(self, other: ActionSet) -> ActionSet {
        ActionSet(self.0 & other.0)
    }

    /// Actions in `self` but not in `other`.
    #[inline]
    pub const fn difference(self, other: ActionSet) -> ActionSet {
        ActionSet(self.0 & !other.0)
    }

    /// Number of actions.
    #[inline]
    pub const fn len(self) -> usize {
        self.0.count_ones() as usize
    }

    /// Whether the set is empty.
    #[inline]
    pub const fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The actions, by number.
    pub fn iter(self) -> impl Iterator<Item = Action> {
        Action::ALL.into_iter().filter(move |&a| self.contains(a))
    }

    /// The names, comma-separated, by number.
    pub fn names(self) -> String {
        self.iter().map(Action::name).collect::<Vec<_>>().join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbering_round_trips_and_names_are_the_thesis_s() {
        for (i, a) in Action::ALL.into_iter().enumerate() {
            assert_eq!(a.index(), i);
            assert_eq!(Action::from_index(i), a);
        }
        let names: Vec<&str> = Action::ALL.iter().map(|a| a.name()).collect();
        assert_eq!(
            names,
            [
                "TakePicture",
                "LPickUp",
                "LPutDown",
                "LDrop",
                "LLeft",
                "LRight",
                "RPickUp",
                "RPutDown",
                "RDrop",
                "RLeft",
                "RRight"
            ]
        );
    }

    #[test]
    fn hand_and_kind_recompose_every_arm_action() {
        for a in Action::ALL {
            match a.hand() {
                Some(h) => assert_eq!(Action::of(h, a.kind()), a),
                None => assert_eq!(a.kind(), ActionKind::Picture),
            }
        }
        assert_eq!(Action::ALL.iter().filter(|a| a.hand() == Some(Hand::Left)).count(), 5);
        assert_eq!(Action::ALL.iter().filter(|a| a.hand() == Some(Hand::Right)).count(), 5);
    }

    #[test]
    fn sets_behave_as_sets() {
        let s = ActionSet::of(&[Action::LDrop, Action::RRight]);
        assert!(s.contains(Action::LDrop) && s.contains(Action::RRight) && !s.contains(Action::TakePicture));
        assert_eq!(s.len(), 2);
        assert_eq!(s.with(Action::TakePicture).len(), 3);
        assert_eq!(s.intersection(ActionSet::of(&[Action::LDrop])), ActionSet::of(&[Action::LDrop]));
        assert_eq!(s.difference(ActionSet::of(&[Action::LDrop])), ActionSet::of(&[Action::RRight]));
        assert_eq!(ActionSet::ALL.len(), 11);
        assert!(ActionSet::EMPTY.is_empty());
        assert_eq!(s.names(), "LDrop, RRight");
        assert_eq!(s.iter().collect::<Vec<_>>(), vec![Action::LDrop, Action::RRight]);
    }
}
