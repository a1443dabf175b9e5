//! The chapter's open choices, declared as readings (see
//! [`rlfd_harness::Axis`]), and how each changes the agents' parameters in
//! either half (the halves' [`ExperimentParams`]).
//!
//! Each axis lists its levels with the sentence behind each and the default
//! with its reason (the thesis's literal text, then the cited paper, then a
//! value fixed before any run). An axis sets only what the agents that use
//! it read ([`maze_params`], [`mario_params`]), so it changes only their
//! trials' identities: κ changes SIS and DIS in the Maze (the agents that
//! learn from R_IRL); Mario's β changes DIS; the terminal potential changes
//! SIS's static potential and the advice terminal HAT's and SBS's look-ahead
//! advice, in both domains; the tile width and the layout change every Maze
//! agent; the Value Bonus changes HAT in both domains and Mario's HAT scale
//! HAT in Mario; SBS's width changes SBS; the units of HMN change no trial at all, only the
//! demonstrator's line the Maze agents are compared with (a report-only
//! axis: the robustness run reuses every trial and recomputes the
//! verdicts).
//!
//! The sensitivity studies of round 1 (`maze-irl-scale`, `mario-dis-beta`)
//! are sweeps: the Maze experiment sweeps `irl-scale` and the Mario
//! experiment sweeps `dis-beta` ([`crate::Ch6`]'s `sweeps`), their trials at
//! each level being the ones a run of that reading makes.

use rlfd_harness::{AnyAxis, Axis, Level, Reading};
use rlfd_rl::shaping::TerminalPotential;

use crate::mario::params::MarioParams;
use crate::maze::layout::LayoutId;
use crate::maze::params::MazeParams;
use crate::shaping::trials::ExperimentParams;
use crate::shaping::{Agent, HatBonus};

/// The size of the RE-IRL reward in the Maze.
pub static IRL_SCALE: Axis<f64> = Axis {
    name: "irl-scale",
    question: "How large is the RE-IRL reward R_IRL(s) = θ·φ(s) that SIS and DIS shape with? RE-IRL fixes the direction of θ, not its size, and the thesis does not give it.",
    levels: &[
        Level {
            name: "1",
            value: 1.0,
            meaning: "θ at unit length (κ = 1)",
            source: "the value fixed before any learner ran: Boularias et al. (2011) give θ up to scale",
        },
        Level {
            name: "0.1",
            value: 0.1,
            meaning: "R_IRL × 0.1",
            source: "the thesis's shaping scale of 100 suggests a smaller R_IRL than unit-length θ",
        },
        Level { name: "0.01", value: 0.01, meaning: "R_IRL × 0.01", source: "as 0.1, one step further" },
    ],
    default: "1",
    why_default: "neither the thesis nor the cited RE-IRL paper fixes θ's size, and unit length was fixed before any run",
    report_only: false,
};

/// DIS's secondary step size in Mario.
pub static DIS_BETA: Axis<DisBeta> = Axis {
    name: "dis-beta",
    question: "Is Mario's β = 0.05 the step per active feature, or a total spread over the 32 tilings as the Maze's β = 0.05/#tiles?",
    levels: &[
        Level {
            name: "literal",
            value: DisBeta::Literal,
            meaning: "β = 0.05 per active feature",
            source: "section 6.3.2: \"β = 0.05\" for Mario",
        },
        Level {
            name: "per-tiling",
            value: DisBeta::PerTiling,
            meaning: "β = 0.05/32 per active feature",
            source: "section 6.3.1 writes the Maze's β as 0.05/#tiles, and α is spread over the active tilings",
        },
    ],
    default: "literal",
    why_default: "the thesis's text for Mario reads β = 0.05",
    report_only: false,
};

/// The potential of a terminal state for SIS's static potential.
pub static TERMINAL_POTENTIAL: Axis<TerminalPotential> = Axis {
    name: "terminal-potential",
    question: "What is Φ at the terminal state in SIS's F = γΦ(s′) − Φ(s)? The thesis's equation makes no exception for a terminal s′; Ng et al. (1999) set Φ(terminal) = 0.",
    levels: &[
        Level {
            name: "literal",
            value: TerminalPotential::Literal,
            meaning: "Φ evaluated at the terminal state",
            source: "eq. 6.2, F(s, s′) = γΦ(s′) − Φ(s): no exception for a terminal s′",
        },
        Level {
            name: "zero",
            value: TerminalPotential::Zero,
            meaning: "Φ(terminal) = 0",
            source: "Ng, Harada & Russell (1999), the convention that keeps every optimal policy of an episodic task",
        },
    ],
    default: "literal",
    why_default: "the thesis's equation for SIS is the first authority, and it writes Φ(s′) with no exception; DIS keeps 0 under both levels (eq. 6.8's Φ†(s′, a′) has no a′ at a terminal state)",
    report_only: false,
};

