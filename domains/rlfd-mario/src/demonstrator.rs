//! The synthetic Mario demonstrator of section 6.3.2: a model of the
//! thesis's expert, who played ten episodes (random level, random start
//! mode) that became the demonstrations.
//!
//! What the thesis says about its demonstrations (inputs to every learner):
//! ten of them; the demonstrator "scored 1224 points" on average; the
//! 10th-longest is 953 observations long (RE-IRL uses the first 953
//! observations of each). Nothing else is given: not the player's style, not
//! how many episodes were won.
//!
//! The model (its rules fixed before any learner ran): an expert who reads
//! the screen ahead, modelled as a short-horizon planner. Every
//! [`DECISION_TICKS`] ticks it imagines each of a few key sequences for the
//! next [`HORIZON`] ticks on a copy of the game (walk right; jump right,
//! holding the key 2, 5 or 12 ticks; wait; step back) and takes the one that
//! keeps Mario alive, then unhurt, then scores best on pixels gained right
//! plus `greed` times the points earned (ties: the first in that order; a
//! coin is worth 16 px at greed 1, about three ticks of walking). It walks
//! (the speed key is for fireballs: in fire mode it taps it at an enemy up to
//! 6 cells ahead at its height). Now and then it stops to look: at each new
//! plan made on the ground, with probability `pause_start` it stands still
//! for [`PAUSE_TICKS`] ticks instead, if standing there that long is safe (a
//! person does not stop in front of a goomba). With probability `slip` per
//! tick it presses a uniformly random one of the 12 actions instead of the
//! plan's (a person's mistakes and hesitations). Its copy of the game is
//! exact, so its foresight is perfect within the horizon; the slips and
//! pauses are what keep it from scoring the maximum.
//!
//! **Stuck.** When Mario's farthest position has not grown by a cell in
//! [`STUCK_TICKS`] ticks of play (a step under a low ceiling of blocks, say),
//! the next plan is chosen among escapes instead ([`ESCAPE_HORIZON`] ticks):
//! run-ups (back up 4–24 ticks, then go right and jump after 0–8 ticks
//! holding the key 4–12 ticks, walking or running), hop-backs (jump while
//! backing up: out of a pit one cell wide), double jumps and jumps straight
//! up (big Mario breaks a brick overhead, then passes): a person backs off
//! and tries again rather than pressing right into the wall until the timer
//! runs out. When [`ESCAPES_BEFORE_FIDDLING`] escapes in a row have not
//! moved Mario on, the player fiddles: it imagines [`FIDDLES`] key sequences
//! of [`FIDDLE_HORIZON`] ticks, a uniformly random action held
//! [`FIDDLE_SEGMENT`] ticks at a time (seeded from its own stream), and plays
//! the best. The 0.2.0 generator makes traps no single run-up leaves: a
//! ditch under a ceiling of bricks with a wall three cells high, a pit one
//! cell wide under a brick. Before the hop-backs, jumps up and fiddling, the
//! slip-free, pause-free player timed out in 5 of 60 episodes stuck in such a
//! trap; with them it wins 180 of 180 (seeds 5, 6 and the calibration's), and
//! a random-key search from the stuck states found every one of them
//! escapable (12, 82 and 319 of 20,000 random 200-tick sequences), so the
//! traps were the planner's, not the levels'.
//!
//! **The recording rule.** Every episode is kept as it ends, won, died or
//! timed out: none is redone or dropped, so nothing is selected by its
//! length or its outcome. The ten demonstrations are ten consecutive episodes.
//!
//! **Calibration** (inputs only, [`calibrate`]): `slip`, `pause_start` and
//! `greed` together, on a fixed grid, minimising the sum of the squared
//! relative errors of the mean score (against 1,224) and of the expected
//! 10th-longest of ten episodes (against 953), each measured on
//! [`CALIBRATION_DEMOS`] episodes on levels from [`CALIBRATION_SEED`] (the
//! same levels at every grid point). The pause grid is finer between 0.8 and
//! 0.9 (0.825, 0.85, 0.875), where both figures change fastest: on the
//! simulator in the benchmark's tick order (issue 27) the coarse grid's best
//! point (slip 0.02, pause 0.9, greed 1) scored 1,067 with an expected
//! 10th-longest of 655. The shipped [`MarioDemonstrator::thesis`] holds the
//! result, refitted with the escapes above (slip 0.01, pause 0.825, greed 0:
//! mean 1,402, expected 10th-longest 913; before them slip 0.01, pause
//! 0.875, greed 1); a test reruns the calibration. On these levels a won
//! episode is worth about 2,000 points (the real benchmark's forward
//! runner's wins average 1,968), so the thesis's 1,224 with ten episodes of
//! at least 953 observations needs about four in ten episodes to fail late;
//! this model fails mostly by slowness (timeouts: it stops to look often),
//! which the report states with the set's composition.
//!
//! The levels are the benchmark 0.2.0's default difficulty 0, the one the
//! oracle measured; at difficulty 1 and above the real levels hold 80–115
//! enemies and gaps, and the oracle's forward runner dies in 99 % of
//! episodes, which the thesis's positive returns rule out
//! ([`difficulty_table`] measures our player at other difficulties).

