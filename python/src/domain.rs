//! The domains as Gymnasium sees them, in plain Rust (no Python here): one
//! [`Domain`] per environment instance, holding the simulator and its own
//! seeded generator, moved one agent step at a time.
//!
//! What a step is, per domain (the thesis's view of each):
//!
//! - **Maze** (section 6.3.1): one move of 0.02; state `(x, y)`; rewards
//!   −1, −11 into a wall, +9 into the goal (which ends the episode). The
//!   chapter caps episodes at 6,000 steps ([`MAZE_STEP_CAP`]): a
//!   truncation, the `max_episode_steps` option.
//! - **Mario** (section 6.3.2): one game tick; the 27 state variables; the
//!   benchmark's points as reward; a new random level and start mode at every
//!   reset; the game's own timer (3,000 ticks) ends every episode.
//! - **Keepaway** (chapter 5): one SMDP decision of the keeper with the ball
//!   (Hold, or a pass to the i-th nearest teammate); the state variables of
//!   `keeperStateVars` from that keeper's view; the reward is the simulated
//!   time the step took in cycles (100 ms), from the episode's start for the
//!   first step, so an episode's return is its duration, the thesis's score.
//!   What each keeper's own learner sees (the cycles since *its* previous
//!   action, `team.rs` in chapter 5) is reported beside it
//!   ([`KeepawayCore::smdp_reward`]). An episode that ends before any keeper
//!   had to decide (the takers win the ball before a keeper reaches it) has
//!   no first observation; [`Domain::reset`] then starts another from the
//!   same stream and counts it.
//!
//! Seeds: `reset(Some(seed))` reseeds the instance's generator with
//! `rlfd_env::random::seeded(seed)` (ChaCha8, the generator of every trial
//! of the reproduction) before the domain's own reset draws from it (and
//! starts a new Keepaway game: the game keeps the players' body directions
//! and see phases from episode to episode, so only a new game makes the
//! episode a function of the seed); `None` continues the stream and the game. So `reset(seed)` then a list of actions gives the
//! trajectory the Rust simulator gives for that seed and those actions.
//!
//! Not here: Python objects (`py.rs`), pictures (`render.rs`), many
//! environments at once (`vector.rs`).

use rlfd_env::Environment;
use rlfd_env::random::{SimRng, below, seeded};
use rlfd_keepaway::{BenchmarkPolicy, EndCause, Keepaway, KeepawayParams, KeeperAction, Status};
use rlfd_mario::observation::{CLOSE, CLOSEST, NAMES as MARIO_NAMES, STATE_VARIABLES};
use rlfd_mario::{ACTIONS as MARIO_ACTIONS, LevelParams, MarioEnv};
use rlfd_maze::layout::LayoutId;
use rlfd_maze::{Maze, MazeLayout, MazeRewards};

/// The Maze's step cap (chapter 6: episodes end at the goal or after 6,000
/// steps). The Python package registers it as the Gymnasium id's
/// `max_episode_steps`; a bare [`DomainSpec`] has no cap unless given one.
pub const MAZE_STEP_CAP: u64 = 6000;

/// Which environment, and its options, checked.
#[derive(Clone, Debug, PartialEq)]
pub enum DomainSpec {
    /// The Maze: the layout (the `maze-layout` reading), the length of a
    /// move in hundredths (2: the agent's 0.02; 1: the demonstrator's
    /// recording resolution, on which the chapter rolls out RE-IRL's
    /// baseline) and the step cap.
    Maze { layout: LayoutId, step: i32, max_episode_steps: Option<u64> },
    /// Mario on the experiment's levels (width 320, difficulty 0).
    Mario { max_episode_steps: Option<u64> },
    /// Keepaway with `keepers` vs `takers` on a `side` × `side` region.
    Keepaway { keepers: usize, takers: usize, side: f64, max_episode_steps: Option<u64> },
}

/// A value of an option as it came from the caller.
#[derive(Clone, Debug, PartialEq)]
pub enum OptionValue {
    /// An integer.
    Int(i64),
    /// A float.
    Float(f64),
    /// A string.
    Str(String),
    /// None.
    None,
    /// Anything else (a bool, a list…), as Python shows it.
    Other(String),
}

