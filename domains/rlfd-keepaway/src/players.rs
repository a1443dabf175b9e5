//! The hand-coded parts of the players (`KeepawayPlayer.cc` and
//! `BasicPlayer.cc` of the UT-Austin keepaway players v0.6): who goes for
//! the ball, the keepers' GetOpen and the takers' policy, for any number of
//! keepers and takers.
//!
//! - **Fastest to the ball** (`createInterceptFeatures`): for each future
//!   cycle `i` of the ball's path, every keeper that could be there in time
//!   (`distance / player_speed_max < i + 1`) is asked how many cycles it
//!   needs to reach that point ([`cycles_to_point`]); the first `i` that some
//!   keeper can make in `i` cycles or fewer decides it (the lower number on ties).
//! - **GetOpen** (`getOpenForPassFromInRectangle`): from where the fastest
//!   teammate will get the ball (`pass_from`), score a 5 × 5 grid over the
//!   region with a 15 % border, skip points with a taker inside the pass cone
//!   from `pass_from` (half width 0.3 × distance, between the two points and
//!   closer than the point), and take the least congested point, congestion
//!   being `Σ 1/dist` over every other player; the region's centre if no point
//!   is safe. Within 1.5 m of the point the keeper turns to the ball, else it
//!   moves there (`moveToPos` with 7°).
//! - **Takers** (`KeepawayPlayer::taker`): the taker closest to the ball holds
//!   it when it is kickable (`holdBall(0.3)`); with more than two takers, a
//!   taker that is neither of the two closest to the ball marks the keeper
//!   most open for a pass from the keeper fastest to the ball
//!   (`markMostOpenOpponent`: 4 m from it toward the ball); a taker whose
//!   teammate is the player closest to the ball with the ball kickable turns
//!   to the ball; otherwise it intercepts the ball.

use super::geometry::{RAD_PER_DEG, Vec2};
use super::server::{Body, Command};
use super::skills::{
    BallForecast, INTERCEPT_HORIZON, InterceptMemory, Interceptor, Kinematics, cycles_to_point, hold_ball, move_to_pos,
    turn_body_to_point,
};

/// Points per side of the GetOpen grid.
pub const GRID: usize = 5;

/// The border of the GetOpen grid, as a fraction of each side.
pub const GRID_BORDER: f64 = 0.15;

/// Half-width of the pass cone at unit distance.
pub const CONE_WIDTH: f64 = 0.3;

/// Within this distance of its GetOpen point a keeper turns to the ball (m).
pub const GET_OPEN_BUFFER: f64 = 1.5;

/// `cos(7°)` (`player_when_to_turn`), for the keepers' moves.
pub const COS_WHEN_TO_TURN: f64 = 0.992_546_151_641_322;

/// `cos(25°)`, the marking taker's `moveToPos` angle.
const COS_MARK_TURN: f64 = 0.906_307_787_036_649_9;

/// How far from the marked keeper a marking taker stands (m).
pub const MARK_DISTANCE: f64 = 4.0;

/// The keepaway region, centred at the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region {
    /// Length along x (m).
    pub length: f64,
    /// Width along y (m).
    pub width: f64,
}

impl Region {
    /// Whether `p` lies strictly inside the region (the referee's test).
    #[inline]
    pub fn contains(&self, p: Vec2) -> bool {
        p.x.abs() < 0.5 * self.length && p.y.abs() < 0.5 * self.width
    }

    /// The GetOpen grid, x outer and y inner, from the low corner.
    pub fn grid(&self) -> [Vec2; GRID * GRID] {
        let mut out = [Vec2::ZERO; GRID * GRID];
        let step_x = self.length * (1.0 - 2.0 * GRID_BORDER) / (GRID - 1) as f64;
        let step_y = self.width * (1.0 - 2.0 * GRID_BORDER) / (GRID - 1) as f64;
        let x0 = -0.5 * self.length + GRID_BORDER * self.length;
        let y0 = -0.5 * self.width + GRID_BORDER * self.width;
        for i in 0..GRID {
            for j in 0..GRID {
                out[i * GRID + j] = Vec2::new(x0 + i as f64 * step_x, y0 + j as f64 * step_y);
            }
        }
        out
    }
}

