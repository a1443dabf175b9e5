//! How the players see the ball: the server's visual quantisation
//! (`VisualSenderPlayerV1` in rcssserver's `visual.cc`) and the keepaway
//! players' reading of it (`WorldModel::calculateStateBall`).
//!
//! The server tells a player the ball's distance, direction, distance
//! change and direction change, each quantised:
//!
//! ```text
//! dist     = Q(exp(Q(ln(d + 1e-10), 0.1)), 0.1)        (quantize_step 0.1)
//! dir      = round(bearing in degrees)                  (relative to the player's facing)
//! dist_chg = dist · Q((v_rel · e) / d, 0.02)            (v_rel: the ball's velocity relative to the player's)
//! dir_chg  = Q((v_rel × e) / d in degrees, 0.1)
//! ```
//!
//! with `Q(v, q) = rint(v / q) · q`. The player rebuilds a position and a
//! velocity from these, averages the velocity with the one it predicted
//! from its last belief when the two agree within twice the ball's noise
//! (`2 · ball_rand · speed` per component), and believes a ball still when
//! an opponent has it within the kickable area and it does not.
//!
//! Every cycle, before any look, a player carries its belief on (decayed
//! velocity, plus its own kick as it computed it from its belief: it knows
//! no teammate's kick), and believes the ball still when the prediction
//! lands at an opponent's feet. Then it compares the speed its sense message
//! reports with the motion it predicted from its own command: a velocity
//! that vanished or turned round near the ball means a collision, and when
//! the ball is nearer than any player it puts the ball 0.2 m from itself with
//! its velocity times −0.1 (`updateAgentAndBallAfterSense`,
//! `updateBallForCollision` in `WorldModelUpdate.cc`). Each player acts on
//! its own belief.

use rand::Rng;
use rlfd_env::random::uniform01;

use super::geometry::{RAD_PER_DEG, Vec2, rint, unit_deg};
use super::server::{Ball, Body};

/// Beyond this quantised distance the server may leave out a ball's
/// velocity and a player's number (`UNUM_FAR_LENGTH`, m).
pub const UNUM_FAR_LENGTH: f64 = 20.0;

/// Beyond this it always does (`UNUM_TOOFAR_LENGTH`, m).
pub const UNUM_TOOFAR_LENGTH: f64 = 40.0;

/// Whether the server's see of a ball or a player `d` metres away carries
/// its velocity, and a player's number (`sendHighBall`, `sendHighPlayer`):
/// always within 20 m (quantised), never from 40 m, and between them with
/// probability `1 − (qd − 20) / 20`, one draw from `rng` (the server's
/// `decide` draws only strictly between 0 and 1).
#[inline]
pub fn sends_velocity<R: Rng + ?Sized>(d: f64, rng: &mut R) -> bool {
    // Below 19 m the logarithm rounds to 2.9 at most, e^2.9 = 18.2 m: no
    // quantising needed for most sees (the same answer, no draw either way).
    if d < 19.0 {
        return true;
    }
    let qd = quantized_distance_fast(d);
    let drop = (qd - UNUM_FAR_LENGTH) / (UNUM_TOOFAR_LENGTH - UNUM_FAR_LENGTH);
    drop <= 0.0 || (drop < 1.0 && uniform01(rng) >= drop)
}

/// The server's `EPS` added before the logarithm.
const EPS: f64 = 1.0e-10;

/// `quantize_step` for movable objects (rcssserver 11 default 0.1).
pub const QUANTIZE_STEP: f64 = 0.1;

/// The quantisation of the distance change, as a fraction of the distance (hard-coded 0.02).
pub const DIST_CHANGE_STEP: f64 = 0.02;

/// The quantisation of the direction change, degrees (`dir_qstep`? the v1 sender's 0.1).
pub const DIR_CHANGE_STEP: f64 = 0.1;

/// `Q(v, q) = rint(v / q) · q` (`Quantize` in `utility.h`).
#[inline]
fn quantize(v: f64, q: f64) -> f64 {
    rint(v / q) * q
}

/// The distance a player is told for an object `d` metres away.
#[inline]
pub fn quantized_distance(d: f64) -> f64 {
    quantize(libm::exp(quantize(libm::log(d + EPS), QUANTIZE_STEP)), 0.1)
}

/// The log-steps the distance table covers: `e^{0.1 k}` for `k` in `LOW..=HIGH` (0.05 m to 90 m).
const LOW: i32 = -30;
const HIGH: i32 = 45;