impl OptionValue {
    fn describe(&self) -> String {
        match self {
            OptionValue::Int(v) => v.to_string(),
            OptionValue::Float(v) => v.to_string(),
            OptionValue::Str(s) => format!("{s:?}"),
            OptionValue::None => "None".into(),
            OptionValue::Other(repr) => repr.clone(),
        }
    }
}

/// The environments by name (as `rlfd.make_vec` and the registry know them).
pub const DOMAINS: [&str; 3] = ["maze", "mario", "keepaway"];

fn option_error(domain: &str, name: &str, value: &OptionValue, expected: &str) -> String {
    format!("{domain} option {name}={} is invalid: expected {expected}", value.describe())
}

fn positive_int(domain: &str, name: &str, value: &OptionValue) -> Result<u64, String> {
    match value {
        OptionValue::Int(v) if *v > 0 => Ok(*v as u64),
        _ => Err(option_error(domain, name, value, "a positive integer")),
    }
}

fn step_cap(domain: &str, value: &OptionValue) -> Result<Option<u64>, String> {
    match value {
        OptionValue::None => Ok(None),
        v => positive_int(domain, "max_episode_steps", v).map(Some),
    }
}

impl DomainSpec {
    /// The spec of `domain` with `options` (name, value) applied to its
    /// defaults; an unknown domain or option, or a value outside its domain,
    /// is refused with one sentence naming it and what is accepted.
    pub fn parse(domain: &str, options: &[(String, OptionValue)]) -> Result<DomainSpec, String> {
        let mut spec = match domain {
            "maze" => DomainSpec::Maze { layout: LayoutId::LowDetour, step: 2, max_episode_steps: None },
            "mario" => DomainSpec::Mario { max_episode_steps: None },
            "keepaway" => DomainSpec::Keepaway { keepers: 3, takers: 2, side: 20.0, max_episode_steps: None },
            other => return Err(format!("unknown environment {other:?}: expected one of {}", DOMAINS.join(", "))),
        };
        for (name, value) in options {
            match (&mut spec, name.as_str()) {
                (DomainSpec::Maze { max_episode_steps, .. }, "max_episode_steps")
                | (DomainSpec::Mario { max_episode_steps }, "max_episode_steps")
                | (DomainSpec::Keepaway { max_episode_steps, .. }, "max_episode_steps") => {
                    *max_episode_steps = step_cap(domain, value)?;
                }
                (DomainSpec::Maze { layout, .. }, "layout") => {
                    let names = LayoutId::ALL.map(LayoutId::name);
                    *layout = match value {
                        OptionValue::Str(s) => LayoutId::ALL.into_iter().find(|l| l.name() == s),
                        _ => None,
                    }
                    .ok_or_else(|| option_error(domain, name, value, &format!("one of {}", names.join(", "))))?;
                }
                (DomainSpec::Maze { step, .. }, "step") => {
                    *step = match value {
                        OptionValue::Int(v) if (1..=20).contains(v) => *v as i32,
                        _ => return Err(option_error(domain, name, value, "a move length in hundredths, 1 to 20")),
                    };
                }
                (DomainSpec::Keepaway { keepers, .. }, "keepers") => {
                    *keepers = match value {
                        OptionValue::Int(v) if (3..=5).contains(v) => *v as usize,
                        _ => return Err(option_error(domain, name, value, "3, 4 or 5")),
                    };
                }
                (DomainSpec::Keepaway { takers, .. }, "takers") => {
                    *takers = match value {
                        OptionValue::Int(v) if (2..=4).contains(v) => *v as usize,
                        _ => return Err(option_error(domain, name, value, "2, 3 or 4")),
                    };
                }
                (DomainSpec::Keepaway { side, .. }, "region") => {
                    let v = match value {
                        OptionValue::Int(v) => *v as f64,
                        OptionValue::Float(v) => *v,
                        _ => f64::NAN,
                    };
                    // The referee insets players 3 m and the ball 4 m from the corners.
                    if !(v.is_finite() && v > 8.0 && v <= 100.0) {
                        return Err(option_error(
                            domain,
                            name,
                            value,
                            "a side length in metres, over 8 and at most 100",
                        ));
                    }
                    *side = v;
                }
                _ => {
                    return Err(format!(
                        "unknown {domain} option {name:?}: expected one of {}",
                        Self::option_names(domain).join(", ")
                    ));
                }
            }
        }
        Ok(spec)
    }