/// Whether `obj` lies in the pass cone from `start` to `end` (Trilearn's
/// `getNrInSetInCone`): its foot on the line is between the two points, its
/// distance from the line under `width` times the foot's distance from
/// `start`, and it is closer to `start` than `end` is. Written without
/// division: with `d = end − start`, `r = obj − start` and `u = r·d`, the foot
/// is `d u/|d|²`, so the tests are `0 ≤ u ≤ |d|²`, `|r|² < |d|²` and
/// `|r |d|² − d u|² < width² u² |d|²`.
#[inline]
pub fn in_cone(start: Vec2, end: Vec2, obj: Vec2, width: f64) -> bool {
    let d = end - start;
    let len2 = d.norm2();
    if len2 == 0.0 {
        return false;
    }
    let r = obj - start;
    let u = r.dot(d);
    if u < 0.0 || u > len2 || r.norm2() >= len2 {
        return false;
    }
    (r * len2 - d * u).norm2() < width * width * u * u * len2
}

/// The most players GetOpen considers.
pub const MAX_PLAYERS: usize = super::server::MAX_PLAYERS;

/// The GetOpen grid, also as single-precision coordinate arrays padded to a
/// multiple of four points (the padding is never safe) so the per-point
/// loops run four points per instruction. The choice is an argmin over 25
/// points, which single precision decides as double would up to exact ties.
#[derive(Clone, Debug)]
pub struct GetOpenGrid {
    /// The 25 points.
    pub points: [Vec2; GRID * GRID],
    x: [f32; GetOpenGrid::LANES],
    y: [f32; GetOpenGrid::LANES],
    real: [bool; GetOpenGrid::LANES],
}

impl GetOpenGrid {
    /// 25 points padded to 28.
    pub const LANES: usize = 28;

    /// The grid of a region.
    pub fn new(region: &Region) -> GetOpenGrid {
        let points = region.grid();
        let n = GRID * GRID;
        GetOpenGrid {
            points,
            x: std::array::from_fn(|i| if i < n { points[i].x as f32 } else { 0.0 }),
            y: std::array::from_fn(|i| if i < n { points[i].y as f32 } else { 0.0 }),
            real: std::array::from_fn(|i| i < n),
        }
    }
}

/// Every player's inverse distance to every GetOpen grid point (single
/// precision, four points per instruction), computed once per cycle for all
/// the keepers getting open.
#[derive(Clone, Debug)]
pub struct Congestion {
    inv: [[f32; GetOpenGrid::LANES]; MAX_PLAYERS],
    total: [f32; GetOpenGrid::LANES],
}

impl Congestion {
    /// The table for `players` (keepers then takers).
    #[inline]
    pub fn new(grid: &GetOpenGrid, players: &[Vec2]) -> Congestion {
        const N: usize = GetOpenGrid::LANES;
        let mut inv = [[0.0f32; N]; MAX_PLAYERS];
        let mut total = [0.0f32; N];
        for (row, q) in inv.iter_mut().zip(players) {
            inverse_distances(grid, *q, row);
            for i in 0..N {
                total[i] += row[i];
            }
        }
        Congestion { inv, total }
    }

    /// [`Congestion::best_point`] for keeper `k` alone, from `players` (keepers
    /// then takers), without the table of every player's row: the same sums
    /// in the same order, so the same point.
    #[inline]
    pub fn best_point_for(
        grid: &GetOpenGrid,
        players: &[Vec2],
        pass_from: Vec2,
        takers: &[Vec2],
        k: usize,
        centre: Vec2,
    ) -> Vec2 {
        const N: usize = GetOpenGrid::LANES;
        let mut total = [0.0f32; N];
        let mut mine = [0.0f32; N];
        let mut row = [0.0f32; N];
        for (j, q) in players.iter().enumerate() {
            inverse_distances(grid, *q, &mut row);
            for i in 0..N {
                total[i] += row[i];
            }
            if j == k {
                mine = row;
            }
        }
        choose_point(grid, &total, &mine, pass_from, takers, centre)
    }