/// [`quantized_distance`] by table: the told distance is constant between
/// the points `e^{0.1 (k + ½)}` where the rounded logarithm steps, so a
/// binary search over those points replaces the logarithm and the
/// exponential (the same values except at exact ties of the rounding).
///
/// The search itself is a lookup: the top 16 bits of a positive `f64` (its
/// exponent and 4 mantissa bits) cut each octave into 16 buckets, each
/// narrower (a ratio ≤ 1.0625) than the steps between the edges (e^0.1 =
/// 1.105), so a bucket holds at most one edge; the count of edges at or
/// below the bucket's smallest value, plus one comparison, is exactly the
/// binary search's answer.
#[inline]
pub fn quantized_distance_fast(d: f64) -> f64 {
    struct Table {
        edges: Vec<f64>,
        values: Vec<f64>,
        /// Per bucket, the number of edges at or below its smallest value.
        start: Vec<u8>,
        /// The first bucket's number (`edges[0]`'s top 16 bits).
        first: u64,
    }
    const SHIFT: u32 = 48;
    static TABLE: std::sync::OnceLock<Table> = std::sync::OnceLock::new();
    let t = TABLE.get_or_init(|| {
        let edges: Vec<f64> = (LOW..HIGH).map(|k| libm::exp(QUANTIZE_STEP * (f64::from(k) + 0.5))).collect();
        let values = (LOW..=HIGH).map(|k| quantize(libm::exp(QUANTIZE_STEP * f64::from(k)), 0.1)).collect();
        let first = edges[0].to_bits() >> SHIFT;
        let last = edges[edges.len() - 1].to_bits() >> SHIFT;
        let start = (first..=last)
            .map(|b| {
                let lo = f64::from_bits(b << SHIFT);
                edges.partition_point(|&e| e <= lo) as u8
            })
            .collect();
        Table { edges, values, start, first }
    });
    let x = d + EPS;
    if x < t.edges[0] || x >= t.edges[t.edges.len() - 1] {
        return quantized_distance(d);
    }
    let i = usize::from(t.start[((x.to_bits() >> SHIFT) - t.first) as usize]);
    t.values[i + usize::from(t.edges[i] <= x)]
}

/// The bearing the server tells, whole degrees: `rint(atan2(c, d) / 1°)`
/// for the observer-frame vector `(d, c)` (`d` along the body, `c` across).
///
/// Without the arc tangent when it can: a rough angle (within 0.25°) names a
/// candidate `b`, and two cross products with the tabulated directions of
/// `b − ½°` and `b + ½°` show whether `(d, c)` lies strictly between them by
/// a margin (10⁻¹² of its length) a thousand times wider than the combined
/// rounding of the table, the products and `libm::atan2`, so the rounded
/// arc tangent is `b` bit for bit. Undecided cases (within the margin of a
/// half degree, or near ±180° where the sign of the result depends on the
/// side of the wrap) take `libm::atan2`.
#[inline]
pub fn bearing_deg(c: f64, d: f64) -> i32 {
    bearing_by_table(c, d).unwrap_or_else(|| rint(libm::atan2(c, d) / RAD_PER_DEG) as i32)
}

/// [`bearing_deg`]'s table path; `None` when undecided.
#[inline]
fn bearing_by_table(c: f64, d: f64) -> Option<i32> {
    /// Half-degree directions: `HALF[k + 181]` is the unit vector of `(k + ½)°`, `k` in `-181..=180`.
    static HALF: std::sync::OnceLock<Vec<Vec2>> = std::sync::OnceLock::new();
    let half =
        HALF.get_or_init(|| (-181..=180).map(|k| Vec2::from_angle((f64::from(k) + 0.5) * RAD_PER_DEG)).collect());
    let (ax, ay) = (d.abs(), c.abs());
    let (lo, hi) = if ax < ay { (ax, ay) } else { (ay, ax) };
    if !(hi > 0.0 && hi.is_finite()) {
        return None;
    }
    // atan(z) ≈ 45° z + 15.64° z (1 − z) on [0, 1]: within 0.22°.
    let z = lo / hi;
    let mut a = z * (45.0 + 15.64 * (1.0 - z));
    if ay > ax {
        a = 90.0 - a;
    }
    if d < 0.0 {
        a = 180.0 - a;
    }
    if c < 0.0 {
        a = -a;
    }
    let margin = 1e-12 * (ax + ay);
    let mut b = rint(a) as i32;
    for _ in 0..2 {
        if b.abs() > 178 {
            return None;
        }
        let below = half[(b + 180) as usize]; // (b − ½)°
        let above = half[(b + 181) as usize]; // (b + ½)°
        let s_lo = below.x * c - below.y * d;
        let s_hi = above.x * c - above.y * d;
        if s_lo > margin && s_hi < -margin {
            return Some(b);
        }
        if s_lo < -margin {
            b -= 1;
        } else if s_hi > margin {
            b += 1;
        } else {
            return None;
        }
    }
    None
}

/// The ball as `observer` sees it: position and velocity rebuilt from the
/// quantised distance, direction and changes (see the module docs).
pub fn seen_ball(observer: &Body, ball: &Ball) -> (Vec2, Vec2) {
    seen_object(observer, ball.pos, ball.vel)
}

