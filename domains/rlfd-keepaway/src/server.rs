//! The soccer server's physics, as rcssserver 11.1 runs it (the thesis
//! used 11.1.0; the oracle, `rcsoccersim/rcssserver` at 11.1.2): the
//! constants, the objects (players and the ball), the commands as the
//! server receives them, one cycle of motion and the collisions.
//!
//! Per cycle, for every object (`MPObject::_inc` in `object.C`):
//!
//! ```text
//! accel ← accel capped at accel_max            (only when accel ≠ 0)
//! vel   ← vel + accel, capped at speed_max
//! vel   ← vel + (U(−r, r), U(−r, r)),  r = rand · |vel|       (after the cap)
//! pos   ← pos + vel
//! vel   ← decay · vel;  accel ← 0
//! ```
//!
//! then the collisions (`Stadium::collisions` in `field.C`): every ball–player
//! pair closer than `ball_size + player_size` and every player pair closer
//! than `2 · player_size` is moved apart along the line of their centres, each
//! object to the mean of the positions its collisions give it (the midpoint
//! rule, `calcCollPos`), repeated until nothing overlaps or ten times; every
//! object that collided then has its velocity multiplied by −0.1.
//!
//! Commands act at once, in the cycle they are sent (`player.cc`): a dash
//! pushes the player along its body by `power · dash_power_rate`; a turn
//! rotates the body by `moment · (1 + U(−player_rand, player_rand)) / (1 +
//! inertia_moment · |vel|)`; a kick of a ball within the kickable area pushes
//! the ball by `power · kick_power_rate · (1 − 0.25 · dir_diff/180° − 0.25 ·
//! dist_ball/kickable_margin)` toward `body + dir`, `dir_diff` being the
//! ball's angle off the body and `dist_ball` the gap between the player's and
//! the ball's edges. The keepaway players print every argument with `%d`
//! (`SoccerCommand::make*Command`), so the server receives dash powers, kick
//! powers and directions and turn moments truncated to whole numbers, and an
//! argument out of range makes a dash or turn of 0 or drops the kick
//! ([`Command::as_sent`]).
//!
//! What it is not: no stamina (keepaway.sh's `stamina_inc_max` 3500 makes it
//! unlimited, so effort stays 1), no wind (`wind_force` 0), no kick noise
//! (`kick_rand` 0 for the default player type 0).

use rand::Rng;
use rlfd_env::random::uniform01;
use serde::{Deserialize, Serialize};

use super::geometry::{RAD_PER_DEG, Vec2, unit_deg};

/// The server's constants (`server_param`/`player_param`/`player_type 0` as
/// rcssserver 11.1.2 sends them to the players; `keepaway-oracle.md`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ServerParams {
    /// The ball's velocity decay per cycle (`ball_decay`).
    pub ball_decay: f64,
    /// The ball's motion noise factor (`ball_rand`).
    pub ball_rand: f64,
    /// The ball's radius, m (`ball_size`).
    pub ball_size: f64,
    /// The ball's speed cap, m/cycle (`ball_speed_max`).
    pub ball_speed_max: f64,
    /// The ball's acceleration cap per cycle (`ball_accel_max`).
    pub ball_accel_max: f64,
    /// A player's velocity decay per cycle (`player_decay`).
    pub player_decay: f64,
    /// A player's motion noise factor, also the turn noise (`player_rand`).
    pub player_rand: f64,
    /// A player's radius, m (`player_size`).
    pub player_size: f64,
    /// A player's speed cap, m/cycle (`player_speed_max`).
    pub player_speed_max: f64,
    /// A player's acceleration cap per cycle (`player_accel_max`).
    pub player_accel_max: f64,
    /// Acceleration per unit of dash power (`dash_power_rate`).
    pub dash_power_rate: f64,
    /// Acceleration per unit of kick power before the penalties (`kick_power_rate`).
    pub kick_power_rate: f64,
    /// Reach beyond the player's body within which the ball can be kicked, m (`kickable_margin`).
    pub kickable_margin: f64,
    /// How much a player's speed damps its turns (`inertia_moment`).
    pub inertia_moment: f64,
    /// The largest dash and kick power (`maxpower`; the smallest is its negative).
    pub max_power: f64,
    /// The largest turn moment, degrees (`maxmoment`; the smallest is its negative).
    pub max_moment: f64,
}

