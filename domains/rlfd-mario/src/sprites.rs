//! The sprites other than Mario: enemies, shells, bullet bills, power-ups and
//! fireballs, with their movement rules, after the benchmark 0.2.0's
//! `Enemy`, `FlowerEnemy`, `Shell`, `BulletBill`, `Mushroom`, `FireFlower`
//! and `Fireball` (units: pixels and ticks; `x` is a sprite's centre, `y` its
//! bottom edge, rows grow downwards).
//!
//! | sprite | movement |
//! |---|---|
//! | goomba, koopas, spiky | walk 1.75 px/tick, turn at walls; red koopas also turn at ledges; gravity +2/tick, `ya ×= 0.85`; winged ones hop (`ya = −10` on landing, gravity 0.6, `ya ×= 0.95`) |
//! | piranha plant | rises from its tube (`ya = −8`, `ya ← 0.9 ya + 0.1`) after 40 ticks down, unless Mario is within 24 px |
//! | shell | still until kicked, then 11 px/tick, turning at walls and killing what it meets |
//! | bullet bill | 4 px/tick in a straight line, through everything |
//! | mushroom | rises 9 ticks out of its block, then walks like a goomba |
//! | fire flower | rises 9 ticks out of its block, then stays |
//! | fireball | 8 px/tick, bounces (`ya = −10`) on the ground, gravity 1.5, dies at a wall |
//!
//! A killed sprite dies as in the benchmark (`deadTime`): it lies or falls
//! for its death's ticks without interacting, then leaves.
//!
//! What it is not: no shell carrying.

use super::decay::damp;
use super::level::{CELL, EnemyKind, Level};

/// Ground and air inertia of every mover (the benchmark's 0.89).
pub const INERTIA: f32 = 0.89;

/// What a sprite is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum SpriteKind {
    /// Turns at ledges.
    RedKoopa,
    /// Walks off ledges.
    GreenKoopa,
    /// Walks off ledges, dies when stomped.
    Goomba,
    /// Cannot be stomped, immune to fireballs.
    Spiky,
    /// A piranha plant.
    Flower,
    /// Fired by cannons.
    BulletBill,
    /// A koopa's shell.
    Shell,
    /// Makes small Mario large.
    Mushroom,
    /// Gives Mario fire.
    FireFlower,
    /// Mario's fireball.
    Fireball,
}

impl SpriteKind {
    /// The kind an enemy template spawns.
    pub fn of_enemy(kind: EnemyKind) -> SpriteKind {
        match kind {
            EnemyKind::RedKoopa => SpriteKind::RedKoopa,
            EnemyKind::GreenKoopa => SpriteKind::GreenKoopa,
            EnemyKind::Goomba => SpriteKind::Goomba,
            EnemyKind::Spiky => SpriteKind::Spiky,
            EnemyKind::Flower => SpriteKind::Flower,
        }
    }

    /// Whether the observation counts it as an enemy (anything that can hurt Mario).
    #[inline]
    pub fn is_enemy(self) -> bool {
        !matches!(self, SpriteKind::Mushroom | SpriteKind::FireFlower | SpriteKind::Fireball)
    }

    /// Walking enemies (the benchmark's `Enemy` class without plants).
    #[inline]
    pub fn is_walker(self) -> bool {
        matches!(self, SpriteKind::RedKoopa | SpriteKind::GreenKoopa | SpriteKind::Goomba | SpriteKind::Spiky)
    }
}

/// No template.
pub const NO_TEMPLATE: u32 = u32::MAX;

/// A sprite's state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sprite {
    /// What it is.
    pub kind: SpriteKind,
    /// Centre, px.
    pub x: f32,
    /// Bottom edge, px (rows grow downwards).
    pub y: f32,
    /// Horizontal speed, px/tick.
    pub xa: f32,
    /// Vertical speed, px/tick (negative is up).
    pub ya: f32,
    /// −1, 0 (a still shell) or 1.
    pub facing: i32,
    /// Standing on something.
    pub on_ground: bool,
    /// Hops.
    pub winged: bool,
    /// Half width, px.
    pub width: f32,
    /// Height, px.
    pub height: f32,
    /// Ticks lived (power-ups rising, plants waiting).
    pub timer: i32,
    /// A plant's resting height.
    pub y_start: f32,
    /// The template it came from, or [`NO_TEMPLATE`].
    pub template: u32,
    /// Leaves the scene at the end of this tick (the benchmark's
    /// `removeSprite`: until then it still moves and collides).
    pub removed: bool,
    /// Ticks of its death left (the benchmark's `deadTime`): a stomped
    /// enemy lies 10 ticks, one killed by a shell, a fireball or a bump flies
    /// off for up to 100; a dying fireball leaves on its next tick. Zero while alive.
    pub dead_time: i32,
    /// Killed by a shell, a fireball or a bump: it falls off the screen.
    pub fly_death: bool,
    /// Its template is dead (the benchmark's `isDead()`): the enemy map no
    /// longer shows it and the template never spawns again.
    pub dead: bool,
}

