//! The soccer server's physics, as rcssserver before version 12 ran it (the
//! thesis used 11.1.0): the constants, the objects (players and the ball) and
//! one simulation cycle of 100 ms.
//!
//! Per cycle, for every object ([`ServerParams`], `domains.md` 1.2):
//!
//! ```text
//! accel ← accel capped at accel_max
//! vel   ← vel + accel, capped at speed_max
//! vel   ← vel + (U(−r, r), U(−r, r)),  r = rand · |vel|       (pre-v12 noise)
//! pos   ← pos + vel
//! vel   ← decay · vel;  accel ← 0
//! ```
//!
//! Commands set the acceleration before the move: a dash pushes the player
//! along its body by `power · dash_power_rate`; a turn rotates the body by
//! `moment · (1 + U(−player_rand, player_rand)) / (1 + inertia_moment · |vel|)`
//! at once; a kick of a ball within the kickable area pushes the ball by
//! `power · kick_power_rate · (1 − 0.25 · dir_diff/180° − 0.25 · dist_ball/kickable_margin)`,
//! `dir_diff` being the ball's angle off the body and `dist_ball` the gap
//! between the player's and the ball's edges.
//!
//! What it is not: no stamina (keepaway.sh gives effectively unlimited
//! stamina, so effort stays 1), no collisions between objects (a
//! documented deviation), no vision, no noise on kicks (`kick_rand` = 0
//! before version 12).

use rand::Rng;
use rlfd_rl::random::uniform01;
use serde::{Deserialize, Serialize};

use super::geometry::Vec2;

/// The server's constants (rcssserver defaults before version 12, `domains.md` 1.2).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ServerParams {
    /// The ball's velocity decay per cycle.
    pub ball_decay: f64,
    /// The ball's motion noise factor.
    pub ball_rand: f64,
    /// The ball's radius (m).
    pub ball_size: f64,
    /// The ball's speed cap (m/cycle).
    pub ball_speed_max: f64,
    /// The ball's acceleration cap per cycle.
    pub ball_accel_max: f64,
    /// A player's velocity decay per cycle.
    pub player_decay: f64,
    /// A player's motion noise factor (also the turn noise).
    pub player_rand: f64,
    /// A player's radius (m).
    pub player_size: f64,
    /// A player's speed cap (m/cycle).
    pub player_speed_max: f64,
    /// A player's acceleration cap per cycle.
    pub player_accel_max: f64,
    /// Acceleration per unit of dash power.
    pub dash_power_rate: f64,
    /// Acceleration per unit of kick power (before the direction and distance penalties).
    pub kick_power_rate: f64,
    /// Reach beyond the player's body within which the ball can be kicked (m).
    pub kickable_margin: f64,
    /// How much a player's speed damps its turns.
    pub inertia_moment: f64,
    /// The largest dash and kick power.
    pub max_power: f64,
}

impl ServerParams {
    /// rcssserver 11.1.0's defaults, the thesis's server.
    pub const fn rcssserver_11() -> Self {
        ServerParams {
            ball_decay: 0.94,
            ball_rand: 0.05,
            ball_size: 0.085,
            ball_speed_max: 2.7,
            ball_accel_max: 2.7,
            player_decay: 0.4,
            player_rand: 0.1,
            player_size: 0.3,
            player_speed_max: 1.2,
            player_accel_max: 1.0,
            dash_power_rate: 0.006,
            kick_power_rate: 0.027,
            kickable_margin: 0.7,
            inertia_moment: 5.0,
            max_power: 100.0,
        }
    }

    /// The distance between a player's and the ball's centres within which
    /// the ball is kickable: `kickable_margin + player_size + ball_size` = 1.085 m.
    #[inline]
    pub fn kickable_area(&self) -> f64 {
        self.kickable_margin + self.player_size + self.ball_size
    }

    /// The acceleration one unit of kick power gives a ball at `ball` for a
    /// player at `player` facing `dir` (unit vector): the kick power rate
    /// with the server's direction and distance penalties.
    #[inline]
    pub fn actual_kick_power_rate(&self, player: Vec2, dir: Vec2, ball: Vec2) -> f64 {
        let rel = ball - player;
        let dir_diff = super::geometry::angle_between(dir, rel);
        let dist_ball = rel.norm() - self.player_size - self.ball_size;
        self.kick_power_rate
            * (1.0 - 0.25 * dir_diff / std::f64::consts::PI - 0.25 * dist_ball.max(0.0) / self.kickable_margin)
    }
}

/// A player: position, velocity, body direction and this cycle's acceleration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Body {
    /// Position (m).
    pub pos: Vec2,
    /// Velocity (m/cycle).
    pub vel: Vec2,
    /// Body direction, radians.
    pub angle: f64,
    /// The unit vector of `angle` (kept in step with it).
    pub dir: Vec2,
    /// Acceleration to apply at the next move.
    pub accel: Vec2,
}

