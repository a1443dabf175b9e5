//! The players' skills: the commands the UT-Austin keepaway players (v0.6,
//! built on UvA Trilearn's `BasicPlayer` and `WorldModel`) send for turning,
//! moving, intercepting and kicking, re-implemented from the algorithms of
//! `tjpalmer/keepaway:player/BasicPlayer.cc`, `WorldModelPredict.cc` and
//! `WorldModelHighLevel.cc` (read for the rules, not copied).
//!
//! Every skill decides from a noise-free prediction of the server's physics
//! (the players' own model: no motion noise, commands with real-valued
//! arguments) and returns a [`Command`] the server then receives with its
//! arguments truncated ([`Command::as_sent`]).
//!
//! - **Turning and moving**: [`turn_body_to_point`] aims the body at a point
//!   seen from where the player drifts to; [`dash_to_point`] asks for the
//!   speed that covers the distance along the body in the given number of
//!   cycles (a geometric series with the player's decay, capped at the
//!   top speed); [`move_to_pos`] dashes when the point lies within
//!   `when_to_turn` of the body (seen from where the player comes to rest),
//!   otherwise turns, or brakes when three or more turns would be needed
//!   (`directTowards`).
//! - **Intercepting** ([`Interceptor::intercept`]): for each future cycle
//!   `i` of the ball's path the player simulates moving to the ball's
//!   position then (turning while the point lies off its body line by more
//!   than 0.9, 2 or 3 kickable areas for points within 10, 20 or more metres,
//!   or behind it more than 2.5 m away, then dashing to arrive in the
//!   remaining cycles), and takes the first cycle at which it would be within
//!   the kickable area, unless a cycle close to last cycle's interception
//!   point keeps it consistent. Within three cycles it uses the close
//!   interception ([`intercept_close`]); when the point is within 0.5 m of
//!   where it drifts to, it **does not move** and turns to face forward; else it
//!   moves there to arrive in that many cycles.
//! - **Kicking**: [`kick_ball_close_to_body`], [`freeze_ball`],
//!   [`accelerate_ball_to_velocity`], [`kick_to`] (a pass that reaches the
//!   target at `end_speed`: the first speed `end_speed · (1/0.94)ⁿ` for the
//!   whole number of cycles `n` the geometric series needs) and
//!   [`hold_ball`] (the ball kept `ratio · kickable_margin` beyond the body,
//!   at 45° away from an opponent within 5 m of the ball).
//!
//! "Forward" is +x in each team's own frame: the keepers' (left team) +x and
//! the takers' (right team, whose coordinates the server mirrors) −x.
//!
//! What it is not: the player's own simulation of its movement while
//! intercepting is computed in closed form (turns one at a time, then the
//! dashes' exact arrival or their full-power reach), and the rare "turn
//! the back to the point" branch of `predictCommandTurnTowards` is left out;
//! both listed as deviations in the report.

use super::geometry::{RAD_PER_DEG, Vec2, normalize_angle, signed_angle};
use super::server::{Ball, Body, Command, ServerParams};

/// How far ahead interceptions are planned (`player_when_to_intercept`, 30 in `PlayerSettings.cc`).
pub const INTERCEPT_HORIZON: usize = 30;

/// The angle within which a keeper dashes toward its GetOpen point
/// (`player_when_to_turn`, 7° in `PlayerSettings.cc`).
pub const WHEN_TO_TURN_DEG: f64 = 7.0;

/// A kick ratio for repositioning the ball close to the body (`kickBallCloseToBody`'s default 0.16).
pub const CLOSE_TO_BODY_RATIO: f64 = 0.16;

/// `player_when_to_kick` (0.85 in `PlayerSettings.cc`): how much of the best
/// kick a too-long pass must still reach to be kicked at once.
pub const WHEN_TO_KICK: f64 = 0.85;

/// Distance from the ball within which an opponent makes the holder kick the ball to its side (m).
pub const HOLD_OPPONENT_RANGE: f64 = 5.0;

/// Within this distance of the interception point a player does not move (m).
pub const ALREADY_CLOSE: f64 = 0.5;

/// Largest number of cycles the tables cover.
const TABLE: usize = 64;

/// Noise-free kinematics of the server's players and ball, tabulated once.
#[derive(Clone, Debug)]
pub struct Kinematics {
    /// The server's constants.
    pub p: ServerParams,
    /// `reach[n]`: metres covered by `n` full dashes from rest.
    reach: [f64; TABLE + 1],
    /// `drift[n] = Σ_{k<n} player_decay^k`: where a velocity alone carries a player in `n` cycles, per unit velocity.
    drift: [f64; TABLE + 1],
    /// `player_decay^n`.
    player_pow: [f64; TABLE + 1],
    /// `(1/ball_decay)^n`, for pass speeds.
    ball_inv_pow: [f64; TABLE + 1],
    /// `ball_decay^n`.
    ball_pow: [f64; TABLE + 1],
    /// `(cos, sin)` of the largest turn at speeds `0, TURN_STEP, 2 TURN_STEP, …`.
    turn_unit: Vec<Vec2>,
}

/// Speed resolution of the turn table (m/cycle).
const TURN_STEP: f64 = 1.0 / 512.0;

/// Speeds the turn table covers (players' speeds stay under 1.2 m/cycle plus noise).
const TURN_SPEEDS: usize = 1024;

impl Kinematics {
    /// The tables of `p`.
    pub fn new(p: &ServerParams) -> Kinematics {
        let mut k = Kinematics {
            p: p.clone(),
            reach: [0.0; TABLE + 1],
            drift: [0.0; TABLE + 1],
            player_pow: [1.0; TABLE + 1],
            ball_inv_pow: [1.0; TABLE + 1],
            ball_pow: [1.0; TABLE + 1],
            turn_unit: (0..=TURN_SPEEDS)
                .map(|i| {
                    let max = p.max_moment * RAD_PER_DEG / (1.0 + p.inertia_moment * i as f64 * TURN_STEP);
                    Vec2::from_angle(max.min(std::f64::consts::PI))
                })
                .collect(),
        };
        let accel = (p.max_power * p.dash_power_rate).min(p.player_accel_max);
        let mut v = 0.0;
        for n in 1..=TABLE {
            v = (v + accel).min(p.player_speed_max);
            k.reach[n] = k.reach[n - 1] + v;
            v *= p.player_decay;
            k.drift[n] = k.drift[n - 1] + k.player_pow[n - 1];
            k.player_pow[n] = k.player_pow[n - 1] * p.player_decay;
            k.ball_inv_pow[n] = k.ball_inv_pow[n - 1] / p.ball_decay;
            k.ball_pow[n] = k.ball_pow[n - 1] * p.ball_decay;
        }
        k
    }

