//! The thesis's 27 state variables (section 6.3.2), computed from the game.
//!
//! The exact mapping is the oracle's `State27.java` (`../shared/oracle/mario/`),
//! which reads the Mario AI Benchmark 0.2.0's API after every tick.
//!
//! In order (the thesis's): `jump` (Mario may jump: on the ground or sliding,
//! jump key released), `ground` (on the ground), `shoot` (the API's
//! `isMarioAbleToShoot()`: the speed key was up last tick, in any mode; see
//! [`Shoot`] for our former, stricter reading); `x-dir`
//! and `y-dir` (−1, 0, 1: the sign of the last tick's move, right and up
//! positive, 0 below 0.8 px as in Liao et al.'s code); 8 `close-enemies` and
//! 8 `mid-enemies` booleans; 4 `obstacle` booleans; `closest-enemy-x` and
//! `closest-enemy-y`.
//!
//! Our readings where the thesis is brief (project decisions, in the report):
//! - **Cells.** The benchmark's 22 × 22 grid (`-rfw 22 -rfh 22`) around Mario: columns
//!   `c − 11 … c + 10`, rows `r − 11 … r + 10`, with `(c, r)` the cell of
//!   Mario's feet; a sprite's cell is that of its bottom centre.
//! - **Close and mid enemies.** An enemy's offset from Mario is counted from
//!   the nearest cell Mario occupies (large Mario fills his feet's cell and
//!   the one above, as in Liao et al.'s code). The eight cells around Mario
//!   (ring 1) are `close-enemies`; the sixteen cells of ring 2, "one step
//!   farther", are grouped into the same eight directions (the signs of the
//!   offset) as `mid-enemies`. Directions run clockwise from up: up,
//!   up-right, right, down-right, down, down-left, left, up-left. An enemy
//!   overlapping Mario's own cells is in neither ring.
//! - **Enemies** are everything that can hurt Mario: goombas, koopas, spiky,
//!   piranha plants (also while hidden in their tube, as the benchmark's
//!   enemy map shows them), bullet bills and shells.
//! - **Obstacles** are the four cells in the column right of Mario, from the
//!   cell below his feet up to two above them (Liao et al.'s rows +1 … −2),
//!   holding what the benchmark's level map (`getLevelSceneObservationZ(1)`)
//!   calls a brick, a border that cannot be passed, a flower pot or cannon,
//!   or a ladder: every tile that blocks from all sides. Hill tops (the map's
//!   `BORDER_HILL`, platforms) are not obstacles, nor are coins or hidden
//!   blocks; cells outside the level or from the exit column on read empty,
//!   as in that map.
//! - **Closest enemy.** The thesis calls these the Euclidean distance to the
//!   closest enemy within the 22 × 22 grid; we give its signed offset in
//!   cells (x right, y up) from Mario's feet, the closest by Euclidean
//!   distance, and [`NO_ENEMY`] for both when the grid holds none.

use super::level::{CELL, behaviour, behaviour_of, tile};
use super::sprites::Sprite;
use super::world::{MAX_FIREBALLS, Mode, World};

/// What the `shoot` variable reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Shoot {
    /// The benchmark's `isMarioAbleToShoot()`: the speed key was up last
    /// tick, in any mode (P(1) ≈ 0.50 under random play on the real benchmark).
    #[default]
    Api,
    /// Our former reading, kept as a declared alternative: a fireball would
    /// leave now (fire mode, the speed key up last tick, fewer than two
    /// fireballs out; P(1) ≈ 0.065 under random play).
    Strict,
}

/// Whether tile `t` is an obstacle for the observation (see the module docs).
#[inline]
fn is_obstacle(t: u8) -> bool {
    // An inner corner of the ground blocks nothing but reads as a border
    // (`BORDER_CANNOT_PASS_THROUGH`) in the benchmark's observation.
    behaviour_of(t) & behaviour::BLOCK_ALL != 0 || t == tile::GROUND_CORNER
}

/// Number of state variables.
pub const STATE_VARIABLES: usize = 27;

/// `closest-enemy-x` and `closest-enemy-y` when no enemy is in the grid (outside the grid's −11 … 11).
pub const NO_ENEMY: f64 = 16.0;

/// Movement below this many pixels per tick counts as none (Liao et al.'s threshold).
pub const DIRECTION_THRESHOLD: f32 = 0.8;

