//! The players' skills: the commands the UT-Austin keepaway players (v0.6,
//! built on UvA Trilearn's `BasicPlayer`) send for moving, turning,
//! intercepting and kicking, written from the public sources' descriptions
//! (`tjpalmer/keepaway:player/BasicPlayer.cc`, `WorldModel*.cc`).
//!
//! - Moving: [`move_to`] dashes toward a point when the body points within
//!   7° of it (`player_when_to_turn`), or dashes backwards to a point less
//!   than 3 m behind, else turns toward it (or, when the turn would take
//!   more than two cycles, brakes first). [`dash_power_to`] asks for the
//!   acceleration that would reach the point in one cycle, capped at 100.
//! - Intercepting: [`BallForecast`] holds the ball's positions for the next
//!   30 cycles without noise (`p + v (1 − 0.94ⁿ)/(1 − 0.94)`), or its
//!   present position while a player has it within the kickable area (the
//!   holder re-kicks it every cycle, so its velocity does not predict it);
//!   [`plan_intercept`] finds the first cycle at which a player turning (0,
//!   1 or 2 cycles) and then dashing at full power can be within the
//!   kickable area of the ball, and [`intercept`] moves to that point (or,
//!   when one dash along the body reaches the ball, dashes).
//! - Kicking: [`kick_ball_close_to_body`], [`freeze_ball`],
//!   [`accelerate_ball_to_velocity`], [`kick_to`] (a pass whose ball reaches
//!   the target at `end_speed`: first speed `end_speed + d (1 − 0.94)`, the
//!   ball repositioned first when one kick cannot give it) and [`hold_ball`]
//!   (the ball kept 0.7 m (keepers) or 0.3 m (takers) beyond the body, ±45°
//!   away from an opponent within 5 m).
//!
//! What it is not: the Trilearn code's every branch. Its two-cycle close
//! interception, collision-based tricks and dead-ball cases are folded into
//! the one interception plan above (the server here has no collisions); the
//! simplifications are listed as deviations in the report.

use super::geometry::{Vec2, signed_angle};
use super::server::{Ball, Body, Command, ServerParams};

/// How far ahead interceptions are planned (`player_when_to_intercept`).
pub const INTERCEPT_HORIZON: usize = 30;

/// The angle within which a player dashes instead of turning (`player_when_to_turn`, 7°).
pub const WHEN_TO_TURN: f64 = 7.0 * std::f64::consts::PI / 180.0;

/// `cos(7°)`, so the dash-or-turn test needs no trigonometry per call (a test checks it against `libm`).
pub const COS_WHEN_TO_TURN: f64 = 0.992_546_151_641_322;

/// Distance behind the player within which it dashes backwards instead of turning (m).
pub const DIST_BACK: f64 = 3.0;

/// A kick ratio for repositioning the ball close to the body (Trilearn's default 0.16).
pub const CLOSE_TO_BODY_RATIO: f64 = 0.16;

/// Distance from a taker within which the keeper holding the ball kicks it sideways (m).
pub const HOLD_OPPONENT_RANGE: f64 = 5.0;

/// The point the hold skill turns the body toward when the ball already lies
/// where it should (Trilearn turns to the opponent's goal at (52.5, 0);
/// seen from the keepaway region at the field's centre that is +x).
pub const HOLD_TURN_POINT: Vec2 = Vec2 { x: 52.5, y: 0.0 };

/// The ball's noise-free positions over the next [`INTERCEPT_HORIZON`] cycles.
#[derive(Clone, Debug)]
pub struct BallForecast {
    /// `at[n]`: the position after `n` cycles (`at[0]` is now).
    pub at: [Vec2; INTERCEPT_HORIZON + 1],
    /// Where the ball comes to rest.
    pub rest: Vec2,
    held: bool,
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
        BallForecast { at, rest: ball.pos + ball.vel * (1.0 / (1.0 - p.ball_decay)), held: false }
    }

    /// A ball that stays at `pos` (one under a player's control: its holder
    /// re-kicks it every cycle, so its velocity says nothing about where it goes).
    pub fn held(pos: Vec2) -> BallForecast {
        BallForecast { at: [pos; INTERCEPT_HORIZON + 1], rest: pos, held: true }
    }

    /// Whether this is a held ball's forecast ([`BallForecast::held`]).
    #[inline]
    pub fn is_held(&self) -> bool {
        self.held
    }

    /// The position after `n` cycles (the resting point beyond the horizon).
    #[inline]
    pub fn after(&self, n: usize) -> Vec2 {
        if n <= INTERCEPT_HORIZON { self.at[n] } else { self.rest }
    }
}