    /// The kickable area (1.085 m).
    #[inline]
    pub fn ka(&self) -> f64 {
        self.p.kickable_area()
    }

    /// Metres covered by `n` full dashes from rest.
    #[inline]
    pub fn reach(&self, n: usize) -> f64 {
        if n <= TABLE { self.reach[n] } else { self.reach[TABLE] + (n - TABLE) as f64 * self.step_limit() }
    }

    /// The distance a full dash adds per cycle in the limit (`accel / (1 − decay)`).
    #[inline]
    fn step_limit(&self) -> f64 {
        self.reach[TABLE] - self.reach[TABLE - 1]
    }

    /// Where a player's velocity alone carries it in `n` cycles, per unit velocity.
    #[inline]
    pub fn drift(&self, n: usize) -> f64 {
        self.drift[n.min(TABLE)]
    }

    /// Where `body` drifts to in `n` cycles without commands.
    #[inline]
    pub fn drift_pos(&self, body: &Body, n: usize) -> Vec2 {
        body.pos + body.vel * self.drift(n)
    }

    /// Where `body` comes to rest without commands (`predictFinalAgentPos`).
    #[inline]
    pub fn final_pos(&self, body: &Body) -> Vec2 {
        body.pos + body.vel * (1.0 / (1.0 - self.p.player_decay))
    }

    /// The first term of the geometric series with ratio `player_decay` and
    /// `n` terms summing to `dist` (`getFirstSpeedFromDist`).
    #[inline]
    fn first_speed(&self, dist: f64, n: usize) -> f64 {
        let n = n.clamp(1, TABLE);
        dist * (1.0 - self.p.player_decay) / (1.0 - self.player_pow[n])
    }

    /// The largest turn (radians) a player moving at `speed` makes in one cycle.
    #[inline]
    pub fn max_turn(&self, speed: f64) -> f64 {
        self.p.max_moment * RAD_PER_DEG / (1.0 + self.p.inertia_moment * speed)
    }

    /// The body direction after the player's model turns `dir` toward the
    /// direction of `rel` at `speed`: exactly onto it when the largest turn at
    /// that speed reaches it, else by the largest turn toward it (no
    /// trigonometry: the largest turn's unit vector is tabulated by speed).
    #[inline]
    pub fn turned_toward(&self, dir: Vec2, rel: Vec2, speed: f64) -> Vec2 {
        let n = rel.norm();
        if n == 0.0 {
            return dir;
        }
        let x = (speed / TURN_STEP).min(TURN_SPEEDS as f64 - 1.0);
        let i = x as usize;
        let f = x - i as f64;
        let (a, b) = (self.turn_unit[i], self.turn_unit[i + 1]);
        let max = Vec2::new(a.x + f * (b.x - a.x), a.y + f * (b.y - a.y));
        let cos = dir.dot(rel) / n;
        if cos >= max.x {
            return rel * (1.0 / n);
        }
        let side = if dir.cross(rel) >= 0.0 { max.y } else { -max.y };
        dir.rotate(Vec2::new(max.x, side)).normalized_or(dir)
    }

    /// The body after the player's model turns it toward `rel` and drifts
    /// one cycle (`predictStateAfterTurn` with the moment of [`Kinematics::moment_for_turn`];
    /// only `dir` is kept up to date, not `angle`).
    #[inline]
    pub fn after_turn_toward(&self, body: &Body, rel: Vec2) -> Body {
        let mut b = *body;
        b.dir = self.turned_toward(body.dir, rel, body.vel.norm());
        b.pos += b.vel;
        b.vel = b.vel * self.p.player_decay;
        b
    }

    /// The moment (degrees) to send for an actual turn of `angle` radians
    /// at `speed` (`getAngleForTurn`: scaled up for the inertia, capped).
    #[inline]
    pub fn moment_for_turn(&self, angle: f64, speed: f64) -> f64 {
        (angle / RAD_PER_DEG * (1.0 + self.p.inertia_moment * speed)).clamp(-self.p.max_moment, self.p.max_moment)
    }

    /// The body after a turn of `moment` degrees and one cycle of drift
    /// (`predictStateAfterTurn`).
    #[inline]
    pub fn after_turn(&self, body: &Body, moment: f64) -> Body {
        let mut b = *body;
        let actual = moment * RAD_PER_DEG / (1.0 + self.p.inertia_moment * body.vel.norm());
        b.set_angle(body.angle + actual);
        b.pos += b.vel;
        b.vel = b.vel * self.p.player_decay;
        b
    }

    /// The body after a dash of `power` and one cycle (`predictStateAfterDash`).
    #[inline]
    pub fn after_dash(&self, body: &Body, power: f64) -> Body {
        let mut b = *body;
        b.vel += body.dir * (power * self.p.dash_power_rate);
        let v2 = b.vel.norm2();
        if v2 > self.p.player_speed_max * self.p.player_speed_max {
            b.vel = b.vel * (self.p.player_speed_max / v2.sqrt());
        }
        b.pos += b.vel;
        b.vel = b.vel * self.p.player_decay;
        b
    }

    /// The body one cycle after `cmd` (noise-free; kicks and idling drift).
    #[inline]
    pub fn after(&self, body: &Body, cmd: Command) -> Body {
        match cmd {
            Command::Turn { moment } => self.after_turn(body, moment),
            Command::Dash { power } => self.after_dash(body, power),
            _ => self.after_dash(body, 0.0),
        }
    }