/// Another player as `observer` sees it (`sendHighPlayer`, then
/// `calculateStatePlayer`): position and velocity rebuilt from the quantised
/// distance, direction and changes as for the ball, the velocity capped at
/// the player's top speed, and its body direction in whole degrees.
pub fn seen_player(observer: &Body, other: &Body, speed_max: f64) -> Body {
    let sight = PairSight::new(observer.pos, observer.vel, other.pos, other.vel);
    seen_player_with(observer, other, sight, Heading::of(other), speed_max)
}

/// [`seen_player`] from the parts its observer shares with others: the
/// pair's [`PairSight`] (either player's) and the seen player's [`Heading`].
#[inline]
pub fn seen_player_with(
    observer: &Body,
    other: &Body,
    sight: Option<PairSight>,
    heading: Heading,
    speed_max: f64,
) -> Body {
    let (pos, mut vel) = match sight {
        Some(s) => s.seen_from(observer, other.pos),
        None => (other.pos, other.vel),
    };
    let v = vel.norm();
    if v > speed_max {
        vel = vel * (speed_max / v);
    }
    Body { pos, vel, angle: heading.angle, dir: heading.dir, accel: Vec2::ZERO }
}

/// Trilearn's `UnknownAngleValue` (degrees): the body angle of a player
/// object that was never told one.
pub const UNKNOWN_ANGLE_DEG: f64 = -1000.0;

/// `other` seen beyond 20 m without its number (and so without velocity
/// and body direction: `sendHighPlayer`'s far name), as Trilearn keeps it
/// (`mapUnknownPlayers`): the unnumbered player is matched to the nearest
/// player it knows (here always the right one) by copying over it the
/// unknown-player object, whose velocity was never set, (0, 0), and whose
/// body angle is `UnknownAngleValue`, −1000°, which its trigonometry reads
/// as 80°; the position is the seen one.
#[inline]
pub fn seen_unnumbered_player(observer: &Body, other: &Body, sight: Option<PairSight>) -> Body {
    let pos = sight.map_or(other.pos, |s| s.seen_from(observer, other.pos).0);
    let angle = UNKNOWN_ANGLE_DEG * RAD_PER_DEG;
    Body { pos, vel: Vec2::ZERO, angle, dir: Vec2::new(libm::cos(angle), libm::sin(angle)), accel: Vec2::ZERO }
}

/// A player's body direction as every observer is told it: whole degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Heading {
    /// The rounded angle, radians.
    pub angle: f64,
    /// Its unit vector.
    pub dir: Vec2,
}

impl Heading {
    /// `other`'s heading as seen: `Body::at(·, rint(angle / 1°) · 1°)`'s
    /// direction without its cosine and sine (the direction of a whole
    /// degree is tabulated with the same `libm` values; 0° keeps the sign
    /// of its zero as `sin(±0) = ±0` does).
    #[inline]
    pub fn of(other: &Body) -> Heading {
        let deg = rint(other.angle / RAD_PER_DEG);
        let dir = if deg == 0.0 { Vec2::new(1.0, deg) } else { unit_deg(deg as i32) };
        Heading { angle: deg * RAD_PER_DEG, dir }
    }
}

/// What the server's look computes for a pair of objects that does not
/// depend on which of the two looks (a player at the other, or the other
/// way round): the quantised distance and the quantised distance and
/// direction changes. Seen from the other side the relative position and
/// velocity are exactly negated (IEEE subtraction is antisymmetric), so
/// the distance, the products and hence every quantised value are the same
/// bits: the pair's part is computed once per cycle for both players.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairSight {
    qd: f64,
    dist_chg: f64,
    dir_chg: f64,
}

impl PairSight {
    /// The pair's part for an object at `obj_pos` moving at `obj_vel` seen
    /// from `pos` moving at `vel`; `None` when the two coincide.
    #[inline]
    pub fn new(pos: Vec2, vel: Vec2, obj_pos: Vec2, obj_vel: Vec2) -> Option<PairSight> {
        let rel = obj_pos - pos;
        let d = rel.norm();
        if d == 0.0 {
            return None;
        }
        let qd = quantized_distance_fast(d);
        let true_e = rel * (1.0 / d);
        let v_rel = obj_vel - vel;
        let dist_chg = qd * quantize(v_rel.dot(true_e) / d, DIST_CHANGE_STEP);
        let dir_chg = -v_rel.cross(true_e) / d / RAD_PER_DEG;
        let dir_chg = if dir_chg == 0.0 { 0.0 } else { quantize(dir_chg, DIR_CHANGE_STEP) };
        Some(PairSight { qd, dist_chg, dir_chg })
    }

    /// The position and velocity `observer` rebuilds for the object at
    /// `obj_pos` (its own whole-degree bearing; see the module docs).
    #[inline]
    pub fn seen_from(&self, observer: &Body, obj_pos: Vec2) -> (Vec2, Vec2) {
        let rel = obj_pos - observer.pos;
        // `rint(signed_angle(observer.dir, rel) / 1°)`, from the same two products.
        let bearing = bearing_deg(observer.dir.cross(rel), observer.dir.dot(rel));
        let e = observer.dir.rotate(unit_deg(bearing));
        let pos = observer.pos + e * self.qd;
        let vel = observer.vel + e * self.dist_chg + e.perp() * (self.dir_chg * RAD_PER_DEG * self.qd);
        (pos, vel)
    }
}