/// Distances a player starting from rest covers with `n` full dashes
/// (`REACH[n]`); the speed after `k` dashes is `1 − 0.4ᵏ` m/cycle.
#[derive(Clone, Debug)]
pub struct ReachTable {
    reach: [f64; INTERCEPT_HORIZON + 1],
    drift: [f64; INTERCEPT_HORIZON + 1],
    /// `(cos(one turn), cos(two turns))` of the largest angles a player can
    /// turn through at speeds `0, TURN_STEP, 2·TURN_STEP, …` (interpolated
    /// in between), so planning needs no trigonometry per call.
    turn_cos: Vec<(f64, f64)>,
}

/// Speed resolution of the turn table (m/cycle).
const TURN_STEP: f64 = 1.0 / 1024.0;

/// Speeds the turn table covers (a player's speed cap is 1.2 m/cycle; the motion noise may add a little).
const TURN_SPEEDS: usize = 1600;

impl ReachTable {
    /// The table for `p`'s dash and decay.
    pub fn new(p: &ServerParams) -> ReachTable {
        let mut reach = [0.0; INTERCEPT_HORIZON + 1];
        let mut drift = [0.0; INTERCEPT_HORIZON + 1];
        let accel = p.max_power * p.dash_power_rate;
        let (mut v, mut d) = (0.0, 0.0);
        let mut decay_sum = 0.0;
        let mut decay_pow = 1.0;
        for n in 1..=INTERCEPT_HORIZON {
            v += accel;
            d += v;
            v *= p.player_decay;
            reach[n] = d;
            decay_sum += decay_pow;
            decay_pow *= p.player_decay;
            drift[n] = decay_sum;
        }
        let turn_cos = (0..=TURN_SPEEDS)
            .map(|i| {
                let speed = i as f64 * TURN_STEP;
                let first = max_turn(p, speed);
                let two = first + max_turn(p, speed * p.player_decay);
                (libm::cos(first), if two >= std::f64::consts::PI { -2.0 } else { libm::cos(two) })
            })
            .collect();
        ReachTable { reach, drift, turn_cos }
    }

    /// The cosines of the largest angles one and two turns cover at `speed`.
    #[inline]
    pub fn turn_cosines(&self, speed: f64) -> (f64, f64) {
        let x = (speed / TURN_STEP).min(TURN_SPEEDS as f64 - 1.0);
        let i = x as usize;
        let f = x - i as f64;
        let (a, b) = (self.turn_cos[i], self.turn_cos[i + 1]);
        (a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1))
    }

    /// Metres covered by `n` full dashes from rest.
    #[inline]
    pub fn reach(&self, n: usize) -> f64 {
        self.reach[n.min(INTERCEPT_HORIZON)]
    }

    /// Where a player's current velocity alone carries it in `n` cycles, as a multiple of that velocity.
    #[inline]
    pub fn drift(&self, n: usize) -> f64 {
        self.drift[n.min(INTERCEPT_HORIZON)]
    }
}

/// The largest turn (radians) a player moving at `speed` can make in one cycle.
#[inline]
pub fn max_turn(p: &ServerParams, speed: f64) -> f64 {
    std::f64::consts::PI / (1.0 + p.inertia_moment * speed)
}

