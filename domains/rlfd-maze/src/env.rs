//! The Maze as an [`Environment`] (thesis section 6.3.1).
//!
//! State `(x, y)` with `0 ≤ x, y < 1`, origin lower left; start `(0.08, 0.6)`;
//! actions left, right, up, down moving 0.02 (the agent) or 0.01 (the
//! demonstrator's recording resolution, see [`super::demonstrator`]). Rewards
//! (the project's reading of the text, see the chapter's decisions): −1 for
//! every step; a further −10 when the move would leave the square or enter a
//! wall, in which case the agent stays where it is; a further +10 on reaching
//! the goal `x ≥ 0.9 && y ≥ 0.9`, which ends the episode. The thesis's
//! demonstrator return, −327.5 for demonstrations of 337.5 steps on average,
//! is −337.5 + 10: the goal bonus adds to the step cost, and the wall
//! penalty is read the same way. Episodes are capped at 6,000 steps by the
//! caller.
//!
//! Positions are integers in hundredths, so no rounding error accumulates
//! over thousands of steps and wall tests are exact.

use rand::Rng;
use rlfd_env::{Environment, Step};

use super::layout::{LATTICE, MazeLayout, START};

/// The four moves, in the thesis's order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Move {
    /// −x.
    Left = 0,
    /// +x.
    Right = 1,
    /// +y.
    Up = 2,
    /// −y.
    Down = 3,
}

impl Move {
    /// All moves, indexed by action number.
    pub const ALL: [Move; 4] = [Move::Left, Move::Right, Move::Up, Move::Down];

    /// The move with action number `a`.
    pub fn from_action(a: usize) -> Move {
        Move::ALL[a]
    }

    /// Lattice displacement of one unit step.
    pub fn delta(self) -> (i32, i32) {
        match self {
            Move::Left => (-1, 0),
            Move::Right => (1, 0),
            Move::Up => (0, 1),
            Move::Down => (0, -1),
        }
    }

    /// The move between two lattice points one step apart, if any.
    pub fn between(from: (i32, i32), to: (i32, i32)) -> Option<Move> {
        let d = (to.0 - from.0, to.1 - from.1);
        let unit = |v: i32| v.signum();
        match (unit(d.0), unit(d.1)) {
            (-1, 0) => Some(Move::Left),
            (1, 0) => Some(Move::Right),
            (0, 1) => Some(Move::Up),
            (0, -1) => Some(Move::Down),
            _ => None,
        }
    }

    /// Lower-case name, as in reports.
    pub fn name(self) -> &'static str {
        match self {
            Move::Left => "left",
            Move::Right => "right",
            Move::Up => "up",
            Move::Down => "down",
        }
    }
}

/// Rewards of the Maze (section 6.3.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MazeRewards {
    /// Every step.
    pub step: f64,
    /// Added when a move is blocked by a wall or the border.
    pub blocked: f64,
    /// Added when the goal is reached.
    pub goal: f64,
}

impl MazeRewards {
    /// −1 per step, −10 more for a blocked move, +10 more at the goal.
    pub const THESIS: MazeRewards = MazeRewards { step: -1.0, blocked: -10.0, goal: 10.0 };
}

/// The Maze environment.
#[derive(Clone, Debug)]
pub struct Maze {
    layout: MazeLayout,
    step_units: i32,
    rewards: MazeRewards,
    pos: (i32, i32),
    state: [f64; 2],
}

impl Maze {
    /// A maze whose moves are `step_units` hundredths long (2 for the agent's 0.02).
    pub fn new(layout: MazeLayout, step_units: i32, rewards: MazeRewards) -> Self {
        assert!((1..LATTICE).contains(&step_units), "a Maze step is 1 to 99 hundredths");
        let mut m = Maze { layout, step_units, rewards, pos: START, state: [0.0; 2] };
        m.place(START);
        m
    }

    /// The thesis's agent: the modified Dyna Maze, steps of 0.02.
    pub fn thesis_agent() -> Self {
        Maze::new(MazeLayout::thesis(), 2, MazeRewards::THESIS)
    }

