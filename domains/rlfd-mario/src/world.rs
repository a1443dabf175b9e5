//! One Mario game: Mario's physics, the sprites, the screen's spawner and the
//! scoring, advanced one tick at a time (the benchmark 0.2.0's `LevelScene.tick`
//! and `Mario.move`, in pixels and ticks).
//!
//! Mario per tick (keys: left, right, jump, speed):
//!
//! ```text
//! accel = 1.2 if speed else 0.6; jump pressed: on ground and may jump → jumpTime = 7, ya = −1.9·7;
//! held while jumpTime > 0 → ya = −1.9·jumpTime, jumpTime −= 1; against a wall in the air → wall jump
//! (xa = −6·facing, ya = 2·6, jumpTime = −6 counting up); released → jumpTime = 0
//! left/right: xa ∓= accel;  move(xa, 0); move(0, ya) with tile collisions (8 px sub-steps)
//! ya ×= 0.85; xa ×= 0.89; airborne: ya += 3
//! ```
//!
//! A tick runs in the order of the benchmark 0.2.0's `LevelScene.tick`: the
//! timer; sprites far off screen marked to leave (they still move and
//! collide this tick); the spawner, each newborn moving once as it is added;
//! every sprite in list order (newest first) and then Mario, who is always
//! last in the benchmark's list; every sprite's check against Mario (stomp
//! from above when falling, else hurt); the moving shells, then the
//! fireballs, against every sprite; finally the newborns join at the list's
//! front and the leavers go. A killed enemy lies dead 10 ticks (stomped) or
//! flies off for up to 100 (shell, fireball, a block bumped under it), off the
//! enemy map, its template dead. `examples/replay_oracle.rs` replays episodes
//! recorded from the real benchmark and finds them identical tick by tick.
//! Scoring is the benchmark's
//! intermediate reward ("SystemOfValues"): +10 per stomp (enemies, shells,
//! bullet bills), +58 mushroom, +64 fire flower, +16 coin, +24 hidden block,
//! +1,024 win, −42 hurt, −512 death (a small Mario hit pays both; a hit in
//! the tick Mario wins still counts). The timer starts at 200 Mario seconds =
//! 3,000 ticks; at 0 Mario dies.
//!
//! What it is not: no drawing; no shell carrying; no ducking (the thesis's 12
//! actions have no down key); no sparkles, coin animations or brick
//! particles (sprites that touch nothing). There is no world pause on a hurt
//! or a power-up: the benchmark 0.2.0 has none either (its `paused` line in
//! `Mario.getHurt` is commented out).

use super::decay::damp;
use super::level::{CELL, EnemyKind, Level, ROWS, behaviour, behaviour_of, tile};
use super::sprites::{Bumps, INERTIA, NO_TEMPLATE, Sprite, SpriteKind};

/// Points of the benchmark's intermediate reward (the thesis's reward table).
pub mod points {
    /// Stomping an enemy, a shell or a bullet bill.
    pub const STOMP: i32 = 10;
    /// Eating a mushroom.
    pub const MUSHROOM: i32 = 58;
    /// Eating a fire flower.
    pub const FIRE_FLOWER: i32 = 64;
    /// A coin.
    pub const COIN: i32 = 16;
    /// Finding a hidden block.
    pub const HIDDEN_BLOCK: i32 = 24;
    /// Finishing the level.
    pub const WIN: i32 = 1024;
    /// Getting hurt (losing a mode).
    pub const HURT: i32 = -42;
    /// Dying (−win/2).
    pub const DEATH: i32 = -512;
}

/// Ticks of the 200-Mario-second timer (15 ticks per Mario second).
pub const TIME_LIMIT_TICKS: i32 = 3000;

/// Ticks Mario cannot be hurt after losing a mode.
pub const INVULNERABLE_TICKS: i32 = 32;

/// Fireballs allowed on screen at once.
pub const MAX_FIREBALLS: usize = 2;

/// Sprites kept at once (a spawn beyond it is dropped; levels never come near).
pub const MAX_SPRITES: usize = 128;

/// Screen width and height in px (20 × 15 cells).
const SCREEN_W: f32 = 320.0;
const SCREEN_H: f32 = 240.0;

/// Mario's size and power.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Mode {
    /// One hit kills.
    Small = 0,
    /// Two cells tall, breaks bricks.
    Large = 1,
    /// Large and throws fireballs.
    Fire = 2,
}

impl Mode {
    /// The three modes, small to fire.
    pub const ALL: [Mode; 3] = [Mode::Small, Mode::Large, Mode::Fire];
}

/// How the game stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Playing.
    Running,
    /// Reached the exit.
    Won,
    /// Died (hit while small, fell, or ran out of time).
    Dead,
}

/// The keys of one tick.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Keys {
    /// Left.
    pub left: bool,
    /// Right.
    pub right: bool,
    /// Jump.
    pub jump: bool,
    /// Speed (run) and fire.
    pub speed: bool,
}

/// Mario.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mario {
    /// Centre, px.
    pub x: f32,
    /// Bottom edge (feet), px.
    pub y: f32,
    /// Horizontal speed, px/tick.
    pub xa: f32,
    /// Vertical speed, px/tick (negative is up).
    pub ya: f32,
    /// −1 or 1.
    pub facing: i32,
    /// Size and power.
    pub mode: Mode,
    /// Standing on something.
    pub on_ground: bool,
    /// Was standing on something before this tick.
    pub was_on_ground: bool,
    /// May start a jump (on ground or sliding, jump key released).
    pub may_jump: bool,
    /// Sliding down a wall.
    pub sliding: bool,
    /// Jump ticks left (negative: a wall jump).
    pub jump_time: i32,
    x_jump_speed: f32,
    y_jump_speed: f32,
    /// The speed key was up last tick (a fireball needs a fresh press).
    pub able_to_shoot: bool,
    /// Ticks left without being hurt.
    pub invulnerable: i32,
}

impl Mario {
    fn new(mode: Mode) -> Mario {
        Mario {
            x: 32.0,
            // The benchmark's default start (`-mix 32 -miy 32`): in the air, falling.
            y: 32.0,
            xa: 0.0,
            ya: 0.0,
            facing: 1,
            mode,
            on_ground: false,
            was_on_ground: false,
            may_jump: false,
            sliding: false,
            jump_time: 0,
            x_jump_speed: 0.0,
            y_jump_speed: 0.0,
            able_to_shoot: false,
            invulnerable: 0,
        }
    }

    /// Height in px: 24 when large, 12 when small.
    #[inline]
    pub fn height(&self) -> f32 {
        if self.mode == Mode::Small { 12.0 } else { 24.0 }
    }