/// The dash power that would bring `body` to `target` in one cycle
/// (Trilearn's `getPowerForDash`), in `[-100, 100]`.
#[inline]
pub fn dash_power_to(p: &ServerParams, body: &Body, target: Vec2) -> f64 {
    let along = (target - body.pos).dot(body.dir);
    let accel = along.min(p.player_speed_max) - body.vel.dot(body.dir);
    (accel / p.dash_power_rate).clamp(-p.max_power, p.max_power)
}

/// A turn toward `target`, seen from where the body drifts to next cycle,
/// with the moment scaled up to undo the inertia (Trilearn's `turnBodyToPoint`).
#[inline]
pub fn turn_to(p: &ServerParams, body: &Body, target: Vec2) -> Command {
    let from = body.pos + body.vel;
    let angle = signed_angle(body.dir, target - from);
    let moment = angle * (1.0 + p.inertia_moment * body.vel.norm());
    Command::Turn { moment: moment.clamp(-std::f64::consts::PI, std::f64::consts::PI) }
}

/// Moves toward `target` (Trilearn's `moveToPos` with `angWhenToTurn` = 7°,
/// `dDistBack` = 3 m): dash when facing it (or backing onto it), else turn.
pub fn move_to(p: &ServerParams, reach: &ReachTable, body: &Body, target: Vec2) -> Command {
    let final_pos = body.pos + body.vel * (1.0 / (1.0 - p.player_decay));
    let to = target - final_pos;
    let to_norm = to.norm();
    if to_norm < 1e-6 {
        return Command::Dash { power: dash_power_to(p, body, target) };
    }
    let cos_off = to.dot(body.dir) / to_norm;
    if cos_off > COS_WHEN_TO_TURN || (-cos_off > COS_WHEN_TO_TURN && body.pos.dist2(target) < DIST_BACK * DIST_BACK) {
        return Command::Dash { power: dash_power_to(p, body, target) };
    }
    // Trilearn's `directTowards`: turn if at most two turns get there, else stop first.
    let (_, cos_two) = reach.turn_cosines(body.vel.norm());
    if cos_off >= cos_two {
        turn_to(p, body, target)
    } else {
        Command::Dash { power: dash_power_to(p, body, body.pos) }
    }
}

/// Where and when a player can first reach the ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InterceptPlan {
    /// Cycles until the ball is within the kickable area (0: it is now);
    /// `INTERCEPT_HORIZON + 1` when it cannot be reached within the horizon.
    pub cycles: usize,
    /// Where the ball will be then (the resting point when unreachable).
    pub point: Vec2,
}

/// The first cycle at which `body` can have the ball within its kickable
/// area, turning toward the ball's position then (0–2 turns) and dashing at
/// full power for the remaining cycles (Trilearn's interception loop).
pub fn plan_intercept(p: &ServerParams, reach: &ReachTable, body: &Body, ball: &BallForecast) -> InterceptPlan {
    let ka = p.kickable_area();
    if body.pos.dist2(ball.at[0]) < ka * ka {
        return InterceptPlan { cycles: 0, point: ball.at[0] };
    }
    // Cosines of the largest angles one and two turns can cover at this speed.
    let (cos_first, cos_two) = reach.turn_cosines(body.vel.norm());
    let ka2 = ka * ka;
    let mut n = 1;
    while n <= INTERCEPT_HORIZON {
        let target = ball.at[n];
        let gap = target - (body.pos + body.vel * reach.drift(n));
        let gap2 = gap.norm2();
        if gap2 <= ka2 {
            return InterceptPlan { cycles: n, point: target };
        }
        // Out of reach even without turning: the common case, one comparison.
        let straight = reach.reach(n) + ka;
        if gap2 > straight * straight {
            n += 1;
            continue;
        }
        let along = gap.dot(body.dir);
        let turns = if cos_at_least(along, gap2, COS_WHEN_TO_TURN) {
            0
        } else if cos_at_least(along, gap2, cos_first) {
            1
        } else if cos_at_least(along, gap2, cos_two) {
            2
        } else {
            3
        };
        if turns < n {
            let run = reach.reach(n - turns) + ka;
            if gap2 <= run * run {
                return InterceptPlan { cycles: n, point: target };
            }
        }
        n += 1;
    }
    InterceptPlan { cycles: INTERCEPT_HORIZON + 1, point: ball.rest }
}

