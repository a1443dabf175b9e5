//! The hand-coded parts of the players (`KeepawayPlayer.cc` of the UT-Austin
//! keepaway players v0.6): the keepers' GetOpen and the takers' policy.
//!
//! - **GetOpen** (`getOpenForPassFromInRectangle`): from where the fastest
//!   teammate will get the ball (`pass_from`), score a 5 × 5 grid over the
//!   region with a 15 % border (at 15, 32.5, 50, 67.5 and 85 % of each side),
//!   skip points with a taker inside the pass cone from `pass_from` (half
//!   width 0.3 × distance, between the two points and closer than the
//!   point), and take the least congested point, congestion being
//!   `Σ 1/dist` over every other player; the region's centre if no point is
//!   safe. Within 1.5 m of the point the keeper turns to the ball, else moves
//!   there.
//! - **Takers** (`KeepawayPlayer::taker`): the taker closest to the ball
//!   holds it when it is kickable (`holdBall(0.3)`); a taker whose teammate is
//!   the player closest to the ball and has it kickable turns to the ball;
//!   otherwise both takers intercept (running at the keeper when the ball is
//!   at a keeper's feet, see [`taker_command`]). (The marking branch needs more than two
//!   takers and never runs in 3 vs 2.)

use super::geometry::Vec2;
use super::server::{Ball, Body, Command, ServerParams};
use super::skills::{BallForecast, InterceptPlan, ReachTable, hold_ball, intercept, move_to, plan_intercept, turn_to};

/// Points per side of the GetOpen grid.
pub const GRID: usize = 5;

/// The border of the GetOpen grid, as a fraction of each side.
pub const GRID_BORDER: f64 = 0.15;

/// Half-width of the pass cone at unit distance.
pub const CONE_WIDTH: f64 = 0.3;

/// Within this distance of its GetOpen point a keeper turns to the ball (m).
pub const GET_OPEN_BUFFER: f64 = 1.5;

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

/// The least congested safe grid point for a pass from `pass_from`, for
/// each keeper getting open (Trilearn's `leastCongestedPointForPassInRectangle`).
///
/// `players`: the three keepers then the two takers; `supporters[k]`: whether
/// keeper `k` is getting open; `out[k]` receives its point. A point is unsafe
/// when a taker lies in the pass cone; a keeper's congestion at a point is
/// `Σ 1/dist` over every player but itself. Both keepers share the cone tests
/// and the distances, so the grid is scanned once.
pub fn least_congested_points(
    grid: &GetOpenGrid,
    centre: Vec2,
    pass_from: Vec2,
    players: &[Vec2; 5],
    supporters: [bool; 3],
    out: &mut [Vec2; 3],
) {
    const N: usize = GetOpenGrid::LANES;
    let (gx, gy) = (&grid.x, &grid.y);
    let (fx, fy) = (pass_from.x as f32, pass_from.y as f32);
    let w2 = (CONE_WIDTH * CONE_WIDTH) as f32;
    let mut safe = grid.real;
    for t in &players[3..5] {
        let (rx, ry) = (t.x as f32 - fx, t.y as f32 - fy);
        let r2 = rx * rx + ry * ry;
        for i in 0..N {
            let (dx, dy) = (gx[i] - fx, gy[i] - fy);
            let len2 = dx * dx + dy * dy;
            let u = rx * dx + ry * dy;
            let (ex, ey) = (rx * len2 - dx * u, ry * len2 - dy * u);
            let inside =
                (len2 > 0.0) & (u >= 0.0) & (u <= len2) & (r2 < len2) & (ex * ex + ey * ey < w2 * u * u * len2);
            safe[i] &= !inside;
        }
    }
    let mut inv = [[0.0f32; N]; 5];
    for (row, q) in inv.iter_mut().zip(players) {
        let (qx, qy) = (q.x as f32, q.y as f32);
        for i in 0..N {
            let (dx, dy) = (gx[i] - qx, gy[i] - qy);
            let d2 = dx * dx + dy * dy;
            row[i] = if d2 > 0.0 { 1.0 / d2.sqrt() } else { 0.0 };
        }
    }
    // The first least congested safe point (strictly smaller wins, as in
    // Trilearn's loop): the minimum of (congestion bits, index) keys, which
    // order as (congestion, index) because congestion is positive; found with
    // conditional moves instead of unpredictable branches.
    *out = [centre; 3];
    for k in 0..3 {
        if !supporters[k] {
            continue;
        }
        let mut best = u64::MAX;
        for i in 0..GRID * GRID {
            let congestion = inv[0][i] + inv[1][i] + inv[2][i] + inv[3][i] + inv[4][i] - inv[k][i];
            let key = (u64::from(congestion.to_bits()) << 8) | i as u64;
            best = best.min(if safe[i] { key } else { u64::MAX });
        }
        if best != u64::MAX {
            out[k] = grid.points[(best & 0xff) as usize];
        }
    }
}

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