    /// The options `domain` accepts.
    pub fn option_names(domain: &str) -> &'static [&'static str] {
        match domain {
            "maze" => &["layout", "step", "max_episode_steps"],
            "mario" => &["max_episode_steps"],
            "keepaway" => &["keepers", "takers", "region", "max_episode_steps"],
            _ => &[],
        }
    }

    /// The step cap (a truncation), if any.
    pub fn max_episode_steps(&self) -> Option<u64> {
        match self {
            DomainSpec::Maze { max_episode_steps, .. }
            | DomainSpec::Mario { max_episode_steps }
            | DomainSpec::Keepaway { max_episode_steps, .. } => *max_episode_steps,
        }
    }

    /// Number of actions.
    pub fn num_actions(&self) -> usize {
        match self {
            DomainSpec::Maze { .. } => 4,
            DomainSpec::Mario { .. } => MARIO_ACTIONS,
            DomainSpec::Keepaway { keepers, .. } => *keepers,
        }
    }

    /// Length of the observation.
    pub fn state_dim(&self) -> usize {
        match self {
            DomainSpec::Maze { .. } => 2,
            DomainSpec::Mario { .. } => STATE_VARIABLES,
            DomainSpec::Keepaway { keepers, takers, .. } => rlfd_keepaway::state_len(*keepers, *takers),
        }
    }

    /// Per-variable bounds of the observation `(low, high)`.
    ///
    /// Maze: the unit square. Mario: booleans in {0, 1}, directions in
    /// {−1, 0, 1}, the closest enemy's offset in −11 … 16 (16: none).
    /// Keepaway: distances in [0, ∞) (players may stray past the region's
    /// lines), angles in [0, 180] degrees.
    pub fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        let n = self.state_dim();
        match self {
            DomainSpec::Maze { .. } => (vec![0.0; n], vec![1.0; n]),
            DomainSpec::Mario { .. } => {
                let mut low = vec![0.0; n];
                let mut high = vec![1.0; n];
                low[3] = -1.0;
                low[4] = -1.0;
                for i in CLOSEST..n {
                    low[i] = -11.0;
                    high[i] = rlfd_mario::observation::NO_ENEMY;
                }
                debug_assert_eq!(CLOSE, 5);
                (low, high)
            }
            DomainSpec::Keepaway { keepers, .. } => {
                let mut high = vec![f64::INFINITY; n];
                for h in &mut high[n - (keepers - 1)..] {
                    *h = 180.0;
                }
                (vec![0.0; n], high)
            }
        }
    }

    /// The names of the state variables.
    pub fn state_names(&self) -> Vec<String> {
        match self {
            DomainSpec::Maze { .. } => vec!["x".into(), "y".into()],
            DomainSpec::Mario { .. } => MARIO_NAMES.iter().map(|s| s.to_string()).collect(),
            DomainSpec::Keepaway { .. } => (0..self.state_dim()).map(|i| format!("state_{i}")).collect(),
        }
    }

    /// The names of the actions.
    pub fn action_names(&self) -> Vec<String> {
        match self {
            DomainSpec::Maze { .. } => rlfd_maze::Move::ALL.iter().map(|m| m.name().to_string()).collect(),
            DomainSpec::Mario { .. } => rlfd_mario::env::ACTION_NAMES.iter().map(|s| s.to_string()).collect(),
            DomainSpec::Keepaway { keepers, .. } => {
                std::iter::once("hold".to_string()).chain((1..*keepers).map(|i| format!("pass{i}"))).collect()
            }
        }
    }
}

