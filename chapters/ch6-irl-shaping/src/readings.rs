//! The chapter's open choices, declared as readings (see
//! [`rlfd_harness::Axis`]), and how each changes the agents' parameters.
//!
//! Each axis lists its levels with the sentence behind each and the default
//! with its reason (the thesis's literal text, then the cited paper, then a
//! value fixed before any run). An axis changes only the conditions that use
//! what it sets: κ changes SIS and DIS in the Maze (the agents that learn
//! from R_IRL); Mario's β changes DIS; the terminal potential changes the
//! static potentials of SIS, HAT and SBS in both domains.

use rlfd_harness::{Axis, Level, Reading};
use rlfd_rl::shaping::TerminalPotential;

use crate::agents::{MazeAgent, MazeParams};
use crate::mario_agents::{MarioAgent, MarioParams};

/// The size of the RE-IRL reward in the Maze.
pub static IRL_SCALE: Axis = Axis {
    name: "irl-scale",
    question: "How large is the RE-IRL reward R_IRL(s) = θ·φ(s) that SIS and DIS shape with? RE-IRL fixes the direction of θ, not its size, and the thesis does not give it.",
    levels: &[
        Level {
            name: "1",
            meaning: "θ at unit length (κ = 1)",
            source: "the value fixed before any learner ran: Boularias et al. (2011) give θ up to scale",
        },
        Level {
            name: "0.1",
            meaning: "R_IRL × 0.1",
            source: "the thesis's shaping scale of 100 suggests a smaller R_IRL than unit-length θ",
        },
        Level { name: "0.01", meaning: "R_IRL × 0.01", source: "as 0.1, one step further" },
    ],
    default: "1",
    why_default: "neither the thesis nor the cited RE-IRL paper fixes θ's size, and unit length was fixed before any run",
    experiments: &["maze:sis", "maze:dis"],
};

/// DIS's secondary step size in Mario.
pub static DIS_BETA: Axis = Axis {
    name: "dis-beta",
    question: "Is Mario's β = 0.05 the step per active feature, or a total spread over the 32 tilings as the Maze's β = 0.05/#tiles?",
    levels: &[
        Level {
            name: "literal",
            meaning: "β = 0.05 per active feature",
            source: "section 6.3.2: \"β = 0.05\" for Mario",
        },
        Level {
            name: "per-tiling",
            meaning: "β = 0.05/32 per active feature",
            source: "section 6.3.1 writes the Maze's β as 0.05/#tiles, and α is spread over the active tilings",
        },
    ],
    default: "literal",
    why_default: "the thesis's text for Mario reads β = 0.05",
    experiments: &["mario:dis", "mario-demo-length:dis"],
};

/// The potential of a terminal state for the static potentials.
pub static TERMINAL_POTENTIAL: Axis = Axis {
    name: "terminal-potential",
    question: "What is Φ at the terminal state in F = γΦ(s′) − Φ(s)? The thesis's equations make no exception for a terminal s′; Ng et al. (1999) set Φ(terminal) = 0.",
    levels: &[
        Level {
            name: "literal",
            meaning: "Φ evaluated at the terminal state (for a state-action potential, the best action's value there)",
            source: "eq. 6.2, F(s, s′) = γΦ(s′) − Φ(s), and eq. 6.3 for the look-ahead potentials of HAT and SBS: no exception for a terminal s′",
        },
        Level {
            name: "zero",
            meaning: "Φ(terminal) = 0",
            source: "Ng, Harada & Russell (1999), the convention that keeps every optimal policy of an episodic task",
        },
    ],
    default: "literal",
    why_default: "the thesis's equations are the first authority, and they write Φ(s′) with no exception; DIS keeps 0 under both levels (eq. 6.8's Φ†(s′, a′) has no a′ at a terminal state)",
    experiments: &["maze:sis", "maze:hat", "maze:sbs", "mario:sis", "mario:hat", "mario:sbs"],
};