/// A supporting keeper's command: move to its GetOpen point, or turn to the ball there.
pub fn get_open(p: &ServerParams, reach: &ReachTable, me: &Body, ball: &Ball, point: Vec2) -> Command {
    if me.pos.dist2(point) < GET_OPEN_BUFFER * GET_OPEN_BUFFER {
        turn_to(p, me, ball.pos)
    } else {
        move_to(p, reach, me, point)
    }
}

/// What a taker does this cycle.
///
/// `me`: this taker's index; `closest_keeper`: the keeper nearest the ball,
/// with its distance. The interception plan is made only when needed.
pub fn taker_command(
    p: &ServerParams,
    reach: &ReachTable,
    takers: &[Body; 2],
    me: usize,
    ball: &Ball,
    forecast: &BallForecast,
    closest_keeper: (&Body, f64),
) -> Command {
    let ka = p.kickable_area();
    let body = &takers[me];
    let mate = &takers[1 - me];
    let my_dist = body.pos.dist(ball.pos);
    let mate_dist = mate.pos.dist(ball.pos);
    // The closest taker to the ball (ties: the lower index, as the iteration order).
    let i_am_closest = my_dist < mate_dist || (my_dist == mate_dist && me == 0);
    if my_dist < ka && i_am_closest {
        return hold_ball(p, body, ball, Some(closest_keeper.0), 0.3);
    }
    // If my teammate is the closest player to the ball and has it kickable, don't mess with it.
    if mate_dist < closest_keeper.1 && mate_dist < my_dist && mate_dist < ka {
        return turn_to(p, body, forecast.after(1));
    }
    // A ball at a keeper's feet: run at that keeper, where the ball is kept
    // (within 0.9 m of him, on the side away from the takers). Aiming at the
    // ball itself, which the keeper moves around his body every cycle, would
    // have the taker turn after it forever in a server without collisions.
    let plan = if closest_keeper.1 < ka {
        InterceptPlan { cycles: 0, point: closest_keeper.0.pos }
    } else if forecast.is_held() {
        InterceptPlan { cycles: 0, point: forecast.at[0] }
    } else {
        plan_intercept(p, reach, body, forecast)
    };
    intercept(p, reach, body, &plan, forecast)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_has_a_15_percent_border() {
        let r = Region { length: 20.0, width: 20.0 };
        let g = r.grid();
        assert_eq!(g[0], Vec2::new(-7.0, -7.0));
        assert_eq!(g[1], Vec2::new(-7.0, -3.5));
        assert_eq!(g[12], Vec2::new(0.0, 0.0));
        assert_eq!(g[24], Vec2::new(7.0, 7.0));
        assert!(r.contains(Vec2::new(9.99, -9.99)) && !r.contains(Vec2::new(10.0, 0.0)));
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
        let mut rng = rlfd_rl::random::seeded(1);
        for _ in 0..10_000 {
            let mut draw = || {
                Vec2::new(
                    20.0 * rlfd_rl::random::uniform01(&mut rng) - 10.0,
                    20.0 * rlfd_rl::random::uniform01(&mut rng) - 10.0,
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
        least_congested_points(&open_grid, Vec2::ZERO, from, &players, [false, true, true], &mut out);
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
        assert_eq!(out[0], Vec2::ZERO, "not getting open: the centre");
        assert!(out[2].dist(Vec2::new(7.0, 6.0)) > 3.0, "{:?}", out[2]);
    }
}