/// The variables' names, in order.
pub const NAMES: [&str; STATE_VARIABLES] = [
    "jump",
    "ground",
    "shoot",
    "x-dir",
    "y-dir",
    "close-up",
    "close-up-right",
    "close-right",
    "close-down-right",
    "close-down",
    "close-down-left",
    "close-left",
    "close-up-left",
    "mid-up",
    "mid-up-right",
    "mid-right",
    "mid-down-right",
    "mid-down",
    "mid-down-left",
    "mid-left",
    "mid-up-left",
    "obstacle-below",
    "obstacle-feet",
    "obstacle-body",
    "obstacle-above",
    "closest-enemy-x",
    "closest-enemy-y",
];

/// Index of the first `close-enemies` variable.
pub const CLOSE: usize = 5;
/// Index of the first `mid-enemies` variable.
pub const MID: usize = 13;
/// Index of the first `obstacle` variable.
pub const OBSTACLE: usize = 21;
/// Index of `closest-enemy-x` (`closest-enemy-y` follows).
pub const CLOSEST: usize = 25;

/// The direction index (0 up, clockwise) of a cell offset's signs (`sy` positive down).
#[inline]
pub fn direction(sx: i32, sy: i32) -> Option<usize> {
    match (sx.signum(), sy.signum()) {
        (0, -1) => Some(0),
        (1, -1) => Some(1),
        (1, 0) => Some(2),
        (1, 1) => Some(3),
        (0, 1) => Some(4),
        (-1, 1) => Some(5),
        (-1, 0) => Some(6),
        (-1, -1) => Some(7),
        _ => None,
    }
}

/// The 27 variables packed into 37 bits (one per boolean, two per
/// direction, five per closest-enemy offset), or `None` when a value is not
/// one the game produces. A key for memoising per-state computations.
///
/// Branch-free (every variable is tested, the verdicts are combined): it
/// runs once per agent step.
#[inline]
pub fn pack(state: &[f64]) -> Option<u64> {
    let state: &[f64; STATE_VARIABLES] = state.try_into().ok()?;
    let mut valid = true;
    // The booleans, first one highest: jump, ground, shoot, then the 20 from close-up on.
    let (mut first, mut rest) = (0u64, 0u64);
    for (j, &v) in state[..3].iter().enumerate() {
        valid &= (v == 0.0) | (v == 1.0);
        first |= u64::from(v == 1.0) << (2 - j);
    }
    for (j, &v) in state[CLOSE..CLOSEST].iter().enumerate() {
        valid &= (v == 0.0) | (v == 1.0);
        rest |= u64::from(v == 1.0) << (CLOSEST - CLOSE - 1 - j);
    }
    // The directions −1, 0, 1 as 0, 1, 2.
    let mut directions = 0u64;
    for &v in &state[3..CLOSE] {
        valid &= (v == -1.0) | (v == 0.0) | (v == 1.0);
        directions = (directions << 2) | (u64::from(v == 0.0) + 2 * u64::from(v == 1.0));
    }
    // The closest enemy's offsets −11 … 16 as 0 … 27.
    let mut closest = 0u64;
    for &v in &state[CLOSEST..] {
        let u = v + 11.0;
        let k = u as i64;
        valid &= (k as f64 == u) & (0..=27).contains(&k);
        closest = (closest << 5) | (k as u64 & 31);
    }
    valid.then_some((first << 34) | (directions << 30) | (rest << 10) | closest)
}

/// The bits of [`pack`]'s key that hold the 23 booleans.
const PACKED_BOOLEANS: u64 = (0b111 << 34) | (((1 << 20) - 1) << 10);

/// Squared differences between two [`pack`]ed states, summed in two groups:
/// over the 23 booleans and the two directions, and over the two
/// closest-enemy offsets (in cells). The squared Euclidean distance between
/// the states, each variable scaled by its group's `1 / σ`, is
/// `first · (1/σ₁)² + second · (1/σ₂)²`: what SBS's similarity potential
/// needs, from two keys without unpacking them.
#[inline]
pub fn packed_differences(a: u64, b: u64) -> (u32, u32) {
    let sq = |shift: u32, mask: u64| {
        let d = ((a >> shift) & mask) as i32 - ((b >> shift) & mask) as i32;
        (d * d) as u32
    };
    let booleans = ((a ^ b) & PACKED_BOOLEANS).count_ones();
    (booleans + sq(32, 3) + sq(30, 3), sq(5, 31) + sq(0, 31))
}