    /// The dash power that brings `body` to `target` along its body in
    /// `cycles` cycles (`getPowerForDash`), in `[-max_power, max_power]`.
    #[inline]
    pub fn power_for_dash(&self, body: &Body, target: Vec2, cycles: usize) -> f64 {
        let along = (target - body.pos).dot(body.dir);
        let speed = self.first_speed(along, cycles).min(self.p.player_speed_max);
        let accel = speed - body.vel.dot(body.dir);
        (accel / self.p.dash_power_rate).clamp(-self.p.max_power, self.p.max_power)
    }

    /// The first speed of a ball that reaches `dist` metres away at
    /// `end_speed` (`getKickSpeedToTravel`): `end_speed · (1/decay)ⁿ` for the
    /// whole number of cycles `n` of the geometric series from the end speed.
    pub fn kick_speed_to_travel(&self, dist: f64, end_speed: f64) -> f64 {
        let decay = self.p.ball_decay;
        if end_speed < 0.0001 {
            return dist * (1.0 - decay);
        }
        let r = 1.0 / decay;
        let temp = dist * (r - 1.0) / end_speed + 1.0;
        let n = if temp <= 0.0 { -1.0 } else { libm::log(temp) / libm::log(r) };
        let k = super::geometry::rint(n);
        if (0.0..=TABLE as f64).contains(&k) {
            end_speed * self.ball_inv_pow[k as usize]
        } else {
            end_speed * libm::pow(r, k)
        }
    }
}

/// The ball's noise-free path over the next [`INTERCEPT_HORIZON`] cycles.
#[derive(Clone, Debug)]
pub struct BallForecast {
    /// `at[n]`: the position after `n` cycles (`at[0]` is now).
    pub at: [Vec2; INTERCEPT_HORIZON + 1],
    /// The ball's velocity now.
    pub vel: Vec2,
    /// Where the ball comes to rest.
    pub rest: Vec2,
}

impl BallForecast {
    /// The forecast of `ball` under `p`'s decay.
    pub fn new(p: &ServerParams, ball: &Ball) -> BallForecast {
        let mut at = [Vec2::ZERO; INTERCEPT_HORIZON + 1];
        let mut pos = ball.pos;
        let mut vel = ball.vel;
        at[0] = pos;
        for slot in at.iter_mut().skip(1) {
            pos += vel;
            vel = vel * p.ball_decay;
            *slot = pos;
        }
        BallForecast { at, vel: ball.vel, rest: ball.pos + ball.vel * (1.0 / (1.0 - p.ball_decay)) }
    }

    /// A ball believed to lie still at `pos`. The players' world model sets
    /// the ball's velocity to zero when an opponent has it within the
    /// kickable area and they do not (`WorldModel::calculateStateBall`): a
    /// ball at an opponent's feet is taken to stay there.
    pub fn still(pos: Vec2) -> BallForecast {
        BallForecast { at: [pos; INTERCEPT_HORIZON + 1], vel: Vec2::ZERO, rest: pos }
    }

    /// The position after `n` cycles (the resting point beyond the horizon).
    #[inline]
    pub fn after(&self, n: usize) -> Vec2 {
        if n <= INTERCEPT_HORIZON { self.at[n] } else { self.rest }
    }

    /// The ball's velocity over cycle `n` (its velocity now for `n = 0`).
    #[inline]
    pub fn vel_at(&self, n: usize) -> Vec2 {
        if n == 0 { self.vel } else { self.after(n) - self.after(n - 1) }
    }
}

/// The signed angle (degrees) from `body`'s direction to `v`.
#[inline]
fn rel_deg(body: &Body, v: Vec2) -> f64 {
    signed_angle(body.dir, v) / RAD_PER_DEG
}

/// A turn toward `target` seen from where the body drifts to in `cycles`
/// cycles, scaled up for the inertia (`turnBodyToPoint`).
#[inline]
pub fn turn_body_to_point(k: &Kinematics, body: &Body, target: Vec2, cycles: usize) -> Command {
    let from = k.drift_pos(body, cycles);
    Command::Turn { moment: k.moment_for_turn(signed_angle(body.dir, target - from), body.vel.norm()) }
}

/// A dash toward `target` along the body, to arrive in `cycles` (`dashToPoint`).
#[inline]
pub fn dash_to_point(k: &Kinematics, body: &Body, target: Vec2, cycles: usize) -> Command {
    Command::Dash { power: k.power_for_dash(body, target, cycles) }
}

/// Turns toward `target`, or brakes when three or more turns would be
/// needed (`directTowards`); the turns are simulated as the player does.
pub fn direct_towards(k: &Kinematics, body: &Body, target: Vec2, cos_when: f64) -> Command {
    let to = target - k.final_pos(body);
    let mut dir = body.dir;
    let mut speed = body.vel.norm();
    let mut turns = 0;
    while turns < 5 && !within(dir, to, cos_when) {
        turns += 1;
        let ang = signed_angle(dir, to);
        let max = k.max_turn(speed);
        let actual = ang.clamp(-max, max);
        dir = if actual == ang { to.normalized_or(dir) } else { dir.rotate(Vec2::from_angle(actual)) };
        speed *= k.p.player_decay;
    }
    match turns {
        0 => Command::Idle,
        1 | 2 => turn_body_to_point(k, body, target, 2),
        _ => dash_to_point(k, body, body.pos, 1),
    }
}

/// Whether `v` lies within the angle whose cosine is `cos_when` of the unit
/// direction `dir` (strictly: `|angle| < when`).
#[inline]
fn within(dir: Vec2, v: Vec2, cos_when: f64) -> bool {
    let along = dir.dot(v);
    along > 0.0 && along * along > cos_when * cos_when * v.norm2()
}

/// Moves to `target` (`moveToPos`): dash when it lies within `when` of the
/// body seen from where the player comes to rest (or, within `dist_back`,
/// of its back), else [`direct_towards`]. `cos_when = cos(when)`.
pub fn move_to_pos(k: &Kinematics, body: &Body, target: Vec2, cos_when: f64, dist_back: f64, cycles: usize) -> Command {
    let to = target - k.final_pos(body);
    if within(body.dir, to, cos_when)
        || (within(-body.dir, to, cos_when) && body.pos.dist2(target) < dist_back * dist_back)
    {
        return dash_to_point(k, body, target, cycles);
    }
    direct_towards(k, body, target, cos_when)
}