/// An object at `pos` moving at `vel` as `observer` sees it (see the module docs).
fn seen_object(observer: &Body, obj_pos: Vec2, obj_vel: Vec2) -> (Vec2, Vec2) {
    match PairSight::new(observer.pos, observer.vel, obj_pos, obj_vel) {
        Some(s) => s.seen_from(observer, obj_pos),
        None => (obj_pos, obj_vel),
    }
}

/// Trilearn's `EPSILON` (`Geometry.h`): a sensed speed below it "gives no information".
const SENSE_EPSILON: f64 = 1.0e-4;

/// What a player believes its own motion this cycle would have been without
/// a collision (`updateAgentAndBallAfterSense`, before it reads the sense
/// message's speed): from where it was and its velocity, after the command
/// it sent. A dash or a turn moves it as `predictStateAfterDash` does
/// (velocity plus the dash, capped, added to the position, then decayed); a
/// kick, or no command, leaves both as they were (the source updates only the
/// ball for a kick). The closest other player is measured from where it was
/// to where it believed the others (its view before this cycle's update).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OwnMotion {
    /// Its predicted position.
    pub pos: Vec2,
    /// Its predicted velocity.
    pub vel: Vec2,
    /// The distance from its old position to the closest other player it believed in.
    pub closest_player: f64,
}

/// The velocity a player reads from its sense message (`BodySenderPlayerV6`):
/// the speed quantised to 0.01 and its direction relative to the body (the
/// keepaway players never turn their necks) truncated to whole degrees
/// (`Rad2IDeg`), turned back into the field's frame with the body direction
/// the player knows.
pub fn sensed_velocity(body: &Body) -> Vec2 {
    let speed = rint(body.vel.norm() / 0.01) * 0.01;
    if speed == 0.0 {
        return Vec2::ZERO;
    }
    let rel = super::geometry::normalize_angle(body.vel.angle() - body.angle);
    let head = (rel / RAD_PER_DEG).trunc();
    Vec2::from_angle(body.angle + head * RAD_PER_DEG) * speed
}

/// `updateAgentAndBallAfterSense`'s collision test: the player believes it
/// collided when its sensed velocity `sensed` is zero while it predicted a
/// motion (`predicted` over 0.01) and the ball it predicts is within 0.8 m of
/// where it predicts itself (`dist_ball`); or the ball is within `touch`
/// (player plus ball radius) and the sensed speed zero; or the ball is within
/// `kick_reach` + 0.5 m, the sensed velocity is not zero, each component has
/// changed sign or is under 0.08, and the sensed speed is under a quarter of
/// the predicted one (the server's collision multiplies velocity by −0.1).
pub fn senses_collision(predicted: Vec2, sensed: Vec2, dist_ball: f64, touch: f64, kick_reach: f64) -> bool {
    // Trilearn's `sign`: 1 for positive, −1 otherwise (zero included).
    let sign = |v: f64| if v > 0.0 { 1 } else { -1 };
    let (s, v) = (sensed.norm(), predicted.norm());
    (s < SENSE_EPSILON && v > 0.01 && dist_ball < 0.8)
        || (dist_ball < touch && s < SENSE_EPSILON)
        || (dist_ball < kick_reach + 0.5
            && s > SENSE_EPSILON
            && (sign(predicted.x) != sign(sensed.x) || predicted.x.abs() < 0.08)
            && (sign(predicted.y) != sign(sensed.y) || predicted.y.abs() < 0.08)
            && s < 0.25 * v)
}

/// The ball part of a player's say message (`BallInfo`, made by
/// `KeepawayPlayer::makeSayMessage`): where the speaker believed the ball,
/// its velocity, and the cycles the hearer carries it on by (1: the
/// speaker's belief of the cycle it spoke in; 0: the speaker kicked the ball
/// away and said where its kick sends it, which is the cycle it is heard in).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BallMessage {
    /// The ball's position.
    pub pos: Vec2,
    /// Its velocity.
    pub vel: Vec2,
    /// Cycles to carry it on by (0 or 1).
    pub cycles: u8,
}

/// The ball decay `WMBallInfo::process` carries a heard ball on by (hard-coded there).
const HEARD_BALL_DECAY: f64 = 0.94;

/// A team's belief of the ball, carried from cycle to cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BallBelief {
    /// Where the team believes the ball is.
    pub pos: Vec2,
    /// Its believed velocity.
    pub vel: Vec2,
    /// Whether the belief holds anything yet this episode.
    pub known: bool,
}