impl ServerParams {
    /// rcssserver 11.1's defaults, the thesis's server.
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
            max_moment: 180.0,
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
        self.kick_power_rate * (1.0 - 0.25 * dir_diff / std::f64::consts::PI - 0.25 * dist_ball / self.kickable_margin)
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

/// A player's command for one cycle, in the server's units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Command {
    /// Nothing this cycle.
    Idle,
    /// Accelerate along the body (negative power: backwards).
    Dash {
        /// Dash power, in `[-max_power, max_power]`.
        power: f64,
    },
    /// Turn the body.
    Turn {
        /// Requested turn, degrees, in `[-max_moment, max_moment]`.
        moment: f64,
    },
    /// Kick the ball.
    Kick {
        /// Kick power, in `[-max_power, max_power]`.
        power: f64,
        /// Direction relative to the body, degrees, in `[-max_moment, max_moment]`.
        dir: f64,
    },
}

impl Command {
    /// The command as the keepaway players send it: every argument printed
    /// with `%d` (truncated toward zero); a dash or turn out of range is sent
    /// as 0 and a kick out of range is not sent (`SoccerCommand::make*Command`).
    #[inline]
    pub fn as_sent(self, p: &ServerParams) -> Command {
        match self {
            Command::Idle => Command::Idle,
            Command::Dash { power } => {
                Command::Dash { power: if power.abs() <= p.max_power { power.trunc() } else { 0.0 } }
            }
            Command::Turn { moment } => {
                Command::Turn { moment: if moment.abs() <= p.max_moment { moment.trunc() } else { 0.0 } }
            }
            Command::Kick { power, dir } => {
                if power.abs() <= p.max_power && dir.abs() <= p.max_moment {
                    Command::Kick { power: power.trunc(), dir: dir.trunc() }
                } else {
                    Command::Idle
                }
            }
        }
    }
}