impl Body {
    /// A player at rest at `pos` facing `angle`.
    pub fn at(pos: Vec2, angle: f64) -> Body {
        Body { pos, vel: Vec2::ZERO, angle, dir: Vec2::from_angle(angle), accel: Vec2::ZERO }
    }

    /// Sets the body direction.
    #[inline]
    pub fn set_angle(&mut self, angle: f64) {
        self.angle = super::geometry::normalize_angle(angle);
        self.dir = Vec2::from_angle(self.angle);
    }
}

/// The ball: position, velocity and this cycle's acceleration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Ball {
    /// Position (m).
    pub pos: Vec2,
    /// Velocity (m/cycle).
    pub vel: Vec2,
    /// Acceleration to apply at the next move (the sum of this cycle's kicks).
    pub accel: Vec2,
}

/// A player's command for one cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Command {
    /// Nothing this cycle.
    Idle,
    /// Accelerate along the body (negative power: backwards); power in `[-100, 100]`.
    Dash {
        /// Dash power.
        power: f64,
    },
    /// Turn the body by `moment` radians (before noise and inertia), in `[-π, π]`.
    Turn {
        /// Requested turn.
        moment: f64,
    },
    /// Kick the ball in the global direction `dir` (a unit vector) with `power` in `[0, 100]`.
    Kick {
        /// Kick power.
        power: f64,
        /// Global kick direction.
        dir: Vec2,
    },
}

/// Executes `cmd` for `body`: sets its acceleration (dash), turns it, or
/// pushes the ball (kick). One uniform draw for a turn, none otherwise.
#[inline]
pub fn execute<R: Rng + ?Sized>(p: &ServerParams, body: &mut Body, ball: &mut Ball, cmd: Command, rng: &mut R) {
    match cmd {
        Command::Idle => {}
        Command::Dash { power } => {
            let power = power.clamp(-p.max_power, p.max_power);
            body.accel += body.dir * (power * p.dash_power_rate);
        }
        Command::Turn { moment } => {
            let moment = moment.clamp(-std::f64::consts::PI, std::f64::consts::PI);
            let noise = 1.0 + p.player_rand * (2.0 * uniform01(rng) - 1.0);
            let actual = moment * noise / (1.0 + p.inertia_moment * body.vel.norm());
            body.set_angle(body.angle + actual);
        }
        Command::Kick { power, dir } => {
            let ka = p.kickable_area();
            if body.pos.dist2(ball.pos) <= ka * ka {
                let power = power.clamp(0.0, p.max_power);
                let rate = p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
                ball.accel += dir * (power * rate);
            }
        }
    }
}

/// How one kind of object moves: its caps, noise and decay.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Acceleration cap per cycle.
    pub accel_max: f64,
    /// Speed cap (m/cycle).
    pub speed_max: f64,
    /// Noise factor.
    pub rand: f64,
    /// Velocity decay per cycle.
    pub decay: f64,
}

impl ServerParams {
    /// How players move.
    #[inline]
    pub fn player_motion(&self) -> Motion {
        Motion {
            accel_max: self.player_accel_max,
            speed_max: self.player_speed_max,
            rand: self.player_rand,
            decay: self.player_decay,
        }
    }

    /// How the ball moves.
    #[inline]
    pub fn ball_motion(&self) -> Motion {
        Motion {
            accel_max: self.ball_accel_max,
            speed_max: self.ball_speed_max,
            rand: self.ball_rand,
            decay: self.ball_decay,
        }
    }
}

/// 2⁻³²: turns a 32-bit integer into a uniform in `[0, 1)`.
const TWO_POW_M32: f64 = 1.0 / 4_294_967_296.0;

/// Moves one object one cycle (see the module docs). One 64-bit draw.
#[inline]
pub fn advance<R: Rng + ?Sized>(m: Motion, pos: &mut Vec2, vel: &mut Vec2, accel: &mut Vec2, rng: &mut R) {
    if accel.x != 0.0 || accel.y != 0.0 {
        let a2 = accel.norm2();
        if a2 > m.accel_max * m.accel_max {
            *accel = *accel * (m.accel_max / a2.sqrt());
        }
        *vel += *accel;
        let v2 = vel.norm2();
        if v2 > m.speed_max * m.speed_max {
            *vel = *vel * (m.speed_max / v2.sqrt());
        }
    }
    // Both noise components from one 64-bit draw (32 bits each: ample for a
    // ±5–10 % perturbation, and half the generator's work).
    let r = m.rand * vel.norm();
    let bits = rng.next_u64();
    let (u, v) = ((bits >> 32) as f64 * TWO_POW_M32, (bits & 0xffff_ffff) as f64 * TWO_POW_M32);
    let nx = r * (2.0 * u - 1.0);
    let ny = r * (2.0 * v - 1.0);
    vel.x += nx;
    vel.y += ny;
    *pos += *vel;
    *vel = *vel * m.decay;
    *accel = Vec2::ZERO;
}