/// [`pack`] as first written, one variable at a time (the reference its tests compare with).
#[cfg(test)]
fn pack_reference(state: &[f64]) -> Option<u64> {
    /// Bits, offset and largest offset value of each variable.
    const LAYOUT: [(u32, f64, i64); STATE_VARIABLES] = {
        let mut l = [(1u32, 0.0f64, 1i64); STATE_VARIABLES];
        l[3] = (2, 1.0, 2);
        l[4] = (2, 1.0, 2);
        l[CLOSEST] = (5, 11.0, 27);
        l[CLOSEST + 1] = (5, 11.0, 27);
        l
    };
    if state.len() != STATE_VARIABLES {
        return None;
    }
    let mut key = 0u64;
    for (&v, &(bits, offset, max)) in state.iter().zip(&LAYOUT) {
        let u = v + offset;
        let k = u as i64;
        if k as f64 != u || !(0..=max).contains(&k) {
            return None;
        }
        key = (key << bits) | k as u64;
    }
    Some(key)
}

#[inline]
fn sign(d: f32) -> f64 {
    if d.abs() < DIRECTION_THRESHOLD {
        0.0
    } else if d > 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// Writes the 27 variables of `world` into `out`, `shoot` read as the
/// benchmark's API; `previous` is Mario's position one tick earlier (for the directions).
pub fn observe(world: &World, previous: (f32, f32), out: &mut [f64; STATE_VARIABLES]) {
    observe_with(world, previous, Shoot::Api, out);
}

/// [`observe`] with the `shoot` variable read as `shoot`.
pub fn observe_with(world: &World, previous: (f32, f32), shoot: Shoot, out: &mut [f64; STATE_VARIABLES]) {
    let m = world.mario();
    out.fill(0.0);
    out[0] = f64::from(u8::from(m.may_jump));
    out[1] = f64::from(u8::from(m.on_ground));
    let can_shoot = match shoot {
        Shoot::Api => m.able_to_shoot,
        Shoot::Strict => m.mode == Mode::Fire && m.able_to_shoot && world.fireballs() < MAX_FIREBALLS,
    };
    out[2] = f64::from(u8::from(can_shoot));
    out[3] = sign(m.x - previous.0);
    out[4] = sign(previous.1 - m.y);
    let (mc, mr) = m.cell();
    let head = if m.is_large() { mr - 1 } else { mr };
    let mut best = (i32::MAX, 0, 0);
    // The benchmark's enemy map (`getEnemiesObservationZ(2)`), built as it
    // builds it: every sprite of the list in order writes its cell, an enemy
    // 1 and anything else (a fireball, a mushroom, a fire flower) 0, so a
    // later non-enemy hides an enemy in its cell; sprites whose template is
    // dead (`Sprite.isDead()`: stomped or burnt enemies lying or flying off),
    // and sprites left of column 0 or above row 0, are left out. (The
    // benchmark's sparkles, coin animations and brick particles write 0 too;
    // we do not simulate them.) Mario sits at row and column 11 of 22.
    // The map's cell of sprite `s`, if it is on the map.
    let cell_of = |s: &Sprite| {
        let (ec, er) = ((s.x / CELL) as i32, (s.y / CELL) as i32);
        let (dx, dr) = (ec - mc, er - mr);
        (!s.dead && ec >= 0 && er >= 0 && (-11..=10).contains(&dx) && (-11..=10).contains(&dr)).then_some((dx, dr))
    };
    // The few non-enemies on the map (their list index and cell): an enemy
    // counts unless one of them comes later in the list in its cell. (Not a
    // 22 × 22 grid: clearing and scanning it every tick cost three times the
    // rest of the tick.) Beyond 8 of them, the rest are ignored (fireballs are
    // at most 2, power-ups rarely more than 1 on screen).
    let mut hiders = [(0usize, 0i32, 0i32); 8];
    let mut n_hiders = 0;
    for (k, s) in world.sprites().iter().enumerate() {
        if !s.kind.is_enemy()
            && n_hiders < hiders.len()
            && let Some((dx, dr)) = cell_of(s)
        {
            hiders[n_hiders] = (k, dx, dr);
            n_hiders += 1;
        }
    }
    for (k, s) in world.sprites().iter().enumerate() {
        if !s.kind.is_enemy() {
            continue;
        }
        let Some((dx, dr)) = cell_of(s) else { continue };
        if hiders[..n_hiders].iter().any(|&(j, hx, hr)| j > k && (hx, hr) == (dx, dr)) {
            continue;
        }
        let er = mr + dr;
        let d2 = dx * dx + dr * dr;
        // Ties go to the first cell in the map's row-major order, as the
        // oracle's State27 scans it.
        if (d2, dr, dx) < (best.0, best.2, best.1) {
            best = (d2, dx, dr);
        }
        let dy = if er > mr {
            er - mr
        } else if er >= head {
            0
        } else {
            er - head
        };
        let ring = dx.abs().max(dy.abs());
        if let Some(d) = direction(dx, dy) {
            match ring {
                1 => out[CLOSE + d] = 1.0,
                2 => out[MID + d] = 1.0,
                _ => {}
            }
        }
    }
    let level = world.level();
    for (k, row) in [mr + 1, mr, mr - 1, mr - 2].into_iter().enumerate() {
        // The benchmark's level map (`getLevelSceneObservationZ`, which the
        // oracle's State27 reads) is empty outside the level; the exit column
        // is inside (only the merged map stops at the exit).
        let t = level.get_inside(mc + 1, row);
        out[OBSTACLE + k] = f64::from(u8::from(t.is_some_and(is_obstacle)));
    }
    if best.0 == i32::MAX {
        out[CLOSEST] = NO_ENEMY;
        out[CLOSEST + 1] = NO_ENEMY;
    } else {
        out[CLOSEST] = f64::from(best.1);
        out[CLOSEST + 1] = f64::from(-best.2);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::level::{EnemyKind, Level, tile};
    use crate::sprites::{NO_TEMPLATE, Sprite};
    use crate::world::Keys;

    /// Mario standing at cell (10, 12) on a floor at row 13.
    fn scene(mode: Mode) -> World {
        let mut l = Level::empty(60);
        for x in 0..60 {
            l.set(x, 13, tile::GROUND);
        }
        let mut w = World::new(l, mode);
        for _ in 0..40 {
            w.tick(Keys::default());
        }
        w.mario_mut().x = 10.0 * CELL + 8.0;
        w
    }

    fn goomba_at(w: &mut World, c: i32, r: i32) {
        w.add_sprite(Sprite::enemy(EnemyKind::Goomba, false, c, r, 1, NO_TEMPLATE));
    }

    fn obs(w: &World, prev: (f32, f32)) -> [f64; STATE_VARIABLES] {
        let mut o = [0.0; STATE_VARIABLES];
        observe(w, prev, &mut o);
        o
    }

    #[test]
    fn packing_is_one_to_one_on_game_values() {
        let mut a = [0.0; STATE_VARIABLES];
        a[CLOSEST] = NO_ENEMY;
        a[CLOSEST + 1] = -11.0;
        a[3] = -1.0;
        let mut b = a;
        b[24] = 1.0;
        assert_ne!(pack(&a), pack(&b));
        assert!(pack(&a).is_some());
        a[5] = 0.5;
        assert_eq!(pack(&a), None);
        assert_eq!(pack(&[0.0; 3]), None);
    }

    proptest::proptest! {
        // The branch-free packing is the reference's, on game values and on
        // values the game never produces (fractions, NaN, out of range).
        #[test]
        fn packing_equals_the_reference(
            picks in proptest::collection::vec((0usize..6, -13i32..19), STATE_VARIABLES),
            odd in proptest::collection::vec(proptest::prop_oneof![
                proptest::num::f64::ANY, -20.0f64..20.0, proptest::strategy::Just(-0.0f64)
            ], STATE_VARIABLES),
            spoil in proptest::option::of((0usize..STATE_VARIABLES, proptest::bool::ANY)),
        ) {
            let mut s = [0.0f64; STATE_VARIABLES];
            for (i, &(pick, offset)) in picks.iter().enumerate() {
                s[i] = match pick {
                    0 | 1 => f64::from(pick as u8),
                    2 => -1.0,
                    3 => f64::from(offset),
                    4 => odd[i],
                    _ => if i >= CLOSEST { f64::from(offset) } else { 0.0 },
                };
            }
            proptest::prop_assert_eq!(pack(&s), pack_reference(&s));
            let mut game = [0.0f64; STATE_VARIABLES];
            for (i, &(pick, offset)) in picks.iter().enumerate() {
                game[i] = match i {
                    3 | 4 => f64::from(pick as i32 % 3 - 1),
                    CLOSEST.. => f64::from(offset.clamp(-11, 16)),
                    _ => f64::from(pick as u8 % 2),
                };
            }
            if let Some((i, half)) = spoil {
                game[i] += if half { 0.5 } else { 1e-9 };
            }
            proptest::prop_assert_eq!(pack(&game), pack_reference(&game));
            proptest::prop_assert_eq!(pack(&game).is_some(), spoil.is_none());
        }
    }

    proptest::proptest! {
        // The differences from two keys are the variables' own.
        #[test]
        fn packed_differences_are_the_variables_squared_differences(
            picks in proptest::collection::vec((0usize..6, -11i32..17, 0usize..6, -11i32..17), STATE_VARIABLES),
        ) {
            let (mut x, mut y) = ([0.0f64; STATE_VARIABLES], [0.0f64; STATE_VARIABLES]);
            for (i, &(p, o, q, r)) in picks.iter().enumerate() {
                (x[i], y[i]) = match i {
                    3 | 4 => (f64::from(p as i32 % 3 - 1), f64::from(q as i32 % 3 - 1)),
                    CLOSEST.. => (f64::from(o), f64::from(r)),
                    _ => (f64::from(p as u8 % 2), f64::from(q as u8 % 2)),
                };
            }
            let sq = |r: std::ops::Range<usize>| r.map(|j| (x[j] - y[j]) * (x[j] - y[j])).sum::<f64>();
            let (first, second) = packed_differences(pack(&x).unwrap(), pack(&y).unwrap());
            proptest::prop_assert_eq!(f64::from(first), sq(0..CLOSEST));
            proptest::prop_assert_eq!(f64::from(second), sq(CLOSEST..STATE_VARIABLES));
        }
    }

    #[test]
    fn twenty_seven_named_variables() {
        assert_eq!(NAMES.len(), 27);
        assert_eq!(3 + 2 + 8 + 8 + 4 + 2, STATE_VARIABLES);
        assert_eq!(NAMES[CLOSE], "close-up");
        assert_eq!(NAMES[MID + 7], "mid-up-left");
        assert_eq!(NAMES[OBSTACLE], "obstacle-below");
        assert_eq!(NAMES[CLOSEST + 1], "closest-enemy-y");
    }

    #[test]
    fn an_empty_scene() {
        let w = scene(Mode::Small);
        let m = *w.mario();
        assert_eq!(m.cell(), (10, 12));
        let o = obs(&w, (m.x, m.y));
        // jump (on ground, key released), ground; the speed key was up last tick; still.
        assert_eq!(&o[..5], &[1.0, 1.0, 1.0, 0.0, 0.0]);
        // Under the strict reading small Mario cannot shoot.
        let mut strict = [0.0; STATE_VARIABLES];
        observe_with(&w, (m.x, m.y), Shoot::Strict, &mut strict);
        assert_eq!(strict[2], 0.0);
        assert!(o[CLOSE..OBSTACLE].iter().all(|&v| v == 0.0));
        // Only the floor below the next column.
        assert_eq!(&o[OBSTACLE..CLOSEST], &[1.0, 0.0, 0.0, 0.0]);
        assert_eq!(&o[CLOSEST..], &[NO_ENEMY, NO_ENEMY]);
    }

    #[test]
    fn jump_ground_shoot_and_directions() {
        let mut w = scene(Mode::Fire);
        let m = *w.mario();
        let o = obs(&w, (m.x, m.y));
        assert_eq!(o[2], 1.0, "fire Mario with the speed key up can shoot");
        // Holding speed: no fresh press, cannot shoot.
        w.tick(Keys { speed: true, ..Keys::default() });
        let m = *w.mario();
        assert_eq!(obs(&w, (m.x, m.y))[2], 0.0);
        // Jump key held: may not jump; in the air: not on the ground; moving up and right.
        w.tick(Keys { jump: true, right: true, ..Keys::default() });
        let prev = (w.mario().x, w.mario().y);
        w.tick(Keys { jump: true, right: true, ..Keys::default() });
        let o = obs(&w, prev);
        assert_eq!(&o[..2], &[0.0, 0.0]);
        assert_eq!(o[3], 1.0);
        assert_eq!(o[4], 1.0);
        // Falling left.
        let o = obs(&w, (w.mario().x + 5.0, w.mario().y - 5.0));
        assert_eq!((o[3], o[4]), (-1.0, -1.0));
        // Below the threshold: no direction.
        let o = obs(&w, (w.mario().x - 0.5, w.mario().y + 0.5));
        assert_eq!((o[3], o[4]), (0.0, 0.0));
    }

    #[test]
    fn every_close_and_mid_direction() {
        // Ring 1 and ring 2 around small Mario at (10, 12), one enemy at a time.
        let offsets = [(0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1)];
        for (d, &(dx, dy)) in offsets.iter().enumerate() {
            for ring in [1, 2] {
                let mut w = scene(Mode::Small);
                goomba_at(&mut w, 10 + dx * ring, 12 + dy * ring);
                let m = *w.mario();
                let o = obs(&w, (m.x, m.y));
                let at = if ring == 1 { CLOSE + d } else { MID + d };
                for k in CLOSE..OBSTACLE {
                    assert_eq!(o[k], f64::from(u8::from(k == at)), "{} for ring {ring} offset {dx},{dy}", NAMES[k]);
                }
                assert_eq!(o[CLOSEST], f64::from(dx * ring));
                assert_eq!(o[CLOSEST + 1], f64::from(-dy * ring));
            }
        }
        // Ring 2's off-diagonal cells group with the diagonal direction of their signs.
        let mut w = scene(Mode::Small);
        goomba_at(&mut w, 12, 11);
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert_eq!(o[MID + 1], 1.0, "two right, one up: mid up-right");
        // Ring 3 is neither close nor mid, but is the closest enemy.
        let mut w = scene(Mode::Small);
        goomba_at(&mut w, 13, 12);
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert!(o[CLOSE..OBSTACLE].iter().all(|&v| v == 0.0));
        assert_eq!(&o[CLOSEST..], &[3.0, 0.0]);
    }

    #[test]
    fn large_mario_counts_from_his_head_too() {
        // An enemy one cell above large Mario's head (two above his feet) is close-up.
        let mut w = scene(Mode::Large);
        goomba_at(&mut w, 10, 10);
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert_eq!(o[CLOSE], 1.0);
        // Beside his head: close-right.
        let mut w = scene(Mode::Large);
        goomba_at(&mut w, 11, 11);
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert_eq!(o[CLOSE + 2], 1.0);
        assert_eq!(&o[CLOSEST..], &[1.0, 1.0]);
    }

    #[test]
    fn the_closest_enemy_is_euclidean_and_the_grid_is_22_by_22() {
        let mut w = scene(Mode::Small);
        goomba_at(&mut w, 14, 12); // distance 4
        goomba_at(&mut w, 7, 10); // distance √13 ≈ 3.6
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert_eq!(&o[CLOSEST..], &[-3.0, 2.0]);
        // Column c + 10 is in the grid, c + 11 is not; c − 11 is.
        for (c, inside) in [(20, true), (21, false), (-1, true)] {
            let mut w = scene(Mode::Small);
            goomba_at(&mut w, c, 12);
            let o = obs(&w, (w.mario().x, w.mario().y));
            assert_eq!(o[CLOSEST] != NO_ENEMY, inside, "column {c}");
        }
        // Items are not enemies.
        let mut w = scene(Mode::Small);
        w.add_sprite(Sprite::power_up(crate::sprites::SpriteKind::Mushroom, 11, 12));
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert_eq!(o[CLOSEST], NO_ENEMY);
        assert_eq!(o[CLOSE + 2], 0.0);
    }

    #[test]
    fn obstacles_in_the_next_column() {
        let mut w = scene(Mode::Small);
        // A tube three cells tall right of Mario: rows 10–12 above the floor at 13.
        w.level_mut().set(11, 10, tile::TUBE_TOP);
        w.level_mut().set(11, 11, tile::TUBE);
        w.level_mut().set(11, 12, tile::TUBE);
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert_eq!(&o[OBSTACLE..CLOSEST], &[1.0, 1.0, 1.0, 1.0]);
        // A gap ahead and a coin: no obstacle; neither a hill top (a platform) nor a hidden block counts.
        let mut w = scene(Mode::Small);
        w.level_mut().set(11, 13, tile::EMPTY);
        w.level_mut().set(11, 12, tile::COIN);
        w.level_mut().set(11, 11, tile::HILL_TOP);
        w.level_mut().set(11, 10, tile::HIDDEN);
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert_eq!(&o[OBSTACLE..CLOSEST], &[0.0, 0.0, 0.0, 0.0]);
        // A brick, a question block and a used block are obstacles.
        w.level_mut().set(11, 12, tile::BRICK);
        w.level_mut().set(11, 11, tile::QUESTION_COINS);
        w.level_mut().set(11, 10, tile::USED);
        let o = obs(&w, (w.mario().x, w.mario().y));
        assert_eq!(&o[OBSTACLE..CLOSEST], &[0.0, 1.0, 1.0, 1.0]);
    }
}