impl Sprite {
    fn base(kind: SpriteKind, x: f32, y: f32, facing: i32, width: f32, height: f32) -> Sprite {
        Sprite {
            kind,
            x,
            y,
            xa: 0.0,
            ya: 0.0,
            facing,
            on_ground: false,
            winged: false,
            width,
            height,
            timer: 0,
            y_start: y,
            template: NO_TEMPLATE,
            removed: false,
            dead_time: 0,
            fly_death: false,
            dead: false,
        }
    }

    /// An enemy from a template at cell `(cx, cy)`, facing `dir` (0 becomes 1).
    pub fn enemy(kind: EnemyKind, winged: bool, cx: i32, cy: i32, dir: i32, template: u32) -> Sprite {
        let mut s = if kind == EnemyKind::Flower {
            // The plant hides in its tube: centred on the tube's two columns, 24 px below its top.
            let mut s =
                Sprite::base(SpriteKind::Flower, cx as f32 * CELL + 15.0, cy as f32 * CELL + 24.0, 1, 2.0, 12.0);
            s.y_start = s.y;
            s.ya = -8.0;
            s.y -= 1.0;
            s
        } else {
            let height = if matches!(kind, EnemyKind::RedKoopa | EnemyKind::GreenKoopa) { 24.0 } else { 12.0 };
            let facing = if dir == 0 { 1 } else { dir };
            let mut s = Sprite::base(
                SpriteKind::of_enemy(kind),
                cx as f32 * CELL + 8.0,
                cy as f32 * CELL + 15.0,
                facing,
                4.0,
                height,
            );
            s.winged = winged;
            s
        };
        s.template = template;
        s
    }

    /// A still shell where a koopa was stomped.
    pub fn shell(x: f32, y: f32) -> Sprite {
        let mut s = Sprite::base(SpriteKind::Shell, x, y, 0, 4.0, 12.0);
        // The benchmark's `Shell` starts with a hop.
        s.ya = -5.0;
        s
    }

    /// A bullet bill leaving a cannon.
    pub fn bullet_bill(x: f32, y: f32, dir: i32) -> Sprite {
        let mut s = Sprite::base(SpriteKind::BulletBill, x, y, dir, 4.0, 12.0);
        s.ya = -5.0;
        s
    }

    /// A power-up rising out of the block at cell `(cx, cy)`.
    pub fn power_up(kind: SpriteKind, cx: i32, cy: i32) -> Sprite {
        Sprite::base(kind, cx as f32 * CELL + 8.0, cy as f32 * CELL + 8.0, 1, 4.0, 12.0)
    }

    /// A fireball thrown from `(x, y)` towards `facing`.
    pub fn fireball(x: f32, y: f32, facing: i32) -> Sprite {
        let mut s = Sprite::base(SpriteKind::Fireball, x, y, facing, 4.0, 8.0);
        s.ya = 4.0;
        s
    }

    /// Whether the cell holding `(px, py)` blocks; a sprite's own cell (`own`) never blocks it.
    #[inline]
    fn blocking(level: &Level, own: (i32, i32), px: f32, py: f32, ya: f32) -> bool {
        let (cx, cy) = ((px / CELL) as i32, (py / CELL) as i32);
        (cx, cy) != own && level.is_blocking(cx, cy, ya)
    }