    /// Whether Mario is two cells tall.
    #[inline]
    pub fn is_large(&self) -> bool {
        self.mode != Mode::Small
    }

    /// The cell of Mario's feet.
    #[inline]
    pub fn cell(&self) -> (i32, i32) {
        ((self.x / CELL) as i32, (self.y / CELL) as i32)
    }
}

/// Enemies killed so far, by what killed them (the benchmark's
/// `killedCreaturesByStomp`, `…ByFireBall`, `…ByShell`; winged enemies losing
/// their wings and shells are not kills).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Kills {
    /// Stomped (enemies without wings, and bullet bills).
    pub stomp: u32,
    /// Burnt by a fireball.
    pub fire: u32,
    /// Hit by a moving shell.
    pub shell: u32,
}

/// Where a sprite is during a tick: in the list, or among this tick's newborns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Slot {
    Old(usize),
    Born(usize),
}

/// The shells and fireballs listed for checking during a tick (a fixed
/// buffer: no allocation per tick; beyond its size, ignored).
#[derive(Clone, Debug)]
struct Checks {
    slots: [Slot; 16],
    len: usize,
}

impl Checks {
    fn clear(&mut self) {
        self.len = 0;
    }

    fn push(&mut self, slot: Slot) {
        if self.len < self.slots.len() {
            self.slots[self.len] = slot;
            self.len += 1;
        }
    }

    fn len(&self) -> usize {
        self.len
    }

    fn get(&self, k: usize) -> Slot {
        self.slots[k]
    }
}

/// The state of a template during a game.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct TemplateState {
    last_visible: i32,
    alive: bool,
    dead: bool,
}

/// A game in progress.
#[derive(Clone, Debug)]
pub struct World {
    level: Level,
    mario: Mario,
    /// The benchmark's sprite list without Mario (who is always last), newest first.
    sprites: Vec<Sprite>,
    /// This tick's newborns, in the order they were added.
    born: Vec<Sprite>,
    /// The next tick's list, built at the tick's end (kept to reuse its memory).
    scratch: Vec<Sprite>,
    checks: Checks,
    templates: Vec<TemplateState>,
    bumps: Bumps,
    tick: i32,
    /// The first template whose column is not left of the screen (a cursor: the screen moves little per tick).
    first_template: usize,
    time_left: i32,
    status: Status,
    bonus: i32,
    keys: Keys,
    stomps: u32,
    coins: u32,
    hurts: u32,
    kills: Kills,
}

impl World {
    /// A game on `level`, Mario starting in `mode` at the benchmark's start (x 32, y 32, falling).
    pub fn new(level: Level, mode: Mode) -> World {
        let mut w = World {
            mario: Mario::new(mode),
            sprites: Vec::with_capacity(MAX_SPRITES),
            born: Vec::with_capacity(MAX_SPRITES),
            scratch: Vec::with_capacity(MAX_SPRITES),
            checks: Checks { slots: [Slot::Old(0); 16], len: 0 },
            templates: Vec::with_capacity(level.templates().len()),
            bumps: Bumps::default(),
            tick: 0,
            first_template: 0,
            time_left: TIME_LIMIT_TICKS,
            status: Status::Running,
            bonus: 0,
            keys: Keys::default(),
            stomps: 0,
            coins: 0,
            hurts: 0,
            kills: Kills::default(),
            level,
        };
        w.restart(mode);
        w
    }

    /// Starts a new game on the current level (after [`World::level_mut`] regenerated it).
    pub fn restart(&mut self, mode: Mode) {
        self.mario = Mario::new(mode);
        self.sprites.clear();
        self.born.clear();
        self.templates.clear();
        self.templates.resize(self.level.templates().len(), TemplateState { last_visible: -10, ..Default::default() });
        self.bumps.clear();
        self.tick = 0;
        self.first_template = 0;
        self.time_left = TIME_LIMIT_TICKS;
        self.status = Status::Running;
        self.bonus = 0;
        self.keys = Keys::default();
        self.stomps = 0;
        self.coins = 0;
        self.hurts = 0;
        self.kills = Kills::default();
    }

    /// The level (tiles change as blocks are bumped and coins taken).
    pub fn level(&self) -> &Level {
        &self.level
    }

    /// The level, to regenerate it before [`World::restart`].
    pub fn level_mut(&mut self) -> &mut Level {
        &mut self.level
    }

    /// Mario.
    pub fn mario(&self) -> &Mario {
        &self.mario
    }

    /// Mario, for hand-built scenes.
    pub fn mario_mut(&mut self) -> &mut Mario {
        &mut self.mario
    }

    /// The sprites on screen.
    pub fn sprites(&self) -> &[Sprite] {
        &self.sprites
    }

    /// Adds a sprite (for hand-built scenes).
    pub fn add_sprite(&mut self, s: Sprite) {
        if self.sprites.len() < MAX_SPRITES {
            self.sprites.push(s);
        }
    }

    /// How the game stands.
    pub fn status(&self) -> Status {
        self.status
    }

    /// Ticks played.
    pub fn ticks(&self) -> i32 {
        self.tick
    }

    /// Ticks left on the timer.
    pub fn time_left(&self) -> i32 {
        self.time_left
    }

    /// Enemies, shells and bullet bills stomped so far.
    pub fn stomps(&self) -> u32 {
        self.stomps
    }

    /// Enemies killed so far, by cause.
    pub fn kills(&self) -> Kills {
        self.kills
    }

    /// Times Mario was hurt (lost a mode or died by a creature).
    pub fn hurts(&self) -> u32 {
        self.hurts
    }

    /// Coins collected so far (from tiles and blocks).
    pub fn coins(&self) -> u32 {
        self.coins
    }

    /// Fireballs on screen.
    pub fn fireballs(&self) -> usize {
        self.sprites.iter().filter(|s| s.kind == SpriteKind::Fireball).count()
    }

