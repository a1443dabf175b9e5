//! One 3 vs 2 Keepaway game: the referee, the players' behaviours and the
//! macro-action interface the keeper with the ball is driven through.
//!
//! The referee (rcssserver's `KeepawayRef`): at the start of an episode the
//! keepers stand in three corners of the 20 m × 20 m region, each up to 3 m
//! in from it on both axes (a random corner for the first keeper, the next
//! corners for the others), both takers in the fourth corner likewise, and
//! the ball at rest 4 m in from the first corner on both axes. After every
//! cycle the episode ends when the ball has left the region ("o"), or when
//! a taker has had the ball within its kickable area for 4 cycles without a
//! keeper touching it in between ("t"). The duration is the number of cycles.
//!
//! Every cycle, each player sends one command:
//! - the keeper with the ball kickable (the one closest to it if two) runs
//!   its macro-action: [`KeeperAction::Hold`] (one cycle) or a pass to the
//!   nearer or farther teammate (end speed 1.7 m/cycle), which continues on
//!   its own while the ball stays kickable the next cycle;
//! - the other keepers run Receive: the keeper that can reach the ball
//!   first intercepts it, the others GetOpen (`players`);
//! - the takers run their hand-coded policy (`players`).
//!
//! [`Keepaway::run`] simulates cycles until the keeper with the ball must
//! choose (returning [`Status::Decision`]) or the episode ends; [`Keepaway::act`]
//! applies the choice and runs on. The keeper's SMDP reward is the number of
//! cycles since its previous action ([`Keepaway::last_action_cycle`]).
//!
//! What it is not: a network server; perception is exact, there are no
//! collisions and no stamina (see the report's deviations). It knows no
//! learner: policies live outside this module.

use rand::Rng;
use rlfd_rl::random::{below, uniform01};
use serde::{Deserialize, Serialize};
use thiserror::Error;

use super::geometry::Vec2;
use super::players::{GetOpenGrid, Region, get_open, least_congested_points, taker_command};
use super::server::{Ball, Body, Command, ServerParams, advance_ball, advance_player, execute};
use super::skills::{BallForecast, InterceptPlan, ReachTable, hold_ball, intercept, kick_to, plan_intercept};
use super::state::{KeeperAction, STATE_VARS, sort_by_distance, state_vars};

/// Number of keepers.
pub const KEEPERS: usize = 3;

/// Number of takers.
pub const TAKERS: usize = 2;

/// Cycles per simulated second (one cycle is 100 ms).
pub const CYCLES_PER_SECOND: f64 = 10.0;

/// Cycles per simulated hour.
pub const CYCLES_PER_HOUR: u64 = 36_000;

/// A parameter of the simulator outside its domain.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("keepaway parameter `{name}` = {value} is invalid: {expected}")]
pub struct KeepawayParamError {
    /// The field's name.
    pub name: &'static str,
    /// Its value.
    pub value: String,
    /// What it should be.
    pub expected: &'static str,
}

/// The game's parameters: the server's physics and the keepaway task's setup.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct KeepawayParams {
    /// Soccer-server constants.
    pub server: ServerParams,
    /// The region's length and width (m): `keepaway_length`, `keepaway_width`.
    pub length: f64,
    /// See `length`.
    pub width: f64,
    /// Largest random inset of a starting player from its corner, per axis (m).
    pub start_inset: f64,
    /// The ball's start, inset from the first keeper's corner on both axes (m).
    pub ball_inset: f64,
    /// Cycles a taker must control the ball to end the episode (`TURNOVER_TIME`, 4 since rcssserver 10.0.4).
    pub turnover_cycles: u32,
    /// The speed a pass should have when it reaches the teammate (player.conf `pass_end_speed`).
    pub pass_end_speed: f64,
    /// How far beyond its body a keeper holds the ball, as a fraction of the kickable margin (`holdBall`'s 0.7).
    pub keeper_hold_ratio: f64,
    /// The same for a taker (`holdBall(0.3)`).
    pub taker_hold_ratio: f64,
}