/// The potential of a terminal state for HAT's and SBS's look-ahead advice.
///
/// Written before any run that uses it. The thesis describes both agents
/// only as Q-initialisation (section 6.3.1: HAT "initializes the Q-function
/// with the potential function at the very beginning", SBS "implements
/// Q-function initialization"), which look-ahead advice with Wiewiora's
/// correction equals only when Φ(terminal) = 0 (a test in `rlfd_rl::shaping`
/// checks the equivalence); eq. 6.3 read literally adds a terminal bonus of
/// γ·scale·max_a Φ(s′, a) at the goal instead (up to 100 for the Maze's SBS,
/// ten times the goal's +10; review round 3, ch. 6 §4.3).
pub static ADVICE_TERMINAL: Axis<TerminalPotential> = Axis {
    name: "advice-terminal",
    question: "What is Φ(s′, a′) at a terminal s′ in HAT's and SBS's look-ahead advice? The thesis calls both Q-initialisation, which holds only with Φ(terminal) = 0; eq. 6.3 itself makes no exception.",
    levels: &[
        Level {
            name: "zero",
            value: TerminalPotential::Zero,
            meaning: "Φ(terminal) = 0: look-ahead advice with Wiewiora's correction is then exactly Q-initialisation",
            source: "section 6.3.1's descriptions of HAT (\"initializes the Q-function with the potential function\") and SBS (\"implements Q-function initialization\")",
        },
        Level {
            name: "literal",
            value: TerminalPotential::Literal,
            meaning: "the best action's advice at the terminal state, a terminal bonus that Q-initialisation does not have",
            source: "eq. 6.3, F(s, a, s′, a′) = γΦ(s′, a′) − Φ(s, a), with no exception for a terminal s′",
        },
    ],
    default: "zero",
    why_default: "the thesis's own description of these two agents is Q-initialisation, the more specific text about them than the general equation; before round 3 they shared SIS's literal default, which is not Q-initialisation",
    report_only: false,
};

/// HAT's bonus B in Mario.
///
/// Written before any run that uses it. For Mario the thesis gives
/// "scaling = 1 for the shaping reward" and nothing for HAT; in the Maze it
/// gives HAT a scale of its own (10) beside the shaping scale (100), so the
/// shaping scale does not set HAT's B. Where the thesis is silent the rule
/// reads the cited original: chapter 5's and Taylor et al.'s HAT use B = 10
/// (section 5.2, "We use B = 10 and C = 100").
pub static HAT_SCALE: Axis<f64> = Axis {
    name: "hat-scale",
    question: "How large is HAT's bonus B in Mario? The thesis gives Mario's scaling for the shaping reward (1) and no B for HAT; the Maze's HAT has its own B = 10.",
    levels: &[
        Level {
            name: "1",
            value: 1.0,
            meaning: "B = 1, Mario's shaping scale",
            source: "section 6.3.2: \"scaling = 1 for the shaping reward\", read as covering HAT",
        },
        Level {
            name: "10",
            value: 10.0,
            meaning: "B = 10",
            source: "section 5.2: \"We use B = 10 and C = 100\" (the HAT paper's value), as the Maze's HAT scale",
        },
    ],
    default: "10",
    why_default: "the thesis gives no B for Mario's HAT (its scaling is for the shaping reward, and the Maze shows HAT with a scale of its own), so the cited original's B = 10; the previous rounds' 1 was an undeclared choice",
    report_only: false,
};

