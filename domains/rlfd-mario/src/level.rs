//! Mario levels: the tile map, the enemy templates and the generator.
//!
//! What it is: our generator after the Mario AI Benchmark 0.2.0's
//! `LevelGenerator` (SVN trunk, November 2011, the version whose intermediate
//! reward is the thesis's reward table), at the options the oracle measured
//! (`../shared/oracle/mario/`): overground, difficulty 0, length 256 with the
//! exit at column 255, no dead ends, no ladders, no hidden blocks unless asked.
//! Units are the benchmark's: cells of 16 px, a level 15 cells high.
//!
//! A level is a safe straight of 10–14 cells, then zones while it is shorter
//! than its width minus 10, then ground to the end. Zones are drawn by weighted
//! odds (difficulty `d`): straight 20, hill 1, tubes `2 + d`, gaps `3d`,
//! cannons `max(0, 5d − 10)`, dead ends `2 + 2d` (dead ends are off at the
//! benchmark's defaults, so that draw builds nothing and the next zone starts
//! at the same column). Every zone's floor is one of rows 11–14.
//!
//! - Straight: 2–9 cells; longer than 5 cells it is *decorated*: a coin row
//!   two cells above the floor, then rows of blocks from the row right above
//!   the floor upwards, 3–8 rows apart, up to the top of the level. In a row
//!   a cell holds with p 1/3 a question block (a power-up, a coin, or 1–9
//!   more coins, a third each), else with p 1/4 a brick with a coin or (1/4)
//!   a power-up, else with p 1/2 a plain brick; every block lays a coin row
//!   two cells above its row. Each row's ends are drawn anew.
//! - Hill: ground of 10–19 cells and platforms 2–3 rows above one another,
//!   each `1 + U(length/2)` wide, until one is decorated (p 1/4) or the top is
//!   reached; one creature stands on each platform's first cell.
//! - Tubes: 5–14 cells of ground with tubes 1–3 cells high every 3–6 cells; a
//!   piranha plant in a tube with p `(d + 1)/11`; with p 1/2 block rows above.
//! - Gaps (d ≥ 1): two landings of 2–6 cells around 3 (10 at high
//!   difficulty) empty columns, with stairs one time in three.
//! - Cannons (d ≥ 3): cannons every 2–5 cells; with p 1/2 block rows above.
//!
//! Creatures: at the first column of every zone, at most `d + 1`, in the empty
//! cells above the ground (each with p ≥ 1/2, scanning up from the floor), each
//! moved sideways by a whole-cell Gaussian jitter (the benchmark truncates a
//! standard normal), so one may stand inside the neighbouring column's ground,
//! as in the benchmark. Below difficulty 1 every creature is a goomba; below 3
//! one of goomba, green or red koopa, each winged or not; else also spiky
//! (winged or not) and the wave goomba, which we make a winged goomba.
//!
//! Hidden blocks exist only with [`HiddenBlocks::On`] (the benchmark's `-lhb
//! on`): a block row drawn as a hidden row (p 1/4 after the first, or the
//! first at `d ≥ 1` when its straight loses its coins) places a hidden block
//! with p 1/2 per cell, four rows above the row.
//!
//! What it is not: a transcription of the Java (the structure follows its
//! rules; the random numbers are our ChaCha8 generator seeded with the level
//! seed, so our level S is not the benchmark's level S, and only
//! distributions can be compared); no underground or castle levels, no dead
//! ends, no ladders, no hill inside a wide gap (difficulty ≥ 4), no tile art
//! (the benchmark's `fixWalls` only picks pictures, and every picture it picks
//! blocks as the ground does).

use rlfd_env::random::{SimRng, below, seeded, standard_normal};

/// Pixels per cell.
pub const CELL: f32 = 16.0;

/// Rows of a level (the benchmark's minimum and default height).
pub const ROWS: i32 = 15;

/// Rows stored per column (15 used, padded to a power of two for indexing).
const STRIDE: usize = 16;