/// The turn, if any, the player's model takes first to move to `target` in
/// `cycles` (`predictCommandTurnTowards`): turn while the point lies off the
/// body line through where the player drifts to (in `min(cycles, 4)` cycles)
/// by more than 0.9, 2 or 3 kickable areas (points within 10 m, 20 m,
/// farther), or lies behind that line more than `dist_back` away.
#[inline]
pub fn turn_towards(k: &Kinematics, body: &Body, target: Vec2, cycles: usize, dist_back: f64) -> Option<Command> {
    needs_turn(k, body, target, cycles, dist_back)
        .map(|rel| Command::Turn { moment: k.moment_for_turn(signed_angle(body.dir, rel), body.vel.norm()) })
}

/// [`turn_towards`]'s test: `Some(the direction to turn toward)` when a turn is needed.
#[inline]
fn needs_turn(k: &Kinematics, body: &Body, target: Vec2, cycles: usize, dist_back: f64) -> Option<Vec2> {
    let pp = k.drift_pos(body, cycles.min(4));
    let rel = target - pp;
    let d2 = body.pos.dist2(target);
    let ratio = if d2 > 400.0 {
        3.0
    } else if d2 > 100.0 {
        2.0
    } else {
        0.9
    };
    let off = ratio * k.ka();
    let orth = body.dir.cross(rel).abs();
    let behind = body.dir.dot(rel) < 0.0 && rel.norm2() > dist_back * dist_back;
    if orth > off || behind { Some(rel) } else { None }
}

/// The player's model's command to move to `target` in `cycles`
/// (`predictCommandToMoveToPos`, `dist_back` 2.5): [`turn_towards`], else a
/// dash to arrive in `cycles`.
#[inline]
pub fn command_to_move(k: &Kinematics, body: &Body, target: Vec2, cycles: usize) -> Command {
    turn_towards(k, body, target, cycles, 2.5).unwrap_or_else(|| dash_to_point(k, body, target, cycles))
}

/// Where the player's model puts it after `cycles` cycles of
/// [`command_to_move`] toward `target`: turns one at a time while
/// [`turn_towards`] asks for them, then the dashes, which with the power of
/// [`Kinematics::power_for_dash`] arrive exactly when full dashes can cover
/// the distance and otherwise cover their full reach; the velocity across
/// the body line drifts and decays.
pub fn simulate_move(k: &Kinematics, body: &Body, target: Vec2, cycles: usize) -> Vec2 {
    let mut b = *body;
    let mut left = cycles;
    let mut turns = 0;
    while left > 0 && turns < 5 {
        match needs_turn(k, &b, target, left, 2.5) {
            Some(rel) => {
                b = k.after_turn_toward(&b, rel);
                left -= 1;
                turns += 1;
            }
            None => break,
        }
    }
    if left == 0 {
        return b.pos;
    }
    let along = (target - b.pos).dot(b.dir);
    let v_along = b.vel.dot(b.dir);
    let v_across = b.vel.cross(b.dir);
    let drift = k.drift(left);
    let reach = k.reach(left);
    let along = along.clamp(-reach + v_along * drift, reach + v_along * drift);
    let across = b.dir.perp() * (-v_across * drift);
    b.pos + b.dir * along + across
}

/// Cycles a player at `speed` along its body needs to come within the
/// kickable area of a point `dist` metres ahead with full dashes
/// (`predictNrCyclesForDistance`).
#[inline]
pub fn cycles_for_distance(k: &Kinematics, dist: f64, speed: f64) -> usize {
    let need = dist - k.ka();
    if need <= 0.0 {
        return 0;
    }
    for n in 1..=TABLE {
        if k.reach[n] + speed * k.drift[n] >= need {
            return n;
        }
    }
    TABLE + ((need - k.reach[TABLE] - speed * k.drift[TABLE]) / k.step_limit()).ceil().max(0.0) as usize
}

/// Cycles another player (as a teammate or opponent models it) needs to
/// reach `target` (`predictNrCyclesToPoint`): the turns its move would take
/// (and backward dashes more than 20° off), then full dashes.
pub fn cycles_to_point(k: &Kinematics, body: &Body, target: Vec2) -> usize {
    let ka = k.ka();
    if body.pos.dist2(target) < ka * ka {
        return 0;
    }
    let toward = target - body.pos;
    let cos20 = 0.939_692_620_785_908_4; // cos 20°
    let mut b = *body;
    let mut cycles = 0;
    for _ in 0..8 {
        if let Some(rel) = needs_turn(k, &b, target, 1, 2.5) {
            b = k.after_turn_toward(&b, rel);
        } else {
            let power = k.power_for_dash(&b, target, 1);
            if !(power < 0.0 && b.dir.dot(toward) < cos20 * toward.norm()) {
                break;
            }
            b = k.after_dash(&b, power);
        }
        cycles += 1;
        if b.pos.dist2(target) < ka * ka {
            return cycles;
        }
    }
    cycles + cycles_for_distance(k, b.pos.dist(target), b.vel.dot(b.dir))
}

/// Collides with the ball on purpose if a turn or one dash brings the
/// body within touching distance of the ball next cycle (`collideWithBall`).
pub fn collide_with_ball(k: &Kinematics, body: &Body, ball: &BallForecast, forward: Vec2) -> Option<Command> {
    let touch = k.p.ball_size + k.p.player_size;
    if body.pos.dist(ball.at[0]) > ball.vel.norm() + k.p.player_speed_max {
        return None;
    }
    let next = ball.at[1];
    let turn = turn_body_to_point(k, body, body.pos + forward, 1);
    if k.after(body, turn).pos.dist2(next) < touch * touch {
        return Some(turn);
    }
    let dash = dash_to_point(k, body, next, 1);
    if k.after(body, dash).pos.dist2(next) < touch * touch {
        return Some(dash);
    }
    None
}