use rand::Rng;
use rlfd_env::Environment;
use rlfd_env::demonstration::{DemonstrationSet, Trajectory};
use rlfd_env::random::{below, bernoulli, seeded};

use super::env::{ACTION_KEYS, ACTIONS, MarioEnv, action_of};
use super::level::{CELL, LevelParams};
use super::observation::{NAMES, STATE_VARIABLES};
use super::sprites::SpriteKind;
use super::world::{Keys, Mode, Status, World};

/// The thesis's figures about its demonstrations.
pub mod thesis {
    /// Number of demonstrations.
    pub const COUNT: usize = 10;
    /// The demonstrator's mean score.
    pub const MEAN_SCORE: f64 = 1224.0;
    /// Length of the 10th-longest demonstration (RE-IRL's horizon).
    pub const TENTH_LONGEST: usize = 953;
}

/// The calibrated slip probability per tick (see [`calibrate`]).
pub const SLIP: f64 = 0.01;

/// The calibrated probability per tick of starting a pause (see [`calibrate`]).
pub const PAUSE_START: f64 = 0.825;

/// The calibrated weight of points against distance (see [`calibrate`]).
pub const GREED: f64 = 0.0;

/// Ticks a pause lasts.
pub const PAUSE_TICKS: u32 = 15;

/// The seed of the calibration's levels (not any experiment's seed).
pub const CALIBRATION_SEED: u64 = 0x6d61_7269_6f63_616c; // "mariocal"

/// Demonstrations simulated per grid point in the calibration.
pub const CALIBRATION_DEMOS: usize = 60;

/// The grid of slip probabilities the calibration searches.
pub fn slip_grid() -> Vec<f64> {
    vec![0.0, 0.005, 0.01, 0.02]
}

/// The grid of pause probabilities (per walking plan) the calibration
/// searches: finer from 0.8 to 0.9, where the score falls from about 2,000 to
/// about 600 (inputs only: the grid, not a learner's result, was refined).
pub fn pause_grid() -> Vec<f64> {
    vec![0.0, 0.4, 0.6, 0.7, 0.8, 0.825, 0.85, 0.875, 0.9]
}

/// The grid of greed values the calibration searches.
pub fn greed_grid() -> Vec<f64> {
    vec![0.0, 1.0]
}

/// The scripted expert.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MarioDemonstrator {
    /// Probability per tick of a random action instead of the script's.
    pub slip: f64,
    /// Probability of a pause instead of each new plan made on the ground.
    pub pause_start: f64,
    /// Weight of the points earned against the pixels gained when judging a
    /// plan: 1 takes every coin within reach (a coin is worth 16 px), 0
    /// heads for the exit and takes only what lies on the way.
    pub greed: f64,
}

/// One recorded episode.
#[derive(Clone, Debug, PartialEq)]
pub struct Demonstration {
    /// The 27 variables before each action (one observation per tick).
    pub states: Vec<[f64; STATE_VARIABLES]>,
    /// The action taken after each observation.
    pub actions: Vec<usize>,
    /// Mario's position (px) at each observation, for drawing.
    pub path: Vec<(f32, f32)>,
    /// The level's seed.
    pub level_seed: u64,
    /// Mario's start mode.
    pub start_mode: Mode,
    /// Points scored (the environment's return).
    pub score: f64,
    /// How it ended.
    pub outcome: Status,
    /// Times the player was stuck (no new best position for [`STUCK_TICKS`]) and planned an escape.
    pub stuck: u32,
    /// Whether the game ended with the timer at zero.
    pub timer_out: bool,
}

impl Demonstration {
    /// Observations (= ticks played).
    pub fn len(&self) -> usize {
        self.states.len()
    }

    /// Whether nothing was recorded.
    pub fn is_empty(&self) -> bool {
        self.states.is_empty()
    }