impl KeepawayParams {
    /// 3 vs 2 on the 20 m × 20 m region, as the thesis ran it (rcssserver 11.1.0, players v0.6).
    pub fn benchmark() -> Self {
        KeepawayParams {
            server: ServerParams::rcssserver_11(),
            length: 20.0,
            width: 20.0,
            start_inset: 3.0,
            ball_inset: 4.0,
            turnover_cycles: 4,
            pass_end_speed: 1.7,
            keeper_hold_ratio: 0.7,
            taker_hold_ratio: 0.3,
        }
    }

    /// Checks every field once.
    pub fn check(&self) -> Result<(), KeepawayParamError> {
        let bad = |name: &'static str, value: f64, expected: &'static str| {
            Err(KeepawayParamError { name, value: value.to_string(), expected })
        };
        for (name, v) in [("length", self.length), ("width", self.width), ("pass_end_speed", self.pass_end_speed)] {
            if !(v.is_finite() && v > 0.0) {
                return bad(name, v, "a finite number > 0");
            }
        }
        if !(self.start_inset >= 0.0 && 2.0 * self.start_inset < self.length.min(self.width)) {
            return bad("start_inset", self.start_inset, "at least 0 and under half the region");
        }
        if !(self.ball_inset >= 0.0 && 2.0 * self.ball_inset < self.length.min(self.width)) {
            return bad("ball_inset", self.ball_inset, "at least 0 and under half the region");
        }
        if self.turnover_cycles == 0 {
            return bad("turnover_cycles", 0.0, "at least 1");
        }
        for (name, v) in [("keeper_hold_ratio", self.keeper_hold_ratio), ("taker_hold_ratio", self.taker_hold_ratio)] {
            if !(0.0..=1.0).contains(&v) {
                return bad(name, v, "a fraction in [0, 1]");
            }
        }
        let s = &self.server;
        for (name, v) in [
            ("ball_decay", s.ball_decay),
            ("player_decay", s.player_decay),
            ("ball_rand", s.ball_rand),
            ("player_rand", s.player_rand),
        ] {
            if !(0.0..1.0).contains(&v) {
                return bad(name, v, "a number in [0, 1)");
            }
        }
        for (name, v) in [
            ("ball_size", s.ball_size),
            ("player_size", s.player_size),
            ("ball_speed_max", s.ball_speed_max),
            ("ball_accel_max", s.ball_accel_max),
            ("player_speed_max", s.player_speed_max),
            ("player_accel_max", s.player_accel_max),
            ("dash_power_rate", s.dash_power_rate),
            ("kick_power_rate", s.kick_power_rate),
            ("kickable_margin", s.kickable_margin),
            ("max_power", s.max_power),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return bad(name, v, "a finite number > 0");
            }
        }
        if !(s.inertia_moment.is_finite() && s.inertia_moment >= 0.0) {
            return bad("inertia_moment", s.inertia_moment, "a finite number ≥ 0");
        }
        Ok(())
    }

    /// The region.
    pub fn region(&self) -> Region {
        Region { length: self.length, width: self.width }
    }
}

/// Why an episode ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum EndCause {
    /// The ball left the region (the referee's "o").
    Out,
    /// A taker kept the ball for the turnover time ("t").
    Taken,
}

/// What [`Keepaway::run`] stopped for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Keeper `0..3` has the ball and must choose a macro-action.
    Decision(usize),
    /// The episode is over.
    Ended(EndCause),
}

/// Where everything was at the start of a cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Snapshot {
    /// The cycle (from the episode's start).
    pub cycle: u32,
    /// The ball's position.
    pub ball: Vec2,
    /// The ball's velocity.
    pub ball_vel: Vec2,
    /// The keepers' positions, by keeper number.
    pub keepers: [Vec2; KEEPERS],
    /// The takers' positions.
    pub takers: [Vec2; TAKERS],
}

/// The last snapshots of the episode, for observers who react with a delay.
#[derive(Clone, Debug)]
struct History {
    ring: Vec<Snapshot>,
    len: usize,
    next: usize,
}

impl History {
    fn new(capacity: usize) -> History {
        History { ring: vec![Snapshot::default(); capacity.max(1)], len: 0, next: 0 }
    }

    fn clear(&mut self) {
        self.len = 0;
        self.next = 0;
    }