/// The Keepaway game driven decision by decision.
#[derive(Clone, Debug)]
pub struct KeepawayCore {
    /// The game.
    pub game: Keepaway,
    state: Vec<f64>,
    /// The keeper deciding now.
    keeper: usize,
    /// The cycle of the previous agent step (0 at the start).
    previous_cycle: u32,
    /// Episodes that ended before any decision, since the last reset call.
    pub skipped_episodes: u32,
}

impl KeepawayCore {
    fn new(keepers: usize, takers: usize, side: f64) -> Result<Self, String> {
        let params = KeepawayParams::configuration(keepers, takers, side);
        let game = Keepaway::new(params).map_err(|e| e.to_string())?;
        let n = rlfd_keepaway::state_len(keepers, takers);
        Ok(KeepawayCore { game, state: vec![0.0; n], keeper: 0, previous_cycle: 0, skipped_episodes: 0 })
    }

    fn reset(&mut self, rng: &mut SimRng) {
        self.skipped_episodes = 0;
        loop {
            self.game.reset(rng);
            match self.game.run(rng) {
                Status::Decision(k) => {
                    self.decision(k);
                    self.previous_cycle = 0;
                    return;
                }
                Status::Ended(_) => self.skipped_episodes += 1,
            }
        }
    }

    fn decision(&mut self, k: usize) {
        self.keeper = k;
        self.game.state_vars_into(&mut self.state);
    }

    /// Returns (cycles this step took, how the episode ended if it did).
    fn step(&mut self, action: usize, rng: &mut SimRng) -> (f64, Option<EndCause>) {
        let status = self.game.act(KeeperAction(action as u8), rng);
        let cycle = self.game.cycle();
        let reward = f64::from(cycle - self.previous_cycle);
        self.previous_cycle = cycle;
        match status {
            Status::Decision(k) => {
                self.decision(k);
                (reward, None)
            }
            // The observation stays the last decision's (there is no keeper's view at the end).
            Status::Ended(cause) => (reward, Some(cause)),
        }
    }

    /// The keeper deciding now (keepers are numbered from 0).
    pub fn keeper(&self) -> usize {
        self.keeper
    }

    /// What the deciding keeper's own SMDP learner is rewarded now: the
    /// cycles since its previous action this episode (0 at its first), as
    /// chapter 5's keepers are (`learners/team.rs`).
    pub fn smdp_reward(&self) -> f64 {
        self.game.last_action_cycle(self.keeper).map_or(0.0, |c| f64::from(self.game.cycle() - c))
    }

    /// At the end: each keeper's last SMDP reward (the cycles from its last
    /// action to the end), NaN for a keeper that never acted.
    pub fn final_smdp_rewards(&self) -> Vec<f64> {
        let end = self.game.cycle();
        (0..self.game.params().keepers)
            .map(|k| self.game.last_action_cycle(k).map_or(f64::NAN, |c| f64::from(end - c)))
            .collect()
    }

    /// The benchmark policy's action now; Random draws from `rng` as the
    /// benchmark runs do.
    pub fn benchmark_action(&self, policy: BenchmarkPolicy, rng: &mut SimRng) -> usize {
        let p = self.game.params();
        policy.choose_in(&self.state, p.keepers, p.takers, rng).index()
    }
}

/// The simulator of one environment instance.
#[derive(Clone, Debug)]
pub enum Simulator {
    /// The Maze.
    Maze(Maze),
    /// Mario (boxed: its level and sprites are large).
    Mario(Box<MarioEnv>),
    /// Keepaway.
    Keepaway(Box<KeepawayCore>),
}

/// What one step did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// The environment's reward.
    pub reward: f64,
    /// The episode ended in the task (goal, timer, ball lost).
    pub terminated: bool,
    /// The episode was cut by the step cap.
    pub truncated: bool,
}

/// One environment instance: its spec, simulator, generator and step count.
#[derive(Clone, Debug)]
pub struct Domain {
    spec: DomainSpec,
    sim: Simulator,
    rng: SimRng,
    steps: u64,
    /// Whether the current episode has ended (a step then is refused).
    done: bool,
    /// Whether `reset` has been called.
    started: bool,
}