/// Whether the angle between the body and a gap vector has a cosine of at
/// least `c`, given the gap's projection on the body `along` and its squared
/// length `gap2 > 0` (no square root: `along/√gap2 ≥ c`).
#[inline]
fn cos_at_least(along: f64, gap2: f64, c: f64) -> bool {
    if c >= 0.0 { along >= 0.0 && along * along >= c * c * gap2 } else { along >= 0.0 || along * along <= c * c * gap2 }
}

/// Goes for the ball: first Trilearn's close interception (`interceptClose`,
/// its one-dash case): a dash forward or backward along the body that leaves
/// the player within 95 % of the kickable area of the ball's next position;
/// otherwise toward the planned interception point.
pub fn intercept(
    p: &ServerParams,
    reach: &ReachTable,
    body: &Body,
    plan: &InterceptPlan,
    ball: &BallForecast,
) -> Command {
    let next_ball = ball.after(1);
    let next_me = body.pos + body.vel;
    let close = 0.95 * p.kickable_area();
    if next_me.dist2(next_ball) < 4.0 * 4.0 {
        let along = (next_ball - next_me).dot(body.dir);
        let power = (along / p.dash_power_rate).clamp(-p.max_power, p.max_power);
        let after = next_me + body.dir * (power * p.dash_power_rate);
        if after.dist2(next_ball) < close * close {
            return Command::Dash { power };
        }
    }
    move_to(p, reach, body, plan.point)
}

/// Kicks the ball to a spot `ratio · kickable_margin` beyond the body's
/// edge in the global direction `dir` (a unit vector), relative to where the
/// body will be next cycle (Trilearn's `kickBallCloseToBody`).
pub fn kick_ball_close_to_body(p: &ServerParams, body: &Body, ball: &Ball, dir: Vec2, ratio: f64) -> Command {
    let next = body.pos + body.vel;
    let spot = next + dir * (p.player_size + p.ball_size + p.kickable_margin * ratio);
    let shoot = spot - ball.pos - ball.vel;
    let rate = p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
    let power = shoot.norm() / rate;
    if power > p.max_power && ball.vel.norm() > 0.1 {
        return freeze_ball(p, body, ball);
    }
    Command::Kick { power: power.min(p.max_power), dir: shoot.normalized_or(body.dir) }
}

/// Stops the ball dead: a kick against its velocity (Trilearn's `freezeBall`).
pub fn freeze_ball(p: &ServerParams, body: &Body, ball: &Ball) -> Command {
    let rate = p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
    let power = (ball.vel.norm() / rate).min(p.max_power);
    Command::Kick { power, dir: (-ball.vel).normalized_or(body.dir) }
}

/// Gives the ball the velocity `target` if one kick can, else the largest
/// speed along `target`'s direction (Trilearn's `accelerateBallToVelocity`).
pub fn accelerate_ball_to_velocity(p: &ServerParams, body: &Body, ball: &Ball, target: Vec2) -> Command {
    let rate = p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
    let need = target - ball.vel;
    let need_norm = need.norm();
    if need_norm < p.ball_accel_max {
        let power = need_norm / rate;
        if power <= p.max_power {
            return Command::Kick { power, dir: need.normalized_or(body.dir) };
        }
    }
    Command::Kick { power: p.max_power, dir: max_kick_along(p, rate, ball.vel, target) }
}

/// The direction of a full-power kick that leaves the ball moving along
/// `target`'s direction: the kick cancels the ball's velocity across it.
fn max_kick_along(p: &ServerParams, rate: f64, ball_vel: Vec2, target: Vec2) -> Vec2 {
    let u = target.normalized_or(Vec2::new(1.0, 0.0));
    let n = u.perp();
    let speed = rate * p.max_power;
    let sin = (-ball_vel.dot(n) / speed).clamp(-1.0, 1.0);
    let cos = (1.0 - sin * sin).sqrt();
    u * cos + n * sin
}