    /// Advances one tick with `keys` and returns the points it earned.
    ///
    /// The benchmark's `LevelScene.tick`, step for step: sprites far off
    /// screen are marked to leave (they still move and collide this tick);
    /// the spawner adds the templates coming into view, each newborn moving
    /// once as it is added (`addSprite` ticks it); every sprite moves in list
    /// order, newest first, and Mario, who is always last, moves after them;
    /// then every sprite checks Mario in the same order; then the moving
    /// shells, then the fireballs, check the other sprites; at the end the
    /// newborns join at the front of the list and the leavers go.
    pub fn tick(&mut self, keys: Keys) -> i32 {
        assert_eq!(self.status, Status::Running, "a finished game cannot tick");
        self.keys = keys;
        self.bonus = 0;
        self.time_left -= 1;
        if self.time_left == 0 {
            // The benchmark goes on with the tick, but a dying Mario neither
            // moves by his keys nor scores: he only starts to fall (`Mario.move`
            // with `deathTime` set), and the game ends with the tick.
            self.die();
            let m = &mut self.mario;
            m.ya += 2.0;
            m.x += m.xa;
            m.y += m.ya;
            return self.bonus;
        }
        let x_cam = (self.mario.x - 160.0).clamp(0.0, (self.level.width() as f32 * CELL - SCREEN_W).max(0.0));
        // The fireballs on screen are counted at the tick's start, dying ones
        // included (`fireballsOnScreen`), among the sprites that stay.
        let mut fireballs = 0;
        for s in &mut self.sprites {
            let (xd, yd) = (s.x - x_cam, s.y);
            if !(-64.0..=SCREEN_W + 64.0).contains(&xd) || !(-64.0..=SCREEN_H + 64.0).contains(&yd) {
                s.removed = true;
            } else {
                fireballs += usize::from(s.kind == SpriteKind::Fireball);
            }
        }
        self.tick += 1;
        self.checks.clear();
        self.spawn(x_cam);
        let mario_x = self.mario.x;
        for i in 0..self.sprites.len() {
            self.advance(Slot::Old(i), mario_x);
        }
        self.move_mario(fireballs);
        for i in 0..self.sprites.len() {
            self.collide_with_mario(i);
        }
        self.shells_and_fireballs();
        self.finish_tick();
        self.bonus
    }

    /// Moves the sprite in `slot` one tick, bumps what a shell hit on the way
    /// (during its move, as `Shell.isBlocking` does) and lists it for the
    /// shell or fireball checks as its `move` does.
    fn advance(&mut self, slot: Slot, mario_x: f32) {
        let s = self.slot(slot);
        // Registered before the move, as `Shell.move` and `Fireball.move` do.
        let check =
            s.dead_time == 0 && (s.kind == SpriteKind::Fireball || (s.kind == SpriteKind::Shell && s.facing != 0));
        self.bumps.clear();
        let level = &self.level;
        let bumps = &mut self.bumps;
        match slot {
            Slot::Old(i) => self.sprites[i].advance(level, mario_x, bumps),
            Slot::Born(i) => self.born[i].advance(level, mario_x, bumps),
        }
        if check {
            self.checks.push(slot);
        }
        for k in 0..self.bumps.cells().len() {
            let (x, y) = self.bumps.cells()[k];
            self.bump(x, y, true);
        }
    }

    fn slot(&self, slot: Slot) -> &Sprite {
        match slot {
            Slot::Old(i) => &self.sprites[i],
            Slot::Born(i) => &self.born[i],
        }
    }

    /// The benchmark's `addSprite`: the newborn joins the list at the tick's
    /// end but moves once now.
    fn add_born(&mut self, s: Sprite) {
        if self.born.len() + self.sprites.len() >= MAX_SPRITES {
            return;
        }
        self.born.push(s);
        let i = self.born.len() - 1;
        let mario_x = self.mario.x;
        self.advance(Slot::Born(i), mario_x);
    }

    fn finish_tick(&mut self) {
        let mut removed = false;
        for s in self.sprites.iter().chain(self.born.iter()) {
            if s.removed {
                removed = true;
                if s.template != NO_TEMPLATE {
                    self.templates[s.template as usize].alive = false;
                }
            }
        }
        // Most ticks neither add nor remove a sprite: the list stays as it is.
        if !removed && self.born.is_empty() {
            return;
        }
        // `sprites.addAll(0, spritesToAdd); sprites.removeAll(spritesToRemove)`.
        self.scratch.clear();
        self.scratch.extend(self.born.drain(..).filter(|s| !s.removed));
        self.scratch.extend(self.sprites.iter().filter(|s| !s.removed).copied());
        std::mem::swap(&mut self.sprites, &mut self.scratch);
    }

    fn spawn(&mut self, x_cam: f32) {
        let x0 = (x_cam as i32) / CELL as i32 - 1;
        let x1 = ((x_cam + SCREEN_W) as i32) / CELL as i32 + 1;
        let mut start = self.first_template.min(self.level.templates().len());
        while start < self.level.templates().len() && self.level.templates()[start].x < x0 {
            start += 1;
        }
        while start > 0 && self.level.templates()[start - 1].x >= x0 {
            start -= 1;
        }
        self.first_template = start;
        let mx = self.mario.x;
        let dir_of = |x: i32| {
            let centre = x as f32 * CELL + 8.0;
            if centre > mx + 16.0 {
                -1
            } else if centre < mx - 16.0 {
                1
            } else {
                0
            }
        };
        // Columns left to right, rows top to bottom, as the benchmark's scan.
        let mut k = start;
        while k < self.level.templates().len() {
            let t = self.level.templates()[k];
            if t.x > x1 {
                break;
            }
            let state = self.templates[k];
            if state.last_visible != self.tick - 1 && !state.alive && !state.dead {
                self.templates[k].alive = true;
                let mut s = Sprite::enemy(t.kind, t.winged, t.x, t.y, dir_of(t.x), k as u32);
                if t.kind == EnemyKind::Flower {
                    // `FlowerEnemy`'s constructor moves it four times.
                    for _ in 0..4 {
                        s.advance(&self.level, mx, &mut self.bumps);
                    }
                }
                self.add_born(s);
            }
            self.templates[k].last_visible = self.tick;
            k += 1;
        }
        // Cannons fire every 100 ticks (staggered by column) when Mario is not beside them.
        let first = self.level.cannons().partition_point(|c| c.0 < x0);
        let mut c = first;
        while c < self.level.cannons().len() && self.level.cannons()[c].0 <= x1 {
            let (x, y) = self.level.cannons()[c];
            let dir = dir_of(x);
            if dir != 0 && (self.tick - x * 2) % 100 == 0 {
                let centre = x as f32 * CELL + 8.0;
                self.add_born(Sprite::bullet_bill(centre + dir as f32 * 8.0, y as f32 * CELL + 15.0, dir));
            }
            c += 1;
        }
    }