    fn push(&mut self, s: Snapshot) {
        let cap = self.ring.len();
        self.ring[self.next] = s;
        self.next = (self.next + 1) % cap;
        self.len = (self.len + 1).min(cap);
    }

    /// The snapshot `ago` cycles back (0: the latest), the oldest kept if fewer.
    fn ago(&self, ago: usize) -> Option<&Snapshot> {
        if self.len == 0 {
            return None;
        }
        let cap = self.ring.len();
        let back = ago.min(self.len - 1);
        Some(&self.ring[(self.next + cap - 1 - back) % cap])
    }
}

/// A 3 vs 2 Keepaway game (see the module docs).
#[derive(Clone, Debug)]
pub struct Keepaway {
    params: KeepawayParams,
    region: Region,
    grid: GetOpenGrid,
    reach: ReachTable,
    ball: Ball,
    keepers: [Body; KEEPERS],
    takers: [Body; TAKERS],
    cycle: u32,
    take_time: u32,
    last_action: [Option<KeeperAction>; KEEPERS],
    last_action_cycle: [Option<u32>; KEEPERS],
    pending: Option<usize>,
    ended: Option<EndCause>,
    history: Option<History>,
    trace: Option<Vec<Snapshot>>,
}

impl Keepaway {
    /// A game with checked parameters (call [`Keepaway::reset`] before running).
    pub fn new(params: KeepawayParams) -> Result<Keepaway, KeepawayParamError> {
        params.check()?;
        let region = params.region();
        Ok(Keepaway {
            grid: GetOpenGrid::new(&region),
            reach: ReachTable::new(&params.server),
            region,
            params,
            ball: Ball::default(),
            keepers: [Body::default(); KEEPERS],
            takers: [Body::default(); TAKERS],
            cycle: 0,
            take_time: 0,
            last_action: [None; KEEPERS],
            last_action_cycle: [None; KEEPERS],
            pending: None,
            ended: Some(EndCause::Out),
            history: None,
            trace: None,
        })
    }

    /// The benchmark game ([`KeepawayParams::benchmark`]).
    pub fn benchmark() -> Keepaway {
        Keepaway::new(KeepawayParams::benchmark()).expect("the benchmark parameters are valid")
    }

    /// Keeps the last `capacity` snapshots of every episode (for observers with a reaction delay).
    pub fn keep_history(&mut self, capacity: usize) {
        self.history = Some(History::new(capacity));
    }

    /// Records every cycle of the episodes from the next reset on (for pictures); `false` stops.
    pub fn record_trace(&mut self, on: bool) {
        self.trace = on.then(Vec::new);
    }

    /// The recorded cycles of the current episode (empty unless recording).
    pub fn trace(&self) -> &[Snapshot] {
        self.trace.as_deref().unwrap_or(&[])
    }

    /// The parameters.
    pub fn params(&self) -> &KeepawayParams {
        &self.params
    }

    /// Cycles since the episode started.
    pub fn cycle(&self) -> u32 {
        self.cycle
    }

    /// The ball.
    pub fn ball(&self) -> &Ball {
        &self.ball
    }

    /// The keepers, by number.
    pub fn keepers(&self) -> &[Body; KEEPERS] {
        &self.keepers
    }

    /// The takers.
    pub fn takers(&self) -> &[Body; TAKERS] {
        &self.takers
    }

    /// Why the episode ended, if it has.
    pub fn ended(&self) -> Option<EndCause> {
        self.ended
    }

    /// The cycle at which keeper `k` last acted this episode (a decision or
    /// the continuation of a pass), if it has.
    pub fn last_action_cycle(&self, k: usize) -> Option<u32> {
        self.last_action_cycle[k]
    }

