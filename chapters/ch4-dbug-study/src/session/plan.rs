//! Where a user who controls the bugs puts one: the spots they show the
//! robot, one after another.
//!
//! A participant who controls the bugs shows each zone in turn (pick-up,
//! sweep, wait) at a random spot of it, [`super::SessionParams::dwell_seconds`]
//! each. The scripted ideal teacher, who knows the algorithm, goes through a
//! fixed list: for Int-RL the centre of every cell of the 10 × 10 grid (the
//! pick-up and sweep rows first), for CBA a lattice of spots over every
//! zone; it moves on when the spot is taught (see the session drivers).

use rand::Rng;

use crate::dbug::{Pixel, Table, Zone, zone_of};
use crate::intrl::{CELL, NUM_CELLS, cell_origin};
use crate::users::hands::spot_in_zone;

/// A sequence of spots to show.
#[derive(Clone, Debug)]
pub enum SpotPlan {
    /// Zones in turn, a random spot each.
    Rotation { next_zone: usize },
    /// A fixed list of pixels, cycled.
    List { spots: Vec<Pixel>, next: usize },
}

impl SpotPlan {
    /// A participant's rotation.
    pub fn rotation() -> SpotPlan {
        SpotPlan::Rotation { next_zone: 0 }
    }

    /// The ideal teacher's Int-RL plan: every cell centre, bottom rows first.
    pub fn grid_cells() -> SpotPlan {
        let mut cells: Vec<usize> = (0..NUM_CELLS).collect();
        cells.sort_by_key(|&c| (std::cmp::Reverse(c / 10), c % 10));
        let spots = cells
            .into_iter()
            .map(|c| {
                let o = cell_origin(c);
                Pixel::new(o.x + CELL.0 / 2, o.y + CELL.1 / 2)
            })
            .collect();
        SpotPlan::List { spots, next: 0 }
    }

    /// The ideal teacher's CBA plan: a lattice over each zone, 20 px apart
    /// in the pick-up and sweep zones and 40 px apart in the wait zone.
    pub fn zone_lattice() -> SpotPlan {
        let mut spots = Vec::new();
        for y in (170..240).step_by(20) {
            for x in (130..220).step_by(20) {
                spots.push(Pixel::new(x, y));
            }
            for x in (10..120).step_by(20) {
                spots.push(Pixel::new(x, y));
            }
        }
        for y in (10..160).step_by(40) {
            for x in (10..320).step_by(40) {
                spots.push(Pixel::new(x, y));
            }
        }
        for y in (170..240).step_by(30) {
            for x in (230..320).step_by(30) {
                spots.push(Pixel::new(x, y));
            }
        }
        spots.sort_by_key(|p| (zone_of(*p).index(), p.y, p.x));
        SpotPlan::List { spots, next: 0 }
    }

    /// The next spot, as a table point, and its pixel.
    pub fn next_spot<R: Rng + ?Sized>(&mut self, table: &Table, rng: &mut R) -> (f64, f64) {
        match self {
            SpotPlan::Rotation { next_zone } => {
                let z = Zone::ALL[*next_zone % 3];
                *next_zone += 1;
                spot_in_zone(table, z, rng)
            }
            SpotPlan::List { spots, next } => {
                let p = spots[*next % spots.len()];
                *next += 1;
                table.params().camera.pixel_centre(p)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plans_cover_the_image() {
        let SpotPlan::List { spots, .. } = SpotPlan::grid_cells() else { panic!() };
        assert_eq!(spots.len(), 100);
        assert_eq!(spots[0], Pixel::new(16, 228), "bottom row first");
        let SpotPlan::List { spots, .. } = SpotPlan::zone_lattice() else { panic!() };
        for z in Zone::ALL {
            assert!(spots.iter().filter(|p| zone_of(**p) == z).count() >= 12, "{z:?}");
        }
    }
}

/// A controlling user showing spots one after another: the current spot,
/// until when a participant dwells on it, and whether the robot has been
/// taught there (the ideal teacher moves on only then).
#[derive(Clone, Debug)]
pub struct SpotShow {
    plan: SpotPlan,
    spot: Option<(f64, f64)>,
    until: u32,
    dwell: u32,
    ideal: bool,
    /// Set by the session when the robot was taught at the current spot.
    pub taught: bool,
}

impl SpotShow {
    /// Follows `plan`, `dwell` ticks a spot for a participant, until taught for the ideal teacher.
    pub fn new(plan: SpotPlan, dwell: u32, ideal: bool) -> SpotShow {
        SpotShow { plan, spot: None, until: 0, dwell, ideal, taught: false }
    }

    /// Moves on to the next spot when it is due, and puts a bug on the
    /// current spot when the robot does not already see one there.
    pub fn show<R: Rng + ?Sized>(&mut self, st: &mut super::Stage, rng: &mut R) {
        let due = self.spot.is_none() || if self.ideal { self.taught } else { st.tick >= self.until };
        if due {
            self.spot = Some(self.plan.next_spot(&st.table, rng));
            self.until = st.tick + self.dwell;
            self.taught = false;
        }
        if let Some(at) = self.spot
            && st.table.params().camera.pixel(at.0, at.1) != Some(st.table.observe())
        {
            st.hands.show(&mut st.table, at);
        }
    }
}
