//! The chapter's open choices, declared as readings (see
//! [`rlfd_harness::Axis`]), and how each changes the agents' parameters.
//!
//! Each axis lists its levels with the sentence behind each and the default
//! with its reason (the thesis's literal text, then the cited paper, then a
//! value fixed before any run). An axis changes only the conditions that use
//! what it sets: κ changes SIS and DIS in the Maze (the agents that learn
//! from R_IRL); Mario's β changes DIS.

use rlfd_harness::{Axis, Level, Reading};

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

/// Every axis of the chapter.
pub static AXES: [&Axis; 2] = [&IRL_SCALE, &DIS_BETA];

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
    if IRL_SCALE.changes("maze", agent.slug()) {
        MazeParams { irl_scale: irl_scale(reading), ..params.clone() }
    } else {
        params.clone()
    }
}

/// The Mario parameters of `agent` under `reading`.
pub fn mario_params(reading: &Reading, agent: MarioAgent, params: &MarioParams) -> MarioParams {
    if DIS_BETA.changes("mario", agent.slug()) && reading.level_of(&DIS_BETA) == "per-tiling" {
        MarioParams { beta: params.beta / 32.0, ..params.clone() }
    } else {
        params.clone()
    }
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
        for axis in AXES {
            assert!(axis.level(axis.default).is_some(), "{} has its default among its levels", axis.name);
        }
    }
}
