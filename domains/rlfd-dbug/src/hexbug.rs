//! One hexbug: it walks forward until an antenna touches an obstacle, then
//! backs up while turning for a short time.
//!
//! Section 4.3.2: "By default hexbugs move forward until either of their
//! antenna touches to an obstacle (i.e. our short wall at the perimeter of
//! the table, another hexbug, the test subject's hand, or our humanoid
//! robot's manipulator). When the toy bumps into an obstacle, it moves
//! backwards while rotating for a short period of time. In this manner, the
//! bugs continuously move around the table unless turned off by the user."
//!
//! The thesis gives no speed, turn rate or size, and no public specification
//! was found (spec `domains.md` §5). The constants of [`HexbugParams::thesis`]
//! are our choices for a toy of that kind (about 1.75" long, walking a few
//! centimetres a second), fixed before any learner ran; the walk is noisy
//! (a random drift of the heading), as vibration-driven toys are. Per tick of
//! `dt` seconds:
//!
//! - forward: `θ ← θ + σ_θ √dt · N(0, 1)`, `p ← p + v dt (cos θ, sin θ)`; if
//!   the antenna tip `p + r_a (cos θ, sin θ)` touches an obstacle, start
//!   backing up for `T_b` seconds, turning left or right (a fair coin);
//! - backing up: `θ ← θ ± ω dt`, `p ← p − v_b dt (cos θ, sin θ)`, kept inside
//!   the walls.

use rand::Rng;
use rlfd_env::random::{bernoulli, standard_normal};
use serde::{Deserialize, Serialize};

/// The bug's motion constants (inches, seconds, radians).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct HexbugParams {
    /// Forward speed `v` (in/s).
    pub speed: f64,
    /// Backing-up speed `v_b` (in/s).
    pub backup_speed: f64,
    /// How long a bump's back-up-and-turn lasts, `T_b` (s).
    pub backup_seconds: f64,
    /// Turn rate while backing up, `ω` (rad/s).
    pub turn_rate: f64,
    /// Heading drift while walking, `σ_θ` (rad/√s).
    pub heading_noise: f64,
    /// Radius of the body for collisions between bugs (in).
    pub body_radius: f64,
    /// Distance from the centre to the antenna tips, `r_a` (in).
    pub antenna_reach: f64,
}

impl HexbugParams {
    /// Our choices (see the module doc): 2 in/s forward, 1 in/s back for 1.5 s turning 90°/s.
    pub const fn thesis() -> HexbugParams {
        HexbugParams {
            speed: 2.0,
            backup_speed: 1.0,
            backup_seconds: 1.5,
            turn_rate: std::f64::consts::FRAC_PI_2,
            heading_noise: 0.5,
            body_radius: 0.45,
            antenna_reach: 1.0,
        }
    }
}

/// What the bug is doing.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Motion {
    /// Walking forward.
    Forward,
    /// Backing up after a bump: ticks left and the turn direction (±1).
    Backing { ticks_left: u32, turn: f64 },
}

/// One hexbug on (or off) the table.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Hexbug {
    /// Position on the table (inches from the left and far walls).
    pub x: f64,
    pub y: f64,
    /// Heading (radians, table frame).
    pub heading: f64,
    /// Switched on (it moves) or off (it lies still).
    pub on: bool,
    pub motion: Motion,
}

impl Hexbug {
    /// A bug at `(x, y)` facing `heading`, switched on or off.
    pub fn new(x: f64, y: f64, heading: f64, on: bool) -> Hexbug {
        Hexbug { x, y, heading, on, motion: Motion::Forward }
    }

    /// Where the antennae touch, one step ahead.
    pub fn antenna_tip(&self, p: &HexbugParams) -> (f64, f64) {
        (self.x + p.antenna_reach * libm::cos(self.heading), self.y + p.antenna_reach * libm::sin(self.heading))
    }