    fn move_mario(&mut self, fireballs: usize) {
        let keys = self.keys;
        let m = &mut self.mario;
        if m.invulnerable > 0 {
            m.invulnerable -= 1;
        }
        m.was_on_ground = m.on_ground;
        let sideways = if keys.speed { 1.2 } else { 0.6 };
        if m.xa > 2.0 {
            m.facing = 1;
        }
        if m.xa < -2.0 {
            m.facing = -1;
        }
        if keys.jump || (m.jump_time < 0 && !m.on_ground && !m.sliding) {
            if m.jump_time < 0 {
                m.xa = m.x_jump_speed;
                m.ya = -(m.jump_time as f32) * m.y_jump_speed;
                m.jump_time += 1;
            } else if m.on_ground && m.may_jump {
                m.x_jump_speed = 0.0;
                m.y_jump_speed = -1.9;
                m.jump_time = 7;
                m.ya = m.jump_time as f32 * m.y_jump_speed;
                m.on_ground = false;
                m.sliding = false;
            } else if m.sliding && m.may_jump {
                m.x_jump_speed = -(m.facing as f32) * 6.0;
                m.y_jump_speed = -2.0;
                m.jump_time = -6;
                m.xa = m.x_jump_speed;
                m.ya = -(m.jump_time as f32) * m.y_jump_speed;
                m.on_ground = false;
                m.sliding = false;
                m.facing = -m.facing;
            } else if m.jump_time > 0 {
                m.xa += m.x_jump_speed;
                m.ya = m.jump_time as f32 * m.y_jump_speed;
                m.jump_time -= 1;
            }
        } else {
            m.jump_time = 0;
        }
        if keys.left {
            if m.facing == 1 {
                m.sliding = false;
            }
            m.xa -= sideways;
            if m.jump_time >= 0 {
                m.facing = -1;
            }
        }
        if keys.right {
            if m.facing == -1 {
                m.sliding = false;
            }
            m.xa += sideways;
            if m.jump_time >= 0 {
                m.facing = 1;
            }
        }
        if (!keys.left && !keys.right) || m.ya < 0.0 || m.on_ground {
            m.sliding = false;
        }
        if keys.speed && m.able_to_shoot && m.mode == Mode::Fire && fireballs < MAX_FIREBALLS {
            let f = Sprite::fireball(m.x + m.facing as f32 * 6.0, m.y - 20.0, m.facing);
            self.add_born(f);
        }
        let m = &mut self.mario;
        m.able_to_shoot = !keys.speed;
        m.may_jump = (m.on_ground || m.sliding) && !keys.jump;
        if m.xa.abs() < 0.5 {
            m.xa = 0.0;
        }
        if m.sliding {
            m.ya = damp(m.ya, 0.5);
        }
        m.on_ground = false;
        // The benchmark tests the exit with the cell Mario held before this
        // tick's move (`mapX`, `mapY` are updated after it).
        let (map_x, map_y) = m.cell();
        let xa = m.xa;
        self.mario_move(xa, 0.0);
        let ya = self.mario.ya;
        self.mario_move(0.0, ya);
        if self.mario.y > ROWS as f32 * CELL + CELL {
            self.die();
            return;
        }
        if map_x >= self.level.x_exit() && map_y <= self.level.y_exit() {
            self.mario.x = (self.level.x_exit() + 1) as f32 * CELL;
            self.status = Status::Won;
            self.bonus += points::WIN;
        }
        let m = &mut self.mario;
        if m.x < 0.0 {
            m.x = 0.0;
            m.xa = 0.0;
        }
        let right = self.level.width() as f32 * CELL;
        if m.x > right {
            m.x = right;
            m.xa = 0.0;
        }
        // Standing, Mario's vertical speed decays through the subnormals:
        // damped in integers there (see `decay`), the same bits.
        m.ya = damp(m.ya, 0.85);
        m.xa *= INERTIA;
        if !m.on_ground {
            m.ya += 3.0;
        }
    }

    /// The benchmark's `Mario.move(xa, ya)`: tile collisions in 8 px sub-steps,
    /// picking up coins and bumping blocks on the way. Inlined so that each
    /// call site's constant zero speed removes the other axis's probes.
    #[inline(always)]
    fn mario_move(&mut self, mut xa: f32, mut ya: f32) -> bool {
        while xa > 8.0 {
            if !self.mario_step(8.0, 0.0) {
                return false;
            }
            xa -= 8.0;
        }
        while xa < -8.0 {
            if !self.mario_step(-8.0, 0.0) {
                return false;
            }
            xa += 8.0;
        }
        while ya > 8.0 {
            if !self.mario_step(0.0, 8.0) {
                return false;
            }
            ya -= 8.0;
        }
        while ya < -8.0 {
            if !self.mario_step(0.0, -8.0) {
                return false;
            }
            ya += 8.0;
        }
        self.mario_step(xa, ya)
    }

    /// One sub-step of [`World::mario_move`], at most 8 px each way.
    #[inline(always)]
    fn mario_step(&mut self, xa: f32, ya: f32) -> bool {
        let (x, y, w, h) = (self.mario.x, self.mario.y, 4.0f32, self.mario.height());
        let own = ((x / CELL) as i32, (y / CELL) as i32);
        let mut collide = false;
        if ya > 0.0 {
            collide = self.mario_blocking(own, x + xa - w, y + ya, 0.0)
                || self.mario_blocking(own, x + xa + w, y + ya, 0.0)
                || self.mario_blocking(own, x + xa - w, y + ya + 1.0, ya)
                || self.mario_blocking(own, x + xa + w, y + ya + 1.0, ya);
        }
        if ya < 0.0 {
            collide = self.mario_blocking(own, x + xa, y + ya - h, ya)
                || self.mario_blocking(own, x + xa - w, y + ya - h, ya)
                || self.mario_blocking(own, x + xa + w, y + ya - h, ya);
        }
        if xa != 0.0 {
            let edge = if xa > 0.0 { x + xa + w } else { x + xa - w };
            let mut all = true;
            for py in [y + ya - h, y + ya - h / 2.0, y + ya] {
                if self.mario_blocking(own, edge, py, ya) {
                    collide = true;
                } else {
                    all = false;
                }
            }
            self.mario.sliding = all;
        }
        let m = &mut self.mario;
        if collide {
            if xa < 0.0 {
                m.x = (((x - w) / CELL) as i32) as f32 * CELL + w;
                m.xa = 0.0;
            }
            if xa > 0.0 {
                // Java adds the 1 before truncating (`(int) ((x + w) / 16 + 1)`): not the same above row 0 or left of column 0.
                m.x = (((x + w) / CELL + 1.0) as i32) as f32 * CELL - w - 1.0;
                m.xa = 0.0;
            }
            if ya < 0.0 {
                m.y = (((y - h) / CELL) as i32) as f32 * CELL + h;
                m.jump_time = 0;
                m.ya = 0.0;
            }
            if ya > 0.0 {
                // As the benchmark, truncating after adding 1: Mario may stand on a hill top above the screen (y < 0).
                m.y = (((y - 1.0) / CELL + 1.0) as i32) as f32 * CELL - 1.0;
                m.on_ground = true;
            }
            false
        } else {
            m.x += xa;
            m.y += ya;
            true
        }
    }

