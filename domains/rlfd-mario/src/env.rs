//! Mario as an [`Environment`]: a new random level and a random start mode
//! every episode, one agent step per game tick, the benchmark's points as
//! reward, the 27 variables as state.
//!
//! The 12 actions are Liao et al.'s order of {none, left, right} × {jump or
//! not} × {speed/fire or not}: 0 none, 1 left, 2 right, 3 jump, 4 speed,
//! 5 left+jump, 6 right+jump, 7 left+speed, 8 right+speed, 9 jump+speed,
//! 10 left+jump+speed, 11 right+jump+speed.
//!
//! `reset` draws the level seed (64 bits) and then the start mode (uniform
//! over small, large, fire) from the caller's generator: a trial's seed fixes
//! its sequence of levels. As in the benchmark, an episode opens with one
//! tick without keys (Mario falls from his start at y 32; the benchmark's
//! `reset` is followed by a `tick` before the agent's first action), and the
//! first state is observed after it. That tick never scores.

use rand::Rng;
use rlfd_env::random::below;
use rlfd_env::{Environment, Step};

use super::level::{Level, LevelParams};
use super::observation::{STATE_VARIABLES, Shoot, observe_with};
use super::world::{Keys, Mode, Status, World};

/// Number of actions.
pub const ACTIONS: usize = 12;

/// The keys of each action.
pub const ACTION_KEYS: [Keys; ACTIONS] = {
    const fn k(left: bool, right: bool, jump: bool, speed: bool) -> Keys {
        Keys { left, right, jump, speed }
    }
    [
        k(false, false, false, false),
        k(true, false, false, false),
        k(false, true, false, false),
        k(false, false, true, false),
        k(false, false, false, true),
        k(true, false, true, false),
        k(false, true, true, false),
        k(true, false, false, true),
        k(false, true, false, true),
        k(false, false, true, true),
        k(true, false, true, true),
        k(false, true, true, true),
    ]
};

/// Short names of the actions, in order.
pub const ACTION_NAMES: [&str; ACTIONS] = [
    "none",
    "left",
    "right",
    "jump",
    "speed",
    "left+jump",
    "right+jump",
    "left+speed",
    "right+speed",
    "jump+speed",
    "left+jump+speed",
    "right+jump+speed",
];

/// The action with these keys.
pub fn action_of(keys: Keys) -> usize {
    ACTION_KEYS.iter().position(|k| *k == keys).expect("every key combination without up/down is an action")
}

/// The Mario environment.
#[derive(Clone, Debug)]
pub struct MarioEnv {
    params: LevelParams,
    shoot: Shoot,
    world: World,
    state: [f64; STATE_VARIABLES],
}

impl MarioEnv {
    /// An environment whose episodes play levels generated with `params`.
    pub fn new(params: LevelParams) -> Self {
        let world = World::new(Level::generate(params, 0), Mode::Small);
        let mut e = MarioEnv { params, shoot: Shoot::Api, world, state: [0.0; STATE_VARIABLES] };
        e.observe_from(None);
        e
    }

    /// Starts an episode on the level of `level_seed` with Mario in `mode`.
    pub fn start(&mut self, level_seed: u64, mode: Mode) {
        self.world.level_mut().regenerate(self.params, level_seed);
        self.world.restart(mode);
        let start = (self.world.mario().x, self.world.mario().y);
        let points = self.world.tick(Keys::default());
        debug_assert_eq!(points, 0, "the first tick, in the air at the start, scores nothing");
        self.observe_from(Some(start));
    }

    /// The same environment with `shoot` read as `reading` (the benchmark's API by default).
    pub fn with_shoot(mut self, reading: Shoot) -> Self {
        self.shoot = reading;
        self.observe_from(None);
        self
    }

    /// How the `shoot` variable is read.
    pub fn shoot_reading(&self) -> Shoot {
        self.shoot
    }

    /// The game.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The level settings.
    pub fn params(&self) -> LevelParams {
        self.params
    }

    fn observe_from(&mut self, previous: Option<(f32, f32)>) {
        let m = self.world.mario();
        observe_with(&self.world, previous.unwrap_or((m.x, m.y)), self.shoot, &mut self.state);
    }
}

impl Environment for MarioEnv {
    fn num_actions(&self) -> usize {
        ACTIONS
    }

    fn state_dim(&self) -> usize {
        STATE_VARIABLES
    }

    fn reset<R: Rng + ?Sized>(&mut self, rng: &mut R) {
        let seed = rng.next_u64();
        let mode = Mode::ALL[below(rng, 3)];
        self.start(seed, mode);
    }

    fn state(&self) -> &[f64] {
        &self.state
    }

    #[inline]
    fn step<R: Rng + ?Sized>(&mut self, action: usize, _rng: &mut R) -> Step {
        let previous = (self.world.mario().x, self.world.mario().y);
        let points = self.world.tick(ACTION_KEYS[action]);
        self.observe_from(Some(previous));
        Step { reward: f64::from(points), terminal: self.world.status() != Status::Running }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_env::random::seeded;

    #[test]
    fn actions_are_liao_et_al_s() {
        assert_eq!(action_of(Keys { right: true, jump: true, speed: true, left: false }), 11);
        assert_eq!(action_of(Keys::default()), 0);
        for (a, k) in ACTION_KEYS.iter().enumerate() {
            assert_eq!(action_of(*k), a);
            assert!(!(k.left && k.right));
        }
    }

    #[test]
    fn episodes_end_within_the_timer_and_are_reproducible() {
        let run = |seed: u64| {
            let mut env = MarioEnv::new(LevelParams::EXPERIMENT);
            let mut rng = seeded(seed);
            let mut out = Vec::new();
            for _ in 0..3 {
                env.reset(&mut rng);
                let (mut ret, mut n) = (0.0, 0);
                loop {
                    let s = env.step(below(&mut rng, ACTIONS), &mut rng);
                    ret += s.reward;
                    n += 1;
                    assert_eq!(env.state().len(), STATE_VARIABLES);
                    if s.terminal {
                        break;
                    }
                }
                assert!(n <= 3000);
                out.push((ret, n));
            }
            out
        };
        assert_eq!(run(5), run(5));
        assert_ne!(run(5), run(6));
    }
}