impl Domain {
    /// A new instance (call [`Domain::reset`] before stepping).
    pub fn new(spec: DomainSpec) -> Result<Domain, String> {
        let sim = match &spec {
            DomainSpec::Maze { layout, step, .. } => {
                Simulator::Maze(Maze::new(MazeLayout::of(*layout), *step, MazeRewards::THESIS))
            }
            DomainSpec::Mario { .. } => Simulator::Mario(Box::new(MarioEnv::new(LevelParams::EXPERIMENT))),
            DomainSpec::Keepaway { keepers, takers, side, .. } => {
                Simulator::Keepaway(Box::new(KeepawayCore::new(*keepers, *takers, *side)?))
            }
        };
        Ok(Domain { spec, sim, rng: seeded(0), steps: 0, done: true, started: false })
    }

    /// The spec.
    pub fn spec(&self) -> &DomainSpec {
        &self.spec
    }

    /// The simulator.
    pub fn simulator(&self) -> &Simulator {
        &self.sim
    }

    /// Whether `reset` has been called on this instance.
    pub fn started(&self) -> bool {
        self.started
    }

    /// Whether the current episode is over.
    pub fn done(&self) -> bool {
        self.done
    }

    /// Agent steps taken this episode.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Reseeds the generator without starting an episode.
    pub fn reseed(&mut self, seed: u64) {
        self.rng = seeded(seed);
    }

    /// A uniformly random action drawn from this instance's generator (as
    /// `rlfd_lfd::irl::rollout_uniform` draws its walkers' actions).
    pub fn uniform_action(&mut self) -> usize {
        below(&mut self.rng, self.spec.num_actions())
    }

    /// Starts an episode, reseeding first when `seed` is given (see the module docs).
    pub fn reset(&mut self, seed: Option<u64>) {
        if let Some(seed) = seed {
            self.rng = seeded(seed);
            // A Keepaway game carries the players' body directions and see
            // phases from one episode to the next (as the server does): a
            // seeded reset starts a new game, as a Rust trial does.
            if let Simulator::Keepaway(k) = &mut self.sim {
                let p = k.game.params();
                let (keepers, takers, side) = (p.keepers, p.takers, p.length);
                **k = KeepawayCore::new(keepers, takers, side).expect("the parameters were checked when first built");
            }
        }
        match &mut self.sim {
            Simulator::Maze(m) => m.reset(&mut self.rng),
            Simulator::Mario(m) => m.reset(&mut self.rng),
            Simulator::Keepaway(k) => k.reset(&mut self.rng),
        }
        self.steps = 0;
        self.done = false;
        self.started = true;
    }

    /// The current observation.
    pub fn state(&self) -> &[f64] {
        match &self.sim {
            Simulator::Maze(m) => m.state(),
            Simulator::Mario(m) => m.state(),
            Simulator::Keepaway(k) => &k.state,
        }
    }

    /// Checks that a step may be taken with `action`, else says why.
    pub fn check_step(&self, action: i64) -> Result<usize, String> {
        if !self.started {
            return Err("call reset() before step()".into());
        }
        if self.done {
            return Err("the episode has ended: call reset() before step()".into());
        }
        let n = self.spec.num_actions();
        if action < 0 || action as u64 >= n as u64 {
            return Err(format!("action {action} is out of range: expected 0 to {}", n - 1));
        }
        Ok(action as usize)
    }

    /// Takes a checked action (see [`Domain::check_step`]).
    pub fn step(&mut self, action: usize) -> Outcome {
        debug_assert!(!self.done && action < self.spec.num_actions());
        let (reward, terminated) = match &mut self.sim {
            Simulator::Maze(m) => {
                let s = m.step(action, &mut self.rng);
                (s.reward, s.terminal)
            }
            Simulator::Mario(m) => {
                let s = m.step(action, &mut self.rng);
                (s.reward, s.terminal)
            }
            Simulator::Keepaway(k) => {
                let (r, end) = k.step(action, &mut self.rng);
                (r, end.is_some())
            }
        };
        self.steps += 1;
        let truncated = !terminated && self.spec.max_episode_steps().is_some_and(|cap| self.steps >= cap);
        self.done = terminated || truncated;
        Outcome { reward, terminated, truncated }
    }