    /// Whether the timer ran out (the episode lasted every tick of it).
    pub fn timed_out(&self) -> bool {
        self.outcome == Status::Dead && self.timer_out
    }
}

/// Ticks between two plans.
pub const DECISION_TICKS: u32 = 5;

/// Ticks a plan looks ahead.
pub const HORIZON: u32 = 24;

/// The plans considered: key sequences over the horizon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Plan {
    /// Walk right.
    Walk,
    /// Walk right, jump after `delay` ticks holding the key `hold` ticks.
    Jump { delay: u32, hold: u32 },
    /// Stand still for 8 ticks, then walk right.
    Wait,
    /// Step back for 8 ticks, then walk right and jump after 8 more (a run-up).
    BackJump,
    /// Walk right and jump after 8 ticks, holding the key 12 ticks.
    LateJump,
    /// A way out when stuck: back up `back` ticks, then go right, jumping
    /// `delay` ticks after turning and holding the key `hold` ticks; running
    /// (the speed key held) throughout if `run`.
    Escape { back: u32, delay: u32, hold: u32, run: bool },
    /// A way out of a pit one cell wide: hop back (jump held for the first
    /// `hop` ticks of a back-up of `back` ticks), then go right and jump at
    /// once holding the key 12 ticks; running throughout if `run`.
    HopBack { back: u32, hop: u32, run: bool },
    /// A way up through a low ceiling of bricks: back up `back` ticks, then
    /// go right jumping twice (the key held 8 ticks, released 8, held 12):
    /// big Mario breaks a brick with the first jump and passes with the
    /// second; running throughout if `run`.
    DoubleJump { back: u32, run: bool },
    /// A way up through a ceiling just overhead: walk right `forward` ticks,
    /// jump straight up (the key held 12 ticks, no direction: big Mario
    /// breaks the brick above him), wait 8 ticks, then go right and jump
    /// holding the key 12 ticks; running throughout if `run`.
    BumpUp { forward: u32, run: bool },
    /// Fiddling, when the escapes have failed: a key combination drawn anew
    /// every [`FIDDLE_SEGMENT`] ticks from `seed` (uniform over the 12 actions).
    Fiddle { seed: u64 },
}

/// Ticks a fiddling key combination is held.
pub const FIDDLE_SEGMENT: u32 = 6;

/// Ticks a fiddling sequence lasts (and looks ahead).
pub const FIDDLE_HORIZON: u32 = 200;

/// Fiddling sequences the player imagines when the escapes have failed.
pub const FIDDLES: u64 = 256;

/// Failed escapes in a row after which the player fiddles instead.
pub const ESCAPES_BEFORE_FIDDLING: u32 = 2;

/// SplitMix64's finaliser: a fiddling sequence's key index at a segment.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

const PLANS: [Plan; 9] = [
    Plan::Walk,
    Plan::Jump { delay: 0, hold: 2 },
    Plan::Jump { delay: 0, hold: 5 },
    Plan::Jump { delay: 0, hold: 12 },
    Plan::Jump { delay: 2, hold: 12 },
    Plan::Jump { delay: 5, hold: 12 },
    Plan::Wait,
    Plan::BackJump,
    Plan::LateJump,
];

/// Ticks without a new best position (by at least a cell) after which the player is stuck.
pub const STUCK_TICKS: u32 = 30;

/// Ticks an escape plan looks ahead.
pub const ESCAPE_HORIZON: u32 = 72;

/// The escapes considered when stuck: every back-up, delay, hold and pace
/// of a run-up (72), then the hop-backs (24), double jumps (8) and bumps up
/// (6), in that order (ties go to the first).
const ESCAPES: [Plan; 110] = {
    const BACK: [u32; 4] = [4, 10, 16, 24];
    const DELAY: [u32; 3] = [0, 4, 8];
    const HOLD: [u32; 3] = [4, 8, 12];
    let mut out = [Plan::Walk; 110];
    let mut k = 0;
    let mut i = 0;
    while i < 4 {
        let mut j = 0;
        while j < 3 {
            let mut h = 0;
            while h < 3 {
                out[k] = Plan::Escape { back: BACK[i], delay: DELAY[j], hold: HOLD[h], run: false };
                out[k + 1] = Plan::Escape { back: BACK[i], delay: DELAY[j], hold: HOLD[h], run: true };
                k += 2;
                h += 1;
            }
            j += 1;
        }
        i += 1;
    }
    i = 0;
    while i < 4 {
        let mut h = 0;
        while h < 3 {
            out[k] = Plan::HopBack { back: BACK[i], hop: HOLD[h], run: false };
            out[k + 1] = Plan::HopBack { back: BACK[i], hop: HOLD[h], run: true };
            k += 2;
            h += 1;
        }
        i += 1;
    }
    i = 0;
    while i < 4 {
        out[k] = Plan::DoubleJump { back: BACK[i], run: false };
        out[k + 1] = Plan::DoubleJump { back: BACK[i], run: true };
        k += 2;
        i += 1;
    }
    const FORWARD: [u32; 3] = [0, 2, 4];
    i = 0;
    while i < 3 {
        out[k] = Plan::BumpUp { forward: FORWARD[i], run: false };
        out[k + 1] = Plan::BumpUp { forward: FORWARD[i], run: true };
        k += 2;
        i += 1;
    }
    out
};