/// SBS's Gaussian width, as a factor on the widths fixed before any run.
///
/// Written before any run that uses it. Brys et al. (2015) leave σ to the
/// domain and the thesis gives none; ours (the Maze 0.05, half a tile;
/// Mario half a tile per variable) sets SBS's strength, so it is an axis.
pub static SBS_SIGMA: Axis<f64> = Axis {
    name: "sbs-sigma",
    question: "How wide is SBS's Gaussian similarity? Neither the thesis nor Brys et al. (2015) give a width for these domains.",
    levels: &[
        Level {
            name: "half",
            value: 0.5,
            meaning: "half the widths fixed before any run (a quarter of a tile)",
            source: "a narrower similarity: the potential drops off within a tile",
        },
        Level {
            name: "fixed",
            value: 1.0,
            meaning: "the widths fixed before any run: half a tile (the Maze σ = 0.05; Mario 1 for the booleans and directions, 2 cells for the closest enemy's offsets)",
            source: "our choice before any learner ran, half a tile of the agents' own tile coding",
        },
        Level {
            name: "double",
            value: 2.0,
            meaning: "twice the widths fixed before any run (a whole tile)",
            source: "a wider similarity: a demonstrated state's potential reaches the neighbouring tiles",
        },
    ],
    default: "fixed",
    why_default: "neither the thesis nor the cited paper gives a width; half a tile was fixed before any learner ran",
    report_only: false,
};

/// The Maze's tile width.
pub static TILE_WIDTH: Axis<f64> = Axis {
    name: "tile-width",
    question: "How wide is a tile of the Maze's 32 tilings over (x, y)? The thesis gives \"number of tiles = 32\" and no width.",
    levels: &[
        Level {
            name: "0.1",
            value: 0.1,
            meaning: "ten tiles across the unit square per tiling",
            source: "the value fixed before any learner ran (the project's round-1 choice)",
        },
        Level {
            name: "0.2",
            value: 0.2,
            meaning: "five tiles across the unit square per tiling: coarser, faster generalisation",
            source: "the review's alternative: at 0.1 SARSA has not converged by episode 150 (its last episode −351, the thesis's asymptote −222)",
        },
    ],
    default: "0.1",
    why_default: "neither the thesis nor a cited paper gives the width; 0.1 was fixed before any run",
    report_only: false,
};

/// The units the Maze demonstrator's return HMN is counted in.
///
/// Written before any run that uses it. The demonstrations are recorded at
/// 0.01 per step (the only resolution at which the thesis's lengths and its
/// path ratio agree, see `maze::demonstrator`); the agents move 0.02 per
/// step. Table 6.1's HMN, −327.5, is −337.5 + 10: counted per recorded step.
/// The same paths walked at the agents' step would score about −160. C6.4
/// and C6.5 compare the agents with HMN, so this decides them; no trial
/// changes.
pub static HMN_UNITS: Axis<HmnUnits> = Axis {
    name: "hmn-units",
    question: "In which steps is the Maze demonstrator's return HMN counted? The demonstrations are recorded at 0.01 per step, the agents move 0.02 per step. This changes no trial, only the demonstrator's line the Maze agents are compared with (C6.4, C6.5).",
    levels: &[
        Level {
            name: "recorded",
            value: HmnUnits::Recorded,
            meaning: "−1 per recorded step of 0.01 and +10 at the goal, as the thesis's −327.5 for demonstrations of 337.5 steps",
            source: "Table 6.1: \"HMN: average of the reward human demonstrator received in 10 demonstrations\", −327.5; section 6.3.1: \"The shortest demonstration took 328 steps to reach the goal and the longest demonstration was 353 steps long (μ = 337.5 …)\"",
        },
        Level {
            name: "agent-steps",
            value: HmnUnits::AgentSteps,
            meaning: "the same paths scored at the agents' step of 0.02: −(mean length in steps of 0.01)/2 + 10, about −160",
            source: "section 6.3.1: \"Step size for each action is 0.02\" and \"On average the demonstration paths are 27.4% longer than the optimal path length\" (2.665): paths of about 3.4, about 170 of the agents' steps",
        },
    ],
    default: "recorded",
    why_default: "Table 6.1 prints HMN = −327.5, the return counted in the demonstrations' own steps: the thesis's literal number",
    report_only: true,
};