    /// The least congested safe grid point for keeper `k` to get open for a
    /// pass from `pass_from` with the takers at `takers`; `centre` when no
    /// point is safe (Trilearn's `leastCongestedPointForPassInRectangle`). A
    /// point is unsafe when a taker lies in the pass cone; congestion is
    /// `Σ 1/dist` over every player but `k`; the first strictly least wins.
    #[inline]
    pub fn best_point(&self, grid: &GetOpenGrid, pass_from: Vec2, takers: &[Vec2], k: usize, centre: Vec2) -> Vec2 {
        choose_point(grid, &self.total, &self.inv[k], pass_from, takers, centre)
    }
}

/// One player's inverse distance to every grid lane (0 at distance 0).
#[inline]
fn inverse_distances(grid: &GetOpenGrid, q: Vec2, row: &mut [f32; GetOpenGrid::LANES]) {
    let (qx, qy) = (q.x as f32, q.y as f32);
    for i in 0..GetOpenGrid::LANES {
        let (dx, dy) = (grid.x[i] - qx, grid.y[i] - qy);
        let d2 = dx * dx + dy * dy;
        // Computed in every lane and then selected (no branch), so the loop
        // runs four lanes per instruction; IEEE `sqrt` and `/` give the same
        // bits either way.
        let r = 1.0 / d2.sqrt();
        row[i] = if d2 > 0.0 { r } else { 0.0 };
    }
}

/// [`Congestion::best_point`] from the summed inverse distances `total` and
/// the keeper's own `mine`.
#[inline]
fn choose_point(
    grid: &GetOpenGrid,
    total: &[f32; GetOpenGrid::LANES],
    mine: &[f32; GetOpenGrid::LANES],
    pass_from: Vec2,
    takers: &[Vec2],
    centre: Vec2,
) -> Vec2 {
    const N: usize = GetOpenGrid::LANES;
    let (gx, gy) = (&grid.x, &grid.y);
    let (fx, fy) = (pass_from.x as f32, pass_from.y as f32);
    let w2 = (CONE_WIDTH * CONE_WIDTH) as f32;
    // The cone's axis per point, shared by the takers.
    let mut dx = [0.0f32; N];
    let mut dy = [0.0f32; N];
    let mut len2 = [0.0f32; N];
    for i in 0..N {
        dx[i] = gx[i] - fx;
        dy[i] = gy[i] - fy;
        len2[i] = dx[i] * dx[i] + dy[i] * dy[i];
    }
    // Safety as 32-bit lane masks (all ones: safe), so the tests run four
    // points per instruction.
    let mut safe: [u32; N] = std::array::from_fn(|i| if grid.real[i] { u32::MAX } else { 0 });
    for t in takers {
        let (rx, ry) = (t.x as f32 - fx, t.y as f32 - fy);
        let r2 = rx * rx + ry * ry;
        for i in 0..N {
            let (dx, dy, len2) = (dx[i], dy[i], len2[i]);
            let u = rx * dx + ry * dy;
            let (ex, ey) = (rx * len2 - dx * u, ry * len2 - dy * u);
            let inside =
                (len2 > 0.0) & (u >= 0.0) & (u <= len2) & (r2 < len2) & (ex * ex + ey * ey < w2 * u * u * len2);
            safe[i] &= u32::from(inside).wrapping_sub(1);
        }
    }
    // The minimum of (congestion bits, index) keys, which order as
    // (congestion, index) because congestion is positive; found with
    // conditional moves instead of unpredictable branches.
    let mut best = u64::MAX;
    for i in 0..GRID * GRID {
        let congestion = (total[i] - mine[i]).max(0.0);
        let key = (u64::from(congestion.to_bits()) << 8) | i as u64;
        best = best.min(if safe[i] != 0 { key } else { u64::MAX });
    }
    if best == u64::MAX { centre } else { grid.points[(best & 0xff) as usize] }
}

/// [`Congestion::best_point`] for every keeper getting open from one
/// `pass_from` (`players`: the keepers, `keepers` of them, then the takers;
/// `out[k]` is `centre` for a keeper not getting open).
pub fn least_congested_points(
    grid: &GetOpenGrid,
    centre: Vec2,
    pass_from: Vec2,
    players: &[Vec2],
    keepers: usize,
    supporters: &[bool],
    out: &mut [Vec2],
) {
    let field = Congestion::new(grid, players);
    for k in 0..keepers {
        out[k] = if supporters[k] { field.best_point(grid, pass_from, &players[keepers..], k, centre) } else { centre };
    }
}