impl BallBelief {
    /// Updates the belief from `observer`'s look at `ball`
    /// (`calculateStateBall`): the position is the seen one; the seen
    /// velocity is averaged with the belief's (already carried to this cycle
    /// by [`BallBelief::predict`], as the sense message's update does before
    /// the see is processed) when they agree within twice the ball's noise
    /// of its speed per component; a ball seen within the kickable area `ka`
    /// of an opponent as the observer sees them (`opponents`), and not
    /// within its own, is believed still.
    ///
    /// A see without the ball's velocity (`with_velocity` false: beyond
    /// 20 m the server drops it at random) leaves the belief's velocity.
    pub fn update(
        &mut self,
        observer: &Body,
        ball: &Ball,
        ball_rand: f64,
        opponents: &[Body],
        ka: f64,
        with_velocity: bool,
    ) {
        let (pos, mut vel) = seen_ball(observer, ball);
        if !with_velocity {
            vel = self.vel;
        } else if self.known {
            let predicted = self.vel;
            let tol = 2.0 * ball_rand * predicted.norm();
            if (vel.x - predicted.x).abs() <= tol && (vel.y - predicted.y).abs() <= tol {
                vel = (vel + predicted) * 0.5;
            }
        }
        let held_by_opponent = opponents.iter().any(|o| o.pos.dist2(pos) < ka * ka);
        if held_by_opponent && observer.pos.dist2(pos) > ka * ka {
            vel = Vec2::ZERO;
        }
        *self = BallBelief { pos, vel, known: true };
    }

    /// Carries the belief one cycle on, as the sense message's update does
    /// every cycle (`updateAgentAndBallAfterSense`): after the player's own
    /// kick (`own_kick`: the acceleration it computed from its belief,
    /// `updateBallAfterKick`) the ball takes that kick and rolls on;
    /// otherwise it rolls on, and a ball predicted at an opponent's feet is
    /// believed still (`updateDynamicObjectForNextCycle`). A player knows
    /// only its own kicks: its teammates' reach it by their say messages
    /// ([`BallBelief::hear`]) or its next look.
    pub fn predict(&mut self, own_kick: Option<Vec2>, speed_max: f64, decay: f64, opponent_has_it: bool) {
        match own_kick {
            Some(accel) => {
                let mut vel = self.vel + accel;
                let v = vel.norm();
                if v > speed_max {
                    vel = vel * (speed_max / v);
                }
                self.pos += vel;
                self.vel = vel * decay;
            }
            None => {
                self.pos += self.vel;
                self.vel = if opponent_has_it { Vec2::ZERO } else { self.vel * decay };
            }
        }
    }

    /// Takes a teammate's ball message (`WMBallInfo::process`, then
    /// `processPerfectHearInfoBall`), heard by a player at `observer` whose
    /// last look at the ball was `since_seen` cycles ago (`None`: never this
    /// episode). The message is carried on by its cycles; it is taken when
    /// the player has no ball yet, or the believed ball is more than 3 m
    /// away and either unseen for more than 3 cycles or unseen since the
    /// message's cycle with a velocity more than 0.3 off; and then only if
    /// it is more confident (confidence 1 − cycles/100, less 0.01, against
    /// 1 − since_seen/100) or its velocity is more than 0.3 off. Returns
    /// whether it was taken.
    pub fn hear(&mut self, msg: &BallMessage, observer: Vec2, since_seen: Option<u64>) -> bool {
        let (mut pos, mut vel) = (msg.pos, msg.vel);
        for _ in 0..msg.cycles {
            pos += vel;
            vel = vel * HEARD_BALL_DECAY;
        }
        let far = self.pos.dist(observer) > 3.0;
        let off = vel.dist(self.vel) > 0.3;
        let cycles = u64::from(msg.cycles);
        let take = match since_seen {
            None => true,
            Some(s) => far && (s > 3 || (s > cycles && off)),
        };
        if !take {
            return false;
        }
        let own_conf = since_seen.map_or(0.0, |s| (1.0 - s as f64 / 100.0).max(0.0));
        let msg_conf = 1.0 - cycles as f64 / 100.0 - 0.01;
        if own_conf < msg_conf || off {
            *self = BallBelief { pos, vel, known: true };
            true
        } else {
            false
        }
    }

    /// After a collision the player sensed with the ball closer than any
    /// player (`updateBallForCollision`): the ball is put 0.2 m from where
    /// the player predicts itself (`agent`), in the direction it was believed
    /// in, and its believed velocity is multiplied by −0.1 as the server's
    /// collision does.
    pub fn collide(&mut self, agent: Vec2) {
        let dir = (self.pos - agent).normalized_or(Vec2::new(1.0, 0.0));
        self.pos = agent + dir * 0.2;
        self.vel = self.vel * -0.1;
    }

