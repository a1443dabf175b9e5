//! Replays episodes of the real Mario AI Benchmark 0.2.0, recorded tick by
//! tick by `oracle/Trace.java`, in our simulator, and reports the first tick
//! where the two differ: the tool that shows our `World` follows the
//! benchmark's `LevelScene.tick` mechanism by mechanism (not a test: CI has no
//! JDK).
//!
//! ```text
//! java -cp "…" oracle.Trace --policy fwdjump --episodes 1000 --seed 1 > fwdjump.trace
//! cargo run --release -p rlfd-mario --example replay_oracle -- fwdjump.trace [SHOW]
//! ```
//!
//! Each episode's level is rebuilt from the trace (its tiles, block data and
//! sprite templates as the benchmark generated them), Mario starts in the
//! recorded mode, and every tick gets the recorded keys. Compared after every
//! tick: Mario's position (bit for bit), mode, status and the running reward,
//! and while the game runs the 27 variables (ours against the oracle's
//! `State27`, `shoot` as the API's).
//! The benchmark's princess at the exit is a sprite that never interacts, so
//! it is left out. `SHOW` prints the first `SHOW` divergences in full.

use std::collections::BTreeMap;
use std::io::BufRead;

use rlfd_mario::level::{EnemyKind, Template, tile};
use rlfd_mario::observation::{NAMES, STATE_VARIABLES, observe};
use rlfd_mario::{Keys, Level, Mode, Status, World};

/// One tick of the trace.
struct Tick {
    keys: u8,
    x: u32,
    y: u32,
    mode: u8,
    status: u8,
    bonus: i32,
    sprites: u32,
    state: [f64; STATE_VARIABLES],
}

struct Episode {
    seed: i64,
    mode: u8,
    level: Level,
    ticks: Vec<Tick>,
}

/// Our tile for the benchmark's block byte `b` (its `TILE_BEHAVIORS` read from `tiles.dat`).
fn tile_of(b: u8) -> u8 {
    match b {
        0 | 255 => tile::EMPTY,
        1 => tile::HIDDEN,
        4 => tile::USED,
        10 | 11 => tile::TUBE_TOP,
        26 | 27 => tile::TUBE,
        14 => tile::CANNON_TOP,
        30 | 46 => tile::CANNON,
        16 => tile::BRICK,
        17 => tile::BRICK_COIN,
        18 => tile::BRICK_POWERUP,
        21 => tile::QUESTION_COIN,
        22 => tile::QUESTION_POWERUP,
        23 => tile::QUESTION_COINS,
        34 => tile::COIN,
        // Ground pictures block from every side; hill tops from above; the rest is background.
        128..=130 | 144..=146 | 160..=162 => tile::GROUND,
        131 | 147 | 163 | 179 => tile::GROUND_CORNER,
        132..=134 | 180 | 182 => tile::HILL_TOP,
        _ => tile::HILL,
    }
}

fn template_of(kind: i32) -> Option<(EnemyKind, bool)> {
    Some(match kind {
        80 => (EnemyKind::Goomba, false),
        95 => (EnemyKind::Goomba, true),
        81 => (EnemyKind::GreenKoopa, false),
        96 => (EnemyKind::GreenKoopa, true),
        82 => (EnemyKind::RedKoopa, false),
        97 => (EnemyKind::RedKoopa, true),
        93 => (EnemyKind::Spiky, false),
        99 => (EnemyKind::Spiky, true),
        91 => (EnemyKind::Flower, false),
        _ => return None,
    })
}

fn read(path: &str) -> Vec<Episode> {
    let f = std::io::BufReader::new(std::fs::File::open(path).expect("a trace file"));
    let mut out: Vec<Episode> = Vec::new();
    for line in f.lines() {
        let line = line.expect("a readable trace");
        let w: Vec<&str> = line.split_whitespace().collect();
        let int = |k: usize| -> i64 { w[k].parse().expect("a number") };
        match w.first().copied() {
            Some("E") => {
                let mut level = Level::empty(int(3) as i32);
                level.set_exit(int(5) as i32, int(6) as i32);
                out.push(Episode { seed: int(1), mode: int(2) as u8, level, ticks: Vec::new() });
            }
            Some("B") => {
                let e = out.last_mut().expect("E first");
                let (x, y, b, d) = (int(1) as i32, int(2) as i32, int(3) as u8, int(4));
                let t = tile_of(b);
                e.level.set(x, y, t);
                if t == tile::QUESTION_COINS {
                    e.level.set_data(x, y, (-d) as u8);
                }
            }
            Some("S") => {
                let e = out.last_mut().expect("E first");
                if let Some((kind, winged)) = template_of(int(3) as i32) {
                    e.level.add_template(Template { x: int(1) as i32, y: int(2) as i32, kind, winged });
                }
            }
            Some("T") => {
                let hex = |k: usize| u32::from_str_radix(w[k], 16).expect("hex bits");
                out.last_mut().expect("E first").ticks.push(Tick {
                    keys: int(1) as u8,
                    x: hex(2),
                    y: hex(3),
                    mode: int(4) as u8,
                    status: int(5) as u8,
                    bonus: int(6) as i32,
                    sprites: int(7) as u32,
                    state: std::array::from_fn(|k| w[8 + k].parse().expect("a variable")),
                });
            }
            _ => {}
        }
    }
    out
}