/// The walls of the modified Dyna Maze.
///
/// Written before any learner ran on the alternative layouts. The thesis
/// draws its maze (Figure 6.1) and gives the optimal path's length, 2.665,
/// but lists no wall. The default layout (round 1's) routes the detour down
/// to the bottom row and back up, and RE-IRL's linear potential over (x, y)
/// reduces to x alone there (θ = (0.999, −0.047); the review's item 9).
///
/// - `high-detour` was designed first, on the review's reading of item 9
///   (the bottom detour is what collapses θ): it keeps the detour in the
///   upper half (over column 2, three corridors under the top edge, one
///   descent past column 7, extended by a cell), and its optimal route
///   (132 steps) runs left for a stretch, so x is not monotone along it.
///   Its RE-IRL fit, measured on its demonstrations before any learner's
///   result was looked at, is x alone again, θ = (1.0, 0.0): the random
///   baseline stays near the start (y ≈ 0.6), every demonstration travels
///   about 0.5 to the right, and a route whose mean height is near the
///   start's (0.66) leaves the y counts within Hoeffding's ε of the
///   baseline's. So the collapse is not the bottom detour's doing.
/// - `floor-route` was designed then, for the y component item 9 asks
///   for: a route whose mean height lies far from the start's, in the lower
///   half (down the start column, under column 2, over column 5's lengthened
///   wall, down again, under column 7 lengthened to row 4, up the goal
///   column; 134 steps, mean height 0.40). On the master seed's
///   demonstrations (mean height 0.36), measured before any learner ran on
///   it, θ = (0.985, −0.172): a y component, though x still dominates, since
///   every route must also cover the 0.8 from the start to the goal column.
///
/// All keep the Dyna walls, the start and the goal, and meet the path
/// length (133 ± 2 steps, tested by breadth-first search). The demonstrator
/// keeps its calibrated slip and drift (a model of the person) and follows
/// each layout's own route; the report shows its statistics.
pub static MAZE_LAYOUT: Axis<LayoutId> = Axis {
    name: "maze-layout",
    question: "Where are the walls of the thesis's \"modified version of the Dyna Maze\"? Figure 6.1 draws them, the text lists none; it gives the optimal path's length, 2.665 (133 steps of 0.02).",
    levels: &[
        Level {
            name: "low-detour",
            value: LayoutId::LowDetour,
            meaning: "the Dyna walls plus four cells and a thin wall: the route climbs over column 2, dives to the bottom row, passes under column 6 and climbs the goal column (134 steps)",
            source: "section 6.3.1: \"a modified version of the Dyna Maze domain introduced by Sutton and Barto\", \"The length of the optimal path is 2.665\"; the layout fixed before any learner ran (round 1)",
        },
        Level {
            name: "high-detour",
            value: LayoutId::HighDetour,
            meaning: "the Dyna walls plus three cells and three thin walls: the route climbs over column 2, winds through three corridors under the top edge and descends once, past column 7, before climbing the goal column (132 steps)",
            source: "the same sentences; designed before any learner ran on it so that the detour lies in the upper half instead of along the bottom row, where a linear (x, y) potential reduces to x alone (the review's item 9)",
        },
        Level {
            name: "floor-route",
            value: LayoutId::FloorRoute,
            meaning: "the Dyna walls plus six cells: the route runs down the start column, under column 2, over column 5, down again, under column 7 and up the goal column, in the lower half but for two climbs (134 steps)",
            source: "the same sentences; designed before any learner ran on it so that the demonstrations' mean height lies far from the start's and RE-IRL's potential has a y component (item 9), which the high detour's turned out not to have",
        },
    ],
    default: "low-detour",
    why_default: "neither the thesis's text nor Sutton & Barto's Dyna Maze gives the added walls; the low-detour layout was fixed before any learner ran",
    report_only: false,
};

/// HAT's Value Bonus in chapter 6.
///
/// Written before any run that uses it. Chapter 6 compares with "HAT with
/// value-bonus" and says its HAT "initializes the Q-function with the
/// potential function at the very beginning" (Q-initialisation, the
/// default). Chapter 5 defines the Value Bonus as a bonus B added whenever
/// Q(s, a) is calculated, with the rules' action forced for the first C =
/// 100 episodes (the alternative). B is the chapter's HAT scale under both
/// levels (Maze 10, as chapter 5's B; Mario the `hat-scale` reading's, 10
/// by default), so the axis changes the mechanism alone.
pub static HAT_BONUS: Axis<HatBonus> = Axis {
    name: "hat-bonus",
    question: "How does chapter 6's HAT use its rules? Chapter 6 says it initialises the Q-function; the Value Bonus of chapter 5, which chapter 6 cites, adds a constant bonus whenever Q(s, a) is calculated and forces the rules' action for the first C episodes.",
    levels: &[
        Level {
            name: "q-init",
            value: HatBonus::QInit,
            meaning: "Q initialised with B·1[a = rules(s)] (look-ahead advice with Wiewiora's correction: exactly Q-initialisation when the `advice-terminal` reading is zero, its default), no forced episodes",
            source: "section 6.3.1: \"The HAT algorithm, initializes the Q-function with the potential function at the very beginning\"",
        },
        Level {
            name: "persistent",
            value: HatBonus::Persistent { forced_episodes: FORCED_EPISODES },
            meaning: "B added to the rules' action every time the agent chooses, Q learned on the environment's reward alone, and the rules' action taken for the first C = 100 episodes",
            source: "section 5.2: \"When the agent reaches a state and calculates Q(s, a), the Q-value of the action suggested by the summarized policy is given a constant bonus (B). For the first C episodes, the learner is forced to execute the action suggested by the rule set\"; \"We use B = 10 and C = 100\"",
        },
    ],
    default: "q-init",
    why_default: "chapter 6's own sentence describes its HAT agent as Q-initialisation; the thesis's text on the chapter is the first authority",
    report_only: false,
};