/// The points of the line through `from` along the unit `dir` at distance
/// `r` from `c`, nearer-along-the-line first.
fn line_circle(from: Vec2, dir: Vec2, c: Vec2, r: f64) -> [Option<Vec2>; 2] {
    let rel = c - from;
    let along = rel.dot(dir);
    let across2 = rel.norm2() - along * along;
    let h2 = r * r - across2;
    if h2 < 0.0 {
        return [None, None];
    }
    if h2 == 0.0 {
        return [Some(from + dir * along), None];
    }
    let h = h2.sqrt();
    [Some(from + dir * (along - h)), Some(from + dir * (along + h))]
}

/// The close interception (`interceptClose`, not the goalie's): a dash that
/// leaves the ball in front of the body next cycle, or a turn to face
/// forward that keeps the ball close, or a collision, or a stop, in the
/// source's order. `opp_dist` is the nearest opponent's distance from the player.
pub fn intercept_close(
    k: &Kinematics,
    body: &Body,
    ball: &BallForecast,
    forward: Vec2,
    opp_dist: f64,
) -> Option<Command> {
    let ka = k.ka();
    let p = &k.p;
    let ready = body.pos.dist(ball.at[0]) > 3.0 * p.player_speed_max + (1.0 + p.ball_decay) * p.ball_speed_max + ka;
    let collide = collide_with_ball(k, body, ball, forward);
    let ang_turn = signed_angle(body.dir, forward).abs();
    let threshold = 25.0 * RAD_PER_DEG;
    let opp_close = opp_dist < 3.0;
    let pred1 = k.drift_pos(body, 1);
    let (ball1, ball2) = (ball.at[1], ball.at[2]);
    let close = |q: Vec2, b: Vec2, f: f64| q.dist2(b) < (f * ka) * (f * ka);
    // One dash onto the line of the body, the ball a small buffer in front.
    let radius = p.player_size + p.ball_size + p.kickable_margin / 6.0;
    let mut dash1 = None;
    let sols = line_circle(pred1, body.dir, ball1, radius);
    let ordered = match sols {
        [Some(a), Some(b)] if b.dot(forward) > a.dot(forward) => [Some(b), Some(a)],
        s => s,
    };
    for s in ordered.into_iter().flatten() {
        let power = k.power_for_dash(body, s, 1);
        if close(k.after_dash(body, power.trunc()).pos, ball1, 0.95) {
            dash1 = Some(Command::Dash { power });
            break;
        }
    }
    if dash1.is_none() {
        let d = dash_to_point(k, body, ball1, 1);
        if close(k.after(body, d).pos, ball1, 0.95) {
            dash1 = Some(d);
        }
    }
    if ready {
        return None;
    }
    if opp_close && dash1.is_some() {
        return dash1;
    }
    let mut turn_ok = None;
    let turn = turn_body_to_point(k, body, pred1 + forward, 1);
    let after = k.after(body, turn);
    if close(after.pos, ball1, 0.8) {
        turn_ok = Some(turn);
        if signed_angle(after.dir, forward).abs() < threshold {
            return Some(turn);
        }
    }
    let second = k.after_turn(&after, k.moment_for_turn(signed_angle(after.dir, forward), after.vel.norm()));
    if close(second.pos, ball2, 0.8) {
        turn_ok = Some(turn);
        if signed_angle(second.dir, forward).abs() < threshold {
            return Some(turn);
        }
    }
    if ang_turn > threshold {
        if let Some(c) = collide {
            return Some(c);
        }
        let stop = dash_to_point(k, body, body.pos, 1);
        if close(k.after(body, stop).pos, ball2, 0.8) {
            return Some(stop);
        }
    }
    turn_ok.or(dash1)
}

/// A player's memory of its last interception point (`predictCommandToInterceptBall`'s statics).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InterceptMemory {
    point: Option<Vec2>,
    cycle: Option<u32>,
}

impl InterceptMemory {
    /// Forgets (a new episode).
    pub fn clear(&mut self) {
        *self = InterceptMemory::default();
    }
}

/// How a player intercepts (see the module docs).
pub struct Interceptor<'a> {
    /// The kinematics.
    pub k: &'a Kinematics,
    /// The ball's path.
    pub ball: &'a BallForecast,
    /// The player's forward direction in global coordinates.
    pub forward: Vec2,
    /// The nearest opponent's distance from the player.
    pub opp_dist: f64,
    /// The current cycle (for the memory).
    pub cycle: u32,
}

impl Interceptor<'_> {
    /// The cycle at which `body` intercepts the ball (`predictCommandToInterceptBall`);
    /// `INTERCEPT_HORIZON + 70` (the source's 100) when it cannot within the horizon.
    pub fn plan(&self, body: &Body, memory: &mut InterceptMemory) -> usize {
        let k = self.k;
        let ka = k.ka();
        let old = match (memory.point, memory.cycle) {
            (Some(p), Some(c)) if self.cycle.saturating_sub(c) <= 2 => Some(p),
            _ => None,
        };
        memory.cycle = Some(self.cycle);
        const NONE: usize = 100;
        let (mut first, mut min) = (NONE, NONE);
        let mut old_i: Option<usize> = None;
        let (mut min_old, mut dist_best) = (100.0f64, 10.0f64);
        for i in 0..=INTERCEPT_HORIZON {
            if first != NONE && i > first + 20 {
                break;
            }
            let at = self.ball.at[i];
            let pp = k.drift_pos(body, i.min(4));
            let bound = (i as f64 + ka) * k.p.player_speed_max;
            if pp.dist2(at) > bound * bound {
                continue;
            }
            // Out of reach even running straight at it from the start: skip
            // the simulation (it could only say the same).
            let straight = k.reach(i) + body.vel.norm() * k.drift(i) + ka;
            if k.drift_pos(body, i).dist2(at) >= straight * straight + 1e-9 && body.pos.dist2(at) >= straight * straight
            {
                continue;
            }
            if first != NONE && old.is_none() {
                // Without last cycle's point the first reachable cycle is the choice.
                break;
            }
            let fast = self.ball.vel_at(i).norm2() > 0.6 * 0.6;
            let near_old = fast && old.is_some_and(|o| o.dist2(at) < min_old.min(1.0) * min_old.min(1.0));
            let safer_window = i <= min.saturating_add(3) || old_i.is_some_and(|o| i <= o + 3);
            if first != NONE && !near_old && !(safer_window && dist_best > 0.5 * ka) {
                if !fast && old_i.is_none() && i > min.saturating_add(3) {
                    // The ball only slows: no later cycle can keep last cycle's point.
                    break;
                }
                continue;
            }
            let d = simulate_move(k, body, at, i).dist(at);
            if d >= ka {
                continue;
            }
            if min == NONE {
                first = i;
                min = i;
            }
            if near_old && d < 0.7 * ka {
                old_i = Some(i);
                dist_best = d;
                min_old = old.map_or(min_old, |o| o.dist(at));
            } else if d < dist_best && dist_best > 0.5 * ka && safer_window {
                min = i;
                dist_best = d;
                if old_i == Some(min.wrapping_sub(1)) {
                    old_i = Some(min);
                }
            }
        }
        let chosen = match old_i {
            Some(o) if min <= o + 2 => o,
            _ => first,
        };
        memory.point = Some(self.ball.after(chosen));
        chosen
    }

    /// The command to intercept (`BasicPlayer::intercept`): the close
    /// interception within three cycles, nothing but a turn to face forward
    /// within [`ALREADY_CLOSE`] of the point, else a move to arrive on time.
    pub fn intercept(&self, body: &Body, memory: &mut InterceptMemory) -> Command {
        let k = self.k;
        let chosen = self.plan(body, memory);
        let point = self.ball.after(chosen);
        if chosen < 3
            && let Some(c) = intercept_close(k, body, self.ball, self.forward, self.opp_dist)
        {
            return c;
        }
        if k.drift_pos(body, chosen.min(4)).dist2(point) < ALREADY_CLOSE * ALREADY_CLOSE {
            return turn_body_to_point(k, body, body.pos + self.forward, 1);
        }
        command_to_move(k, body, point, chosen.min(TABLE))
    }
}