    /// The Keepaway core, if this is Keepaway.
    pub fn keepaway(&self) -> Option<&KeepawayCore> {
        match &self.sim {
            Simulator::Keepaway(k) => Some(k),
            _ => None,
        }
    }

    /// The benchmark policy's action now, drawing Random's choice from this
    /// instance's generator (as the benchmark runs draw from the game's).
    pub fn benchmark_action(&mut self, policy: BenchmarkPolicy) -> Option<usize> {
        match &self.sim {
            Simulator::Keepaway(k) => Some(k.benchmark_action(policy, &mut self.rng)),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn opts(list: &[(&str, OptionValue)]) -> Vec<(String, OptionValue)> {
        list.iter().map(|(k, v)| (k.to_string(), v.clone())).collect()
    }

    #[test]
    fn options_are_checked_with_one_sentence() {
        assert_eq!(
            DomainSpec::parse("keepaway", &opts(&[("keepers", OptionValue::Int(4)), ("takers", OptionValue::Int(3))])),
            Ok(DomainSpec::Keepaway { keepers: 4, takers: 3, side: 20.0, max_episode_steps: None })
        );
        let e = DomainSpec::parse("keepaway", &opts(&[("keeper", OptionValue::Int(4))])).unwrap_err();
        assert_eq!(e, "unknown keepaway option \"keeper\": expected one of keepers, takers, region, max_episode_steps");
        let e = DomainSpec::parse("maze", &opts(&[("layout", OptionValue::Str("spiral".into()))])).unwrap_err();
        assert_eq!(e, "maze option layout=\"spiral\" is invalid: expected one of low-detour, high-detour, floor-route");
        assert!(DomainSpec::parse("tetris", &[]).unwrap_err().starts_with("unknown environment \"tetris\""));
        let e = DomainSpec::parse("keepaway", &opts(&[("region", OptionValue::Float(5.0))])).unwrap_err();
        assert!(e.contains("region=5"), "{e}");
    }

    #[test]
    fn the_maze_truncates_at_its_cap_and_refuses_steps_after_the_end() {
        let spec = DomainSpec::parse("maze", &opts(&[("max_episode_steps", OptionValue::Int(3))])).unwrap();
        let mut d = Domain::new(spec).unwrap();
        assert!(d.check_step(0).is_err());
        d.reset(Some(1));
        assert_eq!(d.state(), &[0.08, 0.6]);
        for i in 0..3 {
            let a = d.check_step(2).unwrap();
            let o = d.step(a);
            assert_eq!(o, Outcome { reward: -1.0, terminated: false, truncated: i == 2 });
        }
        assert_eq!(d.check_step(0).unwrap_err(), "the episode has ended: call reset() before step()");
        assert_eq!(d.check_step(9).unwrap_err(), "the episode has ended: call reset() before step()");
        d.reset(None);
        assert_eq!(d.check_step(4).unwrap_err(), "action 4 is out of range: expected 0 to 3");
    }

    #[test]
    fn a_keepaway_episode_s_return_is_its_duration() {
        let spec = DomainSpec::parse("keepaway", &[]).unwrap();
        let mut d = Domain::new(spec).unwrap();
        d.reset(Some(3));
        let first = d.state().to_vec();
        let mut total = 0.0;
        loop {
            let a = d.benchmark_action(BenchmarkPolicy::HandCoded).unwrap();
            let o = d.step(a);
            total += o.reward;
            if o.terminated {
                break;
            }
        }
        let k = d.keepaway().unwrap();
        assert_eq!(total, f64::from(k.game.cycle()));
        assert!(k.final_smdp_rewards().iter().any(|r| r.is_finite()));
        // A seeded reset is a new game: the same first decision again.
        d.reset(Some(3));
        assert_eq!(d.state(), first.as_slice());
    }
}
