//! The DBug domain of section 4.3.2: a walled table with three hexbugs, seen
//! by the Nao's 320 × 240 camera, with the robot's three preprogrammed
//! actions and the zones that say which action is correct where.
//!
//! What it is: [`camera`] (table inches ↔ image pixels, the out-of-view
//! strips), [`zones`] (the spec's zone decision and the correct action per
//! state), [`hexbug`] (one bug's walk-and-bump motion), [`table`] (the three
//! bugs, the robot's tools and the user's hand, advanced in 0.1 s ticks),
//! [`action`] (the three actions and their durations).
//!
//! What it is not: no learner, no user and no session logic; it knows the
//! robot only as the tool each action moves over the table. The crate
//! depends on `rlfd-env` alone among the workspace's libraries, so it cannot
//! name an agent.

pub mod action;
pub mod camera;
pub mod hexbug;
pub mod table;
pub mod zones;

pub use action::{Action, TICKS_PER_SECOND, seconds_to_ticks};
pub use camera::{Camera, IMAGE_HEIGHT, IMAGE_WIDTH, NUM_STATES, Pixel};
pub use hexbug::{Hexbug, HexbugParams, Motion};
pub use table::{BugPlace, StepEvents, Table, TableParams};
pub use zones::{PICKUP_MARK, Zone, ZoneCounts, zone_at, zone_of};

/// Takes `ticks` ticks of the table with the robot repeating
/// pickup, sweep and wait in turn, and returns `ticks`: the simulator alone,
/// for speed measurements.
pub fn busy_table_ticks(seed: u64, ticks: u64) -> u64 {
    let mut rng = rlfd_env::random::seeded(seed);
    let mut table = Table::new(TableParams::thesis(), &mut rng);
    let mut k = 0;
    let mut left = 0u32;
    for _ in 0..ticks {
        if left == 0 {
            let a = Action::ALL[k % 3];
            table.start_action(a);
            left = a.duration_ticks();
            k += 1;
        }
        table.step(&mut rng);
        left -= 1;
        if let Some(i) = table.lifted_bug() {
            table.remove_to_hand(i);
            table.place(i, table.params().random_place(&mut rng), true);
        }
    }
    ticks
}