/// The first tick (1-based) where ours differs and what differs, or `None`.
fn replay(e: &Episode, show: bool) -> Option<(usize, &'static str)> {
    let mode = Mode::ALL[e.mode as usize];
    let mut w = World::new(e.level.clone(), mode);
    let mut ret = -1; // the benchmark's bonus starts at −1
    let mut state = [0.0; STATE_VARIABLES];
    for (t, r) in e.ticks.iter().enumerate() {
        let keys =
            Keys { left: r.keys & 1 != 0, right: r.keys & 2 != 0, jump: r.keys & 4 != 0, speed: r.keys & 8 != 0 };
        let previous = (w.mario().x, w.mario().y);
        ret += w.tick(keys);
        let m = w.mario();
        let status = match w.status() {
            Status::Running => 2,
            Status::Won => 1,
            Status::Dead => 0,
        };
        let what = if m.x.to_bits() != r.x || m.y.to_bits() != r.y {
            Some("position")
        } else if m.mode as u8 != r.mode {
            Some("mode")
        } else if status != r.status {
            Some("status")
        } else if ret != r.bonus {
            Some("reward")
        } else if status == 2 && {
            observe(&w, previous, &mut state);
            state != r.state
        } {
            if show {
                let k = (0..STATE_VARIABLES).find(|&k| state[k] != r.state[k]).unwrap_or(0);
                println!("seed {} tick {}: {} ours {} benchmark {}", e.seed, t + 1, NAMES[k], state[k], r.state[k]);
            }
            Some("observation")
        } else {
            None
        };
        if let Some(what) = what {
            if show {
                println!(
                    "seed {} mode {} tick {}: {what}: ours x {} y {} mode {} status {status} reward {ret} sprites {}; \
                     benchmark x {} y {} mode {} status {} reward {} sprites {}",
                    e.seed,
                    e.mode,
                    t + 1,
                    m.x,
                    m.y,
                    m.mode as u8,
                    w.sprites().len(),
                    f32::from_bits(r.x),
                    f32::from_bits(r.y),
                    r.mode,
                    r.status,
                    r.bonus,
                    r.sprites
                );
            }
            return Some((t + 1, what));
        }
        if w.status() != Status::Running {
            return (t + 1 != e.ticks.len()).then_some((t + 1, "ended early"));
        }
    }
    None
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args.first().expect("usage: replay_oracle TRACE [SHOW]");
    let show: usize = args.get(1).map_or(0, |s| s.parse().expect("SHOW is a number"));
    let episodes = read(path);
    // Our generator's last pass (`Level::fix_walls`) on the benchmark's own
    // ground: the inner corners it marks against the benchmark's pictures.
    let (mut corners, mut wrong) = (0, 0);
    for e in &episodes {
        let mut l = e.level.clone();
        for x in 0..l.width() {
            for y in 0..rlfd_mario::level::ROWS {
                if l.get(x, y) == tile::GROUND_CORNER {
                    l.set(x, y, tile::GROUND);
                }
            }
        }
        l.fix_walls();
        for x in 0..l.width() {
            for y in 0..rlfd_mario::level::ROWS {
                corners += usize::from(e.level.get(x, y) == tile::GROUND_CORNER);
                // The exit's princess tile replaced a ground cell after the
                // benchmark's pass in some levels: the last two columns are left out.
                let differs = x < l.x_exit() - 1
                    && (l.get(x, y) == tile::GROUND_CORNER) != (e.level.get(x, y) == tile::GROUND_CORNER);
                wrong += usize::from(differs);
            }
        }
    }
    println!(
        "inner corners: {corners} in the benchmark's levels, {wrong} cells where Level::fix_walls differs (last two columns not compared)"
    );
    let mut same = 0;
    let mut causes: BTreeMap<&str, usize> = BTreeMap::new();
    let mut shown = 0;
    for e in &episodes {
        match replay(e, shown < show) {
            None => same += 1,
            Some((_, what)) => {
                shown += 1;
                *causes.entry(what).or_default() += 1;
            }
        }
    }
    println!("{path}: {same}/{} episodes identical to the benchmark, tick by tick", episodes.len());
    for (what, n) in causes {
        println!("  first difference in {what}: {n}");
    }
}