    /// Moves by `(xa, ya)` with the benchmark's tile collisions, in steps of
    /// at most 8 px (x first, then y); false when blocked. Red koopas treat a
    /// ledge as a wall. `bumps` collects cells a moving shell hits from the
    /// side (it bumps them).
    ///
    /// Inlined so that each call site's constant zero speed (`xa` or `ya`)
    /// removes the other axis's probes and loops.
    #[inline(always)]
    pub fn move_by(&mut self, level: &Level, mut xa: f32, mut ya: f32, bumps: &mut Bumps) -> bool {
        while xa > 8.0 {
            if !self.step_by(level, 8.0, 0.0, bumps) {
                return false;
            }
            xa -= 8.0;
        }
        while xa < -8.0 {
            if !self.step_by(level, -8.0, 0.0, bumps) {
                return false;
            }
            xa += 8.0;
        }
        while ya > 8.0 {
            if !self.step_by(level, 0.0, 8.0, bumps) {
                return false;
            }
            ya -= 8.0;
        }
        while ya < -8.0 {
            if !self.step_by(level, 0.0, -8.0, bumps) {
                return false;
            }
            ya += 8.0;
        }
        self.step_by(level, xa, ya, bumps)
    }

    /// One step of [`Sprite::move_by`], at most 8 px each way.
    #[inline(always)]
    fn step_by(&mut self, level: &Level, xa: f32, ya: f32, bumps: &mut Bumps) -> bool {
        let (x, y, w, h) = (self.x, self.y, self.width, self.height);
        let own = ((x / CELL) as i32, (y / CELL) as i32);
        let mut collide = false;
        if ya > 0.0 {
            collide = Self::blocking(level, own, x + xa - w, y + ya, 0.0)
                || Self::blocking(level, own, x + xa + w, y + ya, 0.0)
                || Self::blocking(level, own, x + xa - w, y + ya + 1.0, ya)
                || Self::blocking(level, own, x + xa + w, y + ya + 1.0, ya);
        }
        if ya < 0.0 {
            collide = Self::blocking(level, own, x + xa, y + ya - h, ya)
                || Self::blocking(level, own, x + xa - w, y + ya - h, ya)
                || Self::blocking(level, own, x + xa + w, y + ya - h, ya);
        }
        if xa != 0.0 {
            let edge = if xa > 0.0 { x + xa + w } else { x + xa - w };
            for py in [y + ya - h, y + ya - h / 2.0, y + ya] {
                if Self::blocking(level, own, edge, py, ya) {
                    collide = true;
                    if self.kind == SpriteKind::Shell && ya == 0.0 {
                        bumps.push((edge / CELL) as i32, (py / CELL) as i32);
                    }
                }
            }
            if self.kind == SpriteKind::RedKoopa
                && self.on_ground
                && !level.is_blocking((edge / CELL) as i32, (y / CELL) as i32 + 1, 1.0)
            {
                collide = true;
            }
        }
        if collide {
            if xa < 0.0 {
                self.x = (((x - w) / CELL) as i32) as f32 * CELL + w;
                self.xa = 0.0;
            }
            if xa > 0.0 {
                // Truncating after adding 1, as the benchmark (it differs left of column 0).
                self.x = (((x + w) / CELL + 1.0) as i32) as f32 * CELL - w - 1.0;
                self.xa = 0.0;
            }
            if ya < 0.0 {
                self.y = (((y - h) / CELL) as i32) as f32 * CELL + h;
                self.ya = 0.0;
            }
            if ya > 0.0 {
                // Truncating after adding 1, as the benchmark (it differs above row 0).
                self.y = ((y / CELL + 1.0) as i32) as f32 * CELL - 1.0;
                self.on_ground = true;
            }
            false
        } else {
            self.x += xa;
            self.y += ya;
            true
        }
    }