/// A kick command giving the ball the acceleration `acc` (global).
#[inline]
fn kick_for(body: &Body, acc: Vec2, rate: f64) -> Command {
    Command::Kick { power: acc.norm() / rate, dir: rel_deg(body, acc) }
}

/// The ball after a kick command and one cycle, as the player predicts it
/// (`predictBallInfoAfterCommand`: whole-number power and direction, the
/// speed capped).
fn ball_after_kick(k: &Kinematics, body: &Body, ball: &Ball, cmd: Command) -> (Vec2, Vec2) {
    let mut vel = ball.vel;
    if let Command::Kick { power, dir } = cmd {
        let rate = k.p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
        vel += body.dir.rotate(Vec2::from_angle(dir.trunc() * RAD_PER_DEG)) * (rate * power.trunc());
        vel = vel.with_norm(vel.norm().min(k.p.ball_speed_max));
    }
    let pos = ball.pos + vel;
    (pos, vel * k.p.ball_decay)
}

/// Gives the ball the velocity `target` if one kick can, else kicks at
/// full power so that it moves along `target`'s direction (`accelerateBallToVelocity`).
pub fn accelerate_ball_to_velocity(k: &Kinematics, body: &Body, ball: &Ball, target: Vec2) -> Command {
    let rate = k.p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
    let acc = target - ball.vel;
    if acc.norm() < k.p.ball_accel_max {
        let power = acc.norm() / rate;
        if power <= k.p.max_power {
            return kick_for(body, acc, rate);
        }
    }
    Command::Kick { power: k.p.max_power, dir: full_kick_dir(k, body, ball, target, rate) }
}

/// The direction (degrees, relative to the body) of a full-power kick whose
/// result moves along `target`: the kick cancels the ball's velocity across it.
fn full_kick_dir(k: &Kinematics, body: &Body, ball: &Ball, target: Vec2, rate: f64) -> f64 {
    let u = target.normalized_or(body.dir);
    let across = ball.vel.unrotate(u).y;
    let ang = signed_angle(Vec2::new(1.0, 0.0), u) - libm::asin((across / (rate * k.p.max_power)).clamp(-1.0, 1.0));
    normalize_angle(ang - body.angle) / RAD_PER_DEG
}

/// Stops the ball dead, or, if it would end too far from the body, pulls
/// it to a point inside the kickable area (`freezeBall`).
pub fn freeze_ball(k: &Kinematics, body: &Body, ball: &Ball) -> Command {
    let rate = k.p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
    let pred = k.drift_pos(body, 1);
    let power = (ball.vel.norm() / rate).min(k.p.max_power);
    let cmd = Command::Kick { power, dir: rel_deg(body, -ball.vel) };
    let (pos, _) = ball_after_kick(k, body, ball, cmd);
    let ka = k.ka();
    if pos.dist2(pred) < (0.8 * ka) * (0.8 * ka) {
        return cmd;
    }
    let to_ball = ball.pos - pred;
    let to = pred + to_ball.normalized_or(body.dir) * (0.7 * ka).min(to_ball.norm() - 0.1);
    accelerate_ball_to_velocity(k, body, ball, to - ball.pos)
}

/// Kicks the ball to a spot `ratio · kickable_margin` beyond the body's
/// edge at `ang` radians from the body, relative to where the body will
/// be next cycle (`kickBallCloseToBody`); freezes a fast ball it cannot.
pub fn kick_ball_close_to_body(k: &Kinematics, body: &Body, ball: &Ball, ang: f64, ratio: f64) -> Command {
    let p = &k.p;
    let spot = k.drift_pos(body, 1)
        + body.dir.rotate(Vec2::from_angle(ang)) * (p.player_size + p.ball_size + p.kickable_margin * ratio);
    let shoot = spot - ball.pos - ball.vel;
    let rate = p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
    let power = shoot.norm() / rate;
    if power > p.max_power && ball.vel.norm() > 0.1 {
        return freeze_ball(k, body, ball);
    }
    Command::Kick { power: power.min(p.max_power), dir: rel_deg(body, shoot) }
}

