//! The physical side of the sorting table: where the hands and the object
//! are, which actions are physically possible, and what each does.
//!
//! From section 3.3.1: the table has three zones, z1 (the robot's left), z2
//! (in front) and z3 (right). "The robot's left hand can operate only in
//! z1,2, and the right hand can operate only in z2,3, which enables the robot
//! to pick up an object with either hand but allows only one hand to reach
//! each cup and Drop the object into it" (the left cup from z1, the right
//! cup from z3). "If the robot initially picks up the object with the wrong
//! hand, it can switch hands by performing a xPutDown action followed by a
//! xPickUp." "The PickUp action is not valid before the robot determines
//! whether there is an object in front of it using the TakePicture action."
//!
//! The rules, as this module implements them ([`Physical::legal`]):
//!
//! | action | legal when | effect |
//! |---|---|---|
//! | TakePicture | always | if the object lies on the table in z2, it is now seen |
//! | xPickUp | hand empty-handed, object on the table in the hand's zone, object seen | the hand holds it |
//! | xPutDown | the hand holds the object | it lies on the table in the hand's zone |
//! | xDrop | the hand holds the object and is above its cup (left: z1, right: z3) | it falls into the cup; the next object is placed in z2, unseen |
//! | xLeft / xRight | the hand's zone has a neighbour that way within its reach | the hand (and what it holds) moves one zone |
//!
//! Both hands may be in z2 at once (the Nao's arms do not collide above the
//! table's front). There is always exactly one object on the table or in a
//! hand: the experimenter places the next one in front as soon as the
//! previous one is in a cup ("Magnetic objects are placed in front of the
//! robot one at a time").
//!
//! What this is not: perception (the object's descriptor, see
//! [`super::perception`]), the robot's view of the state (see
//! [`super::state`]) or time (see [`super::timing`]).

use serde::{Deserialize, Serialize};

use super::action::{Action, ActionKind, ActionSet, Hand};

/// A zone of the table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Zone {
    /// The robot's left (the left cup's side).
    Z1,
    /// In front of the robot, where objects are placed and photographed.
    Z2,
    /// The robot's right (the right cup's side).
    Z3,
}

impl Zone {
    /// Every zone, left to right.
    pub const ALL: [Zone; 3] = [Zone::Z1, Zone::Z2, Zone::Z3];

    /// 0, 1, 2 from left to right.
    #[inline]
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The thesis's name, `z1` … `z3`.
    pub fn name(self) -> &'static str {
        match self {
            Zone::Z1 => "z1",
            Zone::Z2 => "z2",
            Zone::Z3 => "z3",
        }
    }

    fn left(self) -> Option<Zone> {
        match self {
            Zone::Z1 => None,
            Zone::Z2 => Some(Zone::Z1),
            Zone::Z3 => Some(Zone::Z2),
        }
    }

    fn right(self) -> Option<Zone> {
        match self {
            Zone::Z1 => Some(Zone::Z2),
            Zone::Z2 => Some(Zone::Z3),
            Zone::Z3 => None,
        }
    }
}

/// One of the two cups.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Cup {
    /// Reached by the left hand from z1.
    Left,
    /// Reached by the right hand from z3.
    Right,
}

impl Cup {
    /// The zone the cup stands in.
    pub const fn zone(self) -> Zone {
        match self {
            Cup::Left => Zone::Z1,
            Cup::Right => Zone::Z3,
        }
    }

    /// The only hand that reaches it.
    pub const fn hand(self) -> Hand {
        match self {
            Cup::Left => Hand::Left,
            Cup::Right => Hand::Right,
        }
    }
}

impl Hand {
    /// The zones the hand reaches: left z1–z2, right z2–z3.
    pub const fn reach(self) -> [Zone; 2] {
        match self {
            Hand::Left => [Zone::Z1, Zone::Z2],
            Hand::Right => [Zone::Z2, Zone::Z3],
        }
    }

    /// The cup the hand can drop into.
    pub const fn cup(self) -> Cup {
        match self {
            Hand::Left => Cup::Left,
            Hand::Right => Cup::Right,
        }
    }
}

/// Where the current object is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum ObjectPosition {
    /// Lying on the table in a zone.
    Table(Zone),
    /// Held by a hand.
    Held(Hand),
}

/// The physical configuration: hands, the current object, and whether the
/// camera has seen it since it was placed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct Physical {
    /// The left hand's zone (z1 or z2).
    pub left: Zone,
    /// The right hand's zone (z2 or z3).
    pub right: Zone,
    /// The current object.
    pub object: ObjectPosition,
    /// Whether a TakePicture has seen the current object (PickUp needs it).
    pub seen: bool,
}

/// What an action did, beyond the new configuration.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Effect {
    /// A hand moved, grasped or set down.
    Motion,
    /// A picture was taken; `object` says whether the object lay in front.
    Picture { object: bool },
    /// The object fell into `cup`; a new, unseen object now lies in z2.
    Dropped(Cup),
}

/// Number of distinct [`Physical::config_index`] values.
pub const CONFIGS: usize = 2 * 2 * 5 * 2;

