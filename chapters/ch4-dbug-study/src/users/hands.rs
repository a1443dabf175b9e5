//! What users do with the bugs by hand, whatever the algorithm.
//!
//! Section 4.3.2: "The test subject had the option of turning the hexbugs on
//! and off, or moving them around at will", and a lifted bug is removed by
//! hand ("the Nao raised its arm and asked the user to remove it
//! manually"). The model (rates ours, from those sentences):
//! - a lifted bug is taken off the magnet a reaction time after the pickup
//!   ends and, for a user who lets the bugs roam, put back at a random spot,
//!   switched on, [`HandsModel::return_seconds`] later;
//! - a user who lets the bugs roam now and then moves one "at will" into
//!   the pickup or sweep zone to show the robot a case: every
//!   [`HandsModel::nudge_seconds`], with probability
//!   [`HandsModel::nudge_probability`];
//! - a user who controls the bugs ("by turning them off and displacing
//!   them manually") keeps one bug on the table, switched off, at a spot of
//!   their choosing (see [`Hands::show`]), and the others in hand. Who
//!   controls in Int-RL and CBA: experts with probability
//!   [`HandsModel::control_probability`]`[0]`, others much less ("if the
//!   user did not control the location of the hexbugs"), drawn per session;
//!   in BNets, the reading `bnets-bug-control`
//!   ([`super::kinesthetic::BugControl`]), whatever the expertise;
//! - a BNets participant who controls the bugs demonstrates by "turning them
//!   off and displacing them manually" (l. 580): the bugs on the table are
//!   switched off where they stand and one is displaced
//!   ([`Hands::switch_off_and_place`]); nothing is cleared.

use rand::Rng;
use rlfd_rl::random::{below, bernoulli, uniform01};
use serde::{Deserialize, Serialize};

use super::traits::{Expertise, UserTraits};
use crate::dbug::table::NUM_BUGS;
use crate::dbug::zones::{PICKUP_ZONE, SWEEP_ZONE};
use crate::dbug::{BugPlace, IMAGE_HEIGHT, IMAGE_WIDTH, Table, Zone, seconds_to_ticks, zone_at};

/// The hands model's constants (our choices).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct HandsModel {
    /// Seconds between taking a lifted bug off the magnet and putting it back.
    pub return_seconds: f64,
    /// Seconds between chances to move a roaming bug into a zone.
    pub nudge_seconds: f64,
    /// Probability of doing so at each chance.
    pub nudge_probability: f64,
    /// Probability that a user controls the bugs in a session, per expertise.
    pub control_probability: [f64; 3],
}

impl HandsModel {
    /// Our choices: bugs back after 3 s; a nudge chance every 30 s taken half the time;
    /// experts control the bugs 90 % of sessions, novices 25 %, users without background 10 %.
    pub const fn thesis() -> HandsModel {
        HandsModel {
            return_seconds: 3.0,
            nudge_seconds: 30.0,
            nudge_probability: 0.5,
            control_probability: [0.9, 0.25, 0.1],
        }
    }

    /// Whether a user controls the bugs this session (one draw).
    pub fn draws_control<R: Rng + ?Sized>(&self, traits: &UserTraits, rng: &mut R) -> bool {
        let p = match traits.expertise {
            Expertise::Expert => self.control_probability[0],
            Expertise::Novice => self.control_probability[1],
            Expertise::None => self.control_probability[2],
        };
        bernoulli(rng, p)
    }
}

/// A random in-view spot of `zone`, as a table point.
pub fn spot_in_zone<R: Rng + ?Sized>(table: &Table, zone: Zone, rng: &mut R) -> (f64, f64) {
    let (x0, x1, y0, y1) = match zone {
        Zone::Pickup => PICKUP_ZONE,
        Zone::Sweep => SWEEP_ZONE,
        Zone::Wait => (0, IMAGE_WIDTH as u16, 0, IMAGE_HEIGHT as u16),
    };
    loop {
        let px = f64::from(x0) + 2.0 + uniform01(rng) * f64::from(x1 - x0 - 4);
        let py = f64::from(y0) + 2.0 + uniform01(rng) * f64::from(y1 - y0 - 4);
        if zone_at(px, py) == zone {
            return table.params().table_point(px, py);
        }
    }
}