/// Every axis of the chapter.
pub static AXES: [&dyn AnyAxis; 10] = [
    &TERMINAL_POTENTIAL,
    &ADVICE_TERMINAL,
    &IRL_SCALE,
    &TILE_WIDTH,
    &DIS_BETA,
    &HMN_UNITS,
    &MAZE_LAYOUT,
    &HAT_BONUS,
    &HAT_SCALE,
    &SBS_SIGMA,
];

/// The units of HMN under `reading`.
pub fn hmn_units(reading: &Reading) -> HmnUnits {
    *reading.value(&HMN_UNITS)
}

/// How the Maze demonstrator's return is counted (the `hmn-units` reading).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum HmnUnits {
    /// −1 per recorded step of 0.01, +10 at the goal (Table 6.1's −327.5).
    #[default]
    Recorded,
    /// The same path at the agents' step of 0.02.
    AgentSteps,
}

/// Mario's DIS step β under the `dis-beta` reading.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DisBeta {
    /// β per active feature, as written.
    Literal,
    /// β spread over the 32 tilings.
    PerTiling,
}

/// The Maze layout under `reading`.
pub fn maze_layout(reading: &Reading) -> LayoutId {
    *reading.value(&MAZE_LAYOUT)
}

/// Chapter 5's forced period C (episodes), for the persistent Value Bonus.
pub const FORCED_EPISODES: usize = 100;

/// κ under `reading`.
pub fn irl_scale(reading: &Reading) -> f64 {
    *reading.value(&IRL_SCALE)
}

/// The Maze parameters of `agent` under `reading`: each axis sets what the
/// agents that use it read (κ: SIS and DIS, the agents that learn from
/// R_IRL; the terminal potential: SIS; the advice terminal: HAT and SBS; the
/// tile width and the layout: every agent; the Value Bonus: HAT; the width:
/// SBS).
/// The trials' identities follow from these parameters.
pub fn maze_params(reading: &Reading, agent: Agent, params: &MazeParams) -> MazeParams {
    let mut out = params.clone();
    if matches!(agent, Agent::Sis | Agent::Dis) {
        out.irl_scale = irl_scale(reading);
    }
    if agent == Agent::Sis {
        out.terminal_potential = *reading.value(&TERMINAL_POTENTIAL);
    }
    if matches!(agent, Agent::Hat | Agent::Sbs) {
        out.advice_terminal = *reading.value(&ADVICE_TERMINAL);
    }
    out.tile_width = *reading.value(&TILE_WIDTH);
    out.layout = maze_layout(reading);
    if agent == Agent::Hat {
        out.hat_bonus = *reading.value(&HAT_BONUS);
    }
    if agent == Agent::Sbs {
        out.sbs_sigma = params.sbs_sigma * *reading.value(&SBS_SIGMA);
    }
    out
}

/// The Maze parameters under `reading` as the report shows them: every
/// field an axis sets, at the reading's level, whichever agent it is for.
pub fn maze_params_shown(reading: &Reading, params: &MazeParams) -> MazeParams {
    let of = |agent| maze_params(reading, agent, params);
    let (sis, hat, sbs) = (of(Agent::Sis), of(Agent::Hat), of(Agent::Sbs));
    MazeParams {
        irl_scale: sis.irl_scale,
        terminal_potential: sis.terminal_potential,
        advice_terminal: hat.advice_terminal,
        hat_bonus: hat.hat_bonus,
        sbs_sigma: sbs.sbs_sigma,
        ..of(Agent::Baseline)
    }
}