impl Physical {
    /// A configuration, if the hands are within their reach.
    pub fn new(left: Zone, right: Zone, object: ObjectPosition, seen: bool) -> Option<Physical> {
        let ok = Hand::Left.reach().contains(&left) && Hand::Right.reach().contains(&right);
        ok.then_some(Physical { left, right, object, seen })
    }

    /// The configuration a training session starts in: each hand resting
    /// beside its cup (left in z1, right in z3, as in Figure 3.2b's left
    /// hand) and the first object just placed in front, not yet seen.
    pub const fn start() -> Physical {
        Physical { left: Zone::Z1, right: Zone::Z3, object: ObjectPosition::Table(Zone::Z2), seen: false }
    }

    /// The zone of `hand`.
    #[inline]
    pub const fn hand_zone(&self, hand: Hand) -> Zone {
        match hand {
            Hand::Left => self.left,
            Hand::Right => self.right,
        }
    }

    /// The zone the object is in (a held object is where its hand is).
    #[inline]
    pub const fn object_zone(&self) -> Zone {
        match self.object {
            ObjectPosition::Table(z) => z,
            ObjectPosition::Held(h) => self.hand_zone(h),
        }
    }

    /// The hand holding the object, if any.
    #[inline]
    pub const fn holding(&self) -> Option<Hand> {
        match self.object {
            ObjectPosition::Held(h) => Some(h),
            ObjectPosition::Table(_) => None,
        }
    }

    /// A dense number in `0..CONFIGS`, for lookup tables.
    pub const fn config_index(&self) -> usize {
        let left = self.left as usize - Zone::Z1 as usize; // z1, z2 → 0, 1
        let right = self.right as usize - Zone::Z2 as usize; // z2, z3 → 0, 1
        let object = match self.object {
            ObjectPosition::Table(z) => z as usize,
            ObjectPosition::Held(Hand::Left) => 3,
            ObjectPosition::Held(Hand::Right) => 4,
        };
        ((left * 2 + right) * 5 + object) * 2 + self.seen as usize
    }

    /// The configuration with number `i < CONFIGS` (inverse of [`Physical::config_index`]).
    pub fn from_config_index(i: usize) -> Physical {
        assert!(i < CONFIGS, "configuration number {i} is out of range (there are {CONFIGS})");
        let seen = i % 2 == 1;
        let object = match (i / 2) % 5 {
            3 => ObjectPosition::Held(Hand::Left),
            4 => ObjectPosition::Held(Hand::Right),
            z => ObjectPosition::Table(Zone::ALL[z]),
        };
        let right = if (i / 10).is_multiple_of(2) { Zone::Z2 } else { Zone::Z3 };
        let left = if i / 20 == 0 { Zone::Z1 } else { Zone::Z2 };
        Physical { left, right, object, seen }
    }

    /// The actions physically possible now (the table in the module docs).
    pub fn legal(&self) -> ActionSet {
        let mut set = ActionSet::EMPTY.with(Action::TakePicture);
        for hand in [Hand::Left, Hand::Right] {
            let zone = self.hand_zone(hand);
            let action = |kind| Action::of(hand, kind);
            match self.object {
                ObjectPosition::Held(h) if h == hand => {
                    set = set.with(action(ActionKind::PutDown));
                    if zone == hand.cup().zone() {
                        set = set.with(action(ActionKind::Drop));
                    }
                }
                ObjectPosition::Table(z) if z == zone && self.seen => {
                    set = set.with(action(ActionKind::PickUp));
                }
                _ => {}
            }
            if zone.left().is_some_and(|z| hand.reach().contains(&z)) {
                set = set.with(action(ActionKind::MoveLeft));
            }
            if zone.right().is_some_and(|z| hand.reach().contains(&z)) {
                set = set.with(action(ActionKind::MoveRight));
            }
        }
        set
    }