    /// Whether the cell holding `(px, py)` blocks Mario moving with vertical
    /// speed `ya`; a coin there is collected and a block hit from below is
    /// bumped. The tile lookup is inlined into the move; the rare tiles with
    /// an effect go to [`World::touch_tile`].
    #[inline(always)]
    fn mario_blocking(&mut self, own: (i32, i32), px: f32, py: f32, ya: f32) -> bool {
        let (cx, cy) = ((px / CELL) as i32, (py / CELL) as i32);
        if (cx, cy) == own {
            return false;
        }
        let t = self.level.get(cx, cy);
        if t == tile::EMPTY {
            return false;
        }
        let b = behaviour_of(t);
        let blocking = b & behaviour::BLOCK_ALL != 0
            || (ya > 0.0 && b & behaviour::BLOCK_UPPER != 0)
            || (ya < 0.0 && b & behaviour::BLOCK_LOWER != 0);
        if t == tile::COIN || (blocking && ya < 0.0) {
            self.touch_tile(cx, cy, t, blocking, ya);
        }
        blocking
    }

    /// What touching tile `t` at `(cx, cy)` does: a coin is collected, a
    /// blocking tile hit from below (`ya < 0`) is bumped.
    #[inline(never)]
    fn touch_tile(&mut self, cx: i32, cy: i32, t: u8, blocking: bool, ya: f32) {
        if t == tile::COIN && self.level.get_inside(cx, cy).is_some() {
            self.gain_coin();
            self.level.set(cx, cy, tile::EMPTY);
        }
        if blocking && ya < 0.0 {
            let large = self.mario.is_large();
            self.bump(cx, cy, large);
        }
    }

    fn gain_coin(&mut self) {
        self.coins += 1;
        self.bonus += points::COIN;
    }

    /// A block hit from below (by Mario) or from the side (by a shell): the
    /// benchmark's `LevelScene.bump`, in its order (what stands on the block
    /// first, then the block's content).
    fn bump(&mut self, x: i32, y: i32, can_break: bool) {
        let Some(t) = self.level.get_inside(x, y) else { return };
        let b = behaviour_of(t);
        if b & behaviour::BUMPABLE != 0 {
            if t == tile::HIDDEN {
                self.bonus += points::HIDDEN_BLOCK;
            }
            self.bump_into(x, y - 1);
            // A block with coins left pays one and stays; the last bump uses it up.
            let left = self.level.data(x, y);
            if t == tile::QUESTION_COINS && left > 0 {
                self.level.set_data(x, y, left - 1);
            } else {
                self.level.set(x, y, tile::USED);
            }
            if b & behaviour::SPECIAL != 0 {
                let kind = if self.mario.is_large() { SpriteKind::FireFlower } else { SpriteKind::Mushroom };
                self.add_born(Sprite::power_up(kind, x, y));
            } else {
                self.gain_coin();
            }
        }
        if b & behaviour::BREAKABLE != 0 {
            self.bump_into(x, y - 1);
            if can_break {
                self.level.set(x, y, tile::EMPTY);
            }
        }
    }

    /// What stands on a bumped block (`LevelScene.bumpInto`): a coin is
    /// collected, and every sprite of the list runs its `bumpCheck`: an
    /// enemy over the block flies off dead, a shell or a mushroom hops away
    /// from Mario.
    fn bump_into(&mut self, x: i32, y: i32) {
        if self.level.get_inside(x, y) == Some(tile::COIN) {
            self.gain_coin();
            self.level.set(x, y, tile::EMPTY);
        }
        let left = x as f32 * CELL;
        let away = -self.mario.facing;
        for k in 0..self.sprites.len() {
            let s = &mut self.sprites[k];
            let over = s.x + s.width > left && s.x - s.width < left + CELL && y == ((s.y - 1.0) / CELL) as i32;
            if !over {
                continue;
            }
            match s.kind {
                SpriteKind::RedKoopa
                | SpriteKind::GreenKoopa
                | SpriteKind::Goomba
                | SpriteKind::Spiky
                | SpriteKind::Flower
                    if s.dead_time == 0 =>
                {
                    s.xa = (away * 2) as f32;
                    s.ya = -5.0;
                    s.winged = false;
                    self.fly_dead(k, 100);
                }
                SpriteKind::Shell | SpriteKind::Mushroom => {
                    s.facing = away;
                    s.ya = -10.0;
                }
                _ => {}
            }
        }
    }

    /// An enemy dies (`deadTime`, and its template with it): a corpse for
    /// `ticks` ticks, flying off if killed by a shell, a fireball or a bump.
    fn fly_dead(&mut self, k: usize, ticks: i32) {
        self.corpse(k, ticks);
        self.sprites[k].fly_death = true;
    }

    fn corpse(&mut self, k: usize, ticks: i32) {
        let s = &mut self.sprites[k];
        s.dead_time = ticks;
        if s.template != NO_TEMPLATE {
            s.dead = true;
            self.templates[s.template as usize].dead = true;
        }
    }