    fn place(&mut self, pos: (i32, i32)) {
        self.pos = pos;
        self.state = [f64::from(pos.0) / f64::from(LATTICE), f64::from(pos.1) / f64::from(LATTICE)];
    }

    /// The current lattice position (hundredths).
    pub fn position(&self) -> (i32, i32) {
        self.pos
    }

    /// The layout.
    pub fn layout(&self) -> &MazeLayout {
        &self.layout
    }

    /// Whether moving `m` from the current position is blocked.
    pub fn is_blocked(&self, m: Move) -> bool {
        let (dx, dy) = m.delta();
        self.layout.is_blocked(self.pos.0 + dx * self.step_units, self.pos.1 + dy * self.step_units)
    }
}

impl Environment for Maze {
    fn num_actions(&self) -> usize {
        4
    }

    fn state_dim(&self) -> usize {
        2
    }

    fn reset<R: Rng + ?Sized>(&mut self, _rng: &mut R) {
        self.place(START);
    }

    fn state(&self) -> &[f64] {
        &self.state
    }

    #[inline]
    fn step<R: Rng + ?Sized>(&mut self, action: usize, _rng: &mut R) -> Step {
        let (dx, dy) = Move::from_action(action).delta();
        let next = (self.pos.0 + dx * self.step_units, self.pos.1 + dy * self.step_units);
        if self.layout.is_blocked(next.0, next.1) {
            return Step { reward: self.rewards.step + self.rewards.blocked, terminal: false };
        }
        self.place(next);
        if MazeLayout::is_goal(next.0, next.1) {
            Step { reward: self.rewards.step + self.rewards.goal, terminal: true }
        } else {
            Step { reward: self.rewards.step, terminal: false }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rlfd_env::random::seeded;

    #[test]
    fn moves_rewards_and_goal() {
        let mut m = Maze::thesis_agent();
        let mut rng = seeded(0);
        m.reset(&mut rng);
        assert_eq!(m.state(), &[0.08, 0.6]);
        let s = m.step(Move::Up as usize, &mut rng);
        assert_eq!(s, Step { reward: -1.0, terminal: false });
        assert_eq!(m.state(), &[0.08, 0.62]);
        // Walk left into the border: x = 0.06, 0.04, 0.02, 0.00, then blocked.
        for _ in 0..4 {
            assert_eq!(m.step(Move::Left as usize, &mut rng).reward, -1.0);
        }
        assert_eq!(m.state()[0], 0.0);
        assert_eq!(m.step(Move::Left as usize, &mut rng), Step { reward: -11.0, terminal: false });
        assert_eq!(m.state(), &[0.0, 0.62]);
        // Into the wall of column 2 at y = 0.62: x = 0.22 is free, 0.24 is wall.
        let mut m = Maze::new(MazeLayout::thesis(), 2, MazeRewards::THESIS);
        m.place((20, 62));
        assert_eq!(m.step(Move::Right as usize, &mut rng).reward, -1.0);
        assert_eq!(m.step(Move::Right as usize, &mut rng).reward, -11.0);
        assert_eq!(m.position(), (22, 62));
        // Into the goal.
        m.place((90, 88));
        assert_eq!(m.step(Move::Up as usize, &mut rng), Step { reward: 9.0, terminal: true });
    }

    #[test]
    fn states_are_exact_multiples_of_a_hundredth() {
        let mut m = Maze::thesis_agent();
        let mut rng = seeded(0);
        m.reset(&mut rng);
        for _ in 0..10 {
            m.step(Move::Up as usize, &mut rng);
        }
        assert_eq!(m.state()[1], 0.8);
    }

    #[test]
    fn move_between_positions() {
        assert_eq!(Move::between((5, 5), (6, 5)), Some(Move::Right));
        assert_eq!(Move::between((5, 5), (5, 3)), Some(Move::Down));
        assert_eq!(Move::between((5, 5), (5, 5)), None);
        assert_eq!(Move::between((5, 5), (6, 6)), None);
    }
}