impl Plan {
    /// Ticks the player follows the plan before planning again: at least
    /// [`DECISION_TICKS`], and until its jump has begun (a plan is chosen for its jump).
    fn commitment(self) -> u32 {
        let until = match self {
            Plan::Walk => 0,
            Plan::Jump { delay, .. } => delay + 1,
            Plan::Wait => 8,
            Plan::BackJump => 17,
            Plan::LateJump => 9,
            Plan::Escape { back, delay, .. } => back + delay + 1,
            Plan::HopBack { back, .. } => back + 1,
            Plan::DoubleJump { back, .. } => back + 17,
            Plan::BumpUp { forward, .. } => forward + 21,
            Plan::Fiddle { .. } => FIDDLE_HORIZON,
        };
        until.max(DECISION_TICKS)
    }

    /// The keys at tick `t` of the plan (the caller may add speed).
    fn keys(self, t: u32) -> Keys {
        let right = Keys { right: true, ..Keys::default() };
        match self {
            Plan::Walk => right,
            Plan::Jump { delay, hold } => Keys { jump: t >= delay && t < delay + hold, ..right },
            Plan::Wait => {
                if t < 8 {
                    Keys::default()
                } else {
                    right
                }
            }
            Plan::BackJump => {
                if t < 8 {
                    Keys { left: true, ..Keys::default() }
                } else {
                    Keys { jump: t >= 16, ..right }
                }
            }
            Plan::LateJump => Keys { jump: (8..20).contains(&t), ..right },
            Plan::Escape { back, delay, hold, run } => {
                if t < back {
                    Keys { left: true, speed: run, ..Keys::default() }
                } else {
                    let jump = t >= back + delay && t < back + delay + hold;
                    Keys { jump, speed: run, ..right }
                }
            }
            Plan::HopBack { back, hop, run } => {
                if t < back {
                    Keys { left: true, jump: t < hop, speed: run, ..Keys::default() }
                } else {
                    Keys { jump: t < back + 12, speed: run, ..right }
                }
            }
            Plan::DoubleJump { back, run } => {
                if t < back {
                    Keys { left: true, speed: run, ..Keys::default() }
                } else {
                    let u = t - back;
                    Keys { jump: u < 8 || (16..28).contains(&u), speed: run, ..right }
                }
            }
            Plan::BumpUp { forward, run } => {
                if t < forward {
                    Keys { speed: run, ..right }
                } else if t < forward + 20 {
                    Keys { jump: t < forward + 12, speed: run, ..Keys::default() }
                } else {
                    Keys { jump: t < forward + 32, speed: run, ..right }
                }
            }
            Plan::Fiddle { seed } => {
                let segment = u64::from(t / FIDDLE_SEGMENT);
                ACTION_KEYS[(mix(seed ^ mix(segment)) % ACTIONS as u64) as usize]
            }
        }
    }
}

/// The player's memory between ticks.
#[derive(Clone, Debug)]
struct Player {
    plan: Plan,
    step: u32,
    pause_left: u32,
    last_speed: bool,
    /// The farthest x (px) reached so far, and the ticks since it last grew by a cell.
    best_x: f32,
    stalled: u32,
    /// Times the player found itself stuck (for the report).
    stuck: u32,
    /// Stuck in a row without a new best position since.
    streak: u32,
    scratch: Option<World>,
}

/// How good an imagined future is: alive first, then unhurt, then pixels
/// gained right plus `greed` times the points earned.
fn judge(start: &World, end: &World, points: i32, greed: f64) -> (i32, i32, i32, i32) {
    let alive = i32::from(end.status() != Status::Dead);
    let mode = end.mario().mode as i32 - start.mario().mode as i32;
    let gain = f64::from(end.mario().x - start.mario().x) + greed * f64::from(points);
    // Between plans that gain the same, one that finishes the level is
    // better: at the level's right edge, below the exit's row, every plan
    // gains nothing, and a person jumps to the flag rather than walk into
    // the edge (the benchmark wins only when Mario's row is at most the exit's).
    let won = i32::from(end.status() == Status::Won);
    (alive, mode.min(0), gain.round() as i32, won)
}