/// Tile kinds. Their behaviour is in [`behaviour`].
pub mod tile {
    /// Nothing.
    pub const EMPTY: u8 = 0;
    /// Ground (solid).
    pub const GROUND: u8 = 1;
    /// A stair block beside a gap (solid).
    pub const ROCK: u8 = 2;
    /// The top of a hill: a platform, blocking only from above.
    pub const HILL_TOP: u8 = 3;
    /// The body of a hill (background, not blocking).
    pub const HILL: u8 = 4;
    /// The top of a tube (solid).
    pub const TUBE_TOP: u8 = 5;
    /// The body of a tube (solid).
    pub const TUBE: u8 = 6;
    /// The top of a cannon, where bullet bills come from (solid).
    pub const CANNON_TOP: u8 = 7;
    /// The body of a cannon (solid).
    pub const CANNON: u8 = 8;
    /// A plain brick: large Mario breaks it from below.
    pub const BRICK: u8 = 9;
    /// A brick holding a coin.
    pub const BRICK_COIN: u8 = 10;
    /// A brick holding a power-up.
    pub const BRICK_POWERUP: u8 = 11;
    /// A question block holding a coin.
    pub const QUESTION_COIN: u8 = 12;
    /// A question block holding a power-up (a mushroom for small Mario, else a fire flower).
    pub const QUESTION_POWERUP: u8 = 13;
    /// A used block (solid).
    pub const USED: u8 = 14;
    /// A hidden block: invisible, blocks only upward movement; bumping it pays
    /// the hidden-block bonus and a coin.
    pub const HIDDEN: u8 = 15;
    /// A coin.
    pub const COIN: u8 = 16;
    /// A question block holding several coins (its count is the cell's
    /// [`Level::data`](super::Level::data)): every bump pays a coin, and the
    /// bump that finds the count at zero pays the last one and uses it up
    /// (the benchmark's block `4 + 3·16` with negative block data).
    pub const QUESTION_COINS: u8 = 17;
    /// Ground at an inner corner (the benchmark's `fixWalls` pictures
    /// `3 + 8·16` … `3 + 11·16`: a ground cell three of whose four corners
    /// touch only ground): its `tiles.dat` behaviour is empty, so nothing
    /// collides with it, yet the observation sees ground there.
    pub const GROUND_CORNER: u8 = 18;
    /// Number of kinds.
    pub const COUNT: usize = 19;
}

/// Behaviour bits of a tile (the benchmark's `TILE_BEHAVIORS`).
pub mod behaviour {
    /// Blocks from every side.
    pub const BLOCK_ALL: u8 = 1;
    /// Blocks downward movement only (a platform).
    pub const BLOCK_UPPER: u8 = 2;
    /// Blocks upward movement only (a hidden block).
    pub const BLOCK_LOWER: u8 = 4;
    /// Gives its content when bumped from below.
    pub const BUMPABLE: u8 = 8;
    /// Broken by large Mario from below.
    pub const BREAKABLE: u8 = 16;
    /// Its content is a power-up.
    pub const SPECIAL: u8 = 32;
    /// Picked up on touch (a coin).
    pub const PICKUP: u8 = 64;
}

/// Indexed by any `u8` (kinds past [`tile::COUNT`] have none), so a lookup
/// needs no bounds check.
const BEHAVIOURS: [u8; 256] = {
    use behaviour::*;
    let mut b = [0u8; 256];
    b[tile::GROUND as usize] = BLOCK_ALL;
    b[tile::ROCK as usize] = BLOCK_ALL;
    b[tile::HILL_TOP as usize] = BLOCK_UPPER;
    b[tile::TUBE_TOP as usize] = BLOCK_ALL;
    b[tile::TUBE as usize] = BLOCK_ALL;
    b[tile::CANNON_TOP as usize] = BLOCK_ALL;
    b[tile::CANNON as usize] = BLOCK_ALL;
    b[tile::BRICK as usize] = BLOCK_ALL | BREAKABLE;
    b[tile::BRICK_COIN as usize] = BLOCK_ALL | BUMPABLE;
    b[tile::BRICK_POWERUP as usize] = BLOCK_ALL | BUMPABLE | SPECIAL;
    b[tile::QUESTION_COIN as usize] = BLOCK_ALL | BUMPABLE;
    b[tile::QUESTION_POWERUP as usize] = BLOCK_ALL | BUMPABLE | SPECIAL;
    b[tile::QUESTION_COINS as usize] = BLOCK_ALL | BUMPABLE;
    b[tile::USED as usize] = BLOCK_ALL;
    b[tile::HIDDEN as usize] = BLOCK_LOWER | BUMPABLE;
    b[tile::COIN as usize] = PICKUP;
    b
};

/// The behaviour bits of tile kind `t`.
#[inline]
pub fn behaviour_of(t: u8) -> u8 {
    BEHAVIOURS[t as usize]
}

/// Enemy kinds a template can spawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum EnemyKind {
    /// Turns at ledges; leaves a shell when stomped.
    RedKoopa,
    /// Walks off ledges; leaves a shell when stomped.
    GreenKoopa,
    /// Walks off ledges; dies when stomped.
    Goomba,
    /// Cannot be stomped, immune to fireballs.
    Spiky,
    /// A piranha plant in a tube: cannot be stomped.
    Flower,
}

/// An enemy waiting on a cell until the screen reaches it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Template {
    /// Column.
    pub x: i32,
    /// Row (0 at the top).
    pub y: i32,
    /// What it spawns.
    pub kind: EnemyKind,
    /// Winged (hops).
    pub winged: bool,
}