    /// The configuration after `action`, which must be legal, and its effect.
    pub fn apply(&self, action: Action) -> (Physical, Effect) {
        assert!(
            self.legal().contains(action),
            "{} is not physically possible in {self:?}; the learner only chooses legal actions",
            action.name()
        );
        let mut next = *self;
        let effect = match (action.hand(), action.kind()) {
            (None, _) => {
                let object = self.object == ObjectPosition::Table(Zone::Z2);
                next.seen |= object;
                Effect::Picture { object }
            }
            (Some(hand), ActionKind::PickUp) => {
                next.object = ObjectPosition::Held(hand);
                Effect::Motion
            }
            (Some(hand), ActionKind::PutDown) => {
                next.object = ObjectPosition::Table(self.hand_zone(hand));
                Effect::Motion
            }
            (Some(hand), ActionKind::Drop) => {
                next.object = ObjectPosition::Table(Zone::Z2);
                next.seen = false;
                Effect::Dropped(hand.cup())
            }
            (Some(hand), kind) => {
                let zone = self.hand_zone(hand);
                let to = if kind == ActionKind::MoveLeft { zone.left() } else { zone.right() };
                let to = to.expect("legal moves stay on the table");
                match hand {
                    Hand::Left => next.left = to,
                    Hand::Right => next.right = to,
                }
                Effect::Motion
            }
        };
        (next, effect)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use Action::*;

    fn config(left: Zone, right: Zone, object: ObjectPosition, seen: bool) -> Physical {
        Physical::new(left, right, object, seen).unwrap()
    }

    #[test]
    fn config_numbers_are_dense_and_invert() {
        let mut numbers = Vec::new();
        for left in [Zone::Z1, Zone::Z2] {
            for right in [Zone::Z2, Zone::Z3] {
                let objects = Zone::ALL.map(ObjectPosition::Table);
                for object in objects.into_iter().chain([Hand::Left, Hand::Right].map(ObjectPosition::Held)) {
                    for seen in [false, true] {
                        let p = config(left, right, object, seen);
                        assert_eq!(Physical::from_config_index(p.config_index()), p);
                        numbers.push(p.config_index());
                    }
                }
            }
        }
        numbers.sort_unstable();
        assert_eq!(numbers, (0..CONFIGS).collect::<Vec<_>>());
    }

    #[test]
    fn hands_outside_their_reach_are_refused() {
        assert!(Physical::new(Zone::Z3, Zone::Z3, ObjectPosition::Table(Zone::Z2), false).is_none());
        assert!(Physical::new(Zone::Z1, Zone::Z1, ObjectPosition::Table(Zone::Z2), false).is_none());
    }

    #[test]
    fn pick_up_needs_a_picture_first() {
        let p = config(Zone::Z2, Zone::Z2, ObjectPosition::Table(Zone::Z2), false);
        assert!(!p.legal().contains(LPickUp) && !p.legal().contains(RPickUp));
        let (seen, effect) = p.apply(TakePicture);
        assert_eq!(effect, Effect::Picture { object: true });
        assert!(seen.legal().contains(LPickUp) && seen.legal().contains(RPickUp));
    }

    #[test]
    fn the_start_allows_exactly_the_picture_and_moves_towards_the_front() {
        let legal = Physical::start().legal();
        assert_eq!(legal, ActionSet::of(&[TakePicture, LRight, RLeft]));
    }

    #[test]
    fn a_correct_right_hand_sort_and_the_next_object() {
        let mut p = Physical::start();
        for a in [TakePicture, RLeft, RPickUp, RRight] {
            p = p.apply(a).0;
        }
        assert_eq!(p.object, ObjectPosition::Held(Hand::Right));
        assert_eq!(p.object_zone(), Zone::Z3);
        assert!(p.legal().contains(RDrop));
        let (after, effect) = p.apply(RDrop);
        assert_eq!(effect, Effect::Dropped(Cup::Right));
        assert_eq!(after.object, ObjectPosition::Table(Zone::Z2));
        assert!(!after.seen);
        assert_eq!(after.right, Zone::Z3);
    }

    #[test]
    fn switching_hands_is_put_down_then_pick_up() {
        let p = config(Zone::Z2, Zone::Z2, ObjectPosition::Held(Hand::Left), true);
        assert!(!p.legal().contains(RPickUp), "the right hand cannot take it from the left");
        let (down, _) = p.apply(LPutDown);
        assert_eq!(down.object, ObjectPosition::Table(Zone::Z2));
        let (up, _) = down.apply(RPickUp);
        assert_eq!(up.holding(), Some(Hand::Right));
    }

    #[test]
    fn drops_only_over_the_hand_s_own_cup() {
        let at_front = config(Zone::Z2, Zone::Z2, ObjectPosition::Held(Hand::Left), true);
        assert!(!at_front.legal().contains(LDrop));
        let at_cup = at_front.apply(LLeft).0;
        assert_eq!(at_cup.object_zone(), Zone::Z1);
        assert!(at_cup.legal().contains(LDrop));
        assert_eq!(at_cup.apply(LDrop).1, Effect::Dropped(Cup::Left));
    }

    #[test]
    fn a_picture_of_an_empty_front_sees_nothing() {
        let p = config(Zone::Z1, Zone::Z2, ObjectPosition::Held(Hand::Left), true);
        assert_eq!(p.apply(TakePicture).1, Effect::Picture { object: false });
        let q = config(Zone::Z1, Zone::Z3, ObjectPosition::Table(Zone::Z1), false);
        let (after, effect) = q.apply(TakePicture);
        assert_eq!(effect, Effect::Picture { object: false });
        assert!(!after.seen);
    }

    #[test]
    fn every_legal_action_keeps_hands_in_reach_and_one_object() {
        for i in 0..CONFIGS {
            let p = Physical::from_config_index(i);
            let legal = p.legal();
            assert!(legal.contains(TakePicture));
            for a in legal.iter() {
                let (n, _) = p.apply(a);
                assert!(Physical::new(n.left, n.right, n.object, n.seen).is_some(), "{p:?} {a:?}");
                if let ObjectPosition::Held(h) = n.object {
                    assert!(h.reach().contains(&n.hand_zone(h)));
                }
            }
            // Exactly one move per hand is possible: each hand has two zones.
            assert_eq!(legal.intersection(ActionSet::of(&[LLeft, LRight])).len(), 1);
            assert_eq!(legal.intersection(ActionSet::of(&[RLeft, RRight])).len(), 1);
        }
    }
}