impl MarioDemonstrator {
    /// The calibrated demonstrator.
    pub fn thesis() -> Self {
        MarioDemonstrator { slip: SLIP, pause_start: PAUSE_START, greed: GREED }
    }

    /// Plays one episode on `env` (level and start mode drawn from `rng` as
    /// an agent's episode draws them) and records it.
    pub fn demonstrate<R: Rng + ?Sized>(&self, env: &mut MarioEnv, rng: &mut R) -> Demonstration {
        let level_seed = rng.next_u64();
        let mode = Mode::ALL[below(rng, 3)];
        self.demonstrate_on(env, level_seed, mode, rng)
    }

    /// Plays the level of `level_seed` from `mode` and records it; `rng` drives the player.
    pub fn demonstrate_on<R: Rng + ?Sized>(
        &self,
        env: &mut MarioEnv,
        level_seed: u64,
        mode: Mode,
        rng: &mut R,
    ) -> Demonstration {
        env.start(level_seed, mode);
        let mut d = Demonstration {
            states: Vec::with_capacity(1200),
            actions: Vec::with_capacity(1200),
            path: Vec::with_capacity(1200),
            level_seed,
            start_mode: mode,
            score: 0.0,
            outcome: Status::Running,
            stuck: 0,
            timer_out: false,
        };
        let mut player = Player {
            plan: Plan::Walk,
            step: DECISION_TICKS,
            pause_left: 0,
            last_speed: false,
            best_x: env.world().mario().x,
            stalled: 0,
            stuck: 0,
            streak: 0,
            scratch: None,
        };
        loop {
            let mut keys = self.play(env.world(), &mut player, rng);
            if bernoulli(rng, self.slip) {
                keys = ACTION_KEYS[below(rng, ACTIONS)];
            }
            player.last_speed = keys.speed;
            let action = action_of(keys);
            let mut s = [0.0; STATE_VARIABLES];
            s.copy_from_slice(env.state());
            d.states.push(s);
            d.actions.push(action);
            d.path.push((env.world().mario().x, env.world().mario().y));
            let step = env.step(action, rng);
            d.score += step.reward;
            if step.terminal {
                d.stuck = player.stuck;
                d.timer_out = env.world().time_left() <= 0;
                d.outcome = env.world().status();
                d.path.push((env.world().mario().x, env.world().mario().y));
                return d;
            }
        }
    }

    /// Records `count` demonstrations on consecutive random levels, keeping
    /// every episode as it ends (won, died or timed out): none is redone, so
    /// no episode is kept or dropped for its length or its outcome.
    pub fn record<R: Rng + ?Sized>(&self, params: LevelParams, rng: &mut R, count: usize) -> Vec<Demonstration> {
        let mut env = MarioEnv::new(params);
        (0..count).map(|_| self.demonstrate(&mut env, rng)).collect()
    }

    /// The player's keys for this tick.
    fn play<R: Rng + ?Sized>(&self, w: &World, p: &mut Player, rng: &mut R) -> Keys {
        if p.pause_left > 0 {
            p.pause_left -= 1;
            return Keys::default();
        }
        // A pause is not being stuck: only ticks of play count.
        if w.mario().x >= p.best_x + CELL {
            p.best_x = w.mario().x;
            p.stalled = 0;
            p.streak = 0;
        } else {
            p.stalled += 1;
        }
        if p.step >= p.plan.commitment() {
            // Stuck (a wall under a low ceiling, say): a person backs up and
            // tries a run-up; the planner looks over longer run-ups.
            p.plan = if p.stalled >= STUCK_TICKS {
                p.stalled = 0;
                p.stuck += 1;
                p.streak += 1;
                if p.streak > ESCAPES_BEFORE_FIDDLING {
                    // The run-ups have failed: a person tries other things
                    // (some traps need a sequence no run-up is, e.g. a hop
                    // under a low ceiling); the best of many imagined ones.
                    let base = rng.next_u64();
                    self.choose(w, p, (0..FIDDLES).map(|i| Plan::Fiddle { seed: base.wrapping_add(i) }), FIDDLE_HORIZON)
                } else {
                    self.choose(w, p, ESCAPES, ESCAPE_HORIZON)
                }
            } else {
                self.choose(w, p, PLANS, HORIZON)
            };
            p.step = 0;
            if w.mario().on_ground && bernoulli(rng, self.pause_start) && self.safe_to_pause(w, p) {
                p.pause_left = PAUSE_TICKS - 1;
                p.step = p.plan.commitment();
                return Keys::default();
            }
        }
        let mut keys = p.plan.keys(p.step);
        p.step += 1;
        // Fire at an enemy ahead with a fresh press; otherwise run during spells.
        let m = w.mario();
        let target = m.mode == Mode::Fire
            && w.sprites().iter().any(|e| {
                let dx = (e.x - m.x) * m.facing as f32;
                e.kind.is_enemy()
                    && e.kind != SpriteKind::Spiky
                    && dx > 0.0
                    && dx < 6.0 * CELL
                    && ((e.y / CELL) as i32 - (m.y / CELL) as i32).abs() <= 1
            });
        // A running escape keeps its speed key held.
        keys.speed |= target && !p.last_speed;
        keys
    }