    /// One tick of movement. `mario_x` is Mario's centre (plants wait while he
    /// is near their tube); `bumps` collects cells a shell hits.
    pub fn advance(&mut self, level: &Level, mario_x: f32, bumps: &mut Bumps) {
        if self.dead_time > 0 {
            // A dying fireball leaves on its next tick (`Fireball.move`).
            if self.kind == SpriteKind::Fireball {
                self.removed = true;
                return;
            }
            // The benchmark's death countdown: the sprite leaves when it ends
            // (`deadTime` is set back to 1 so that it stays dead meanwhile).
            self.dead_time -= 1;
            if self.dead_time == 0 {
                self.dead_time = 1;
                self.removed = true;
            }
            // Flying deaths, shells and bullet bills fall through everything;
            // Java's `ya *= 0.95` multiplies in double precision.
            if self.fly_death || matches!(self.kind, SpriteKind::Shell | SpriteKind::BulletBill) {
                self.x += self.xa;
                self.y += self.ya;
                self.ya = (f64::from(self.ya) * 0.95) as f32;
                self.ya += 1.0;
            }
            return;
        }
        match self.kind {
            SpriteKind::RedKoopa | SpriteKind::GreenKoopa | SpriteKind::Goomba | SpriteKind::Spiky => {
                self.walk(level, 1.75, bumps)
            }
            SpriteKind::Mushroom => {
                if self.timer < 9 {
                    self.y -= 1.0;
                    self.timer += 1;
                } else {
                    self.walk(level, 1.75, bumps);
                }
            }
            SpriteKind::FireFlower => {
                if self.timer < 9 {
                    self.y -= 1.0;
                    self.timer += 1;
                }
            }
            SpriteKind::Shell => {
                if self.facing != 0 {
                    self.walk(level, 11.0, bumps);
                } else {
                    self.xa = 0.0;
                    self.fall(level, bumps);
                }
            }
            SpriteKind::BulletBill => {
                self.xa = self.facing as f32 * 4.0;
                self.x += self.xa;
            }
            SpriteKind::Flower => {
                if self.y >= self.y_start {
                    self.y = self.y_start;
                    let xd = (mario_x - self.x).abs() as i32;
                    self.timer += 1;
                    self.ya = if self.timer > 40 && xd > 24 { -8.0 } else { 0.0 };
                } else {
                    self.timer = 0;
                }
                self.y += self.ya;
                // Java's `ya *= 0.9` rounds a double product to float; then `ya += 0.1f`.
                self.ya = (f64::from(self.ya) * 0.9) as f32;
                self.ya += 0.1;
            }
            SpriteKind::Fireball => {
                if self.xa > 2.0 {
                    self.facing = 1;
                }
                if self.xa < -2.0 {
                    self.facing = -1;
                }
                self.xa = self.facing as f32 * 8.0;
                if !self.move_by(level, self.xa, 0.0, bumps) {
                    // `Fireball.die`: it stays one more tick (counted among
                    // the fireballs on screen), then leaves.
                    self.dead_time = 100;
                    self.xa = -(self.facing as f32) * 2.0;
                    self.ya = -5.0;
                }
                self.on_ground = false;
                self.move_by(level, 0.0, self.ya, bumps);
                if self.on_ground {
                    self.ya = -10.0;
                }
                self.ya *= 0.95;
                self.xa *= INERTIA;
                if !self.on_ground {
                    self.ya += 1.5;
                }
            }
        }
    }

    /// The benchmark's `Enemy.move` (also shells at 11 px/tick and mushrooms).
    fn walk(&mut self, level: &Level, speed: f32, bumps: &mut Bumps) {
        if self.xa > 2.0 {
            self.facing = 1;
        }
        if self.xa < -2.0 {
            self.facing = -1;
        }
        self.xa = self.facing as f32 * speed;
        if !self.move_by(level, self.xa, 0.0, bumps) {
            self.facing = -self.facing;
        }
        self.fall(level, bumps);
    }

    fn fall(&mut self, level: &Level, bumps: &mut Bumps) {
        self.on_ground = false;
        self.move_by(level, 0.0, self.ya, bumps);
        // Damped without subnormal arithmetic (see `decay`): the same bits.
        self.ya = damp(self.ya, if self.winged { 0.95 } else { 0.85 });
        self.xa *= INERTIA;
        if !self.on_ground {
            self.ya += if self.winged { 0.6 } else { 2.0 };
        } else if self.winged {
            self.ya = -10.0;
        }
    }

    /// Whether `(x, y)`-anchored box of half width `hw` and height `h`
    /// overlaps this sprite the way the benchmark's collision checks test it.
    #[inline]
    pub fn touches(&self, x: f32, y: f32, reach: f32, other_height: f32) -> bool {
        let (xd, yd) = (x - self.x, y - self.y);
        xd > -reach && xd < reach && yd > -self.height && yd < other_height
    }
}

/// Cells bumped by shells during a tick (a fixed-capacity buffer: no allocation per tick).
#[derive(Clone, Debug, Default)]
pub struct Bumps {
    cells: [(i32, i32); 8],
    len: usize,
}