    /// The sprite's `collideCheck` against Mario.
    fn collide_with_mario(&mut self, i: usize) {
        let s = self.sprites[i];
        // What the checks read of Mario before any stomp moves him (not a copy of all of him).
        let m = &self.mario;
        let falling_on = m.ya > 0.0 && m.y - s.y <= 0.0 && (!m.on_ground || !m.was_on_ground);
        let (mx, my, mh, facing) = (m.x, m.y, m.height(), m.facing);
        match s.kind {
            SpriteKind::RedKoopa
            | SpriteKind::GreenKoopa
            | SpriteKind::Goomba
            | SpriteKind::Spiky
            | SpriteKind::Flower => {
                if s.dead_time != 0 || !s.touches(mx, my, s.width * 2.0 + 4.0, mh) {
                    return;
                }
                let stompable = !matches!(s.kind, SpriteKind::Spiky | SpriteKind::Flower);
                if stompable && falling_on {
                    self.stomp(s.y, s.height);
                    if s.winged {
                        let e = &mut self.sprites[i];
                        e.winged = false;
                        e.ya = 0.0;
                    } else {
                        // A stomped enemy lies 10 ticks; a koopa leaves a shell (also
                        // when the stomp came too late to pay, Mario dying).
                        self.corpse(i, 10);
                        self.sprites[i].winged = false;
                        if matches!(s.kind, SpriteKind::RedKoopa | SpriteKind::GreenKoopa) {
                            self.add_born(Sprite::shell(s.x, s.y));
                        }
                        self.kills.stomp += 1;
                    }
                } else {
                    self.hurt();
                }
            }
            SpriteKind::Shell => {
                if s.dead_time != 0 || !s.touches(mx, my, 16.0, mh) {
                    return;
                }
                if falling_on {
                    self.stomp(s.y, s.height);
                    let e = &mut self.sprites[i];
                    if e.facing != 0 {
                        e.xa = 0.0;
                        e.facing = 0;
                    } else {
                        e.facing = facing;
                    }
                } else if s.facing != 0 {
                    self.hurt();
                } else {
                    // `Mario.kick` without the speed key (no carrying here).
                    self.sprites[i].facing = facing;
                    self.mario.invulnerable = 1;
                }
            }
            SpriteKind::BulletBill => {
                if s.dead_time != 0 || !s.touches(mx, my, 16.0, mh) {
                    return;
                }
                if falling_on {
                    self.stomp(s.y, s.height);
                    let e = &mut self.sprites[i];
                    e.xa = 0.0;
                    e.ya = 1.0;
                    e.dead_time = 100;
                    self.kills.stomp += 1;
                } else {
                    self.hurt();
                }
            }
            SpriteKind::Mushroom | SpriteKind::FireFlower => {
                if !s.touches(mx, my, 16.0, mh) {
                    return;
                }
                self.sprites[i].removed = true;
                if self.status == Status::Dead {
                    return;
                }
                if s.kind == SpriteKind::Mushroom {
                    self.bonus += points::MUSHROOM;
                    if self.mario.mode == Mode::Small {
                        self.mario.mode = Mode::Large;
                    } else {
                        self.gain_coin();
                    }
                } else {
                    self.bonus += points::FIRE_FLOWER;
                    if self.mario.mode != Mode::Fire {
                        self.mario.mode = Mode::Fire;
                    } else {
                        self.gain_coin();
                    }
                }
            }
            SpriteKind::Fireball => {}
        }
    }

    /// The benchmark's `Mario.stomp`: Mario lands on the sprite's middle and
    /// bounces (a dying Mario does nothing, and earns nothing).
    fn stomp(&mut self, sprite_y: f32, sprite_height: f32) {
        if self.status == Status::Dead {
            return;
        }
        let target = sprite_y - sprite_height / 2.0;
        let dy = target - self.mario.y;
        self.mario_move(0.0, dy);
        let m = &mut self.mario;
        m.x_jump_speed = 0.0;
        m.y_jump_speed = -1.9;
        m.jump_time = 8;
        m.ya = m.jump_time as f32 * m.y_jump_speed;
        m.on_ground = false;
        m.sliding = false;
        m.invulnerable = 1;
        self.stomps += 1;
        self.bonus += points::STOMP;
    }

    /// `Mario.getHurt`: also after a win in the same tick (the benchmark
    /// checks only for a dying or invulnerable Mario).
    fn hurt(&mut self) {
        if self.status == Status::Dead || self.mario.invulnerable > 0 {
            return;
        }
        self.bonus += points::HURT;
        self.hurts += 1;
        match self.mario.mode {
            Mode::Fire => self.mario.mode = Mode::Large,
            Mode::Large => self.mario.mode = Mode::Small,
            Mode::Small => {
                self.die();
                return;
            }
        }
        self.mario.invulnerable = INVULNERABLE_TICKS;
    }

    /// `Mario.die`: pays −512, also after a win in the same tick.
    fn die(&mut self) {
        if self.status != Status::Dead {
            self.status = Status::Dead;
            self.bonus += points::DEATH;
        }
    }

    /// The moving shells, then the fireballs, listed during the tick, each
    /// against every sprite of the list (`shellsToCheck`, `fireballsToCheck`).
    fn shells_and_fireballs(&mut self) {
        for shells in [true, false] {
            for c in 0..self.checks.len() {
                let slot = self.checks.get(c);
                let me = *self.slot(slot);
                if (me.kind == SpriteKind::Shell) != shells {
                    continue;
                }
                for j in 0..self.sprites.len() {
                    if slot == Slot::Old(j) {
                        continue;
                    }
                    let me = *self.slot(slot);
                    // A shell stops checking once dead; a fireball once it died.
                    if me.dead_time != 0 && (shells || me.kind == SpriteKind::Fireball) {
                        break;
                    }
                    let e = self.sprites[j];
                    if e.dead_time != 0 || !e.touches(me.x, me.y, 16.0, me.height) {
                        continue;
                    }
                    let facing = me.facing;
                    if shells {
                        match e.kind {
                            SpriteKind::Shell => {
                                self.shell_die(Slot::Old(j));
                                self.shell_die(slot);
                            }
                            SpriteKind::BulletBill => {
                                let b = &mut self.sprites[j];
                                b.xa = 0.0;
                                b.ya = 1.0;
                                b.dead_time = 100;
                            }
                            k if k.is_walker() || k == SpriteKind::Flower => {
                                let v = &mut self.sprites[j];
                                v.xa = (facing * 2) as f32;
                                v.ya = -5.0;
                                v.winged = false;
                                self.fly_dead(j, 100);
                                self.kills.shell += 1;
                            }
                            _ => {}
                        }
                    } else {
                        let hit = match e.kind {
                            SpriteKind::Spiky | SpriteKind::BulletBill => true,
                            SpriteKind::Shell => {
                                if e.facing == 0 {
                                    let v = &mut self.sprites[j];
                                    v.xa = (facing * 2) as f32;
                                    v.ya = -5.0;
                                    v.dead_time = 100;
                                }
                                true
                            }
                            k if k.is_walker() || k == SpriteKind::Flower => {
                                let v = &mut self.sprites[j];
                                v.xa = (facing * 2) as f32;
                                v.ya = -5.0;
                                v.winged = false;
                                self.fly_dead(j, 100);
                                self.kills.fire += 1;
                                true
                            }
                            _ => false,
                        };
                        if hit {
                            let f = self.slot_mut(slot);
                            f.dead_time = 100;
                            f.xa = -(f.facing as f32) * 2.0;
                            f.ya = -5.0;
                        }
                    }
                }
            }
        }
    }

    fn slot_mut(&mut self, slot: Slot) -> &mut Sprite {
        match slot {
            Slot::Old(i) => &mut self.sprites[i],
            Slot::Born(i) => &mut self.born[i],
        }
    }