/// A supporting keeper's command: move to its GetOpen point, or turn to the ball there.
pub fn get_open(k: &Kinematics, me: &Body, ball: Vec2, point: Vec2) -> Command {
    if me.pos.dist2(point) < GET_OPEN_BUFFER * GET_OPEN_BUFFER {
        turn_body_to_point(k, me, ball, 1)
    } else {
        move_to_pos(k, me, point, COS_WHEN_TO_TURN, 0.0, 1)
    }
}

/// The keeper that gets to the ball first and the cycle at which it does
/// (see the module docs); `bodies` are the keepers.
pub fn fastest_to_ball(k: &Kinematics, bodies: &[Body], ball: &BallForecast) -> (usize, usize) {
    let speed = k.p.player_speed_max;
    let mut last = None;
    for i in 0..=INTERCEPT_HORIZON {
        let at = ball.at[i];
        let mut best: Option<(usize, usize)> = None;
        for (j, b) in bodies.iter().enumerate() {
            if b.pos.dist(at) / speed < (i + 1) as f64 {
                let c = cycles_to_point(k, b, at);
                if best.is_none_or(|(_, m)| c < m) {
                    best = Some((j, c));
                }
            }
        }
        if let Some((j, c)) = best {
            if c <= i {
                return (j, i);
            }
            last = Some(j);
        }
    }
    let j = last.unwrap_or_else(|| closest(bodies, ball.rest).0);
    (j, INTERCEPT_HORIZON + 1)
}

/// The body closest to `to` (the first on ties) and its distance.
#[inline]
pub fn closest(bodies: &[Body], to: Vec2) -> (usize, f64) {
    let mut best = (0, f64::INFINITY);
    for (i, b) in bodies.iter().enumerate() {
        let d2 = b.pos.dist2(to);
        if d2 < best.1 {
            best = (i, d2);
        }
    }
    (best.0, best.1.sqrt())
}

/// Whether `ang` lies in the counter-clockwise interval from `min` to `max`
/// (radians; Trilearn's `isAngInInterval`).
fn ang_in_interval(ang: f64, min: f64, max: f64) -> bool {
    let two_pi = 2.0 * std::f64::consts::PI;
    let norm = |a: f64| a.rem_euclid(two_pi);
    let (a, lo, hi) = (norm(ang), norm(min), norm(max));
    if lo < hi { lo <= a && a <= hi } else { a >= lo || a <= hi }
}

/// Everything a taker's decision reads.
pub struct TakerView<'a> {
    /// The kinematics.
    pub k: &'a Kinematics,
    /// The takers.
    pub takers: &'a [Body],
    /// The keepers.
    pub keepers: &'a [Body],
    /// The ball's path as the takers see it (still while a keeper has it at his feet).
    pub ball: &'a BallForecast,
    /// The ball's path as it is (for a taker with the ball kickable itself).
    pub moving: &'a BallForecast,
    /// The ball now.
    pub ball_now: &'a super::server::Ball,
    /// The keeper fastest to the ball (the takers' view of it).
    pub fastest_keeper: usize,
    /// The current cycle.
    pub cycle: u32,
}

/// The takers' forward direction (their own +x is the field's −x).
pub const TAKER_FORWARD: Vec2 = Vec2 { x: -1.0, y: 0.0 };

/// The goal takers turn to when holding the ball (their opponents' goal, at their own +x).
pub const TAKER_GOAL: Vec2 = Vec2 { x: -52.5, y: 0.0 };