/// The Maze's tile width.
pub static TILE_WIDTH: Axis = Axis {
    name: "tile-width",
    question: "How wide is a tile of the Maze's 32 tilings over (x, y)? The thesis gives \"number of tiles = 32\" and no width.",
    levels: &[
        Level {
            name: "0.1",
            meaning: "ten tiles across the unit square per tiling",
            source: "the value fixed before any learner ran (the project's round-1 choice)",
        },
        Level {
            name: "0.2",
            meaning: "five tiles across the unit square per tiling: coarser, faster generalisation",
            source: "the review's alternative: at 0.1 SARSA has not converged by episode 150 (its last episode −351, the thesis's asymptote −222)",
        },
    ],
    default: "0.1",
    why_default: "neither the thesis nor a cited paper gives the width; 0.1 was fixed before any run",
    experiments: &["maze"],
};

/// Every axis of the chapter.
pub static AXES: [&Axis; 4] = [&TERMINAL_POTENTIAL, &IRL_SCALE, &TILE_WIDTH, &DIS_BETA];

fn terminal_potential(reading: &Reading) -> TerminalPotential {
    match reading.level_of(&TERMINAL_POTENTIAL) {
        "zero" => TerminalPotential::Zero,
        _ => TerminalPotential::Literal,
    }
}

/// κ under `reading`.
pub fn irl_scale(reading: &Reading) -> f64 {
    match reading.level_of(&IRL_SCALE) {
        "0.1" => 0.1,
        "0.01" => 0.01,
        _ => 1.0,
    }
}

/// The Maze parameters of `agent` under `reading`.
pub fn maze_params(reading: &Reading, agent: MazeAgent, params: &MazeParams) -> MazeParams {
    // The axis's own list of the conditions it changes decides, so the
    // parameters and the trials' identity never disagree.
    let mut out = params.clone();
    if IRL_SCALE.changes("maze", agent.slug()) {
        out.irl_scale = irl_scale(reading);
    }
    if TERMINAL_POTENTIAL.changes("maze", agent.slug()) {
        out.terminal_potential = terminal_potential(reading);
    }
    if TILE_WIDTH.changes("maze", agent.slug()) && reading.level_of(&TILE_WIDTH) == "0.2" {
        out.tile_width = 0.2;
    }
    out
}

/// The Mario parameters of `agent` under `reading`.
pub fn mario_params(reading: &Reading, agent: MarioAgent, params: &MarioParams) -> MarioParams {
    let mut out = params.clone();
    if DIS_BETA.changes("mario", agent.slug()) && reading.level_of(&DIS_BETA) == "per-tiling" {
        out.beta = params.beta / 32.0;
    }
    if TERMINAL_POTENTIAL.changes("mario", agent.slug()) {
        out.terminal_potential = terminal_potential(reading);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_leave_the_parameters_as_the_thesis_reads_them() {
        let p = MazeParams::paper();
        assert_eq!(maze_params(&Reading::defaults(), MazeAgent::Sis, &p), p);
        let r = Reading::defaults().with(&IRL_SCALE, IRL_SCALE.level("0.01").unwrap());
        assert_eq!(maze_params(&r, MazeAgent::Dis, &p).irl_scale, 0.01);
        assert_eq!(maze_params(&r, MazeAgent::Sarsa, &p), p);
        let m = MarioParams::paper();
        let b = Reading::defaults().with(&DIS_BETA, DIS_BETA.level("per-tiling").unwrap());
        assert_eq!(mario_params(&b, MarioAgent::Dis, &m).beta, 0.05 / 32.0);
        assert_eq!(mario_params(&b, MarioAgent::Sis, &m), m);
        let z = Reading::defaults().with(&TERMINAL_POTENTIAL, TERMINAL_POTENTIAL.level("zero").unwrap());
        assert_eq!(p.terminal_potential, TerminalPotential::Literal);
        assert_eq!(maze_params(&z, MazeAgent::Sbs, &p).terminal_potential, TerminalPotential::Zero);
        assert_eq!(maze_params(&z, MazeAgent::Dis, &p), p);
        let w = Reading::defaults().with(&TILE_WIDTH, TILE_WIDTH.level("0.2").unwrap());
        assert_eq!(p.tile_width, 0.1);
        assert_eq!(maze_params(&w, MazeAgent::Sarsa, &p).tile_width, 0.2);
        assert_eq!(mario_params(&w, MarioAgent::Sis, &m), m);
        assert_eq!(mario_params(&z, MarioAgent::Hat, &m).terminal_potential, TerminalPotential::Zero);
        for axis in AXES {
            assert!(axis.level(axis.default).is_some(), "{} has its default among its levels", axis.name);
        }
    }
}