    /// Where everything is now.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            cycle: self.cycle,
            ball: self.ball.pos,
            ball_vel: self.ball.vel,
            keepers: [self.keepers[0].pos, self.keepers[1].pos, self.keepers[2].pos],
            takers: [self.takers[0].pos, self.takers[1].pos],
        }
    }

    /// The snapshot `ago` cycles back in this episode (the episode's first if
    /// it is younger); `None` without [`Keepaway::keep_history`].
    pub fn snapshot_ago(&self, ago: usize) -> Option<&Snapshot> {
        self.history.as_ref().and_then(|h| h.ago(ago))
    }

    /// The 13 state variables from keeper `k`'s view (see `state`).
    pub fn state_vars(&self, k: usize, out: &mut [f64; STATE_VARS]) {
        let mates = self.mates_of(k);
        let takers = [self.takers[0].pos, self.takers[1].pos];
        state_vars(self.keepers[k].pos, &mates, &takers, Vec2::ZERO, out);
    }

    /// The two other keepers' positions.
    #[inline]
    fn mates_of(&self, k: usize) -> [Vec2; 2] {
        let (a, b) = other_two(k);
        [self.keepers[a].pos, self.keepers[b].pos]
    }

    /// The keeper number a pass action of keeper `k` goes to (the nearer or farther teammate now).
    pub fn pass_receiver(&self, k: usize, action: KeeperAction) -> Option<usize> {
        let (a, b) = other_two(k);
        let order = sort_by_distance(self.keepers[k].pos, &self.mates_of(k));
        let ids = [a, b];
        match action {
            KeeperAction::Hold => None,
            KeeperAction::Pass1 => Some(ids[order[0]]),
            KeeperAction::Pass2 => Some(ids[order[1]]),
        }
    }

    /// Starts an episode: the referee's placement (see the module docs).
    pub fn reset<R: Rng + ?Sized>(&mut self, rng: &mut R) {
        let (hl, hw, inset) = (0.5 * self.params.length, 0.5 * self.params.width, self.params.start_inset);
        let first = below(rng, KEEPERS);
        for p in 0..KEEPERS {
            let (dx, dy) = (inset * uniform01(rng), inset * uniform01(rng));
            let pos = match (first + p) % KEEPERS {
                0 => Vec2::new(-hl + dx, -hw + dy),
                1 => Vec2::new(hl - dx, -hw + dy),
                _ => Vec2::new(hl - dx, hw - dy),
            };
            self.keepers[p] = Body::at(pos, 0.0);
        }
        for t in 0..TAKERS {
            let (dx, dy) = (inset * uniform01(rng), inset * uniform01(rng));
            self.takers[t] = Body::at(Vec2::new(-hl + dx, hw - dy), 0.0);
        }
        // Body directions are not part of the referee's placement; drawn uniformly.
        for b in self.keepers.iter_mut().chain(self.takers.iter_mut()) {
            b.set_angle(std::f64::consts::PI * (2.0 * uniform01(rng) - 1.0));
        }
        self.ball =
            Ball { pos: Vec2::new(-hl + self.params.ball_inset, -hw + self.params.ball_inset), ..Ball::default() };
        self.cycle = 0;
        self.take_time = 0;
        self.last_action = [None; KEEPERS];
        self.last_action_cycle = [None; KEEPERS];
        self.pending = None;
        self.ended = None;
        if let Some(h) = &mut self.history {
            h.clear();
        }
        if let Some(t) = &mut self.trace {
            t.clear();
        }
        self.record();
    }

    /// The keeper that must act now: the one with the ball kickable (the
    /// closest to the ball if several).
    fn holder(&self) -> Option<usize> {
        let ka = self.params.server.kickable_area();
        let mut best: Option<(usize, f64)> = None;
        for (k, body) in self.keepers.iter().enumerate() {
            let d2 = body.pos.dist2(self.ball.pos);
            if d2 < ka * ka && best.is_none_or(|(_, b)| d2 < b) {
                best = Some((k, d2));
            }
        }
        best.map(|(k, _)| k)
    }

    /// Simulates cycles until a keeper must choose or the episode ends.
    pub fn run<R: Rng + ?Sized>(&mut self, rng: &mut R) -> Status {
        if let Some(k) = self.pending {
            return Status::Decision(k);
        }
        loop {
            if let Some(cause) = self.ended {
                return Status::Ended(cause);
            }
            match self.holder() {
                Some(k) => {
                    let continuing = match (self.last_action[k], self.last_action_cycle[k]) {
                        (Some(a), Some(c)) => a.is_pass() && c + 1 == self.cycle,
                        _ => false,
                    };
                    if continuing {
                        self.last_action_cycle[k] = Some(self.cycle);
                        let action = self.last_action[k].expect("a pass in progress");
                        self.step_cycle(Some((k, action)), rng);
                    } else {
                        self.pending = Some(k);
                        return Status::Decision(k);
                    }
                }
                None => self.step_cycle(None, rng),
            }
        }
    }

    /// The keeper awaiting a decision, if any.
    pub fn pending(&self) -> Option<usize> {
        self.pending
    }

    /// Applies the pending keeper's choice, then runs on (see [`Keepaway::run`]).
    ///
    /// Panics if no keeper is waiting for a decision (a driver bug).
    pub fn act<R: Rng + ?Sized>(&mut self, action: KeeperAction, rng: &mut R) -> Status {
        let k = self.pending.take().expect("act() needs a keeper waiting for a decision; call run() first");
        self.last_action[k] = Some(action);
        self.last_action_cycle[k] = Some(self.cycle);
        self.step_cycle(Some((k, action)), rng);
        self.run(rng)
    }

    /// One cycle: every player's command, the physics, the referee.
    fn step_cycle<R: Rng + ?Sized>(&mut self, holder: Option<(usize, KeeperAction)>, rng: &mut R) {
        let p = &self.params.server;
        let ka2 = p.kickable_area() * p.kickable_area();
        let controlled = self.keepers.iter().chain(self.takers.iter()).any(|b| b.pos.dist2(self.ball.pos) < ka2);
        let forecast = if controlled { BallForecast::held(self.ball.pos) } else { BallForecast::new(p, &self.ball) };
        // The keeper that reaches the ball first (ties: the lower number). A
        // keeper with the ball in its kickable area needs 0 cycles, so then
        // no plan is needed.
        let fastest_plan = match (0..KEEPERS).find(|&k| self.keepers[k].pos.dist2(self.ball.pos) < ka2) {
            Some(k) => (k, InterceptPlan { cycles: 0, point: self.ball.pos }),
            None => {
                let mut best = (0, plan_intercept(p, &self.reach, &self.keepers[0], &forecast));
                for k in 1..KEEPERS {
                    let plan = plan_intercept(p, &self.reach, &self.keepers[k], &forecast);
                    if plan.cycles < best.1.cycles {
                        best = (k, plan);
                    }
                }
                best
            }
        };
        let (fastest, fastest_plan) = fastest_plan;
        let (closest_taker, taker_dist) = closest(&self.takers, self.ball.pos);
        let (closest_keeper, keeper_dist) = closest(&self.keepers, self.ball.pos);

        let holder_index = holder.map(|(h, _)| h);
        let supporters: [bool; KEEPERS] = std::array::from_fn(|k| Some(k) != holder_index && k != fastest);
        let mut open_points = [Vec2::ZERO; KEEPERS];
        if supporters.iter().any(|&s| s) {
            let players =
                [self.keepers[0].pos, self.keepers[1].pos, self.keepers[2].pos, self.takers[0].pos, self.takers[1].pos];
            least_congested_points(&self.grid, Vec2::ZERO, fastest_plan.point, &players, supporters, &mut open_points);
        }
        let mut commands = [Command::Idle; KEEPERS + TAKERS];
        for k in 0..KEEPERS {
            commands[k] = match holder {
                Some((h, action)) if h == k => match action {
                    KeeperAction::Hold => hold_ball(
                        p,
                        &self.keepers[k],
                        &self.ball,
                        Some(&self.takers[closest_taker]),
                        self.params.keeper_hold_ratio,
                    ),
                    pass => {
                        let to = self.pass_receiver(k, pass).expect("a pass has a receiver");
                        kick_to(
                            p,
                            &self.keepers[k],
                            &self.ball,
                            self.keepers[to].pos,
                            self.params.pass_end_speed,
                            taker_dist,
                        )
                    }
                },
                _ if k == fastest => intercept(p, &self.reach, &self.keepers[k], &fastest_plan, &forecast),
                _ => get_open(p, &self.reach, &self.keepers[k], &self.ball, open_points[k]),
            };
        }
        for t in 0..TAKERS {
            commands[KEEPERS + t] = taker_command(
                p,
                &self.reach,
                &self.takers,
                t,
                &self.ball,
                &forecast,
                (&self.keepers[closest_keeper], keeper_dist),
            );
        }

        for (k, cmd) in commands[..KEEPERS].iter().enumerate() {
            execute(p, &mut self.keepers[k], &mut self.ball, *cmd, rng);
        }
        for (t, cmd) in commands[KEEPERS..].iter().enumerate() {
            execute(p, &mut self.takers[t], &mut self.ball, *cmd, rng);
        }
        advance_ball(p, &mut self.ball, rng);
        for b in self.keepers.iter_mut().chain(self.takers.iter_mut()) {
            advance_player(p, b, rng);
        }
        self.cycle += 1;
        self.referee();
        self.record();
    }

    /// Appends the current positions to the history and the trace, if kept.
    fn record(&mut self) {
        if self.history.is_none() && self.trace.is_none() {
            return;
        }
        let s = self.snapshot();
        if let Some(h) = &mut self.history {
            h.push(s);
        }
        if let Some(t) = &mut self.trace {
            t.push(s);
        }
    }

    /// The referee's analysis after a cycle (`KeepawayRef::analyse`).
    fn referee(&mut self) {
        if !self.region.contains(self.ball.pos) {
            self.ended = Some(EndCause::Out);
            return;
        }
        if self.take_time >= self.params.turnover_cycles {
            self.ended = Some(EndCause::Taken);
            return;
        }
        let ka = self.params.server.kickable_area();
        let ka2 = ka * ka;
        if self.takers.iter().any(|t| t.pos.dist2(self.ball.pos) < ka2) {
            self.take_time += 1;
        } else if self.keepers.iter().any(|k| k.pos.dist2(self.ball.pos) < ka2) {
            self.take_time = 0;
        }
    }

    /// Plays one whole episode with `choose` deciding for the keeper with the
    /// ball; returns its duration in cycles and how it ended.
    pub fn play_episode<R: Rng + ?Sized>(
        &mut self,
        rng: &mut R,
        mut choose: impl FnMut(&Keepaway, usize, &mut R) -> KeeperAction,
    ) -> (u32, EndCause) {
        self.reset(rng);
        let mut status = self.run(rng);
        loop {
            match status {
                Status::Decision(k) => {
                    let a = choose(self, k, rng);
                    status = self.act(a, rng);
                }
                Status::Ended(cause) => return (self.cycle, cause),
            }
        }
    }
}