/// Kicks the ball toward `target` so that it arrives with `end_speed`
/// (Trilearn's `kickTo`): one kick when it can give the needed velocity
/// (5 % over full power allowed, 30 % when an opponent is within 2 m of the
/// ball), else the ball is first repositioned in front of the body.
pub fn kick_to(
    p: &ServerParams,
    body: &Body,
    ball: &Ball,
    target: Vec2,
    end_speed: f64,
    opponent_distance: f64,
) -> Command {
    let traj = target - ball.pos;
    let speed = end_speed + traj.norm() * (1.0 - p.ball_decay);
    let vel_des = traj.normalized_or(body.dir) * speed;
    let rate = p.actual_kick_power_rate(body.pos, body.dir, ball.pos);
    if speed > p.ball_speed_max {
        let dir = max_kick_along(p, rate, ball.vel, vel_des);
        let reached = (ball.vel + dir * (rate * p.max_power)).norm();
        return if reached > 0.85 * p.ball_accel_max {
            accelerate_ball_to_velocity(p, body, ball, vel_des)
        } else if rate > 0.85 * p.kick_power_rate {
            freeze_ball(p, body, ball)
        } else {
            kick_ball_close_to_body(p, body, ball, body.dir, CLOSE_TO_BODY_RATIO)
        };
    }
    let power = (vel_des - ball.vel).norm() / rate;
    if power <= 1.05 * p.max_power || (opponent_distance < 2.0 && power <= 1.3 * p.max_power) {
        accelerate_ball_to_velocity(p, body, ball, vel_des)
    } else {
        kick_ball_close_to_body(p, body, ball, body.dir, CLOSE_TO_BODY_RATIO)
    }
}