    /// Whether standing still for a pause keeps Mario alive and unhurt (a
    /// person stops to look only where nothing is coming).
    fn safe_to_pause(&self, w: &World, p: &mut Player) -> bool {
        let scratch = p.scratch.get_or_insert_with(|| w.clone());
        scratch.clone_from(w);
        for _ in 0..PAUSE_TICKS {
            if scratch.status() != Status::Running {
                break;
            }
            scratch.tick(Keys::default());
        }
        judge(w, scratch, 0, 0.0).0 == 1 && scratch.mario().mode == w.mario().mode
    }

    /// The plan of `plans` whose imagined future over `horizon` ticks is best.
    fn choose(&self, w: &World, p: &mut Player, plans: impl IntoIterator<Item = Plan>, horizon: u32) -> Plan {
        let scratch = p.scratch.get_or_insert_with(|| w.clone());
        let mut best = (Plan::Walk, (i32::MIN, i32::MIN, i32::MIN, i32::MIN));
        for plan in plans {
            scratch.clone_from(w);
            let mut points = 0;
            for t in 0..horizon {
                if scratch.status() != Status::Running {
                    break;
                }
                points += scratch.tick(plan.keys(t));
            }
            // The win's points count as distance: a plan is not better for ending the level sooner.
            if scratch.status() == Status::Won {
                points -= super::world::points::WIN;
            }
            let score = judge(w, scratch, points, self.greed);
            if score > best.1 {
                best = (plan, score);
            }
        }
        best.0
    }
}

/// What the report says about a set of demonstrations.
#[derive(Clone, Debug, PartialEq)]
pub struct DemonstrationStats {
    /// Observations of each demonstration.
    pub lengths: Vec<usize>,
    /// Score of each.
    pub scores: Vec<f64>,
    /// Mean score.
    pub mean_score: f64,
    /// The 10th-longest length (the shortest of ten).
    pub tenth_longest: usize,
    /// Levels finished.
    pub wins: usize,
    /// Deaths before the timer ran out.
    pub deaths: usize,
    /// Episodes whose timer ran out.
    pub timeouts: usize,
    /// Escapes planned over all episodes (see [`STUCK_TICKS`]).
    pub stuck: usize,
}

/// Measures demonstrations.
pub fn measure(demos: &[Demonstration]) -> DemonstrationStats {
    let lengths: Vec<usize> = demos.iter().map(Demonstration::len).collect();
    let scores: Vec<f64> = demos.iter().map(|d| d.score).collect();
    let mut sorted = lengths.clone();
    sorted.sort_unstable_by(|a, b| b.cmp(a));
    DemonstrationStats {
        mean_score: scores.iter().sum::<f64>() / scores.len().max(1) as f64,
        tenth_longest: sorted.get(thesis::COUNT - 1).or(sorted.last()).copied().unwrap_or(0),
        wins: demos.iter().filter(|d| d.outcome == Status::Won).count(),
        deaths: demos.iter().filter(|d| d.outcome == Status::Dead && !d.timed_out()).count(),
        timeouts: demos.iter().filter(|d| d.timed_out()).count(),
        stuck: demos.iter().map(|d| d.stuck as usize).sum(),
        lengths,
        scores,
    }
}

/// The demonstrations as a set: states are the 27 variables, actions 0..12.
pub fn to_demonstration_set(demos: &[Demonstration]) -> DemonstrationSet {
    let trajectories = demos
        .iter()
        .map(|d| Trajectory::from_states(&d.states, Some(d.actions.clone())).expect("a demonstration has a state"))
        .collect();
    DemonstrationSet::new(NAMES.iter().map(|n| n.to_string()).collect(), Some(ACTIONS), trajectories)
        .expect("a well-formed set")
}

