//! The zones of Figure 4.1(b) and the correct action in each state.
//!
//! The thesis: "approximately 12.5% of the states fall into the sweep zone,
//! 10.4% fall into the pick-up zone, and 77.1% fall into the wait zone", the
//! sweep zone bottom-left, the pick-up zone bottom-centre with a marked ×.
//! The spec's zone decision meets these areas exactly: pickup `x ∈ [120,
//! 220), y ∈ [160, 240)` (8,000 px, 10.42 %), sweep `x ∈ [0, 120), y ∈ [160,
//! 240)` (9,600 px, 12.5 %), wait the rest (59,200 px, 77.08 %). "The correct
//! action label for each state was pre-determined by the region in which that
//! state was located."
//!
//! The pickup mark (the ×) is not placed by the thesis; we put it at the
//! pickup zone's centre, pixel (170, 200).

use serde::{Deserialize, Serialize};

use super::action::Action;
use super::camera::{IMAGE_HEIGHT, IMAGE_WIDTH, Pixel};

/// Pickup zone `[x0, x1) × [y0, y1)` in pixels.
pub const PICKUP_ZONE: (u16, u16, u16, u16) = (120, 220, 160, 240);
/// Sweep zone `[x0, x1) × [y0, y1)` in pixels.
pub const SWEEP_ZONE: (u16, u16, u16, u16) = (0, 120, 160, 240);
/// The pickup mark (×), in continuous image coordinates.
pub const PICKUP_MARK: (f64, f64) = (170.0, 200.0);

/// A zone of the image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Zone {
    Pickup,
    Sweep,
    Wait,
}

impl Zone {
    /// In the order of [`Action::ALL`].
    pub const ALL: [Zone; 3] = [Zone::Pickup, Zone::Sweep, Zone::Wait];

    /// The action the zone requires.
    pub fn correct_action(self) -> Action {
        match self {
            Zone::Pickup => Action::Pickup,
            Zone::Sweep => Action::Sweep,
            Zone::Wait => Action::Wait,
        }
    }

    /// Its index `0..3` (the index of its action).
    pub fn index(self) -> usize {
        self.correct_action().index()
    }

    /// Its rectangle `[x0, x1) × [y0, y1)` in pixels; the wait zone is the rest of the image.
    pub fn rect(self) -> Option<(u16, u16, u16, u16)> {
        match self {
            Zone::Pickup => Some(PICKUP_ZONE),
            Zone::Sweep => Some(SWEEP_ZONE),
            Zone::Wait => None,
        }
    }

    /// The name in tables.
    pub fn label(self) -> &'static str {
        match self {
            Zone::Pickup => "pick-up",
            Zone::Sweep => "sweep",
            Zone::Wait => "wait",
        }
    }
}

fn inside((x0, x1, y0, y1): (u16, u16, u16, u16), x: f64, y: f64) -> bool {
    x >= f64::from(x0) && x < f64::from(x1) && y >= f64::from(y0) && y < f64::from(y1)
}

/// The zone of a pixel.
#[inline]
pub fn zone_of(p: Pixel) -> Zone {
    zone_at(f64::from(p.x), f64::from(p.y))
}

/// The zone of continuous image coordinates (outside the image: wait).
#[inline]
pub fn zone_at(x: f64, y: f64) -> Zone {
    if inside(PICKUP_ZONE, x, y) {
        Zone::Pickup
    } else if inside(SWEEP_ZONE, x, y) {
        Zone::Sweep
    } else {
        Zone::Wait
    }
}

/// Pixels per zone, in [`Zone::ALL`] order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ZoneCounts(pub [u32; 3]);

impl ZoneCounts {
    /// Counted over the whole image.
    pub fn of_image() -> ZoneCounts {
        let mut c = [0u32; 3];
        for y in 0..IMAGE_HEIGHT as u16 {
            for x in 0..IMAGE_WIDTH as u16 {
                c[zone_of(Pixel::new(x, y)).index()] += 1;
            }
        }
        ZoneCounts(c)
    }

    /// The share of the image in percent, per zone.
    pub fn percent(&self) -> [f64; 3] {
        let total = f64::from(self.0.iter().sum::<u32>());
        self.0.map(|c| 100.0 * f64::from(c) / total)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zone_areas_are_the_thesis_shares() {
        let c = ZoneCounts::of_image();
        assert_eq!(c.0, [8_000, 9_600, 59_200]);
        let p = c.percent();
        // "12.5% … sweep zone, 10.4% … pick-up zone, and 77.1% … wait zone".
        assert_eq!(format!("{:.1} {:.1} {:.1}", p[0], p[1], p[2]), "10.4 12.5 77.1");
        assert!((p[0] - 10.416_666).abs() < 1e-5 && (p[2] - 77.083_333).abs() < 1e-5);
    }

    #[test]
    fn zones_sit_where_figure_4_1_draws_them() {
        assert_eq!(zone_of(Pixel::new(170, 200)), Zone::Pickup);
        assert_eq!(zone_of(Pixel::new(119, 239)), Zone::Sweep);
        assert_eq!(zone_of(Pixel::new(120, 160)), Zone::Pickup);
        assert_eq!(zone_of(Pixel::new(219, 159)), Zone::Wait);
        assert_eq!(zone_of(Pixel::new(220, 239)), Zone::Wait);
        assert_eq!(zone_of(Pixel::NONE_SEEN), Zone::Wait);
        assert_eq!(zone_at(PICKUP_MARK.0, PICKUP_MARK.1), Zone::Pickup);
        for z in Zone::ALL {
            assert_eq!(z.correct_action().index(), z.index());
        }
    }
}