/// One user's hands during a session.
#[derive(Clone, Debug)]
pub struct Hands {
    model: HandsModel,
    /// This session the user controls the bugs.
    pub controls: bool,
    take_at: [Option<u32>; NUM_BUGS],
    return_at: [Option<u32>; NUM_BUGS],
    next_nudge: u32,
    reaction_ticks: u32,
    /// Bugs moved or placed by hand.
    pub moves: u32,
}

impl Hands {
    /// The hands of a user; `controls` as drawn for the session.
    pub fn new(model: HandsModel, traits: &UserTraits, controls: bool) -> Hands {
        Hands {
            model,
            controls,
            take_at: [None; NUM_BUGS],
            return_at: [None; NUM_BUGS],
            next_nudge: seconds_to_ticks(model.nudge_seconds),
            reaction_ticks: seconds_to_ticks(traits.reaction_time),
            moves: 0,
        }
    }

    /// Called every tick: takes lifted bugs off the magnet, puts roaming bugs back, nudges.
    pub fn tick<R: Rng + ?Sized>(&mut self, table: &mut Table, tick: u32, rng: &mut R) {
        if let Some(i) = table.lifted_bug()
            && !table.arm_busy()
        {
            match self.take_at[i] {
                None => self.take_at[i] = Some(tick + self.reaction_ticks.max(1)),
                Some(t) if tick >= t => {
                    table.remove_to_hand(i);
                    self.take_at[i] = None;
                    if !self.controls {
                        self.return_at[i] = Some(tick + seconds_to_ticks(self.model.return_seconds));
                    }
                }
                _ => {}
            }
        }
        for i in 0..NUM_BUGS {
            if self.return_at[i].is_some_and(|t| tick >= t) {
                self.return_at[i] = None;
                if table.places()[i] == BugPlace::InHand {
                    let at = table.params().random_place(rng);
                    table.place(i, at, true);
                    self.moves += 1;
                }
            }
        }
        if !self.controls && tick >= self.next_nudge {
            self.next_nudge = tick + seconds_to_ticks(self.model.nudge_seconds);
            if bernoulli(rng, self.model.nudge_probability) {
                let on: Vec<usize> = (0..NUM_BUGS).filter(|&i| table.places()[i] == BugPlace::OnTable).collect();
                if !on.is_empty() {
                    let i = on[below(rng, on.len())];
                    let zone = if bernoulli(rng, 0.5) { Zone::Pickup } else { Zone::Sweep };
                    let at = spot_in_zone(table, zone, rng);
                    table.place(i, at, true);
                    self.moves += 1;
                }
            }
        }
    }

    /// A controlling user shows the robot one spot: one bug there, switched
    /// off, the others in hand.
    pub fn show(&mut self, table: &mut Table, at: (f64, f64)) {
        let keep = (0..NUM_BUGS).find(|&i| table.places()[i] != BugPlace::Lifted).unwrap_or(0);
        for i in 0..NUM_BUGS {
            if i != keep && table.places()[i] == BugPlace::OnTable {
                table.remove_to_hand(i);
            }
        }
        table.place(keep, at, false);
        self.moves += 1;
    }

    /// A BNets participant who controls the bugs, after START: every bug on
    /// the table switched off where it stands, and one bug (one from the
    /// hand if any, else the first on the table) put down, switched off, at
    /// `at`. The others stay where they are, so they may still be what the
    /// robot perceives (it perceives the bug nearest the mark).
    pub fn switch_off_and_place(&mut self, table: &mut Table, at: (f64, f64)) {
        for i in 0..NUM_BUGS {
            if table.places()[i] == BugPlace::OnTable {
                table.set_on(i, false);
            }
        }
        let places = *table.places();
        let one = places
            .iter()
            .position(|&p| p == BugPlace::InHand)
            .or_else(|| places.iter().position(|&p| p == BugPlace::OnTable));
        if let Some(i) = one {
            table.place(i, at, false);
            self.moves += 1;
        }
    }

    /// A controlling user clears the table (every bug in hand).
    pub fn clear(&mut self, table: &mut Table) {
        for i in 0..NUM_BUGS {
            if table.places()[i] == BugPlace::OnTable {
                table.remove_to_hand(i);
            }
        }
    }
}