    /// Starts backing up after a bump, turning one way at random.
    pub fn bump<R: Rng + ?Sized>(&mut self, p: &HexbugParams, dt: f64, rng: &mut R) {
        let ticks = (p.backup_seconds / dt).round() as u32;
        let turn = if bernoulli(rng, 0.5) { 1.0 } else { -1.0 };
        self.motion = Motion::Backing { ticks_left: ticks.max(1), turn };
    }

    /// Moves one tick (if on); `touches(tip)` says whether the antenna tip
    /// is against an obstacle. Returns whether the bug bumped this tick.
    pub fn advance<R: Rng + ?Sized>(
        &mut self,
        p: &HexbugParams,
        dt: f64,
        bounds: (f64, f64),
        touches: impl Fn((f64, f64)) -> bool,
        rng: &mut R,
    ) -> bool {
        if !self.on {
            return false;
        }
        match self.motion {
            Motion::Forward => {
                self.heading += p.heading_noise * dt.sqrt() * standard_normal(rng);
                self.x += p.speed * dt * libm::cos(self.heading);
                self.y += p.speed * dt * libm::sin(self.heading);
                self.keep_inside(p, bounds);
                if touches(self.antenna_tip(p)) {
                    self.bump(p, dt, rng);
                    return true;
                }
            }
            Motion::Backing { ticks_left, turn } => {
                self.heading += turn * p.turn_rate * dt;
                self.x -= p.backup_speed * dt * libm::cos(self.heading);
                self.y -= p.backup_speed * dt * libm::sin(self.heading);
                self.keep_inside(p, bounds);
                self.motion = if ticks_left <= 1 {
                    Motion::Forward
                } else {
                    Motion::Backing { ticks_left: ticks_left - 1, turn }
                };
            }
        }
        false
    }

    fn keep_inside(&mut self, p: &HexbugParams, (w, h): (f64, f64)) {
        let r = p.body_radius;
        self.x = self.x.clamp(r, w - r);
        self.y = self.y.clamp(r, h - r);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_env::random::seeded;

    #[test]
    fn walks_at_its_speed_and_backs_up_on_a_bump() {
        let p = HexbugParams { heading_noise: 0.0, ..HexbugParams::thesis() };
        let mut rng = seeded(1);
        let mut b = Hexbug::new(5.0, 9.5, 0.0, true);
        for _ in 0..10 {
            assert!(!b.advance(&p, 0.1, (25.0, 19.0), |_| false, &mut rng));
        }
        assert!((b.x - 7.0).abs() < 1e-9, "2 in/s for 1 s: {}", b.x);
        // A wall right ahead: it bumps, then backs up for 1.5 s while turning.
        assert!(b.advance(&p, 0.1, (25.0, 19.0), |(x, _)| x > 7.5, &mut rng));
        assert!(matches!(b.motion, Motion::Backing { ticks_left: 15, .. }));
        let before = b.x;
        for _ in 0..15 {
            b.advance(&p, 0.1, (25.0, 19.0), |_| false, &mut rng);
        }
        assert_eq!(b.motion, Motion::Forward);
        assert!(b.x < before, "it moved backwards");
        assert!((b.heading.abs() - 1.5 * std::f64::consts::FRAC_PI_2).abs() < 1e-9, "turned 135°: {}", b.heading);
    }

    #[test]
    fn a_bug_switched_off_stays_put_and_walls_hold() {
        let p = HexbugParams::thesis();
        let mut rng = seeded(2);
        let mut off = Hexbug::new(3.0, 3.0, 1.0, false);
        off.advance(&p, 0.1, (25.0, 19.0), |_| false, &mut rng);
        assert_eq!((off.x, off.y), (3.0, 3.0));
        let mut b = Hexbug::new(0.5, 0.5, std::f64::consts::PI, true);
        for _ in 0..100 {
            b.advance(&p, 0.1, (25.0, 19.0), |_| false, &mut rng);
            assert!(b.x >= p.body_radius && b.x <= 25.0 - p.body_radius);
            assert!(b.y >= p.body_radius && b.y <= 19.0 - p.body_radius);
        }
    }
}