/// Kicks the ball toward `target` so that it arrives with `end_speed`
/// (`kickTo`): one kick when it can give the needed velocity (5 % over full
/// power allowed, 30 % with an opponent within 2 m of the ball), else the
/// ball is first repositioned or frozen. `opp_dist`: the nearest
/// opponent's distance from the ball.
pub fn kick_to(k: &Kinematics, body: &Body, ball: &Ball, target: Vec2, end_speed: f64, opp_dist: f64) -> Command {
    let p = &k.p;
    let traj = target - ball.pos;
    let mut vel_des = traj.normalized_or(body.dir) * k.kick_speed_to_travel(traj.norm(), end_speed);
    let touch = p.ball_size + p.player_size;
    if k.drift_pos(body, 1).dist2(ball.pos + vel_des) < touch * touch {
        // The kick would run the ball into the player: shorten or lengthen it past the body.
        let u = vel_des.normalized_or(body.dir);
        let proj = (body.pos - ball.pos).dot(u);
        let d = if vel_des.norm() < proj { proj - touch } else { proj + touch };
        vel_des = u * d;
    }
    let rate = p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
    if vel_des.norm() > p.ball_speed_max {
        let dir = full_kick_dir(k, body, ball, vel_des, rate) * RAD_PER_DEG;
        let reached = (ball.vel + body.dir.rotate(Vec2::from_angle(dir)) * (rate * p.max_power)).norm();
        return if reached > WHEN_TO_KICK * p.ball_accel_max {
            accelerate_ball_to_velocity(k, body, ball, vel_des)
        } else if rate > WHEN_TO_KICK * p.kick_power_rate {
            freeze_ball(k, body, ball)
        } else {
            kick_ball_close_to_body(k, body, ball, 0.0, CLOSE_TO_BODY_RATIO)
        };
    }
    let power = (vel_des - ball.vel).norm() / rate;
    if power <= 1.05 * p.max_power || (opp_dist < 2.0 && power <= 1.3 * p.max_power) {
        accelerate_ball_to_velocity(k, body, ball, vel_des)
    } else {
        kick_ball_close_to_body(k, body, ball, 0.0, CLOSE_TO_BODY_RATIO)
    }
}