/// Whether levels hold hidden blocks (the benchmark's `-lhb`, off by default).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum HiddenBlocks {
    /// None (the benchmark's default, and the oracle's).
    Off,
    /// Hidden block rows among the block rows (`-lhb on`).
    On,
}

/// The generator's settings (the thesis gives none; see the chapter's decisions).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct LevelParams {
    /// Level length in cells (the benchmark 0.2.0's `-ll`, default 256); the exit is the last column.
    pub width: i32,
    /// Difficulty `d` (the benchmark's `-ld`).
    pub difficulty: u32,
    /// Hidden blocks (the benchmark's `-lhb`).
    pub hidden_blocks: HiddenBlocks,
}

impl LevelParams {
    /// The levels of the chapter's Mario experiments: the benchmark 0.2.0's
    /// defaults, as the oracle measured them (`-ld 0 -lt 0 -ll 256 -lhb off`).
    pub const EXPERIMENT: LevelParams = LevelParams { width: 256, difficulty: 0, hidden_blocks: HiddenBlocks::Off };
}

/// Zone kinds, in the order of the odds table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Zone {
    Straight,
    Hill,
    Tubes,
    Gap,
    Cannons,
    /// Off at the benchmark's defaults: the draw builds nothing.
    DeadEnd,
}

const ZONES: [Zone; 6] = [Zone::Straight, Zone::Hill, Zone::Tubes, Zone::Gap, Zone::Cannons, Zone::DeadEnd];

/// A generated level.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    width: i32,
    tiles: Vec<u8>,
    /// Per cell: the coins left in a [`tile::QUESTION_COINS`] block (0 elsewhere).
    data: Vec<u8>,
    templates: Vec<Template>,
    cannons: Vec<(i32, i32)>,
    x_exit: i32,
    y_exit: i32,
    seed: u64,
    params: LevelParams,
}

impl Level {
    /// An empty level of `width` cells (all tiles empty, no templates, exit at the end).
    pub fn empty(width: i32) -> Level {
        let width = width.max(1);
        Level {
            width,
            tiles: vec![tile::EMPTY; width as usize * STRIDE],
            data: vec![0; width as usize * STRIDE],
            templates: Vec::new(),
            cannons: Vec::new(),
            x_exit: width,
            y_exit: ROWS - 1,
            seed: 0,
            params: LevelParams { width, difficulty: 0, hidden_blocks: HiddenBlocks::Off },
        }
    }

    /// Generates the level of `seed` (same seed, same level, on any machine).
    pub fn generate(params: LevelParams, seed: u64) -> Level {
        let mut level = Level::empty(params.width);
        level.regenerate(params, seed);
        level
    }

    /// Generates the level of `seed` into `self`, reusing its memory.
    pub fn regenerate(&mut self, params: LevelParams, seed: u64) {
        let width = params.width.max(MIN_WIDTH);
        self.width = width;
        self.tiles.clear();
        self.tiles.resize(width as usize * STRIDE, tile::EMPTY);
        self.data.clear();
        self.data.resize(width as usize * STRIDE, 0);
        self.templates.clear();
        self.seed = seed;
        self.params = LevelParams { width, ..params };
        let mut g = Generator {
            level: self,
            rng: seeded(seed),
            difficulty: params.difficulty as i32,
            hidden: params.hidden_blocks == HiddenBlocks::On,
        };
        g.build();
        // One template per cell (a later one replaces an earlier one, as the
        // benchmark's map does); sorted by column for the spawner.
        let t = &mut self.templates;
        t.sort_by_key(|t| (t.x, t.y));
        let mut w = 0;
        for r in 0..t.len() {
            if w > 0 && (t[w - 1].x, t[w - 1].y) == (t[r].x, t[r].y) {
                t[w - 1] = t[r];
            } else {
                t[w] = t[r];
                w += 1;
            }
        }
        t.truncate(w);
        self.index_cannons();
    }

    /// Lists the cannon tops by column (the spawner visits only these).
    fn index_cannons(&mut self) {
        self.cannons.clear();
        for (x, column) in self.tiles.chunks_exact(STRIDE).enumerate() {
            for (y, &t) in column[..ROWS as usize].iter().enumerate() {
                if t == tile::CANNON_TOP {
                    self.cannons.push((x as i32, y as i32));
                }
            }
        }
    }

    /// The cannon tops `(column, row)`, by column.
    pub fn cannons(&self) -> &[(i32, i32)] {
        &self.cannons
    }

    /// Width in cells.
    #[inline]
    pub fn width(&self) -> i32 {
        self.width
    }

    /// The column Mario must pass to win.
    #[inline]
    pub fn x_exit(&self) -> i32 {
        self.x_exit
    }