/// The Mario parameters under `reading` as the report shows them.
pub fn mario_params_shown(reading: &Reading, params: &MarioParams) -> MarioParams {
    let of = |agent| mario_params(reading, agent, params);
    let (dis, sis, hat, sbs) = (of(Agent::Dis), of(Agent::Sis), of(Agent::Hat), of(Agent::Sbs));
    MarioParams {
        beta: dis.beta,
        terminal_potential: sis.terminal_potential,
        advice_terminal: hat.advice_terminal,
        hat_scale: hat.hat_scale,
        hat_bonus: hat.hat_bonus,
        sbs_sigma_boolean: sbs.sbs_sigma_boolean,
        sbs_sigma_distance: sbs.sbs_sigma_distance,
        ..params.clone()
    }
}

/// The Mario parameters of `agent` under `reading` (β: DIS; the terminal
/// potential: SIS; the advice terminal: HAT and SBS; the Value Bonus and B:
/// HAT; the width: SBS).
pub fn mario_params(reading: &Reading, agent: Agent, params: &MarioParams) -> MarioParams {
    let mut out = params.clone();
    if agent == Agent::Dis && *reading.value(&DIS_BETA) == DisBeta::PerTiling {
        out.beta = params.beta / 32.0;
    }
    if agent == Agent::Sis {
        out.terminal_potential = *reading.value(&TERMINAL_POTENTIAL);
    }
    if matches!(agent, Agent::Hat | Agent::Sbs) {
        out.advice_terminal = *reading.value(&ADVICE_TERMINAL);
    }
    if agent == Agent::Hat {
        out.hat_bonus = *reading.value(&HAT_BONUS);
        out.hat_scale = *reading.value(&HAT_SCALE);
    }
    if agent == Agent::Sbs {
        let factor = *reading.value(&SBS_SIGMA);
        out.sbs_sigma_boolean = params.sbs_sigma_boolean * factor;
        out.sbs_sigma_distance = params.sbs_sigma_distance * factor;
    }
    out
}

impl ExperimentParams for MazeParams {
    fn trials(&self) -> u32 {
        self.trials
    }

    fn under(&self, reading: &Reading, agent: Agent) -> Self {
        maze_params(reading, agent, self)
    }
}

impl ExperimentParams for MarioParams {
    fn trials(&self) -> u32 {
        self.trials
    }