impl Bumps {
    /// Records a bumped cell (beyond 8 in one tick, ignored).
    pub fn push(&mut self, x: i32, y: i32) {
        if self.len < self.cells.len() {
            self.cells[self.len] = (x, y);
            self.len += 1;
        }
    }

    /// The cells, in order.
    pub fn cells(&self) -> &[(i32, i32)] {
        &self.cells[..self.len]
    }

    /// Empties the buffer.
    pub fn clear(&mut self) {
        self.len = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::level::tile;

    fn floor_level() -> Level {
        let mut l = Level::empty(40);
        for x in 0..40 {
            l.set(x, 13, tile::GROUND);
        }
        l
    }

    #[test]
    fn walkers_walk_at_1_75_and_turn_at_walls() {
        let mut l = floor_level();
        l.set(10, 12, tile::GROUND);
        let mut s = Sprite::enemy(EnemyKind::Goomba, false, 5, 12, 1, NO_TEMPLATE);
        let mut b = Bumps::default();
        // Settle on the floor.
        for _ in 0..3 {
            s.advance(&l, 0.0, &mut b);
        }
        assert!(s.on_ground);
        assert_eq!(s.y, 207.0);
        let x0 = s.x;
        s.advance(&l, 0.0, &mut b);
        assert!((s.x - x0 - 1.75).abs() < 1e-6);
        for _ in 0..40 {
            s.advance(&l, 0.0, &mut b);
        }
        assert_eq!(s.facing, -1, "turned at the wall at column 10");
        assert!(s.x < 10.0 * CELL);
    }

    #[test]
    fn red_koopas_turn_at_ledges_and_green_ones_fall() {
        let mut l = Level::empty(40);
        for x in 0..8 {
            l.set(x, 13, tile::GROUND);
        }
        let mut b = Bumps::default();
        let mut red = Sprite::enemy(EnemyKind::RedKoopa, false, 4, 12, 1, NO_TEMPLATE);
        let mut green = Sprite::enemy(EnemyKind::GreenKoopa, false, 4, 12, 1, NO_TEMPLATE);
        for _ in 0..80 {
            red.advance(&l, 0.0, &mut b);
            green.advance(&l, 0.0, &mut b);
        }
        assert!(red.y <= 208.0 && red.x < 8.0 * CELL, "red koopa stays on its ledge: {:?}", (red.x, red.y));
        assert!(green.y > 15.0 * CELL, "green koopa walked off: {:?}", (green.x, green.y));
    }

    #[test]
    fn plants_rise_about_three_cells_and_wait_while_mario_is_near() {
        let mut b = Bumps::default();
        let l = floor_level();
        let mut p = Sprite::enemy(EnemyKind::Flower, false, 10, 10, 0, NO_TEMPLATE);
        let top = 10.0 * CELL;
        let mut highest = f32::INFINITY;
        for _ in 0..200 {
            p.advance(&l, 0.0, &mut b);
            highest = highest.min(p.y);
        }
        // Rises from 24 px below the tube's top to about 35 px above it.
        assert!(highest < top - 30.0 && highest > top - 45.0, "{highest}");
        // Its first rise comes at once; once back down, it waits while Mario stands within 24 px.
        let mut q = Sprite::enemy(EnemyKind::Flower, false, 10, 10, 0, NO_TEMPLATE);
        for _ in 0..150 {
            q.advance(&l, q.x + 10.0, &mut b);
        }
        for _ in 0..200 {
            q.advance(&l, q.x + 10.0, &mut b);
            assert!(q.y >= q.y_start - 1e-3, "stays down while Mario stands beside the tube");
        }
    }

    #[test]
    fn fireballs_bounce_and_die_at_walls() {
        let mut l = floor_level();
        l.set(20, 12, tile::GROUND);
        l.set(20, 11, tile::GROUND);
        let mut b = Bumps::default();
        let mut f = Sprite::fireball(100.0, 180.0, 1);
        let mut bounced = false;
        for _ in 0..40 {
            f.advance(&l, 0.0, &mut b);
            bounced |= f.ya < -5.0;
            if f.removed {
                break;
            }
        }
        assert!(bounced);
        assert!(f.removed, "died at the wall at column 20");
    }
}