    /// The lowest row Mario's feet may be in when he reaches the exit column
    /// to win (the row above the exit's floor, as the benchmark's `yExit`).
    pub fn y_exit(&self) -> i32 {
        self.y_exit
    }

    /// The seed it was generated from.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The generator settings.
    pub fn params(&self) -> LevelParams {
        self.params
    }

    /// The enemy templates, sorted by column then row.
    pub fn templates(&self) -> &[Template] {
        &self.templates
    }

    /// The tile at `(x, y)`: columns are clamped to the level (as the
    /// benchmark's `getBlock`), rows above the top are empty and rows below
    /// the bottom repeat the bottom row.
    #[inline]
    pub fn get(&self, x: i32, y: i32) -> u8 {
        if y < 0 {
            return tile::EMPTY;
        }
        let x = x.clamp(0, self.width - 1) as usize;
        let y = y.min(ROWS - 1) as usize;
        self.tiles[x * STRIDE + y]
    }

    /// The tile at `(x, y)` if it lies inside the level.
    #[inline]
    pub fn get_inside(&self, x: i32, y: i32) -> Option<u8> {
        ((0..self.width).contains(&x) && (0..ROWS).contains(&y)).then(|| self.tiles[x as usize * STRIDE + y as usize])
    }

    /// The data of cell `(x, y)`: the coins left in a [`tile::QUESTION_COINS`] block.
    #[inline]
    pub fn data(&self, x: i32, y: i32) -> u8 {
        if (0..self.width).contains(&x) && (0..ROWS).contains(&y) {
            self.data[x as usize * STRIDE + y as usize]
        } else {
            0
        }
    }

    /// Sets the data of cell `(x, y)` (ignored outside the level).
    #[inline]
    pub fn set_data(&mut self, x: i32, y: i32, d: u8) {
        if (0..self.width).contains(&x) && (0..ROWS).contains(&y) {
            self.data[x as usize * STRIDE + y as usize] = d;
        }
    }

    /// Sets a tile (ignored outside the level).
    #[inline]
    pub fn set(&mut self, x: i32, y: i32, t: u8) {
        if (0..self.width).contains(&x) && (0..ROWS).contains(&y) {
            let old = std::mem::replace(&mut self.tiles[x as usize * STRIDE + y as usize], t);
            if old == tile::CANNON_TOP || t == tile::CANNON_TOP {
                self.index_cannons();
            }
        }
    }

    /// Sets a tile during generation (ignored outside the level), leaving
    /// the cannon list to [`Level::regenerate`], which lists them once at the end.
    #[inline]
    fn put(&mut self, x: i32, y: i32, t: u8) {
        if (0..self.width).contains(&x) && (0..ROWS).contains(&y) {
            self.tiles[x as usize * STRIDE + y as usize] = t;
        }
    }

    /// Adds a template (for hand-built scenes; the generator adds its own).
    pub fn add_template(&mut self, template: Template) {
        self.templates.push(template);
        self.templates.sort_by_key(|t| (t.x, t.y));
    }

    /// Moves the exit (for hand-built scenes).
    pub fn set_exit(&mut self, x: i32, y: i32) {
        self.x_exit = x;
        self.y_exit = y;
    }

    /// Whether `(x, y)` blocks a mover going `(xa, ya)` (the benchmark's `Level.isBlocking`).
    #[inline(always)]
    pub fn is_blocking(&self, x: i32, y: i32, ya: f32) -> bool {
        let b = behaviour_of(self.get(x, y));
        b & behaviour::BLOCK_ALL != 0
            || (ya > 0.0 && b & behaviour::BLOCK_UPPER != 0)
            || (ya < 0.0 && b & behaviour::BLOCK_LOWER != 0)
    }

    /// The benchmark's `fixWalls` and `blockify`, reduced to what they change
    /// in play: every ground cell gets a picture from the four corners it
    /// shares with its neighbours (a corner counts when its four cells are
    /// all ground, reading off-level cells as the nearest level cell); the
    /// pictures of a ground cell with exactly three such corners, an inner
    /// corner of a step, block nothing.
    /// (Public so that a level rebuilt from the benchmark's own tiles can be
    /// checked against its pictures: `examples/replay_oracle.rs`.)
    pub fn fix_walls(&mut self) {
        let level = self;
        let capped = |l: &Level, x: i32, y: i32| {
            l.tiles[x.clamp(0, l.width - 1) as usize * STRIDE + y.clamp(0, H - 1) as usize] == tile::GROUND
        };
        // The corner at (x, y) joins cells x − 1 … x and y − 1 … y; corners
        // past the level's last column and row read as those (the benchmark
        // clamps the corner map too).
        let corner = |l: &Level, x: i32, y: i32| {
            let (x, y) = (x.min(l.width), y.min(H));
            capped(l, x - 1, y - 1) && capped(l, x, y - 1) && capped(l, x - 1, y) && capped(l, x, y)
        };
        // All corners are read from the ground as generated, before any
        // picture is placed (the benchmark builds its corner map first).
        let mut inner = Vec::new();
        for x in 0..level.width {
            for y in 0..H {
                if level.tiles[x as usize * STRIDE + y as usize] != tile::GROUND {
                    continue;
                }
                let n =
                    [(0, 0), (1, 0), (0, 1), (1, 1)].iter().filter(|&&(dx, dy)| corner(level, x + dx, y + dy)).count();
                if n == 3 {
                    inner.push(x as usize * STRIDE + y as usize);
                }
            }
        }
        for k in inner {
            level.tiles[k] = tile::GROUND_CORNER;
        }
    }