/// Keeps the ball `ratio · kickable_margin` beyond the body (`holdBall`):
/// straight ahead, or, with the opponent `opp` nearest the ball within 5 m
/// of it, at 45° off the line from that opponent to the player, on the side
/// away from the opponent's heading. When the ball already lies near the spot
/// (the source tests the spot at `ratio` metres in the *relative* direction,
/// kept here) and stays kickable, the player turns to `goal` instead.
pub fn hold_ball(k: &Kinematics, body: &Body, ball: &Ball, opp: Option<&Body>, ratio: f64, goal: Vec2) -> Command {
    let mut ang = 0.0;
    if let Some(o) = opp
        && o.pos.dist2(ball.pos) < HOLD_OPPONENT_RANGE * HOLD_OPPONENT_RANGE
    {
        let away = (body.pos - o.pos).angle();
        let side = if normalize_angle(o.angle - away) > 0.0 { -1.0 } else { 1.0 };
        ang = normalize_angle(away + side * 45.0 * RAD_PER_DEG - body.angle);
    }
    if ball.pos.dist2(body.pos + Vec2::from_angle(ang) * ratio) < 0.3 * 0.3 {
        let turn = turn_body_to_point(k, body, goal, 1);
        let ka = 0.85 * k.ka();
        if k.after(body, turn).pos.dist2(ball.pos + ball.vel) < ka * ka {
            return turn;
        }
    }
    kick_ball_close_to_body(k, body, ball, ang, ratio)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::server::{advance_ball, advance_player, execute};
    use rlfd_env::random::seeded;

    const P: ServerParams = ServerParams::rcssserver_11();

    fn kin() -> Kinematics {
        Kinematics::new(&P)
    }

    #[test]
    fn tables_follow_the_server() {
        let k = kin();
        assert!((k.reach(1) - 0.6).abs() < 1e-12);
        assert!((k.reach(2) - 1.44).abs() < 1e-12);
        assert!((k.reach(40) - k.reach(39) - 1.0).abs() < 1e-9);
        assert!((k.drift(1) - 1.0).abs() < 1e-12 && (k.drift(2) - 1.4).abs() < 1e-12);
        // A pass of 10 m at end speed 1.2: 7 whole cycles, 1.2 · (1/0.94)^7.
        let v = k.kick_speed_to_travel(10.0, 1.2);
        assert!((v - 1.2 * (1.0f64 / 0.94).powi(7)).abs() < 1e-12, "{v}");
        // Dash power to arrive in one cycle is the whole distance, capped.
        let b = Body::at(Vec2::ZERO, 0.0);
        assert!((k.power_for_dash(&b, Vec2::new(0.3, 0.0), 1) - 50.0).abs() < 1e-9);
        assert_eq!(k.power_for_dash(&b, Vec2::new(5.0, 0.0), 1), 100.0);
        assert_eq!(k.power_for_dash(&b, Vec2::new(-5.0, 0.0), 1), -100.0);
        // Arriving in three cycles asks for the first term of the series.
        let three = k.power_for_dash(&b, Vec2::new(0.78, 0.0), 3);
        assert!((three * 0.006 - 0.78 * 0.6 / (1.0 - 0.064)).abs() < 1e-12);
    }

    #[test]
    fn simulated_moves_arrive_or_reach_as_far_as_full_dashes() {
        let k = kin();
        let b = Body::at(Vec2::ZERO, 0.0);
        // Ahead and reachable: arrives.
        let end = simulate_move(&k, &b, Vec2::new(3.0, 0.0), 5);
        assert!(end.dist(Vec2::new(3.0, 0.0)) < 1e-9, "{end:?}");
        // Too far: full reach.
        let end = simulate_move(&k, &b, Vec2::new(30.0, 0.0), 5);
        assert!((end.x - k.reach(5)).abs() < 1e-9);
        // To the side: one turn first, then dashes.
        let end = simulate_move(&k, &b, Vec2::new(0.0, 3.0), 6);
        assert!(end.dist(Vec2::new(0.0, 3.0)) < 1e-6, "{end:?}");
        // The closed form agrees with stepping the player's own commands.
        let mut rng = seeded(3);
        let mut errors = Vec::new();
        for _ in 0..500 {
            let mut u = || rlfd_env::random::uniform01(&mut rng);
            let body = Body {
                vel: Vec2::new(0.6 * u() - 0.3, 0.6 * u() - 0.3),
                ..Body::at(Vec2::new(10.0 * u() - 5.0, 10.0 * u() - 5.0), 6.0 * u() - 3.0)
            };
            let target = Vec2::new(16.0 * u() - 8.0, 16.0 * u() - 8.0);
            let n = 1 + (12.0 * u()) as usize;
            let mut s = body;
            for j in 0..n {
                let c = command_to_move(&k, &s, target, n - j);
                s = k.after(&s, c);
            }
            let closed = simulate_move(&k, &body, target, n);
            errors.push(closed.dist(s.pos));
        }
        // Turns after the first dash (which the closed form leaves out) are
        // rare: nine in ten agree within 10 cm.
        errors.sort_by(f64::total_cmp);
        assert!(errors[errors.len() * 9 / 10] < 0.1, "{:?}", &errors[errors.len() * 9 / 10..]);
    }

    #[test]
    fn cycles_to_a_point_count_turns_and_dashes() {
        let k = kin();
        let b = Body::at(Vec2::ZERO, 0.0);
        assert_eq!(cycles_to_point(&k, &b, Vec2::new(0.5, 0.0)), 0);
        // 6 − 1.085 = 4.9 m: five dashes cover 4.33, six 5.32.
        assert_eq!(cycles_to_point(&k, &b, Vec2::new(6.0, 0.0)), 6);
        // Facing away costs a turn.
        assert_eq!(cycles_to_point(&k, &b, Vec2::new(-6.0, 0.0)), 7);
    }

    #[test]
    fn a_pass_leaves_at_the_speed_that_arrives_at_the_end_speed() {
        let k = kin();
        let body = Body::at(Vec2::ZERO, 0.0);
        let ball = Ball { pos: Vec2::new(0.5, 0.0), ..Ball::default() };
        let cmd = kick_to(&k, &body, &ball, Vec2::new(10.5, 0.0), 1.2, 10.0);
        let Command::Kick { power, dir } = cmd else { panic!("{cmd:?}") };
        let rate = P.actual_kick_power_rate(body.pos, body.dir, ball.pos);
        assert!(dir.abs() < 1e-9);
        assert!((power * rate - k.kick_speed_to_travel(10.0, 1.2)).abs() < 1e-9);
    }

    #[test]
    fn a_long_pass_from_a_badly_placed_ball_repositions_it_first() {
        // Ball behind the player at the kickable edge: the kick rate is halved,
        // so a 16 m pass cannot be given in one kick.
        let k = kin();
        let body = Body::at(Vec2::ZERO, 0.0);
        let ball = Ball { pos: Vec2::new(-1.0, 0.0), ..Ball::default() };
        match kick_to(&k, &body, &ball, Vec2::new(15.0, 0.0), 1.2, 10.0) {
            Command::Kick { power, .. } => {
                let rate = P.actual_kick_power_rate(body.pos, body.dir, ball.pos);
                assert!(power * rate < 2.0, "a small repositioning kick, not the pass");
            }
            other => panic!("expected a kick, got {other:?}"),
        }
    }

    #[test]
    fn hold_keeps_the_ball_near_and_away_from_a_close_taker() {
        let k = kin();
        let mut rng = seeded(5);
        let mut keeper = Body::at(Vec2::ZERO, 0.0);
        let mut ball = Ball { pos: Vec2::new(0.6, 0.2), ..Ball::default() };
        let taker = Body::at(Vec2::new(3.0, 0.0), std::f64::consts::PI);
        for _ in 0..20 {
            let cmd = hold_ball(&k, &keeper, &ball, Some(&taker), 0.7, Vec2::new(52.5, 0.0)).as_sent(&P);
            execute(&P, &mut keeper, &mut ball, cmd, &mut rng);
            advance_player(&P, &mut keeper, &mut rng);
            advance_ball(&P, &mut ball, &mut rng);
            assert!(keeper.pos.dist(ball.pos) < P.kickable_area(), "the ball stays kickable");
        }
        // The ball sits on the side away from the taker.
        assert!((ball.pos - keeper.pos).x < 0.0, "{:?}", ball.pos - keeper.pos);
    }

    #[test]
    fn an_interceptor_close_to_the_point_waits_and_a_far_one_runs() {
        let k = kin();
        // A ball rolling at 1.4 m/cycle along +x from (−10, 0): a player five
        // metres off its path runs (a turn or a dash toward the point).
        let ball = Ball { pos: Vec2::new(-10.0, 0.0), vel: Vec2::new(1.4, 0.0), accel: Vec2::ZERO };
        let f = BallForecast::new(&P, &ball);
        let i = Interceptor { k: &k, ball: &f, forward: Vec2::new(1.0, 0.0), opp_dist: 10.0, cycle: 0 };
        let off = Body::at(Vec2::new(0.0, 5.0), -std::f64::consts::FRAC_PI_2);
        let mut mem = InterceptMemory::default();
        let plan = i.plan(&off, &mut mem);
        assert!((4..=12).contains(&plan), "{plan}");
        let run = i.intercept(&off, &mut mem);
        assert_ne!(run, turn_body_to_point(&k, &off, off.pos + Vec2::new(1.0, 0.0), 1), "it does not wait");
        assert!(matches!(run, Command::Dash { power } if power > 50.0) || matches!(run, Command::Turn { .. }));
        // A ball believed out of reach for three cycles and then 0.3 m from
        // where the player drifts to: it does not move, but turns to face
        // forward (+x; it faces −x).
        let mut near = BallForecast::still(Vec2::new(0.0, 0.3));
        for p in &mut near.at[..3] {
            *p = Vec2::new(-20.0, 0.0);
        }
        let wait = Interceptor { k: &k, ball: &near, forward: Vec2::new(1.0, 0.0), opp_dist: 10.0, cycle: 0 };
        let body = Body::at(Vec2::ZERO, std::f64::consts::PI);
        let mut mem = InterceptMemory::default();
        assert_eq!(wait.plan(&body, &mut mem), 3);
        assert!(matches!(wait.intercept(&body, &mut mem), Command::Turn { moment } if moment.abs() > 170.0));
    }
}