    /// `Shell.die`.
    fn shell_die(&mut self, slot: Slot) {
        let s = self.slot_mut(slot);
        s.xa = -(s.facing as f32) * 2.0;
        s.ya = -5.0;
        s.dead_time = 100;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::level::{EnemyKind, Template};

    /// A flat level: ground top at row 13 (Mario's feet rest at y = 207).
    pub(crate) fn flat(width: i32) -> Level {
        let mut l = Level::empty(width);
        for x in 0..width {
            l.set(x, 13, tile::GROUND);
            l.set(x, 14, tile::GROUND);
        }
        l.set_exit(width - 2, 12);
        l
    }

    fn settle(w: &mut World) {
        for _ in 0..40 {
            w.tick(Keys::default());
        }
    }

    const RIGHT: Keys = Keys { left: false, right: true, jump: false, speed: false };
    const RUN: Keys = Keys { left: false, right: true, jump: false, speed: true };

    #[test]
    fn mario_lands_walks_and_runs_at_the_benchmark_speeds() {
        let mut w = World::new(flat(200), Mode::Small);
        settle(&mut w);
        assert!(w.mario().on_ground);
        assert_eq!(w.mario().y, 207.0);
        for _ in 0..60 {
            w.tick(RIGHT);
        }
        // Terminal walking speed: xa = 0.89 (xa + 0.6) → 4.85 px/tick after inertia.
        assert!((w.mario().xa - 0.6 * 0.89 / 0.11).abs() < 0.05, "{}", w.mario().xa);
        for _ in 0..60 {
            w.tick(RUN);
        }
        assert!((w.mario().xa - 1.2 * 0.89 / 0.11).abs() < 0.1, "{}", w.mario().xa);
    }

    #[test]
    fn a_held_jump_rises_about_four_cells_and_needs_a_release() {
        let mut w = World::new(flat(100), Mode::Small);
        settle(&mut w);
        let y0 = w.mario().y;
        let jump = Keys { jump: true, ..Keys::default() };
        let mut top = y0;
        for _ in 0..40 {
            w.tick(jump);
            top = top.min(w.mario().y);
        }
        let rise = y0 - top;
        assert!(rise > 60.0 && rise < 80.0, "rise {rise}");
        assert!(w.mario().on_ground);
        // Still holding: no new jump.
        w.tick(jump);
        assert!(w.mario().on_ground);
        w.tick(Keys::default());
        w.tick(jump);
        assert!(!w.mario().on_ground);
    }

    #[test]
    fn falling_into_a_gap_kills_and_the_exit_wins() {
        let mut l = flat(60);
        for x in 10..14 {
            l.set(x, 13, tile::EMPTY);
            l.set(x, 14, tile::EMPTY);
        }
        let mut w = World::new(l, Mode::Large);
        settle(&mut w);
        let mut total = 0;
        while w.status() == Status::Running {
            total += w.tick(RIGHT);
        }
        assert_eq!(w.status(), Status::Dead);
        assert_eq!(total, points::DEATH);

        let mut w = World::new(flat(60), Mode::Small);
        let mut total = 0;
        while w.status() == Status::Running {
            total += w.tick(RUN);
        }
        assert_eq!(w.status(), Status::Won);
        assert_eq!(total, points::WIN);
    }

    #[test]
    fn the_timer_kills_after_3000_ticks() {
        let mut w = World::new(flat(60), Mode::Fire);
        let mut total = 0;
        let mut n = 0;
        while w.status() == Status::Running {
            total += w.tick(Keys::default());
            n += 1;
        }
        assert_eq!(n, TIME_LIMIT_TICKS);
        assert_eq!(total, points::DEATH);
    }

    #[test]
    fn coins_blocks_and_power_ups_pay_the_table() {
        let mut l = flat(60);
        l.set(6, 12, tile::COIN);
        l.set(3, 9, tile::QUESTION_POWERUP);
        l.set(3, 8, tile::COIN);
        let mut w = World::new(l, Mode::Small);
        settle(&mut w);
        // Jump under the question block at column 3 (Mario stands at x = 32..).
        w.mario_mut().x = 3.0 * CELL + 8.0;
        let mut got = 0;
        got += w.tick(Keys { jump: true, ..Keys::default() });
        for _ in 0..20 {
            got += w.tick(Keys { jump: true, ..Keys::default() });
        }
        // The bump took the coin standing on the block.
        assert_eq!(got, points::COIN);
        assert_eq!(w.level().get(3, 9), tile::USED);
        assert!(w.sprites().iter().any(|s| s.kind == SpriteKind::Mushroom));
        // The mushroom walks right; follow it and eat it; then the coin at column 6.
        let mut got = 0;
        for _ in 0..120 {
            got += w.tick(RIGHT);
        }
        assert_eq!(w.mario().mode, Mode::Large);
        assert_eq!(got, points::MUSHROOM + points::COIN);
    }

    #[test]
    fn hidden_blocks_pay_when_bumped() {
        let mut l = flat(60);
        l.set(3, 9, tile::HIDDEN);
        let mut w = World::new(l, Mode::Large);
        settle(&mut w);
        // Walking under it: nothing (it blocks only from below).
        w.mario_mut().x = 3.0 * CELL + 8.0;
        let mut got = 0;
        for _ in 0..20 {
            got += w.tick(Keys { jump: true, ..Keys::default() });
        }
        assert_eq!(got, points::HIDDEN_BLOCK + points::COIN);
        assert_eq!(w.level().get(3, 9), tile::USED);
    }

    #[test]
    fn a_newborn_moves_once_in_the_tick_it_is_added() {
        // `addSprite` ticks the newborn: a goomba spawned at column 14 in the
        // first tick has already walked 1.75 px towards Mario.
        let mut w = with_enemy(EnemyKind::Goomba, false, Mode::Small);
        w.tick(Keys::default());
        let g = w.sprites().iter().find(|s| s.kind == SpriteKind::Goomba).expect("spawned");
        assert_eq!(g.x, 14.0 * CELL + 8.0 - 1.75);
    }

    #[test]
    fn a_block_bumped_under_a_goomba_kills_it() {
        // `bumpInto` runs every sprite's `bumpCheck`: a goomba standing on the
        // block flies off dead, its template with it, and leaves the enemy map.
        let mut l = flat(60);
        l.set(3, 9, tile::QUESTION_COIN);
        let mut w = World::new(l, Mode::Small);
        settle(&mut w);
        w.mario_mut().x = 3.0 * CELL + 8.0;
        w.add_sprite(Sprite::enemy(EnemyKind::Goomba, false, 3, 8, 1, NO_TEMPLATE));
        for _ in 0..6 {
            w.tick(Keys { jump: true, ..Keys::default() });
        }
        assert_eq!(w.level().get(3, 9), tile::USED);
        let g = w.sprites().iter().find(|s| s.kind == SpriteKind::Goomba).expect("still falling off");
        assert!(g.fly_death && g.dead_time > 0);
        assert_eq!(w.kills(), Kills::default(), "the benchmark does not count a bump as a kill");
    }

    fn with_enemy(kind: EnemyKind, winged: bool, mode: Mode) -> World {
        let mut l = flat(80);
        l.add_template(Template { x: 14, y: 12, kind, winged });
        World::new(l, mode)
    }

    #[test]
    fn stomping_pays_10_and_koopas_leave_shells() {
        let mut w = with_enemy(EnemyKind::GreenKoopa, false, Mode::Small);
        settle(&mut w);
        // Wait for the koopa to come close, then jump on it.
        let mut got = 0;
        for _ in 0..200 {
            let near = w.sprites().iter().any(|s| s.kind == SpriteKind::GreenKoopa && (s.x - w.mario().x) < 40.0);
            let keys = Keys { jump: near, ..Keys::default() };
            got += w.tick(keys);
            if w.stomps() > 0 {
                break;
            }
        }
        assert_eq!(w.stomps(), 1);
        assert_eq!(got, points::STOMP);
        assert_eq!(w.kills().stomp, 1);
        // The koopa lies dead for 10 ticks (no longer on the enemy map), then leaves.
        assert!(w.sprites().iter().any(|s| s.kind == SpriteKind::GreenKoopa && s.dead));
        for _ in 0..10 {
            w.tick(Keys::default());
        }
        assert!(w.sprites().iter().any(|s| s.kind == SpriteKind::Shell));
        assert!(w.sprites().iter().all(|s| s.kind != SpriteKind::GreenKoopa));
    }

    #[test]
    fn hurt_downgrades_with_invulnerability_and_small_mario_dies() {
        let mut l = flat(80);
        for x in [12, 16, 20] {
            l.add_template(Template { x, y: 12, kind: EnemyKind::Spiky, winged: false });
        }
        let mut w = World::new(l, Mode::Fire);
        let mut got = Vec::new();
        let mut modes = Vec::new();
        for _ in 0..400 {
            if w.status() != Status::Running {
                break;
            }
            let r = w.tick(Keys::default());
            if r != 0 {
                got.push(r);
                modes.push(w.mario().mode);
                assert!(w.mario().invulnerable == INVULNERABLE_TICKS || w.status() == Status::Dead);
            }
        }
        // Three spikies walk into a standing Mario: fire → large → small → dead, never stomped.
        assert_eq!(modes, vec![Mode::Large, Mode::Small, Mode::Small]);
        assert_eq!(got, vec![points::HURT, points::HURT, points::HURT + points::DEATH]);
        assert_eq!(w.status(), Status::Dead);
    }

    #[test]
    fn spiky_cannot_be_stomped() {
        let mut w = with_enemy(EnemyKind::Spiky, false, Mode::Large);
        settle(&mut w);
        let mut got = 0;
        for _ in 0..200 {
            let near = w.sprites().iter().any(|s| (s.x - w.mario().x) < 40.0);
            got += w.tick(Keys { jump: near, ..Keys::default() });
            if got != 0 {
                break;
            }
        }
        assert_eq!(got, points::HURT);
        assert_eq!(w.stomps(), 0);
    }

    #[test]
    fn fire_mario_shoots_at_most_two_fireballs_and_they_kill() {
        let mut w = with_enemy(EnemyKind::Goomba, false, Mode::Fire);
        settle(&mut w);
        let mut most = 0;
        for t in 0..60 {
            // Press speed on every other tick: a fresh press each time.
            w.tick(Keys { speed: t % 2 == 0, ..Keys::default() });
            most = most.max(w.fireballs());
        }
        assert_eq!(most, MAX_FIREBALLS);
        // Burnt: it flies off dead (off the enemy map), a kill by fire.
        assert!(w.sprites().iter().all(|s| s.kind != SpriteKind::Goomba || s.dead), "the goomba was burnt");
        assert_eq!(w.kills(), Kills { fire: 1, ..Kills::default() });
        assert_eq!(w.stomps(), 0);
    }

    #[test]
    fn cannons_fire_bullet_bills_towards_mario() {
        let mut l = flat(80);
        l.set(15, 12, tile::CANNON);
        l.set(15, 11, tile::CANNON_TOP);
        let mut w = World::new(l, Mode::Large);
        let mut seen = false;
        for _ in 0..200 {
            w.tick(Keys::default());
            seen |= w.sprites().iter().any(|s| s.kind == SpriteKind::BulletBill && s.facing == -1);
        }
        assert!(seen);
    }

    #[test]
    fn plants_wait_while_mario_is_near_and_hurt_when_up() {
        let mut l = flat(80);
        for x in [8, 9] {
            l.set(x, 11, tile::TUBE_TOP);
            l.set(x, 12, tile::TUBE);
        }
        l.add_template(Template { x: 8, y: 11, kind: EnemyKind::Flower, winged: false });
        let mut w = World::new(l, Mode::Large);
        let beside = 8.0 * CELL + 15.0 + 60.0;
        w.mario_mut().x = beside;
        // Wait for the plant to be down in its tube, then stand on the tube: it never comes up.
        for _ in 0..300 {
            w.tick(Keys::default());
            if w.sprites().iter().any(|s| s.kind == SpriteKind::Flower && s.y >= s.y_start && s.timer > 0) {
                break;
            }
        }
        w.mario_mut().x = 8.0 * CELL + 15.0;
        w.mario_mut().y = 11.0 * CELL - 1.0;
        let mut got = 0;
        for _ in 0..200 {
            got += w.tick(Keys::default());
        }
        assert_eq!(got, 0);
        // Away from the tube it rises; stepping onto the tube then hurts.
        w.mario_mut().x = beside;
        w.mario_mut().y = 207.0;
        for _ in 0..200 {
            w.tick(Keys::default());
            if w.sprites().iter().any(|s| s.kind == SpriteKind::Flower && s.y < s.y_start - 30.0) {
                break;
            }
        }
        let plant = *w.sprites().iter().find(|s| s.kind == SpriteKind::Flower).unwrap();
        w.mario_mut().x = plant.x;
        w.mario_mut().y = 11.0 * CELL - 1.0;
        w.mario_mut().ya = 2.0;
        let got = w.tick(Keys::default());
        assert_eq!(got, points::HURT);
        assert_eq!(w.mario().mode, Mode::Small);
        assert_eq!(w.stomps(), 0);
    }
}