impl TakerView<'_> {
    /// What taker `me` does this cycle (see the module docs).
    pub fn command(&self, me: usize, hold_ratio: f64, memory: &mut InterceptMemory) -> Command {
        let k = self.k;
        let ka = k.ka();
        let body = &self.takers[me];
        let ball = self.ball_now.pos;
        let (closest_taker, my_dist) = (closest(self.takers, ball).0, body.pos.dist(ball));
        if my_dist < ka && closest_taker == me {
            let opp = &self.keepers[closest(self.keepers, ball).0];
            return hold_ball(k, body, self.ball_now, Some(opp), hold_ratio, TAKER_GOAL);
        }
        if self.takers.len() > 2 {
            let mut order: [(f64, usize); super::server::MAX_PLAYERS] =
                [(f64::INFINITY, 0); super::server::MAX_PLAYERS];
            for (i, t) in self.takers.iter().enumerate() {
                order[i] = (t.pos.dist2(ball), i);
            }
            let n = self.takers.len();
            order[..n].sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            if order[0].1 != me && order[1].1 != me {
                return self.mark_most_open(me);
            }
        }
        // Don't mess with a teammate who has the ball (the player closest to
        // it, teammates first on ties, within the kickable area).
        let (mate, dt) = closest(self.takers, ball);
        if mate != me && dt < ka && dt <= closest(self.keepers, ball).1 {
            return turn_body_to_point(k, body, self.ball.after(1), 1);
        }
        let opp_dist = closest(self.keepers, body.pos).1;
        let ball = if my_dist < ka { self.moving } else { self.ball };
        Interceptor { k, ball, forward: TAKER_FORWARD, opp_dist, cycle: self.cycle }.intercept(body, memory)
    }

    /// `markMostOpenOpponent`: the keeper with the fewest takers in the pass
    /// cone from the keeper fastest to the ball (the first of the fewest, the
    /// search starting from that keeper with an impossible count), marked
    /// 4 m from it toward the ball (`mark(…, MARK_BALL)`).
    fn mark_most_open(&self, me: usize) -> Command {
        let k = self.k;
        let body = &self.takers[me];
        let from = self.keepers[self.fastest_keeper].pos;
        let mut target = self.fastest_keeper;
        let mut fewest = usize::MAX;
        for (j, kp) in self.keepers.iter().enumerate() {
            let count = self.takers.iter().filter(|t| in_cone(from, kp.pos, t.pos, CONE_WIDTH)).count();
            if count < fewest {
                fewest = count;
                target = j;
            }
        }
        let opp = self.keepers[target].pos;
        let ball = self.ball_now.pos;
        // The source assumes the marked player moves toward its own goal (one metre along its −x).
        let shifted = opp - TAKER_FORWARD;
        let mark = shifted + (ball - shifted).normalized_or(Vec2::new(1.0, 0.0)) * MARK_DISTANCE;
        if body.pos.dist2(mark) < 2.0 * 2.0 {
            let ang_opp = (opp - body.pos).angle();
            let ang_ball = (ball - body.pos).angle();
            let turn = if ang_in_interval(ang_ball, ang_opp, ang_opp + std::f64::consts::PI) { 80.0 } else { -80.0 };
            let dir = Vec2::from_angle(ang_opp + turn * RAD_PER_DEG);
            return turn_body_to_point(k, body, body.pos + dir, 1);
        }
        move_to_pos(k, body, mark, COS_MARK_TURN, 3.0, 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::server::{Ball, ServerParams};

    #[test]
    fn the_grid_has_a_15_percent_border() {
        let r = Region { length: 20.0, width: 20.0 };
        let g = r.grid();
        assert_eq!(g[0], Vec2::new(-7.0, -7.0));
        assert_eq!(g[1], Vec2::new(-7.0, -3.5));
        assert_eq!(g[12], Vec2::new(0.0, 0.0));
        assert_eq!(g[24], Vec2::new(7.0, 7.0));
        assert!(r.contains(Vec2::new(9.99, -9.99)) && !r.contains(Vec2::new(10.0, 0.0)));
        let big = Region { length: 25.0, width: 25.0 }.grid();
        assert_eq!(big[0], Vec2::new(-8.75, -8.75));
    }

    #[test]
    fn the_cone_is_between_the_points_and_narrow() {
        let (s, e) = (Vec2::ZERO, Vec2::new(10.0, 0.0));
        assert!(in_cone(s, e, Vec2::new(5.0, 1.0), 0.3));
        assert!(!in_cone(s, e, Vec2::new(5.0, 2.0), 0.3));
        assert!(!in_cone(s, e, Vec2::new(-1.0, 0.0), 0.3));
        assert!(!in_cone(s, e, Vec2::new(11.0, 0.0), 0.3));
        assert!(!in_cone(s, s, Vec2::new(1.0, 0.0), 0.3));
        // The division-free form agrees with the geometric definition.
        let mut rng = rlfd_env::random::seeded(1);
        for _ in 0..10_000 {
            let mut draw = || {
                Vec2::new(
                    20.0 * rlfd_env::random::uniform01(&mut rng) - 10.0,
                    20.0 * rlfd_env::random::uniform01(&mut rng) - 10.0,
                )
            };
            let (a, b, o) = (draw(), draw(), draw());
            let d = b - a;
            let t = (o - a).dot(d) / d.norm2();
            let foot = a + d * t;
            let expected = (0.0..=1.0).contains(&t) && o.dist(a) < b.dist(a) && o.dist(foot) < 0.3 * foot.dist(a);
            assert_eq!(in_cone(a, b, o, 0.3), expected);
        }
    }

    #[test]
    fn get_open_avoids_blocked_and_crowded_points() {
        let r = Region { length: 20.0, width: 20.0 };
        let grid = r.grid();
        let open_grid = GetOpenGrid::new(&r);
        // Pass from the low-left corner (keeper 0 has the ball); a taker in the
        // way of the diagonal and keeper 2 crowding the high-right corner.
        let from = Vec2::new(-9.0, -9.0);
        let players = [from, Vec2::new(0.0, 9.0), Vec2::new(7.0, 6.0), Vec2::new(-4.0, -4.0), Vec2::new(6.0, 6.0)];
        let mut out = [Vec2::ZERO; 3];
        least_congested_points(&open_grid, Vec2::ZERO, from, &players, 3, &[false, true, true], &mut out);
        for k in [1, 2] {
            assert!(!in_cone(from, out[k], players[3], CONE_WIDTH));
            assert!(grid.contains(&out[k]));
            // The chosen point minimises Σ 1/dist over the others among the safe points.
            let congestion = |p: Vec2| {
                players.iter().enumerate().filter(|&(i, _)| i != k).map(|(_, q)| 1.0 / q.dist(p)).sum::<f64>()
            };
            for &g in &grid {
                if !in_cone(from, g, players[3], CONE_WIDTH) && !in_cone(from, g, players[4], CONE_WIDTH) {
                    assert!(congestion(out[k]) <= congestion(g) + 1e-5);
                }
            }
        }
        for k in 0..3 {
            let table =
                Congestion::new(&open_grid, &players).best_point(&open_grid, from, &players[3..], k, Vec2::ZERO);
            let own = Congestion::best_point_for(&open_grid, &players, from, &players[3..], k, Vec2::ZERO);
            assert_eq!(own, table, "keeper {k}: the compact sums choose as the table does");
        }
        assert_eq!(out[0], Vec2::ZERO, "not getting open: the centre");
        assert!(out[2].dist(Vec2::new(7.0, 6.0)) > 3.0, "{:?}", out[2]);
    }

    #[test]
    fn the_fastest_keeper_is_the_one_that_gets_there_first() {
        let k = Kinematics::new(&ServerParams::rcssserver_11());
        let ball = Ball { pos: Vec2::new(0.0, 0.0), vel: Vec2::new(1.0, 0.0), accel: Vec2::ZERO };
        let f = BallForecast::new(&k.p, &ball);
        let keepers = [
            Body::at(Vec2::new(-9.0, -9.0), 0.0),
            Body::at(Vec2::new(8.0, 1.0), std::f64::consts::PI),
            Body::at(Vec2::new(9.0, 9.0), 0.0),
        ];
        let (who, when) = fastest_to_ball(&k, &keepers, &f);
        assert_eq!(who, 1);
        assert!((2..=6).contains(&when), "{when}");
        assert!(ang_in_interval(0.1, 0.0, 1.0) && !ang_in_interval(-0.1, 0.0, 1.0) && ang_in_interval(3.2, 3.0, -3.0));
    }
}