    fn under(&self, reading: &Reading, agent: Agent) -> Self {
        mario_params(reading, agent, self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m_default_advice() -> TerminalPotential {
        MarioParams::paper().advice_terminal
    }

    #[test]
    fn defaults_leave_the_parameters_as_the_thesis_reads_them() {
        let p = MazeParams::paper();
        assert_eq!(maze_params(&Reading::defaults(), Agent::Sis, &p), p);
        let r = Reading::defaults().with(&IRL_SCALE, "0.01");
        assert_eq!(maze_params(&r, Agent::Dis, &p).irl_scale, 0.01);
        assert_eq!(maze_params(&r, Agent::Baseline, &p), p);
        let m = MarioParams::paper();
        let b = Reading::defaults().with(&DIS_BETA, "per-tiling");
        assert_eq!(mario_params(&b, Agent::Dis, &m).beta, 0.05 / 32.0);
        assert_eq!(mario_params(&b, Agent::Sis, &m), m);
        // The terminal potential is SIS's; the advice terminal HAT's and SBS's.
        let z = Reading::defaults().with(&TERMINAL_POTENTIAL, "zero");
        assert_eq!(p.terminal_potential, TerminalPotential::Literal);
        assert_eq!(maze_params(&z, Agent::Sis, &p).terminal_potential, TerminalPotential::Zero);
        assert_eq!(maze_params(&z, Agent::Sbs, &p), p);
        assert_eq!(maze_params(&z, Agent::Dis, &p), p);
        let a = Reading::defaults().with(&ADVICE_TERMINAL, "literal");
        assert_eq!((p.advice_terminal, m_default_advice()), (TerminalPotential::Zero, TerminalPotential::Zero));
        assert_eq!(maze_params(&a, Agent::Sbs, &p).advice_terminal, TerminalPotential::Literal);
        assert_eq!(maze_params(&a, Agent::Hat, &p).advice_terminal, TerminalPotential::Literal);
        assert_eq!(maze_params(&a, Agent::Sis, &p), p);
        // Mario's HAT scale changes Mario's HAT alone; SBS's width SBS alone.
        let hs = Reading::defaults().with(&HAT_SCALE, "1");
        assert_eq!(mario_params(&hs, Agent::Hat, &MarioParams::paper()).hat_scale, 1.0);
        assert_eq!(mario_params(&hs, Agent::Sbs, &MarioParams::paper()), MarioParams::paper());
        assert_eq!(maze_params(&hs, Agent::Hat, &p), p);
        let sg = Reading::defaults().with(&SBS_SIGMA, "double");
        assert_eq!(maze_params(&sg, Agent::Sbs, &p).sbs_sigma, 0.1);
        assert_eq!(mario_params(&sg, Agent::Sbs, &MarioParams::paper()).sbs_sigma_distance, 4.0);
        assert_eq!(maze_params(&sg, Agent::Hat, &p), p);
        let w = Reading::defaults().with(&TILE_WIDTH, "0.2");
        assert_eq!(p.tile_width, 0.1);
        assert_eq!(maze_params(&w, Agent::Baseline, &p).tile_width, 0.2);
        assert_eq!(mario_params(&w, Agent::Sis, &m), m);
        assert_eq!(mario_params(&z, Agent::Sis, &m).terminal_potential, TerminalPotential::Zero);
        assert_eq!(mario_params(&z, Agent::Hat, &m), m);
        for axis in AXES {
            axis.check().unwrap();
        }
        // The layout changes every Maze agent and no Mario one.
        let l = Reading::defaults().with(&MAZE_LAYOUT, "floor-route");
        assert_eq!(p.layout, LayoutId::LowDetour);
        assert_eq!(maze_params(&l, Agent::Baseline, &p).layout, LayoutId::FloorRoute);
        assert_eq!(maze_layout(&l), LayoutId::FloorRoute);
        assert_eq!(mario_params(&l, Agent::Hat, &m), m);
        // The Value Bonus changes HAT alone, in both domains.
        let h = Reading::defaults().with(&HAT_BONUS, "persistent");
        let persistent = HatBonus::Persistent { forced_episodes: 100 };
        assert_eq!(maze_params(&h, Agent::Hat, &p).hat_bonus, persistent);
        assert_eq!(mario_params(&h, Agent::Hat, &m).hat_bonus, persistent);
        assert_eq!(maze_params(&h, Agent::Sbs, &p), p);
        assert_eq!(mario_params(&h, Agent::Sbs, &m), m);
        // HMN's units change no trial: no condition of any experiment.
        let u = Reading::defaults().with(&HMN_UNITS, "agent-steps");
        assert_eq!(hmn_units(&u), HmnUnits::AgentSteps);
        assert_eq!(hmn_units(&Reading::defaults()), HmnUnits::Recorded);
        for agent in Agent::ALL {
            assert_eq!(maze_params(&u, agent, &p), p);
            assert_eq!(mario_params(&u, agent, &m), m);
        }
        // The parameters shown carry every axis's level.
        let all = Reading::parse(
            "irl-scale=0.1,tile-width=0.2,maze-layout=high-detour,hat-bonus=persistent,dis-beta=per-tiling,terminal-potential=zero,advice-terminal=literal,hat-scale=1,sbs-sigma=half",
            &AXES,
        )
        .unwrap();
        let shown = maze_params_shown(&all, &p);
        assert_eq!((shown.irl_scale, shown.tile_width, shown.layout), (0.1, 0.2, LayoutId::HighDetour));
        assert_eq!((shown.hat_bonus, shown.terminal_potential), (persistent, TerminalPotential::Zero));
        assert_eq!((shown.advice_terminal, shown.sbs_sigma), (TerminalPotential::Literal, 0.025));
        let shown = mario_params_shown(&all, &m);
        assert_eq!(
            (shown.beta, shown.hat_bonus, shown.terminal_potential),
            (0.05 / 32.0, persistent, TerminalPotential::Zero)
        );
        assert_eq!(
            (shown.advice_terminal, shown.hat_scale, shown.sbs_sigma_boolean),
            (TerminalPotential::Literal, 1.0, 0.5)
        );
        assert_eq!(maze_params_shown(&Reading::defaults(), &p), p);
        // Each layout level names a layout of its own.
        for level in MAZE_LAYOUT.levels {
            let r = Reading::defaults().with(&MAZE_LAYOUT, level.name);
            assert_eq!(maze_layout(&r).name(), level.name);
        }
    }
}