    /// Counts of tiles of each kind (for tests and the report).
    pub fn tile_counts(&self) -> [usize; tile::COUNT] {
        let mut c = [0; tile::COUNT];
        for x in 0..self.width {
            for y in 0..ROWS {
                c[self.get(x, y) as usize] += 1;
            }
        }
        c
    }
}

/// The shortest level the generator builds (the benchmark's minimum is 50).
const MIN_WIDTH: i32 = 50;

/// A zone or straight whose floor the generator draws: rows 11–14.
const FLOORS: i32 = 4;

struct Generator<'a> {
    level: &'a mut Level,
    rng: SimRng,
    difficulty: i32,
    hidden: bool,
}

const H: i32 = ROWS;

impl Generator<'_> {
    /// Uniform on `0..n` (`n ≥ 1`).
    fn rand(&mut self, n: i32) -> i32 {
        below(&mut self.rng, n.max(1) as usize) as i32
    }

    /// A fresh floor row, 11–14.
    fn floor(&mut self) -> i32 {
        H - 1 - self.rand(FLOORS)
    }

    fn odds(&self) -> [i32; 6] {
        let d = self.difficulty;
        [20, 1, 2 + d, 3 * d, (5 * d - 10).max(0), 2 + 2 * d]
    }

    fn build(&mut self) {
        let width = self.level.width;
        let mut length = self.straight(0, width, true);
        while length < width - 10 {
            length += self.zone(length, width - length);
        }
        let floor = self.floor();
        self.level.x_exit = width - 1;
        self.level.y_exit = floor - 1;
        for x in length..width {
            self.ground(x, floor);
        }
        self.level.fix_walls();
        // The benchmark then puts its princess tile (`15 + 15·16`, blocking
        // nothing) on the exit cell: air above the exit's floor, unless the
        // last zone reached the end on another floor, where it replaces ground.
        let (x, y) = (self.level.x_exit, self.level.y_exit);
        self.level.put(x, y, tile::EMPTY);
    }

    fn ground(&mut self, x: i32, floor: i32) {
        for y in floor..H {
            self.level.put(x, y, tile::GROUND);
        }
    }

    fn is_empty(&self, x: i32, y: i32) -> bool {
        self.level.get(x, y) == tile::EMPTY
    }

    /// Builds one zone at column `x` and puts its creatures on its first column.
    fn zone(&mut self, x: i32, max_length: i32) -> i32 {
        let odds = self.odds();
        let total: i32 = odds.iter().sum();
        let mut t = self.rand(total);
        let mut kind = Zone::Straight;
        for (z, &o) in ZONES.iter().zip(&odds) {
            if t < o {
                kind = *z;
                break;
            }
            t -= o;
        }
        let length = match kind {
            Zone::Straight => self.straight(x, max_length, false),
            Zone::Hill => self.hill(x, max_length),
            Zone::Tubes => self.tubes(x, max_length),
            Zone::Gap => self.gap(x, max_length),
            Zone::Cannons => self.cannons(x, max_length),
            // The benchmark still tries its creatures on the unbuilt column;
            // they would stand below the level and are refused.
            Zone::DeadEnd => return 0,
        };
        self.zone_creatures(x);
        length
    }

    /// Up to `d + 1` creatures in the empty cells of column `x`, scanning up
    /// from below the level (a cell below the level counts, and is refused as
    /// the benchmark refuses it).
    fn zone_creatures(&mut self, x: i32) {
        let d = self.difficulty;
        let mut placed = 0;
        for y in (1..=H).rev() {
            if placed > d {
                break;
            }
            if self.is_empty(x, y) && self.rand(d + 1) + 1 > (d + 1) / 2 && !self.has_template(x, y) {
                self.creature(x, y);
                placed += 1;
            }
        }
    }

    fn has_template(&self, x: i32, y: i32) -> bool {
        self.level.templates.iter().any(|t| t.x == x && t.y == y)
    }

    /// A creature of the difficulty's kinds at `(x + jitter, y)`; refused outside the level.
    fn creature(&mut self, x: i32, y: i32) {
        // The benchmark's `(int) nextGaussian()`: truncation towards zero.
        let dx = standard_normal(&mut self.rng) as i32;
        let d = self.difficulty;
        let (kind, winged) = if d < 1 {
            (EnemyKind::Goomba, false)
        } else {
            // Goomba, winged goomba, green koopa, winged, red koopa, winged;
            // from difficulty 3 also spiky, winged spiky and the wave goomba.
            const KINDS: [(EnemyKind, bool); 9] = [
                (EnemyKind::Goomba, false),
                (EnemyKind::Goomba, true),
                (EnemyKind::GreenKoopa, false),
                (EnemyKind::GreenKoopa, true),
                (EnemyKind::RedKoopa, false),
                (EnemyKind::RedKoopa, true),
                (EnemyKind::Spiky, false),
                (EnemyKind::Spiky, true),
                (EnemyKind::Goomba, true),
            ];
            KINDS[self.rand(if d < 3 { 6 } else { 9 }) as usize]
        };
        let x = x + dx;
        if (0..self.level.width).contains(&x) && (0..H).contains(&y) {
            self.level.templates.push(Template { x, y, kind, winged });
        }
    }

    fn straight(&mut self, xo: i32, max_length: i32, safe: bool) -> i32 {
        let length = if safe { 10 + self.rand(5) } else { self.rand(8) + 2 }.min(max_length);
        let floor = self.floor();
        for x in xo..xo + length {
            self.ground(x, floor);
        }
        if !safe && length > 5 {
            self.decorate(xo, xo + length, floor);
        }
        length
    }

    /// A coin row and block rows over `x0..x1`, whose floor is `floor`.
    fn decorate(&mut self, x0: i32, x1: i32, floor: i32) {
        if floor < 1 {
            return;
        }
        let (s, e) = (self.rand(4), self.rand(4));
        // At difficulty ≥ 1 the first row may be a hidden row, which loses the coins.
        let d = self.difficulty;
        let hidden_row = self.rand(d + 1) % (d + 1) > 0;
        if floor - 2 > 0 && !hidden_row {
            self.coins(x0, x1, floor, s, e);
        }
        self.blocks(x0, x1, floor, hidden_row, s, e);
    }

    /// Coins two cells above `floor`, in the empty cells of `x0 + 1 + s .. x1 − 1 − e`.
    fn coins(&mut self, x0: i32, x1: i32, floor: i32, s: i32, e: i32) {
        if floor - 2 < 0 || (x1 - 1 - e) - (x0 + 1 + s) <= 1 {
            return;
        }
        for x in x0 + 1 + s..x1 - 1 - e {
            if self.is_empty(x, floor - 2) {
                self.level.put(x, floor - 2, tile::COIN);
            }
        }
    }

    /// Rows of blocks from the row above `floor` up to the top, 3–8 rows apart.
    fn blocks(&mut self, x0: i32, x1: i32, floor: i32, first_hidden: bool, s: i32, e: i32) {
        let (mut s, mut e, mut hidden_row) = (s, e, first_hidden);
        let mut row = floor - 1;
        while row > 0 {
            if (x1 - 1 - e) - (x0 + 1 + s) > 0 {
                for x in x0 + s..x1 - e {
                    if hidden_row && self.hidden {
                        if self.rand(2) == 1 {
                            self.level.put(x, row - 4, tile::HIDDEN);
                        }
                    } else if self.block(x, row, x != x0 + 1 && x != x1 - 2) {
                        self.coins(x0, x1, row, s, e);
                    }
                }
            }
            hidden_row = self.rand(4) == 0;
            row -= self.rand(6) + 3;
            s = self.rand(4);
            e = self.rand(4);
        }
    }

    /// Maybe a block at `(x, y)`; whether the row gets its coins.
    fn block(&mut self, x: i32, y: i32, question_allowed: bool) -> bool {
        if question_allowed && self.rand(3) == 0 {
            match self.rand(3) {
                0 => self.put_if_empty(x, y, tile::QUESTION_POWERUP),
                1 => self.put_if_empty(x, y, tile::QUESTION_COIN),
                _ => {
                    // The benchmark writes this one over whatever is there.
                    let coins = self.rand(9) + 1;
                    self.level.put(x, y, tile::QUESTION_COINS);
                    self.level.set_data(x, y, coins as u8);
                }
            }
            true
        } else if self.rand(4) == 0 {
            let t = if self.rand(4) == 0 { tile::BRICK_POWERUP } else { tile::BRICK_COIN };
            self.put_if_empty(x, y, t);
            true
        } else if self.rand(2) == 1 && self.is_empty(x, y) {
            self.level.put(x, y, tile::BRICK);
            true
        } else {
            false
        }
    }

    fn put_if_empty(&mut self, x: i32, y: i32, t: u8) {
        if self.is_empty(x, y) {
            self.level.put(x, y, t);
        }
    }

    fn hill(&mut self, x0: i32, max_length: i32) -> i32 {
        let length = (self.rand(10) + 10).min(max_length);
        let floor = self.floor();
        for x in x0..x0 + length {
            self.ground(x, floor);
        }
        let mut top = floor;
        loop {
            top -= self.rand(2) + 2;
            if top < 0 {
                break;
            }
            let l = self.rand(length / 2) + 1;
            let xx0 = self.rand(l + 1) + x0;
            let last = self.rand(4) == 0;
            if last {
                self.decorate(xx0 - 1, xx0 + l + 1, top);
            }
            for x in xx0..xx0 + l {
                for y in top..floor {
                    self.put_if_empty(x, y, if y == top { tile::HILL_TOP } else { tile::HILL });
                }
            }
            self.creature(xx0, top - 1);
            if last {
                break;
            }
        }
        length
    }

    fn tubes(&mut self, xo: i32, max_length: i32) -> i32 {
        let length = (self.rand(10) + 5).min(max_length);
        let floor = self.floor();
        let mut x_tube = xo + 1 + self.rand(4);
        let mut tube_top = floor - self.rand(3) - 1;
        // The benchmark's block rows start from the lowest later tube top's
        // row (a row index, not a height), or the floor when there is none.
        let mut lowest_later_top = 0;
        for x in xo..xo + length {
            if x > x_tube + 1 {
                x_tube += 3 + self.rand(4);
                tube_top = floor - self.rand(2) - 2;
                lowest_later_top = lowest_later_top.max(tube_top);
            }
            if x_tube >= xo + length - 2 {
                x_tube += 10;
            }
            if x == x_tube && self.rand(11) < self.difficulty + 1 {
                self.level.templates.push(Template { x, y: tube_top, kind: EnemyKind::Flower, winged: false });
            }
            self.ground(x, floor);
            if x == x_tube || x == x_tube + 1 {
                for y in tube_top..floor {
                    self.level.put(x, y, if y == tube_top { tile::TUBE_TOP } else { tile::TUBE });
                }
            }
        }
        if self.rand(2) == 0 {
            self.blocks(xo, xo + length, floor - lowest_later_top - 2, false, 0, 0);
        }
        length
    }

    fn gap(&mut self, xo: i32, max_length: i32) -> i32 {
        let d = self.difficulty;
        let landing = self.rand(5) + 2;
        let gap = if self.rand(d) + d > 7 { 10 } else { 3 };
        let length = (landing * 2 + gap).min(max_length);
        let has_stairs = self.rand(3) == 0;
        let floor = self.floor();
        for x in xo..xo + length {
            if x < xo + landing || x > xo + length - landing - 1 {
                self.ground(x, floor);
                if has_stairs {
                    let top = if x < xo + landing { floor - (x - xo) + 1 } else { floor - ((xo + length) - x) + 2 };
                    for y in top.max(0)..floor {
                        self.level.put(x, y, tile::ROCK);
                    }
                }
            }
        }
        length
    }

    fn cannons(&mut self, xo: i32, max_length: i32) -> i32 {
        let length = (self.rand(10) + 2).min(max_length);
        let floor = self.floor();
        let mut x_cannon = xo + 1 + self.rand(4);
        for x in xo..xo + length {
            if x > x_cannon {
                x_cannon += 2 + self.rand(4);
            }
            if x_cannon == xo + length - 1 {
                x_cannon += 10;
            }
            let cannon_top = floor - self.rand(3) - 1;
            self.ground(x, floor);
            if x == x_cannon {
                for y in cannon_top.max(0)..floor {
                    self.level.put(x, y, if y == cannon_top { tile::CANNON_TOP } else { tile::CANNON });
                }
            }
        }
        if self.rand(2) == 0 {
            self.blocks(xo, xo + length, floor - 2, false, 0, 0);
        }
        length
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_level_and_different_seeds_differ() {
        let p = LevelParams::EXPERIMENT;
        let a = Level::generate(p, 42);
        assert_eq!(a, Level::generate(p, 42));
        assert_ne!(a, Level::generate(p, 43));
        // Regenerating into a used level gives the same level.
        let mut b = Level::generate(p, 7);
        b.regenerate(p, 42);
        assert_eq!(a, b);
    }

    #[test]
    fn a_level_is_pinned_across_machines() {
        // A digest of level 2016's tiles and templates: a change here changes every Mario result.
        let l = Level::generate(LevelParams::EXPERIMENT, 2016);
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        for x in 0..l.width() {
            for y in 0..ROWS {
                h = (h ^ u64::from(l.get(x, y))).wrapping_mul(0x100_0000_01b3);
            }
        }
        for t in l.templates() {
            h = (h ^ (t.x as u64 * 31 + t.y as u64 + t.kind as u64 * 1000)).wrapping_mul(0x100_0000_01b3);
        }
        assert_eq!(
            (l.x_exit(), l.templates().len(), h),
            PINNED_LEVEL_2016,
            "{:?}",
            (l.x_exit(), l.templates().len(), h)
        );
    }

    const PINNED_LEVEL_2016: (i32, usize, u64) = (255, 42, 2974331028674392899);

    #[test]
    fn difficulty_1_brings_gaps_koopas_and_winged_creatures() {
        let p = LevelParams { difficulty: 1, ..LevelParams::EXPERIMENT };
        let mut totals = [0usize; tile::COUNT];
        let (mut kinds, mut winged, mut gap_levels) = ([0usize; 5], 0, 0);
        for seed in 0..200 {
            let l = Level::generate(p, seed);
            assert_eq!(l.x_exit(), l.width() - 1);
            for (t, c) in totals.iter_mut().zip(l.tile_counts()) {
                *t += c;
            }
            for t in l.templates() {
                kinds[t.kind as usize] += 1;
                winged += usize::from(t.winged);
                assert!(t.x >= 0 && t.x < l.width() && (0..ROWS).contains(&t.y));
            }
            gap_levels += usize::from((0..l.x_exit()).any(|x| (0..ROWS).all(|y| l.get(x, y) == tile::EMPTY)));
        }
        for t in [tile::HILL_TOP, tile::TUBE_TOP, tile::COIN, tile::QUESTION_COINS, tile::QUESTION_POWERUP, tile::BRICK]
        {
            assert!(totals[t as usize] > 0, "tile {t} never generated");
        }
        // No hidden blocks unless asked, no cannons below difficulty 3, no spiky below 3.
        assert_eq!(totals[tile::HIDDEN as usize], 0);
        assert_eq!(totals[tile::CANNON_TOP as usize], 0);
        assert_eq!(kinds[EnemyKind::Spiky as usize], 0);
        for k in [EnemyKind::RedKoopa, EnemyKind::GreenKoopa, EnemyKind::Goomba, EnemyKind::Flower] {
            assert!(kinds[k as usize] > 0, "{k:?} never generated");
        }
        assert!(winged > 0);
        assert!(gap_levels > 100, "{gap_levels} of 200 levels with a gap");
    }

    #[test]
    fn higher_difficulties_bring_cannons_and_spiky() {
        let p = LevelParams { difficulty: 5, ..LevelParams::EXPERIMENT };
        let (mut cannons, mut spiky) = (0, 0);
        for seed in 0..50 {
            let l = Level::generate(p, seed);
            cannons += l.tile_counts()[tile::CANNON_TOP as usize];
            spiky += l.templates().iter().filter(|t| t.kind == EnemyKind::Spiky).count();
        }
        assert!(cannons > 0 && spiky > 0);
    }

    #[test]
    fn multi_coin_blocks_hold_1_to_9_coins() {
        let (mut n, mut sum) = (0, 0u32);
        for seed in 0..100 {
            let l = Level::generate(LevelParams::EXPERIMENT, seed);
            for x in 0..l.width() {
                for y in 0..ROWS {
                    if l.get(x, y) == tile::QUESTION_COINS {
                        let d = l.data(x, y);
                        assert!((1..=9).contains(&d));
                        n += 1;
                        sum += u32::from(d);
                    } else {
                        assert_eq!(l.data(x, y), 0);
                    }
                }
            }
        }
        // U{1..9}: mean 5.
        assert!(n > 500 && (sum as f64 / n as f64 - 5.0).abs() < 0.3, "{n} blocks, mean {}", sum as f64 / n as f64);
    }

    #[test]
    fn blocking_rules() {
        let mut l = Level::empty(10);
        l.set(1, 5, tile::HILL_TOP);
        l.set(2, 5, tile::HIDDEN);
        l.set(3, 5, tile::GROUND);
        l.set(4, 5, tile::COIN);
        assert!(l.is_blocking(1, 5, 1.0) && !l.is_blocking(1, 5, -1.0) && !l.is_blocking(1, 5, 0.0));
        assert!(l.is_blocking(2, 5, -1.0) && !l.is_blocking(2, 5, 1.0));
        assert!(l.is_blocking(3, 5, 0.0));
        assert!(!l.is_blocking(4, 5, 1.0));
        // Columns are clamped, rows below repeat the bottom row, rows above are empty.
        l.set(0, 14, tile::GROUND);
        assert_eq!(l.get(-3, 14), tile::GROUND);
        assert_eq!(l.get(0, 20), tile::GROUND);
        assert_eq!(l.get(0, -1), tile::EMPTY);
    }
}