/// Executes `cmd` (as sent) for `body`: sets its acceleration (dash), turns
/// it (one uniform draw), or pushes the ball (kick). Returns whether a kick
/// reached the ball.
#[inline]
pub fn execute<R: Rng + ?Sized>(p: &ServerParams, body: &mut Body, ball: &mut Ball, cmd: Command, rng: &mut R) -> bool {
    match cmd {
        Command::Idle => false,
        Command::Dash { power } => {
            body.accel += body.dir * (power * p.dash_power_rate);
            false
        }
        Command::Turn { moment } => {
            let noise = 1.0 + p.player_rand * (2.0 * uniform01(rng) - 1.0);
            let actual = moment * RAD_PER_DEG * noise / (1.0 + p.inertia_moment * body.vel.norm());
            body.set_angle(body.angle + actual);
            false
        }
        Command::Kick { power, dir } => {
            let ka = p.kickable_area();
            if body.pos.dist2(ball.pos) > ka * ka {
                return false;
            }
            let rate = p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
            ball.accel += body.dir.rotate(unit_deg(dir as i32)) * (power * rate);
            true
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
    vel.x += r * (2.0 * u - 1.0);
    vel.y += r * (2.0 * v - 1.0);
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

/// The server's `EPS` (`utility.h`): the extra gap collisions leave.
const EPS: f64 = 1.0e-10;

/// The most collision passes per cycle (`Stadium::collisions`' `max_loop`).
const MAX_COLLISION_PASSES: usize = 10;

/// The most players collisions handle.
pub const MAX_PLAYERS: usize = 10;

/// Where the midpoint rule puts two overlapping objects at `a` and `b` whose
/// radii sum to `sum` (`Stadium::calcCollPos`): each `sum/2 + EPS` from
/// their midpoint along the line of centres (a random line when they
/// coincide, one draw), pushed apart by 0.01 % steps until they no longer overlap.
fn separate<R: Rng + ?Sized>(a: Vec2, b: Vec2, sum: f64, rng: &mut R) -> (Vec2, Vec2) {
    let mid = (a + b) * 0.5;
    let half = 0.5 * sum + EPS;
    let (mut ma, mut mb) = (a - mid, b - mid);
    if a == b || (ma.norm() < EPS && mb.norm() < EPS) {
        let u = Vec2::from_angle(std::f64::consts::PI * (2.0 * uniform01(rng) - 1.0));
        ma = u * half;
        mb = -ma;
    } else {
        ma = ma.with_norm(half);
        mb = mb.with_norm(half);
    }
    let mut count = 0;
    while (mid + ma).dist(mid + mb) < sum && count < 10 {
        ma = ma * 1.0001;
        mb = mb * 1.0001;
        count += 1;
    }
    (mid + ma, mid + mb)
}

/// The server's collision step over the ball and `players` (keepers first,
/// then takers, as `Stadium::players` lists them); see the module docs.
/// Returns whether anything collided.
pub fn collisions<R: Rng + ?Sized>(p: &ServerParams, ball: &mut Ball, players: &mut [Body], rng: &mut R) -> bool {
    let n = players.len().min(MAX_PLAYERS);
    let ball_gap = p.ball_size + p.player_size;
    let player_gap = 2.0 * p.player_size;
    let mut collided = [false; MAX_PLAYERS + 1];
    let mut any = false;
    for _ in 0..MAX_COLLISION_PASSES {
        let mut sum = [Vec2::ZERO; MAX_PLAYERS + 1];
        let mut count = [0u32; MAX_PLAYERS + 1];
        let mut col = false;
        for i in 0..n {
            if ball.pos.dist2(players[i].pos) < ball_gap * ball_gap {
                let (b, q) = separate(ball.pos, players[i].pos, ball_gap, rng);
                sum[MAX_PLAYERS] += b;
                count[MAX_PLAYERS] += 1;
                sum[i] += q;
                count[i] += 1;
                col = true;
            }
        }
        for i in 0..n.saturating_sub(1) {
            for j in i + 1..n {
                if players[i].pos.dist2(players[j].pos) < player_gap * player_gap {
                    let (a, b) = separate(players[i].pos, players[j].pos, player_gap, rng);
                    sum[i] += a;
                    count[i] += 1;
                    sum[j] += b;
                    count[j] += 1;
                    col = true;
                }
            }
        }
        if count[MAX_PLAYERS] > 0 {
            ball.pos = sum[MAX_PLAYERS] * (1.0 / f64::from(count[MAX_PLAYERS]));
            collided[MAX_PLAYERS] = true;
        }
        for i in 0..n {
            if count[i] > 0 {
                players[i].pos = sum[i] * (1.0 / f64::from(count[i]));
                collided[i] = true;
            }
        }
        any |= col;
        if !col {
            break;
        }
    }
    if collided[MAX_PLAYERS] {
        ball.vel = ball.vel * -0.1;
    }
    for i in 0..n {
        if collided[i] {
            players[i].vel = players[i].vel * -0.1;
        }
    }
    any
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_env::random::seeded;

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
        assert!(execute(&P, &mut b, &mut ball, Command::Kick { power: 100.0, dir: 0.0 }, &mut rng));
        assert!((ball.accel.x - 2.7).abs() < 1e-12);
        // 90° to the left of the body.
        let mut side = Ball { pos: touching, ..Ball::default() };
        execute(&P, &mut b, &mut side, Command::Kick { power: 10.0, dir: 90.0 }, &mut rng);
        assert!(side.accel.x.abs() < 1e-12 && (side.accel.y - 0.27).abs() < 1e-12);
        let mut far = Ball { pos: Vec2::new(2.0, 0.0), ..Ball::default() };
        assert!(!execute(&P, &mut b, &mut far, Command::Kick { power: 100.0, dir: 0.0 }, &mut rng));
        assert_eq!(far.accel, Vec2::ZERO);
    }

    #[test]
    fn commands_are_sent_as_whole_numbers() {
        assert_eq!(Command::Dash { power: 67.9 }.as_sent(&P), Command::Dash { power: 67.0 });
        assert_eq!(Command::Dash { power: -0.7 }.as_sent(&P), Command::Dash { power: 0.0 });
        assert_eq!(Command::Dash { power: 130.0 }.as_sent(&P), Command::Dash { power: 0.0 });
        assert_eq!(Command::Turn { moment: -41.8 }.as_sent(&P), Command::Turn { moment: -41.0 });
        assert_eq!(Command::Kick { power: 0.9, dir: 12.5 }.as_sent(&P), Command::Kick { power: 0.0, dir: 12.0 });
        assert_eq!(Command::Kick { power: 101.0, dir: 0.0 }.as_sent(&P), Command::Idle);
    }

    #[test]
    fn turns_are_damped_by_speed() {
        let mut rng = seeded(4);
        let mut ball = Ball::default();
        let mut still = Body::at(Vec2::ZERO, 0.0);
        execute(&P, &mut still, &mut ball, Command::Turn { moment: 57.0 }, &mut rng);
        assert!((still.angle - 57.0 * RAD_PER_DEG).abs() <= 5.7 * RAD_PER_DEG + 1e-12);
        let mut moving = Body { vel: Vec2::new(1.0, 0.0), ..Body::at(Vec2::ZERO, 0.0) };
        execute(&P, &mut moving, &mut ball, Command::Turn { moment: 60.0 }, &mut rng);
        assert!((moving.angle - 10.0 * RAD_PER_DEG).abs() <= 1.0 * RAD_PER_DEG + 1e-12, "{}", moving.angle);
        assert!((moving.dir.angle() - moving.angle).abs() < 1e-12);
    }

    #[test]
    fn collisions_separate_by_the_midpoint_rule_and_bounce() {
        let mut rng = seeded(5);
        // Two players 0.4 m apart: each moves 0.1 m out, velocities × −0.1.
        let mut players = [Body::at(Vec2::new(0.0, 0.0), 0.0), Body::at(Vec2::new(0.4, 0.0), 0.0)];
        players[0].vel = Vec2::new(0.5, 0.0);
        let mut ball = Ball { pos: Vec2::new(5.0, 5.0), ..Ball::default() };
        assert!(collisions(&P, &mut ball, &mut players, &mut rng));
        assert!((players[0].pos.x + 0.1).abs() < 1e-6 && (players[1].pos.x - 0.5).abs() < 1e-6);
        assert!((players[1].pos.x - players[0].pos.x) >= 0.6);
        assert!((players[0].vel.x + 0.05).abs() < 1e-12);
        // The ball inside a player: both pushed apart to 0.385 m.
        let mut one = [Body::at(Vec2::ZERO, 0.0)];
        let mut inside = Ball { pos: Vec2::new(0.2, 0.0), vel: Vec2::new(-1.0, 0.0), accel: Vec2::ZERO };
        collisions(&P, &mut inside, &mut one, &mut rng);
        assert!((inside.pos.dist(one[0].pos) - 0.385).abs() < 1e-6);
        assert!((inside.vel.x - 0.1).abs() < 1e-12);
        // Nothing overlapping: nothing moves.
        let mut apart = [Body::at(Vec2::ZERO, 0.0), Body::at(Vec2::new(1.0, 0.0), 0.0)];
        let mut free = Ball { pos: Vec2::new(5.0, 0.0), ..Ball::default() };
        assert!(!collisions(&P, &mut free, &mut apart, &mut rng));
        assert_eq!(apart[1].pos, Vec2::new(1.0, 0.0));
    }
}