/// What the calibration measured at one grid point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CalibrationPoint {
    /// The demonstrator.
    pub model: MarioDemonstrator,
    /// Mean score over the calibration's recorded demonstrations.
    pub mean_score: f64,
    /// Expected 10th-longest of ten demonstrations (order statistic of the sample).
    pub expected_tenth_longest: f64,
    /// How the episodes ended.
    pub outcomes: Outcomes,
}

/// How a number of episodes ended: won, died (hit or fell), timed out; and
/// how often the player found itself stuck.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outcomes {
    /// Levels finished.
    pub won: usize,
    /// Deaths before the timer ran out.
    pub died: usize,
    /// Timer ran out (3,000 ticks).
    pub timed_out: usize,
    /// Escapes planned (see [`STUCK_TICKS`]).
    pub stuck: usize,
}

impl Outcomes {
    /// Counts one episode.
    pub fn add(&mut self, d: &Demonstration) {
        match d.outcome {
            Status::Won => self.won += 1,
            _ if d.timed_out() => self.timed_out += 1,
            _ => self.died += 1,
        }
        self.stuck += d.stuck as usize;
    }
}

/// Records `demos` demonstrations with `model` on the calibration levels
/// (every episode kept, as [`MarioDemonstrator::record`]) and measures them.
pub fn evaluate(model: MarioDemonstrator, params: LevelParams, demos: usize) -> CalibrationPoint {
    // Levels and start modes from one stream, the player's draws from another:
    // every grid point plays the same levels.
    let mut levels = seeded(CALIBRATION_SEED);
    let mut rng = seeded(CALIBRATION_SEED ^ 1);
    let mut env = MarioEnv::new(params);
    let mut lengths = Vec::with_capacity(demos);
    let (mut total, mut outcomes) = (0.0, Outcomes::default());
    for _ in 0..demos {
        let d = model.demonstrate_on(&mut env, levels.next_u64(), Mode::ALL[below(&mut levels, 3)], &mut rng);
        total += d.score;
        lengths.push(d.len() as f64);
        outcomes.add(&d);
    }
    CalibrationPoint {
        model,
        mean_score: total / demos as f64,
        expected_tenth_longest: expected_minimum_of(&mut lengths, thesis::COUNT),
        outcomes,
    }
}

/// The expected minimum of `k` draws (without replacement) from `sample`:
/// `Σ_i x_(i) · C(n − i, k − 1) / C(n, k)` over the ascending order statistics.
pub fn expected_minimum_of(sample: &mut [f64], k: usize) -> f64 {
    sample.sort_by(f64::total_cmp);
    let n = sample.len();
    if n < k || k == 0 {
        return f64::NAN;
    }
    // P(the minimum is the i-th smallest) = C(n−1−i, k−1) / C(n, k), computed as a running ratio.
    let mut p = k as f64 / n as f64; // i = 0
    let mut e = 0.0;
    for (i, &x) in sample.iter().enumerate() {
        if n - 1 - i < k - 1 {
            break;
        }
        e += p * x;
        // Next: C(n−2−i, k−1) / C(n−1−i, k−1) = (n−1−i−(k−1)) / (n−1−i).
        let m = (n - 1 - i) as f64;
        p *= (m - (k - 1) as f64) / m;
    }
    e
}

/// The calibration: `slip` and `pause_start` together (see the module
/// docs). Grid points run in parallel; the choice is made over them in grid
/// order (slip-major), the first of equal errors winning.
pub fn calibrate(params: LevelParams, demos: usize) -> (MarioDemonstrator, Vec<CalibrationPoint>) {
    use rayon::prelude::*;
    let grid: Vec<MarioDemonstrator> = slip_grid()
        .into_iter()
        .flat_map(|slip| pause_grid().into_iter().map(move |pause_start| (slip, pause_start)))
        .flat_map(|(slip, pause_start)| {
            greed_grid().into_iter().map(move |greed| MarioDemonstrator { slip, pause_start, greed })
        })
        .collect();
    let points: Vec<CalibrationPoint> = grid.into_par_iter().map(|m| evaluate(m, params, demos)).collect();
    let mut best = (f64::INFINITY, points[0].model);
    for p in &points {
        let e_score = (p.mean_score - thesis::MEAN_SCORE) / thesis::MEAN_SCORE;
        let e_length = (p.expected_tenth_longest - thesis::TENTH_LONGEST as f64) / thesis::TENTH_LONGEST as f64;
        let err = e_score * e_score + e_length * e_length;
        if err < best.0 {
            best = (err, p.model);
        }
    }
    (best.1, points)
}