/// Moves a player one cycle.
#[inline]
pub fn advance_player<R: Rng + ?Sized>(p: &ServerParams, body: &mut Body, rng: &mut R) {
    advance(p.player_motion(), &mut body.pos, &mut body.vel, &mut body.accel, rng);
}

/// Moves the ball one cycle.
#[inline]
pub fn advance_ball<R: Rng + ?Sized>(p: &ServerParams, ball: &mut Ball, rng: &mut R) {
    advance(p.ball_motion(), &mut ball.pos, &mut ball.vel, &mut ball.accel, rng);
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    const P: ServerParams = ServerParams::rcssserver_11();

    #[test]
    fn kickable_area_is_1_085() {
        assert!((P.kickable_area() - 1.085).abs() < 1e-12);
    }

    #[test]
    fn full_dashes_approach_one_metre_per_cycle() {
        // v = 0.6 / (1 − 0.4) = 1.0 m/cycle: the speed cap of 1.2 never binds.
        // Averaged over 200 runs, the motion noise (±10 % per component) cancels.
        let mut rng = seeded(1);
        let (mut first, mut late) = (0.0, 0.0);
        for _ in 0..200 {
            let mut body = Body::at(Vec2::ZERO, 0.0);
            let mut ball = Ball::default();
            for t in 0..30 {
                let before = body.pos;
                execute(&P, &mut body, &mut ball, Command::Dash { power: 100.0 }, &mut rng);
                advance_player(&P, &mut body, &mut rng);
                let step = body.pos.x - before.x;
                if t == 0 {
                    first += step / 200.0;
                } else if t >= 20 {
                    late += step / 2000.0;
                }
            }
        }
        assert!((first - 0.6).abs() < 0.01, "{first}");
        assert!((late - 1.0).abs() < 0.01, "{late}");
    }

    #[test]
    fn a_ball_decays_geometrically_and_travels_v0_over_0_06() {
        // 2.0 / (1 − 0.94) = 33.3 m on average; the noise, added to a velocity
        // that persists, spreads single rolls by metres.
        let mut rng = seeded(2);
        let (mut x, mut y) = (0.0, 0.0);
        for _ in 0..200 {
            let mut ball = Ball { pos: Vec2::ZERO, vel: Vec2::new(2.0, 0.0), accel: Vec2::ZERO };
            for _ in 0..400 {
                advance_ball(&P, &mut ball, &mut rng);
            }
            assert!(ball.vel.norm() < 1e-9);
            x += ball.pos.x / 200.0;
            y += ball.pos.y / 200.0;
        }
        assert!((x - 33.33).abs() < 0.5, "{x}");
        assert!(y.abs() < 0.6, "{y}");
    }

    #[test]
    fn kicks_are_penalised_by_angle_and_distance_and_need_the_ball_kickable() {
        let body = Body::at(Vec2::ZERO, 0.0);
        // Ball touching the body, straight ahead: full rate.
        let touching = Vec2::new(P.player_size + P.ball_size, 0.0);
        assert!((P.actual_kick_power_rate(body.pos, body.dir, touching) - 0.027).abs() < 1e-15);
        // Behind at the edge of the kickable area: 0.027 · (1 − 0.25 − 0.25) = 0.0135.
        let behind = Vec2::new(-P.kickable_area(), 0.0);
        assert!((P.actual_kick_power_rate(body.pos, body.dir, behind) - 0.0135).abs() < 1e-12);
        let mut rng = seeded(3);
        let mut b = body;
        let mut ball = Ball { pos: touching, ..Ball::default() };
        execute(&P, &mut b, &mut ball, Command::Kick { power: 100.0, dir: Vec2::new(1.0, 0.0) }, &mut rng);
        assert!((ball.accel.x - 2.7).abs() < 1e-12);
        let mut far = Ball { pos: Vec2::new(2.0, 0.0), ..Ball::default() };
        execute(&P, &mut b, &mut far, Command::Kick { power: 100.0, dir: Vec2::new(1.0, 0.0) }, &mut rng);
        assert_eq!(far.accel, Vec2::ZERO);
    }

    #[test]
    fn turns_are_damped_by_speed() {
        let mut rng = seeded(4);
        let mut ball = Ball::default();
        let mut still = Body::at(Vec2::ZERO, 0.0);
        execute(&P, &mut still, &mut ball, Command::Turn { moment: 1.0 }, &mut rng);
        assert!((still.angle - 1.0).abs() <= 0.1 + 1e-12);
        let mut moving = Body { vel: Vec2::new(1.0, 0.0), ..Body::at(Vec2::ZERO, 0.0) };
        execute(&P, &mut moving, &mut ball, Command::Turn { moment: 1.2 }, &mut rng);
        assert!((moving.angle - 0.2).abs() <= 0.02 + 1e-12, "{}", moving.angle);
        assert!((moving.dir.angle() - moving.angle).abs() < 1e-12);
    }
}