/// The two keeper numbers other than `k`, in increasing order.
#[inline]
pub fn other_two(k: usize) -> (usize, usize) {
    match k {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    }
}

/// The body closest to `to` (the first on ties) and its distance.
#[inline]
fn closest<const N: usize>(bodies: &[Body; N], to: Vec2) -> (usize, f64) {
    let mut best = (0, f64::INFINITY);
    for (i, b) in bodies.iter().enumerate() {
        let d2 = b.pos.dist2(to);
        if d2 < best.1 {
            best = (i, d2);
        }
    }
    (best.0, best.1.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_rl::random::seeded;

    fn always(a: KeeperAction) -> impl FnMut(&Keepaway, usize, &mut rlfd_rl::random::SimRng) -> KeeperAction {
        move |_, _, _| a
    }

    #[test]
    fn placement_follows_the_referee() {
        let mut game = Keepaway::benchmark();
        let mut rng = seeded(11);
        for _ in 0..50 {
            game.reset(&mut rng);
            assert_eq!(game.ball().pos, Vec2::new(-6.0, -6.0));
            let mut corners: Vec<(i8, i8)> = game
                .keepers()
                .iter()
                .map(|k| {
                    assert!(k.pos.x.abs() >= 7.0 && k.pos.y.abs() >= 7.0 && k.pos.x.abs() <= 10.0);
                    (k.pos.x.signum() as i8, k.pos.y.signum() as i8)
                })
                .collect();
            corners.sort();
            assert_eq!(corners, vec![(-1, -1), (1, -1), (1, 1)]);
            for t in game.takers() {
                assert!(t.pos.x <= -7.0 && t.pos.y >= 7.0);
            }
        }
    }

    #[test]
    fn episodes_end_and_are_deterministic() {
        let run = |seed| {
            let mut game = Keepaway::benchmark();
            let mut rng = seeded(seed);
            (0..20).map(|_| game.play_episode(&mut rng, always(KeeperAction::Hold))).collect::<Vec<_>>()
        };
        let a = run(5);
        assert_eq!(a, run(5));
        assert_ne!(a, run(6));
        // Always Hold loses the ball to the takers within seconds.
        let mean = a.iter().map(|e| f64::from(e.0)).sum::<f64>() / 20.0;
        assert!(mean > 15.0 && mean < 100.0, "{mean}");
        assert!(a.iter().filter(|e| e.1 == EndCause::Taken).count() >= 10);
    }

    #[test]
    fn decisions_come_only_with_the_ball_kickable_and_passes_continue() {
        let mut game = Keepaway::benchmark();
        let mut rng = seeded(3);
        let ka = game.params().server.kickable_area();
        let mut decisions = 0;
        for _ in 0..30 {
            game.reset(&mut rng);
            let mut status = game.run(&mut rng);
            while let Status::Decision(k) = status {
                decisions += 1;
                assert!(game.keepers()[k].pos.dist(game.ball().pos) < ka);
                let cycle = game.cycle();
                if let Some(last) = game.last_action_cycle(k) {
                    assert!(last < cycle);
                }
                status = game.act(KeeperAction::Pass2, &mut rng);
            }
            let n = game.cycle();
            assert!(n > 0);
        }
        assert!(decisions > 30);
    }

    #[test]
    fn the_turnover_needs_four_cycles_of_taker_control() {
        // A keeper that never gets the ball: put the ball at a taker's feet.
        let mut game = Keepaway::benchmark();
        let mut rng = seeded(8);
        game.reset(&mut rng);
        game.ball.pos = game.takers[0].pos + Vec2::new(0.5, 0.0);
        for k in 0..KEEPERS {
            game.keepers[k].pos = Vec2::new(8.0, 8.0 - k as f64);
        }
        let status = game.run(&mut rng);
        assert_eq!(status, Status::Ended(EndCause::Taken));
        // take_time counts 1..4 over four analyses; the fifth ends the episode.
        assert_eq!(game.cycle(), 5);
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config::with_cases(24))]
        // Whatever the keepers choose, every decision comes with the ball
        // kickable, the ball stays in the region until the last cycle, and the
        // episode ends with the referee's reason.
        #[test]
        fn any_choices_give_a_well_formed_episode(seed in 0u64..1_000_000, choices in proptest::collection::vec(0usize..3, 1..64)) {
            let mut game = Keepaway::benchmark();
            let mut rng = seeded(seed);
            game.reset(&mut rng);
            let ka = game.params().server.kickable_area();
            let region = game.params().region();
            let mut i = 0;
            let mut status = game.run(&mut rng);
            while let Status::Decision(k) = status {
                proptest::prop_assert!(game.keepers()[k].pos.dist(game.ball().pos) < ka);
                proptest::prop_assert!(region.contains(game.ball().pos));
                status = game.act(KeeperAction::ALL[choices[i % choices.len()]], &mut rng);
                i += 1;
                proptest::prop_assert!(game.cycle() < 100_000);
            }
            let Status::Ended(cause) = status else { unreachable!() };
            proptest::prop_assert_eq!(game.ended(), Some(cause));
            if cause == EndCause::Out {
                proptest::prop_assert!(!region.contains(game.ball().pos));
            }
        }
    }

    #[test]
    fn history_reaches_back_within_the_episode() {
        let mut game = Keepaway::benchmark();
        game.keep_history(16);
        let mut rng = seeded(4);
        game.reset(&mut rng);
        assert_eq!(game.snapshot_ago(0).unwrap().cycle, 0);
        let mut status = game.run(&mut rng);
        for _ in 0..40 {
            if let Status::Decision(_) = status {
                status = game.act(KeeperAction::Hold, &mut rng);
            }
        }
        let now = game.cycle();
        assert!(now > 20, "{now}");
        assert_eq!(game.snapshot_ago(0).unwrap(), &game.snapshot());
        assert_eq!(game.snapshot_ago(3).unwrap().cycle, now - 3);
        assert_eq!(game.snapshot_ago(1000).unwrap().cycle, now - 15);
    }
}