    /// The belief as a ball (no acceleration).
    pub fn ball(&self) -> Ball {
        Ball { pos: self.pos, vel: self.vel, accel: Vec2::ZERO }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_are_quantised_in_log_steps() {
        // ln(10) = 2.3026 → 2.3 → e^2.3 = 9.974 → 10.0.
        assert!((quantized_distance(10.0) - 10.0).abs() < 1e-9);
        // ln(7.2) = 1.974 → 2.0 → 7.389 → 7.4.
        assert!((quantized_distance(7.2) - 7.4).abs() < 1e-9);
        // Within 5 % of the truth, and a step of 10 % in the log.
        for i in 1..400 {
            let d = f64::from(i) * 0.1;
            let q = quantized_distance(d);
            assert!((q - d).abs() <= 0.06 * d + 0.05, "{d} {q}");
        }
    }

    #[test]
    fn the_table_gives_the_servers_distances() {
        let mut rng = rlfd_env::random::seeded(4);
        for _ in 0..20_000 {
            let d = 40.0 * rlfd_env::random::uniform01(&mut rng);
            assert_eq!(quantized_distance_fast(d), quantized_distance(d), "{d}");
        }
        // The bucket lookup is the binary search over the same edges, bit for
        // bit: around every edge, at the table's ends and everywhere between.
        let edges: Vec<f64> = (LOW..HIGH).map(|k| libm::exp(QUANTIZE_STEP * (f64::from(k) + 0.5))).collect();
        let values: Vec<f64> = (LOW..=HIGH).map(|k| quantize(libm::exp(QUANTIZE_STEP * f64::from(k)), 0.1)).collect();
        let search = |d: f64| {
            let x = d + EPS;
            if x < edges[0] || x >= edges[edges.len() - 1] {
                return quantized_distance(d);
            }
            values[edges.partition_point(|&e| e <= x)]
        };
        let mut xs = Vec::new();
        for &e in &edges {
            for x in [e, f64::from_bits(e.to_bits() + 1), f64::from_bits(e.to_bits() - 1), e * 1.01, e * 0.99] {
                xs.extend([x, x - EPS]);
            }
        }
        xs.extend((0..200_000).map(|_| 100.0 * rlfd_env::random::uniform01(&mut rng)));
        xs.extend([0.0, 1e-9, 0.04, 95.0, 1e6]);
        for d in xs {
            assert_eq!(quantized_distance_fast(d).to_bits(), search(d).to_bits(), "{d}");
        }
    }

    #[test]
    fn the_bearing_table_gives_libms_rounded_arc_tangent() {
        let exact = |c: f64, d: f64| rint(libm::atan2(c, d) / RAD_PER_DEG) as i32;
        let mut rng = rlfd_env::random::seeded(6);
        let mut u = || rlfd_env::random::uniform01(&mut rng);
        let mut by_table = 0;
        for _ in 0..300_000 {
            let (c, d) = (40.0 * u() - 20.0, 40.0 * u() - 20.0);
            assert_eq!(bearing_deg(c, d), exact(c, d), "({c}, {d})");
            by_table += usize::from(bearing_by_table(c, d).is_some());
        }
        assert!(by_table > 290_000, "{by_table}");
        // At and within a few ulps of every half degree, at several lengths,
        // and on the axes and the ±180° wrap.
        for k in -181..=180 {
            for len in [1e-3, 0.7, 13.0, 80.0] {
                let a = (f64::from(k) + 0.5) * RAD_PER_DEG;
                for da in [0.0, 1e-15, -1e-15, 1e-13, -1e-13, 1e-9, -1e-9, 2e-3, -2e-3] {
                    let (c, d) = (len * libm::sin(a + da), len * libm::cos(a + da));
                    for (c, d) in [(c, d), (f64::from_bits(c.to_bits() + 1), d), (c, f64::from_bits(d.to_bits() + 1))] {
                        assert_eq!(bearing_deg(c, d), exact(c, d), "({c}, {d})");
                    }
                }
            }
        }
        for (c, d) in [(0.0, 1.0), (-0.0, 1.0), (0.0, -1.0), (-0.0, -1.0), (1.0, 0.0), (-1.0, 0.0), (1e-300, -5.0)] {
            assert_eq!(bearing_deg(c, d), exact(c, d), "({c}, {d})");
        }
    }

    #[test]
    fn a_pair_sight_serves_both_players_bit_for_bit() {
        let mut rng = rlfd_env::random::seeded(8);
        let mut u = || rlfd_env::random::uniform01(&mut rng);
        let bits = |b: &Body| [b.pos.x, b.pos.y, b.vel.x, b.vel.y, b.angle, b.dir.x, b.dir.y].map(f64::to_bits);
        for n in 0..50_000 {
            let mut body = || Body {
                vel: Vec2::new(1.4 * u() - 0.7, 1.4 * u() - 0.7),
                ..Body::at(Vec2::new(24.0 * u() - 12.0, 24.0 * u() - 12.0), 6.4 * u() - 3.2)
            };
            let (a, mut b) = (body(), body());
            if n % 1000 == 0 {
                b.pos = a.pos; // coincident: both see the other as it is
            }
            let sight = PairSight::new(a.pos, a.vel, b.pos, b.vel);
            let a_sees_b = seen_player_with(&a, &b, sight, Heading::of(&b), 1.2);
            let b_sees_a = seen_player_with(&b, &a, sight, Heading::of(&a), 1.2);
            assert_eq!(bits(&a_sees_b), bits(&seen_player(&a, &b, 1.2)));
            assert_eq!(bits(&b_sees_a), bits(&seen_player(&b, &a, 1.2)));
            // Against the look computed from scratch from b's side.
            let own = PairSight::new(b.pos, b.vel, a.pos, a.vel);
            assert_eq!(bits(&b_sees_a), bits(&seen_player_with(&b, &a, own, Heading::of(&a), 1.2)));
        }
    }

    #[test]
    fn the_seen_ball_is_close_and_its_velocity_roughly_right() {
        let observer = Body::at(Vec2::new(0.0, 0.0), 0.3);
        let ball = Ball { pos: Vec2::new(8.0, 3.0), vel: Vec2::new(-1.2, 0.4), accel: Vec2::ZERO };
        let (p, v) = seen_ball(&observer, &ball);
        assert!(p.dist(ball.pos) < 0.05 * 8.6 + 0.1, "{p:?}");
        // The radial part is quantised to 2 % of the distance per cycle.
        assert!(v.dist(ball.vel) < 0.02 * 8.6 + 0.05, "{v:?}");
        // A still observer right at the ball sees it (nearly) exactly.
        let near = Ball { pos: Vec2::new(0.6, 0.1), vel: Vec2::new(0.05, 0.0), accel: Vec2::ZERO };
        let (p, v) = seen_ball(&observer, &near);
        assert!(p.dist(near.pos) < 0.04 && v.dist(near.vel) < 0.02, "{p:?} {v:?}");
        // A ball at an opponent's feet is believed still.
        let mut b = BallBelief::default();
        b.update(&observer, &ball, 0.05, &[Body::at(ball.pos + Vec2::new(0.5, 0.0), 0.0)], 1.085, true);
        assert_eq!(b.vel, Vec2::ZERO);
    }

    #[test]
    fn far_sees_leave_out_the_balls_velocity_at_the_servers_rate() {
        let mut rng = rlfd_env::random::seeded(3);
        // Within 20 m (quantised) and from 40 m: decided without a draw.
        let mut untouched = rng.clone();
        assert!(sends_velocity(19.0, &mut rng) && !sends_velocity(41.0, &mut rng));
        assert_eq!(uniform01(&mut rng).to_bits(), uniform01(&mut untouched).to_bits());
        // The shortcut below 19 m: every such distance quantises to 20 m or less.
        assert!((0..190_000).all(|i| quantized_distance_fast(f64::from(i) * 1e-4) <= UNUM_FAR_LENGTH));
        // 30 m quantises to 30.0: left out with probability (30 − 20) / 20 = 0.5;
        // 25 m to 25.0 (e^3.2 = 24.53 → 24.5): 0.225.
        for (d, p) in [(30.0, 0.5), (25.0, 0.225)] {
            let n = 100_000;
            let kept = (0..n).filter(|_| sends_velocity(d, &mut rng)).count() as f64 / f64::from(n);
            assert!((kept - (1.0 - p)).abs() < 0.01, "{d} m: {kept}");
        }
        // A see without it moves the belief to the seen place and keeps the predicted velocity.
        let observer = Body::at(Vec2::new(0.0, 0.0), 0.0);
        let ball = Ball { pos: Vec2::new(24.0, 3.0), vel: Vec2::new(-1.2, 0.4), accel: Vec2::ZERO };
        let mut b = BallBelief { pos: Vec2::new(20.0, 0.0), vel: Vec2::new(0.5, 0.5), known: true };
        b.update(&observer, &ball, 0.05, &[], 1.085, false);
        assert_eq!(b.vel, Vec2::new(0.5, 0.5));
        assert_eq!(b.pos, seen_ball(&observer, &ball).0);
    }

    #[test]
    fn an_unnumbered_far_player_is_believed_still_where_it_was_seen_facing_80_degrees() {
        let a = Body::at(Vec2::new(-10.0, -10.0), 0.2);
        let mut b = Body::at(Vec2::new(12.0, 9.0), 1.0);
        b.vel = Vec2::new(0.4, -0.2);
        let sight = PairSight::new(a.pos, a.vel, b.pos, b.vel);
        let numbered = seen_player_with(&a, &b, sight, Heading::of(&b), 1.2);
        let unnumbered = seen_unnumbered_player(&a, &b, sight);
        assert_eq!(unnumbered.pos, numbered.pos);
        assert_eq!(unnumbered.vel, Vec2::ZERO);
        assert!(unnumbered.dir.dist(unit_deg(80)) < 1e-12, "{:?}", unnumbered.dir);
    }

    #[test]
    fn a_player_predicts_its_own_kick_and_nothing_else() {
        let still = BallBelief { pos: Vec2::new(1.0, 2.0), vel: Vec2::ZERO, known: true };
        // Its own kick of (2, 0) per cycle: capped at 2.7, moved, decayed.
        let mut own = still;
        own.predict(Some(Vec2::new(3.0, 0.0)), 2.7, 0.94, true);
        assert!((own.pos.x - 3.7).abs() < 1e-12 && own.pos.y == 2.0);
        assert!((own.vel.x - 2.7 * 0.94).abs() < 1e-12);
        // A teammate that did not kick sees no change until it looks or hears.
        let mut mate = still;
        mate.predict(None, 2.7, 0.94, false);
        assert_eq!(mate, still);
        // A rolling ball predicted at an opponent's feet is believed still.
        let mut rolling = BallBelief { vel: Vec2::new(0.5, 0.0), ..still };
        rolling.predict(None, 2.7, 0.94, true);
        assert_eq!((rolling.pos, rolling.vel), (Vec2::new(1.5, 2.0), Vec2::ZERO));
    }

    #[test]
    fn a_sensed_collision_is_trilearns() {
        let (touch, reach) = (0.385, 1.085);
        // Running at 0.4 m/cycle, sensed turned round at a tenth: a collision within 1.585 m of the ball.
        let run = Vec2::new(0.4, 0.1);
        assert!(senses_collision(run, run * -0.1, 1.5, touch, reach));
        assert!(!senses_collision(run, run * -0.1, 1.6, touch, reach));
        // Decayed as predicted: none.
        assert!(!senses_collision(run, run, 0.5, touch, reach));
        // Stopped dead (sensed 0) near the ball: a collision within 0.8 m.
        assert!(senses_collision(run, Vec2::ZERO, 0.7, touch, reach));
        assert!(!senses_collision(run, Vec2::ZERO, 0.9, touch, reach));
        // Standing, sensed 0, the ball touching: a collision.
        assert!(senses_collision(Vec2::ZERO, Vec2::ZERO, 0.3, touch, reach));
        // The sense message rounds the speed to 0.01 and truncates its direction to whole degrees.
        let mut b = Body::at(Vec2::ZERO, 0.0);
        b.vel = Vec2::new(0.004, 0.0);
        assert_eq!(sensed_velocity(&b), Vec2::ZERO);
        b.vel = Vec2::from_angle(10.7 * RAD_PER_DEG) * 0.123;
        let s = sensed_velocity(&b);
        assert!((s.norm() - 0.12).abs() < 1e-12 && (s.angle() / RAD_PER_DEG - 10.0).abs() < 1e-9, "{s:?}");
        // The ball is put 0.2 m away in its believed direction, its velocity reversed at a tenth.
        let mut ball = BallBelief { pos: Vec2::new(3.0, 4.0), vel: Vec2::new(1.0, 0.5), known: true };
        ball.collide(Vec2::new(2.4, 3.2));
        assert!(ball.pos.dist(Vec2::new(2.52, 3.36)) < 1e-12 && ball.vel == Vec2::new(-0.1, -0.05), "{ball:?}");
    }

    #[test]
    fn a_heard_ball_is_taken_only_as_wmballinfo_takes_it() {
        let kick = BallMessage { pos: Vec2::new(5.0, 0.0), vel: Vec2::new(2.0, 0.0), cycles: 0 };
        let still = BallBelief { pos: Vec2::new(4.0, 0.0), vel: Vec2::ZERO, known: true };
        // Seen this cycle: the look wins.
        let mut b = still;
        assert!(!b.hear(&kick, Vec2::new(-6.0, 0.0), Some(0)));
        // Unseen for a cycle, ball 10 m away, the pass's velocity 2 m/cycle off: taken.
        assert!(b.hear(&kick, Vec2::new(-6.0, 0.0), Some(1)));
        assert_eq!((b.pos, b.vel), (kick.pos, kick.vel));
        // The same within 3 m of the hearer: kept.
        let mut near = still;
        assert!(!near.hear(&kick, Vec2::new(2.0, 0.0), Some(1)));
        // A belief message (1 cycle) is carried on by the hard-coded decay.
        let roll = BallMessage { pos: Vec2::new(0.0, 0.0), vel: Vec2::new(1.0, 0.0), cycles: 1 };
        let mut none = BallBelief::default();
        assert!(none.hear(&roll, Vec2::new(9.0, 9.0), None));
        assert_eq!(none.pos, Vec2::new(1.0, 0.0));
        assert!((none.vel.x - 0.94).abs() < 1e-12);
        // Unseen for 2 cycles, same velocity: only a message older than the look is refused.
        let mut seen2 = BallBelief { pos: Vec2::new(1.0, 0.0), vel: Vec2::new(0.94, 0.0), known: true };
        assert!(!seen2.hear(&roll, Vec2::new(9.0, 9.0), Some(2)));
    }
}