/// The slip-free, pause-free player's mean score and expected 10th-longest
/// of ten episodes (every episode kept, none redone) at each difficulty (the measurements behind the
/// levels' difficulty).
pub fn difficulty_table(
    width: i32,
    difficulties: std::ops::RangeInclusive<u32>,
    demos: usize,
) -> Vec<(u32, CalibrationPoint)> {
    use rayon::prelude::*;
    let ds: Vec<u32> = difficulties.collect();
    ds.into_par_iter()
        .map(|difficulty| {
            let p = LevelParams { width, difficulty, ..LevelParams::EXPERIMENT };
            (difficulty, evaluate(MarioDemonstrator { slip: 0.0, pause_start: 0.0, greed: 1.0 }, p, demos))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expected_minimum_matches_brute_force() {
        let mut s = vec![5.0, 1.0, 4.0, 2.0, 3.0];
        // Minimum of 2 draws from {1..5}: Σ over pairs of the smaller / 10 = (4·1 + 3·2 + 2·3 + 1·4)/10 = 2.
        assert!((expected_minimum_of(&mut s, 2) - 2.0).abs() < 1e-12);
        let mut s = vec![7.0, 3.0, 9.0];
        assert!((expected_minimum_of(&mut s, 3) - 3.0).abs() < 1e-12);
        assert!((expected_minimum_of(&mut s, 1) - 19.0 / 3.0).abs() < 1e-12);
    }

    #[test]
    fn the_shipped_demonstrator_is_the_calibrated_one() {
        let (model, points) = calibrate(LevelParams::EXPERIMENT, CALIBRATION_DEMOS);
        assert_eq!(model, MarioDemonstrator::thesis());
        assert_eq!(points.len(), slip_grid().len() * pause_grid().len() * greed_grid().len());
    }

    #[test]
    fn demonstrations_are_whole_episodes_with_actions() {
        let model = MarioDemonstrator::thesis();
        let demos = model.record(LevelParams::EXPERIMENT, &mut seeded(3), 3);
        for d in &demos {
            assert_eq!(d.states.len(), d.actions.len());
            assert_eq!(d.path.len(), d.len() + 1);
            assert_ne!(d.outcome, Status::Running);
            assert!(d.len() <= 3000);
        }
        // Every episode is kept, in order: the same seed plays the same three episodes.
        let again = model.record(LevelParams::EXPERIMENT, &mut seeded(3), 3);
        assert_eq!(
            demos.iter().map(|d| (d.level_seed, d.len())).collect::<Vec<_>>(),
            again.iter().map(|d| (d.level_seed, d.len())).collect::<Vec<_>>()
        );
        let set = to_demonstration_set(&demos);
        assert_eq!(set.len(), 3);
        assert_eq!(set.dimension(), 27);
        assert_eq!(set.num_actions(), Some(12));
    }

    /// The longest stretch of ticks in which Mario's farthest x did not grow by a cell.
    fn longest_stall(d: &Demonstration) -> usize {
        let (mut best, mut since, mut longest) = (f32::MIN, 0, 0);
        for &(x, _) in &d.path {
            if x >= best + CELL {
                best = x;
                since = 0;
            } else {
                since += 1;
                longest = longest.max(since);
            }
        }
        longest
    }

    #[test]
    fn the_player_does_not_stall() {
        // The slip-free, pause-free player on 60 levels: it wins nearly all,
        // and where it is held up it backs up and tries run-ups instead of
        // pressing right into a wall until the timer runs out.
        let model = MarioDemonstrator { slip: 0.0, pause_start: 0.0, greed: 1.0 };
        let demos = model.record(LevelParams::EXPERIMENT, &mut seeded(5), 60);
        let mut outcomes = Outcomes::default();
        for d in &demos {
            outcomes.add(d);
        }
        let stalls: Vec<usize> = demos.iter().map(longest_stall).collect();
        let long = stalls.iter().filter(|&&s| s > 600).count();
        // Measured with the hop-backs, jumps up and fiddling: 60 won (before
        // them 54 won, 1 died, 5 timed out in traps no run-up leaves).
        assert!(outcomes.won >= 58, "{outcomes:?}");
        assert!(outcomes.timed_out <= 1 && long <= 1, "{outcomes:?}, stalls {stalls:?}");
    }
}