/// Keeps the ball `ratio · kickable_margin` beyond the body (Trilearn's
/// `holdBall`): straight ahead, or, with the opponent nearest the ball within
/// 5 m, at 45° off the line from that opponent to the player, on the side
/// away from the opponent's heading. When the ball already lies at the spot
/// and stays kickable, the player turns instead.
pub fn hold_ball(p: &ServerParams, body: &Body, ball: &Ball, opponent: Option<&Body>, ratio: f64) -> Command {
    let mut dir = body.dir;
    if let Some(opp) = opponent
        && opp.pos.dist2(ball.pos) < HOLD_OPPONENT_RANGE * HOLD_OPPONENT_RANGE
    {
        let away = (body.pos - opp.pos).normalized_or(body.dir);
        // iSign = −sign(angle from `away` to the opponent's heading); sign(0) = 1.
        let side = if away.cross(opp.dir) > 0.0 { -1.0 } else { 1.0 };
        let (c, s) = (std::f64::consts::FRAC_1_SQRT_2, std::f64::consts::FRAC_1_SQRT_2 * side);
        dir = Vec2::new(away.x * c - away.y * s, away.x * s + away.y * c);
    }
    let spot = body.pos + dir * ratio;
    if ball.pos.dist2(spot) < 0.3 * 0.3 {
        let turn = turn_to(p, body, HOLD_TURN_POINT);
        let ball_next = ball.pos + ball.vel;
        let body_next = body.pos + body.vel;
        let ka = 0.85 * p.kickable_area();
        if body_next.dist2(ball_next) < ka * ka {
            return turn;
        }
    }
    kick_ball_close_to_body(p, body, ball, dir, ratio)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::keepaway::server::{advance_ball, advance_player, execute};
    use rlfd_rl::random::seeded;

    const P: ServerParams = ServerParams::rcssserver_11();

    #[test]
    fn the_turn_threshold_cosine_is_cos_7_degrees() {
        assert!((COS_WHEN_TO_TURN - libm::cos(WHEN_TO_TURN)).abs() < 1e-15);
    }

    #[test]
    fn skipping_unreachable_cycles_finds_the_same_first_cycle() {
        // The plan equals a plain scan over every cycle, for random players and balls.
        let reach = ReachTable::new(&P);
        let mut rng = seeded(77);
        let mut u = || rlfd_rl::random::uniform01(&mut rng);
        for _ in 0..2000 {
            let body = Body {
                vel: Vec2::new(u() - 0.5, u() - 0.5),
                ..Body::at(Vec2::new(20.0 * u() - 10.0, 20.0 * u() - 10.0), 6.0 * u())
            };
            let ball = Ball {
                pos: Vec2::new(20.0 * u() - 10.0, 20.0 * u() - 10.0),
                vel: Vec2::new(4.0 * u() - 2.0, 4.0 * u() - 2.0),
                accel: Vec2::ZERO,
            };
            let f = BallForecast::new(&P, &ball);
            let plan = plan_intercept(&P, &reach, &body, &f);
            let (c1, c2) = reach.turn_cosines(body.vel.norm());
            let ka = P.kickable_area();
            let scan = (1..=INTERCEPT_HORIZON).find(|&n| {
                let gap = f.at[n] - (body.pos + body.vel * reach.drift(n));
                let g2 = gap.norm2();
                if g2 <= ka * ka {
                    return true;
                }
                let along = gap.dot(body.dir);
                let turns = [COS_WHEN_TO_TURN, c1, c2].iter().take_while(|&&c| !cos_at_least(along, g2, c)).count();
                turns < n && g2 <= (reach.reach(n - turns) + ka).powi(2)
            });
            if body.pos.dist2(ball.pos) >= ka * ka {
                assert_eq!(Some(plan.cycles).filter(|&c| c <= INTERCEPT_HORIZON), scan);
            }
        }
    }

    #[test]
    fn forecast_and_reach_tables() {
        let ball = Ball { pos: Vec2::ZERO, vel: Vec2::new(1.0, 0.0), accel: Vec2::ZERO };
        let f = BallForecast::new(&P, &ball);
        assert!((f.at[1].x - 1.0).abs() < 1e-12);
        assert!((f.at[2].x - 1.94).abs() < 1e-12);
        assert!((f.rest.x - 1.0 / 0.06).abs() < 1e-9);
        let r = ReachTable::new(&P);
        assert!((r.reach(1) - 0.6).abs() < 1e-12);
        assert!((r.reach(2) - 1.44).abs() < 1e-12);
        assert!((r.reach(30) - r.reach(29) - 1.0).abs() < 1e-9);
        assert!((r.drift(1) - 1.0).abs() < 1e-12 && (r.drift(2) - 1.4).abs() < 1e-12);
        for speed in [0.0, 0.1, 0.37, 0.8, 1.0, 1.2] {
            let (one, two) = r.turn_cosines(speed);
            let first = max_turn(&P, speed);
            assert!((one - libm::cos(first)).abs() < 1e-5, "{speed}");
            let both = first + max_turn(&P, 0.4 * speed);
            if both < std::f64::consts::PI {
                assert!((two - libm::cos(both)).abs() < 1e-5, "{speed}");
            }
        }
    }

    #[test]
    fn a_still_ball_ahead_is_reached_when_the_plan_says() {
        let reach = ReachTable::new(&P);
        let ball = Ball { pos: Vec2::new(6.0, 0.0), ..Ball::default() };
        let body = Body::at(Vec2::ZERO, 0.0);
        let plan = plan_intercept(&P, &reach, &body, &BallForecast::new(&P, &ball));
        // 6 − 1.085 = 4.9 m: five dashes cover 4.33, six 5.32.
        assert_eq!(plan.cycles, 6);
        // Facing away costs one turn (at rest a turn can reach 180°).
        let back = Body::at(Vec2::ZERO, std::f64::consts::PI);
        let plan_back = plan_intercept(&P, &reach, &back, &BallForecast::new(&P, &ball));
        assert_eq!(plan_back.cycles, 7);
        // Follow the plan through the noisy physics: the ball is kickable within a cycle of it.
        let mut rng = seeded(9);
        let mut b = back;
        let mut ball_now = ball;
        let mut reached = None;
        for t in 1..=12 {
            let plan = plan_intercept(&P, &reach, &b, &BallForecast::new(&P, &ball_now));
            let cmd = intercept(&P, &reach, &b, &plan, &BallForecast::new(&P, &ball_now));
            execute(&P, &mut b, &mut ball_now, cmd, &mut rng);
            advance_player(&P, &mut b, &mut rng);
            advance_ball(&P, &mut ball_now, &mut rng);
            if b.pos.dist(ball_now.pos) < P.kickable_area() {
                reached = Some(t);
                break;
            }
        }
        let t = reached.expect("the ball is reached");
        assert!((7..=8).contains(&t), "{t}");
    }

    #[test]
    fn a_pass_leaves_at_the_speed_that_arrives_at_1_7() {
        let body = Body::at(Vec2::ZERO, 0.0);
        let ball = Ball { pos: Vec2::new(0.5, 0.0), ..Ball::default() };
        let target = Vec2::new(10.5, 0.0);
        let cmd = kick_to(&P, &body, &ball, target, 1.7, 10.0);
        let mut b = body;
        let mut moved = ball;
        execute(&P, &mut b, &mut moved, cmd, &mut seeded(1));
        // 1.7 + 10 · 0.06 = 2.3 m/cycle along +x.
        assert!((moved.accel.x - 2.3).abs() < 1e-9 && moved.accel.y.abs() < 1e-9, "{:?}", moved.accel);
    }

    #[test]
    fn a_long_pass_from_a_badly_placed_ball_repositions_it_first() {
        // Ball behind the player at the kickable edge: the kick rate is halved,
        // so a 16 m pass (2.66 m/cycle) cannot be given in one kick.
        let body = Body::at(Vec2::ZERO, 0.0);
        let ball = Ball { pos: Vec2::new(-1.0, 0.0), ..Ball::default() };
        match kick_to(&P, &body, &ball, Vec2::new(15.0, 0.0), 1.7, 10.0) {
            Command::Kick { power, dir } => {
                let rate = P.actual_kick_power_rate(body.pos, body.dir, ball.pos);
                assert!(power * rate < 2.0, "a small repositioning kick, not the pass");
                assert!(dir.x > 0.0);
            }
            other => panic!("expected a kick, got {other:?}"),
        }
    }

    #[test]
    fn hold_keeps_the_ball_near_and_away_from_a_close_taker() {
        let mut rng = seeded(5);
        let mut keeper = Body::at(Vec2::ZERO, 0.0);
        let mut ball = Ball { pos: Vec2::new(0.6, 0.2), ..Ball::default() };
        let taker = Body::at(Vec2::new(3.0, 0.0), std::f64::consts::PI);
        for _ in 0..20 {
            let cmd = hold_ball(&P, &keeper, &ball, Some(&taker), 0.7);
            execute(&P, &mut keeper, &mut ball, cmd, &mut rng);
            advance_player(&P, &mut keeper, &mut rng);
            advance_ball(&P, &mut ball, &mut rng);
            assert!(keeper.pos.dist(ball.pos) < P.kickable_area(), "the ball stays kickable");
        }
        // The ball sits on the side away from the taker (x < 0 side, at ±45°).
        let rel = ball.pos - keeper.pos;
        assert!(rel.x < 0.0, "{rel:?}");
    }

    #[test]
    fn moving_turns_first_then_dashes() {
        let r = ReachTable::new(&P);
        let body = Body::at(Vec2::ZERO, 0.0);
        assert!(matches!(move_to(&P, &r, &body, Vec2::new(5.0, 0.0)), Command::Dash { power } if power == 100.0));
        assert!(matches!(move_to(&P, &r, &body, Vec2::new(0.0, 5.0)), Command::Turn { .. }));
        // Backing onto a point 2 m behind.
        assert!(matches!(move_to(&P, &r, &body, Vec2::new(-2.0, 0.0)), Command::Dash { power } if power < 0.0));
        // Fast and facing away: brake first.
        let fast = Body { vel: Vec2::new(1.0, 0.0), ..body };
        assert!(matches!(move_to(&P, &r, &fast, Vec2::new(-8.0, 0.5)), Command::Dash { power } if power < 0.0));
    }
}
